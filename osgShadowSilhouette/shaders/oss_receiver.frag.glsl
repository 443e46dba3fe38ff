#version 400 compatibility
// osgShadowSilhouette: receiver shading, fragment stage.
//
// colour = unshadowed part + sum over shadow slots of (shadow term x that light's diffuse
// and specular), modulated by the texture on unit 0 where there is one.
// With OSS_DEBUG_MASK the pass writes the shadow mask of light oss_maskLight instead:
// 1 where that light reaches the surface, 0 where it is blocked or the surface's geometric
// normal faces away from it (the conventions of the exact reference); with
// OSS_DEBUG_VISIBILITY too, the shadow term itself (its visibility) where the surface faces it. With OSS_DEBUG_CLASSES
// it writes the class colours of that light (oss_classColor()). Both carry the alpha the
// shading gives an alpha-tested receiver (OSS_ALPHA_TEST), so the scene's osg::AlphaFunc
// cuts the mask where it cuts the picture.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_CUBE_FACES, OSS_BASE_TEXTURE, OSS_DEBUG_MASK, OSS_DEBUG_CLASSES, OSS_MAX_SHADOW_LIGHTS, OSS_NUM_SHADOW_SLOTS)
#pragma import_defines(OSS_SILHOUETTE_MAP, OSS_FILTER_SILHOUETTE, OSS_DEBUG_SILHOUETTE_PIXELS, OSS_DEBUG_SILHOUETTE_MAP, OSS_TRIANGLE_LISTS, OSS_MAX_LIST_SLOTS, OSS_SKIPPED_SLOTS, OSS_ALPHA_TEST)
#pragma import_defines(OSS_DEBUG_VISIBILITY, OSS_FILTER_PCF, OSS_FILTER_PCSS, OSS_LIST_SOFT)
// OSS_SKIPPED_SLOTS, bit s: slot s is a cube face with nothing to shadow (its newest build
// drew no caster), left out: its term is 1 everywhere. The OSS_MAX_* and slot defines have
// their defaults in the prelude (ShaderSource.cpp, shaderPrelude()).

in vec4 oss_eyePosition;
in vec4 oss_texCoord0;
// Emission, ambients and unshadowed lights; shadowed[s]: the diffuse + specular of shadow
// slot s, per vertex or per pixel (oss_fragment_lighting.frag.glsl).
vec4 oss_fragmentLighting(out vec3 shadowed[OSS_MAX_SHADOW_LIGHTS]);

uniform int oss_numLights;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform int oss_maskLight;
uniform sampler2D oss_baseTexture;
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform OSS_SHADOW_SAMPLER oss_shadowMap[OSS_MAX_SHADOW_SLOTS]; // prelude: raw depths in SILHOUETTE_MAP

float oss_shadowTerm(int light, vec4 eyePosition);
float oss_pcf(sampler2DShadow map, mat4 eyeToShadow, vec4 eyePosition);

// One shadow slot's light, scaled by its shadow term. The number of slots in use is a
// compile-time constant (a define set per view), so unused slots cost nothing: shaders
// execute both sides of a branch on SIMD rasterizers such as llvmpipe.
// In the silhouette-map mode the term comes from oss_silhouetteTerm() (oss_silhouette.frag.glsl).
#if defined(OSS_SILHOUETTE_MAP) && defined(OSS_FILTER_SILHOUETTE)
// FILTER_SILHOUETTE: the edge distances, oss_silhouetteFilterTerm() (oss_silhouette_filter.frag.glsl).
uniform sampler2D oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS]; // distance maps (oss_sildist.frag.glsl)
float oss_silhouetteFilterTerm(int s, sampler2D depthMap, sampler2D distanceMap, mat4 eyeToShadow, vec4 eyePosition);
vec4 oss_silhouetteDebug(vec4 eyePosition); // DEBUG_SILHOUETTE_MAP: the edge distances
#define OSS_SLOT_TERM(s) oss_silhouetteFilterTerm(s, oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], oss_eyePosition)
#elif defined(OSS_SILHOUETTE_MAP)
uniform usampler2D oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS]; // neighbourhood maps (oss_silnbr.frag.glsl)
float oss_silhouetteTerm(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition);
vec4 oss_silhouetteDebug(vec4 eyePosition);
#define OSS_SLOT_TERM(s) oss_silhouetteTerm(oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], oss_eyePosition)
#elif defined(OSS_TRIANGLE_LISTS)
// HYBRID with triangle lists: oss_listTerm() (oss_trilist_term.frag.glsl).
float oss_listTerm(int s, float pcf, vec4 eyePosition, bool walk);
// A slot's silhouette pixels walk their lists only where its light's diffuse and specular
// reach half an 8-bit step (oss_walkLight, set in main): elsewhere the term multiplies a
// colour that rounds to nothing (faces turned away from the light, the end of its range),
// and the PCF answer is kept at no cost. The masks (DEBUG_SHADOW_MASK) always walk.
#ifdef OSS_CUBE_FACES
#define OSS_SLOT_WALK(s) oss_walkLight[oss_slotOwner[s]]
#else
#define OSS_SLOT_WALK(s) oss_walkLight[s]
#endif
#ifdef OSS_LIST_SOFT
// Lights with a size: shadow rays at the penumbra's pixels (oss_shadow.frag.glsl).
vec2 oss_listSizedTerm(int s, vec4 p, bool walk);
#define OSS_SLOT_TERM(s) oss_listSizedTerm(s, oss_eyePosition, OSS_SLOT_WALK(s)).x
#else
#define OSS_SLOT_TERM(s) oss_listTerm(s, oss_pcf(oss_shadowMap[s], oss_eyeToShadow[s], oss_eyePosition), oss_eyePosition, OSS_SLOT_WALK(s))
#endif
#elif defined(OSS_FILTER_PCF) || defined(OSS_FILTER_PCSS)
// SHADOW_MAP under a soft filter: oss_filterTerm() (oss_filter.frag.glsl).
float oss_filterTerm(int s, sampler2D map, mat4 eyeToShadow, vec4 eyePosition);
#define OSS_SLOT_TERM(s) oss_filterTerm(s, oss_shadowMap[s], oss_eyeToShadow[s], oss_eyePosition)
#else
#define OSS_SLOT_TERM(s) oss_pcf(oss_shadowMap[s], oss_eyeToShadow[s], oss_eyePosition)
#endif
#ifdef OSS_CUBE_FACES
// A point light's cube faces multiply its term (oss_shadow.frag.glsl); each light's colour
// is added once all its faces are in.
uniform int oss_slotOwner[OSS_MAX_SHADOW_SLOTS];
float oss_faceGate(int slot, vec4 eyePosition, float term);
#define OSS_ADD_SLOT(s) lightTerm[oss_slotOwner[s]] *= oss_faceGate(s, oss_eyePosition, OSS_SLOT_TERM(s))
#else
#define OSS_ADD_SLOT(s) color += OSS_SLOT_TERM(s) * oss_shadowedColor[s]
#endif

