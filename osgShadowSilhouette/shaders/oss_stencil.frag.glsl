#version 400 compatibility
// osgShadowSilhouette: the eye passes of the stencil modes, SHADOW_VOLUME and HYBRID.
//
// Each pass draws the receivers again (same vertex stage, oss_receiver.vert, so depths are
// identical and the passes meet with GL_EQUAL), and the define set by the pass's StateSet
// chooses what this stage writes:
//   (none)                 base pass: emission, ambients and the unshadowed lights
//   OSS_LIGHT_PASS=s       one shadowed light (shadow slot s, GL light OSS_LIGHT_NUM), added
//                          where the stencil test lets it through (count 0: lit)
//   + OSS_HYBRID_SHADOW_MAP  ... scaled by the shadow map's answer (non-silhouette pixels)
//   OSS_HYBRID_MASK=s      marks the silhouette pixels of slot s in the stencil buffer
//                          (Chan and Durand 2004): front-facing to the light and 2x2 PCF
//                          strictly between 0 and 1; every other fragment is discarded
//   OSS_LIGHT_FACES=bits   HYBRID's mask and shadow-map light passes: the slots of the light's
//                          maps (bit s: slot s; a point light's cube faces), read by oss_lightPcf()
//   OSS_VISIBILITY_CLEAR, OSS_VISIBILITY_MARK  with an application's program on receivers:
//                          the base pass clears the screen-space visibility image, a light
//                          pass sets its slot's bit instead of adding colour
//                          (oss_screen_visibility.frag.glsl)
// With OSS_DEBUG_MASK the passes write the MEASURE.md mask of the light instead: the base
// pass 0 (1 where an unshadowed light faces the surface), the light pass 1 where the surface
// faces the light. With OSS_DEBUG_CLASSES they
// write the class colours (oss_classColor()): black base, green where the volumes leave the
// light, red / blue where HYBRID's shadow map answers lit / shadowed.
// An alpha-tested receiver (OSS_ALPHA_TEST) writes, in every pass, the alpha its shading
// gives it, so the scene's osg::AlphaFunc cuts each pass (and the masks) where it cuts the
// base pass; a light pass adds its alpha too, to a destination alpha nothing reads.
// OSS_BLENDED_PASS: a light pass of the blended round (receivers drawn after the opaque
// bins): it writes the surface's alpha too, which its blending (GL_SRC_ALPHA, GL_ONE) scales
// the light by, as the receiver's own blending scales its base pass.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_CUBE_FACES, OSS_BASE_TEXTURE, OSS_DEBUG_MASK, OSS_DEBUG_CLASSES, OSS_MAX_SHADOW_LIGHTS, OSS_LIGHT_PASS, OSS_LIGHT_NUM, OSS_HYBRID_SHADOW_MAP, OSS_HYBRID_MASK, OSS_HYBRID_EDGES)
#pragma import_defines(OSS_VISIBILITY_CLEAR, OSS_VISIBILITY_MARK, OSS_ALPHA_TEST, OSS_BLENDED_PASS)
#ifndef OSS_LIGHT_NUM
#define OSS_LIGHT_NUM 0
#endif

in vec4 oss_eyePosition;
in vec4 oss_texCoord0;
// Emission, ambients and unshadowed lights; shadowed[s]: the diffuse + specular of shadow
// slot s, per vertex or per pixel (oss_fragment_lighting.frag.glsl).
vec4 oss_fragmentLighting(out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS]);

uniform sampler2D oss_baseTexture;
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform sampler2DShadow oss_shadowMap[OSS_MAX_SHADOW_SLOTS];

float oss_lightPcf(int slot, vec4 eyePosition);
#if defined(OSS_HYBRID_MASK) && defined(OSS_HYBRID_EDGES)
bool oss_lightEdges(int slot, vec4 eyePosition); // the light's edge mask (oss_shadow.frag.glsl)
#endif

bool oss_facesLight(int n, vec3 p);
#ifdef OSS_VISIBILITY_CLEAR
void oss_clearVisibility(); // oss_screen_visibility.frag.glsl
#endif
#ifdef OSS_VISIBILITY_MARK
void oss_markVisible(int slot);
#endif
vec4 oss_classColor(bool silhouette, bool lit);

#ifdef OSS_DEBUG_MASK
uniform int oss_numLights;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform int oss_maskLight;
int oss_shadowSlotOf(int light);

