// HYBRID's soft shadows (triangle lists under a light with a size, docs/soft-shadows.md)
// against the exact visibility (MEASURE.md, "Soft shadows"): SoftSamples shadow rays per
// penumbra pixel, each walked over every grid texel its path crosses, follow the reference's
// penumbrae for a sun, a point light and a spot light, and converge as the rays grow; a
// penumbra cast by a caster that lies over none of the pixel's own texels is found; a static
// frame renders the same twice; size 0 keeps the hard answer; the stencil method takes the
// lists with a warning; the penumbra pixels and rays reach the statistics and the classes;
// the receivers' own shading (the picture, not only the debug views) is soft.
#include "Classes.h"
#include "Meshes.h"
#include "GLTestSupport.h"
#include "NotifyCapture.h"
#include "SoftLights.h"
#include "Peers.h"

#include <osg/Stats>

namespace {

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

constexpr int W = 512, H = 384;
constexpr unsigned int MAP = 2048;

struct SoftCase
{
    const char* name;
    const char* light; ///< "sun", "point" or "spot"
    double size;       ///< degrees (sun) or scene units
    double bound64;    ///< vis_mae_penumbra bound at 64 rays
    double bound256;   ///< ... at 256 rays
};

/** vis_mae_penumbra bounds: 0.02 at 64 rays, 0.01 at 256; vis_p99_penumbra 0.06 at 64 rays
 *  and 0.05 at 256. Measured 0.0111 / 0.0046 (sun), 0.0114 / 0.0044 (point), 0.0117 / 0.0047
 *  (spot), p99 0.040 / 0.023, 0.040 / 0.016, 0.042 / 0.017; docs/soft-shadows.md. With the
 *  blocker search's footprint that of a disc facing the map's axis (not the point), the point
 *  light's outer rims off its cube faces' axes read lit: 0.0161 / 0.0102, p99 0.121. With the
 *  first pass's answer kept on the pixel's own rays alone (not its quad's), the penumbrae's
 *  edges read lit or shadowed: p99 at 64 rays 0.084, 0.095, 0.103. */
const SoftCase kCases[] = {
    {"Sun2Degrees", "sun", 2.0, 0.02, 0.01},
    {"Point03", "point", 0.3, 0.02, 0.01},
    {"Spot03", "spot", 0.3, 0.02, 0.01},
};

ossref::VisibilityComparison score(ShadowedRender& r, const ossref::VisibilityMask& reference)
{
    const ossref::VisibilityComparison c = ossref::compareVisibility(reference, r.visibility());
    EXPECT_TRUE(c.valid) << c.error;
    return c;
}

/** HYBRID with triangle lists over the scene of @p options, lights of size @p size. */
struct SoftHybrid
{
    ShadowedRender r;
    ossref::VisibilityMask reference;

    SoftHybrid(const osshar::RenderOptions& options, double size, unsigned int map) : r(options, "hybrid", map, W, H)
    {
        if (!r.valid()) return;
        r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
        reference = r.referenceVisibility(0, size);
        r.technique->setLightSize(float(size));
    }
    SoftHybrid(osshar::PreparedScene scene, double size, unsigned int map) : r(std::move(scene), "hybrid", map, W, H)
    {
        if (!r.valid()) return;
        r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
        reference = r.referenceVisibility(0, size);
        r.technique->setLightSize(float(size));
    }

    ossref::VisibilityComparison at(unsigned int rays)
    {
        r.technique->setSoftSamples(rays);
        return score(r, reference);
    }
};

class HybridSoft : public ::testing::TestWithParam<SoftCase>
{
};

TEST_P(HybridSoft, ConvergesToTheExactPenumbra)
{
    const SoftCase& c = GetParam();
    SoftHybrid h(osstest::softLightOptions(c.light), c.size, MAP);
    ASSERT_TRUE(h.r.valid());
    const ossref::VisibilityComparison k64 = h.at(64), k256 = h.at(256);
    std::printf("[ soft     ] hybrid %s: penumbra pixels %lld; vis_mae_penumbra K=64 %.4f, K=256 %.4f; vis_mae %.5f, "
                "%.5f; vis_p99_penumbra %.4f, %.4f; hard_wrong_pct %.4f, %.4f\n",
                c.name, k64.penumbraPixels, k64.visMaePenumbra, k256.visMaePenumbra, k64.visMae, k256.visMae,
                k64.visP99Penumbra, k256.visP99Penumbra, k64.hardWrongPct, k256.hardWrongPct);
    EXPECT_TRUE(h.r.technique->getStatistics().triangleLists);
    EXPECT_GT(k64.penumbraPixels, 500);
    EXPECT_LE(k64.visMaePenumbra, c.bound64);
    EXPECT_LE(k256.visMaePenumbra, c.bound256);
    EXPECT_LE(k64.visP99Penumbra, 0.06) << "the first pass kept an answer the other rays would change";
    EXPECT_LE(k256.visP99Penumbra, 0.05) << "a penumbra's pixels read lit or shadowed";
    EXPECT_LE(k256.hardWrongPct, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Lights, HybridSoft, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<SoftCase>& info) { return info.param.name; });

/** A square plate floating 3 units over the ground under a sun of 3 degrees: its penumbra on
 *  the ground is 0.3 units wide on each side of its shadow's edge, 20 texels of a 512 map, so
 *  that the outer half's rays meet the plate only in texels other than the pixel's own. */
osshar::PreparedScene plateScene()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeGround(0, 0, 16));
    geode->addDrawable(osshar::makeGround(0, 0, 2.5f, 3.0f));
    osshar::PreparedScene scene;
    scene.content = new osg::Group;
    scene.content->addChild(geode.get());
    scene.content->addChild(osshar::makeLight(osg::Vec4(0.3f, -0.2f, 1.0f, 0.0f), 0));
    scene.lights = osshar::findLights(scene.content.get());
    scene.view = {osg::Vec3d(0, -5, 6), osg::Vec3d(0.3, 0.2, 0), osg::Vec3d(0, 0, 1), 40.0};
    return scene;
}

