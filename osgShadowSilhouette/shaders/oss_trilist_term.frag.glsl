#version 430 compatibility
// osgShadowSilhouette: HYBRID's TRIANGLE_LISTS method, eye pass.
//
// Silhouette pixels (2x2 PCF strictly between 0 and 1, as in Chan and Durand 2004) are not
// resolved with shadow volumes but exactly, by a shadow ray from the point toward the light
// tested against the caster triangles listed for its texel by the triangle-list pass
// (oss_trilist.*): the point is shadowed when a listed triangle contains it in the light's
// texture-space x, y and lies nearer to the light. Other pixels keep the shadow map's answer.
// Linked into the receiver program; empty unless OSS_TRIANGLE_LISTS is defined.

#pragma import_defines(OSS_TRIANGLE_LISTS, OSS_MAX_SHADOW_LIGHTS, OSS_MAX_SHADOW_SLOTS, OSS_MAX_LIST_SLOTS, OSS_HYBRID_EDGES, OSS_LIST_IMAGES, OSS_LIST_BLOCK_HEADS, OSS_COUNT_EXACT, OSS_GLSL_430)
// Left out of the programs of a context older than GL 4.3 (no comment on a pragma line: OSG
// reads every word there as a define).
#pragma requires(OSS_GLSL_430)
#ifdef OSS_TRIANGLE_LISTS
// Slots 0 .. OSS_MAX_LIST_SLOTS-1 have lists (at most 12, one storage block each: the
// technique sets it to the slots in use); the others answer with their PCF.

// Each slot's whole list buffer (layout: oss_trilist.geom.glsl), read 16 bytes at a time:
// as an RGBA32UI image buffer (OSS_LIST_IMAGES, image unit = slot; where the context has the
// image uniforms) or as a shader storage block (binding 1 + slot). The same on GPUs, but a
// SIMD rasterizer (llvmpipe) loads a storage block lane by lane with a branch for each, an
// image with one gather: the walks cost a third less (docs/shadow-volumes.md).
#ifdef OSS_LIST_IMAGES
layout(rgba32ui, binding = 0) readonly uniform uimageBuffer oss_listImages[OSS_MAX_LIST_SLOTS];
#define OSS_LIST_LOAD(k, i) imageLoad(oss_listImages[k], int(i))
#else
layout(std430, binding = 1) readonly buffer OssListRead { uvec4 data4[]; } oss_lists[OSS_MAX_LIST_SLOTS];
#define OSS_LIST_LOAD(k, i) oss_lists[k].data4[i]
#endif
// OSS_LIST_BLOCK_HEADS (with OSS_LIST_IMAGES, where the context has the resources for both):
// the walk's prologue (the header and the texel's head and count) reads the same buffer as a
// storage block, the walk itself as an image. A SIMD rasterizer (llvmpipe) executes the
// prologue in every block of pixels, walking or not; a storage-block load skips the lanes
// that do not walk, an image load does not (measured in docs/shadow-volumes.md).
#if defined(OSS_LIST_IMAGES) && defined(OSS_LIST_BLOCK_HEADS)
layout(std430, binding = 1) readonly buffer OssListHeads { uint data[]; } oss_listHeads[OSS_MAX_LIST_SLOTS];
#define OSS_HEAD_LOAD(k, i) oss_listHeads[k].data[i]
#else
#define OSS_HEAD_LOAD(k, i) OSS_LIST_LOAD(k, (i) >> 2u)[(i) & 3u]
#endif
// OSS_COUNT_EXACT (while the technique records statistics): the fragments resolved exactly,
// summed over slots, in an atomic counter (GpuCounter's binding 0): HYBRID's silhouette
// pixels. Tests are early so that a hidden fragment is not counted (a shader with side
// effects would otherwise run before them) and early-z still works.
#ifdef OSS_COUNT_EXACT
layout(early_fragment_tests) in;
layout(binding = 0, offset = 0) uniform atomic_uint oss_exactFragments;
#endif
uniform uvec4 oss_listCapacity[OSS_MAX_SHADOW_SLOTS];  // nodes, triangles, grid size, 0 of each slot's buffer
uniform int oss_listSlotPerspective[OSS_MAX_SHADOW_SLOTS]; // 1: perspective light
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform vec4 oss_listRayFrame;            // eye-space centre of the shadowed scene's bound, offset at it
uniform float oss_listRayOffsetPerDistance; // offset per unit of distance from that centre

