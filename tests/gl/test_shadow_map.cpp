// SHADOW_MAP mode against the exact ray-cast reference (MEASURE.md), at 1024x768.
#include "GLTestSupport.h"

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

double wrongPct(ShadowedRender& r, unsigned int light = 0)
{
    const ossref::Comparison c = ossref::compareMasks(r.mask(light), r.reference(light));
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.coverageMismatch, 50) << "the mask and the reference disagree on where geometry is";
    EXPECT_GT(c.geometryPixels, 100000);
    return c.wrongPct;
}

} // namespace

// Measured 0.04% at 1024 (edge aliasing only); the bound leaves room for rasterizer differences.
TEST(ShadowMapAccuracy, DefaultSceneAt1024IsWithinBound)
{
    ShadowedRender r("default", "shadowmap", 1024);
    ASSERT_TRUE(r.valid());
    EXPECT_LT(wrongPct(r), 0.15);
}

// The same check must be able to fail: a 32x32 map loses the shadows' shapes.
TEST(ShadowMapAccuracy, TinyMapExceedsTheBound)
{
    ShadowedRender r("default", "shadowmap", 32);
    ASSERT_TRUE(r.valid());
    EXPECT_GT(wrongPct(r), 1.0);
}

TEST(ShadowMapAccuracy, LargerMapIsMoreAccurate)
{
    ShadowedRender coarse("default", "shadowmap", 256);
    ShadowedRender fine("default", "shadowmap", 2048);
    ASSERT_TRUE(coarse.valid() && fine.valid());
    const double a = wrongPct(coarse), b = wrongPct(fine);
    EXPECT_LT(b * 2.0, a) << "256: " << a << "%, 2048: " << b << "%";
}

TEST(ShadowMapStatistics, OneLightOnePass)
{
    ShadowedRender r("default", "shadowmap", 512);
    ASSERT_TRUE(r.valid());
    r.renderer->timeFrames(0, 1);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 1u);
    EXPECT_EQ(s.lightsShadowed, 1u);
    EXPECT_EQ(s.shadowPasses, 1u);
    EXPECT_EQ(s.depthPassesReused, 0u);
    r.renderer->timeFrames(0, 1); // nothing moved: the map is kept, still in use
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, 1u);
    EXPECT_EQ(r.technique->getStatistics().depthPassesReused, 1u);
    EXPECT_EQ(s.effectiveMode, SilhouetteShadowTechnique::SHADOW_MAP);
}

TEST(ShadowMapLights, SecondDirectionalLightHasItsOwnShadow)
{
    ShadowedRender r("default", "shadowmap", 1024);
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::LightSource> second = osshar::makeLight(osg::Vec4(-0.5f, -0.4f, 0.77f, 0.0f), 1);
    r.scene.content->addChild(second.get());
    r.scene.lights = osshar::findLights(r.scene.content.get());
    ASSERT_EQ(r.scene.lights.size(), 2u);
    r.renderer->timeFrames(0, 1);
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, 2u);
    EXPECT_LT(wrongPct(r, 0), 0.15);
    EXPECT_LT(wrongPct(r, 1), 0.15);
}

TEST(ShadowMapLights, LightNumSelectsOneLight)
{
    ShadowedRender r("default", "shadowmap", 512);
    ASSERT_TRUE(r.valid());
    r.scene.content->addChild(osshar::makeLight(osg::Vec4(-0.5f, -0.4f, 0.77f, 0.0f), 1));
    r.technique->setLightNum(1);
    r.renderer->timeFrames(0, 2);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 2u);
    EXPECT_EQ(s.lightsShadowed, 1u);
}

TEST(ShadowMapLights, BudgetLimitsShadowedLights)
{
    ShadowedRender r("default", "shadowmap", 256);
    ASSERT_TRUE(r.valid());
    for (int i = 1; i < 4; ++i)
        r.scene.content->addChild(osshar::makeLight(osg::Vec4(0.2f * i, -0.3f, 0.9f, 0.0f), i));
    r.technique->setMaxShadowLights(2);
    r.renderer->timeFrames(0, 3); // dirty() -> init() in the next update
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 4u);
    EXPECT_EQ(s.lightsShadowed, 2u);
}
