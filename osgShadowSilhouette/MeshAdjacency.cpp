/* -*-c++-*- osgShadowSilhouette - hard shadows for OpenSceneGraph
 *
 * Distributed under the terms of the OpenSceneGraph Public License (OSGPL).
 */

#include <osgShadowSilhouette/MeshAdjacency>
#include <osgShadowSilhouette/HalfEdgeMesh>

#include "VertexBounds.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <osg/Notify>
#include <osg/TriangleIndexFunctor>

#include <mutex>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>
#include <unordered_map>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

namespace osgShadowSilhouette {

namespace {

const std::uint32_t kInvalid = std::numeric_limits<std::uint32_t>::max();
/** Interleaved sums per part of a closed mesh's signed volume (computePlanes()). */
constexpr std::size_t kLanes = 4;

struct IndexCollector
{
    std::vector<std::uint32_t>* indices = nullptr;
    void operator()(unsigned int a, unsigned int b, unsigned int c)
    {
        indices->push_back(a);
        indices->push_back(b);
        indices->push_back(c);
    }
};

/** osg::TriangleIndexFunctor reads a whole triangle past the end of a GL_TRIANGLES index
 *  list whose length is not a multiple of 3: this one hands it whole triangles only. */
struct WholeTrianglesFunctor : public osg::TriangleIndexFunctor<IndexCollector>
{
    using Base = osg::TriangleIndexFunctor<IndexCollector>;
    static GLsizei whole(GLenum mode, GLsizei count) { return mode == GL_TRIANGLES ? count - count % 3 : count; }
    void drawElements(GLenum mode, GLsizei count, const GLubyte* indices) override
    {
        Base::drawElements(mode, whole(mode, count), indices);
    }
    void drawElements(GLenum mode, GLsizei count, const GLushort* indices) override
    {
        Base::drawElements(mode, whole(mode, count), indices);
    }
    void drawElements(GLenum mode, GLsizei count, const GLuint* indices) override
    {
        Base::drawElements(mode, whole(mode, count), indices);
    }
};

/** A vertex as a position in double: Vec2 gets z = 0, Vec4 is divided by w. */
template <class Vec>
osg::Vec3d toVec3d(const Vec& v)
{
    constexpr int n = Vec::num_components;
    osg::Vec3d p;
    for (int i = 0; i < 3 && i < n; ++i) p[i] = v[i];
    if constexpr (n == 4) p /= v[3];
    return p;
}

/** Calls @p visit with @p array cast to its type, for the vertex array types read as
 *  positions; false for the others. */
template <class Visit>
bool visitPositions(const osg::Array* array, Visit&& visit)
{
    if (!array) return false;
    switch (array->getType())
    {
    case osg::Array::Vec2ArrayType: visit(static_cast<const osg::Vec2Array&>(*array)); return true;
    case osg::Array::Vec3ArrayType: visit(static_cast<const osg::Vec3Array&>(*array)); return true;
    case osg::Array::Vec4ArrayType: visit(static_cast<const osg::Vec4Array&>(*array)); return true;
    case osg::Array::Vec2dArrayType: visit(static_cast<const osg::Vec2dArray&>(*array)); return true;
    case osg::Array::Vec3dArrayType: visit(static_cast<const osg::Vec3dArray&>(*array)); return true;
    case osg::Array::Vec4dArrayType: visit(static_cast<const osg::Vec4dArray&>(*array)); return true;
    default: return false;
    }
}

bool copyVertexArray(const osg::Array* array, std::vector<osg::Vec3d>& out)
{
    return visitPositions(array, [&out](const auto& typed) {
        out.reserve(typed.size());
        for (const auto& v : typed) out.push_back(toVec3d(v));
    });
}

bool isFinite(const osg::Vec3d& p)
{
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

/** Merges vertices closer than a distance on a hashed grid whose cells are twice that
 *  distance: a neighbour within the distance lies in one of 8 cells. */
class VertexWelder
{
public:
    VertexWelder(const osg::BoundingBoxd& box, double distance, std::size_t expected)
        : _origin(box._min), _distance(distance)
    {
        double extent = std::max(box.xMax() - box.xMin(),
                                 std::max(box.yMax() - box.yMin(), box.zMax() - box.zMin()));
        // at most 2^20 cells per axis so that the three cell indices pack into 64 bits
        _cell = std::max(2.0 * distance, extent / double(1 << 20));
        if (_cell <= 0.0) _cell = 1.0;
        _heads.reserve(expected);
        _next.reserve(expected);
    }

    std::uint32_t weld(const osg::Vec3d& p, std::vector<osg::Vec3d>& welded)
    {
        osg::Vec3d g = (p - _origin) / _cell;
        long long base[3] = { (long long)std::floor(g.x()), (long long)std::floor(g.y()),
                              (long long)std::floor(g.z()) };
        int step[3];
        for (int i = 0; i < 3; ++i) step[i] = (g[i] - double(base[i]) < 0.5) ? -1 : 1;
        for (int n = 0; n < 8; ++n)
        {
            std::uint32_t found = search(key(base[0] + ((n & 1) ? step[0] : 0),
                                             base[1] + ((n & 2) ? step[1] : 0),
                                             base[2] + ((n & 4) ? step[2] : 0)), p, welded);
            if (found != kInvalid) return found;
        }
        std::uint32_t id = static_cast<std::uint32_t>(welded.size());
        welded.push_back(p);
        auto inserted = _heads.emplace(key(base[0], base[1], base[2]), id);
        _next.push_back(inserted.second ? kInvalid : inserted.first->second);
        inserted.first->second = id;
        return id;
    }

private:
    static std::uint64_t key(long long x, long long y, long long z)
    {
        const std::uint64_t mask = (1u << 21) - 1;
        return (std::uint64_t(x + 1) & mask) | ((std::uint64_t(y + 1) & mask) << 21) |
               ((std::uint64_t(z + 1) & mask) << 42);
    }

    std::uint32_t search(std::uint64_t k, const osg::Vec3d& p,
                         const std::vector<osg::Vec3d>& welded) const
    {
        auto it = _heads.find(k);
        if (it == _heads.end()) return kInvalid;
        const double limit = _distance * _distance;
        for (std::uint32_t id = it->second; id != kInvalid; id = _next[id])
            if ((welded[id] - p).length2() <= limit) return id;
        return kInvalid;
    }

    osg::Vec3d _origin;
    double _distance;
    double _cell;
    std::unordered_map<std::uint64_t, std::uint32_t> _heads;
    std::vector<std::uint32_t> _next;
};

/** Welded vertices and the triangles that survive welding (three ids each). */
struct WeldedSoup
{
    std::vector<osg::Vec3d> positions;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> weldedOf; ///< per input vertex, as MeshWelding::weldedOf
};

std::vector<char> markReferenced(const TriangleSoup& soup)
{
    std::vector<char> referenced(soup.positions.size(), 0);
    for (std::uint32_t i : soup.indices)
        if (i < referenced.size()) referenced[i] = 1;
    return referenced;
}

void weldSoup(const TriangleSoup& soup, double tolerance, WeldedSoup& out, MeshBuildReport& report)
{
    std::vector<char> referenced = markReferenced(soup);
    osg::BoundingBoxd box;
    for (std::size_t i = 0; i < soup.positions.size(); ++i)
    {
        if (!referenced[i]) continue;
        if (isFinite(soup.positions[i])) box.expandBy(soup.positions[i]);
        else ++report.nonFiniteVertices;
    }
    report.weldDistance = box.valid() ? tolerance * (box._max - box._min).length() : 0.0;
    VertexWelder welder(box, report.weldDistance, soup.positions.size());
    std::vector<std::uint32_t>& remap = out.weldedOf;
    remap.assign(soup.positions.size(), MeshWelding::kUnreferenced);
    for (std::size_t i = 0; i < soup.positions.size(); ++i)
        if (referenced[i])
            remap[i] =
                isFinite(soup.positions[i]) ? welder.weld(soup.positions[i], out.positions) : MeshWelding::kNonFinite;

    out.indices.reserve(soup.indices.size());
    for (std::size_t t = 0; t + 2 < soup.indices.size(); t += 3)
    {
        std::uint32_t v[3];
        bool finite = true, inRange = true;
        for (int k = 0; k < 3; ++k)
        {
            std::uint32_t i = soup.indices[t + k];
            inRange = inRange && i < remap.size();
            v[k] = inRange ? remap[i] : kInvalid;
            finite = finite && v[k] < MeshWelding::kNonFinite;
        }
        if (!inRange) { ++report.outOfRangeTriangles; continue; }
        if (!finite) { ++report.nonFiniteTriangles; continue; }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) { ++report.degenerateTriangles; continue; }
        out.indices.insert(out.indices.end(), v, v + 3);
    }
}

/** Adds the welded triangles to OpenMesh; faces it refuses get their own vertex copies.
 *  Returns where the refused triangles start in soup.indices. */
std::vector<std::size_t> fillHalfEdgeMesh(const WeldedSoup& soup, HalfEdgeMesh& mesh, MeshBuildReport& report)
{
    mesh.clear();
    mesh.reserve(soup.positions.size(), soup.indices.size() / 2, soup.indices.size() / 3);
    std::vector<HalfEdgeMesh::VertexHandle> handles;
    handles.reserve(soup.positions.size());
    for (const osg::Vec3d& p : soup.positions)
        handles.push_back(mesh.add_vertex(HalfEdgeMesh::Point(p.x(), p.y(), p.z())));

    std::vector<std::size_t> refused;
    {
        // OpenMesh reports each refused face on omerr(); we count them instead. The
        // stream switch is process-wide, hence the lock.
        static std::mutex quietMutex;
        std::lock_guard<std::mutex> lock(quietMutex);
        const bool wasEnabled = ::omerr().is_enabled();
        ::omerr().disable();
        for (std::size_t t = 0; t < soup.indices.size(); t += 3)
        {
            HalfEdgeMesh::FaceHandle f = mesh.add_face(handles[soup.indices[t]],
                                                       handles[soup.indices[t + 1]],
                                                       handles[soup.indices[t + 2]]);
            if (!f.is_valid()) refused.push_back(t);
        }
        if (wasEnabled) ::omerr().enable();
    }
    for (std::size_t t : refused)
    {
        HalfEdgeMesh::VertexHandle copies[3];
        for (int k = 0; k < 3; ++k)
        {
            const HalfEdgeMesh::Point p = mesh.point(handles[soup.indices[t + k]]); // copy: add_vertex may reallocate
            copies[k] = mesh.add_vertex(p);
        }
        mesh.add_face(copies[0], copies[1], copies[2]);
    }
    report.nonManifoldFaces = refused.size();
    mesh.update_face_normals();
    return refused;
}

osg::Vec4d facePlane(const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c)
{
    osg::Vec3d n = (b - a) ^ (c - a);
    return osg::Vec4d(n, -(n * a));
}

void flattenFaces(const HalfEdgeMesh& mesh, MeshAdjacency& adjacency)
{
    adjacency.positions.resize(mesh.n_vertices());
    for (auto v : mesh.vertices())
    {
        const HalfEdgeMesh::Point& p = mesh.point(v);
        adjacency.positions[v.idx()].set(float(p[0]), float(p[1]), float(p[2]));
    }
    adjacency.faces.resize(mesh.n_faces());
    for (auto f : mesh.faces())
    {
        MeshTriangle& tri = adjacency.faces[f.idx()];
        int k = 0;
        for (auto v : mesh.fv_range(f)) tri.v[k++] = static_cast<std::uint32_t>(v.idx());
    }
}

void flattenEdges(const HalfEdgeMesh& mesh, MeshAdjacency& adjacency)
{
    adjacency.edgeFaces.clear();
    adjacency.edgeVertices.clear();
    adjacency.boundaryEdges.clear();
    adjacency.edgeFaces.reserve(mesh.n_edges());
    adjacency.edgeVertices.reserve(mesh.n_edges());
    for (auto e : mesh.edges())
    {
        auto h0 = mesh.halfedge_handle(e, 0);
        auto h1 = mesh.halfedge_handle(e, 1);
        if (mesh.is_boundary(h0)) std::swap(h0, h1);
        if (mesh.is_boundary(h0)) continue; // isolated edge: no face at all
        std::uint32_t f0 = mesh.face_handle(h0).idx();
        std::uint32_t v0 = mesh.from_vertex_handle(h0).idx();
        std::uint32_t v1 = mesh.to_vertex_handle(h0).idx();
        if (mesh.is_boundary(h1))
            adjacency.boundaryEdges.push_back(BoundaryEdge{ f0, v0, v1 });
        else
        {
            adjacency.edgeFaces.push_back(EdgeFaces{ f0, std::uint32_t(mesh.face_handle(h1).idx()) });
            adjacency.edgeVertices.push_back(EdgeVertices{ v0, v1 });
        }
    }
    adjacency.edgeFaces.shrink_to_fit();
    adjacency.edgeVertices.shrink_to_fit();
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t f)
{
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
}

/** Per face, its connected part (faces joined by interior edges), the parts numbered 0,
 *  1, ... in the order of their first faces. */
std::vector<std::uint32_t> connectedParts(const MeshAdjacency& m)
{
    std::vector<std::uint32_t> parent(m.faces.size());
    for (std::uint32_t f = 0; f < parent.size(); ++f) parent[f] = f;
    for (const EdgeFaces& e : m.edgeFaces) parent[findRoot(parent, e.face0)] = findRoot(parent, e.face1);
    std::vector<std::uint32_t> number(m.faces.size(), kInvalid), part(m.faces.size());
    std::uint32_t parts = 0;
    for (std::uint32_t f = 0; f < m.faces.size(); ++f)
    {
        std::uint32_t& n = number[findRoot(parent, f)];
        if (n == kInvalid) n = parts++;
        part[f] = n;
    }
    return part;
}

/** The runs of consecutive faces of one part in @p partOf (connectedParts()). */
std::vector<PartRun> partRuns(const std::vector<std::uint32_t>& partOf)
{
    std::vector<PartRun> runs;
    for (std::uint32_t f = 0; f < partOf.size(); ++f)
    {
        if (runs.empty() || runs.back().part != partOf[f]) runs.push_back(PartRun{f, f, partOf[f]});
        runs.back().end = f + 1;
    }
    return runs;
}

/** The planes of faces [first, end) (facePlane(), from the float positions the renderer
 *  draws, in double); with @p lanes, each face's n . (a - @p origin), n its plane's normal and
 *  a its first vertex, added to lanes[f % kLanes]. */
template <bool kVolumes>
void computeRunPlanes(MeshAdjacency& m, std::uint32_t first, std::uint32_t end, const osg::Vec3d& origin, double* lanes)
{
    const osg::Vec3f* p = m.positions.data();
    const MeshTriangle* faces = m.faces.data();
    osg::Vec4d* planes = m.planes.data();
    for (std::uint32_t f = first; f < end; ++f)
    {
        const MeshTriangle& tri = faces[f];
        const osg::Vec3d a(p[tri.v[0]]);
        const osg::Vec4d n = facePlane(a, osg::Vec3d(p[tri.v[1]]), osg::Vec3d(p[tri.v[2]]));
        planes[f] = n;
        if constexpr (kVolumes)
        {
            const osg::Vec3d d = a - origin;
            lanes[f % kLanes] += n.x() * d.x() + n.y() * d.y() + n.z() * d.z();
        }
    }
}

#if defined(__SSE2__)
/** A corner of two faces f, f + 1 in double, each coordinate as the pair (face f, face f + 1). */
struct CornerPair
{
    __m128d x, y, z;
};

/** (x, y) of @p p in double: its first two floats in one load, converted together (exactly). */
inline __m128d xyOf(const osg::Vec3f& p)
{
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p.ptr()))));
}

