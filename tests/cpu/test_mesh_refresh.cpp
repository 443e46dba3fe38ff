// MeshCache and refreshMeshPositions(): when only a caster's positions change (an animated
// mesh), the cached topology is kept and what depends on positions is recomputed; the result
// equals a full build of the moved mesh, field by field. Welded vertices pulled apart, a
// vertex turning finite or non-finite and any change of topology rebuild instead.
#include "NotifyCapture.h"
#include "test_mesh_shapes.h"
#include "test_soups.h"

#include <osgShadowSilhouette/MeshCache>

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <functional>
#include <limits>
#include <thread>

using namespace osgShadowSilhouette;
using namespace meshtest;

namespace {

/** Element-wise equality of two arrays of plain structs, to the bit. */
template <class T>
::testing::AssertionResult sameArrays(const char* what, const std::vector<T>& a, const std::vector<T>& b)
{
    if (a.size() != b.size())
        return ::testing::AssertionFailure() << what << ": " << a.size() << " vs " << b.size() << " elements";
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0)
            return ::testing::AssertionFailure() << what << " differ at " << i;
    return ::testing::AssertionSuccess();
}

/** Every field of @p refreshed equals that of @p fresh (built from scratch). */
void expectSameMesh(const MeshAdjacency& refreshed, const MeshAdjacency& fresh)
{
    EXPECT_TRUE(sameArrays("positions", refreshed.positions, fresh.positions));
    EXPECT_TRUE(sameArrays("faces", refreshed.faces, fresh.faces));
    EXPECT_TRUE(sameArrays("planes", refreshed.planes, fresh.planes));
    EXPECT_TRUE(sameArrays("edgeFaces", refreshed.edgeFaces, fresh.edgeFaces));
    EXPECT_TRUE(sameArrays("edgeVertices", refreshed.edgeVertices, fresh.edgeVertices));
    EXPECT_TRUE(sameArrays("boundaryEdges", refreshed.boundaryEdges, fresh.boundaryEdges));
    EXPECT_TRUE(sameArrays("nonManifoldFaces", refreshed.nonManifoldFaces, fresh.nonManifoldFaces));
    EXPECT_EQ(refreshed.inwardParts, fresh.inwardParts);
    const MeshBuildReport &a = refreshed.report, &b = fresh.report;
    EXPECT_EQ(a.inputTriangles, b.inputTriangles);
    EXPECT_EQ(a.degenerateTriangles, b.degenerateTriangles);
    EXPECT_EQ(a.nonFiniteVertices, b.nonFiniteVertices);
    EXPECT_EQ(a.nonFiniteTriangles, b.nonFiniteTriangles);
    EXPECT_EQ(a.outOfRangeTriangles, b.outOfRangeTriangles);
    EXPECT_EQ(a.nonManifoldFaces, b.nonManifoldFaces);
    EXPECT_EQ(a.weldDistance, b.weldDistance);
}

/** The silhouettes of both meshes for a few lights agree edge for edge. */
void expectSameSilhouettes(const MeshAdjacency& refreshed, const MeshAdjacency& fresh)
{
    SilhouetteExtractor extractor;
    for (const osg::Vec4d& light :
         {osg::Vec4d(0.3, 0.5, 1.0, 0.0), osg::Vec4d(-2.0, 1.0, 3.0, 1.0), osg::Vec4d(0.2, -3.0, -0.5, 1.0)})
    {
        SilhouetteEdges a, b;
        extractor.extract(refreshed, light, a);
        extractor.extract(fresh, light, b);
        EXPECT_TRUE(sameArrays("lit", a.lit, b.lit));
        EXPECT_TRUE(sameArrays("silhouette vertices", a.vertexIndices, b.vertexIndices));
        EXPECT_TRUE(sameArrays("silhouette positions", a.positions, b.positions));
        EXPECT_TRUE(sameArrays("multiplicity", a.multiplicity, b.multiplicity));
        EXPECT_EQ(a.closedCaster, b.closedCaster);
    }
}

MeshAdjacency freshBuild(const osg::Geometry& g)
{
    MeshAdjacency fresh;
    buildMeshAdjacency(g, MeshBuildOptions(), fresh);
    return fresh;
}

/** A smooth, non-affine deformation: a function of the position alone, so vertices that
 *  coincide keep coinciding (the skinning of a welded seam does the same). */
osg::Vec3f bend(const osg::Vec3f& p)
{
    const float s = 1.0f + 0.3f * std::sin(2.0f * p.x() + 1.0f) * std::cos(1.5f * p.y());
    return osg::Vec3f(p.x() * s + 0.2f * p.z() * p.z(), p.y() * s, p.z() * (2.0f - s) + 0.1f);
}

