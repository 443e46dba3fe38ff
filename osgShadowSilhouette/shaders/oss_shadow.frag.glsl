#version 400 compatibility
// osgShadowSilhouette: the shadow term of each shadowed light.
//
// Shadow map with 2x2 hardware percentage-closer filtering (Reeves, Salesin, Cook 1987):
// the depth texture compares with GL_LEQUAL and filters linearly, so one lookup returns the
// share of the four nearest depth samples that see the fragment.
//
// Applications link this shader into their own programs and call oss_shadowTerm().
// Names are kept in sync with osgShadowSilhouette/ShaderConstants.

#pragma import_defines(OSS_MAX_SHADOW_SLOTS, OSS_MAX_SHADOW_LIGHTS, OSS_NUM_SHADOW_SLOTS, OSS_SILHOUETTE_MAP, OSS_CUBE_FACES)
#pragma import_defines(OSS_TRIANGLE_LISTS, OSS_LIGHT_FACES, OSS_HYBRID_EDGES, OSS_SKIPPED_SLOTS, OSS_BIAS_BAND, OSS_LIST_SOFT)
#pragma import_defines(OSS_SCREEN_VISIBILITY, OSS_FILTER_PCF, OSS_FILTER_PCSS, OSS_FILTER_SILHOUETTE)

uniform int oss_numLights;                          // lights lit by the receiver shading
uniform int oss_lightIndex[OSS_MAX_SCENE_LIGHTS];   // their GL light numbers
uniform int oss_shadowSlot[OSS_MAX_SCENE_LIGHTS];   // their shadow slot, -1 unshadowed
uniform mat4 oss_eyeToShadow[OSS_MAX_SHADOW_SLOTS];// eye space -> light texture space [0,1]^3
uniform OSS_SHADOW_SAMPLER oss_shadowMap[OSS_MAX_SHADOW_SLOTS]; // prelude: raw depths in SILHOUETTE_MAP
#ifdef OSS_SILHOUETTE_MAP
// Silhouette-map mode: the term of oss_silhouette.frag.glsl, linked into the same program.
// Under FILTER_SILHOUETTE the second maps are the edge distances of oss_sildist.frag.glsl and the
// term that of oss_silhouette_filter.frag.glsl.
uniform OSS_SILHOUETTE_SAMPLER oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS]; // neighbourhood maps (oss_silnbr.frag.glsl)
float oss_silhouetteTerm(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition);
float oss_silhouetteFilterTerm(int s, sampler2D depthMap, sampler2D distanceMap, mat4 eyeToShadow, vec4 eyePosition);
#endif
#ifdef OSS_TRIANGLE_LISTS
// HYBRID with triangle lists: the term of oss_trilist_term.frag.glsl, linked into the same program.
float oss_listTerm(int s, float pcf, vec4 eyePosition, bool walk);
bool oss_listResolves(int s, float pcf, vec4 eyePosition);
#endif

uniform vec4 oss_lookupBiasFrame;        // eye-space centre of the shadowed scene's bound, the bias there
uniform float oss_lookupBiasPerDistance; // the bias per unit of distance from that centre

// The lookups' depth bias (docs/bias.md) at eye-space position p whose light clip-space
// position is c = eyeToShadow * p, in the map's [0,1] depth: a world-space distance (a share
// of the scene's radius, growing with the distance from its centre) times the gradient of
// the map's depth at p. The depth pass's constant offset is one step of the 24-bit depth;
// the rounding of positions is a share of their magnitude, which a perspective map's depth
// (changing as 1/w^2) magnifies near its near plane and an orthographic one not at all.
float oss_lookupBias(mat4 eyeToShadow, vec4 c, vec4 p)
{
    vec3 dz = vec3(eyeToShadow[0][2], eyeToShadow[1][2], eyeToShadow[2][2]);
    vec3 dw = vec3(eyeToShadow[0][3], eyeToShadow[1][3], eyeToShadow[2][3]);
    vec3 gradient = (dz * c.w - dw * c.z) / (c.w * c.w); // of c.z / c.w, per eye-space unit
    float world = oss_lookupBiasFrame.w + oss_lookupBiasPerDistance * length(p.xyz / p.w - oss_lookupBiasFrame.xyz);
    return world * length(gradient);
}

