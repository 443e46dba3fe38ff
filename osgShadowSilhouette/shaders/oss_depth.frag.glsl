#version 400 compatibility
// osgShadowSilhouette: depth pass from the light, and the eye's depth prepass. Writes depth
// only (colour writes are off). An alpha-tested caster (OSS_ALPHA_TEST) outputs the alpha the
// receiver shading gives it (material diffuse alpha x primary colour alpha x the texture on
// unit 0), and the scene's own osg::AlphaFunc, which the compatibility profile applies to
// the shader's output, cuts the caster's shape out of the map exactly where the eye pass
// cuts it out of the picture. The texture is read at its full resolution (level 0): a
// mipmapped leaf texture seen small from the light averages its holes away, and a low
// threshold (lz.osgt's trees: GEQUAL 0.05) would then cast the whole card.
// A caster drawn with its own vertex stage (OSS_CASTER_VERTEX, CasterVertexStages.h) has no
// texture coordinates for it here: it casts its whole triangles.

#pragma import_defines(OSS_ALPHA_TEST, OSS_BASE_TEXTURE, OSS_CASTER_VERTEX)

#if defined(OSS_ALPHA_TEST) && !defined(OSS_CASTER_VERTEX)
#define OSS_CUT_OUT
#endif

#ifdef OSS_CUT_OUT
in vec4 oss_texCoord0;
#ifdef OSS_BASE_TEXTURE
uniform sampler2D oss_baseTexture;
#endif
#endif

void main()
{
#ifdef OSS_CUT_OUT
    float alpha = gl_FrontMaterial.diffuse.a * gl_Color.a;
#ifdef OSS_BASE_TEXTURE
    alpha *= textureLod(oss_baseTexture, oss_texCoord0.st, 0.0).a;
#endif
    gl_FragColor = vec4(1.0, 1.0, 1.0, alpha);
#elif defined(OSS_ALPHA_TEST)
    gl_FragColor = vec4(1.0); // whole triangles pass the scene's alpha test
#endif
}
