#version 430 compatibility
// osgShadowSilhouette: triangle-list pass, geometry stage.
//
// Stores each caster triangle once in the light's list buffer (texture-space x, y and a
// depth that is linear across the projected triangle) and covers its bounding box, grown by
// half a texel, with a quad: every texel the triangle touches gets a fragment, and the
// fragment stage keeps exactly those (conservative rasterization, as in irregular
// z-buffers). A triangle reaching behind a perspective light's eye plane is listed as its
// part beyond the near plane (one or two triangles), the part the depth pass draws.
//
// List buffer layout (uints, G the grid size): [0] node count, [1] triangle count, [2] 1 when
// any triangle reached the map, listed or not (the technique keeps the slot in the eye pass
// then), [3] the nearest depth listed (1 - z, or 1/w: grows toward the light; 0: none); G*G heads (first node + 1, 0: empty list); G*G counts; nodeCapacity
// (even) nodes of (triangle, next node + 1); triangleCapacity triangles of three vec4 (x0 y0 x1 y1)
// (x2 y2 q0 q1) (q2 cut 0 0) with q = z for an orthographic light, -1/w for a perspective one
// (both grow away from the light and are linear in texture-space x, y); cut is 1 for an
// alpha-tested caster's triangle (OSS_ALPHA_TEST): its texture's cut-outs are in the depth
// map, not in the list, so a point it covers keeps the map's answer (oss_listWalk()).
//
// A triangle that cannot stand between the light and any receiver (every corner of the
// receivers' world box lies on the light's side of its plane, or within oss_listReceiverSlack
// beyond it: a ground plane under the light, for instance) is left out altogether: no
// shadow ray toward the light from a receiver crosses its plane. Grounds are listed in
// every texel they cover otherwise, and would lengthen every walk.
//
// A closed caster (oss_listFrontOnly) lists only its triangles wound counter-clockwise in
// the light's view, those facing the light: a shadow ray that meets a closed surface leaves
// it through one of them, whether it starts outside (it also crossed a face turned away)
// or inside (a room around the receiver). The lists are about half as long. Mirrored draws
// of closed casters list both sides (the technique does not mark them).

#pragma import_defines(OSS_ALPHA_TEST)

layout(triangles) in;
layout(triangle_strip, max_vertices = 8) out;

layout(std430, binding = 0) buffer OssList { uint oss_list[]; };
uniform uint oss_listNodeCapacity;
uniform uint oss_listTriangleCapacity;
uniform vec2 oss_listGridSize;
uniform bool oss_listPerspective; // the light's projection
uniform bool oss_listFrontOnly;   // a closed caster: counter-clockwise triangles only
uniform vec3 oss_listReceivers[8];   // the corners of the receivers' world box, in the light's view space
uniform float oss_listReceiverSlack; // how far beyond a triangle's plane a corner still counts as on it

flat out uint oss_triangle;
flat out vec2 oss_v0, oss_v1, oss_v2; // texture space

// Whether some corner of the receivers' box lies beyond the plane of the triangle (light
// view space) from the light: only then can the triangle shadow a receiver.
bool oss_canShadowReceivers(vec3 v0, vec3 v1, vec3 v2)
{
    vec3 n = cross(v1 - v0, v2 - v0);
    float len = length(n);
    if (!(len > 0.0))
        return true; // degenerate: the other tests decide
    n /= len;
    // The light's side: the eye of a perspective light, +z (toward the light) for a directional one.
    float light = oss_listPerspective ? -dot(n, v0) : n.z;
    if (light == 0.0)
        return true; // edge-on: the area test decides
    float side = sign(light);
    for (int i = 0; i < 8; ++i)
        if (side * dot(n, oss_listReceivers[i] - v0) < -oss_listReceiverSlack)
            return true;
    return false;
}