inline CornerPair cornerPair(const osg::Vec3f& p, const osg::Vec3f& q)
{
    const __m128d pxy = xyOf(p), qxy = xyOf(q);
    return CornerPair{_mm_unpacklo_pd(pxy, qxy), _mm_unpackhi_pd(pxy, qxy), _mm_set_pd(q.z(), p.z())};
}

/** computeRunPlanes() for faces f and f + 1 at once, the same operations in the same order in
 *  SSE2's two lanes; returns the pair of their n . (a - origin). */
inline __m128d planePair(const MeshAdjacency& m, std::uint32_t f, const CornerPair& origin, osg::Vec4d* planes)
{
    const osg::Vec3f* p = m.positions.data();
    const MeshTriangle& s = m.faces[f];
    const MeshTriangle& t = m.faces[f + 1];
    const CornerPair a = cornerPair(p[s.v[0]], p[t.v[0]]), b = cornerPair(p[s.v[1]], p[t.v[1]]),
                     c = cornerPair(p[s.v[2]], p[t.v[2]]);
    const __m128d ux = _mm_sub_pd(b.x, a.x), uy = _mm_sub_pd(b.y, a.y), uz = _mm_sub_pd(b.z, a.z);
    const __m128d vx = _mm_sub_pd(c.x, a.x), vy = _mm_sub_pd(c.y, a.y), vz = _mm_sub_pd(c.z, a.z);
    const __m128d nx = _mm_sub_pd(_mm_mul_pd(uy, vz), _mm_mul_pd(uz, vy));
    const __m128d ny = _mm_sub_pd(_mm_mul_pd(uz, vx), _mm_mul_pd(ux, vz));
    const __m128d nz = _mm_sub_pd(_mm_mul_pd(ux, vy), _mm_mul_pd(uy, vx));
    const __m128d dot = _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, a.x), _mm_mul_pd(ny, a.y)), _mm_mul_pd(nz, a.z));
    const __m128d w = _mm_xor_pd(dot, _mm_set1_pd(-0.0)); // -(n . a), as the scalar negation
    double* out = planes[f].ptr();
    _mm_storeu_pd(out, _mm_unpacklo_pd(nx, ny));
    _mm_storeu_pd(out + 2, _mm_unpacklo_pd(nz, w));
    _mm_storeu_pd(out + 4, _mm_unpackhi_pd(nx, ny));
    _mm_storeu_pd(out + 6, _mm_unpackhi_pd(nz, w));
    const __m128d dx = _mm_sub_pd(a.x, origin.x), dy = _mm_sub_pd(a.y, origin.y), dz = _mm_sub_pd(a.z, origin.z);
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, dx), _mm_mul_pd(ny, dy)), _mm_mul_pd(nz, dz));
}

