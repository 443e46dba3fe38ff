// The statistics and debug views of the stencil modes (Chan and Durand 2004; HYBRID with
// HYBRID_STENCIL_VOLUMES):
//  - DEBUG_CLASSES paints every geometry pixel in one of four colours that agree with the
//    shadow mask (green/red lit, black/blue shadowed);
//  - the GPU count of HYBRID's silhouette pixels equals the silhouette pixels of that view;
//  - blocker culling skips the volumes of casters hidden from the light without changing
//    the picture at map sizes where no gap between casters is thinner than a texel, and the
//    volumes then shade fewer fragments;
//  - the statistics reach an osg::Stats (what osgViewer's StatsHandler reads).
#include "Classes.h"
#include "GLTestSupport.h"

#include <osgShadowSilhouette/StatsHandlerLines>

#include <osg/Stats>
#include <osgViewer/Viewer>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::ShadowedRender;

constexpr int W = 512, H = 384;

/** Renders enough frames for the GPU counters (read back a frame or two late) to report. */
void settle(ShadowedRender& r)
{
    r.renderer->timeFrames(0, 4);
}

/** Per pixel: the classes image and the mask agree on lit / shadowed. Returns the share of
 *  geometry pixels where they disagree, in percent. */
double classMaskDisagreement(const osg::Image& classes, const ossref::Mask& mask)
{
    long long geometry = 0, disagree = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
        {
            const unsigned char m = mask.atGL(x, y); // image rows start at the bottom
            if (m == ossref::MASK_BACKGROUND) continue;
            ++geometry;
            const unsigned char* p = classes.data(x, y);
            const bool lit = p[1] > 128 || p[0] > 128; // green or red
            disagree += lit != (m == ossref::MASK_LIT) ? 1 : 0;
        }
    return geometry ? 100.0 * double(disagree) / double(geometry) : 100.0;
}

