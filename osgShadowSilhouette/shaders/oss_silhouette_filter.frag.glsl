#version 400 compatibility
// osgShadowSilhouette: SILHOUETTE_MAP's FILTER_SILHOUETTE, eye pass (docs/soft-shadows.md).
//
// Valient and Bujnak 2005, "GPU friendly, anti-aliased, soft shadow mapping", section 2.2.
// The distance map (oss_sildist.frag.glsl) holds, per depth texel, the signed distance d_E in
// texels to the nearest silhouette edge (positive on the casting side) and the edge's depth
// z_E. Where the four texels around the point all hold an edge in front of it (z_E < z), the
// boundary inside the cell is the bilinear interpolation of the four distances (exact for a
// straight edge) and the point's visibility across it:
//   size 0:  v = clamp(0.5 - d / f, 0, 1), f the pixel's footprint across the edge (texels);
//   sized:   v = 1 - F(d / r), r = oss_filterScale[s] (z - z_E) the penumbra's radius in
//            texels, F(x) = (acos(-x) + x sqrt(1 - x^2)) / pi the share of a disc cut off by
//            a line at signed distance x (the closed form of the paper's lookup texture).
// Other casters still shadow: the result is multiplied by the depth tests of the texels on
// the edge's outside (d_E < 0). Where the edge lies behind the point (the paper's rule: it
// cannot shadow it) the point is lit but where a caster nearer the light than that edge
// fails all four depth tests; a point on the casting side whose four depth tests all pass (a
// caster's own face beside its rim) is lit. Where a texel holds no edge: the depth map's bilinear
// 2x2 comparison.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_SILHOUETTE_MAP, OSS_FILTER_SILHOUETTE, OSS_MAX_SHADOW_LIGHTS, OSS_DEBUG_SILHOUETTE_MAP)
#if defined(OSS_SILHOUETTE_MAP) && defined(OSS_FILTER_SILHOUETTE)
#define OSS_SILDIST_MAX_PLANE_BIAS 0.01 // largest depth change the plane bias applies to a texel
#define OSS_SILDIST_SAMPLES_MIN_RADIUS 1.0 // penumbrae narrower than this (texels) take one sample
#define OSS_PI 3.14159265358979

uniform vec2 oss_filterScale[OSS_MAX_SHADOW_SLOTS]; // penumbra radius (texture space) per unit of depth

float oss_lookupBias(mat4 eyeToShadow, vec4 c, vec4 p); // oss_shadow.frag.glsl
vec2 oss_depthSlope(vec3 coord);

// The share of a unit disc on the far side of a line at signed distance x from its centre.
float oss_discCut(float x)
{
    x = clamp(x, -1.0, 1.0);
    return (acos(-x) + x * sqrt(1.0 - x * x)) / OSS_PI;
}

// The visibility across an edge at signed distance d (texels; > 0 on the casting side) for
// a penumbra of radius r and a pixel footprint f across the edge.
float oss_edgeVisibility(float d, float r, float f)
{
    if (r <= 0.0)
        return clamp(0.5 - d / f, 0.0, 1.0);
    // A penumbra narrower than the pixel: the disc's profile as wide as the footprint's box.
    return 1.0 - oss_discCut(d / max(r, 0.64 * f));
}

// The boundary inside a cell: the bilinear interpolation of its four signed distances
// (textureGather's order: (0,1), (1,1), (1,0), (0,0)) at the fraction f.
float oss_cellDistance(vec4 dist, vec2 f)
{
    return mix(mix(dist.w, dist.z, f.x), mix(dist.x, dist.y, f.x), f.y);
}

// What the extended map holds around texel position u (texel centres at integers) for a
// receiver at depth z: the 2x2 depth comparison and, where all four texels hold an edge,
// the bilinear boundary d, its gradient g in texels, the edge's depth zE and the outside
// texels' own depth tests.
struct OssEdgeCell
{
    float pcf;
    bool edge;
    float d;
    vec2 g;
    float zE;
    float litOutside;
};

