// MeshCache: one mesh per geometry, rebuilt or refreshed only when its arrays change
// (test_mesh_refresh.cpp: refreshes in detail).
#include "test_mesh_shapes.h"

#include <osgShadowSilhouette/HalfEdgeMesh>
#include <osgShadowSilhouette/MeshCache>

#include <gtest/gtest.h>

#include <array>

#include <atomic>
#include <limits>
#include <thread>

using namespace osgShadowSilhouette;
using namespace meshtest;

namespace {

TEST(MeshCache, SecondLookupReturnsTheCachedMesh)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    osg::ref_ptr<const CachedMesh> first = cache->get(*g);
    osg::ref_ptr<const CachedMesh> second = cache->get(*g);
    EXPECT_EQ(first.get(), second.get());
    EXPECT_EQ(1u, cache->getBuildCount());
    EXPECT_EQ(12u, first->getAdjacency().faces.size());
    ASSERT_NE(nullptr, first->getHalfEdgeMesh());
    EXPECT_EQ(12u, first->getHalfEdgeMesh()->n_faces());
}

struct Change
{
    const char* name;
    std::function<void(osg::Geometry&)> apply;
    std::size_t facesAfter;
    bool refresh; ///< positions alone changed: the entry is refreshed, not rebuilt
};

// each change must make the next lookup refresh or rebuild; the face count after it is
// counted by hand
const std::vector<Change> kChanges = {
    {"vertex_array_dirtied",
     [](osg::Geometry& g) {
         auto* v = static_cast<osg::Vec3Array*>(g.getVertexArray());
         (*v)[6] = osg::Vec3f(2, 2, 2);
         v->dirty();
     },
     12, true},
    {"vertex_array_replaced",
     [](osg::Geometry& g) {
         auto* v = static_cast<osg::Vec3Array*>(g.getVertexArray());
         g.setVertexArray(new osg::Vec3Array(v->begin(), v->end()));
     },
     12, true},
    {"vertex_added",
     [](osg::Geometry& g) {
         auto* v = static_cast<osg::Vec3Array*>(g.getVertexArray());
         v->push_back(osg::Vec3f(2, 2, 2));
         v->dirty();
     },
     12, false},
    {"primitive_set_dirtied",
     [](osg::Geometry& g) {
         auto* e = static_cast<osg::DrawElementsUInt*>(g.getPrimitiveSet(0));
         e->resize(30); // drop the -x face
         e->dirty();
     },
     10, false},
    {"primitive_set_added",
     [](osg::Geometry& g) {
         std::vector<unsigned int> extra = {0, 1, 6};
         g.addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, extra.begin(), extra.end()));
     },
     13, false},
    {"primitive_set_removed", [](osg::Geometry& g) { g.removePrimitiveSet(0, 1); }, 0, false},
};

void PrintTo(const Change& c, std::ostream* os) { *os << c.name; }

class CacheInvalidation : public ::testing::TestWithParam<Change> {};

TEST_P(CacheInvalidation, RebuildsOrRefreshesAfterTheChange)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    osg::ref_ptr<const CachedMesh> before = cache->get(*g);
    GetParam().apply(*g);
    osg::ref_ptr<const CachedMesh> after = cache->get(*g);
    EXPECT_NE(before.get(), after.get());
    const std::size_t builds = GetParam().refresh ? 1u : 2u, refreshes = GetParam().refresh ? 1u : 0u;
    EXPECT_EQ(builds, cache->getBuildCount());
    EXPECT_EQ(refreshes, cache->getRefreshCount());
    EXPECT_EQ(GetParam().facesAfter, after->getAdjacency().faces.size());
    EXPECT_EQ(12u, before->getAdjacency().faces.size()); // old readers keep their mesh
    EXPECT_EQ(after.get(), cache->get(*g).get());
    EXPECT_EQ(builds, cache->getBuildCount());
    EXPECT_EQ(refreshes, cache->getRefreshCount());
}

