#version 430 compatibility
// osgShadowSilhouette: triangle-list pass, fragment stage: one fragment per texel of the
// triangle's grown bounding box. Keeps the texels whose square the triangle overlaps
// (separating axes: the box's two and the triangle's three edge normals) and prepends the
// triangle to the texel's list (buffer layout: oss_trilist.geom.glsl).

layout(early_fragment_tests) in;
layout(std430, binding = 0) buffer OssList { uint oss_list[]; };
uniform uint oss_listNodeCapacity;
uniform vec2 oss_listGridSize;

flat in uint oss_triangle;
flat in vec2 oss_v0, oss_v1, oss_v2;

// Whether the texel square [lo, hi] lies wholly on the outer side of edge a -> b of a
// triangle of orientation s (the triangle's third vertex is on the inner side).
bool oss_outside(vec2 a, vec2 b, float s, vec2 lo, vec2 hi)
{
    vec2 n = s * vec2(b.y - a.y, a.x - b.x); // outward normal
    vec2 corner = vec2(n.x < 0.0 ? hi.x : lo.x, n.y < 0.0 ? hi.y : lo.y); // the most inward corner
    return dot(corner - a, n) > 0.0;
}

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec2 lo = vec2(texel) / oss_listGridSize, hi = vec2(texel + 1) / oss_listGridSize;
    vec2 e1 = oss_v1 - oss_v0, e2 = oss_v2 - oss_v0;
    float s = sign(e1.x * e2.y - e1.y * e2.x);
    vec2 tlo = min(min(oss_v0, oss_v1), oss_v2), thi = max(max(oss_v0, oss_v1), oss_v2);
    if (any(greaterThan(tlo, hi)) || any(lessThan(thi, lo)) || oss_outside(oss_v0, oss_v1, s, lo, hi) ||
        oss_outside(oss_v1, oss_v2, s, lo, hi) || oss_outside(oss_v2, oss_v0, s, lo, hi))
        discard;
    uint node = atomicAdd(oss_list[0], 1u);
    if (node < oss_listNodeCapacity)
    {
        uint grid = uint(oss_listGridSize.x);
        uint t = uint(texel.y) * grid + uint(texel.x);
        uint next = atomicExchange(oss_list[4u + t], node + 1u); // heads hold node + 1
        uint nodes = 4u + 2u * grid * grid;
        oss_list[nodes + 2u * node] = oss_triangle;
        oss_list[nodes + 2u * node + 1u] = next;
        atomicAdd(oss_list[4u + grid * grid + t], 1u);
    }
    gl_FragColor = vec4(0.0);
}
