// Shapes and invariant checks shared by the mesh and extraction tests.
#pragma once

#include <osgShadowSilhouette/MeshAdjacency>
#include <osgShadowSilhouette/SilhouetteExtractor>

#include <osg/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace meshtest {

using osgShadowSilhouette::MeshAdjacency;
using osgShadowSilhouette::ShadowVolume;
using osgShadowSilhouette::SilhouetteEdges;

inline osg::ref_ptr<osg::Geometry> makeGeometry(const std::vector<osg::Vec3f>& positions,
                                                const std::vector<unsigned int>& triangles,
                                                const std::string& name = "")
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(name);
    g->setVertexArray(new osg::Vec3Array(positions.begin(), positions.end()));
    g->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, triangles.begin(), triangles.end()));
    return g;
}

/** Cube [-1,1]^3, 8 vertices, 12 outward counter-clockwise triangles. */
inline osg::ref_ptr<osg::Geometry> cube(const std::string& name = "cube")
{
    std::vector<osg::Vec3f> p = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
                                  { -1, -1, 1 },  { 1, -1, 1 },  { 1, 1, 1 },  { -1, 1, 1 } };
    std::vector<unsigned int> t = { 0, 2, 1, 0, 3, 2,   // -z
                                    4, 5, 6, 4, 6, 7,   // +z
                                    0, 1, 5, 0, 5, 4,   // -y
                                    2, 3, 7, 2, 7, 6,   // +y
                                    1, 2, 6, 1, 6, 5,   // +x
                                    3, 0, 4, 3, 4, 7 }; // -x
    return makeGeometry(p, t, name);
}

/** The tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1); face i is opposite vertex i,
 *  with outward normal along -vertex i. */
inline osg::ref_ptr<osg::Geometry> tetrahedron()
{
    std::vector<osg::Vec3f> p = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
    std::vector<unsigned int> t = { 1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2 };
    return makeGeometry(p, t, "tetrahedron");
}

/** Unit UV sphere around the z axis: poles, stacks-1 rings of `slices` vertices. */
inline osg::ref_ptr<osg::Geometry> uvSphere(unsigned slices, unsigned stacks, float radius = 1.0f)
{
    std::vector<osg::Vec3f> p = { { 0, 0, radius } };
    for (unsigned i = 1; i < stacks; ++i)
        for (unsigned j = 0; j < slices; ++j)
        {
            double theta = osg::PI * i / stacks, phi = 2.0 * osg::PI * j / slices;
            p.push_back(osg::Vec3f(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                   std::cos(theta)) * radius);
        }
    p.push_back(osg::Vec3f(0, 0, -radius));
    auto ring = [&](unsigned i, unsigned j) { return 1 + (i - 1) * slices + j % slices; };
    std::vector<unsigned int> t;
    for (unsigned j = 0; j < slices; ++j)
    {
        t.insert(t.end(), { 0u, ring(1, j), ring(1, j + 1) });
        for (unsigned i = 1; i + 1 < stacks; ++i)
            t.insert(t.end(), { ring(i, j), ring(i + 1, j), ring(i + 1, j + 1),
                                ring(i, j), ring(i + 1, j + 1), ring(i, j + 1) });
        unsigned south = unsigned(p.size() - 1);
        t.insert(t.end(), { south, ring(stacks - 1, j + 1), ring(stacks - 1, j) });
    }
    return makeGeometry(p, t, "sphere");
}

/** Torus around the z axis, major radius R, minor radius r (genus 1). */
inline osg::ref_ptr<osg::Geometry> torus(unsigned major, unsigned minor, float R = 2.0f, float r = 0.5f)
{
    std::vector<osg::Vec3f> p;
    for (unsigned u = 0; u < major; ++u)
        for (unsigned v = 0; v < minor; ++v)
        {
            double phi = 2.0 * osg::PI * u / major, theta = 2.0 * osg::PI * v / minor;
            double rho = R + r * std::cos(theta);
            p.push_back(osg::Vec3f(rho * std::cos(phi), rho * std::sin(phi), r * std::sin(theta)));
        }
    auto id = [&](unsigned u, unsigned v) { return (u % major) * minor + v % minor; };
    std::vector<unsigned int> t;
    for (unsigned u = 0; u < major; ++u)
        for (unsigned v = 0; v < minor; ++v)
            t.insert(t.end(), { id(u, v), id(u + 1, v), id(u + 1, v + 1),
                                id(u, v), id(u + 1, v + 1), id(u, v + 1) });
    return makeGeometry(p, t, "torus");
}

