// What the technique skips when the scene does not need it (docs/skipping.md):
//  - static frames reuse the depth and silhouette maps and the volume geometry, extract no
//    silhouette, and show the same shadows as the frame that rendered them;
//  - moving a caster or the light, or modifying a vertex array, renders the maps again and
//    the shadows follow;
//  - the volume of a caster that shadows nothing in view is not drawn, and no pixel changes;
//  - no casters, or no receivers in view: no light-space pass at all.
#include "GLTestSupport.h"
#include "Meshes.h"

#include <osg/MatrixTransform>
#include <osgShadow/ShadowSettings>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::ShadowedRender;
using Statistics = SilhouetteShadowTechnique::Statistics;

constexpr unsigned int MAP_SIZE = 1024;
constexpr unsigned int RECEIVES = 0x1, CASTS = 0x2;

/** Wrong-pixel bound of each mode against the reference (default scene, 1024 map, 1024x768). */
double boundPct(const std::string& mode)
{
    if (mode == "shadowmap") return 0.15;
    if (mode == "silhouette") return 0.02;
    return 0.01;
}

bool usesMaps(const std::string& mode)
{
    return mode != "volume";
}

bool usesVolumes(const std::string& mode)
{
    return mode == "volume" || mode == "hybrid";
}

/** The shadow mask of the next frame (the passes of that very frame decide it). */
ossref::Mask nextMask(ShadowedRender& r)
{
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    r.technique->setDebugLight(0);
    osg::ref_ptr<osg::Image> image = r.renderer->renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
    return ossref::maskFromImage(*image);
}

long long wrongPixels(const ossref::Mask& a, const ossref::Mask& b)
{
    const ossref::Comparison c = ossref::compareMasks(a, b);
    EXPECT_TRUE(c.valid) << c.error;
    return c.wrongPixels;
}

double wrongPctAgainstReference(ShadowedRender& r, const ossref::Mask& mask)
{
    const ossref::Comparison c = ossref::compareMasks(mask, r.reference());
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.coverageMismatch, 50);
    return c.wrongPct;
}

/** Puts the default scene's green box (child 3) under a MatrixTransform and returns it. */
osg::MatrixTransform* wrapCaster(ShadowedRender& r, unsigned int child = 3)
{
    osg::Group& content = *r.scene.content;
    osg::ref_ptr<osg::Node> node = content.getChild(child);
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
    transform->addChild(node.get());
    content.replaceChild(node.get(), transform.get());
    return transform.get();
}

/** Checks the statistics of a frame that rendered its passes (rendered) or reused them. */
void expectPasses(const Statistics& s, const std::string& mode, bool rendered)
{
    if (usesMaps(mode))
    {
        EXPECT_EQ(s.shadowPasses, 1u) << "in use, rendered or reused";
        EXPECT_EQ(s.depthPassesReused, rendered ? 0u : 1u);
    }
    else
    {
        EXPECT_EQ(s.shadowPasses + s.depthPassesReused, 0u) << "SHADOW_VOLUME renders no map";
    }
    EXPECT_EQ(s.silhouettePassesReused, mode == "silhouette" && !rendered ? 1u : 0u);
    if (mode == "silhouette")
    {
        EXPECT_EQ(s.extractionsSkipped, rendered ? 0u : 1u) << "extraction runs when and only when something moved";
    }
    if (usesVolumes(mode))
    {
        if (rendered)
            EXPECT_GT(s.volumesRebuilt, 0u);
        else
            EXPECT_EQ(s.volumesRebuilt, 0u);
    }
}

/** HYBRID's stencil-volume method, whose volumes these tests follow (with triangle lists,
 *  HYBRID draws no volume: test_hybrid_methods.cpp). */
void volumesForHybrid(ShadowedRender& r)
{
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
}

class Skipping : public ::testing::TestWithParam<const char*>
{
};