/** computeRunPlanes() four faces a step: faces up to a multiple of four and the last ones
 *  one by one, the others in pairs whose sums go to lanes (0, 1) and (2, 3). */
template <bool kVolumes>
void computeRunPlanesSse2(MeshAdjacency& m, std::uint32_t first, std::uint32_t end, const osg::Vec3d& origin,
                          double* lanes)
{
    const std::uint32_t head = std::min(end, (first + 3) / 4 * 4);
    computeRunPlanes<kVolumes>(m, first, head, origin, lanes);
    const CornerPair o{_mm_set1_pd(origin.x()), _mm_set1_pd(origin.y()), _mm_set1_pd(origin.z())};
    __m128d low = kVolumes ? _mm_loadu_pd(lanes) : _mm_setzero_pd();
    __m128d high = kVolumes ? _mm_loadu_pd(lanes + 2) : _mm_setzero_pd();
    std::uint32_t f = head;
    for (; f + 4 <= end; f += 4)
    {
        const __m128d first2 = planePair(m, f, o, m.planes.data());
        const __m128d second2 = planePair(m, f + 2, o, m.planes.data());
        if constexpr (kVolumes) low = _mm_add_pd(low, first2), high = _mm_add_pd(high, second2);
    }
    if constexpr (kVolumes) _mm_storeu_pd(lanes, low), _mm_storeu_pd(lanes + 2, high);
    computeRunPlanes<kVolumes>(m, f, end, origin, lanes);
}
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define OSS_AVX_PLANES 1
/** A corner of four faces f .. f + 3 in double, each coordinate as the four faces' values. */
struct CornerQuad
{
    __m256d x, y, z;
};