// The i-th vec4 of slot s's buffer (constant indices: see oss_shadow.frag.glsl).
uvec4 oss_listData4(int s, uint i)
{
#if OSS_MAX_LIST_SLOTS > 1
    if (s == 1) return OSS_LIST_LOAD(1, i);
#endif
#if OSS_MAX_LIST_SLOTS > 2
    if (s == 2) return OSS_LIST_LOAD(2, i);
#endif
#if OSS_MAX_LIST_SLOTS > 3
    if (s == 3) return OSS_LIST_LOAD(3, i);
#endif
#if OSS_MAX_LIST_SLOTS > 4
    if (s == 4) return OSS_LIST_LOAD(4, i);
#endif
#if OSS_MAX_LIST_SLOTS > 5
    if (s == 5) return OSS_LIST_LOAD(5, i);
#endif
#if OSS_MAX_LIST_SLOTS > 6
    if (s == 6) return OSS_LIST_LOAD(6, i);
#endif
#if OSS_MAX_LIST_SLOTS > 7
    if (s == 7) return OSS_LIST_LOAD(7, i);
#endif
#if OSS_MAX_LIST_SLOTS > 8
    if (s == 8) return OSS_LIST_LOAD(8, i);
#endif
#if OSS_MAX_LIST_SLOTS > 9
    if (s == 9) return OSS_LIST_LOAD(9, i);
#endif
#if OSS_MAX_LIST_SLOTS > 10
    if (s == 10) return OSS_LIST_LOAD(10, i);
#endif
#if OSS_MAX_LIST_SLOTS > 11
    if (s == 11) return OSS_LIST_LOAD(11, i);
#endif
    return OSS_LIST_LOAD(0, i);
}

// The i-th uint of slot s's buffer (the walk's prologue: OSS_LIST_BLOCK_HEADS).
uint oss_listData(int s, uint i)
{
#if OSS_MAX_LIST_SLOTS > 1
    if (s == 1) return OSS_HEAD_LOAD(1, i);
#endif
#if OSS_MAX_LIST_SLOTS > 2
    if (s == 2) return OSS_HEAD_LOAD(2, i);
#endif
#if OSS_MAX_LIST_SLOTS > 3
    if (s == 3) return OSS_HEAD_LOAD(3, i);
#endif
#if OSS_MAX_LIST_SLOTS > 4
    if (s == 4) return OSS_HEAD_LOAD(4, i);
#endif
#if OSS_MAX_LIST_SLOTS > 5
    if (s == 5) return OSS_HEAD_LOAD(5, i);
#endif
#if OSS_MAX_LIST_SLOTS > 6
    if (s == 6) return OSS_HEAD_LOAD(6, i);
#endif
#if OSS_MAX_LIST_SLOTS > 7
    if (s == 7) return OSS_HEAD_LOAD(7, i);
#endif
#if OSS_MAX_LIST_SLOTS > 8
    if (s == 8) return OSS_HEAD_LOAD(8, i);
#endif
#if OSS_MAX_LIST_SLOTS > 9
    if (s == 9) return OSS_HEAD_LOAD(9, i);
#endif
#if OSS_MAX_LIST_SLOTS > 10
    if (s == 10) return OSS_HEAD_LOAD(10, i);
#endif
#if OSS_MAX_LIST_SLOTS > 11
    if (s == 11) return OSS_HEAD_LOAD(11, i);
#endif
    return OSS_HEAD_LOAD(0, i);
}

// The first node + 1 (0: none) and the length of the list of the texel under p (length 0
// outside the grid).
uint oss_listHead(int s, vec2 p, uint grid, out uint count)
{
    vec2 t = floor(p * float(grid));
    bool inside = all(greaterThanEqual(t, vec2(0.0))) && all(lessThan(t, vec2(float(grid))));
    uint texel = inside ? uint(t.y) * grid + uint(t.x) : 0u;
    uint head = oss_listData(s, 4u + texel);
    count = inside ? oss_listData(s, 4u + grid * grid + texel) : 0u;
    return inside ? head : 0u;
}

// 1 lit, 0 shadowed, -1 when the lists cannot say (then the caller falls back to the PCF):
// they overflowed this frame, or the only triangles between the point and the light are
// alpha-tested ones (their cut-outs are in the depth map, not in the lists).
// Written as data flow, not early returns: SIMD rasterizers (llvmpipe) run a loop as long as
// any lane of the block needs it, so a lane that does not walk must have a count of 0. The
// buffer is read only by the lanes that walk (the loads sit behind the branch).
float oss_listWalk(int s, vec2 p, float q, bool walk)
{
    uvec4 capacity = oss_listCapacity[s];
    uint grid = capacity.z;
    bool overflow = false;
    uint count = 0u, node = 0u;
    if (walk)
    {
#if defined(OSS_LIST_IMAGES) && defined(OSS_LIST_BLOCK_HEADS)
        overflow = oss_listData(s, 0u) > capacity.x || oss_listData(s, 1u) > capacity.y;
#else
        uvec4 header = oss_listData4(s, 0u);
        overflow = header.x > capacity.x || header.y > capacity.y;
#endif
        node = oss_listHead(s, p, grid, count);
        count = overflow ? 0u : count;
    }
    float limit = q - (1e-4 + 1e-4 * abs(q)); // a triangle through the point itself does not count
    uint nodes = (4u + 2u * grid * grid) / 4u;    // in vec4s: two nodes each
    uint triangles = nodes + capacity.x / 2u;
    float lit = 1.0;
    bool cutOnly = false;
    for (uint steps = 0u; steps < count && node != 0u && node <= capacity.x; ++steps)
    {
        uint n = node - 1u;
        uvec4 pair = oss_listData4(s, nodes + (n >> 1u));
        uvec2 entry = (n & 1u) != 0u ? pair.zw : pair.xy; // (triangle, next node + 1)
        node = entry.y;
        uint b = triangles + 3u * entry.x;
        vec4 a = uintBitsToFloat(oss_listData4(s, b)), c = uintBitsToFloat(oss_listData4(s, b + 1u));
        uvec4 third = oss_listData4(s, b + 2u);
        float q2 = uintBitsToFloat(third.x);
        vec2 e1 = a.zw - a.xy, e2 = c.xy - a.xy, d = p - a.xy;
        float det = e1.x * e2.y - e1.y * e2.x;
        float u = (d.x * e2.y - d.y * e2.x) / det, v = (e1.x * d.y - e1.y * d.x) / det;
        float qt = c.z + u * (c.w - c.z) + v * (q2 - c.z);
        bool hit = u >= 0.0 && v >= 0.0 && u + v <= 1.0 && qt < limit;
        cutOnly = cutOnly || (hit && third.y != 0u);
        if (hit && third.y == 0u)
        {
            lit = 0.0;
            break;
        }
    }
    return overflow || (cutOnly && lit > 0.0) ? -1.0 : lit;
}