TEST(HybridSoftShadows, FindsCastersBeyondThePixelsOwnTexel)
{
    SoftHybrid h(plateScene(), 3.0, 512);
    ASSERT_TRUE(h.r.valid());
    const ossref::VisibilityComparison c = h.at(64);
    std::printf("[ soft     ] hybrid plate, sun 3 degrees, map 512: penumbra pixels %lld; vis_mae_penumbra %.4f; "
                "vis_p99_penumbra %.4f; vis_mae %.5f\n",
                c.penumbraPixels, c.visMaePenumbra, c.visP99Penumbra, c.visMae);
    // Measured 0.0112 and 0.036; the walk of the pixel's own texel alone: see
    // docs/soft-shadows.md.
    EXPECT_GT(c.penumbraPixels, 3000);
    EXPECT_LE(c.visMaePenumbra, 0.015);
    EXPECT_LE(c.visP99Penumbra, 0.06);
}

/** The poles under a point light of radius 0.1 two units lower than the benchmark's: the
 *  crossbars' long triangles reach from the -x cube face behind its eye plane, and their
 *  ends shade the penumbrae of the poles' shadows there. Listed only where they lay wholly in
 *  front of the eye plane, they were missing from that face's lists, and the rays of those
 *  penumbrae passed through them: 0.0329, vis_p99_penumbra 0.70 (map 512, 64 rays). */
TEST(HybridSoftShadows, ListsTheCastersThatReachBehindACubeFace)
{
    osshar::RenderOptions options;
    options.scene = "poles";
    osshar::LightArg point;
    point.directional = false;
    point.vector = osg::Vec3d(2.0, -4.0, 6.0);
    options.lights.push_back(point);
    SoftHybrid h(options, 0.1, 512);
    ASSERT_TRUE(h.r.valid());
    const ossref::VisibilityComparison c = h.at(64);
    std::printf("[ soft     ] hybrid poles, point 0.1 at (2, -4, 6), map 512: penumbra pixels %lld; vis_mae_penumbra "
                "%.4f; vis_p99_penumbra %.4f\n",
                c.penumbraPixels, c.visMaePenumbra, c.visP99Penumbra);
    // Measured 0.0109 and 0.036.
    EXPECT_GT(c.penumbraPixels, 5000);
    EXPECT_LE(c.visMaePenumbra, 0.015);
    EXPECT_LE(c.visP99Penumbra, 0.06);
}

TEST(HybridSoftShadows, ConvergeAsTheRaysGrow)
{
    SoftHybrid h(osstest::softLightOptions("sun"), 2.0, MAP);
    ASSERT_TRUE(h.r.valid());
    double previous = 1.0;
    for (unsigned int rays : {4u, 16u, 64u, 256u})
    {
        const ossref::VisibilityComparison c = h.at(rays);
        std::printf("[ soft     ] hybrid sun 2 degrees, %u rays: vis_mae_penumbra %.4f\n", rays, c.visMaePenumbra);
        EXPECT_LT(c.visMaePenumbra, 0.75 * previous) << rays << " rays";
        previous = c.visMaePenumbra;
    }
}

TEST(HybridSoftShadows, AStaticFrameRendersTheSameTwice)
{
    SoftHybrid h(osstest::softLightOptions("point"), 0.3, MAP);
    ASSERT_TRUE(h.r.valid());
    h.r.technique->setSoftSamples(16); // few rays: a pattern that changed would show
    const ossref::VisibilityMask first = h.r.visibility(0, 2);
    const ossref::VisibilityMask second = h.r.visibility(0, 3);
    EXPECT_GT(ossref::compareVisibility(h.reference, first).penumbraPixels, 500);
    EXPECT_EQ(first.value, second.value);
}

/** The receivers' own shading, the picture an application shows (not a debug view), casts the
 *  rays too: its luminance over the unshadowed frame's (MEASURE.md's visibility of a technique
 *  without a visibility output) follows the exact penumbra as the visibility view does. The
 *  shading had kept the hard answer: vis_mae_penumbra 0.239 against 0.0106 now (bound 0.02). */
