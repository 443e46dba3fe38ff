#version 400 compatibility
// osgShadowSilhouette: depth pass from the light. Position only.
void main()
{
    gl_Position = ftransform();
}