// The base pass's mask: 1 where the mask light is lit unshadowed (over the budget, or with
// nothing to shadow: it has no light pass) and faces the surface, else 0.
float oss_unshadowedMask(vec3 p)
{
    int n = oss_lightIndex[clamp(oss_maskLight, 0, OSS_MAX_SCENE_LIGHTS - 1)];
    bool facing = oss_facesLight(n, p);
    return oss_maskLight < oss_numLights && oss_shadowSlotOf(n) < 0 && facing ? 1.0 : 0.0;
}
#endif

vec4 oss_textured(vec4 color)
{
#ifdef OSS_BASE_TEXTURE
    color *= texture(oss_baseTexture, oss_texCoord0.st);
#endif
    return color;
}

// A pass's output, with the alpha of an alpha-tested or blended receiver's shading (else `alpha`).
vec4 oss_withAlpha(vec3 rgb, float alpha, vec4 unshadowedColor)
{
#if defined(OSS_ALPHA_TEST) || defined(OSS_BLENDED_PASS)
    alpha = oss_textured(unshadowedColor).a;
#endif
    return vec4(rgb, alpha);
}

void main()
{
    vec3 oss_shadowedColor[OSS_MAX_SHADOW_LIGHTS];
    vec4 oss_unshadowedColor = oss_fragmentLighting(oss_shadowedColor);
#if defined(OSS_HYBRID_MASK)
    float pcf = oss_lightPcf(OSS_HYBRID_MASK, oss_eyePosition);
    bool uncertain = pcf > 0.0 && pcf < 1.0;
#ifdef OSS_HYBRID_EDGES
    uncertain = uncertain || oss_lightEdges(OSS_HYBRID_MASK, oss_eyePosition);
#endif
    if (!uncertain || !oss_facesLight(OSS_LIGHT_NUM, oss_eyePosition.xyz))
        discard;
    gl_FragColor = oss_withAlpha(vec3(0.0), 0.0, oss_unshadowedColor);
#elif defined(OSS_LIGHT_PASS)
    float visible = 1.0;
#ifdef OSS_HYBRID_SHADOW_MAP
    visible = step(0.5, oss_lightPcf(OSS_LIGHT_PASS, oss_eyePosition));
#endif
#if defined(OSS_DEBUG_CLASSES) && defined(OSS_HYBRID_SHADOW_MAP)
    gl_FragColor = oss_withAlpha(oss_classColor(false, oss_facesLight(OSS_LIGHT_NUM, oss_eyePosition.xyz) && visible > 0.5).rgb,
                                 1.0, oss_unshadowedColor);
#elif defined(OSS_DEBUG_CLASSES)
    gl_FragColor = oss_withAlpha(oss_classColor(true, oss_facesLight(OSS_LIGHT_NUM, oss_eyePosition.xyz)).rgb, 1.0,
                                 oss_unshadowedColor);
#elif defined(OSS_DEBUG_MASK)
    gl_FragColor = oss_withAlpha(vec3(oss_facesLight(OSS_LIGHT_NUM, oss_eyePosition.xyz) ? visible : 0.0), 1.0,
                                 oss_unshadowedColor);
#elif defined(OSS_VISIBILITY_MARK)
    if (visible > 0.5)
        oss_markVisible(OSS_LIGHT_PASS);
    gl_FragColor = vec4(0.0); // colour writes are off
#else
    vec3 light = oss_textured(vec4(visible * oss_shadowedColor[OSS_LIGHT_PASS], 0.0)).rgb;
#ifdef OSS_BLENDED_PASS
    // The map modes clamp the whole shading once, before blending; blended passes would
    // each be clamped on their own. The light fills what the base pass and the lights of
    // the slots before it (whose passes come first) left below 1: exact where those are
    // lit, darker than the map modes only where one of them is shadowed and the sum saturates.
    vec3 below = oss_unshadowedColor.rgb;
    for (int s = 0; s < OSS_LIGHT_PASS; ++s)
        below += oss_shadowedColor[s];
    light = min(light, max(vec3(1.0) - oss_textured(vec4(below, 0.0)).rgb, vec3(0.0)));
#endif
    gl_FragColor = oss_withAlpha(light, 0.0, oss_unshadowedColor);
#endif
#else
#if defined(OSS_DEBUG_MASK)
    gl_FragColor = oss_withAlpha(vec3(oss_unshadowedMask(oss_eyePosition.xyz)), 1.0,
                                 oss_unshadowedColor); // a light pass may add the rest
#elif defined(OSS_DEBUG_CLASSES)
    gl_FragColor = oss_withAlpha(vec3(0.0), 1.0, oss_unshadowedColor); // shadowed until a light pass says otherwise
#else
#ifdef OSS_VISIBILITY_CLEAR
    oss_clearVisibility();
#endif
    gl_FragColor = oss_textured(oss_unshadowedColor);
#endif
#endif
}