class ClassesView : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ClassesView, AgreesWithTheShadowMask)
{
    ShadowedRender r("default", GetParam(), 512, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask mask = r.mask();
    osg::ref_ptr<osg::Image> classes = osshar::renderClasses(*r.renderer, *r.technique, 0);
    const osshar::ClassCounts c = osshar::countClasses(*classes);
    EXPECT_EQ(c.other, 0) << "pixels in none of the four class colours";
    EXPECT_GT(c.geometry, W * H / 4);
    EXPECT_LT(classMaskDisagreement(*classes, mask), 0.02);
    const std::string mode = GetParam();
    if (mode == "volume")
    {
        EXPECT_EQ(c.mapLit + c.mapShadow, 0) << "every pixel is answered by the volumes";
    }
    else
    {
        EXPECT_GT(c.mapLit, 0);
        EXPECT_GT(c.mapShadow, 0);
        EXPECT_GT(c.silhouette(), 0);
        EXPECT_LT(c.silhouettePercent(), 20.0) << "silhouette pixels are the exception";
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, ClassesView, ::testing::Values("shadowmap", "silhouette", "hybrid", "volume"));

// A point light amid its casters ("ring": cube faces all around) in the map modes: each pixel's
// class is that of the face whose own directions hold it, so the view agrees with the mask
// everywhere, not only in the first face's directions.
class ClassesViewOfCubeFaces : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ClassesViewOfCubeFaces, AgreesWithTheShadowMask)
{
    osshar::RenderOptions options;
    options.scene = "ring";
    options.lights.push_back({false, osg::Vec3d(0.0, 0.0, 1.6)});
    ShadowedRender r(options, GetParam(), 512, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask mask = r.mask();
    ASSERT_GT(r.technique->getStatistics().shadowPasses, 1u) << "the light should have cube faces";
    osg::ref_ptr<osg::Image> classes = osshar::renderClasses(*r.renderer, *r.technique, 0);
    const osshar::ClassCounts c = osshar::countClasses(*classes);
    EXPECT_EQ(c.other, 0) << "pixels in none of the four class colours";
    EXPECT_GT(c.mapShadow, 0);
    EXPECT_LT(classMaskDisagreement(*classes, mask), 0.02);
}

INSTANTIATE_TEST_SUITE_P(Modes, ClassesViewOfCubeFaces, ::testing::Values("shadowmap", "silhouette", "hybrid"));

class SilhouettePixelCount : public ::testing::TestWithParam<SilhouetteShadowTechnique::HybridMethod>
{
};

// Stencil volumes count the mask pass's samples; triangle lists (the default where the
// context has GL 4.3) count the fragments they resolve exactly, while a stats target is set.
TEST_P(SilhouettePixelCount, MatchesTheClassesView)
{
    ShadowedRender r("default", "hybrid", 512, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(GetParam());
    osg::ref_ptr<osg::Stats> stats = new osg::Stats("viewer");
    r.technique->setStats(stats.get());
    settle(r);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    ASSERT_GE(s.silhouettePixels, 0) << "no GPU count";
    EXPECT_EQ(s.viewportPixels, unsigned(W * H));
    const osshar::ClassCounts c = osshar::countClasses(*osshar::renderClasses(*r.renderer, *r.technique, 0));
    ASSERT_GT(c.silhouette(), 0);
    EXPECT_NEAR(double(s.silhouettePixels), double(c.silhouette()), 0.005 * c.silhouette() + 2);
    EXPECT_NEAR(s.silhouettePixelPercent(), 100.0 * c.silhouette() / (W * H), 0.05);
    r.technique->setStats(nullptr);
}

INSTANTIATE_TEST_SUITE_P(Methods, SilhouettePixelCount,
                         ::testing::Values(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES,
                                           SilhouetteShadowTechnique::HYBRID_AUTO),
                         [](const ::testing::TestParamInfo<SilhouetteShadowTechnique::HybridMethod>& info) {
                             return std::string(info.param == SilhouetteShadowTechnique::HYBRID_AUTO ? "Auto"
                                                                                                    : "StencilVolumes");
                         });

TEST(HybridStatistics, TriangleListsCountOnlyForAStatsTarget)
{
    ShadowedRender r("default", "hybrid", 512, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    settle(r);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    ASSERT_TRUE(s.triangleLists);
    EXPECT_EQ(s.silhouettePixels, -1) << "no counter in the eye pass unless statistics are recorded";
}

TEST(HybridStatistics, BlockerCullingSkipsHiddenCastersAndKeepsThePicture)
{
    ShadowedRender r("cubes", "hybrid", 1024, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES); // the mask pass is counted
    r.technique->setHybridEdgeMask(false); // culling is for the PCF test alone (below)
    r.technique->setBlockerCulling(false);
    const ossref::Mask without = r.mask(0, 4);
    const SilhouetteShadowTechnique::Statistics off = r.technique->getStatistics();
    EXPECT_EQ(off.blockersTested, 0u);
    EXPECT_EQ(off.blockersSkipped, 0u);

    r.technique->setBlockerCulling(true);
    settle(r);
    const SilhouetteShadowTechnique::Statistics on = r.technique->getStatistics();
    const ossref::Mask with = r.mask(0, 1);
    EXPECT_EQ(on.blockersTested, on.silhouetteCasters) << "one query per caster";
    EXPECT_GT(on.blockersSkipped, on.blockersTested / 20) << "the cubes hide each other from the light";
    EXPECT_LT(on.blockersSkipped, on.blockersTested);
    if (on.volumeFragments >= 0 && off.volumeFragments >= 0)
    {
        EXPECT_LT(on.volumeFragments, off.volumeFragments) << "skipped volumes shade no fragments";
    }

    const ossref::Comparison c = ossref::compareMasks(with, without);
    ASSERT_TRUE(c.valid) << c.error;
    EXPECT_LE(c.wrongPct, 0.005) << "skipping hidden casters must not change the shadows";

    // With the edge mask no caster is skipped: one seen only through gaps thinner than a
    // texel still shadows what the mask sends to the volumes.
    r.technique->setHybridEdgeMask(true);
    settle(r);
    EXPECT_EQ(r.technique->getStatistics().blockersTested, 0u);
    EXPECT_EQ(r.technique->getStatistics().blockersSkipped, 0u);
}

TEST(HybridStatistics, StatisticsReachAnOsgStats)
{
    ShadowedRender r("cubes", "hybrid", 512, W, H);
    ASSERT_TRUE(r.valid());
    // The default method (triangle lists here): the line osgViewer shows for it is not blank.
    osg::ref_ptr<osg::Stats> stats = new osg::Stats("viewer");
    r.technique->setStats(stats.get());
    settle(r);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    double percent = -1.0, overdraw = -1.0, skipped = -1.0;
    ASSERT_TRUE(stats->getAttribute(s.frameNumber, SilhouetteShadowTechnique::STATS_SILHOUETTE_PIXEL_PERCENT, percent));
    EXPECT_GT(percent, 0.0);
    EXPECT_LT(percent, 100.0);
    EXPECT_NEAR(percent, s.silhouettePixelPercent(), 1e-9);
    ASSERT_TRUE(stats->getAttribute(s.frameNumber, SilhouetteShadowTechnique::STATS_BLOCKERS_SKIPPED, skipped));
    EXPECT_EQ(skipped, double(s.blockersSkipped));
    if (s.volumeFragments >= 0)
    {
        ASSERT_TRUE(stats->getAttribute(s.frameNumber, SilhouetteShadowTechnique::STATS_VOLUME_OVERDRAW, overdraw));
        EXPECT_GT(overdraw, 1.0) << "the cubes' volumes overlap many times";
    }
    r.technique->setStats(nullptr);
}

TEST(HybridStatistics, StatsHandlerLinesRecordIntoTheViewerStats)
{
    osgViewer::Viewer viewer;
    osg::ref_ptr<osgViewer::StatsHandler> handler = new osgViewer::StatsHandler;
    osg::ref_ptr<SilhouetteShadowTechnique> technique = new SilhouetteShadowTechnique;
    osgShadowSilhouette::addStatsLines(viewer, *handler, *technique);
    EXPECT_EQ(technique->getStats(), viewer.getViewerStats());
}

TEST(HybridStatistics, ShadowVolumeCountsItsFragmentsAndMarksNoSilhouettePixels)
{
    ShadowedRender r("cubes", "volume", 512, W, H);
    ASSERT_TRUE(r.valid());
    settle(r);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.silhouettePixels, -1);
    EXPECT_EQ(s.blockersTested, 0u) << "no depth map to test against";
    if (s.volumeFragments < 0) GTEST_SKIP() << "the driver has no pipeline-statistics query";
    EXPECT_GT(s.volumeOverdraw(), 1.0);
}

} // namespace
