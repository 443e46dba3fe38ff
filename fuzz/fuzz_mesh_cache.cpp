// libFuzzer target: MeshCache and SilhouetteExtractor on meshes built from the input.
//
// Layout of an input (short inputs are padded with zeros):
//   byte 0       primitive mode (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN, QUADS, POLYGON, ...)
//   byte 1       bit 0: indexed (DrawElementsUShort) or DrawArrays; bit 1: weld tolerance 0;
//                bit 2: OpenCasterRule::LIT_FACES_ONLY
//   byte 2       number of vertices n (0 to 255)
//   then         4 floats of the light (x, y, z, w: w = 0 directional), raw bits (NaN, Inf)
//   then         n vertices, 3 floats each, raw bits
//   the rest     indices, one byte each (may point past the vertex array)
// Checked: every index the mesh, the silhouette and the volume hold is in range; positions
// and volume vertices are finite (NaN and Inf vertices are refused); a closed mesh has an
// even number of boundary-free edges per face (3 F = 2 E).
#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/SilhouetteExtractor>

#include <osg/Geometry>
#include <osg/Notify>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace osgShadowSilhouette;

namespace {

struct Reader
{
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t byte() { return at < size ? data[at++] : 0; }
    float number()
    {
        std::uint8_t b[4] = {byte(), byte(), byte(), byte()};
        float f;
        std::memcpy(&f, b, 4);
        return f;
    }
    bool more() const { return at < size; }
};

#define REQUIRE(c) \
    do { if (!(c)) std::abort(); } while (0)

bool finite(const osg::Vec4f& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()) && std::isfinite(v.w());
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    osg::setNotifyLevel(osg::FATAL); // NaN vertices are reported through osg::notify
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Reader in{data, size};
    static const GLenum modes[] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                   GL_QUAD_STRIP, GL_POLYGON, GL_LINES, GL_POINTS};
    const GLenum mode = modes[in.byte() % 8];
    const std::uint8_t flags = in.byte();
    const unsigned int n = in.byte();
    const osg::Vec4d light(in.number(), in.number(), in.number(), in.number());
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    for (unsigned int i = 0; i < n; ++i) vertices->push_back(osg::Vec3(in.number(), in.number(), in.number()));
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setVertexArray(vertices.get());
    if (flags & 1)
    {
        osg::ref_ptr<osg::DrawElementsUShort> e = new osg::DrawElementsUShort(mode);
        while (in.more()) e->push_back(in.byte());
        geometry->addPrimitiveSet(e.get());
    }
    else
        geometry->addPrimitiveSet(new osg::DrawArrays(mode, 0, GLsizei(n)));

    osg::ref_ptr<MeshCache> cache = new MeshCache;
    MeshBuildOptions options;
    if (flags & 2) options.weldTolerance = 0.0;
    cache->setBuildOptions(options);
    osg::ref_ptr<const CachedMesh> cached = cache->get(*geometry);
    REQUIRE(cached.valid());
    REQUIRE(cache->get(*geometry) == cached); // unchanged geometry: the same entry
    const MeshAdjacency& mesh = cached->getAdjacency();
    const std::size_t nv = mesh.positions.size(), nf = mesh.faces.size();
    for (const osg::Vec3f& p : mesh.positions) REQUIRE(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
    REQUIRE(mesh.planes.size() == nf);
    for (std::size_t e = 0; e < mesh.edgeCount(); ++e)
    {
        const InteriorEdge edge = mesh.edge(e);
        REQUIRE(edge.face0 < nf && edge.face1 < nf && edge.v0 < nv && edge.v1 < nv);
    }
    for (std::uint32_t f : mesh.nonManifoldFaces) REQUIRE(f < nf);
    if (mesh.isClosed() && !mesh.empty()) REQUIRE(3 * nf == 2 * mesh.edgeCount());

    const bool lightFinite = std::isfinite(light.x()) && std::isfinite(light.y()) && std::isfinite(light.z()) &&
                             std::isfinite(light.w());
    if (!lightFinite) return 0; // the technique never hands a non-finite light to the extractor
    SilhouetteExtractor extractor(flags & 4 ? OpenCasterRule::LIT_FACES_ONLY : OpenCasterRule::TWO_SIDED);
    SilhouetteEdges edges;
    ShadowVolume volume;
    extractor.extract(mesh, light, edges);
    REQUIRE(edges.lit.size() == nf);
    for (std::uint32_t i : edges.vertexIndices) REQUIRE(i < nv);
    REQUIRE(edges.positions.size() == edges.vertexIndices.size());
    extractor.buildVolume(mesh, edges, volume);
    for (std::uint32_t i : volume.indices) REQUIRE(i < volume.vertices.size());
    REQUIRE(volume.indices.size() % 3 == 0);
    const IndexRange ranges[] = {volume.sides, volume.lightCap, volume.darkCap};
    for (const IndexRange& r : ranges) REQUIRE(std::size_t(r.first) + r.count <= volume.indices.size());
    // Finite positions and a finite light, both of moderate size, give finite volume vertices.
    double largest = 0.0;
    for (const osg::Vec3f& p : mesh.positions) largest = std::max(largest, double(p.length()));
    if (light.length() < 1e18 && largest < 1e18)
        for (const osg::Vec4f& v : volume.vertices) REQUIRE(finite(v));
    return 0;
}
