#version 400 compatibility
// osgShadowSilhouette: depth pass from the light. Writes depth only (colour writes are off).
void main()
{
}
