#version 400 compatibility
// osgShadowSilhouette: shadow volumes extruded on the GPU, geometry stage.
//
// For casters whose final positions exist only on the GPU (a skinning or displacing vertex
// stage of their own, which runs before this stage), and for every caster where the
// technique is told to (GpuExtraction). The input is the caster's welded mesh drawn as
// GL_TRIANGLES_ADJACENCY (GpuVolumes.h): corners 0, 2, 4 are a face, 1, 3, 5 the corners
// opposite the edges 0-2, 2-4 and 4-0 in the faces across them. An edge without exactly one
// face across it (a border, an edge of three or more faces) names the face's own third
// corner instead: the edge is extruded whatever the light does.
//
// Each face casts the volume of the CPU path's rules (SilhouetteExtractor): under TWO_SIDED
// (a caster that is not closed and wound outward, with that open-caster rule) every face,
// turned toward the light where it faces away; otherwise the faces toward the light (closed
// casters, or the LIT_FACES_ONLY rule). A casting face emits its caps and
// the sides of its edges that the face across does not cancel: those whose face across casts
// the other way (or not at all), and the open ones. The sum over the faces is the CPU path's
// volume: shared edges of faces cast the same way cancel there too.
//
// The facing test is the CPU path's, plane . light > 0 strictly, evaluated in eye space
// from gl_Position (gl_ProjectionMatrixInverse): a caster's own vertex stage only has to
// write gl_Position. A mirroring model-view turns the eye-space winding of every face (the
// rule's MIRRORED bit flips it back). The triangles are emitted counter-clockwise
// seen from outside the volume, in eye space, whatever the model-view (the pass sets
// FrontFace CCW). The light cap is a draw of its own (OSS_GPU_VOLUME_LIGHT_CAP), with the
// light cap's polygon offset; the other draw emits the sides and the dark cap.
//
// Where the eye pass culls a caster's faces (the rule's CULLS bits: the windings it culls in
// the window), the eye sees some faces from a culled side: such a face is not in the
// depth buffer, and its light cap, pushed back by its slope, could land behind the surface
// seen through it. Those caps go with the sides, a constant step behind the surface only.

// The light-cap draw is a program of its own, compiled with OSS_GPU_VOLUME_LIGHT_CAP defined
// (GpuVolumes: no OSG define, which a draw of the same program object with other defines may
// not recompile); the rules come per caster in oss_gpuVolumeRule.

layout(triangles_adjacency) in;
#ifdef OSS_GPU_VOLUME_LIGHT_CAP
layout(triangle_strip, max_vertices = 3) out;
#else
layout(triangle_strip, max_vertices = 18) out; // the dark cap, three sides, a culled side's light cap
#endif

// The light in eye space: (x, y, z, 1) a positional light, (x, y, z, 0) toward a directional one.
uniform vec4 oss_gpuVolumeLight;
// The caster's rule, bits: 1 TWO_SIDED (else the faces toward the light cast), 2 a mirroring
// model-view, 4 and 8 the eye culls faces wound counter-clockwise and clockwise in the window.
uniform int oss_gpuVolumeRule;
const int OSS_RULE_TWO_SIDED = 1, OSS_RULE_MIRRORED = 2, OSS_RULE_CULLS_CCW = 4, OSS_RULE_CULLS_CW = 8;

vec3 oss_eye(int i)
{
    vec4 p = gl_ProjectionMatrixInverse * gl_in[i].gl_Position;
    return p.xyz / p.w;
}

// > 0: the face a -> b -> c (eye space) turns its counter-clockwise side toward the light
// (oss_facing.geom.glsl).
float oss_facing(vec3 a, vec3 b, vec3 c, vec4 light);

// The facing of the caster's own winding: lit as the CPU path classifies its planes.
bool oss_lit(float facing)
{
    return (oss_gpuVolumeRule & OSS_RULE_MIRRORED) != 0 ? -facing > 0.0 : facing > 0.0;
}