// The receiver's depth slope in light texture space (receiver plane depth bias, Isidoro
// 2006), from screen-space derivatives: taken in uniform control flow, before any branch.
vec2 oss_depthSlope(vec3 coord)
{
    vec3 dx = dFdx(coord), dy = dFdy(coord);
    float det = dx.x * dy.y - dx.y * dy.x;
    if (det == 0.0)
        return vec2(0.0);
    return vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
}

#ifdef OSS_BIAS_BAND
// HYBRID's lookup (the depth pass has no slope-scaled offset here, so that a caster just in
// front of a receiver keeps its depth): each of the four depth samples is compared with the
// receiver's plane extended to it, less the lookup bias. A sample that lies in front of that
// plane by less than OSS_CURVATURE_BAND of the plane's depth rise over a texel may be the
// receiver itself, curved or creased, or a caster touching it: the map cannot tell, and the
// PCF is moved strictly between 0 and 1 so that the exact test resolves the pixel.
const float OSS_CURVATURE_BAND = 1.0;

float oss_planePcf(sampler2DShadow map, vec3 t, vec2 slope, float bias)
{
    vec2 size = vec2(textureSize(map, 0));
    vec2 u = t.xy * size - 0.5;
    vec2 f = u - floor(u);
    vec2 at = (floor(u) + 1.0) / size; // the middle of the four samples: textureGather's footprint
    vec4 dx = (vec4(0.0, 1.0, 1.0, 0.0) - f.x) / size.x; // NW, NE, SE, SW as textureGather
    vec4 dy = (vec4(1.0, 1.0, 0.0, 0.0) - f.y) / size.y;
    vec4 plane = t.z + dx * slope.x + dy * slope.y - bias;
    vec4 lit = vec4(textureGather(map, at, plane.x).x, textureGather(map, at, plane.y).y,
                    textureGather(map, at, plane.z).z, textureGather(map, at, plane.w).w);
    float band = OSS_CURVATURE_BAND * (abs(slope.x) / size.x + abs(slope.y) / size.y);
    vec4 near = textureGather(map, at, min(min(plane.x, plane.y), min(plane.z, plane.w)) - band);
    float pcf = dot(lit, vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y)));
    return any(lessThan(lit, near)) ? clamp(pcf, 1.0 / 64.0, 63.0 / 64.0) : pcf;
}
#endif

// 2x2 PCF of one depth map at an eye-space position: 1 lit, 0 shadowed, between at edges.
float oss_pcf(sampler2DShadow map, mat4 eyeToShadow, vec4 eyePosition)
{
    vec4 c = eyeToShadow * eyePosition;
    vec3 t = c.xyz / c.w;
#ifdef OSS_BIAS_BAND
    vec2 slope = oss_depthSlope(t);
#endif
    if (c.w <= 0.0) return 1.0; // behind a perspective light: outside its map
    float bias = oss_lookupBias(eyeToShadow, c, eyePosition);
#ifdef OSS_BIAS_BAND
    return oss_planePcf(map, t, slope, bias);
#else
    return texture(map, vec3(t.xy, t.z - bias));
#endif
}

#if defined(OSS_FILTER_PCF) || defined(OSS_FILTER_PCSS)
// SHADOW_MAP under a soft filter (oss_filter.frag.glsl, linked into the same program): raw depths.
float oss_filterTerm(int s, sampler2D map, mat4 eyeToShadow, vec4 eyePosition);
#define OSS_PCF_TERM(s, p) oss_filterTerm(s, oss_shadowMap[s], oss_eyeToShadow[s], p)
#else
#define OSS_PCF_TERM(s, p) oss_pcf(oss_shadowMap[s], oss_eyeToShadow[s], p)
#endif
#if defined(OSS_SILHOUETTE_MAP) && defined(OSS_FILTER_SILHOUETTE)
#define OSS_MAP_TERM(s, p) oss_silhouetteFilterTerm(s, oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], p)
#elif defined(OSS_SILHOUETTE_MAP)
#define OSS_MAP_TERM(s, p) oss_silhouetteTerm(oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], p)
#elif defined(OSS_TRIANGLE_LISTS) && defined(OSS_LIST_SOFT)
#define OSS_MAP_TERM(s, p) oss_listSizedTerm(s, p, true).x
#elif defined(OSS_TRIANGLE_LISTS)
#define OSS_MAP_TERM(s, p) oss_listTerm(s, OSS_PCF_TERM(s, p), p, true)
#else
#define OSS_MAP_TERM(s, p) OSS_PCF_TERM(s, p)
#endif

