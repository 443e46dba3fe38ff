/* -*-c++-*- osgShadowSilhouette - hard shadows for OpenSceneGraph
 *
 * Distributed under the terms of the OpenSceneGraph Public License (OSGPL).
 */

#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/HalfEdgeMesh>

#include "VertexBounds.h"

#include <OpenThreads/ScopedLock>
#include <osg/Math>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace osgShadowSilhouette {

typedef OpenThreads::ScopedLock<OpenThreads::Mutex> Lock;

CachedMesh::CachedMesh() {}
CachedMesh::~CachedMesh() {}

MeshCache::MeshCache() {}
MeshCache::~MeshCache() {}

bool MeshCache::Signature::matches(const osg::Geometry& geometry) const
{
    const osg::Array* array = geometry.getVertexArray();
    if (array != vertices || (array && array->getModifiedCount() != verticesModified)) return false;
    return sameTopology(geometry);
}

bool MeshCache::Signature::sameTopology(const osg::Geometry& geometry) const
{
    const osg::Array* array = geometry.getVertexArray();
    if (!array || !vertices || array->getNumElements() != vertexCount) return false;
    if (geometry.getNumPrimitiveSets() != primitives.size()) return false;
    for (unsigned int i = 0; i < geometry.getNumPrimitiveSets(); ++i)
    {
        const osg::PrimitiveSet* p = geometry.getPrimitiveSet(i);
        if (p != primitives[i].first || (p && p->getModifiedCount() != primitives[i].second))
            return false;
    }
    return true;
}

MeshCache::Signature MeshCache::signatureOf(const osg::Geometry& geometry)
{
    Signature s;
    s.vertices = geometry.getVertexArray();
    s.verticesModified = s.vertices ? s.vertices->getModifiedCount() : 0;
    s.vertexCount = s.vertices ? s.vertices->getNumElements() : 0;
    s.primitives.reserve(geometry.getNumPrimitiveSets());
    for (unsigned int i = 0; i < geometry.getNumPrimitiveSets(); ++i)
    {
        const osg::PrimitiveSet* p = geometry.getPrimitiveSet(i);
        s.primitives.emplace_back(p, p ? p->getModifiedCount() : 0);
    }
    return s;
}

osg::ref_ptr<CachedMesh> MeshCache::build(const osg::Geometry& geometry) const
{
    MeshBuildOptions options;
    bool keep;
    {
        Lock lock(_mutex);
        options = _options;
        keep = _keepHalfEdgeMesh;
    }
    osg::ref_ptr<CachedMesh> mesh = new CachedMesh;
    std::shared_ptr<HalfEdgeMesh> halfEdgeMesh(keep ? new HalfEdgeMesh : nullptr);
    std::shared_ptr<MeshWelding> welding(new MeshWelding);
    buildMeshAdjacency(geometry, options, mesh->_adjacency, halfEdgeMesh.get(), welding.get());
    mesh->_halfEdgeMesh = std::move(halfEdgeMesh);
    mesh->_welding = std::move(welding);
    return mesh;
}

osg::ref_ptr<CachedMesh> MeshCache::refresh(const osg::Geometry& geometry, const CachedMesh& previous,
                                            osg::ref_ptr<CachedMesh> spare)
{
    if (!previous._welding) return nullptr;
    // a spare of the same build has the same topology already: only positions are written
    osg::ref_ptr<CachedMesh> mesh = spare.valid() ? spare.get() : new CachedMesh;
    const MeshAdjacency& built = spare ? spare->_adjacency : previous._adjacency;
    if (!refreshMeshPositions(geometry, *previous._welding, built, mesh->_adjacency)) return nullptr;
    mesh->_halfEdgeMesh = previous._halfEdgeMesh;
    mesh->_welding = previous._welding;
    return mesh;
}

osg::ref_ptr<const CachedMesh> MeshCache::get(const osg::Geometry& geometry)
{
    osg::ref_ptr<const CachedMesh> previous; // the entry to refresh, if only positions changed
    osg::ref_ptr<CachedMesh> spare;          // a retired entry only we hold, to write into
    {
        Lock lock(_mutex);
        auto it = _entries.find(&geometry);
        if (it != _entries.end() && it->second.geometry.get() == &geometry)
        {
            Entry& entry = it->second;
            if (entry.signature.matches(geometry)) return entry.mesh;
            if (entry.signature.sameTopology(geometry)) previous = entry.mesh;
            // Held by the entry alone, it can be reached by no one else: ours to write.
            if (previous && entry.spare && entry.spare->referenceCount() == 1 &&
                entry.spare->_welding == previous->_welding)
                spare.swap(entry.spare);
        }
    }
    // taken before building, so that a change made meanwhile triggers another rebuild
    Signature signature = signatureOf(geometry);
    osg::ref_ptr<CachedMesh> mesh;
    if (previous) mesh = refresh(geometry, *previous, spare);
    const bool refreshed = mesh.valid();
    if (!refreshed) mesh = build(geometry);
    Lock lock(_mutex);
    Entry& entry = _entries[&geometry];
    const bool sameBuild = entry.mesh.valid() && entry.mesh->_welding == mesh->_welding;
    entry.spare = sameBuild ? entry.mesh.get() : nullptr;
    entry.geometry = &geometry;
    entry.signature = signature;
    entry.mesh = mesh;
    ++(refreshed ? _refreshCount : _buildCount);
    return mesh;
}