void deform(osg::Geometry& g, const std::function<osg::Vec3f(const osg::Vec3f&)>& f)
{
    auto* v = static_cast<osg::Vec3Array*>(g.getVertexArray());
    for (osg::Vec3f& p : *v) p = f(p);
    v->dirty();
}

/** Every triangle with its own three corners: all of the topology comes from welding. */
osg::ref_ptr<osg::Geometry> unwelded(const osg::Geometry& g)
{
    const auto& v = *static_cast<const osg::Vec3Array*>(g.getVertexArray());
    const auto& e = *static_cast<const osg::DrawElementsUInt*>(g.getPrimitiveSet(0));
    std::vector<souptest::Triangle> triangles;
    for (std::size_t t = 0; t + 2 < e.size(); t += 3) triangles.push_back({v[e[t]], v[e[t + 1]], v[e[t + 2]]});
    return souptest::soupGeometry(triangles, g.getName() + " unwelded");
}

struct Shape
{
    const char* name;
    std::function<osg::ref_ptr<osg::Geometry>()> make;
};

const std::vector<Shape> kShapes = {
    {"cube", [] { return cube(); }},
    {"sphere", [] { return uvSphere(24, 12); }},
    {"torus", [] { return torus(32, 12); }},
    {"open_plane", [] { return openPlane(); }},
    {"non_manifold_book", [] { return nonManifoldBook(); }},
    {"zero_area_face", [] { return cubeWithZeroAreaFace(); }},
    {"unwelded_sphere", [] { return unwelded(*uvSphere(16, 8)); }},
    {"unwelded_room_with_a_box", [] { return souptest::soupGeometry(souptest::roomWithABox(), "room"); }},
};

void PrintTo(const Shape& s, std::ostream* os)
{
    *os << s.name;
}

class MeshRefreshShapes : public ::testing::TestWithParam<Shape>
{
};

// Moving the vertices in place (dirty()) refreshes the entry, which then equals a fresh
// build of the moved mesh in every field and in its silhouettes; the entry read before
// keeps its positions, and the OpenMesh mesh is shared.
TEST_P(MeshRefreshShapes, MovedVerticesGiveTheFreshBuild)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = GetParam().make();
    osg::ref_ptr<const CachedMesh> before = cache->get(*g);
    const MeshAdjacency original = before->getAdjacency();
    for (int frame = 1; frame <= 3; ++frame)
    {
        deform(*g, bend);
        osg::ref_ptr<const CachedMesh> after = cache->get(*g);
        EXPECT_NE(before.get(), after.get());
        EXPECT_EQ(1u, cache->getBuildCount());
        EXPECT_EQ(std::size_t(frame), cache->getRefreshCount());
        EXPECT_EQ(before->getHalfEdgeMesh(), after->getHalfEdgeMesh());
        const MeshAdjacency fresh = freshBuild(*g);
        expectSameMesh(after->getAdjacency(), fresh);
        expectSameSilhouettes(after->getAdjacency(), fresh);
        EXPECT_EQ(after.get(), cache->get(*g).get());
    }
    expectSameMesh(before->getAdjacency(), original); // its readers see no change
}

INSTANTIATE_TEST_SUITE_P(Shapes, MeshRefreshShapes, ::testing::ValuesIn(kShapes),
                         [](const ::testing::TestParamInfo<Shape>& info) { return info.param.name; });

// Turning the cube inside out (a mirror) turns its volume negative: inwardParts follows.
TEST(MeshRefresh, InwardPartsFollowThePositions)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    EXPECT_TRUE(cache->get(*g)->getAdjacency().isClosedOutward());
    deform(*g, [](const osg::Vec3f& p) { return osg::Vec3f(-p.x(), p.y(), p.z()); });
    osg::ref_ptr<const CachedMesh> mirrored = cache->get(*g);
    EXPECT_EQ(1u, cache->getRefreshCount());
    EXPECT_EQ(1u, mirrored->getAdjacency().inwardParts);
    expectSameMesh(mirrored->getAdjacency(), freshBuild(*g));
}

