#version 400 compatibility
// osgShadowSilhouette: the shadow term of the silhouette-map mode (eye pass).
//
// Sen, Cammarano, Hanrahan, "Shadow Silhouette Maps", SIGGRAPH 2003, section 4.3.
// The sample is compared with the four depth samples around it (one textureGather). When
// they agree (not a silhouette pixel) that is the result and nothing else is read. When they
// disagree (a silhouette pixel), the five silhouette points of the texel and its four
// neighbours (one texelFetch of the neighbourhood map, oss_silnbr.frag.glsl) split the texel
// into four quadrants of two wedges each, and the sample takes the depth-test result of the
// corner whose wedge holds it.
// Frames: see osgShadowSilhouette/SilhouettePoints; the C++ twin is silhouetteMapLit().
// Compiled empty unless OSS_SILHOUETTE_MAP is defined.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_SILHOUETTE_MAP, OSS_MAX_SHADOW_LIGHTS, OSS_DEBUG_SILHOUETTE_PIXELS, OSS_DEBUG_SILHOUETTE_MAP, OSS_FILTER_SILHOUETTE)
#ifdef OSS_SILHOUETTE_MAP
#define OSS_MAX_PLANE_BIAS 0.01 // largest depth change the plane bias applies to a corner

// Where a sample falls in the depth and silhouette maps.
struct oss_SilhouetteSample
{
    ivec2 texel;   // silhouette texel = the depth samples texel .. texel + 1
    vec2 local;    // position in that texel, [0, 1]^2
    vec4 depths;   // depth samples at its corners as textureGather returns them: NW, NE, SE, SW
    vec4 lit;      // their depth tests (GL_LEQUAL: 1 where the sample is not behind), same order
    vec3 coord;    // light texture coordinates and depth, less the lookup bias
    vec2 depthSlope; // d depth / d texture coordinate of the receiver's plane
};

vec2 oss_depthSlope(vec3 coord); // oss_shadow.frag.glsl

float oss_lookupBias(mat4 eyeToShadow, vec4 c, vec4 p); // oss_shadow.frag.glsl

// False for points behind a perspective light (outside its map: lit).
bool oss_silhouetteSample(sampler2D depthMap, mat4 eyeToShadow, vec4 eyePosition, out oss_SilhouetteSample s)
{
    vec4 c = eyeToShadow * eyePosition;
    vec3 t = c.xyz / c.w;
    s.depthSlope = oss_depthSlope(t);
    t.z -= oss_lookupBias(eyeToShadow, c, eyePosition);
    // Beyond the map's far plane compares as at it, as the other modes' hardware comparison
    // clamps its reference: lit where the map holds no caster (a receiver past
    // MaximumShadowMapDistance, outside the map).
    t.z = min(t.z, 1.0);
    s.coord = t;
    s.texel = ivec2(0);
    s.local = vec2(0.5);
    s.depths = vec4(1.0);
    s.lit = vec4(1.0);
    if (c.w <= 0.0)
        return false;
    vec2 size = vec2(textureSize(depthMap, 0));
    vec2 u = t.xy * size - 0.5;
    vec2 cell = floor(u);
    s.texel = ivec2(cell);
    s.local = u - cell;
    // Gather at the middle of the four samples, so that the footprint is exactly these four.
    s.depths = textureGather(depthMap, (cell + 1.0) / size);
    s.lit = vec4(lessThanEqual(vec4(t.z), s.depths));
    return true;
}

// A point's 24-bit stored value (decodeSilhouettePoint()) as its coordinates.
vec2 oss_decodePoint(uint stored)
{
    return vec2(uvec2(stored >> 12u, stored & 0xFFFu)) / 2048.0;
}

// The five silhouette points in the frame of the centre texel, from one texel of the
// neighbourhood map (oss_silnbr.frag.glsl, unpackNeighbourhood()): texel k of the silhouette
// map is its texel k + 1. Outside it (samples whose depth corners all lie outside the depth
// map, never silhouette pixels) the fetch is clamped to the border.
void oss_silhouettePoints(usampler2D neighbourhood, ivec2 texel, out vec2 c, out vec2 e, out vec2 n, out vec2 w,
                          out vec2 s)
{
    ivec2 last = textureSize(neighbourhood, 0) - 1;
    uvec4 v = texelFetch(neighbourhood, clamp(texel + 1, ivec2(0), last), 0);
    uvec3 top = v.xyz >> 24u;
    c = oss_decodePoint(v.x & 0xFFFFFFu);
    e = oss_decodePoint(v.y & 0xFFFFFFu) + vec2(1.0, 0.0);
    n = oss_decodePoint(v.z & 0xFFFFFFu) + vec2(0.0, 1.0);
    w = oss_decodePoint(v.w) - vec2(1.0, 0.0);
    s = oss_decodePoint(top.x | (top.y << 8u) | (top.z << 16u)) - vec2(0.0, 1.0);
}

