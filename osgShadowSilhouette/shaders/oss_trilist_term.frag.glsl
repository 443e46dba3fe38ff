#version 430 compatibility
// osgShadowSilhouette: HYBRID's TRIANGLE_LISTS method, eye pass.
//
// Silhouette pixels (2x2 PCF strictly between 0 and 1, as in Chan and Durand 2004) are not
// resolved with shadow volumes but exactly, by a shadow ray from the point toward the light
// tested against the caster triangles listed for its texel by the triangle-list pass
// (oss_trilist.*): the point is shadowed when a listed triangle contains it in the light's
// texture-space x, y and lies nearer to the light. Other pixels keep the shadow map's answer.
// Linked into the receiver program; empty unless OSS_TRIANGLE_LISTS is defined.

#pragma import_defines(OSS_TRIANGLE_LISTS, OSS_MAX_SHADOW_LIGHTS, OSS_MAX_SHADOW_SLOTS, OSS_MAX_LIST_SLOTS)
#ifdef OSS_TRIANGLE_LISTS
#ifndef OSS_MAX_SHADOW_LIGHTS
#define OSS_MAX_SHADOW_LIGHTS 1
#endif
#ifndef OSS_MAX_SHADOW_SLOTS
#define OSS_MAX_SHADOW_SLOTS OSS_MAX_SHADOW_LIGHTS
#endif
// Slots 0 .. OSS_MAX_LIST_SLOTS-1 have lists (at most 8); the others answer with their PCF.
#ifndef OSS_MAX_LIST_SLOTS
#define OSS_MAX_LIST_SLOTS OSS_MAX_SHADOW_LIGHTS
#endif

layout(std430, binding = 1) readonly buffer OssListRead { uint data[]; } oss_lists[OSS_MAX_LIST_SLOTS];
// The same buffers seen as vec4s, for the triangles (one 16-byte load per three coordinates).
layout(std430, binding = 1) readonly buffer OssListRead4 { uvec4 data4[]; } oss_lists4[OSS_MAX_LIST_SLOTS];
uniform usampler2D oss_listHeads[OSS_MAX_LIST_SLOTS];
uniform usampler2D oss_listCounts[OSS_MAX_LIST_SLOTS]; // nodes per texel
uniform uvec2 oss_listCapacity[OSS_MAX_LIST_SLOTS];  // nodes, triangles of each slot's buffer
uniform int oss_listSlotPerspective[OSS_MAX_LIST_SLOTS]; // 1: perspective light
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];

// Slot s of the buffer and head arrays (constant indices: see oss_shadow.frag.glsl).
uint oss_listData(int s, uint i)
{
#if OSS_MAX_LIST_SLOTS > 1
    if (s == 1) return oss_lists[1].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 2
    if (s == 2) return oss_lists[2].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 3
    if (s == 3) return oss_lists[3].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 4
    if (s == 4) return oss_lists[4].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 5
    if (s == 5) return oss_lists[5].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 6
    if (s == 6) return oss_lists[6].data[i];
#endif
#if OSS_MAX_LIST_SLOTS > 7
    if (s == 7) return oss_lists[7].data[i];
#endif
    return oss_lists[0].data[i];
}

vec4 oss_listVec4(int s, uint i)
{
#if OSS_MAX_LIST_SLOTS > 1
    if (s == 1) return uintBitsToFloat(oss_lists4[1].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 2
    if (s == 2) return uintBitsToFloat(oss_lists4[2].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 3
    if (s == 3) return uintBitsToFloat(oss_lists4[3].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 4
    if (s == 4) return uintBitsToFloat(oss_lists4[4].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 5
    if (s == 5) return uintBitsToFloat(oss_lists4[5].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 6
    if (s == 6) return uintBitsToFloat(oss_lists4[6].data4[i]);
#endif
#if OSS_MAX_LIST_SLOTS > 7
    if (s == 7) return uintBitsToFloat(oss_lists4[7].data4[i]);
#endif
    return uintBitsToFloat(oss_lists4[0].data4[i]);
}

// The first node and the length of the list of the texel under p (length 0 outside the grid).
uint oss_listHead(int s, vec2 p, out uint count)
{
    uint head = 0xffffffffu;
    count = 0u;
    for (int k = 0; k < OSS_MAX_LIST_SLOTS; ++k)
        if (k == s)
        {
            ivec2 size = textureSize(oss_listHeads[k], 0);
            vec2 t = floor(p * vec2(size));
            if (all(greaterThanEqual(t, vec2(0.0))) && all(lessThan(t, vec2(size))))
            {
                head = texelFetch(oss_listHeads[k], ivec2(t), 0).r;
                count = texelFetch(oss_listCounts[k], ivec2(t), 0).r;
            }
        }
    return head;
}

// 1 lit, 0 shadowed, -1 when the lists overflowed this frame (then the caller falls back).
// Written as data flow, not early returns: SIMD rasterizers (llvmpipe) run a loop as long as
// any lane of the block needs it, so a lane that does not walk must have a count of 0.
float oss_listWalk(int s, vec2 p, float q, bool walk)
{
    uvec2 capacity = oss_listCapacity[s];
    bool overflow = oss_listData(s, 0u) > capacity.x || oss_listData(s, 1u) > capacity.y;
    uint count;
    uint node = oss_listHead(s, p, count);
    count = walk && !overflow ? count : 0u;
    float limit = q - (1e-4 + 1e-4 * abs(q)); // a triangle through the point itself does not count
    uint triangles = (4u + 2u * capacity.x) / 4u; // in vec4s
    float lit = 1.0;
    for (uint steps = 0u; steps < count && node < capacity.x; ++steps)
    {
        uint b = triangles + 3u * oss_listData(s, 4u + 2u * node);
        node = oss_listData(s, 5u + 2u * node);
        vec4 a = oss_listVec4(s, b), c = oss_listVec4(s, b + 1u);
        float q2 = oss_listVec4(s, b + 2u).x;
        vec2 e1 = a.zw - a.xy, e2 = c.xy - a.xy, d = p - a.xy;
        float det = e1.x * e2.y - e1.y * e2.x;
        float u = (d.x * e2.y - d.y * e2.x) / det, v = (e1.x * d.y - e1.y * d.x) / det;
        float qt = c.z + u * (c.w - c.z) + v * (q2 - c.z);
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && qt < limit)
        {
            lit = 0.0;
            break;
        }
    }
    return overflow ? -1.0 : lit;
}

// The shadow term of slot s given its 2x2 PCF: exact at silhouette pixels, pcf elsewhere.
float oss_listTerm(int s, float pcf, vec4 eyePosition)
{
    if (s >= OSS_MAX_LIST_SLOTS) return pcf;
    bool silhouette = pcf > 0.0 && pcf < 1.0;
    vec4 c = oss_eyeToShadow[s] * eyePosition;
    bool front = c.w > 0.0;
    vec3 p = c.xyz / (front ? c.w : 1.0);
    float q = oss_listSlotPerspective[s] != 0 ? -1.0 / (front ? c.w : 1.0) : p.z;
    float lit = oss_listWalk(s, p.xy, q, silhouette && front);
    lit = front ? lit : 1.0;
    return silhouette ? (lit < 0.0 ? step(0.5, pcf) : lit) : pcf;
}

#else
// (A translation unit may not be empty.)
const int oss_triangleListsUnused = 0;
#endif