/** The square [-1,1]^2 at z = 0, normal +z, two triangles: an open mesh. */
inline osg::ref_ptr<osg::Geometry> openPlane()
{
    return makeGeometry({ { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } },
                        { 0, 1, 2, 0, 2, 3 }, "plane");
}

/** Three triangles on the edge A(0,-1,0)-B(0,1,0): two flat pages (normal +z) forming the
 *  rhombus |x|+|y| <= 1 and a vertical fin towards C3 = (0,0,1) (normal +x). OpenMesh
 *  refuses the fin. */
inline osg::ref_ptr<osg::Geometry> nonManifoldBook()
{
    return makeGeometry({ { 0, -1, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { -1, 0, 0 }, { 0, 0, 1 } },
                        { 0, 2, 1, 0, 1, 3, 0, 1, 4 }, "book");
}

/** The cube with the top-front edge A-B split at M = (0,-1,1) on the top side only and the
 *  crack closed by the zero-area triangle (A, B, M). */
inline osg::ref_ptr<osg::Geometry> cubeWithZeroAreaFace()
{
    std::vector<osg::Vec3f> p = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
                                  { -1, -1, 1 },  { 1, -1, 1 },  { 1, 1, 1 },  { -1, 1, 1 },
                                  { 0, -1, 1 } };
    std::vector<unsigned int> t = { 0, 2, 1, 0, 3, 2,            // -z
                                    4, 8, 7, 8, 6, 7, 8, 5, 6,   // +z with M
                                    4, 5, 8,                     // zero-area A, B, M
                                    5, 4, 0, 5, 0, 1,            // -y
                                    2, 3, 7, 2, 7, 6,            // +y
                                    1, 2, 6, 1, 6, 5,            // +x
                                    3, 0, 4, 3, 4, 7 };          // -x
    return makeGeometry(p, t, "cube with zero-area face");
}

inline MeshAdjacency adjacencyOf(const osg::Geometry& g)
{
    MeshAdjacency a;
    osgShadowSilhouette::buildMeshAdjacency(g, osgShadowSilhouette::MeshBuildOptions(), a);
    return a;
}

// ----- invariants of silhouettes -----------------------------------------------------------

/** Every vertex has as many silhouette edges leaving as arriving. */
inline bool silhouetteIsBalanced(const SilhouetteEdges& s)
{
    std::map<std::uint32_t, int> balance;
    for (std::size_t e = 0; e < s.edgeCount(); ++e)
    {
        ++balance[s.vertexIndices[2 * e]];
        --balance[s.vertexIndices[2 * e + 1]];
    }
    return std::all_of(balance.begin(), balance.end(), [](const auto& b) { return b.second == 0; });
}

/** Every silhouette vertex has an even number of silhouette edges. */
inline bool silhouetteHasEvenDegrees(const SilhouetteEdges& s)
{
    std::map<std::uint32_t, int> degree;
    for (std::uint32_t v : s.vertexIndices) ++degree[v];
    return std::all_of(degree.begin(), degree.end(), [](const auto& d) { return d.second % 2 == 0; });
}

/** Connected components of the silhouette edge graph. */
inline std::size_t silhouetteLoops(const SilhouetteEdges& s)
{
    std::map<std::uint32_t, std::uint32_t> parent;
    std::function<std::uint32_t(std::uint32_t)> find = [&](std::uint32_t v) {
        if (!parent.count(v)) parent[v] = v;
        return parent[v] == v ? v : parent[v] = find(parent[v]);
    };
    for (std::size_t e = 0; e < s.edgeCount(); ++e)
        parent[find(s.vertexIndices[2 * e])] = find(s.vertexIndices[2 * e + 1]);
    std::set<std::uint32_t> roots;
    for (auto& p : parent) roots.insert(find(p.first));
    return roots.size();
}

// ----- invariants of volumes ---------------------------------------------------------------

/** Undirected edges {a < b} not used exactly once in each direction. With none, the
 *  triangles form a closed, consistently oriented surface in which each edge has two faces. */
inline std::set<std::pair<std::uint32_t, std::uint32_t>> nonManifoldEdges(const ShadowVolume& v)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < v.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k)
            ++directed[{ v.indices[t + k], v.indices[t + (k + 1) % 3] }];
    std::set<std::pair<std::uint32_t, std::uint32_t>> bad;
    for (auto& d : directed)
    {
        auto reverse = directed.find({ d.first.second, d.first.first });
        if (d.second != 1 || reverse == directed.end() || reverse->second != 1)
            bad.insert({ std::min(d.first.first, d.first.second), std::max(d.first.first, d.first.second) });
    }
    return bad;
}

/** Vertices whose triangles form more than one fan (the surface is pinched there). Call on
 *  a closed edge-manifold only; with none, the surface is a closed 2-manifold. */
