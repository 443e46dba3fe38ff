#version 430 compatibility
// osgShadowSilhouette: triangle-list pass, clear: every texel's list empty (the counts are
// reset by a buffer update before the pass).
layout(r32ui, binding = 0) uniform writeonly uimage2D oss_listHeadImage;
layout(r32ui, binding = 1) uniform writeonly uimage2D oss_listCountImage;

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
    imageStore(oss_listHeadImage, texel, uvec4(0xffffffffu));
    imageStore(oss_listCountImage, texel, uvec4(0u));
    gl_FragColor = vec4(0.0);
}
