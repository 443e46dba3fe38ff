#version 430 compatibility
// osgShadowSilhouette: HYBRID's TRIANGLE_LISTS method, eye pass.
//
// Silhouette pixels (2x2 PCF strictly between 0 and 1, as in Chan and Durand 2004) are not
// resolved with shadow volumes but exactly, by a shadow ray from the point toward the light
// tested against the caster triangles listed for its texel by the triangle-list pass
// (oss_trilist.*): the point is shadowed when a listed triangle contains it in the light's
// texture-space x, y and lies nearer to the light. Other pixels keep the shadow map's answer.
// Linked into the receiver program; empty unless OSS_TRIANGLE_LISTS is defined.

#pragma import_defines(OSS_TRIANGLE_LISTS, OSS_MAX_SHADOW_LIGHTS, OSS_MAX_SHADOW_SLOTS, OSS_MAX_LIST_SLOTS, OSS_HYBRID_EDGES, OSS_LIST_IMAGES, OSS_LIST_BLOCK_HEADS, OSS_COUNT_EXACT, OSS_LIST_SOFT, OSS_GLSL_430)
// Left out of the programs of a context older than GL 4.3 (no comment on a pragma line: OSG
// reads every word there as a define).
#pragma requires(OSS_GLSL_430)
// Per-pixel derivatives within a 2 x 2 quad (the soft term's agreement test) where available.
#extension GL_ARB_derivative_control : enable
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
layout(binding = 0, offset = 4) uniform atomic_uint oss_stoppedEarly; // soft: pixels whose first pass sufficed
#endif
uniform uvec4 oss_listCapacity[OSS_MAX_SHADOW_SLOTS];  // nodes, triangles, grid size, 0 of each slot's buffer
uniform int oss_listSlotPerspective[OSS_MAX_SHADOW_SLOTS]; // 1: perspective light
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];
uniform vec4 oss_listRayFrame;            // eye-space centre of the shadowed scene's bound, offset at it
uniform float oss_listRayOffsetPerDistance; // offset per unit of distance from that centre
uniform vec4 oss_lookupBiasFrame;         // the map lookup's world bias (oss_shadow.frag.glsl): centre, bias there
uniform float oss_lookupBiasPerDistance;  // its growth per unit of distance from the centre

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

// 1 lit, 0 shadowed, -1 when the lists cannot say (then the caller falls back to the PCF).
// The ray from texture-space point p at depth q is blocked by an opaque listed triangle that
// contains p and lies more than `margin` (oss_listMargin()) nearer the light. -1: the lists
// overflowed this frame, or the only triangles between the point and the light are
// alpha-tested ones (their cut-outs are in the depth map, not in the lists).
// Written as data flow, not early returns: SIMD rasterizers (llvmpipe) run a loop as long as
// any lane of the block needs it, so a lane that does not walk must have a count of 0. The
// buffer is read only by the lanes that walk (the loads sit behind the branch).
float oss_listWalk(int s, vec2 p, float q, float margin, bool walk)
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
    float limit = q - margin; // the surface the ray leaves does not count
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

// The light's direction in eye space for a map warped in perspective: across the x and y rows
// of eye -> texture matrix m (a light ray keeps its texel).
vec3 oss_listWarpedLight(mat4 m)
{
    return normalize(cross(vec3(m[0].x, m[1].x, m[2].x), vec3(m[0].y, m[1].y, m[2].y)));
}

// How much nearer the light than the shadow ray's origin (eye space) a listed triangle must
// lie to block the ray, in slot s's list depth q: a distance of OSS_LIST_MARGIN times the
// map lookup's world bias there (1e-4 of the shadowed scene's radius plus 1e-4 per unit of
// distance from its centre), the same for every kind of light. Surfaces closer than that
// to the visible one are where rasterization and the exact reference may see different
// ones (coincident faces, a part resting on another: docs/shadow-volumes.md, "The lists'
// depth margin"). q is z for an orthographic light (its rate along the light: the length of
// the matrix's z row), z / w for a directional light's map warped in perspective (w is
// constant along the light, whose direction is across the x and y rows: the z row's part
// along it over w) and -1/w for a perspective one (at most |w row| / w^2).
const float OSS_LIST_MARGIN = 10.0;