void MeshCache::setBuildOptions(const MeshBuildOptions& options)
{
    Lock lock(_mutex);
    _options = options;
}

MeshBuildOptions MeshCache::getBuildOptions() const
{
    Lock lock(_mutex);
    return _options;
}

void MeshCache::setKeepHalfEdgeMesh(bool keep)
{
    Lock lock(_mutex);
    _keepHalfEdgeMesh = keep;
}

bool MeshCache::getKeepHalfEdgeMesh() const
{
    Lock lock(_mutex);
    return _keepHalfEdgeMesh;
}

namespace {

/** Whether none of @p count values is Inf or NaN (an exponent of all ones), read as their bits
 *  so that the loop has no branch and vectorises. */
template <typename Float, typename Bits, Bits kExponent>
bool allFinite(const Float* values, std::size_t count)
{
    static_assert(sizeof(Float) == sizeof(Bits), "bits of the same size");
    Bits notFinite = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        Bits bits;
        std::memcpy(&bits, values + i, sizeof bits);
        notFinite |= (bits & kExponent) == kExponent;
    }
    return notFinite == 0;
}

/** Whether every float or double component of @p array is finite (other types: true). */
bool allComponentsFinite(const osg::Array& array)
{
    const std::size_t bytes = array.getTotalDataSize();
    if (array.getDataType() == GL_FLOAT)
        return allFinite<float, std::uint32_t, 0x7f800000u>(static_cast<const float*>(array.getDataPointer()),
                                                            bytes / sizeof(float));
    if (array.getDataType() == GL_DOUBLE)
        return allFinite<double, std::uint64_t, 0x7ff0000000000000u>(static_cast<const double*>(array.getDataPointer()),
                                                                     bytes / sizeof(double));
    return true;
}

} // namespace

namespace {

/** Whether the points lie in one plane within 1e-6 of their extent; if so, three of them
 *  spanning it. If not because a point lies off the plane of three, the indices of the four
 *  go to @p witness. */
template <typename Vec>
bool spanningPlane(const std::vector<Vec>& points, std::array<osg::Vec3d, 3>& spanning,
                   std::optional<MeshCache::NotFlat>& witness)
{
    if (points.size() < 3) return false;
    const osg::Vec3d p0(points.front());
    osg::Vec3d p1 = p0;
    std::uint32_t i1 = 0, i2 = 0;
    double farthest = 0.0; // squared distances and areas: no square root per point
    for (std::uint32_t i = 0; i < points.size(); ++i)
    {
        const double distance = (osg::Vec3d(points[i]) - p0).length2();
        if (distance > farthest) farthest = distance, p1 = osg::Vec3d(points[i]), i1 = i;
    }
    const osg::Vec3d axis = p1 - p0;
    const double extent = axis.length();
    if (!(extent > 0.0)) return false;
    osg::Vec3d p2 = p0;
    double best = 0.0;
    for (std::uint32_t i = 0; i < points.size(); ++i)
    {
        const double area = ((osg::Vec3d(points[i]) - p0) ^ axis).length2();
        if (area > best) best = area, p2 = osg::Vec3d(points[i]), i2 = i;
    }
    osg::Vec3d normal = axis ^ (p2 - p0);
    // Collinear, or nearly: no plane of their own (a segment casts no shadow, but say no).
    if (!(normal.length() > 1e-12 * extent * extent)) return false;
    normal.normalize();
    const double tolerance = 1e-6 * extent;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        if (std::abs((osg::Vec3d(points[i]) - p0) * normal) > tolerance)
        {
            witness = MeshCache::NotFlat{0, i1, i2, i};
            return false;
        }
    spanning = {p0, p1, p2};
    return true;
}

/** Whether the four points @p witness names (a witness of spanningPlane()) prove that no plane
 *  holds all @p points within spanningPlane()'s tolerance, so that it would say no. If one did,
 *  every point would lie in a slab of width 2e-6 times the extent, which is at most the
 *  diagonal D of the points' box, and a tetrahedron in a slab of width w has a volume of at
 *  most w times the area of a plane figure of diameter D, pi D^2 / 4: six times its volume at
 *  most 3 pi 1e-6 D^3. The bound is taken twice over, far above any rounding. */
template <typename Vec>
bool provesNotFlat(const std::vector<Vec>& points, const MeshCache::NotFlat& witness, const Vec* box)
{
    for (std::uint32_t i : witness)
        if (i >= points.size()) return false;
    Vec low = points.front(), high = points.front();
    if (box)
        low = box[0], high = box[1];
    else
        for (const Vec& v : points)
            for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], v[k]), high[k] = std::max(high[k], v[k]);
    const double diagonal = (osg::Vec3d(high) - osg::Vec3d(low)).length();
    const osg::Vec3d a(points[witness[0]]), b(points[witness[1]]), c(points[witness[2]]), d(points[witness[3]]);
    const double sixVolume = std::abs(((b - a) ^ (c - a)) * (d - a));
    return sixVolume > 2.0 * 3.0 * osg::PI * 1e-6 * diagonal * diagonal * diagonal;
}