#if defined(OSS_DEBUG_MASK) || defined(OSS_DEBUG_CLASSES)
bool oss_facesLight(int n, vec3 p);
int oss_shadowSlotOf(int light);
vec2 oss_shadowSlotClass(int slot, vec4 eyePosition);
vec4 oss_classColor(bool silhouette, bool lit);

// The alpha the shading gives the fragment (1 unless the receiver is alpha-tested).
float oss_shadedAlpha()
{
#ifdef OSS_ALPHA_TEST
    vec3 shadowed[OSS_MAX_SHADOW_LIGHTS];
    float alpha = oss_fragmentLighting(shadowed).a;
#ifdef OSS_BASE_TEXTURE
    alpha *= texture(oss_baseTexture, oss_texCoord0.st).a;
#endif
    return alpha;
#else
    return 1.0;
#endif
}

void main()
{
    int n = oss_lightIndex[clamp(oss_maskLight, 0, OSS_MAX_SCENE_LIGHTS - 1)];
    bool facing = oss_facesLight(n, oss_eyePosition.xyz) && oss_maskLight < oss_numLights;
#ifdef OSS_DEBUG_CLASSES
    int slot = oss_shadowSlotOf(n);
    vec2 c = slot < 0 ? vec2(1.0, 0.0) : oss_shadowSlotClass(slot, oss_eyePosition);
    // HYBRID under a light with a size: yellow where its rays find a penumbra (c.y 2).
    vec3 penumbra = vec3(1.0, 1.0, 0.0);
    gl_FragColor = vec4(facing && c.y > 1.5 ? penumbra : oss_classColor(c.y > 0.5, facing && c.x >= 0.5).rgb,
                        oss_shadedAlpha());
#else
    // The term first, outside the branch: a filter takes derivatives.
    float term = oss_shadowTerm(n, oss_eyePosition);
#ifdef OSS_DEBUG_VISIBILITY
    float lit = facing ? clamp(term, 0.0, 1.0) : 0.0;
#else
    float lit = facing ? step(0.5, term) : 0.0;
#endif
    gl_FragColor = vec4(vec3(lit), oss_shadedAlpha());
#endif
}
#else
void main()
{
    vec3 oss_shadowedColor[OSS_MAX_SHADOW_LIGHTS];
    vec4 oss_unshadowedColor = oss_fragmentLighting(oss_shadowedColor);
    vec3 color = oss_unshadowedColor.rgb;
#ifdef OSS_TRIANGLE_LISTS
    bool oss_walkLight[OSS_MAX_SHADOW_LIGHTS];
    for (int l = 0; l < OSS_MAX_SHADOW_LIGHTS; ++l)
        oss_walkLight[l] = max(max(oss_shadowedColor[l].r, oss_shadowedColor[l].g), oss_shadowedColor[l].b) >= 0.5 / 255.0;
#endif
#ifdef OSS_CUBE_FACES
    float lightTerm[OSS_MAX_SHADOW_LIGHTS];
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        lightTerm[s] = 1.0;
#endif
#if OSS_NUM_SHADOW_SLOTS > 0 && !((OSS_SKIPPED_SLOTS >> 0) & 1)
    OSS_ADD_SLOT(0);
#endif
#if OSS_NUM_SHADOW_SLOTS > 1 && !((OSS_SKIPPED_SLOTS >> 1) & 1)
    OSS_ADD_SLOT(1);
#endif
#if OSS_NUM_SHADOW_SLOTS > 2 && !((OSS_SKIPPED_SLOTS >> 2) & 1)
    OSS_ADD_SLOT(2);
#endif
#if OSS_NUM_SHADOW_SLOTS > 3 && !((OSS_SKIPPED_SLOTS >> 3) & 1)
    OSS_ADD_SLOT(3);
#endif
#if OSS_NUM_SHADOW_SLOTS > 4 && !((OSS_SKIPPED_SLOTS >> 4) & 1)
    OSS_ADD_SLOT(4);
#endif
#if OSS_NUM_SHADOW_SLOTS > 5 && !((OSS_SKIPPED_SLOTS >> 5) & 1)
    OSS_ADD_SLOT(5);
#endif
#if OSS_NUM_SHADOW_SLOTS > 6 && !((OSS_SKIPPED_SLOTS >> 6) & 1)
    OSS_ADD_SLOT(6);
#endif
#if OSS_NUM_SHADOW_SLOTS > 7 && !((OSS_SKIPPED_SLOTS >> 7) & 1)
    OSS_ADD_SLOT(7);
#endif
#if OSS_NUM_SHADOW_SLOTS > 8 && !((OSS_SKIPPED_SLOTS >> 8) & 1)
    OSS_ADD_SLOT(8);
#endif
#if OSS_NUM_SHADOW_SLOTS > 9 && !((OSS_SKIPPED_SLOTS >> 9) & 1)
    OSS_ADD_SLOT(9);
#endif
#if OSS_NUM_SHADOW_SLOTS > 10 && !((OSS_SKIPPED_SLOTS >> 10) & 1)
    OSS_ADD_SLOT(10);
#endif
#if OSS_NUM_SHADOW_SLOTS > 11 && !((OSS_SKIPPED_SLOTS >> 11) & 1)
    OSS_ADD_SLOT(11);
#endif
    // Slots 12-23: SHADOW_MAP only (one texture unit per slot; shader::MAX_SHADOW_SLOTS).
#if OSS_NUM_SHADOW_SLOTS > 12 && !((OSS_SKIPPED_SLOTS >> 12) & 1)
    OSS_ADD_SLOT(12);
#endif
#if OSS_NUM_SHADOW_SLOTS > 13 && !((OSS_SKIPPED_SLOTS >> 13) & 1)
    OSS_ADD_SLOT(13);
#endif
#if OSS_NUM_SHADOW_SLOTS > 14 && !((OSS_SKIPPED_SLOTS >> 14) & 1)
    OSS_ADD_SLOT(14);
#endif
#if OSS_NUM_SHADOW_SLOTS > 15 && !((OSS_SKIPPED_SLOTS >> 15) & 1)
    OSS_ADD_SLOT(15);
#endif
#if OSS_NUM_SHADOW_SLOTS > 16 && !((OSS_SKIPPED_SLOTS >> 16) & 1)
    OSS_ADD_SLOT(16);
#endif
#if OSS_NUM_SHADOW_SLOTS > 17 && !((OSS_SKIPPED_SLOTS >> 17) & 1)
    OSS_ADD_SLOT(17);
#endif
#if OSS_NUM_SHADOW_SLOTS > 18 && !((OSS_SKIPPED_SLOTS >> 18) & 1)
    OSS_ADD_SLOT(18);
#endif
#if OSS_NUM_SHADOW_SLOTS > 19 && !((OSS_SKIPPED_SLOTS >> 19) & 1)
    OSS_ADD_SLOT(19);
#endif
#if OSS_NUM_SHADOW_SLOTS > 20 && !((OSS_SKIPPED_SLOTS >> 20) & 1)
    OSS_ADD_SLOT(20);
#endif
#if OSS_NUM_SHADOW_SLOTS > 21 && !((OSS_SKIPPED_SLOTS >> 21) & 1)
    OSS_ADD_SLOT(21);
#endif
#if OSS_NUM_SHADOW_SLOTS > 22 && !((OSS_SKIPPED_SLOTS >> 22) & 1)
    OSS_ADD_SLOT(22);
#endif
#if OSS_NUM_SHADOW_SLOTS > 23 && !((OSS_SKIPPED_SLOTS >> 23) & 1)
    OSS_ADD_SLOT(23);
#endif
#ifdef OSS_CUBE_FACES
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        color += lightTerm[s] * oss_shadowedColor[s];
#endif
    vec4 result = vec4(color, oss_unshadowedColor.a);
#ifdef OSS_BASE_TEXTURE
    result *= texture(oss_baseTexture, oss_texCoord0.st);
#endif
#if defined(OSS_SILHOUETTE_MAP) && (defined(OSS_DEBUG_SILHOUETTE_PIXELS) || defined(OSS_DEBUG_SILHOUETTE_MAP))
    vec4 overlay = oss_silhouetteDebug(oss_eyePosition);
    result.rgb = mix(result.rgb, overlay.rgb, overlay.a);
#endif
    gl_FragColor = result;
}
#endif