#if defined(OSS_TRIANGLE_LISTS) && defined(OSS_LIST_SOFT)
// HYBRID under a light with a size (docs/soft-shadows.md): the penumbra class and its rays.
uniform float oss_listLightSize[OSS_MAX_SHADOW_SLOTS]; // 0: the slot's light is a point (hard)
uniform vec4 oss_listLight[OSS_MAX_SHADOW_SLOTS];      // eye space: (toward the light, 0) or (position, 1)
uniform vec2 oss_filterScale[OSS_MAX_SHADOW_SLOTS];    // footprint radius per unit of depth (penumbraScale())
vec2 oss_listSoftTerm(int s, float pcf, bool penumbra, vec4 eyePosition, bool walk);
const float OSS_CONE_MAX_TEXELS = 48.0; // ShaderConstants: LIST_CONE_MAX_TEXELS

// Whether one gather of slot s's depth map, `o` texels from the point (window position t),
// holds a sample nearer to the light than both the rays' cone there (a sample rho texels
// away can meet a ray only nearer than rho / perDepth of depth) and the receiver's plane
// (slope) extended to it, less the lookup bias.
bool oss_coneTap(int s, vec3 t, vec2 o, vec2 size, float perDepth, vec2 slope, float bias)
{
    float rho = max(0.0, length(o) - 1.5); // the nearest of the gather's four samples
    float band = abs(slope.x) / size.x + abs(slope.y) / size.y;
    float cone = t.z - rho / perDepth, plane = t.z + dot(slope, o / size) - band;
    vec4 lit = textureGather(oss_shadowMap[s], t.xy + o / size, min(cone, plane) - bias);
    return rho <= perDepth * t.z && any(lessThan(lit, vec4(0.5)));
}

// The blocker search of the penumbra class: whether a depth sample around eye-space point p
// within the footprint of the rays from p to slot s's light can meet one of them
// (oss_coneTap()). Squares of 4 x 4 gathers, each twice as wide as the one before (4, 8, 16,
// 32, 64 texels from the point): every sample within 4 texels, and a blocker whose own
// footprint is r texels wide is sampled at spacing r / 2 or finer, up to the footprint of a
// blocker at the map's near plane (at most OSS_CONE_MAX_TEXELS).
bool oss_coneBlocked(int s, vec4 p, vec2 slope)
{
    vec4 c = oss_eyeToShadow[s] * p;
    if (c.w <= 0.0) return false;
    vec3 t = c.xyz / c.w;
    float bias = oss_lookupBias(oss_eyeToShadow[s], c, p);
    vec2 size = vec2(textureSize(oss_shadowMap[s], 0));
    float perDepth = max(oss_filterScale[s].x * size.x, 1e-6); // footprint texels per unit of depth
    // A point or spot light's sphere: penumbraScale() is the footprint of a disc facing the
    // map's axis. The light's disc faces the point (MEASURE.md): off the axis its footprint
    // is wider, by |D| / D_ax across (D the light to the point, D_ax its depth along the axis,
    // c.w) and by up to D_ax / (D_ax - R) more where the disc leans toward the point's depth.
    // Without this, the outer rim of a penumbra off a cube face's axis read lit.
    vec4 light = oss_listLight[s];
    float radius = oss_listLightSize[s];
    if (light.w != 0.0)
        perDepth *= c.w > 2.0 * radius ? length(p.xyz / p.w - light.xyz) / (c.w - radius) : 1e6;
    float reach = min(perDepth * t.z, OSS_CONE_MAX_TEXELS) + 1.5;
    bool blocked = false;
    for (int level = 0; level < 5 && !blocked; ++level)
    {
        float side = 4.0 * exp2(float(level));
        for (int i = 0; i < 16 && !blocked && (level == 0 || side < 2.0 * reach); ++i)
            blocked = oss_coneTap(s, t, (vec2(float(i % 4), float(i / 4)) - 1.5) * (side / 2.0), size, perDepth, slope, bias);
    }
    return blocked;
}

