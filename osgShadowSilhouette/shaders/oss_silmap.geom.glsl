#version 400 compatibility
// osgShadowSilhouette: silhouette-map pass, geometry stage.
//
// Conservative rasterization of one silhouette edge as a thin quad (Sen, Cammarano,
// Hanrahan 2003, section 4.2): the quad reaches OSS_HALF_WIDTH texels to each side of the
// edge and as far past each endpoint. OSS_HALF_WIDTH > sqrt(2)/2, so the centre of every
// texel the edge touches lies inside the quad and gets a fragment.
//
// Frames (see osgShadowSilhouette/SilhouettePoints): silhouette-map window coordinates are
// depth-texel coordinates minus one half, so that silhouette texel (i, j) spans
// [i, i+1] x [j, j+1] and its local coordinates are the window coordinates minus (i, j).

#ifdef OSS_SILMAP_ADJACENCY
// The edges found on the GPU (GpuEdges.h; the program's own source defines this, not OSG):
// the input is a caster's welded mesh drawn as GL_TRIANGLES_ADJACENCY through the caster's
// own vertex stage (corners 0, 2, 4 a face, 1, 3, 5 the corners across the edges 0-2, 2-4,
// 4-0; an edge without exactly one face across names the face's own third corner), and each
// face emits the silhouette edges the CPU path (SilhouetteExtractor) finds along it.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;
#else
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
#endif

#pragma import_defines(OSS_SILMAP_COMPARE, OSS_SILMAP_NEIGHBOURHOOD, OSS_SILMAP_DISTANCE)
#define OSS_GRID_OFFSET 0.5 // the dual grid: window coordinates are depth-texel coordinates less this
#ifdef OSS_SILMAP_DISTANCE
// FILTER_SILHOUETTE's distance map (oss_sildist.frag.glsl; Valient and Bujnak 2005): on the
// depth map's own grid (texel (i, j)'s centre is depth sample (i, j)), every texel whose
// centre lies within oss_sildistWidth texels of the edge (half a texel's diagonal more).
uniform float oss_sildistWidth; // W, in texels
uniform vec2 oss_sildistSize;   // the map's size in texels (the depth map's)
#define OSS_HALF_WIDTH (oss_sildistWidth + 0.75)
#define OSS_WINDOW_OFFSET 0.0
#undef OSS_GRID_OFFSET
#define OSS_GRID_OFFSET 0.0
#define OSS_MAP_SIZE oss_sildistSize
#elif defined(OSS_SILMAP_NEIGHBOURHOOD)
// The neighbourhood map (oss_silnbr.frag.glsl): every texel within one texel of a texel the
// edge touches, drawn one texel up and to the right in a map one texel larger.
#define OSS_HALF_WIDTH 1.75
#define OSS_WINDOW_OFFSET 1.0
uniform sampler2D oss_silmapPoints;      // the silhouette map (its size is the map size)
#define OSS_MAP_SIZE vec2(textureSize(oss_silmapPoints, 0))
#else
#define OSS_HALF_WIDTH 0.75
#define OSS_WINDOW_OFFSET 0.0
#ifdef OSS_SILMAP_COMPARE
uniform sampler2DShadow oss_silmapDepth; // the light's depth map (its size is the map size)
#else
uniform sampler2D oss_silmapDepth;       // the light's depth map (its size is the map size)
#endif
#define OSS_MAP_SIZE vec2(textureSize(oss_silmapDepth, 0))
#endif

flat out vec4 oss_edge;      // endpoints a.xy, b.xy in silhouette-map window coordinates
flat out vec2 oss_edgeDepth; // window depths of a and b, in [0, 1]
flat out float oss_edgeDepthSlope; // |change of window depth| per texel along the edge

// The edge's part in front of the light's eye plane (w > 0).
bool oss_clipToFront(inout vec4 a, inout vec4 b)
{
    const float minW = 1e-6;
    if (a.w <= minW && b.w <= minW)
        return false;
    if (a.w <= minW)
        a = mix(a, b, (minW - a.w) / (b.w - a.w));
    else if (b.w <= minW)
        b = mix(b, a, (minW - b.w) / (a.w - b.w));
    return true;
}

