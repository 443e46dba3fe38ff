#version 400 compatibility
// osgShadowSilhouette: silhouette distance map (FILTER_SILHOUETTE), fragment stage.
//
// Valient and Bujnak 2005, section 2.1.1: for the texel's centre p, the nearest point of the
// edge a -> b; R = the signed distance to it in texels, positive on the casting side (the
// left of a -> b in light window coordinates: CasterEdges orients each silhouette edge with
// its casting face on the left seen from the light), G = the edge's window depth there.
// Texels farther than W from the edge are discarded. The depth written is |R| / W, and the
// pass tests LESS against a buffer cleared to 1: of the edges reaching a texel the nearest
// wins (the paper's depth and alpha tests, as one depth test). Where the nearest point is an
// endpoint the side of the line says nothing (beyond a corner the two edges meeting there are
// equally near, and the one whose line passes the texel gives the wrong sign): such a texel
// counts OSS_SILDIST_END_PENALTY texels farther, so that an edge the texel projects onto wins.
#define OSS_SILDIST_END_PENALTY 0.01

uniform float oss_sildistWidth; // W, in texels

flat in vec4 oss_edge;
flat in vec2 oss_edgeDepth;

void main()
{
    vec2 p = gl_FragCoord.xy;
    vec2 a = oss_edge.xy, b = oss_edge.zw;
    vec2 ab = b - a;
    float len2 = dot(ab, ab);
    float along = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
    float t = clamp(along, 0.0, 1.0);
    float dist = distance(p, a + ab * t);
    if (dist > oss_sildistWidth)
        discard;
    float side = ab.x * (p.y - a.y) - ab.y * (p.x - a.x); // > 0: left of a -> b
    float d = side >= 0.0 ? dist : -dist;
    gl_FragColor = vec4(d, mix(oss_edgeDepth.x, oss_edgeDepth.y, t), 0.0, 1.0);
    float penalty = along == t ? 0.0 : OSS_SILDIST_END_PENALTY;
    gl_FragDepth = min((dist + penalty) / oss_sildistWidth, 1.0);
}