// Slot s's term under the lists (x) and its class (y: 0 the map's answer, 1 resolved exactly,
// 2 the rays of a light with a size); a slot whose light has no size keeps the hard term.
// `walk` false: the caller needs no exact answer here (the light does not reach the point's
// side), the map's answer is returned. Called by the receivers' shading (oss_receiver.frag)
// and by oss_shadowTerm() for the debug views and applications' programs.
vec2 oss_listSizedTerm(int s, vec4 p, bool walk)
{
    vec4 c = oss_eyeToShadow[s] * p;
    vec2 slope = oss_depthSlope(c.xyz / (c.w > 0.0 ? c.w : 1.0)); // uniform control flow
    float pcf = OSS_PCF_TERM(s, p);
    if (oss_listLightSize[s] <= 0.0)
        return vec2(oss_listTerm(s, pcf, p, walk), oss_listResolves(s, pcf, p) ? 1.0 : 0.0);
    return oss_listSoftTerm(s, pcf, walk && oss_coneBlocked(s, p, slope), p, walk);
}
#endif

#ifdef OSS_CUBE_FACES
// A light with several maps: a point light's cube faces (docs/lights.md), each answering
// only for its own 90-degree square of directions, a few texels inside its slightly wider
// map; or a directional light's cascades (docs/outdoor.md), each answering for its own range
// of view depths. The light's term is the product of its maps' terms, 1 outside each map's
// own part.
uniform int oss_slotOwner[OSS_MAX_SHADOW_SLOTS];   // the light slot whose term a slot's map multiplies
uniform float oss_slotCore[OSS_MAX_SHADOW_SLOTS];  // cube face: half side of its own square; 0: whole map
uniform vec2 oss_slotDepths[OSS_MAX_SHADOW_SLOTS]; // cascade: its view depths [x, y); (0, 3e38): all

// term where the eye-space position lies in slot `slot`'s own part, else 1.
float oss_faceGate(int slot, vec4 eyePosition, float term)
{
    float depth = -eyePosition.z / eyePosition.w;
    vec2 depths = oss_slotDepths[slot];
    if (depth < depths.x || depth >= depths.y)
        return 1.0;
    float core = oss_slotCore[slot];
    vec4 c = oss_eyeToShadow[slot] * eyePosition;
    vec2 d = abs(c.xy / c.w - 0.5);
    return core <= 0.0 || (c.w > 0.0 && max(d.x, d.y) <= core) ? term : 1.0;
}
#endif

// The shadow term of the light of shadow slot `slot`. Sampler arrays take constant indices
// here: a dynamic index is slow on some drivers (llvmpipe) and needs GLSL 4 elsewhere.
float oss_shadowSlotTerm(int slot, vec4 eyePosition)
{
#ifdef OSS_CUBE_FACES
    float term = 1.0;
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (oss_slotOwner[s] == slot && ((OSS_SKIPPED_SLOTS >> s) & 1) == 0)
            term *= oss_faceGate(s, eyePosition, OSS_MAP_TERM(s, eyePosition));
    return term;
#else
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (s == slot)
            return OSS_MAP_TERM(s, eyePosition);
    return 1.0;
#endif
}

#if defined(OSS_HYBRID_EDGES) && !defined(OSS_SILHOUETTE_MAP)
// HYBRID's edge mask of each slot: a silhouette map (oss_silmap.*.glsl, on the dual grid of
// the depth map) drawn from the light's silhouette edges, occluded ones left out, each texel
// holding the nearest depth an edge crossing it reaches (MIN blending; cleared far). Where an
// edge crosses the square of the four depth samples around a point and lies in front of it,
// the shadow boundary may pass between the samples although they agree (a caster or a gap
// thinner than a texel), so the point is resolved exactly (lists or volumes) as well.
uniform sampler2D oss_silhouetteMap[OSS_MAX_SHADOW_SLOTS];