TEST_P(Skipping, StaticFramesReuseEverythingAndKeepTheShadows)
{
    const std::string mode = GetParam();
    ShadowedRender r("default", mode, MAP_SIZE);
    ASSERT_TRUE(r.valid());
    volumesForHybrid(r);
    const ossref::Mask first = nextMask(r);
    expectPasses(r.technique->getStatistics(), mode, true);
    r.renderer->timeFrames(0, 3);
    expectPasses(r.technique->getStatistics(), mode, false);
    const ossref::Mask later = nextMask(r);
    expectPasses(r.technique->getStatistics(), mode, false);
    EXPECT_EQ(wrongPixels(later, first), 0) << "a reused pass must show what it showed when rendered";
    EXPECT_LT(wrongPctAgainstReference(r, later), boundPct(mode));
}

/** One change of the scene between two frames. */
struct Change
{
    const char* name;
    void (*apply)(ShadowedRender& r, osg::MatrixTransform& caster);
};

const Change CHANGES[] = {
    {"caster_moved",
     [](ShadowedRender&, osg::MatrixTransform& caster) {
         caster.setMatrix(osg::Matrixd::translate(-1.5, 1.0, 0.0));
     }},
    {"light_moved",
     [](ShadowedRender& r, osg::MatrixTransform&) {
         osg::Light* light = r.scene.lights.at(0).source->getLight();
         light->setPosition(osg::Vec4(-0.3f, -0.45f, 0.84f, 0.0f));
     }},
    {"vertices_modified",
     [](ShadowedRender&, osg::MatrixTransform& caster) {
         osg::Geode* geode = caster.getChild(0)->asGeode();
         osg::Geometry* geometry = geode->getDrawable(0)->asGeometry();
         osg::Vec3Array* vertices = static_cast<osg::Vec3Array*>(geometry->getVertexArray());
         for (osg::Vec3& v : *vertices) v.z() *= 1.75f; // the box grows upward
         vertices->dirty();
         geometry->dirtyGLObjects();
         geometry->dirtyBound();
     }},
};

class SkippingChange : public ::testing::TestWithParam<std::tuple<const char*, Change>>
{
};

TEST_P(SkippingChange, NextFrameRendersAgainAndFollows)
{
    const std::string mode = std::get<0>(GetParam());
    const Change& change = std::get<1>(GetParam());
    ShadowedRender r("default", mode, MAP_SIZE);
    ASSERT_TRUE(r.valid());
    volumesForHybrid(r);
    osg::MatrixTransform* caster = wrapCaster(r);
    r.renderer->timeFrames(0, 2);
    const ossref::Mask before = nextMask(r);
    expectPasses(r.technique->getStatistics(), mode, false);

    change.apply(r, *caster);
    const ossref::Mask after = nextMask(r);
    expectPasses(r.technique->getStatistics(), mode, true);
    EXPECT_GT(wrongPixels(after, before), 1000) << "the shadows must move with the scene";
    EXPECT_LT(wrongPctAgainstReference(r, after), boundPct(mode));

    nextMask(r);
    expectPasses(r.technique->getStatistics(), mode, false); // static again
}

INSTANTIATE_TEST_SUITE_P(Modes, Skipping, ::testing::Values("shadowmap", "silhouette", "hybrid", "volume"));

INSTANTIATE_TEST_SUITE_P(Modes, SkippingChange,
                         ::testing::Combine(::testing::Values("shadowmap", "silhouette", "hybrid", "volume"),
                                            ::testing::ValuesIn(CHANGES)),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, Change>>& info) {
                             return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param).name;
                         });

TEST(Skipping, ReleasedGLObjectsAreRenderedAgain)
{
    ShadowedRender r("default", "silhouette", MAP_SIZE);
    ASSERT_TRUE(r.valid());
    r.renderer->timeFrames(0, 2);
    expectPasses(r.technique->getStatistics(), "silhouette", false);
    r.root->releaseGLObjects(); // as a viewer does when its context goes away
    const ossref::Mask mask = nextMask(r);
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, 1u);
    EXPECT_EQ(r.technique->getStatistics().depthPassesReused, 0u) << "released maps are rendered again";
    EXPECT_LT(wrongPctAgainstReference(r, mask), boundPct("silhouette"));
}

