// Per-frame silhouette extraction and shadow-volume construction, building the mesh cache
// and refreshing it when only positions change, on generated tori of 10k, 100k and 1M triangles and on the scanned Stanford bunny
// shipped by Debian's glmark2-data. Results and the command are in docs/benchmarks.md.
#include <osgShadowSilhouette/HalfEdgeMesh>
#include <osgShadowSilhouette/MeshAdjacency>
#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/SilhouetteExtractor>

#include <benchmark/benchmark.h>

#include <osg/Geometry>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace osgShadowSilhouette;

namespace {

const char* kBunnyPath = "/usr/share/glmark2/models/bunny.obj";

/** Torus around z with 2 * major * minor triangles. */
osg::ref_ptr<osg::Geometry> makeTorus(unsigned major, unsigned minor)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (unsigned u = 0; u < major; ++u)
        for (unsigned w = 0; w < minor; ++w)
        {
            double phi = 2.0 * osg::PI * u / major, theta = 2.0 * osg::PI * w / minor;
            double rho = 2.0 + 0.5 * std::cos(theta);
            v->push_back(osg::Vec3f(rho * std::cos(phi), rho * std::sin(phi), 0.5 * std::sin(theta)));
        }
    osg::ref_ptr<osg::DrawElementsUInt> t = new osg::DrawElementsUInt(GL_TRIANGLES);
    auto id = [&](unsigned u, unsigned w) { return (u % major) * minor + w % minor; };
    for (unsigned u = 0; u < major; ++u)
        for (unsigned w = 0; w < minor; ++w)
            for (unsigned i : { id(u, w), id(u + 1, w), id(u + 1, w + 1), id(u, w), id(u + 1, w + 1), id(u, w + 1) })
                t->push_back(i);
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName("torus");
    g->setVertexArray(v.get());
    g->addPrimitiveSet(t.get());
    return g;
}

/** The vertices and triangular faces of a Wavefront OBJ file ("f a b c", "f a/x/y ..."). */
osg::ref_ptr<osg::Geometry> readObj(const std::string& path)
{
    std::ifstream in(path);
    if (!in) return nullptr;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::DrawElementsUInt> t = new osg::DrawElementsUInt(GL_TRIANGLES);
    std::string line, tag, corner;
    while (std::getline(in, line))
    {
        std::istringstream fields(line);
        fields >> tag;
        if (tag == "v")
        {
            osg::Vec3f p;
            fields >> p.x() >> p.y() >> p.z();
            v->push_back(p);
        }
        else if (tag == "f")
            for (int k = 0; k < 3 && fields >> corner; ++k) t->push_back(std::stoul(corner) - 1);
    }
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(path);
    g->setVertexArray(v.get());
    g->addPrimitiveSet(t.get());
    return g;
}

osg::ref_ptr<osg::Geometry> meshNumber(int id)
{
    switch (id)
    {
        case 0: return makeTorus(100, 50);   //    10,000 triangles
        case 1: return makeTorus(316, 158);  //    99,856 triangles
        case 2: return makeTorus(1000, 500); // 1,000,000 triangles
        default: return readObj(kBunnyPath); //    69,666 triangles (scanned)
    }
}

const MeshAdjacency* adjacency(int id)
{
    static std::map<int, MeshAdjacency> built;
    auto it = built.find(id);
    if (it != built.end()) return &it->second;
    osg::ref_ptr<osg::Geometry> g = meshNumber(id);
    if (!g) return nullptr;
    buildMeshAdjacency(*g, MeshBuildOptions(), built[id]);
    return &built[id];
}

