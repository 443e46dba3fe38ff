#version 430 compatibility
// osgShadowSilhouette: triangle-list pass, clear: a quad already in clip space.
void main()
{
    gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);
}
