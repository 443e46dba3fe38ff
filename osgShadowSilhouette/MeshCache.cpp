/* -*-c++-*- osgShadowSilhouette - hard shadows for OpenSceneGraph
 *
 * Distributed under the terms of the OpenSceneGraph Public License (OSGPL).
 */

#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/HalfEdgeMesh>

#include <OpenThreads/ScopedLock>

#include <algorithm>
#include <cmath>

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

/** Whether every float or double component of @p array is finite (other types: true). */
bool allComponentsFinite(const osg::Array& array)
{
    const std::size_t bytes = array.getTotalDataSize();
    if (array.getDataType() == GL_FLOAT)
    {
        const float* f = static_cast<const float*>(array.getDataPointer());
        return std::all_of(f, f + bytes / sizeof(float), [](float x) { return std::isfinite(x); });
    }
    if (array.getDataType() == GL_DOUBLE)
    {
        const double* d = static_cast<const double*>(array.getDataPointer());
        return std::all_of(d, d + bytes / sizeof(double), [](double x) { return std::isfinite(x); });
    }
    return true;
}

} // namespace

namespace {

/** Whether the points lie in one plane within 1e-6 of their extent; if so, three of them
 *  spanning it. */
template <typename Vec>
bool spanningPlane(const std::vector<Vec>& points, std::array<osg::Vec3d, 3>& spanning)
{
    if (points.size() < 3) return false;
    const osg::Vec3d p0(points.front());
    osg::Vec3d p1 = p0;
    double farthest = 0.0; // squared distances and areas: no square root per point
    for (const Vec& v : points)
    {
        const double distance = (osg::Vec3d(v) - p0).length2();
        if (distance > farthest) farthest = distance, p1 = osg::Vec3d(v);
    }
    const osg::Vec3d axis = p1 - p0;
    const double extent = axis.length();
    if (!(extent > 0.0)) return false;
    osg::Vec3d p2 = p0;
    double best = 0.0;
    for (const Vec& v : points)
    {
        const double area = ((osg::Vec3d(v) - p0) ^ axis).length2();
        if (area > best) best = area, p2 = osg::Vec3d(v);
    }
    osg::Vec3d normal = axis ^ (p2 - p0);
    // Collinear, or nearly: no plane of their own (a segment casts no shadow, but say no).
    if (!(normal.length() > 1e-12 * extent * extent)) return false;
    normal.normalize();
    const double tolerance = 1e-6 * extent;
    for (const Vec& v : points)
        if (std::abs((osg::Vec3d(v) - p0) * normal) > tolerance) return false;
    spanning = {p0, p1, p2};
    return true;
}

} // namespace

MeshCache::FiniteEntry MeshCache::vertexFacts(const osg::Geometry& geometry)
{
    const osg::Array* vertices = geometry.getVertexArray();
    {
        Lock lock(_mutex);
        auto it = _finite.find(&geometry);
        if (it != _finite.end() && it->second.geometry.get() == &geometry && it->second.vertices == vertices &&
            it->second.verticesModified == (vertices ? vertices->getModifiedCount() : 0u))
            return it->second;
    }
    FiniteEntry entry; // outside the lock
    entry.geometry = &geometry;
    entry.vertices = vertices;
    entry.verticesModified = vertices ? vertices->getModifiedCount() : 0u;
    entry.finite = !vertices || allComponentsFinite(*vertices);
    if (entry.finite && vertices)
    {
        if (const auto* v3 = dynamic_cast<const osg::Vec3Array*>(vertices))
            entry.flat = spanningPlane(v3->asVector(), entry.spanning);
        else if (const auto* v3d = dynamic_cast<const osg::Vec3dArray*>(vertices))
            entry.flat = spanningPlane(v3d->asVector(), entry.spanning);
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