void setLabel(benchmark::State& state, int id, const MeshAdjacency& mesh)
{
    state.SetLabel(id == 3 ? "bunny.obj" : "torus");
    state.counters["faces"] = double(mesh.faces.size());
    state.counters["ns/face"] = benchmark::Counter(double(mesh.faces.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}

osg::Vec4d lightFor(benchmark::State& state)
{
    return state.range(1) == 0 ? osg::Vec4d(0.3, 0.5, 1.0, 0.0) : osg::Vec4d(1.0, 2.0, 6.0, 1.0);
}

/** Part of (a): classification alone (one dot product per face). */
void BM_Classify(benchmark::State& state)
{
    const MeshAdjacency* mesh = adjacency(int(state.range(0)));
    if (!mesh) return state.SkipWithError("cannot read mesh");
    std::vector<std::uint8_t> lit;
    const osg::Vec4d light = lightFor(state);
    for (auto _ : state)
    {
        benchmark::DoNotOptimize(SilhouetteExtractor::classifyFaces(*mesh, light, lit));
    }
    setLabel(state, int(state.range(0)), *mesh);
}

/** (a) per frame: classification and silhouette edges. */
void BM_Silhouette(benchmark::State& state)
{
    const MeshAdjacency* mesh = adjacency(int(state.range(0)));
    if (!mesh) return state.SkipWithError("cannot read mesh");
    SilhouetteExtractor extractor;
    SilhouetteEdges silhouette;
    const osg::Vec4d light = lightFor(state);
    for (auto _ : state)
    {
        extractor.extract(*mesh, light, silhouette);
        benchmark::DoNotOptimize(silhouette.vertexIndices.data());
    }
    setLabel(state, int(state.range(0)), *mesh);
    state.counters["edges"] = double(silhouette.edgeCount());
}

/** (a') per frame: classification, silhouette and the whole z-fail volume. */
void BM_ShadowVolume(benchmark::State& state)
{
    const MeshAdjacency* mesh = adjacency(int(state.range(0)));
    if (!mesh) return state.SkipWithError("cannot read mesh");
    SilhouetteExtractor extractor;
    SilhouetteEdges silhouette;
    ShadowVolume volume;
    const osg::Vec4d light = lightFor(state);
    for (auto _ : state)
    {
        extractor.extract(*mesh, light, silhouette);
        extractor.buildVolume(*mesh, silhouette, volume);
        benchmark::DoNotOptimize(volume.indices.data());
    }
    setLabel(state, int(state.range(0)), *mesh);
    state.counters["triangles"] = double(volume.triangleCount());
}

/** (b) building the cache entry: osg::Geometry -> welded OpenMesh mesh -> flat arrays. */
void BM_BuildCache(benchmark::State& state)
{
    osg::ref_ptr<osg::Geometry> geometry = meshNumber(int(state.range(0)));
    if (!geometry) return state.SkipWithError("cannot read mesh");
    MeshAdjacency mesh;
    for (auto _ : state)
    {
        HalfEdgeMesh halfEdge;
        buildMeshAdjacency(*geometry, MeshBuildOptions(), mesh, &halfEdge);
        benchmark::DoNotOptimize(mesh.edgeFaces.data());
    }
    setLabel(state, int(state.range(0)), mesh);
}

/** A mesh whose vertices a smooth wave moves (a function of the rest position, so welded
 *  vertices stay together) between two poses, one per next(). */
struct Wave
{
    osg::ref_ptr<osg::Geometry> geometry;
    std::vector<osg::Vec3f> rest;
    int phase = 0;

    explicit Wave(int id) : geometry(meshNumber(id))
    {
        if (!geometry) return;
        const auto& v = *static_cast<const osg::Vec3Array*>(geometry->getVertexArray());
        rest.assign(v.begin(), v.end());
    }
    void next()
    {
        auto& v = *static_cast<osg::Vec3Array*>(geometry->getVertexArray());
        const float amplitude = (phase ^= 1) ? 0.02f : -0.02f;
        for (std::size_t i = 0; i < rest.size(); ++i)
            v[i] = rest[i] + osg::Vec3f(0.0f, 0.0f, amplitude * std::sin(8.0f * rest[i].x()));
        v.dirty();
    }
};

/** (c) positions alone changed, in place: refreshMeshPositions() on the adjacency it refreshes
 *  (positions, welding check, planes, inward parts); no copy of the topology. */
void BM_RefreshPositions(benchmark::State& state)
{
    Wave wave(int(state.range(0)));
    if (!wave.geometry) return state.SkipWithError("cannot read mesh");
    MeshAdjacency mesh;
    MeshWelding welding;
    buildMeshAdjacency(*wave.geometry, MeshBuildOptions(), mesh, nullptr, &welding);
    for (auto _ : state)
    {
        state.PauseTiming();
        wave.next();
        state.ResumeTiming();
        if (!refreshMeshPositions(*wave.geometry, welding, mesh, mesh)) return state.SkipWithError("welding broke");
        benchmark::DoNotOptimize(mesh.planes.data());
    }
    setLabel(state, int(state.range(0)), mesh);
}

/** (c') the same through MeshCache::get() after dirty() (what an animated caster costs per
 *  frame). range(1) = 0: the caller holds only the last frame's mesh, so the entry retired
 *  before is free and refreshed in place; 1: it holds the last two, so each refresh goes
 *  into a new CachedMesh with a copy of the topology. */
void BM_RefreshCache(benchmark::State& state)
{
    Wave wave(int(state.range(0)));
    if (!wave.geometry) return state.SkipWithError("cannot read mesh");
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<const CachedMesh> mesh = cache->get(*wave.geometry), older;
    for (auto _ : state)
    {
        state.PauseTiming();
        wave.next();
        state.ResumeTiming();
        osg::ref_ptr<const CachedMesh> next = cache->get(*wave.geometry);
        older = state.range(1) ? mesh : nullptr;
        mesh = next;
    }
    if (cache->getBuildCount() != 1) return state.SkipWithError("rebuilt instead of refreshed");
    setLabel(state, int(state.range(0)), mesh->getAdjacency());
}

/** (c'') the other per-frame cost of an animated caster: MeshCache::hasFiniteVertices() and
 *  getPlane() (asked every frame by the technique) recomputed after dirty(). */
void BM_VertexFacts(benchmark::State& state)
{
    Wave wave(int(state.range(0)));
    if (!wave.geometry) return state.SkipWithError("cannot read mesh");
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    std::array<osg::Vec3d, 3> spanning;
    for (auto _ : state)
    {
        state.PauseTiming();
        wave.next();
        state.ResumeTiming();
        benchmark::DoNotOptimize(cache->hasFiniteVertices(*wave.geometry));
        benchmark::DoNotOptimize(cache->getPlane(*wave.geometry, spanning));
    }
    setLabel(state, int(state.range(0)), *adjacency(int(state.range(0))));
}

// range(0): 0 torus 10k, 1 torus 100k, 2 torus 1M, 3 bunny; range(1): 0 directional, 1 point
// (BM_RefreshCache: 0 the retired entry free, 1 held)
BENCHMARK(BM_Classify)->ArgsProduct({ { 0, 1, 2, 3 }, { 0 } })->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Silhouette)->ArgsProduct({ { 0, 1, 2, 3 }, { 0, 1 } })->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShadowVolume)->ArgsProduct({ { 0, 1, 2, 3 }, { 0, 1 } })->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildCache)->Args({ 0, 0 })->Args({ 1, 0 })->Args({ 2, 0 })->Args({ 3, 0 })
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RefreshPositions)->Args({0, 0})->Args({1, 0})->Args({2, 0})->Args({3, 0})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_VertexFacts)->Args({1, 0})->Args({3, 0})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RefreshCache)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMicrosecond);
}

BENCHMARK_MAIN();
