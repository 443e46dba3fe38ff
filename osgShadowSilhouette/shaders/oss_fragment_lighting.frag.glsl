#version 400 compatibility
// osgShadowSilhouette: the receivers' lighting in their fragment stages (oss_receiver.frag,
// oss_stencil.frag): per pixel with OSS_PER_PIXEL_LIGHTING (the property PerPixelLighting),
// OpenGL's fixed-function equation (oss_lighting.glsl) at the interpolated eye-space
// position, normal and primary colour; else the vertex stage's colours, interpolated.

#pragma import_defines(OSS_MAX_SHADOW_LIGHTS, OSS_PER_PIXEL_LIGHTING)

in vec4 oss_eyePosition;
#ifdef OSS_PER_PIXEL_LIGHTING
in vec3 oss_eyeNormal;
in vec4 oss_color;
vec4 oss_lighting(vec3 p, vec3 n, vec4 color, out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS]);
#else
in vec4 oss_unshadowedColor;
in vec3 oss_shadowedColor[OSS_MAX_SHADOW_LIGHTS];
#endif

// Emission, ambients and the unshadowed lights, with alpha; shadowed[s]: the diffuse +
// specular of shadow slot s.
vec4 oss_fragmentLighting(out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS])
{
#ifdef OSS_PER_PIXEL_LIGHTING
    return oss_lighting(oss_eyePosition.xyz, oss_eyeNormal, oss_color, shadowed);
#else
    shadowed = oss_shadowedColor;
    return oss_unshadowedColor;
#endif
}