// An animated entry alternates between two CachedMesh objects: a refresh writes into the
// entry retired by the refresh before when nobody holds it any more, without copying the
// topology; one still held is left alone.
TEST(MeshRefresh, RetiredEntryNobodyHoldsIsReused)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = uvSphere(16, 8);
    const CachedMesh* first = cache->get(*g).get();
    deform(*g, bend);
    const CachedMesh* second = cache->get(*g).get();
    EXPECT_NE(first, second);
    deform(*g, bend);
    osg::ref_ptr<const CachedMesh> held = cache->get(*g);
    EXPECT_EQ(first, held.get()) << "nobody held it: written again";
    expectSameMesh(held->getAdjacency(), freshBuild(*g));
    const MeshAdjacency heldBefore = held->getAdjacency();

    deform(*g, bend);
    osg::ref_ptr<const CachedMesh> fourth = cache->get(*g);
    EXPECT_EQ(second, fourth.get());
    expectSameMesh(fourth->getAdjacency(), freshBuild(*g));
    expectSameSilhouettes(fourth->getAdjacency(), freshBuild(*g));
    deform(*g, bend);
    osg::ref_ptr<const CachedMesh> fifth = cache->get(*g);
    EXPECT_NE(held.get(), fifth.get()) << "still held: a new one";
    expectSameMesh(fifth->getAdjacency(), freshBuild(*g));
    expectSameMesh(held->getAdjacency(), heldBefore);
    EXPECT_EQ(1u, cache->getBuildCount());
    EXPECT_EQ(4u, cache->getRefreshCount());
}

// Several cull threads refreshing one animated entry at once (the vertices moved between
// rounds, as an update traversal does) each get a mesh equal to a fresh build, while the
// mesh half of them kept from the round before stays as it was (the others' are reused).
TEST(MeshRefresh, ConcurrentRefreshesAgree)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = torus(24, 12);
    constexpr int kThreads = 4;
    std::vector<osg::ref_ptr<const CachedMesh>> kept(kThreads);
    std::vector<MeshAdjacency> keptCopies(kThreads);
    cache->get(*g);
    for (int round = 0; round < 20; ++round)
    {
        deform(*g, [round](const osg::Vec3f& p) { return bend(p) * (0.5f + 0.01f * float(round)); });
        const MeshAdjacency fresh = freshBuild(*g);
        std::vector<std::thread> threads;
        std::atomic<int> wrong{0};
        for (int t = 0; t < kThreads; ++t)
            threads.emplace_back([&, t] {
                osg::ref_ptr<const CachedMesh> mesh = cache->get(*g);
                if (std::memcmp(mesh->getAdjacency().planes.data(), fresh.planes.data(),
                                fresh.planes.size() * sizeof(osg::Vec4d)) != 0)
                    ++wrong;
                if (kept[t] && std::memcmp(kept[t]->getAdjacency().planes.data(), keptCopies[t].planes.data(),
                                           keptCopies[t].planes.size() * sizeof(osg::Vec4d)) != 0)
                    ++wrong;
                if (t % 2 == 0) return; // the others hold theirs a round longer
                kept[t] = mesh;
                keptCopies[t] = mesh->getAdjacency();
            });
        for (std::thread& t : threads) t.join();
        EXPECT_EQ(0, wrong.load()) << "round " << round;
    }
    EXPECT_EQ(1u, cache->getBuildCount());
    EXPECT_GE(cache->getRefreshCount(), 20u);
}

// Another vertex array of the same length, even of another type, is a refresh too.
TEST(MeshRefresh, ReplacedArrayOfTheSameLength)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = torus(16, 8);
    cache->get(*g);
    const auto& v = *static_cast<const osg::Vec3Array*>(g->getVertexArray());
    osg::ref_ptr<osg::Vec3dArray> doubles = new osg::Vec3dArray;
    for (const osg::Vec3f& p : v) doubles->push_back(osg::Vec3d(bend(p)) * 1.5);
    g->setVertexArray(doubles.get());
    osg::ref_ptr<const CachedMesh> refreshed = cache->get(*g);
    EXPECT_EQ(1u, cache->getBuildCount());
    EXPECT_EQ(1u, cache->getRefreshCount());
    expectSameMesh(refreshed->getAdjacency(), freshBuild(*g));
}

// One corner of a welded soup moved away from the others of its vertex: the welding no
// longer holds, so the entry is rebuilt, once, and again equals a fresh build; the next
// move of all vertices refreshes the rebuilt topology.
TEST(MeshRefresh, SeparatedWeldedVerticesRebuild)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = unwelded(*uvSphere(16, 8));
    const std::size_t closedEdges = cache->get(*g)->getAdjacency().boundaryEdges.size();
    EXPECT_EQ(0u, closedEdges);
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    (*v)[4] += osg::Vec3f(0.0f, 0.0f, 0.05f); // one triangle's corner leaves its neighbours
    v->dirty();
    osg::ref_ptr<const CachedMesh> torn = cache->get(*g);
    EXPECT_EQ(2u, cache->getBuildCount());
    EXPECT_EQ(0u, cache->getRefreshCount());
    EXPECT_FALSE(torn->getAdjacency().isClosed());
    expectSameMesh(torn->getAdjacency(), freshBuild(*g));

    deform(*g, bend);
    osg::ref_ptr<const CachedMesh> moved = cache->get(*g);
    EXPECT_EQ(2u, cache->getBuildCount());
    EXPECT_EQ(1u, cache->getRefreshCount());
    expectSameMesh(moved->getAdjacency(), freshBuild(*g));
    expectSameSilhouettes(moved->getAdjacency(), freshBuild(*g));
}