/** Corner @p k of faces f .. f + 3: the floats gathered four by four, then converted
 *  (exactly) to double. */
__attribute__((target("avx"))) inline CornerQuad cornerQuad(const MeshAdjacency& m, std::uint32_t f, int k)
{
    const MeshTriangle* t = m.faces.data() + f;
    const float* p0 = m.positions[t[0].v[k]].ptr();
    const float* p1 = m.positions[t[1].v[k]].ptr();
    const float* p2 = m.positions[t[2].v[k]].ptr();
    const float* p3 = m.positions[t[3].v[k]].ptr();
    const auto xy = [](const float* a, const float* b) { // (xa, ya, xb, yb)
        const __m128 low = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(a)));
        return _mm_loadh_pi(low, reinterpret_cast<const __m64*>(b));
    };
    const __m128 xy01 = xy(p0, p1), xy23 = xy(p2, p3);
    const __m128 z01 = _mm_unpacklo_ps(_mm_load_ss(p0 + 2), _mm_load_ss(p1 + 2));
    const __m128 z23 = _mm_unpacklo_ps(_mm_load_ss(p2 + 2), _mm_load_ss(p3 + 2));
    return CornerQuad{_mm256_cvtps_pd(_mm_shuffle_ps(xy01, xy23, _MM_SHUFFLE(2, 0, 2, 0))),
                      _mm256_cvtps_pd(_mm_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 1, 3, 1))),
                      _mm256_cvtps_pd(_mm_movelh_ps(z01, z23))};
}