float oss_listMargin(int s, vec4 origin)
{
    float world = oss_lookupBiasFrame.w + oss_lookupBiasPerDistance * length(origin.xyz - oss_lookupBiasFrame.xyz);
    mat4 m = oss_eyeToShadow[s];
    vec4 wRow = vec4(m[0].w, m[1].w, m[2].w, m[3].w);
    float w = dot(wRow, origin);
    vec3 zRow = vec3(m[0].z, m[1].z, m[2].z);
    float perUnit = oss_listSlotPerspective[s] != 0 ? length(wRow.xyz) / (w * w)
                    : wRow.xyz == vec3(0.0)         ? length(zRow)
                                                    : abs(dot(zRow, oss_listWarpedLight(m))) / w;
    return OSS_LIST_MARGIN * world * perUnit;
}

// The shadow term of slot s given its 2x2 PCF: exact where the PCF cannot be trusted
// (oss_listUncertain), the PCF elsewhere (and where `walk` is false: the caller does not
// need the exact answer there).
float oss_listTerm(int s, float pcf, vec4 eyePosition, bool walk)
{
    if (s >= OSS_MAX_LIST_SLOTS) return pcf;
    vec4 origin = oss_listRayOrigin(eyePosition);
    vec4 p = oss_listPoint(s, origin);
    bool front = p.w > 0.0;
    bool uncertain = front && oss_listUncertain(s, pcf, eyePosition);
#ifdef OSS_COUNT_EXACT
    if (uncertain) atomicCounterIncrement(oss_exactFragments);
#endif
    float lit = oss_listWalk(s, p.xy, p.z, oss_listMargin(s, origin), walk && uncertain);
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

#ifdef OSS_LIST_SOFT
// Soft shadows (docs/soft-shadows.md, "HYBRID: exact penumbrae"): at the pixels the blocker
// search of oss_shadow.frag.glsl classifies as penumbra, oss_listSoftSamples shadow rays
// toward the light's disc or cone, each tested against the caster triangles of every grid
// texel its path crosses in the light's texture space, so that no caster a ray meets is
// missed; the visibility is the share of rays that reach the light.
uniform vec4 oss_listLight[OSS_MAX_SHADOW_SLOTS];      // eye space: (toward the light, 0) or (position, 1)
uniform float oss_listLightSize[OSS_MAX_SHADOW_SLOTS]; // radius; directional: 1 - cos(angular radius); 0: hard
uniform ivec2 oss_listSoftSamples; // rays per pixel, and the first pass of them (softFirstPass())
uniform mat4 oss_listEyeToPattern; // eye space -> world cells of 1e-3 of the scene's radius
const int OSS_MAX_WALK_TEXELS = 1024;

// A 32-bit integer hash (Wellons' lowbias32).
uint oss_hash(uint x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    return x ^ (x >> 16u);
}

// Whether segment a + t d (t in [0, 1]; light texture x, y and the lists' depth q) meets the
// triangle v0 v1 v2 nearer to the light than `limit` (Moller and Trumbore 1997: the
// coordinates are an affine image of the light's view, in which the ray is straight).
bool oss_segmentHits(vec3 a, vec3 d, float limit, vec3 v0, vec3 v1, vec3 v2)
{
    vec3 e1 = v1 - v0, e2 = v2 - v0;
    vec3 pv = cross(d, e2);
    float det = dot(e1, pv);
    vec3 tv = a - v0, qv = cross(tv, e1);
    float inv = det != 0.0 ? 1.0 / det : 0.0;
    float u = dot(tv, pv) * inv, v = dot(d, qv) * inv, t = dot(e2, qv) * inv;
    return det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t >= 0.0 && t <= 1.0 && a.z + t * d.z < limit;
}

// One node of a texel's list of slot s (node: its index + 1, advanced to the next; 0 past
// the end) against segment a + t d: 0 an opaque triangle meets it, 2 an alpha-tested one
// (its cut-outs are in the depth map), 1 neither.
int oss_nodeBlocks(int s, inout uint node, uvec3 offsets, vec3 a, vec3 d, float limit)
{
    if (node == 0u || node > oss_listCapacity[s].x)
    {
        node = 0u;
        return 1;
    }
    uint n = node - 1u;
    uvec4 pair = oss_listData4(s, offsets.y + (n >> 1u));
    uvec2 entry = (n & 1u) != 0u ? pair.zw : pair.xy; // (triangle, next node + 1)
    node = entry.y;
    uint b = offsets.z + 3u * entry.x;
    vec4 p0 = uintBitsToFloat(oss_listData4(s, b)), p1 = uintBitsToFloat(oss_listData4(s, b + 1u));
    uvec4 third = oss_listData4(s, b + 2u);
    bool hit = oss_segmentHits(a, d, limit, vec3(p0.xy, p1.z), vec3(p0.zw, p1.w), vec3(p1.xy, uintBitsToFloat(third.x)));
    return hit ? (third.y == 0u ? 0 : 2) : 1;
}

// Two answers of oss_nodeBlocks() as one: blocked wins, then alpha-tested only.
int oss_blocks(int result, int r)
{
    return result == 0 || r == 0 ? 0 : max(result, r);
}

// What grid texel `cell` of slot s lists on segment a + t d (oss_nodeBlocks()). Four nodes a
// loop iteration, as four texels in oss_rayWalk(): llvmpipe ends a shader invocation's loops
// after 65535 iterations in all (its loop limiter), which a penumbra pixel's rays taken one
// node and one texel at a time can exceed.
int oss_cellBlocks(int s, uint cell, uvec3 offsets, vec3 a, vec3 d, float limit)
{
    uint grid = offsets.x;
    uint count = oss_listData(s, 4u + grid * grid + cell), node = oss_listData(s, 4u + cell);
    int result = 1;
    for (uint steps = 0u; steps < count && node != 0u && result != 0; steps += 4u)
    {
        result = oss_blocks(result, oss_nodeBlocks(s, node, offsets, a, d, limit));
        result = oss_blocks(result, oss_nodeBlocks(s, node, offsets, a, d, limit));
        result = oss_blocks(result, oss_nodeBlocks(s, node, offsets, a, d, limit));
        result = oss_blocks(result, oss_nodeBlocks(s, node, offsets, a, d, limit));
    }
    return result;
}

// One step of oss_rayWalk(): texel `cell` of slot s tested if `test` and inside the grid,
// then the next texel the segment crosses.
int oss_walkStep(int s, inout ivec2 cell, inout vec2 tMax, vec4 steps, uvec3 offsets, vec3 a, vec3 d, float limit,
                 bool test)
{
    bool inside = all(greaterThanEqual(cell, ivec2(0))) && all(lessThan(cell, ivec2(int(offsets.x))));
    int r = test && inside ? oss_cellBlocks(s, uint(cell.y) * offsets.x + uint(cell.x), offsets, a, d, limit) : 1;
    bool alongX = tMax.x < tMax.y;
    cell += alongX ? ivec2(int(steps.x), 0) : ivec2(0, int(steps.y));
    tMax += alongX ? vec2(steps.z, 0.0) : vec2(0.0, steps.w);
    return r;
}

// The shadow ray from a to b (slot s's light texture space: x, y, q), walked over every grid
// texel its projection crosses (Amanatides and Woo 1987), four a loop iteration: 0 blocked,
// 1 free, 2 only alpha-tested triangles met. Texels outside the grid list nothing.
int oss_rayWalk(int s, vec3 a, vec3 b, float limit)
{
    uint grid = oss_listCapacity[s].z;
    uint nodes = (4u + 2u * grid * grid) / 4u; // in vec4s
    uvec3 offsets = uvec3(grid, nodes, nodes + oss_listCapacity[s].x / 2u);
    vec2 ga = a.xy * float(grid), d = (b.xy - a.xy) * float(grid);
    ivec2 cell = ivec2(floor(ga)), last = ivec2(floor(ga + d));
    vec2 inv = vec2(d.x != 0.0 ? 1.0 / d.x : 1e30, d.y != 0.0 ? 1.0 / d.y : 1e30);
    vec4 steps = vec4(sign(d), abs(inv)); // the step per axis, and the segment's share per texel
    vec2 tMax = (vec2(cell) + max(steps.xy, vec2(0.0)) - ga) * inv;
    tMax = vec2(d.x != 0.0 ? tMax.x : 1e30, d.y != 0.0 ? tMax.y : 1e30);
    int texels = min(abs(last.x - cell.x) + abs(last.y - cell.y) + 1, OSS_MAX_WALK_TEXELS);
    int result = 1;
    vec3 ab = b - a;
    for (int i = 0; i < texels && result != 0; i += 4)
    {
        result = oss_blocks(result, oss_walkStep(s, cell, tMax, steps, offsets, a, ab, limit, result != 0));
        result = oss_blocks(result, oss_walkStep(s, cell, tMax, steps, offsets, a, ab, limit, result != 0 && i + 1 < texels));
        result = oss_blocks(result, oss_walkStep(s, cell, tMax, steps, offsets, a, ab, limit, result != 0 && i + 2 < texels));
        result = oss_blocks(result, oss_walkStep(s, cell, tMax, steps, offsets, a, ab, limit, result != 0 && i + 3 < texels));
    }
    return result;
}

// Of ring i's four spiral points (4i .. 4i+3, oss_lightSample()), the one whose angle lies
// nearest point i of a spiral of a quarter as many points: the first pass's (softFirstPass()).
int oss_ringChoice(int i)
{
    float target = fract(float(i) * 0.618033989);
    int best = 0;
    float bestD = 2.0;
    for (int o = 0; o < 4; ++o)
    {
        float d = abs(fract(float(4 * i + o) * 0.618033989) - target);
        d = min(d, 1.0 - d);
        best = d < bestD ? o : best;
        bestD = min(d, bestD);
    }
    return best;
}

// The spiral point of the k-th ray of n with a first pass of `first` rays: one point of each
// ring of four (oss_ringChoice()) in the first pass, the other three of each ring after it;
// with no first pass (first = n), point k.
int oss_spiralIndex(int k, int n, int first)
{
    if (first >= n) return k;
    if (k < first) return 4 * k + oss_ringChoice(k);
    int j = k - first, i = j / 3, m = j % 3;
    return 4 * i + m + (m >= oss_ringChoice(i) ? 1 : 0);
}

// Spiral point k of n of slot s's light seen from eye-space point p, stratified (a Fibonacci
// spiral: the k-th of n equal areas of the disc or cone, the golden angle apart) and turned
// and shifted by `jitter`: an eye-space direction (w 0, directional light; uniform in solid
// angle) or point (w 1; uniform in area on the disc facing p), as the reference samples them.
vec4 oss_lightSample(int s, vec3 p, int k, int n, vec2 jitter)
{
    vec4 light = oss_listLight[s];
    float size = oss_listLightSize[s];
    vec3 axis = normalize(light.w == 0.0 ? light.xyz : light.xyz - p);
    vec3 b1 = normalize(cross(axis, abs(axis.x) < 0.5 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 b2 = cross(axis, b1);
    float u = (float(k) + jitter.x) / float(n);
    float phi = 6.283185307 * fract(float(k) * 0.618033989 + jitter.y);
    vec3 across = b1 * cos(phi) + b2 * sin(phi);
    float cosA = 1.0 - u * size;
    vec4 direction = vec4(axis * cosA + across * sqrt(max(0.0, 1.0 - cosA * cosA)), 0.0);
    return light.w == 0.0 ? direction : vec4(light.xyz + across * (size * sqrt(u)), 1.0);
}

// The end, in slot s's light texture space (x, y, q), of the shadow ray from eye-space
// `origin` (c0 its clip position) toward light sample `target`: the light's point, or where
// the ray leaves the map's depth range toward the light (depth 0), whichever comes first.
vec3 oss_rayEnd(int s, vec4 origin, vec4 c0, vec4 target)
{
    vec4 direction = target.w == 0.0 ? target : vec4(target.xyz - origin.xyz, 0.0);
    vec4 cd = oss_eyeToShadow[s] * direction;
    float t = target.w == 0.0 ? 1e30 : 1.0;
    t = cd.z < 0.0 ? min(t, -c0.z / cd.z) : (target.w == 0.0 ? 0.0 : t);
    vec4 e = c0 + t * cd;
    return vec3(e.xy / e.w, oss_listSlotPerspective[s] != 0 ? -1.0 / e.w : e.z / e.w);
}

// Segment a -> b cut where its x, y leave the map's square (no texel lists beyond; a
// inside) and where it passes `qNear`, the nearest depth of any triangle listed (header[3]).
vec3 oss_clipToMap(vec3 a, vec3 b, float qNear)
{
    vec2 d = b.xy - a.xy;
    vec2 exitT = vec2(d.x > 0.0 ? (1.0 - a.x) / d.x : (d.x < 0.0 ? -a.x / d.x : 1.0),
                      d.y > 0.0 ? (1.0 - a.y) / d.y : (d.y < 0.0 ? -a.y / d.y : 1.0));
    float nearT = b.z < qNear ? (qNear - a.z) / (b.z - a.z) : 1.0;
    return a + clamp(min(min(exitT.x, exitT.y), nearT), 0.0, 1.0) * (b - a);
}

// The nearest depth, in the lists' terms (q), of any triangle slot s's lists hold, from
// their header's fourth word (oss_trilist.geom.glsl); nothing listed: +infinity's stand-in.
float oss_listNearest(int s, uint word)
{
    float value = uintBitsToFloat(word);
    float q = oss_listSlotPerspective[s] != 0 ? -value : 1.0 - value;
    return word == 0u ? 1e30 : q - (1e-4 + 1e-4 * abs(q)); // less a margin for the rounding
}

// Rays from..to-1 of n (first pass: `first` of them; oss_spiralIndex()) of slot s's soft term
// (oss_listSoftTerm()) from `origin` (p: its light texture point, c0: its clip position),
// meeting triangles nearer than depths.x (the ray's own surface left out) down to depths.y
// (the nearest listed): how many reach the light; `cutOnly` set when one meets only
// alpha-tested triangles.
int oss_castRays(int s, vec4 origin, vec4 p, vec4 c0, ivec4 range, vec2 depths, vec2 jitter, inout bool cutOnly)
{
    int from = range.x, to = range.y, n = range.z, first = range.w;
    float limit = depths.x, qNear = depths.y;
    int lit = 0;
    for (int k = from; k < to; ++k)
    {
        vec4 target = oss_lightSample(s, origin.xyz, oss_spiralIndex(k, n, first), n, jitter);
        vec3 b = oss_clipToMap(p.xyz, oss_rayEnd(s, origin, c0, target), qNear);
        int r = oss_rayWalk(s, p.xyz, b, limit);
        lit += r == 1 ? 1 : 0;
        cutOnly = cutOnly || r == 2;
    }
    return lit;
}

// The visibility of slot s's light at an eye-space position given its 2x2 PCF and whether
// the blocker search found a blocker in the light's footprint (`penumbra`): 1 where nothing
// is found (the map's lit class), else the share of oss_listSoftSamples rays that reach the
// light; the PCF's hard answer where the lists cannot say (overflow, or a ray meeting only
// alpha-tested triangles); the PCF where `walk` is false. x: the visibility; y: its class (0
// the map's, 1 rays cast, all blocked or none, 2 rays cast, some blocked: a penumbra). Call
// in uniform control flow (derivatives).
vec2 oss_listSoftTerm(int s, float pcf, bool penumbra, vec4 eyePosition, bool walk)
{
    vec4 origin = oss_listRayOrigin(eyePosition);
    vec4 p = oss_listPoint(s, origin);
    walk = walk && p.w > 0.0 && (penumbra || pcf < 1.0 || oss_listUncertain(s, pcf, eyePosition));
#ifdef OSS_COUNT_EXACT
    if (walk) atomicCounterIncrement(oss_exactFragments);
#endif
    uvec4 header = walk ? oss_listData4(s, 0u) : uvec4(0u);
    bool overflow = header.x > oss_listCapacity[s].x || header.y > oss_listCapacity[s].y;
    int n = walk && !overflow ? max(oss_listSoftSamples.x, 1) : 0;
    uvec3 cellOf = uvec3(ivec3(floor((oss_listEyeToPattern * origin).xyz)));
    uint h = oss_hash(cellOf.x ^ oss_hash(cellOf.y ^ oss_hash(cellOf.z ^ uint(s))));
    vec2 jitter = vec2(float(h & 0xffffu), float(h >> 16u)) / 65536.0;
    vec4 c0 = oss_eyeToShadow[s] * origin;
    // Once per pixel for both passes: the margin (the surface the ray leaves does not count)
    // and the nearest listed depth (header word 3).
    vec2 depths = n > 0 ? vec2(p.z - oss_listMargin(s, origin), oss_listNearest(s, header.w)) : vec2(0.0);
    bool cutOnly = false;
    // The first pass, a quarter of the rays, one of each ring of four of the spiral (a
    // spiral of its own, nearly): when its rays all agree and so do those of the pixel's
    // neighbours in its 2 x 2 quad, the pixel takes their answer (inside an umbra, or a point
    // the map called shadowed that sees the whole light); else the other three quarters follow.
    int first = min(max(oss_listSoftSamples.y, 1), n);
    int lit = oss_castRays(s, origin, p, c0, ivec4(0, first, n, first), depths, jitter, cutOnly);
    float share = first > 0 ? float(lit) / float(first) : pcf;
#ifdef GL_ARB_derivative_control
    bool quadAgrees = dFdxFine(share) == 0.0 && dFdyFine(share) == 0.0;
#else
    bool quadAgrees = dFdx(share) == 0.0 && dFdy(share) == 0.0;
#endif
    bool agree = (lit == 0 || lit == first) && quadAgrees;
    int end = agree ? first : n;
#ifdef OSS_COUNT_EXACT
    if (walk && end < n) atomicCounterIncrement(oss_stoppedEarly);
#endif
    lit += oss_castRays(s, origin, p, c0, ivec4(first, end, n, first), depths, jitter, cutOnly);
    float v = n > 0 ? float(lit) / float(end) : pcf;
    v = walk && (overflow || cutOnly) ? step(0.5, pcf) : v;
    return vec2(v, walk ? (v > 0.0 && v < 1.0 ? 2.0 : 1.0) : 0.0);
}
#endif

#else
// (A translation unit may not be empty.)
const int oss_triangleListsUnused = 0;
#endif
