#version 430 compatibility
// osgShadowSilhouette: the stencil modes' screen-space visibility, for programs of their own.
//
// SHADOW_VOLUME and HYBRID with stencil volumes decide shadows in the stencil buffer, which
// a fragment shader cannot read. Where an application's program draws receivers (given to
// addShadowShaders()), the technique turns each light's stencil answer into one bit of an
// R32UI image the size of the viewport, and draws the receivers once more, with their own
// programs, where oss_shadowTerm() reads that bit:
//   OSS_VISIBILITY_CLEAR   base pass: clears the pixel's bits
//   OSS_VISIBILITY_MARK    a light pass: sets bit OSS_LIGHT_PASS where the stencil test lets
//                          the light through (tests early: a fragment the stencil or depth
//                          test rejects must not write)
//   OSS_SCREEN_VISIBILITY  final pass: oss_screenVisibilityTerm(slot) reads the bit
// Linked into every program of getShadowShaders(); empty unless one of them is defined.

#pragma import_defines(OSS_SCREEN_VISIBILITY, OSS_VISIBILITY_CLEAR, OSS_VISIBILITY_MARK, OSS_GLSL_430)
#pragma requires(OSS_GLSL_430)
#if defined(OSS_SCREEN_VISIBILITY) || defined(OSS_VISIBILITY_CLEAR) || defined(OSS_VISIBILITY_MARK)
layout(r32ui, binding = OSS_SCREEN_VISIBILITY_UNIT) coherent uniform uimage2D oss_screenVisibility;
#else
// (A translation unit may not be empty.)
const int oss_screenVisibilityUnused = 0;
#endif

#ifdef OSS_VISIBILITY_CLEAR
void oss_clearVisibility()
{
    imageStore(oss_screenVisibility, ivec2(gl_FragCoord.xy), uvec4(0u));
}
#endif

#ifdef OSS_VISIBILITY_MARK
layout(early_fragment_tests) in;

void oss_markVisible(int slot)
{
    imageAtomicOr(oss_screenVisibility, ivec2(gl_FragCoord.xy), 1u << uint(slot));
}
#endif

#ifdef OSS_SCREEN_VISIBILITY
// 1 where the stencil passes let the light of shadow slot `slot` reach the pixel, else 0.
float oss_screenVisibilityTerm(int slot)
{
    uint bits = imageLoad(oss_screenVisibility, ivec2(gl_FragCoord.xy)).r;
    return float((bits >> uint(slot)) & 1u);
}
#endif