/** computeRunPlanes() for faces f .. f + 3 at once, the same operations in the same order in
 *  AVX's four lanes (no fused multiply-add); returns their four n . (a - origin). */
__attribute__((target("avx"))) inline __m256d planeQuad(MeshAdjacency& m, std::uint32_t f, const __m256d origin[3])
{
    const CornerQuad a = cornerQuad(m, f, 0), b = cornerQuad(m, f, 1), c = cornerQuad(m, f, 2);
    const __m256d ux = _mm256_sub_pd(b.x, a.x), uy = _mm256_sub_pd(b.y, a.y), uz = _mm256_sub_pd(b.z, a.z);
    const __m256d vx = _mm256_sub_pd(c.x, a.x), vy = _mm256_sub_pd(c.y, a.y), vz = _mm256_sub_pd(c.z, a.z);
    const __m256d nx = _mm256_sub_pd(_mm256_mul_pd(uy, vz), _mm256_mul_pd(uz, vy));
    const __m256d ny = _mm256_sub_pd(_mm256_mul_pd(uz, vx), _mm256_mul_pd(ux, vz));
    const __m256d nz = _mm256_sub_pd(_mm256_mul_pd(ux, vy), _mm256_mul_pd(uy, vx));
    const __m256d dot =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, a.x), _mm256_mul_pd(ny, a.y)), _mm256_mul_pd(nz, a.z));
    const __m256d w = _mm256_xor_pd(dot, _mm256_set1_pd(-0.0)); // -(n . a), as the scalar negation
    // (nx, ny, nz, w) per face: a 4 x 4 transpose
    const __m256d t0 = _mm256_unpacklo_pd(nx, ny), t1 = _mm256_unpackhi_pd(nx, ny);
    const __m256d t2 = _mm256_unpacklo_pd(nz, w), t3 = _mm256_unpackhi_pd(nz, w);
    double* out = m.planes[f].ptr();
    _mm256_storeu_pd(out, _mm256_permute2f128_pd(t0, t2, 0x20));
    _mm256_storeu_pd(out + 4, _mm256_permute2f128_pd(t1, t3, 0x20));
    _mm256_storeu_pd(out + 8, _mm256_permute2f128_pd(t0, t2, 0x31));
    _mm256_storeu_pd(out + 12, _mm256_permute2f128_pd(t1, t3, 0x31));
    const __m256d dx = _mm256_sub_pd(a.x, origin[0]), dy = _mm256_sub_pd(a.y, origin[1]),
                  dz = _mm256_sub_pd(a.z, origin[2]);
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, dx), _mm256_mul_pd(ny, dy)), _mm256_mul_pd(nz, dz));
}