INSTANTIATE_TEST_SUITE_P(Changes, CacheInvalidation, ::testing::ValuesIn(kChanges),
                         [](const ::testing::TestParamInfo<Change>& info) { return info.param.name; });

TEST(MeshCache, UnrelatedChangesDoNotRebuild)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    cache->get(*g);
    g->setColorArray(new osg::Vec4Array(1), osg::Array::BIND_OVERALL);
    g->setName("renamed");
    g->getOrCreateStateSet();
    cache->get(*g);
    EXPECT_EQ(1u, cache->getBuildCount());
}

// hasFiniteVertices() follows the vertex array's version and builds no mesh.
TEST(MeshCache, FiniteVerticesFollowTheArrayVersion)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    EXPECT_TRUE(cache->hasFiniteVertices(*g));
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    const osg::Vec3 kept = (*v)[3];
    (*v)[3].y() = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(cache->hasFiniteVertices(*g)) << "an edit without dirty() keeps the cached answer";
    v->dirty();
    EXPECT_FALSE(cache->hasFiniteVertices(*g));
    (*v)[3] = kept;
    (*v)[5].x() = std::numeric_limits<float>::quiet_NaN();
    v->dirty();
    EXPECT_FALSE(cache->hasFiniteVertices(*g));
    (*v)[5] = (*v)[4];
    v->dirty();
    EXPECT_TRUE(cache->hasFiniteVertices(*g));
    osg::ref_ptr<osg::Vec3dArray> doubles = new osg::Vec3dArray(3);
    (*doubles)[1].z() = std::numeric_limits<double>::quiet_NaN();
    g->setVertexArray(doubles.get());
    EXPECT_FALSE(cache->hasFiniteVertices(*g)) << "double arrays are checked too";
    EXPECT_EQ(0u, cache->getBuildCount());
}

// getPlane(): a ground quad is flat, a cube and a strip of collinear points are not; the
// answer follows the vertex array's version, and a tilted plane is found as well.
TEST(MeshCache, PlaneOfFlatGeometries)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    // A quad in the plane x + y + z = 3 (tilted), and a vertex at its centre.
    for (const osg::Vec3& p : {osg::Vec3(1, 1, 1), osg::Vec3(3, 0, 0), osg::Vec3(0, 3, 0), osg::Vec3(0, 0, 3),
                               osg::Vec3(2, 1, 0)})
        v->push_back(p);
    g->setVertexArray(v.get());
    std::array<osg::Vec3d, 3> spanning;
    ASSERT_TRUE(cache->getPlane(*g, spanning));
    osg::Vec3d normal = (spanning[1] - spanning[0]) ^ (spanning[2] - spanning[0]);
    normal.normalize();
    EXPECT_NEAR(std::abs(normal * osg::Vec3d(1, 1, 1) / std::sqrt(3.0)), 1.0, 1e-9);
    for (const osg::Vec3d& p : spanning) EXPECT_NEAR(p.x() + p.y() + p.z(), 3.0, 1e-6);

    (*v)[4].z() = 0.01f; // 0.01 off the plane: above 1e-6 of the extent
    EXPECT_TRUE(cache->getPlane(*g, spanning)) << "an edit without dirty() keeps the cached answer";
    v->dirty();
    EXPECT_FALSE(cache->getPlane(*g, spanning));
    (*v)[4].z() = 0.0f;
    v->dirty();
    EXPECT_TRUE(cache->getPlane(*g, spanning));
    // The four vertices that showed the last version not flat are tried first; the answer is
    // the full test's whether they still show it or another vertex does.
    (*v)[4].z() = 0.01f;
    v->dirty();
    EXPECT_FALSE(cache->getPlane(*g, spanning));
    (*v)[4].z() = 0.02f;
    v->dirty();
    EXPECT_FALSE(cache->getPlane(*g, spanning)) << "the same vertex farther off";
    (*v)[4].z() = 0.0f;
    (*v)[3].z() = 3.01f;
    v->dirty();
    EXPECT_FALSE(cache->getPlane(*g, spanning)) << "another vertex off the plane";
    (*v)[3].z() = 3.0f;
    v->dirty();
    EXPECT_TRUE(cache->getPlane(*g, spanning)) << "flat again";

    EXPECT_FALSE(cache->getPlane(*cube(), spanning));
    osg::ref_ptr<osg::Geometry> line = new osg::Geometry;
    const auto points = [](std::initializer_list<osg::Vec3> list) {
        osg::ref_ptr<osg::Vec3Array> a = new osg::Vec3Array;
        for (const osg::Vec3& p : list) a->push_back(p);
        return a;
    };
    line->setVertexArray(points({osg::Vec3(0, 0, 0), osg::Vec3(1, 1, 1), osg::Vec3(2, 2, 2)}));
    EXPECT_FALSE(cache->getPlane(*line, spanning)) << "collinear: no plane of its own";
    line->setVertexArray(points({osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0)}));
    EXPECT_FALSE(cache->getPlane(*line, spanning)) << "fewer than three vertices";
    osg::ref_ptr<osg::Vec3Array> nan = points({osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0)});
    (*nan)[2].x() = std::numeric_limits<float>::quiet_NaN();
    line->setVertexArray(nan.get());
    EXPECT_FALSE(cache->getPlane(*line, spanning)) << "a NaN vertex";
    EXPECT_EQ(0u, cache->getBuildCount());
}