// Whether an edge in front of light texture-space point p (x, y, window depth z) crosses the
// square of slot s's four depth samples around it.
bool oss_slotEdge(int s, vec3 p)
{
    vec2 size = vec2(textureSize(oss_silhouetteMap[s], 0));
    vec2 texel = floor(p.xy * size - 0.5); // the dual-grid texel whose corners are those samples
    return texture(oss_silhouetteMap[s], (texel + 0.5) / size).r < p.z; // border and clear: far
}

// The same at an eye-space position (false behind a perspective light).
bool oss_slotEdgeAt(int s, vec4 eyePosition)
{
    vec4 c = oss_eyeToShadow[s] * eyePosition;
    return c.w > 0.0 && oss_slotEdge(s, c.xyz / c.w);
}
#endif

#ifndef OSS_SILHOUETTE_MAP
// The 2x2 PCF of the light of shadow slot `slot` (HYBRID's mask and light passes): its own
// map's, or the product of its cube faces'.
float oss_lightPcf(int slot, vec4 eyePosition)
{
#if defined(OSS_LIGHT_FACES)
    // A pass of one light (the stencil modes' mask and light passes) names its light's slots
    // at compile time, bit s for slot s: it samples those maps only, whatever the other
    // lights' faces.
#ifdef OSS_CUBE_FACES
#define OSS_FACE_PCF(s) oss_faceGate(s, eyePosition, OSS_PCF_TERM(s, eyePosition))
#else
#define OSS_FACE_PCF(s) OSS_PCF_TERM(s, eyePosition)
#endif
#define OSS_HAS_FACE(s) ((OSS_LIGHT_FACES) >> (s) & 1)
    float term = 1.0;
#if OSS_HAS_FACE(0)
    term *= OSS_FACE_PCF(0);
#endif
#if OSS_HAS_FACE(1)
    term *= OSS_FACE_PCF(1);
#endif
#if OSS_HAS_FACE(2)
    term *= OSS_FACE_PCF(2);
#endif
#if OSS_HAS_FACE(3)
    term *= OSS_FACE_PCF(3);
#endif
#if OSS_HAS_FACE(4)
    term *= OSS_FACE_PCF(4);
#endif
#if OSS_HAS_FACE(5)
    term *= OSS_FACE_PCF(5);
#endif
#if OSS_HAS_FACE(6)
    term *= OSS_FACE_PCF(6);
#endif
#if OSS_HAS_FACE(7)
    term *= OSS_FACE_PCF(7);
#endif
#if OSS_HAS_FACE(8)
    term *= OSS_FACE_PCF(8);
#endif
#if OSS_HAS_FACE(9)
    term *= OSS_FACE_PCF(9);
#endif
#if OSS_HAS_FACE(10)
    term *= OSS_FACE_PCF(10);
#endif
#if OSS_HAS_FACE(11)
    term *= OSS_FACE_PCF(11);
#endif
    return term; // slots 0-11: shader::MAX_SHADOW_SLOTS
#elif defined(OSS_CUBE_FACES)
    float term = 1.0;
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (oss_slotOwner[s] == slot)
            term *= oss_faceGate(s, eyePosition, OSS_PCF_TERM(s, eyePosition));
    return term;
#else
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (s == slot)
            return OSS_PCF_TERM(s, eyePosition);
    return 1.0;
#endif
}
#endif