/** spanningPlane(), answered no at once while @p witness, the four points that showed the last
 *  set of points of the geometry not flat, still proves it (provesNotFlat(), given the
 *  points' @p box, low and high, if not null). */
template <typename Vec>
bool spanningPlaneOrWitness(const std::vector<Vec>& points, std::array<osg::Vec3d, 3>& spanning,
                            std::optional<MeshCache::NotFlat>& witness, const Vec* box = nullptr)
{
    if (witness && provesNotFlat(points, *witness, box)) return false;
    witness.reset();
    return spanningPlane(points, spanning, witness);
}

} // namespace

MeshCache::FiniteEntry MeshCache::vertexFacts(const osg::Geometry& geometry)
{
    const osg::Array* vertices = geometry.getVertexArray();
    std::optional<NotFlat> witness; // the geometry's last one, if any
    {
        Lock lock(_mutex);
        auto it = _finite.find(&geometry);
        if (it != _finite.end() && it->second.geometry.get() == &geometry)
        {
            if (it->second.vertices == vertices &&
                it->second.verticesModified == (vertices ? vertices->getModifiedCount() : 0u))
                return it->second;
            witness = it->second.notFlat;
        }
    }
    FiniteEntry entry; // outside the lock
    entry.geometry = &geometry;
    entry.vertices = vertices;
    entry.verticesModified = vertices ? vertices->getModifiedCount() : 0u;
    const auto* v3 = dynamic_cast<const osg::Vec3Array*>(vertices);
    osg::Vec3f box[2]; // a float array's finiteness and box in one pass
    entry.finite =
        !vertices || (v3 ? detail::finiteBox(v3->empty() ? nullptr : &v3->front(), v3->size(), box[0], box[1])
                         : allComponentsFinite(*vertices));
    if (entry.finite && vertices)
    {
        if (v3)
            entry.flat = spanningPlaneOrWitness(v3->asVector(), entry.spanning, witness, box);
        else if (const auto* v3d = dynamic_cast<const osg::Vec3dArray*>(vertices))
            entry.flat = spanningPlaneOrWitness(v3d->asVector(), entry.spanning, witness);
        entry.notFlat = witness;
    }
    Lock lock(_mutex);
    _finite[&geometry] = entry;
    return entry;
}

bool MeshCache::hasFiniteVertices(const osg::Geometry& geometry)
{
    const osg::Array* vertices = geometry.getVertexArray();
    if (!vertices || vertices->getNumElements() == 0) return true;
    return vertexFacts(geometry).finite;
}

bool MeshCache::getPlane(const osg::Geometry& geometry, std::array<osg::Vec3d, 3>& spanning)
{
    const osg::Array* vertices = geometry.getVertexArray();
    if (!vertices || vertices->getNumElements() < 3) return false;
    const FiniteEntry entry = vertexFacts(geometry);
    if (entry.flat) spanning = entry.spanning;
    return entry.flat;
}

void MeshCache::remove(const osg::Geometry* geometry)
{
    Lock lock(_mutex);
    _entries.erase(geometry);
    _finite.erase(geometry);
}

void MeshCache::prune()
{
    Lock lock(_mutex);
    for (auto it = _entries.begin(); it != _entries.end();)
    {
        if (it->second.geometry.valid()) ++it;
        else it = _entries.erase(it);
    }
    for (auto it = _finite.begin(); it != _finite.end();)
    {
        if (it->second.geometry.valid()) ++it;
        else it = _finite.erase(it);
    }
}

void MeshCache::clear()
{
    Lock lock(_mutex);
    _entries.clear();
    _finite.clear();
}

std::size_t MeshCache::size() const
{
    Lock lock(_mutex);
    return _entries.size();
}

std::size_t MeshCache::getBuildCount() const
{
    Lock lock(_mutex);
    return _buildCount;
}

std::size_t MeshCache::getRefreshCount() const
{
    Lock lock(_mutex);
    return _refreshCount;
}
}
