#version 400 compatibility
// osgShadowSilhouette: silhouette-map pass, vertex stage.
// The edge endpoints are already in light view space (CasterEdges); the model-view matrix
// is the identity and the projection the light's.
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