#ifdef OSS_HYBRID_EDGES
// Whether an edge of slot s's edge mask in front of eye-space position `eyePosition` crosses
// the square of its four depth samples around it (oss_shadow.frag.glsl).
bool oss_slotEdgeAt(int s, vec4 eyePosition);
#endif

// Whether slot s cannot trust its 2x2 PCF at an eye-space position: the PCF lies
// strictly between 0 and 1 (Chan and Durand's silhouette pixels), or an edge touches the
// square of the four depth samples around it in front of it (OSS_HYBRID_EDGES).
bool oss_listUncertain(int s, float pcf, vec4 eyePosition)
{
    bool uncertain = pcf > 0.0 && pcf < 1.0;
#ifdef OSS_HYBRID_EDGES
    uncertain = uncertain || oss_slotEdgeAt(s, eyePosition);
#endif
    return uncertain;
}

// Slot s's light texture-space point of an eye-space position (x, y), its depth in the
// lists' terms (z), and whether it lies in front of a perspective light (w).
vec4 oss_listPoint(int s, vec4 eyePosition)
{
    vec4 c = oss_eyeToShadow[s] * eyePosition;
    bool front = c.w > 0.0;
    vec3 p = c.xyz / (front ? c.w : 1.0);
    float q = oss_listSlotPerspective[s] != 0 ? -1.0 / (front ? c.w : 1.0) : p.z;
    return vec4(p.xy, q, front ? 1.0 : 0.0);
}

// Where the shadow ray of an eye-space position starts: off the surface along its geometric
// normal, turned toward the camera, by a scale-aware offset (ShaderConstants: the radius of
// the shadowed scene's bound times ShadowRayOffset (default 1e-6), plus 1e-6 per unit of
// distance from its centre).
// It is what a ray tracer's shadow ray does (and the exact reference's): points that close
// to a shadow boundary take the answer of the offset point, not of a depth epsilon along the
// light (which, for a directional light, leaves the ray's line where it was). Derivatives:
// call it in uniform control flow.
vec4 oss_listRayOrigin(vec4 eyePosition)
{
    vec3 p = eyePosition.xyz / eyePosition.w;
    vec3 n = cross(dFdx(p), dFdy(p));
    float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0);
    n = dot(n, p) > 0.0 ? -n : n;
    float offset = oss_listRayFrame.w + oss_listRayOffsetPerDistance * length(p - oss_listRayFrame.xyz);
    return vec4(p + n * offset, 1.0);
}

// The shadow term of slot s given its 2x2 PCF: exact where the PCF cannot be trusted
// (oss_listUncertain), the PCF elsewhere (and where `walk` is false: the caller does not
// need the exact answer there).
float oss_listTerm(int s, float pcf, vec4 eyePosition, bool walk)
{
    if (s >= OSS_MAX_LIST_SLOTS) return pcf;
    vec4 p = oss_listPoint(s, oss_listRayOrigin(eyePosition));
    bool front = p.w > 0.0;
    bool uncertain = front && oss_listUncertain(s, pcf, eyePosition);
#ifdef OSS_COUNT_EXACT
    if (uncertain) atomicCounterIncrement(oss_exactFragments);
#endif
    float lit = oss_listWalk(s, p.xy, p.z, walk && uncertain);
    lit = walk && front ? lit : pcf;
    return uncertain ? (lit < 0.0 ? step(0.5, pcf) : lit) : pcf;
}

// Whether oss_listTerm() resolves slot s exactly at this position (DEBUG_CLASSES).
bool oss_listResolves(int s, float pcf, vec4 eyePosition)
{
    if (s >= OSS_MAX_LIST_SLOTS) return false;
    vec4 p = oss_listPoint(s, eyePosition);
    return p.w > 0.0 && oss_listUncertain(s, pcf, eyePosition);
}

#else
// (A translation unit may not be empty.)
const int oss_triangleListsUnused = 0;
#endif