void oss_emit(vec2 window, vec2 size, vec4 edge, vec2 depth)
{
    oss_edge = edge;
    oss_edgeDepth = depth;
    oss_edgeDepthSlope = abs(depth.y - depth.x) / max(length(edge.zw - edge.xy), 1e-6);
    gl_Position = vec4((window + OSS_WINDOW_OFFSET) / (size + OSS_WINDOW_OFFSET) * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
}

// One edge a -> b (clip space): the thin quad over the texels it touches.
void oss_emitEdge(vec4 a, vec4 b)
{
    if (!oss_clipToFront(a, b))
        return;
    vec2 size = OSS_MAP_SIZE;
    vec3 na = a.xyz / a.w, nb = b.xyz / b.w;
    vec2 wa = (na.xy * 0.5 + 0.5) * size - OSS_GRID_OFFSET;
    vec2 wb = (nb.xy * 0.5 + 0.5) * size - OSS_GRID_OFFSET;
    vec4 edge = vec4(wa, wb);
    vec2 depth = vec2(na.z, nb.z) * 0.5 + 0.5;

    vec2 d = wb - wa;
    float len = length(d);
    vec2 along = (len > 1e-6 ? d / len : vec2(1.0, 0.0)) * OSS_HALF_WIDTH;
    vec2 across = vec2(-along.y, along.x);
    oss_emit(wa - along - across, size, edge, depth);
    oss_emit(wa - along + across, size, edge, depth);
    oss_emit(wb + along - across, size, edge, depth);
    oss_emit(wb + along + across, size, edge, depth);
    EndPrimitive();
}

#ifdef OSS_SILMAP_ADJACENCY
// The light in the light's view space: (x, y, z, 1) a positional light, (x, y, z, 0) toward a
// directional one.
uniform vec4 oss_gpuEdgeLight;
// The caster's rule, a bit of the GPU volumes' (oss_gpuvolume.geom.glsl): 1 TWO_SIDED (an open
// caster: its faces away from the light cast too, turned).
uniform int oss_gpuVolumeRule;
const int OSS_RULE_TWO_SIDED = 1;

vec3 oss_view(int i)
{
    vec4 p = gl_ProjectionMatrixInverse * gl_in[i].gl_Position;
    return p.xyz / p.w;
}

float oss_facing(vec3 a, vec3 b, vec3 c, vec4 light); // oss_facing.geom.glsl

// Whether the face a -> b -> c (view space) turns its counter-clockwise side toward the light,
// strictly, as the CPU path's plane test. A mirroring model-view turns every face, which
// changes no silhouette edge, only their direction: here the casting side of each edge, on its
// left in the map (the distance map's sign), is the caster's side whatever the model-view.
bool oss_lit(vec3 a, vec3 b, vec3 c)
{
    return oss_facing(a, b, c, oss_gpuEdgeLight) > 0.0;
}

// The CPU path's edges, each drawn once: an edge between a lit face and an unlit one, by the
// lit face, along its own winding; an open edge of a lit face along its winding, and under
// TWO_SIDED an open edge of an unlit face against it (CasterEdges draws a mirrored caster's
// edges turned, as here).
void main()
{
    vec3 p[6];
    for (int i = 0; i < 6; ++i)
        p[i] = oss_view(i);
    bool lit = oss_lit(p[0], p[2], p[4]);
    if (!lit && (oss_gpuVolumeRule & OSS_RULE_TWO_SIDED) == 0)
        return;
    for (int k = 0; k < 3; ++k)
    {
        int i = 2 * k, j = (2 * k + 2) % 6, across = 2 * k + 1, opposite = (2 * k + 4) % 6;
        bool open = gl_in[across].gl_Position == gl_in[opposite].gl_Position;
        if (open)
            oss_emitEdge(gl_in[lit ? i : j].gl_Position, gl_in[lit ? j : i].gl_Position);
        else if (lit && !oss_lit(p[j], p[i], p[across])) // the face across runs along j -> i
            oss_emitEdge(gl_in[i].gl_Position, gl_in[j].gl_Position);
    }
}
#else
void main()
{
    oss_emitEdge(gl_in[0].gl_Position, gl_in[1].gl_Position);
}
#endif