// Lists triangle c0 c1 c2 (the light's clip space, every w > 0) in the texels it touches.
void oss_listTriangle(vec4 c0, vec4 c1, vec4 c2)
{
    vec3 t0 = c0.xyz / c0.w * 0.5 + 0.5, t1 = c1.xyz / c1.w * 0.5 + 0.5, t2 = c2.xyz / c2.w * 0.5 + 0.5;
    vec2 lo = min(min(t0.xy, t1.xy), t2.xy), hi = max(max(t0.xy, t1.xy), t2.xy);
    if (any(greaterThan(lo, vec2(1.0))) || any(lessThan(hi, vec2(0.0))))
        return; // outside the map
    oss_list[2] = 1u; // this frustum has casters (the same value from every invocation: no atomic)
    vec2 e1 = t1.xy - t0.xy, e2 = t2.xy - t0.xy;
    float area = e1.x * e2.y - e1.y * e2.x;
    if (area == 0.0)
        return; // edge-on to the light: blocks no ray of positive measure
    if (oss_listFrontOnly && area < 0.0)
        return; // the other side of a closed caster blocks the same rays
    uint index = atomicAdd(oss_list[1], 1u);
    if (index >= oss_listTriangleCapacity)
        return; // overflow: the eye pass sees the count and falls back to the shadow map
    bool ortho = !oss_listPerspective;
    uint grid = uint(oss_listGridSize.x);
    uint base = 4u + 2u * grid * grid + 2u * oss_listNodeCapacity + 12u * index;
    oss_list[base + 0u] = floatBitsToUint(t0.x);
    oss_list[base + 1u] = floatBitsToUint(t0.y);
    oss_list[base + 2u] = floatBitsToUint(t1.x);
    oss_list[base + 3u] = floatBitsToUint(t1.y);
    oss_list[base + 4u] = floatBitsToUint(t2.x);
    oss_list[base + 5u] = floatBitsToUint(t2.y);
    oss_list[base + 6u] = floatBitsToUint(ortho ? t0.z : -1.0 / c0.w);
    oss_list[base + 7u] = floatBitsToUint(ortho ? t1.z : -1.0 / c1.w);
    oss_list[base + 8u] = floatBitsToUint(ortho ? t2.z : -1.0 / c2.w);
#ifdef OSS_ALPHA_TEST
    oss_list[base + 9u] = 1u;
#else
    oss_list[base + 9u] = 0u;
#endif
    oss_list[base + 10u] = 0u;
    oss_list[base + 11u] = 0u;
    // The nearest depth listed, for the soft shadows' rays (no caster lies nearer): as a
    // positive float that grows toward the light, whose bits order as the floats do.
    float nearest = ortho ? 1.0 - min(min(t0.z, t1.z), t2.z) : max(max(1.0 / c0.w, 1.0 / c1.w), 1.0 / c2.w);
    atomicMax(oss_list[3], floatBitsToUint(max(nearest, 0.0)));

    vec2 margin = 0.5 / oss_listGridSize + 1e-6;
    lo = clamp(lo - margin, vec2(0.0), vec2(1.0)) * 2.0 - 1.0;
    hi = clamp(hi + margin, vec2(0.0), vec2(1.0)) * 2.0 - 1.0;
    vec2 corners[4] = vec2[4](vec2(lo.x, lo.y), vec2(hi.x, lo.y), vec2(lo.x, hi.y), vec2(hi.x, hi.y));
    for (int i = 0; i < 4; ++i)
    {
        oss_triangle = index;
        oss_v0 = t0.xy;
        oss_v1 = t1.xy;
        oss_v2 = t2.xy;
        gl_Position = vec4(corners[i], 0.0, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}

// Where edge a b crosses the near plane (clip-space z + w = 0; da, db its distances).
vec4 oss_nearCut(vec4 a, vec4 b, float da, float db)
{
    return mix(a, b, da / (da - db));
}

void main()
{
    // The light's view space, from clip space: the vertex stage may be a caster's own
    // (CasterVertexStages.h), which owes the passes gl_Position alone.
    vec4 p0 = gl_ProjectionMatrixInverse * gl_in[0].gl_Position;
    vec4 p1 = gl_ProjectionMatrixInverse * gl_in[1].gl_Position;
    vec4 p2 = gl_ProjectionMatrixInverse * gl_in[2].gl_Position;
    if (p0.w > 0.0 && p1.w > 0.0 && p2.w > 0.0 &&
        !oss_canShadowReceivers(p0.xyz / p0.w, p1.xyz / p1.w, p2.xyz / p2.w))
        return; // no receiver behind it
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;
    if (c0.w > 0.0 && c1.w > 0.0 && c2.w > 0.0)
    {
        oss_listTriangle(c0, c1, c2);
        return;
    }
    // A triangle reaching behind a perspective light's eye plane (a long caster beside a
    // point light, partly in a neighbouring cube face): its part beyond the near plane, where
    // the depth pass draws it and the rays are walked, as one or two triangles. Missing, the
    // rays of its penumbrae (and the hard test at its edges) passed through it. A directional
    // light's map warped in perspective (PerspectiveWarp: w = 0 behind the map's near edge,
    // along its y axis) keeps the part on the map's side of that edge (clip y + w = 0).
    oss_list[2] = 1u; // its depth pass may draw part of it
    vec3 cut = oss_listPerspective ? vec3(c0.z, c1.z, c2.z) : vec3(c0.y, c1.y, c2.y);
    float d0 = cut.x + c0.w, d1 = cut.y + c1.w, d2 = cut.z + c2.w;
    if (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0)
        return; // wholly nearer than the near plane: outside the map
    // Rotated so that the vertices beyond the near plane come first: one (a) or two (a, b).
    vec4 a = c0, b = c1, c = c2;
    float da = d0, db = d1, dc = d2;
    if (d0 <= 0.0 && d1 > 0.0) { a = c1; b = c2; c = c0; da = d1; db = d2; dc = d0; }
    else if (d0 <= 0.0) { a = c2; b = c0; c = c1; da = d2; db = d0; dc = d1; }
    // Now a lies beyond; the polygon a b c cut by the plane keeps winding a -> b -> c.
    if (db > 0.0 && dc > 0.0)
        oss_listTriangle(a, b, c); // (not reached: a vertex lies behind the eye)
    else if (db > 0.0) // a, b beyond, c nearer: quad a b bc ca
    {
        vec4 bc = oss_nearCut(b, c, db, dc), ca = oss_nearCut(c, a, dc, da);
        oss_listTriangle(a, b, bc);
        oss_listTriangle(a, bc, ca);
    }
    else if (dc > 0.0) // a, c beyond, b nearer: quad a ab bc c
    {
        vec4 ab = oss_nearCut(a, b, da, db), bc = oss_nearCut(b, c, db, dc);
        oss_listTriangle(a, ab, bc);
        oss_listTriangle(a, bc, c);
    }
    else // a alone beyond: triangle a ab ca
        oss_listTriangle(a, oss_nearCut(a, b, da, db), oss_nearCut(c, a, dc, da));
}