float oss_cross2(vec2 a, vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

// The corner (0 SW, 1 SE, 2 NE, 3 NW) whose quadrant holds p. The rays from c to its four
// neighbours e, n, w, s split the plane around c into four sectors, counter-clockwise
// NE (e..n), NW (n..w), SW (w..s), SE (s..e), each closed, tried in that order; a sector
// wider than half a turn holds what lies on the near side of either of its rays. Within the
// texel this is the union of the sector's two wedges (c, e, NE) + (c, NE, n) of the paper,
// because every point lies in its own texel (wedgeCorner() in SilhouettePoints).
int oss_wedgeCorner(vec2 c, vec2 e, vec2 n, vec2 w, vec2 s, vec2 p)
{
    vec2 q = p - c;
    vec2 de = e - c, dn = n - c, dw = w - c, ds = s - c;
    vec4 side = vec4(oss_cross2(de, q), oss_cross2(dn, q), oss_cross2(dw, q), oss_cross2(ds, q));
    vec4 turn = vec4(oss_cross2(de, dn), oss_cross2(dn, dw), oss_cross2(dw, ds), oss_cross2(ds, de));
    bvec4 from = greaterThanEqual(side, vec4(0.0)); // on or counter-clockwise of the sector's first ray
    bvec4 to = lessThanEqual(side.yzwx, vec4(0.0)); // on or clockwise of its last ray
    bvec4 convex = greaterThanEqual(turn, vec4(0.0));
    bvec4 inside = bvec4(convex.x ? from.x && to.x : from.x || to.x, convex.y ? from.y && to.y : from.y || to.y,
                         convex.z ? from.z && to.z : from.z || to.z, convex.w ? from.w && to.w : from.w || to.w);
    return inside.x ? 2 : inside.y ? 3 : inside.z ? 0 : inside.w ? 1 : (p.x >= 0.5 ? (p.y >= 0.5 ? 2 : 1) : (p.y >= 0.5 ? 3 : 0));
}

// The depth tests of the four corners, each against the receiver's plane extended to that
// corner rather than against the sample's own depth: near a caster's own silhouette (where
// it receives light at grazing angles) the corners lie up to a texel away on a steep slope.
// Order as textureGather: NW, NE, SE, SW.
vec4 oss_planeBiasedTests(vec2 mapSize, oss_SilhouetteSample s)
{
    vec4 dx = (vec4(0.0, 1.0, 1.0, 0.0) - s.local.x) / mapSize.x;
    vec4 dy = (vec4(1.0, 1.0, 0.0, 0.0) - s.local.y) / mapSize.y;
    vec4 bias = clamp(dx * s.depthSlope.x + dy * s.depthSlope.y, -OSS_MAX_PLANE_BIAS, OSS_MAX_PLANE_BIAS);
    return vec4(lessThanEqual(s.coord.z + bias, s.depths));
}

// The shadow test of a silhouette pixel from the five silhouette points.
float oss_silhouetteReconstruct(usampler2D silhouetteMap, oss_SilhouetteSample s)
{
    vec2 c, e, n, w, so;
    oss_silhouettePoints(silhouetteMap, s.texel, c, e, n, w, so);
    vec4 byCorner = s.lit.wzyx; // SW, SE, NE, NW
    return byCorner[oss_wedgeCorner(c, e, n, w, so, s.local)];
}

bool oss_isSilhouettePixel(oss_SilhouetteSample s)
{
    float pcf = dot(s.lit, vec4(0.25));
    return pcf > 0.0 && pcf < 1.0;
}

// 1 lit, 0 shadowed.
float oss_silhouetteTerm(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition)
{
    oss_SilhouetteSample s;
    if (!oss_silhouetteSample(depthMap, eyeToShadow, eyePosition, s))
        return 1.0;
    float lit = s.lit.x;
    if (oss_isSilhouettePixel(s)) // the branch that lets GPUs skip the reconstruction
    {
        s.lit = oss_planeBiasedTests(vec2(textureSize(depthMap, 0)), s);
        bool reconstruct = oss_isSilhouettePixel(s);
        // SIMD rasterizers (llvmpipe) run this block for every lane of a pixel block, and a
        // lane's fetch reads memory whether the lane is active or not: lanes that do not
        // reconstruct all read the same texel, which stays in cache. (Half the frame at map
        // size 2048 without it; GPUs skip the inactive lanes either way.)
        s.texel = reconstruct ? s.texel : ivec2(-1);
        float exact = oss_silhouetteReconstruct(silhouetteMap, s);
        lit = reconstruct ? exact : s.lit.x;
    }
    return lit;
}

// DebugView DEBUG_CLASSES: x the term of oss_silhouetteTerm(), y 1 where it reconstructed.
vec2 oss_silhouetteClass(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition)
{
    oss_SilhouetteSample s;
    if (!oss_silhouetteSample(depthMap, eyeToShadow, eyePosition, s))
        return vec2(1.0, 0.0);
    if (!oss_isSilhouettePixel(s))
        return vec2(s.lit.x, 0.0);
    s.lit = oss_planeBiasedTests(vec2(textureSize(depthMap, 0)), s);
    return oss_isSilhouettePixel(s) ? vec2(oss_silhouetteReconstruct(silhouetteMap, s), 1.0) : vec2(s.lit.x, 0.0);
}

// Debug view: the silhouette map projected onto the scene. Silhouette texels that hold an
// edge point are tinted yellow and their point drawn as a red dot; where a texel covers
// several pixels the dual grid is drawn too.
vec4 oss_silhouetteMapOverlay(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition)
{
    oss_SilhouetteSample s;
    if (!oss_silhouetteSample(depthMap, eyeToShadow, eyePosition, s))
        return vec4(0.0);
    vec2 c, e, n, w, so;
    oss_silhouettePoints(silhouetteMap, s.texel, c, e, n, w, so);
    vec2 perPixel = fwidth(s.local);
    float texelPixels = 1.0 / max(max(perPixel.x, perPixel.y), 1e-6);
    bool moved = any(notEqual(c, vec2(0.5)));
    if (moved && distance(s.local, c) < max(0.12, 1.5 / texelPixels))
        return vec4(1.0, 0.0, 0.0, 1.0);
    if (texelPixels > 6.0 && any(lessThan(min(s.local, 1.0 - s.local), perPixel)))
        return vec4(0.1, 0.1, 0.1, 0.5);
    return moved ? vec4(1.0, 0.9, 0.2, 0.6) : vec4(0.0);
}

// Debug view: 1 at silhouette pixels.
float oss_silhouettePixelOverlay(sampler2D depthMap, mat4 eyeToShadow, vec4 eyePosition)
{
    oss_SilhouetteSample s;
    return oss_silhouetteSample(depthMap, eyeToShadow, eyePosition, s) && oss_isSilhouettePixel(s) ? 1.0 : 0.0;
}

// (Under FILTER_SILHOUETTE the second maps hold distances: oss_silhouette_filter.frag.glsl
// draws DEBUG_SILHOUETTE_MAP.)
#if (defined(OSS_DEBUG_SILHOUETTE_PIXELS) || defined(OSS_DEBUG_SILHOUETTE_MAP)) && !defined(OSS_FILTER_SILHOUETTE)
uniform int oss_maskLight;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform sampler2D oss_shadowMap[OSS_MAX_SHADOW_SLOTS];
uniform usampler2D oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS]; // neighbourhood maps
int oss_shadowSlotOf(int light);

// The debug overlay (rgb, opacity) of the light oss_maskLight (see the DebugView values).
vec4 oss_silhouetteDebug(vec4 eyePosition)
{
    int slot = oss_shadowSlotOf(oss_lightIndex[clamp(oss_maskLight, 0, OSS_MAX_SCENE_LIGHTS - 1)]);
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
    {
        if (s != slot)
            continue;
#ifdef OSS_DEBUG_SILHOUETTE_MAP
        return oss_silhouetteMapOverlay(oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], eyePosition);
#else
        return vec4(0.0, 1.0, 0.0, 0.75 * oss_silhouettePixelOverlay(oss_shadowMap[s], oss_eyeToShadow[s], eyePosition));
#endif
    }
    return vec4(0.0);
}
#endif

#else
// (A translation unit may not be empty.)
const int oss_silhouetteMapUnused = 0;
#endif
