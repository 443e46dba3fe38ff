#version 400 compatibility
// osgShadowSilhouette: depth pass from the light, and the eye's depth prepass. Position
// only, plus what an alpha-tested caster's fragment needs (OSS_ALPHA_TEST: set where the
// scene enables GL_ALPHA_TEST) to cut its shape out as the eye pass does.

#pragma import_defines(OSS_ALPHA_TEST)

#ifdef OSS_ALPHA_TEST
out vec4 oss_texCoord0;
#endif

void main()
{
    gl_Position = ftransform();
#ifdef OSS_ALPHA_TEST
    oss_texCoord0 = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_FrontColor = gl_Color;
#endif
}
