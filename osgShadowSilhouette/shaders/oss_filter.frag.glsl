#version 400 compatibility
// osgShadowSilhouette: SHADOW_MAP's soft filters (property Filter; docs/soft-shadows.md).
//
// Under a filter the depth maps hold raw depths (no hardware comparison), so that PCSS can
// average its blockers' depths. Every comparison is made here, four texels at a time with
// textureGather, against the receiver's plane extended to the texel (receiver plane depth
// bias, Isidoro 2006) less the lookup bias of oss_shadow.frag.glsl: a window many texels wide
// on a sloped receiver would otherwise shadow the receiver with itself.
//
// FILTER_PCF (OSS_FILTER_PCF = N): Doverspike's N x N window of depth comparisons, each tap a
// bilinear 2x2 PCF, the taps one texel apart: the (N + 1) x (N + 1) texels under the window
// weighted by a box of N texels convolved with the bilinear tent, so that the answer moves
// smoothly with the point. N = 1 is the baseline's 2x2 PCF.
//
// FILTER_PCSS: percentage-closer soft shadows (Fernando 2005). oss_filterScale[s] is the
// penumbra's radius in texture space per unit of map depth between blocker and receiver
// (PenumbraScale in SoftFilter.cpp: exact for a blocker and a receiver on one line from the
// light's centre, orthographic and perspective maps alike). (1) Blocker search: the texels
// in front of the receiver's plane within the radius a blocker at the map's near plane would
// give, 4 x 4 gathers; none: lit. (2) The penumbra's radius from the blockers' mean depth.
// (3) A disc of bilinear PCF taps that wide (the 6 x 6 grid's taps inside the circle). Radii
// are capped at OSS_PCSS_MAX_RADIUS_TEXELS; a radius below a texel gives the 2x2 PCF.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_FILTER_PCF, OSS_FILTER_PCSS)

#if defined(OSS_FILTER_PCF) || defined(OSS_FILTER_PCSS)
uniform vec2 oss_filterScale[OSS_MAX_SHADOW_SLOTS];

float oss_lookupBias(mat4 eyeToShadow, vec4 c, vec4 p); // oss_shadow.frag.glsl
vec2 oss_depthSlope(vec3 coord);

// The four texels from texel `base` (textureGather's order: (0,1), (1,1), (1,0), (0,0)):
// their depths, and 1 where a texel is not in front of the receiver's plane there (lit).
vec4 oss_gatherLit(sampler2D map, vec2 base, vec2 size, vec3 t, vec2 slope, float bias, out vec4 depth)
{
    depth = textureGather(map, (base + 1.0) / size, 0);
    vec4 dx = (base.x + vec4(0.5, 1.5, 1.5, 0.5)) / size.x - t.x;
    vec4 dy = (base.y + vec4(1.5, 1.5, 0.5, 0.5)) / size.y - t.y;
    vec4 plane = t.z + dx * slope.x + dy * slope.y - bias;
    return step(plane, depth);
}

// A bilinear 2x2 PCF tap at texture point q.
float oss_bilinearLit(sampler2D map, vec2 q, vec2 size, vec3 t, vec2 slope, float bias)
{
    vec2 u = q * size - 0.5;
    vec2 base = floor(u), f = u - base;
    vec4 depth;
    vec4 lit = oss_gatherLit(map, base, size, t, slope, bias, depth);
    return dot(lit, vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y)));
}

#ifdef OSS_FILTER_PCF
// Weight of texel k (0 .. n) of the window along one axis: 1 - f, 1, ..., 1, f; 0 past n.
float oss_windowWeight(int k, int n, float f)
{
    return k == 0 ? 1.0 - f : (k == n ? f : (k > n ? 0.0 : 1.0));
}

float oss_pcfWindow(sampler2D map, vec3 t, vec2 slope, float bias)
{
    const int n = OSS_FILTER_PCF;
    vec2 size = vec2(textureSize(map, 0));
    vec2 first = t.xy * size - 0.5 - 0.5 * float(n - 1); // the first tap, in texel-centre units
    vec2 base = floor(first), f = first - base;
    float sum = 0.0;
    for (int j = 0; j <= n; j += 2)
        for (int i = 0; i <= n; i += 2)
        {
            vec4 depth;
            vec4 lit = oss_gatherLit(map, base + vec2(i, j), size, t, slope, bias, depth);
            vec2 w0 = vec2(oss_windowWeight(i, n, f.x), oss_windowWeight(j, n, f.y));
            vec2 w1 = vec2(oss_windowWeight(i + 1, n, f.x), oss_windowWeight(j + 1, n, f.y));
            sum += dot(lit, vec4(w0.x * w1.y, w1.x * w1.y, w1.x * w0.y, w0.x * w0.y));
        }
    return sum / float(n * n);
}
#endif

#ifdef OSS_FILTER_PCSS
// Offset of tap (i, j) of a k x k grid over the square [-1, 1]^2 (cell centres).
vec2 oss_gridTap(int i, int j, int k)
{
    return (vec2(i, j) + 0.5) * (2.0 / float(k)) - 1.0;
}

float oss_pcss(vec2 scale, sampler2D map, vec3 t, vec2 slope, float bias)
{
    vec2 size = vec2(textureSize(map, 0));
    vec2 maxRadius = OSS_PCSS_MAX_RADIUS_TEXELS / size;
    vec2 search = min(scale * max(t.z, 0.0), maxRadius);
    float blockers = 0.0, blockerDepth = 0.0;
    for (int j = 0; j < OSS_PCSS_SEARCH_TAPS; ++j)
        for (int i = 0; i < OSS_PCSS_SEARCH_TAPS; ++i)
        {
            vec2 u = (t.xy + oss_gridTap(i, j, OSS_PCSS_SEARCH_TAPS) * search) * size - 0.5;
            vec4 depth;
            vec4 blocked = 1.0 - oss_gatherLit(map, floor(u), size, t, slope, bias, depth);
            blockers += dot(blocked, vec4(1.0));
            blockerDepth += dot(blocked, depth);
        }
    if (blockers == 0.0)
        return 1.0;
    vec2 radius = min(scale * max(t.z - blockerDepth / blockers, 0.0), maxRadius);
    float sum = 0.0, taps = 0.0;
    for (int j = 0; j < OSS_PCSS_FILTER_TAPS; ++j)
        for (int i = 0; i < OSS_PCSS_FILTER_TAPS; ++i)
        {
            vec2 o = oss_gridTap(i, j, OSS_PCSS_FILTER_TAPS);
            if (dot(o, o) > 1.0)
                continue;
            sum += oss_bilinearLit(map, t.xy + o * radius, size, t, slope, bias);
            taps += 1.0;
        }
    return sum / taps;
}
#endif

// The filtered shadow term of slot s (map `map`, eye -> light texture `eyeToShadow`) at an
// eye-space position: 1 lit, 0 shadowed, fractions in penumbrae and along filtered edges.
float oss_filterTerm(int s, sampler2D map, mat4 eyeToShadow, vec4 eyePosition)
{
    vec4 c = eyeToShadow * eyePosition;
    vec3 t = c.xyz / c.w;
    vec2 slope = oss_depthSlope(t); // derivatives: before any branch
    if (c.w <= 0.0)
        return 1.0; // behind a perspective light: outside its map
    float bias = oss_lookupBias(eyeToShadow, c, eyePosition);
#ifdef OSS_FILTER_PCSS
    return oss_pcss(oss_filterScale[s], map, t, slope, bias);
#else
    return oss_pcfWindow(map, t, slope, bias);
#endif
}
#else
// (A translation unit may not be empty.)
const int oss_filterUnused = 0;
#endif
