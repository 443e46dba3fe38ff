#version 400 compatibility
// osgShadowSilhouette: the neighbourhood map, fragment stage (SILHOUETTE_MAP only).
//
// The eye pass needs five silhouette points at once: its texel's and those of the four texels
// beside it. Fetched from the silhouette map itself they cost two textureGather() calls,
// which a SIMD rasterizer pays at every pixel behind the branch. So after the silhouette
// map is drawn, this pass packs each texel's five points into one RGBA32UI texel, and the
// eye pass reads them with one texelFetch().
//
// It runs over the same edges as the silhouette map, widened to OSS_HALF_WIDTH = 1.75 texels
// (oss_silmap.geom.glsl, OSS_SILMAP_NEIGHBOURHOOD): every texel one of whose four neighbours
// holds a point lies within 1.58 texels of the edge that wrote it. Every other texel keeps
// the cleared value, five default points, which is what it would pack.
//
// The map is one texel larger than the silhouette map: neighbourhood texel k + 1 holds
// silhouette texel k, for k from -1 (outside the map, next to its first texel) to size - 1.
// Packing (packNeighbourhood() in osgShadowSilhouette/SilhouettePoints, its C++ twin): each
// point is its 24-bit stored value (X * 4096 + Y); x = centre, y = east, z = north, w = west
// in the low 24 bits, and south's three bytes in the top bytes of x, y and z.

uniform sampler2D oss_silmapPoints; // the silhouette map just drawn (R32F, border: default point)

layout(location = 0) out uvec4 oss_neighbourhood;

void main()
{
    vec2 texel = floor(gl_FragCoord.xy) - 1.0;
    vec2 size = vec2(textureSize(oss_silmapPoints, 0));
    // Gather order (0,1), (1,1), (1,0), (0,0): around (i+1, j+1) N, NE, E, C; around (i, j) W, C, S, SW.
    uvec4 upper = uvec4(textureGather(oss_silmapPoints, (texel + 1.0) / size));
    uvec4 lower = uvec4(textureGather(oss_silmapPoints, texel / size));
    uint south = lower.z;
    oss_neighbourhood = uvec4(upper.w, upper.z, upper.x, lower.x) |
                        ((uvec4(south, south >> 8u, south >> 16u, 0u) & 0xFFu) << 24u);
}
