// Triangle soups that shadow volumes must handle exactly: every triangle with its own three
// corners (the mesh builder's welding decides what is connected), built in code.
#ifndef OSS_TEST_SOUPS_H
#define OSS_TEST_SOUPS_H

#include <osg/Geometry>

#include <string>
#include <vector>

namespace souptest {

using Triangle = std::vector<osg::Vec3f>; // three corners, counter-clockwise from the front

inline osg::ref_ptr<osg::Geometry> soupGeometry(const std::vector<Triangle>& triangles, const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (const Triangle& t : triangles) corners->insert(corners->end(), t.begin(), t.end());
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(name);
    g->setVertexArray(corners.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(corners->size())));
    return g;
}

/** The quad a, b, c, d (counter-clockwise from the front) as two triangles. */
inline void addQuad(std::vector<Triangle>& out, osg::Vec3f a, osg::Vec3f b, osg::Vec3f c, osg::Vec3f d)
{
    out.push_back({a, b, c});
    out.push_back({a, c, d});
}

inline void flip(Triangle& t) { std::swap(t[1], t[2]); }

/** Box [lo, hi], faces wound outward; `skip`: a face left out (0..5 for -z +z -y +y -x +x). */
inline std::vector<Triangle> box(osg::Vec3f lo, osg::Vec3f hi, int skip = -1)
{
    auto p = [&](int x, int y, int z) { return osg::Vec3f(x ? hi.x() : lo.x(), y ? hi.y() : lo.y(), z ? hi.z() : lo.z()); };
    std::vector<Triangle> t;
    const int faces[6][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                                {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
                                {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
    for (int f = 0; f < 6; ++f)
    {
        if (f == skip) continue;
        const auto& q = faces[f];
        addQuad(t, p(q[0][0], q[0][1], q[0][2]), p(q[1][0], q[1][1], q[1][2]), p(q[2][0], q[2][1], q[2][2]),
                p(q[3][0], q[3][1], q[3][2]));
    }
    return t;
}

inline std::vector<Triangle> flipped(std::vector<Triangle> t)
{
    for (Triangle& x : t) flip(x);
    return t;
}

inline std::vector<Triangle> joined(std::vector<Triangle> a, const std::vector<Triangle>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

/** Three triangles on the edge y = -1..1 at the origin: a book with three pages. */
inline std::vector<Triangle> threeFacesOnAnEdge()
{
    const osg::Vec3f a(0, -1, 0), b(0, 1, 0);
    return {{a, b, osg::Vec3f(1, 0, 0.2f)}, {b, a, osg::Vec3f(-1, 0, 0.3f)}, {a, b, osg::Vec3f(0.2f, 0, 1)}};
}

/** The quad [-1,1]^2 at z = 0 twice, back to back (a double-sided sheet). */
inline std::vector<Triangle> backToBackQuads()
{
    std::vector<Triangle> t;
    addQuad(t, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
    return joined(t, flipped(t));
}

/** The unit box with its top face wound inward. */
inline std::vector<Triangle> boxWithAFlippedFace()
{
    std::vector<Triangle> t = box({-1, -1, -1}, {1, 1, 1});
    flip(t[2]);
    flip(t[3]);
    return t;
}

/** Two quads side by side, the right one split in two along y = 0: its middle vertex lies
 *  on the left quad's edge (a T-junction), with a crack of 1e-4 between them. */
inline std::vector<Triangle> tJunction()
{
    std::vector<Triangle> t;
    addQuad(t, {-1, -1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 1, 0});
    addQuad(t, {1e-4f, -1, 0}, {1, -1, 0}, {1, 0, 0}, {1e-4f, 0, 0});
    addQuad(t, {1e-4f, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1e-4f, 1, 0});
    return t;
}

/** Two unit boxes touching along the face x = 0 (coincident faces wound opposite ways). */
inline std::vector<Triangle> twoTouchingBoxes()
{
    return joined(box({-1, -1, -1}, {0, 1, 1}), box({0, -1, -1}, {1, 1, 1}));
}

/** A room: a closed box wound inward (seen from within), with an outward box inside. */
inline std::vector<Triangle> roomWithABox()
{
    return joined(flipped(box({-2, -2, -2}, {2, 2, 2})), box({-0.5f, -0.5f, -2}, {0.5f, 0.5f, -1}));
}

} // namespace souptest

#endif
