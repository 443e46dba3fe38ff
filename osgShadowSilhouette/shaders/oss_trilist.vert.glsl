#version 430 compatibility
// osgShadowSilhouette: triangle-list pass (HYBRID's TRIANGLE_LISTS method), vertex stage.
// The casters in the light's clip space; the geometry stage does the rest, reading nothing
// but gl_Position, so a caster's own vertex stage can take this one's place
// (CasterVertexStages.h).
void main()
{
    gl_Position = ftransform();
}
