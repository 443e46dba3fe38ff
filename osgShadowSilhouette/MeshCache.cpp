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
    if (keep) mesh->_halfEdgeMesh.reset(new HalfEdgeMesh);
    buildMeshAdjacency(geometry, options, mesh->_adjacency, mesh->_halfEdgeMesh.get());
    return mesh;
}

osg::ref_ptr<const CachedMesh> MeshCache::get(const osg::Geometry& geometry)
{
    {
        Lock lock(_mutex);
        auto it = _entries.find(&geometry);
        if (it != _entries.end() && it->second.geometry.get() == &geometry &&
            it->second.signature.matches(geometry))
            return it->second.mesh;
    }
    // taken before building, so that a change made meanwhile triggers another rebuild
    Signature signature = signatureOf(geometry);
    osg::ref_ptr<const CachedMesh> mesh = build(geometry);
    Lock lock(_mutex);
    Entry& entry = _entries[&geometry];
    entry.geometry = &geometry;
    entry.signature = signature;
    entry.mesh = mesh;
    ++_buildCount;
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

bool MeshCache::hasFiniteVertices(const osg::Geometry& geometry)
{
    const osg::Array* vertices = geometry.getVertexArray();
    if (!vertices || vertices->getNumElements() == 0) return true;
    {
        Lock lock(_mutex);
        auto it = _finite.find(&geometry);
        if (it != _finite.end() && it->second.geometry.get() == &geometry && it->second.vertices == vertices &&
            it->second.verticesModified == vertices->getModifiedCount())
            return it->second.finite;
    }
    FiniteEntry entry;
    entry.geometry = &geometry;
    entry.vertices = vertices;
    entry.verticesModified = vertices->getModifiedCount();
    entry.finite = allComponentsFinite(*vertices); // outside the lock
    Lock lock(_mutex);
    _finite[&geometry] = entry;
    return entry.finite;
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

}