OssEdgeCell oss_edgeCell(sampler2D depthMap, sampler2D distanceMap, vec2 u, float z, vec2 slope, vec2 size)
{
    OssEdgeCell cell;
    vec2 base = floor(u), f = u - base;
    vec2 at = (base + 1.0) / size;
    vec4 depth = textureGather(depthMap, at, 0);
    vec4 dx = (vec4(0.0, 1.0, 1.0, 0.0) - f.x) / size.x;
    vec4 dy = (vec4(1.0, 1.0, 0.0, 0.0) - f.y) / size.y;
    vec4 plane = clamp(dx * slope.x + dy * slope.y, -OSS_SILDIST_MAX_PLANE_BIAS, OSS_SILDIST_MAX_PLANE_BIAS);
    vec4 lit = vec4(lessThanEqual(z + plane, depth));
    vec4 weight = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    cell.pcf = dot(lit, weight);
    vec4 dist = textureGather(distanceMap, at, 0);
    cell.edge = !any(greaterThan(abs(dist), vec4(0.5 * OSS_SILDIST_NO_EDGE)));
    if (!cell.edge)
        return cell;
    cell.d = oss_cellDistance(dist, f);
    cell.g = vec2(mix(dist.z - dist.w, dist.y - dist.x, f.y), mix(dist.x - dist.w, dist.y - dist.z, f.x));
    cell.zE = oss_cellDistance(textureGather(distanceMap, at, 1), f);
    // Other casters still shadow: the outside texels' own depth tests.
    vec4 outside = vec4(lessThan(dist, vec4(0.0)));
    float outsideCount = dot(outside, vec4(1.0));
    cell.litOutside = outsideCount > 0.0 ? dot(lit, outside) / outsideCount : 1.0;
    return cell;
}

// One sample: the visibility of a receiver at depth z across the cell's edge for a penumbra
// of radius `radius` (z - z_E) texels (0: the anti-aliased hard edge), the sample's share of
// the pixel's footprint being `share`. zEdge: the edge's depth, or z where the answer does
// not come from an edge in front of the point (no penumbra there).
float oss_edgeSample(OssEdgeCell cell, float z, float radius, float share, vec2 ux, vec2 uy, out float zEdge)
{
    zEdge = z;
    if (!cell.edge)
        return cell.pcf;
    // An edge behind the point cannot shadow it (Valient and Bujnak's rule): outside the
    // edge the outside texels' tests answer; on its casting side the point is shadowed only
    // where all four depth tests fail, by a caster nearer the light than the edge (any that
    // passes: the point lies on the edge's own caster beside its rim). A point on the
    // casting side whose four depth tests all pass is lit (a caster's own face, or in front).
    if (cell.zE >= z)
        return cell.d < 0.0 ? cell.litOutside : (cell.pcf > 0.0 ? 1.0 : 0.0);
    if (cell.d > 0.0 && cell.pcf >= 1.0)
        return 1.0;
    zEdge = cell.zE;
    float footprint = share * max(abs(dot(cell.g, ux)) + abs(dot(cell.g, uy)), 1e-3);
    return oss_edgeVisibility(cell.d, radius * (z - cell.zE), footprint) * cell.litOutside;
}

