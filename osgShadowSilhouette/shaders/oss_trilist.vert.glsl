#version 430 compatibility
// osgShadowSilhouette: triangle-list pass (HYBRID's TRIANGLE_LISTS method), vertex stage.
// The casters in the light's clip space; the geometry stage does the rest.
void main()
{
    gl_Position = ftransform();
}