class SkippingVolumes : public ::testing::TestWithParam<const char*>
{
};

// A cast-only box (not drawn itself) first shadows the ground in view, then moves where
// its shadow falls outside the receivers: its volume is culled and the picture equals the
// one without that box.
TEST_P(SkippingVolumes, CasterThatShadowsNothingVisibleIsCulled)
{
    const std::string mode = GetParam();
    ShadowedRender r("default", mode, MAP_SIZE);
    ASSERT_TRUE(r.valid());
    volumesForHybrid(r);
    osgShadow::ShadowSettings* settings = r.technique->getShadowedScene()->getShadowSettings();
    settings->setReceivesShadowTraversalMask(RECEIVES);
    settings->setCastsShadowTraversalMask(CASTS);
    osg::ref_ptr<osg::MatrixTransform> extra = new osg::MatrixTransform(osg::Matrixd::translate(-2.0, -7.0, 3.0));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeBox(osg::Vec3(), osg::Vec3(1.5f, 1.5f, 1.5f)));
    extra->addChild(geode.get());
    extra->setNodeMask(CASTS);
    r.scene.content->addChild(extra.get());

    r.renderer->timeFrames(0, 1);
    const ossref::Mask near = nextMask(r);
    const unsigned int culledNear = r.technique->getStatistics().volumesCulled;

    extra->setMatrix(osg::Matrixd::translate(-40.0, 0.0, 5.0));
    const ossref::Mask away = nextMask(r);
    const Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.volumesCulled, culledNear + 1) << "the moved box's volume is not drawn";

    extra->setNodeMask(0);
    const ossref::Mask without = nextMask(r);
    EXPECT_GT(wrongPixels(near, without), 1000) << "the box shadowed the ground at first";
    EXPECT_EQ(wrongPixels(away, without), 0) << "culling a volume that shadows nothing changes no pixel";
}

INSTANTIATE_TEST_SUITE_P(Modes, SkippingVolumes, ::testing::Values("volume", "hybrid"));

class SkippingNothing : public ::testing::TestWithParam<const char*>
{
};

/** Two frames, then: the light is skipped, no pass rendered or reused, no volume. A light
 *  whose view holds no receiver gets no shadow slot at all (lightsShadowed 0); one with
 *  receivers in view but no caster gets a slot and no pass. */
void expectNoShadowPass(ShadowedRender& r, unsigned int lightsShadowed)
{
    r.renderer->timeFrames(0, 2);
    const Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsShadowed, lightsShadowed);
    EXPECT_EQ(s.lightsSkipped, 1u);
    EXPECT_EQ(s.shadowPasses, 0u);
    EXPECT_EQ(s.depthPassesReused, 0u);
    EXPECT_EQ(s.zfailCasters + s.zpassCasters, 0u);
}

TEST_P(SkippingNothing, NoCastersMeansNoShadowPass)
{
    ShadowedRender r("default", GetParam(), MAP_SIZE, 512, 384);
    ASSERT_TRUE(r.valid());
    r.technique->getShadowedScene()->getShadowSettings()->setCastsShadowTraversalMask(0);
    expectNoShadowPass(r, 1u);
}

TEST_P(SkippingNothing, NoReceiversInViewMeansNoShadowPass)
{
    ShadowedRender r("default", GetParam(), MAP_SIZE, 512, 384);
    ASSERT_TRUE(r.valid());
    osshar::View sky = r.scene.view;
    sky.eye = osg::Vec3d(0, 0, 30);
    sky.center = osg::Vec3d(0, 0, 60); // looking straight up, away from everything
    sky.up = osg::Vec3d(0, 1, 0);
    r.renderer->setView(sky);
    expectNoShadowPass(r, 0u);
}

INSTANTIATE_TEST_SUITE_P(Modes, SkippingNothing, ::testing::Values("shadowmap", "silhouette", "hybrid", "volume"));

} // namespace