#if defined(OSS_HYBRID_EDGES) && !defined(OSS_SILHOUETTE_MAP)
// Whether the edge mask of the light of shadow slot `slot` (HYBRID's stencil mask pass)
// marks an eye-space position: its own slot's, or that of the cube face whose own directions
// hold it, among the slots named by OSS_LIGHT_FACES (without it: slot `slot`'s alone).
bool oss_lightEdges(int slot, vec4 eyePosition)
{
#ifndef OSS_LIGHT_FACES
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (s == slot)
            return oss_slotEdgeAt(s, eyePosition);
    return false;
#else
    bool edge = false;
#ifdef OSS_CUBE_FACES
#define OSS_FACE_EDGE(s) (oss_faceGate(s, eyePosition, 0.0) == 0.0 && oss_slotEdgeAt(s, eyePosition))
#else
#define OSS_FACE_EDGE(s) oss_slotEdgeAt(s, eyePosition)
#endif
#if OSS_HAS_FACE(0)
    edge = edge || OSS_FACE_EDGE(0);
#endif
#if OSS_HAS_FACE(1)
    edge = edge || OSS_FACE_EDGE(1);
#endif
#if OSS_HAS_FACE(2)
    edge = edge || OSS_FACE_EDGE(2);
#endif
#if OSS_HAS_FACE(3)
    edge = edge || OSS_FACE_EDGE(3);
#endif
#if OSS_HAS_FACE(4)
    edge = edge || OSS_FACE_EDGE(4);
#endif
#if OSS_HAS_FACE(5)
    edge = edge || OSS_FACE_EDGE(5);
#endif
#if OSS_HAS_FACE(6)
    edge = edge || OSS_FACE_EDGE(6);
#endif
#if OSS_HAS_FACE(7)
    edge = edge || OSS_FACE_EDGE(7);
#endif
#if OSS_HAS_FACE(8)
    edge = edge || OSS_FACE_EDGE(8);
#endif
#if OSS_HAS_FACE(9)
    edge = edge || OSS_FACE_EDGE(9);
#endif
#if OSS_HAS_FACE(10)
    edge = edge || OSS_FACE_EDGE(10);
#endif
#if OSS_HAS_FACE(11)
    edge = edge || OSS_FACE_EDGE(11);
#endif
    return edge; // slots 0-11: shader::MAX_SHADOW_SLOTS
#endif
}
#endif

// The shadow slot of GL light `light`, or -1 when it casts no shadow.
int oss_shadowSlotOf(int light)
{
    for (int k = 0; k < oss_numLights; ++k)
        if (oss_lightIndex[k] == light)
            return oss_shadowSlot[k];
    return -1;
}

// The shadow term of GL light `light` (gl_LightSource index) at an eye-space position:
// 1 where the light reaches the point, 0 where it is blocked; unshadowed lights give 1.
#ifdef OSS_SCREEN_VISIBILITY
float oss_screenVisibilityTerm(int slot); // the stencil modes' answer (oss_screen_visibility.frag.glsl)
#endif

float oss_shadowTerm(int light, vec4 eyePosition)
{
    int slot = oss_shadowSlotOf(light);
#ifdef OSS_SCREEN_VISIBILITY
    return slot < 0 ? 1.0 : oss_screenVisibilityTerm(slot);
#else
    return slot < 0 ? 1.0 : oss_shadowSlotTerm(slot, eyePosition);
#endif
}

// A face counts as facing a light when N.L exceeds this, not merely 0: a face that contains
// the light (N.L = 0 exactly, e.g. the ground under a light along a horizontal axis) is
// otherwise lit or not by the rounding of the derivative normal, and half of it then goes
// to a depth-map lookup exactly at the casters' bottom row. 1e-3 is 0.06 degrees; such a
// face gets at most 0.1% of the light's diffuse, and the exact reference's grazing band
// (0 < N.L < 0.05) is not scored.
const float OSS_MIN_FACING = 1e-3;

// Whether the surface at eye-space point p faces GL light n (geometric normal, from the
// screen-space derivatives of p) and lies inside its spot cone: the "facing" of the exact
// reference. Call it where derivatives are defined (uniform control flow).
bool oss_facesLight(int n, vec3 p)
{
    vec3 ng = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(ng, -p) < 0.0)
        ng = -ng; // toward the camera
    vec4 lp = gl_LightSource[n].position;
    vec3 L = normalize(lp.w == 0.0 ? lp.xyz : lp.xyz / lp.w - p);
    bool inCone = lp.w == 0.0 || gl_LightSource[n].spotCutoff > 90.0 ||
                  dot(-L, normalize(gl_LightSource[n].spotDirection)) >= gl_LightSource[n].spotCosCutoff;
    return dot(ng, L) > OSS_MIN_FACING && inCone;
}