// A point extruded away from the light to infinity.
vec4 oss_far(vec3 p)
{
    return vec4(p * oss_gpuVolumeLight.w - oss_gpuVolumeLight.xyz, 0.0);
}

void oss_emit(vec4 eye)
{
    gl_Position = gl_ProjectionMatrix * eye;
    EmitVertex();
}

// A corner where the caster's vertex stage put it: the caps and the sides meet on the very
// positions the eye pass rasterizes (no round trip through the inverse projection).
void oss_emitCorner(int i)
{
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
}

// A corner of a light cap seen from a culled side, a little behind the surface: in NDC four
// steps of a 24-bit depth buffer (2^-24 of window depth is 2^-23 of NDC depth), as the CPU
// volumes' four units of polygon offset (ShadowVolumeGroup, CULLED_CAP_UNITS) behind it.
const float OSS_CULLED_CAP_DEPTH = 4.0 * exp2(-23.0);
void oss_emitCulledCap(int i)
{
    vec4 v = gl_in[i].gl_Position;
    gl_Position = vec4(v.xy, v.z + OSS_CULLED_CAP_DEPTH * v.w, v.w);
    EmitVertex();
}

// Whether the eye pass culls the face (corners 0, 2, 4) by its winding in the window.
bool oss_culledSide()
{
    if ((oss_gpuVolumeRule & (OSS_RULE_CULLS_CCW | OSS_RULE_CULLS_CW)) == 0)
        return false;
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[2].gl_Position, c2 = gl_in[4].gl_Position;
    if (c0.w <= 0.0 || c1.w <= 0.0 || c2.w <= 0.0)
        return false; // across the eye plane: no winding
    vec2 a = c0.xy / c0.w, b = c1.xy / c1.w, c = c2.xy / c2.w;
    float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    return ((oss_gpuVolumeRule & OSS_RULE_CULLS_CCW) != 0 && area > 0.0) ||
           ((oss_gpuVolumeRule & OSS_RULE_CULLS_CW) != 0 && area < 0.0);
}

void main()
{
    vec3 p[6];
    for (int i = 0; i < 6; ++i)
        p[i] = oss_eye(i);
    float facing = oss_facing(p[0], p[2], p[4], oss_gpuVolumeLight);
    bool lit = oss_lit(facing);
    if (!lit && (oss_gpuVolumeRule & OSS_RULE_TWO_SIDED) == 0)
        return;
    // The face's corners counter-clockwise seen from the light: a, b, c.
    bool toward = facing > 0.0;
    int a = 0, b = toward ? 2 : 4, c = toward ? 4 : 2;
#ifdef OSS_GPU_VOLUME_LIGHT_CAP
    if (oss_culledSide())
        return; // drawn with the sides
    oss_emitCorner(a);
    oss_emitCorner(b);
    oss_emitCorner(c);
    EndPrimitive();
#else
    oss_emit(oss_far(p[a])); // the dark cap faces away from the light
    oss_emit(oss_far(p[c]));
    oss_emit(oss_far(p[b]));
    EndPrimitive();
    if (oss_culledSide())
    {
        oss_emitCulledCap(a);
        oss_emitCulledCap(b);
        oss_emitCulledCap(c);
        EndPrimitive();
    }
    for (int k = 0; k < 3; ++k)
    {
        int i = 2 * k, j = (2 * k + 2) % 6, across = 2 * k + 1, opposite = (2 * k + 4) % 6;
        bool open = gl_in[across].gl_Position == gl_in[opposite].gl_Position;
        // The face across runs along the edge j -> i.
        if (!open && oss_lit(oss_facing(p[j], p[i], p[across], oss_gpuVolumeLight)) == lit)
            continue; // cast the same way: the two sides cancel
        // The edge as the face runs along it seen from the light: e0 -> e1.
        int e0 = toward ? i : j, e1 = toward ? j : i;
        oss_emitCorner(e1);
        oss_emitCorner(e0);
        oss_emit(oss_far(p[e1]));
        oss_emit(oss_far(p[e0]));
        EndPrimitive();
    }
#endif
}