/** computeRunPlanes() four faces a step in AVX: faces up to a multiple of four and the last
 *  ones one by one, the others by four whose sums go to lanes 0 .. 3, as the SSE2 pairs'. */
template <bool kVolumes>
__attribute__((target("avx"))) void computeRunPlanesAvx(MeshAdjacency& m, std::uint32_t first, std::uint32_t end,
                                                        const osg::Vec3d& origin, double* lanes)
{
    const std::uint32_t head = std::min(end, (first + 3) / 4 * 4);
    computeRunPlanes<kVolumes>(m, first, head, origin, lanes);
    const __m256d o[3] = {_mm256_set1_pd(origin.x()), _mm256_set1_pd(origin.y()), _mm256_set1_pd(origin.z())};
    __m256d sums = kVolumes ? _mm256_loadu_pd(lanes) : _mm256_setzero_pd();
    std::uint32_t f = head;
    for (; f + 4 <= end; f += 4)
    {
        const __m256d quad = planeQuad(m, f, o);
        if constexpr (kVolumes) sums = _mm256_add_pd(sums, quad);
    }
    if constexpr (kVolumes) _mm256_storeu_pd(lanes, sums);
    _mm256_zeroupper(); // the SSE code after it would pay for the upper halves (not done for us)
    computeRunPlanes<kVolumes>(m, f, end, origin, lanes);
}

/** Whether the processor and the system run AVX (asked once). */
bool avxPlanes()
{
    static const bool avx = __builtin_cpu_supports("avx");
    return avx;
}
#endif

/** computeRunPlanes(), in AVX where the processor has it, else in SSE2 where the compiler
 *  targets it: the same planes and sums to the last bit. */
template <bool kVolumes>
void computeRunPlanesFast(MeshAdjacency& m, std::uint32_t first, std::uint32_t end, const osg::Vec3d& origin,
                          double* lanes)
{
#if defined(OSS_AVX_PLANES)
    if (avxPlanes()) return computeRunPlanesAvx<kVolumes>(m, first, end, origin, lanes);
#endif
#if defined(__SSE2__)
    computeRunPlanesSse2<kVolumes>(m, first, end, origin, lanes);
#else
    computeRunPlanes<kVolumes>(m, first, end, origin, lanes);
#endif
}

/** Computes the planes of the faces and, given the part runs of a closed mesh (partRuns()),
 *  returns the number of parts whose signed enclosed volume is negative (0 without runs).
 *  Six times a part's volume is the sum over its faces of n . (a - o), n the face's plane
 *  normal, a its first vertex and o the first vertex of the part's first face, in double;
 *  the faces go to kLanes interleaved sums per part (by face index), so that the additions
 *  do not wait for each other. One pass over the faces for both. */
std::size_t computePlanes(MeshAdjacency& m, const std::vector<PartRun>& runs)
{
    m.planes.resize(m.faces.size());
    if (runs.empty())
    {
        computeRunPlanesFast<false>(m, 0, std::uint32_t(m.faces.size()), osg::Vec3d(), nullptr);
        return 0;
    }
    std::vector<double> volume; // kLanes sums per part
    std::vector<osg::Vec3d> origin;
    for (const PartRun& run : runs)
    {
        if (run.part == origin.size()) // the part's first face
        {
            origin.emplace_back(m.positions[m.faces[run.first].v[0]]);
            volume.resize(volume.size() + kLanes, 0.0);
        }
        computeRunPlanesFast<true>(m, run.first, run.end, origin[run.part], &volume[run.part * kLanes]);
    }
    std::size_t inward = 0;
    for (std::size_t r = 0; r < origin.size(); ++r)
    {
        const double* lanes = &volume[r * kLanes];
        if ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) < 0.0) ++inward;
    }
    return inward;
}

/** Fills @p welding from the welded soup and the triangles OpenMesh refused (whose vertex
 *  copies follow the welded vertices, three per refused triangle). */
