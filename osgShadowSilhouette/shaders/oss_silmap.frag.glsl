#version 400 compatibility
// osgShadowSilhouette: silhouette-map pass, fragment stage.
//
// Picks the silhouette point of an edge in this fragment's silhouette texel (Sen,
// Cammarano, Hanrahan 2003, section 4.2; Chan's course notes, "Create Silhouette Map"):
//   1. an endpoint inside the texel: that endpoint (a first);
//   2. one crossing with the texel's diagonals: that crossing;
//   3. two crossings: their midpoint;
//   4. none: discard (the thin quad also covers texels the edge misses).
// Then discards the edge where it lies behind all four neighbouring depth samples (an
// occluded silhouette), and writes the point in the texel's local coordinates.
// HYBRID's edge mask (OSS_SILMAP_COMPARE) writes a depth instead, blended by MIN: the nearest
// the edges crossing the texel come to the light anywhere in it (docs/shadow-volumes.md).
// The C++ twin is pickSilhouettePoint() in osgShadowSilhouette/SilhouettePoints; keep
// them identical (tests/gl/test_silhouette_map.cpp compares them).

#pragma import_defines(OSS_SILMAP_COMPARE)
#ifdef OSS_SILMAP_COMPARE
// HYBRID's edge mask: the depth map keeps its hardware comparison (LEQUAL), the gather
// returns the four tests of the edge's depth instead of the four depths.
uniform sampler2DShadow oss_silmapDepth;
#else
uniform sampler2D oss_silmapDepth;      // the light's depth map, read without comparison
#endif
uniform float oss_silmapDepthBias;       // slack of the occlusion test, in [0, 1] depth

flat in vec4 oss_edge;
flat in vec2 oss_edgeDepth;
flat in float oss_edgeDepthSlope;

float oss_cross(vec2 a, vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

bool oss_insideTexel(vec2 p)
{
    return all(greaterThanEqual(p, vec2(0.0))) && all(lessThanEqual(p, vec2(1.0)));
}

// Parameter t along a -> b where the segment meets d0 -> d1; a collinear overlap counts as
// one crossing at its middle.
bool oss_crossSegment(vec2 a, vec2 b, vec2 d0, vec2 d1, out float t)
{
    vec2 r = b - a, s = d1 - d0, w = d0 - a;
    float denom = oss_cross(r, s);
    t = 0.0;
    if (denom != 0.0)
    {
        t = oss_cross(w, s) / denom;
        float u = oss_cross(w, r) / denom;
        return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
    }
    float rr = dot(r, r);
    if (oss_cross(w, r) != 0.0 || rr == 0.0)
        return false;
    float t0 = dot(w, r) / rr, t1 = dot(d1 - a, r) / rr;
    float lo = max(0.0, min(t0, t1)), hi = min(1.0, max(t0, t1));
    t = 0.5 * (lo + hi);
    return lo <= hi;
}

// The silhouette point of edge a -> b (local coordinates) and its parameter t along the edge.
bool oss_pickSilhouettePoint(vec2 a, vec2 b, out vec2 point, out float t)
{
    point = a;
    t = 0.0;
    if (oss_insideTexel(a))
        return true;
    point = b;
    t = 1.0;
    if (oss_insideTexel(b))
        return true;
    float t1, t2;
    bool hit1 = oss_crossSegment(a, b, vec2(0.0, 0.0), vec2(1.0, 1.0), t1);
    bool hit2 = oss_crossSegment(a, b, vec2(1.0, 0.0), vec2(0.0, 1.0), t2);
    t = hit1 && hit2 ? 0.5 * (t1 + t2) : (hit1 ? t1 : t2);
    point = a + (b - a) * t;
    return hit1 || hit2;
}

void main()
{
    vec2 texel = floor(gl_FragCoord.xy);
    vec2 point;
    float t;
    if (!oss_pickSilhouettePoint(oss_edge.xy - texel, oss_edge.zw - texel, point, t))
        discard;
    float depth = mix(oss_edgeDepth.x, oss_edgeDepth.y, t);
    // Texel (i, j) lies between depth samples i, i+1 and j, j+1: gather around their middle.
    vec2 size = vec2(textureSize(oss_silmapDepth, 0));
#ifdef OSS_SILMAP_COMPARE
    vec4 front = textureGather(oss_silmapDepth, (texel + 1.0) / size, depth - oss_silmapDepthBias);
    if (all(equal(front, vec4(0.0))))
        discard;
    // The nearest the edge comes to the light anywhere in the texel: its depth at the picked
    // point less its change along a texel diagonal (sqrt(2) texels, with margin). The eye pass
    // counts the edge only at points behind that depth: a convex caster's own rim, which lies
    // behind the lit face beside it, then no longer sends that face to the exact test.
    gl_FragColor = vec4(depth - 1.5 * oss_edgeDepthSlope, 0.0, 0.0, 1.0);
    return;
#else
    vec4 samples = textureGather(oss_silmapDepth, (texel + 1.0) / size);
    if (all(greaterThan(vec4(depth - oss_silmapDepthBias), samples)))
        discard;
#endif
    // One channel: X * 4096 + Y, X and Y the coordinates in 1/2048 texel (encodeSilhouettePoint()).
    vec2 q = floor(clamp(point, 0.0, 1.0) * 2048.0 + 0.5);
    gl_FragColor = vec4(q.x * 4096.0 + q.y, 0.0, 0.0, 1.0);
}
