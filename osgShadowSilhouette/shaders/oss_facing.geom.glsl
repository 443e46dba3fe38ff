#version 400 compatibility
// osgShadowSilhouette: the facing test of the geometry stages that find shadow geometry on the
// GPU (oss_gpuvolume.geom.glsl, oss_silmap.geom.glsl over triangles with adjacency), linked
// into their programs beside them.

bool oss_before(vec3 a, vec3 b)
{
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

// > 0: the face a -> b -> c turns its counter-clockwise side toward @p light ((x, y, z, 1) a
// positional light, (x, y, z, 0) toward a directional one; the corners' frame), as the CPU
// path's plane . light. Evaluated from the face's first corner in position order, so that a
// face and its neighbour, which see its corners in another rotation, round alike and agree on
// its sign (were they to disagree, an edge would be drawn twice or not at all).
float oss_facing(vec3 a, vec3 b, vec3 c, vec4 light)
{
    if (oss_before(b, a) && oss_before(b, c))
    {
        vec3 t = a;
        a = b;
        b = c;
        c = t;
    }
    else if (oss_before(c, a) && oss_before(c, b))
    {
        vec3 t = a;
        a = c;
        c = b;
        b = t;
    }
    return dot(cross(b - a, c - a), light.xyz - a * light.w);
}