void describeWelding(const WeldedSoup& welded, const std::vector<std::size_t>& refused, std::vector<PartRun> runs,
                     double tolerance, MeshWelding& welding)
{
    welding.weldedOf = welded.weldedOf;
    welding.sourceOf.assign(welded.positions.size(), kInvalid);
    for (std::size_t i = 0; i < welded.weldedOf.size(); ++i)
    {
        const std::uint32_t w = welded.weldedOf[i];
        if (w < MeshWelding::kNonFinite && welding.sourceOf[w] == kInvalid)
            welding.sourceOf[w] = static_cast<std::uint32_t>(i);
    }
    welding.weldedAway.clear();
    welding.everyVertexUsed = true;
    for (std::size_t i = 0; i < welded.weldedOf.size(); ++i)
    {
        const std::uint32_t w = welded.weldedOf[i];
        welding.everyVertexUsed = welding.everyVertexUsed && w < MeshWelding::kNonFinite;
        if (w < MeshWelding::kNonFinite && welding.sourceOf[w] != i)
            welding.weldedAway.push_back(static_cast<std::uint32_t>(i));
    }
    for (std::size_t t : refused)
        for (int k = 0; k < 3; ++k) welding.sourceOf.push_back(welding.sourceOf[welded.indices[t + k]]);
    welding.partRuns = std::move(runs);
    welding.weldTolerance = tolerance;
}

/** The bounding box of the referenced vertices of @p array; false when one of them turned
 *  finite or non-finite since @p welding was built. */
template <class ArrayT>
bool finiteBounds(const ArrayT& array, const MeshWelding& welding, osg::BoundingBoxd& box)
{
    osg::Vec3d low = box._min, high = box._max; // grown as expandBy() does, without its branches
    for (std::size_t i = 0; i < welding.weldedOf.size(); ++i)
    {
        const std::uint32_t w = welding.weldedOf[i];
        if (w == MeshWelding::kUnreferenced) continue;
        const osg::Vec3d p = toVec3d(array[i]);
        const bool finite = isFinite(p);
        if (finite != (w != MeshWelding::kNonFinite)) return false;
        if (finite)
            for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
    }
    box._min = low;
    box._max = high;
    return true;
}

/** finiteBounds(), for a float array whose every vertex is used (MeshWelding::everyVertexUsed)
 *  the box of the whole array in one pass (detail::finiteBox()): in float, the same extremes
 *  since floats convert to double exactly and in order (a zero extreme may change its sign,
 *  which the box's diagonal, all it is used for, does not see). */
template <class ArrayT>
bool referencedBounds(const ArrayT& array, const MeshWelding& welding, osg::BoundingBoxd& box)
{
    if constexpr (std::is_same_v<ArrayT, osg::Vec3Array>)
    {
        if (welding.everyVertexUsed)
        {
            osg::Vec3f low, high;
            if (!detail::finiteBox(array.empty() ? nullptr : &array.front(), array.size(), low, high)) return false;
            box._min = osg::Vec3d(low);
            box._max = osg::Vec3d(high);
            return true;
        }
    }
    return finiteBounds(array, welding, box);
}

/** Whether every welded vertex of @p array is still within @p distance of the first vertex
 *  of its group (the one whose position the mesh vertex has, as the welder compares): the
 *  others (MeshWelding::weldedAway) are the first of their group. */
template <class ArrayT>
bool weldsHold(const ArrayT& array, const MeshWelding& welding, double distance)
{
    const double limit = distance * distance;
    for (const std::uint32_t i : welding.weldedAway)
    {
        const std::uint32_t first = welding.sourceOf[welding.weldedOf[i]];
        if ((toVec3d(array[i]) - toVec3d(array[first])).length2() > limit) return false;
    }
    return true;
}

/** Mesh vertex v at input vertex sourceOf[v]; float positions are copied as they are (the
 *  round trip through double that other types take changes no finite float). */
template <class ArrayT>
void gatherPositions(const ArrayT& array, const MeshWelding& welding, std::vector<osg::Vec3f>& out)
{
    out.resize(welding.sourceOf.size());
    const std::uint32_t* source = welding.sourceOf.data();
    for (std::size_t v = 0; v < out.size(); ++v)
    {
        if constexpr (std::is_same_v<ArrayT, osg::Vec3Array>)
            out[v] = array[source[v]];
        else
        {
            const osg::Vec3d p = toVec3d(array[source[v]]);
            out[v].set(float(p.x()), float(p.y()), float(p.z()));
        }
    }
}

/** The positions and welding distance of @p out from @p array, if the welding holds. */
template <class ArrayT>
bool refreshPositions(const ArrayT& array, const MeshWelding& welding, MeshAdjacency& out)
{
    if (array.size() != welding.weldedOf.size()) return false;
    osg::BoundingBoxd box;
    if (!referencedBounds(array, welding, box)) return false;
    const double distance = box.valid() ? welding.weldTolerance * (box._max - box._min).length() : 0.0;
    if (!weldsHold(array, welding, distance)) return false;
    out.report.weldDistance = distance;
    gatherPositions(array, welding, out.positions);
    return true;
}

