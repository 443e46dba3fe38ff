#version 400 compatibility
// osgShadowSilhouette: shadow-volume geometry updates the stencil buffer only.
void main()
{
}