// DebugView DEBUG_CLASSES (Chan and Durand 2004, figure colours): red / blue where the
// shadow map answers lit / shadowed, green / black at silhouette pixels by the exact answer
// (silhouette reconstruction or shadow volumes).
vec4 oss_classColor(bool silhouette, bool lit)
{
    return silhouette ? (lit ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(0.0, 0.0, 0.0, 1.0))
                      : (lit ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0, 0.0, 1.0, 1.0));
}

#ifdef OSS_SILHOUETTE_MAP
vec2 oss_silhouetteClass(sampler2D depthMap, usampler2D silhouetteMap, mat4 eyeToShadow, vec4 eyePosition);
#endif

// The class of shadow slot s at an eye-space position: x the shadow term (1 lit), y 1 where
// the mode treats the pixel as a silhouette pixel. SHADOW_MAP marks the pixels whose 2x2 PCF
// lies strictly between 0 and 1 (those HYBRID would resolve with volumes).
#if defined(OSS_SILHOUETTE_MAP) && defined(OSS_FILTER_SILHOUETTE)
// FILTER_SILHOUETTE's silhouette pixels: where its answer is a visible fraction. Within half
// an 8-bit step of 0 or 1 it is not: rounding in the samples' sum and the disc profile's tails
// left about 800 scattered pixels of the default scene's lit ground marked.
const float OSS_CLASS_FRACTION = 1.0 / 510.0;
vec2 oss_termClass(float v)
{
    return vec2(step(0.5, v), v > OSS_CLASS_FRACTION && v < 1.0 - OSS_CLASS_FRACTION ? 1.0 : 0.0);
}
#define OSS_SLOT_CLASS(s, p) oss_termClass(OSS_MAP_TERM(s, p))
#elif defined(OSS_SILHOUETTE_MAP)
#define OSS_SLOT_CLASS(s, p) oss_silhouetteClass(oss_shadowMap[s], oss_silhouetteMap[s], oss_eyeToShadow[s], p)
#elif defined(OSS_TRIANGLE_LISTS) && defined(OSS_LIST_SOFT)
vec2 oss_softClass(vec2 c) { return vec2(c.y > 1.5 ? c.x : step(0.5, c.x), c.y); }
#define OSS_SLOT_CLASS(s, p) oss_softClass(oss_listSizedTerm(s, p, true))
#elif defined(OSS_TRIANGLE_LISTS)
vec2 oss_listClass(int s, vec4 eyePosition)
{
    float p = oss_pcf(oss_shadowMap[s], oss_eyeToShadow[s], eyePosition);
    return vec2(step(0.5, oss_listTerm(s, p, eyePosition, true)), oss_listResolves(s, p, eyePosition) ? 1.0 : 0.0);
}
#define OSS_SLOT_CLASS(s, p) oss_listClass(s, p)
#else
vec2 oss_pcfClass(float p) { return vec2(step(0.5, p), p > 0.0 && p < 1.0 ? 1.0 : 0.0); }
#define OSS_SLOT_CLASS(s, p) oss_pcfClass(OSS_PCF_TERM(s, p))
#endif

// The class of the light of shadow slot `slot`: its own slot's, or, for a point light with
// cube faces, that of the face whose own directions hold the point (every face's class is
// computed, in uniform control flow, and the face gate picks one).
vec2 oss_shadowSlotClass(int slot, vec4 eyePosition)
{
    vec2 result = vec2(1.0, 0.0);
#ifdef OSS_CUBE_FACES
    for (int s = 0; s < OSS_NUM_SHADOW_SLOTS; ++s)
        if (oss_slotOwner[s] == slot)
        {
            vec2 c = OSS_SLOT_CLASS(s, eyePosition);
            result = oss_faceGate(s, eyePosition, 0.0) == 0.0 ? c : result;
        }
#else
    for (int s = 0; s < OSS_MAX_SHADOW_LIGHTS; ++s)
        if (s == slot)
            result = OSS_SLOT_CLASS(s, eyePosition);
#endif
    return result;
}
