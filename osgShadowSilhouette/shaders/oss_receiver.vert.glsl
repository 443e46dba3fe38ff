#version 400 compatibility
// osgShadowSilhouette: receiver shading, vertex stage.
//
// Lights each vertex exactly as OpenGL's fixed function does (oss_lighting(),
// oss_lighting.glsl), keeping the diffuse + specular of every shadowed light apart for the
// fragment stage to scale by its own shadow term. The scene therefore looks as it does
// without the technique wherever no shadow falls. With OSS_PER_PIXEL_LIGHTING (the property
// PerPixelLighting) the stage passes the eye-space normal and the primary colour instead,
// and the fragment stage lights each pixel with the same equation.

#pragma import_defines(OSS_MAX_SHADOW_LIGHTS, OSS_PER_PIXEL_LIGHTING)

out vec4 oss_eyePosition;
out vec4 oss_texCoord0;
#ifdef OSS_PER_PIXEL_LIGHTING
out vec3 oss_eyeNormal; // zero where the normal is not finite
out vec4 oss_color;
#else
out vec4 oss_unshadowedColor;                       // emission, ambients, unshadowed lights
out vec3 oss_shadowedColor[OSS_MAX_SHADOW_LIGHTS];  // diffuse + specular of shadow slot s
#endif

vec4 oss_lighting(vec3 p, vec3 n, vec4 color, out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS]);

void main()
{
    oss_eyePosition = gl_ModelViewMatrix * gl_Vertex;
    oss_texCoord0 = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();
    vec3 n = gl_NormalMatrix * gl_Normal;
#ifdef OSS_PER_PIXEL_LIGHTING
    oss_eyeNormal = length(n) < 1e30 ? n : vec3(0.0); // NaN compares false
    oss_color = gl_Color;
#else
    oss_unshadowedColor = oss_lighting(oss_eyePosition.xyz, n, gl_Color, oss_shadowedColor);
#endif
}