TEST(MeshCache, PruneDropsEntriesOfDeletedGeometries)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> kept = cube();
    osg::ref_ptr<osg::Geometry> dropped = tetrahedron();
    osg::ref_ptr<const CachedMesh> held = cache->get(*dropped);
    cache->get(*kept);
    EXPECT_EQ(2u, cache->size());
    dropped = nullptr;
    cache->prune();
    EXPECT_EQ(1u, cache->size());
    EXPECT_EQ(4u, held->getAdjacency().faces.size()); // still valid for its holder
    cache->remove(kept.get());
    EXPECT_EQ(0u, cache->size());
    cache->get(*kept);
    cache->clear();
    EXPECT_EQ(0u, cache->size());
}

TEST(MeshCache, OptionsApplyToMeshesBuiltAfterwards)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    cache->setKeepHalfEdgeMesh(false);
    MeshBuildOptions options;
    options.weldTolerance = 0.25;
    cache->setBuildOptions(options);
    EXPECT_FALSE(cache->getKeepHalfEdgeMesh());
    EXPECT_EQ(0.25, cache->getBuildOptions().weldTolerance);
    osg::ref_ptr<const CachedMesh> mesh = cache->get(*cube());
    EXPECT_EQ(nullptr, mesh->getHalfEdgeMesh());
    // 0.25 x diagonal 3.46 = 0.87 < edge length 2: nothing merges
    EXPECT_EQ(8u, mesh->getAdjacency().positions.size());
}

TEST(MeshCache, ConcurrentLookupsAgree)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    std::vector<osg::ref_ptr<osg::Geometry>> geometries = { cube(), torus(24, 12), uvSphere(16, 8) };
    const std::size_t expectedFaces[] = { 12, 576, 224 };
    std::atomic<int> wrong{ 0 };
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&] {
            for (int i = 0; i < 200; ++i)
            {
                std::size_t k = std::size_t(i) % geometries.size();
                if (cache->get(*geometries[k])->getAdjacency().faces.size() != expectedFaces[k]) ++wrong;
            }
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(0, wrong.load());
    EXPECT_EQ(3u, cache->size());
    std::size_t builds = cache->getBuildCount();
    EXPECT_GE(builds, 3u);
    EXPECT_LE(builds, 12u); // at worst each thread built each mesh once
    for (auto& g : geometries) cache->get(*g);
    EXPECT_EQ(builds, cache->getBuildCount());
}

}