/** Everything of @p from that does not depend on positions. */
void copyTopology(const MeshAdjacency& from, MeshAdjacency& to)
{
    to.faces = from.faces;
    to.edgeFaces = from.edgeFaces;
    to.edgeVertices = from.edgeVertices;
    to.boundaryEdges = from.boundaryEdges;
    to.nonManifoldFaces = from.nonManifoldFaces;
    to.report = from.report;
    to.inwardParts = 0;
}

void warnAboutInput(const std::string& name, const MeshBuildReport& report)
{
    if (report.nonFiniteVertices > 0)
        OSG_WARN << "osgShadowSilhouette: " << name << " has " << report.nonFiniteVertices
                 << " vertices with NaN or infinite coordinates; they are refused and the "
                 << report.nonFiniteTriangles << " triangles using them cast no shadow."
                 << std::endl;
    if (report.nonManifoldFaces > 0)
        OSG_INFO << "osgShadowSilhouette: " << name << " has " << report.nonManifoldFaces
                 << " non-manifold faces, kept as separate open faces." << std::endl;
}

}

std::size_t MeshAdjacency::memoryBytes() const
{
    return positions.capacity() * sizeof(osg::Vec3f) + faces.capacity() * sizeof(MeshTriangle) +
           planes.capacity() * sizeof(osg::Vec4d) + edgeFaces.capacity() * sizeof(EdgeFaces) +
           edgeVertices.capacity() * sizeof(EdgeVertices) +
           boundaryEdges.capacity() * sizeof(BoundaryEdge) +
           nonManifoldFaces.capacity() * sizeof(std::uint32_t);
}

std::string describeGeometry(const osg::Geometry& geometry)
{
    std::ostringstream out;
    if (!geometry.getName().empty()) out << "geometry \"" << geometry.getName() << "\"";
    else out << "unnamed osg::Geometry " << static_cast<const void*>(&geometry);
    return out.str();
}

bool collectTriangles(const osg::Geometry& geometry, TriangleSoup& soup)
{
    soup.positions.clear();
    soup.indices.clear();
    if (!copyVertexArray(geometry.getVertexArray(), soup.positions)) return false;
    WholeTrianglesFunctor functor;
    functor.indices = &soup.indices;
    for (unsigned int i = 0; i < geometry.getNumPrimitiveSets(); ++i)
        geometry.getPrimitiveSet(i)->accept(functor);
    return true;
}

void buildMeshAdjacency(const TriangleSoup& soup, const MeshBuildOptions& options, const std::string& name,
                        MeshAdjacency& adjacency, HalfEdgeMesh* halfEdgeMesh, MeshWelding* welding)
{
    adjacency = MeshAdjacency();
    MeshBuildReport& report = adjacency.report;
    report.inputTriangles = soup.indices.size() / 3;

    WeldedSoup welded;
    const double tolerance = std::max(0.0, options.weldTolerance);
    weldSoup(soup, tolerance, welded, report);

    HalfEdgeMesh local;
    HalfEdgeMesh& mesh = halfEdgeMesh ? *halfEdgeMesh : local;
    const std::vector<std::size_t> refused = fillHalfEdgeMesh(welded, mesh, report);
    flattenFaces(mesh, adjacency);
    flattenEdges(mesh, adjacency);
    std::vector<PartRun> runs;
    if (adjacency.isClosed()) runs = partRuns(connectedParts(adjacency));
    adjacency.inwardParts = computePlanes(adjacency, runs);
    std::size_t firstRefused = mesh.n_faces() - report.nonManifoldFaces;
    for (std::size_t f = firstRefused; f < mesh.n_faces(); ++f)
        adjacency.nonManifoldFaces.push_back(static_cast<std::uint32_t>(f));
    warnAboutInput(name, report);
    if (welding) describeWelding(welded, refused, std::move(runs), tolerance, *welding);
}

void buildMeshAdjacency(const osg::Geometry& geometry, const MeshBuildOptions& options, MeshAdjacency& adjacency,
                        HalfEdgeMesh* halfEdgeMesh, MeshWelding* welding)
{
    TriangleSoup soup;
    collectTriangles(geometry, soup);
    buildMeshAdjacency(soup, options, describeGeometry(geometry), adjacency, halfEdgeMesh, welding);
}

bool refreshMeshPositions(const osg::Geometry& geometry, const MeshWelding& welding, const MeshAdjacency& built,
                          MeshAdjacency& refreshed)
{
    if (&refreshed != &built) copyTopology(built, refreshed);
    bool held = false;
    const bool readable = visitPositions(
        geometry.getVertexArray(), [&](const auto& array) { held = refreshPositions(array, welding, refreshed); });
    if (!readable || !held) return false;
    refreshed.inwardParts = computePlanes(refreshed, welding.partRuns);
    return true;
}
}
