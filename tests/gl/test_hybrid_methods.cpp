// HYBRID's two ways of resolving silhouette pixels, against the exact reference and against
// each other: HYBRID_STENCIL_VOLUMES (Chan and Durand's stencil-masked shadow volumes) and
// HYBRID_TRIANGLE_LISTS (a shadow ray per silhouette pixel against the caster triangles
// listed per light-space texel).
#include "GLTestSupport.h"

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

struct MethodCase
{
    const char* scene;
    SilhouetteShadowTechnique::HybridMethod method;
    unsigned int mapSize;
};

std::string methodName(SilhouetteShadowTechnique::HybridMethod m)
{
    return m == SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS ? "lists" : "stencil";
}

class HybridMethods : public ::testing::TestWithParam<MethodCase>
{
};

TEST_P(HybridMethods, MatchTheReference)
{
    const MethodCase& c = GetParam();
    ShadowedRender r(c.scene, "hybrid", c.mapSize, 512, 384);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(c.method);
    const ossref::Comparison cmp = ossref::compareMasks(r.mask(), r.reference());
    ASSERT_TRUE(cmp.valid) << cmp.error;
    EXPECT_LT(cmp.coverageMismatch, 20);
    EXPECT_LT(cmp.wrongPct, 0.01) << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels;
    EXPECT_EQ(r.technique->getStatistics().triangleLists,
              c.method == SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, HybridMethods,
    ::testing::Values(MethodCase{"default", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 256},
                      MethodCase{"default", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 1024},
                      MethodCase{"spheres", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 512},
                      MethodCase{"poles", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 512},
                      MethodCase{"grazing", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 512},
                      MethodCase{"default", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 256},
                      MethodCase{"spheres", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 512},
                      MethodCase{"poles", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 512}),
    [](const ::testing::TestParamInfo<MethodCase>& info) {
        return std::string(info.param.scene) + "_" + methodName(info.param.method) + "_" +
               std::to_string(info.param.mapSize);
    });

TEST(HybridMethods, AutoUsesTriangleListsWhereTheContextHasThem)
{
    ShadowedRender r("default", "hybrid", 512, 256, 192);
    ASSERT_TRUE(r.valid());
    ASSERT_EQ(r.technique->getHybridMethod(), SilhouetteShadowTechnique::HYBRID_AUTO);
    r.renderer->timeFrames(0, 1);
    EXPECT_TRUE(r.technique->getStatistics().triangleLists) << "this machine's GL is 4.5";
    EXPECT_EQ(r.technique->getStatistics().zfailCasters + r.technique->getStatistics().zpassCasters, 0u)
        << "no shadow volumes with triangle lists";
}

TEST(HybridMethods, ListsAndVolumesAgreeOnManyOverlappingShadows)
{
    ShadowedRender r("cubes", "hybrid", 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    const ossref::Mask volumes = r.mask();
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    const ossref::Mask lists = r.mask();
    const ossref::Comparison c = ossref::compareMasks(lists, volumes);
    ASSERT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.wrongPct, 0.01) << c.wrongPixels << " pixels differ";
    const ossref::Comparison exact = ossref::compareMasks(lists, r.reference());
    EXPECT_LT(exact.wrongPct, 0.05) << "cubes at a 1024 map: casters thinner than a texel are missed by both";
}

} // namespace