float oss_silhouetteFilterTerm(int s, sampler2D depthMap, sampler2D distanceMap, mat4 eyeToShadow, vec4 eyePosition)
{
    vec4 c = eyeToShadow * eyePosition;
    vec3 t = c.xyz / c.w;
    vec2 slope = oss_depthSlope(t); // derivatives: before any branch
    vec2 size = vec2(textureSize(depthMap, 0));
    vec2 u = t.xy * size - 0.5;
    vec2 ux = dFdx(u), uy = dFdy(u);
    if (c.w <= 0.0)
        return 1.0; // behind a perspective light: outside its map
    t.z = min(t.z - oss_lookupBias(eyeToShadow, c, eyePosition), 1.0);
    float scale = oss_filterScale[s].x * size.x; // penumbra radius in texels per unit of depth
    float zE;
    OssEdgeCell here = oss_edgeCell(depthMap, distanceMap, u, t.z, slope, size);
    float centre = oss_edgeSample(here, t.z, scale, 1.0, ux, uy, zE);
    float r = scale * (t.z - zE);
    if (r < OSS_SILDIST_SAMPLES_MIN_RADIUS)
        return centre;
    // The paper's samples around the point, seven here: the light's disc, seen through the
    // blocker plane as a disc of radius r texels around u, split into a centre disc of radius
    // r / 3 and six sectors of the ring around it, each answered as an equal-area disc
    // (radius 0.385 r) at its sector's centroid (0.689 r from u) across its own nearest edge,
    // weighted by area (1/9 and 8/54); the receiver's plane gives each its depth. Where two
    // edges lie inside the penumbra (a caster thinner than it, touching silhouettes) the
    // samples see different edges, which one sample across the nearest edge cannot.
    float zEc;
    float v = oss_edgeSample(here, t.z, scale / 3.0, 1.0 / 3.0, ux, uy, zEc) / 9.0;
    for (int k = 0; k < 6; ++k)
    {
        float a = 1.04719755 * float(k);
        // (At most SILDIST_SAMPLE_REACH texels away: within a cube face's margin.)
        vec2 offset = min(0.689 * r, OSS_SILDIST_SAMPLE_REACH) * vec2(cos(a), sin(a));
        float zk = t.z + dot(slope, offset / size), zEk;
        OssEdgeCell cell = oss_edgeCell(depthMap, distanceMap, u + offset, zk, slope, size);
        float vk = oss_edgeSample(cell, zk, 0.385 * scale, 0.385, ux, uy, zEk);
        v += vk * (8.0 / 54.0);
    }
    return v;
}

#ifdef OSS_DEBUG_SILHOUETTE_MAP
uniform int oss_maskLight;
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform sampler2D oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS]; // distance maps
int oss_shadowSlotOf(int light);

// DebugView DEBUG_SILHOUETTE_MAP under FILTER_SILHOUETTE: the distance map of the light
// oss_maskLight projected on the scene (rgb, opacity). Orange on an edge's casting side, blue
// outside it, fading over 8 texels; white where the bilinear boundary (d = 0) passes; clear
// where no edge lies within the band.
vec4 oss_distanceOverlay(sampler2D distanceMap, mat4 eyeToShadow, vec4 eyePosition)
{
    vec4 c = eyeToShadow * eyePosition;
    vec2 size = vec2(textureSize(distanceMap, 0));
    vec2 u = (c.xy / c.w) * size - 0.5;
    vec2 base = floor(u), f = u - base;
    vec4 dist = textureGather(distanceMap, (base + 1.0) / size, 0);
    float d = oss_cellDistance(dist, f); // as the eye term reads it
    float perPixel = fwidth(d);
    if (c.w <= 0.0 || any(greaterThan(abs(dist), vec4(0.5 * OSS_SILDIST_NO_EDGE))))
        return vec4(0.0);
    if (abs(d) < max(perPixel, 0.05))
        return vec4(1.0);
    vec3 side = d > 0.0 ? vec3(1.0, 0.55, 0.1) : vec3(0.1, 0.6, 1.0);
    return vec4(side, 0.8 * exp(-abs(d) / 8.0));
}

vec4 oss_silhouetteDebug(vec4 eyePosition)
{
    int slot = oss_shadowSlotOf(oss_lightIndex[clamp(oss_maskLight, 0, OSS_MAX_SCENE_LIGHTS - 1)]);
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        if (s == slot)
            return oss_distanceOverlay(oss_silhouetteMap[s], oss_eyeToShadow[s], eyePosition);
    return vec4(0.0);
}
#endif
#else
// (A translation unit may not be empty.)
const int oss_silhouetteFilterUnused = 0;
#endif
