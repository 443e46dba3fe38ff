#version 430 compatibility
// osgShadowSilhouette: triangle-list pass (HYBRID's TRIANGLE_LISTS method), vertex stage.
// The casters in the light's clip space, and in its view space for the geometry stage's
// test against the receivers; the geometry stage does the rest.
out vec4 oss_lightViewPosition;

void main()
{
    gl_Position = ftransform();
    oss_lightViewPosition = gl_ModelViewMatrix * gl_Vertex;
}