// Vertices that come to coincide are not welded by a refresh: the topology stays that of
// the build (open edges stay open), until the topology changes.
TEST(MeshRefresh, NewlyCoincidentVerticesStayApart)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g =
        souptest::soupGeometry({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0.2f, 0}, {1, 1, 0}, {0, 1.2f, 0}}}, "apart");
    EXPECT_EQ(6u, cache->get(*g)->getAdjacency().boundaryEdges.size());
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    (*v)[3] = (*v)[1];
    (*v)[5] = (*v)[2];
    v->dirty();
    osg::ref_ptr<const CachedMesh> touching = cache->get(*g);
    EXPECT_EQ(1u, cache->getRefreshCount());
    EXPECT_EQ(6u, touching->getAdjacency().boundaryEdges.size()) << "kept apart";
    EXPECT_EQ(4u, freshBuild(*g).boundaryEdges.size()) << "a fresh build welds them";
    g->getPrimitiveSet(0)->dirty(); // a change of topology welds them again
    EXPECT_EQ(4u, cache->get(*g)->getAdjacency().boundaryEdges.size());
    EXPECT_EQ(2u, cache->getBuildCount());
}

// Topology changes rebuild: a vertex added (another count), primitive sets edited.
TEST(MeshRefresh, TopologyChangesRebuild)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    cache->get(*g);
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    v->push_back(osg::Vec3f(5, 5, 5));
    v->dirty();
    cache->get(*g);
    EXPECT_EQ(2u, cache->getBuildCount());
    deform(*g, bend);
    auto* e = static_cast<osg::DrawElementsUInt*>(g->getPrimitiveSet(0));
    e->resize(30);
    e->dirty();
    osg::ref_ptr<const CachedMesh> mesh = cache->get(*g);
    EXPECT_EQ(3u, cache->getBuildCount());
    EXPECT_EQ(0u, cache->getRefreshCount());
    EXPECT_EQ(10u, mesh->getAdjacency().faces.size());
}

// A vertex turning NaN rebuilds (the build warns and leaves its triangles out); moving the
// others while it stays NaN refreshes without warning again; its return rebuilds.
TEST(MeshRefresh, NonFiniteVerticesRebuildWhenTheyComeAndGo)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = uvSphere(16, 8);
    cache->get(*g);
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    const osg::Vec3f kept = (*v)[20];
    osstest::NotifyCapture capture;
    (*v)[20].x() = std::numeric_limits<float>::quiet_NaN();
    v->dirty();
    osg::ref_ptr<const CachedMesh> holed = cache->get(*g);
    EXPECT_EQ(2u, cache->getBuildCount());
    EXPECT_EQ(1u, holed->getAdjacency().report.nonFiniteVertices);
    EXPECT_EQ(1, capture.count("NaN or infinite"));
    EXPECT_FALSE(cache->hasFiniteVertices(*g)) << "the technique leaves the caster out";

    deform(*g, bend);
    osg::ref_ptr<const CachedMesh> moved = cache->get(*g);
    EXPECT_EQ(1u, cache->getRefreshCount());
    EXPECT_EQ(1, capture.count("NaN or infinite")) << "a refresh does not warn again";
    expectSameMesh(moved->getAdjacency(), freshBuild(*g));
    EXPECT_FALSE(cache->hasFiniteVertices(*g));

    (*v)[20] = bend(kept);
    v->dirty();
    EXPECT_EQ(0u, cache->get(*g)->getAdjacency().report.nonFiniteVertices);
    EXPECT_EQ(3u, cache->getBuildCount());
    EXPECT_TRUE(cache->hasFiniteVertices(*g));
}

// refreshMeshPositions() on its own: in place, and refused for another vertex count.
TEST(MeshRefresh, RefreshInPlace)
{
    osg::ref_ptr<osg::Geometry> g = torus(16, 8);
    MeshAdjacency mesh;
    MeshWelding welding;
    buildMeshAdjacency(*g, MeshBuildOptions(), mesh, nullptr, &welding);
    deform(*g, bend);
    ASSERT_TRUE(refreshMeshPositions(*g, welding, mesh, mesh));
    expectSameMesh(mesh, freshBuild(*g));
    static_cast<osg::Vec3Array*>(g->getVertexArray())->push_back(osg::Vec3f());
    MeshAdjacency other;
    EXPECT_FALSE(refreshMeshPositions(*g, welding, mesh, other));
}

} // namespace
