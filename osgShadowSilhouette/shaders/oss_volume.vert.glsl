#version 400 compatibility
// osgShadowSilhouette: shadow-volume geometry. Vertices are homogeneous: w = 0 puts a
// vertex at infinity, away from the light; GL_DEPTH_CLAMP keeps those at the far plane.
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