inline std::set<std::uint32_t> pinchedVertices(const ShadowVolume& v)
{
    std::map<std::uint32_t, std::map<std::uint32_t, std::uint32_t>> link; // v: next -> prev
    for (std::size_t t = 0; t < v.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k)
            link[v.indices[t + k]][v.indices[t + (k + 1) % 3]] = v.indices[t + (k + 2) % 3];
    std::set<std::uint32_t> pinched;
    for (auto& l : link)
    {
        std::size_t steps = 0;
        std::uint32_t start = l.second.begin()->first, at = start;
        do {
            auto next = l.second.find(at);
            if (next == l.second.end()) break;
            at = next->second;
            ++steps;
        } while (at != start && steps <= l.second.size());
        if (steps != l.second.size()) pinched.insert(l.first);
    }
    return pinched;
}

/** Silhouette vertices where two loops touch (four or more silhouette edges). */
inline std::set<std::uint32_t> silhouetteCrossings(const SilhouetteEdges& s)
{
    std::map<std::uint32_t, int> degree;
    for (std::uint32_t v : s.vertexIndices) ++degree[v];
    std::set<std::uint32_t> crossings;
    for (auto& d : degree)
        if (d.second >= 4) crossings.insert(d.first);
    return crossings;
}

/** Each undirected edge is used as often in one direction as in the other: the triangles
 *  form a closed 2-cycle (what a non-manifold but watertight volume must be). */
inline bool volumeIsEdgeBalanced(const ShadowVolume& v)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> balance;
    for (std::size_t t = 0; t < v.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k)
        {
            std::uint32_t a = v.indices[t + k], b = v.indices[t + (k + 1) % 3];
            if (a < b) ++balance[{ a, b }];
            else --balance[{ b, a }];
        }
    return std::all_of(balance.begin(), balance.end(), [](const auto& b) { return b.second == 0; });
}

/** Winding number of the volume around @p p: the sum of the signed solid angles of its
 *  triangles over 4 pi (van Oosterom and Strackee 1983). A vertex with w = 0 is a point at
 *  infinity, seen from p in the direction xyz. This is the stencil count z-fail produces. */
inline double windingNumber(const ShadowVolume& v, const osg::Vec3d& p)
{
    auto dir = [&](std::uint32_t i) {
        const osg::Vec4f& q = v.vertices[i];
        osg::Vec3d d = q.w() == 0.0f ? osg::Vec3d(q.x(), q.y(), q.z())
                                     : osg::Vec3d(q.x(), q.y(), q.z()) / q.w() - p;
        d.normalize();
        return d;
    };
    double sum = 0.0;
    for (std::size_t t = 0; t < v.indices.size(); t += 3)
    {
        osg::Vec3d a = dir(v.indices[t]), b = dir(v.indices[t + 1]), c = dir(v.indices[t + 2]);
        double det = a * (b ^ c);
        double den = 1.0 + a * b + b * c + c * a;
        sum += 2.0 * std::atan2(det, den);
    }
    return sum / (4.0 * osg::PI);
}

/** Does the segment (or ray when @p infinite) from @p o along @p d cross triangle abc in
 *  its interior (parameter strictly inside (0, 1) for a segment)? Moller-Trumbore. */
inline bool crosses(const osg::Vec3d& o, const osg::Vec3d& d, bool infinite,
                    const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c)
{
    osg::Vec3d e1 = b - a, e2 = c - a, s = d ^ e2;
    double det = e1 * s;
    if (std::fabs(det) < 1e-300) return false;
    osg::Vec3d t = o - a;
    double u = (t * s) / det;
    osg::Vec3d q = t ^ e1;
    double w = (d * q) / det, h = (e2 * q) / det;
    return u > 0 && w > 0 && u + w < 1 && h > 0 && (infinite || h < 1);
}

/** Reference stencil count by ray casting: the number of faces between @p p and the light
 *  that cast (all faces if @p allFaces, else the lit ones). */
inline int castingFacesBetween(const MeshAdjacency& m, const std::vector<std::uint8_t>& lit,
                               const osg::Vec4d& light, const osg::Vec3d& p, bool allFaces)
{
    const bool directional = light.w() == 0.0;
    osg::Vec3d d = directional ? osg::Vec3d(light.x(), light.y(), light.z())
                               : osg::Vec3d(light.x(), light.y(), light.z()) - p;
    int count = 0;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
    {
        if (!allFaces && !lit[f]) continue;
        const auto& t = m.faces[f];
        count += crosses(p, d, directional, m.positions[t.v[0]], m.positions[t.v[1]],
                         m.positions[t.v[2]]);
    }
    return count;
}

}
