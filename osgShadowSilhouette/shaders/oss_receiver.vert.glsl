#version 400 compatibility
// osgShadowSilhouette: receiver shading, vertex stage. Passes eye-space position and
// normal on for per-pixel lighting; ftransform() keeps depth identical to fixed function.

out vec4 oss_eyePosition;
out vec3 oss_eyeNormal;
out vec4 oss_texCoord0;
out vec4 oss_color;

void main()
{
    oss_eyePosition = gl_ModelViewMatrix * gl_Vertex;
    oss_eyeNormal = gl_NormalMatrix * gl_Normal;
    oss_texCoord0 = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    oss_color = gl_Color;
    gl_Position = ftransform();
}