TEST(HybridSoftShadows, TheShadedPictureIsSoft)
{
    SoftHybrid h(osstest::softLightOptions("sun"), 2.0, MAP);
    ASSERT_TRUE(h.r.valid());
    h.r.technique->setSoftSamples(64);
    osshar::applyMeasurementLight(h.r.scene); // one light, no ambient: luminance ratio = visibility
    h.r.root->setStateSet(osshar::measurementStateSet(h.r.scene).get());
    const osshar::PeerMask shaded =
        osshar::renderPeerMask(*h.r.renderer, h.r.root.get(), osshar::makeUnshadowedRoot(h.r.scene).get());
    const ossref::VisibilityComparison picture = ossref::compareVisibility(h.reference, shaded.visibility);
    ASSERT_TRUE(picture.valid) << picture.error;
    const ossref::VisibilityComparison view = h.at(64);
    std::printf("[ soft     ] hybrid shaded picture: vis_mae_penumbra %.4f (visibility view %.4f), penumbra pixels "
                "%lld\n",
                picture.visMaePenumbra, view.visMaePenumbra, picture.penumbraPixels);
    EXPECT_GT(picture.penumbraPixels, 500);
    EXPECT_LE(picture.visMaePenumbra, 0.02);
}

TEST(HybridSoftShadows, SizeZeroKeepsTheHardAnswer)
{
    ShadowedRender r(osstest::softLightOptions("sun"), "hybrid", MAP, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    const ossref::VisibilityMask hard = r.visibility();
    r.technique->setLightSize(2.0f);
    const ossref::VisibilityMask soft = r.visibility();
    r.technique->setLightSize(0.0f);
    EXPECT_NE(soft.value, hard.value);
    EXPECT_EQ(r.visibility().value, hard.value);
}

TEST(HybridSoftShadows, TheStencilMethodTakesTheListsAndWarnsOnce)
{
    ShadowedRender r(osstest::softLightOptions("sun"), "hybrid", MAP, W, H);
    ASSERT_TRUE(r.valid());
    osstest::NotifyCapture capture;
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    r.technique->setLightSize(2.0f);
    const ossref::VisibilityComparison c = score(r, r.referenceVisibility(0, 2.0));
    r.visibility();
    EXPECT_TRUE(r.technique->getStatistics().triangleLists);
    EXPECT_LE(c.visMaePenumbra, 0.02);
    EXPECT_EQ(capture.count("HYBRID_STENCIL_VOLUMES casts hard shadows only"), 1) << capture.warnings();
}

TEST(HybridSoftShadows, StatisticsAndClassesShowThePenumbra)
{
    ShadowedRender r(osstest::softLightOptions("sun"), "hybrid", MAP, W, H);
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::Stats> stats = new osg::Stats("hybrid soft");
    r.technique->setStats(stats.get());
    r.technique->setLightSize(2.0f);
    r.technique->setSoftSamples(32);
    r.renderer->timeFrames(0, 4);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_GT(s.penumbraPixels, 500);
    // The umbra's pixels agree after the first pass of 8 rays; the penumbra's cast all 32.
    EXPECT_GT(s.penumbraAgreed, 100);
    EXPECT_LT(s.penumbraAgreed, s.penumbraPixels - 100);
    EXPECT_EQ(s.shadowRays, 32 * s.penumbraPixels - 24 * s.penumbraAgreed);
    double rays = 0.0;
    EXPECT_TRUE(stats->getAttribute(s.frameNumber, SilhouetteShadowTechnique::STATS_SHADOW_RAYS, rays));
    EXPECT_EQ(rays, double(s.shadowRays));
    // The count is the shaded picture's: a wider light, a wider penumbra, more pixels cast rays
    // (6970 against 6479; the umbra's pixels cast too). It had counted the hard answer's
    // silhouette pixels, 1797 at either size.
    r.technique->setLightSize(0.5f);
    r.renderer->timeFrames(0, 4);
    const long long narrow = r.technique->getStatistics().penumbraPixels;
    std::printf("[ soft     ] hybrid penumbra pixels cast: %lld at 2 degrees, %lld at 0.5\n", s.penumbraPixels, narrow);
    EXPECT_LT(narrow, s.penumbraPixels);
    r.technique->setLightSize(2.0f);
    r.technique->setStats(nullptr);

    osg::ref_ptr<osg::Image> classes = osshar::renderClasses(*r.renderer, *r.technique, 0);
    long long yellow = 0;
    for (int y = 0; y < classes->t(); ++y)
        for (int x = 0; x < classes->s(); ++x)
        {
            const unsigned char* p = classes->data(x, y);
            yellow += p[0] > 200 && p[1] > 200 && p[2] < 50;
        }
    EXPECT_GT(yellow, 500) << "penumbra pixels in the penumbra colour";
    EXPECT_LT(yellow, s.penumbraPixels + 1);
}

} // namespace
