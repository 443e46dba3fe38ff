// SHADOW_MAP's soft filters (property Filter, docs/soft-shadows.md) against the exact
// visibility of lights with a size (MEASURE.md, "Soft shadows"): PCSS follows the reference's
// penumbrae for a sun, a point light and a spot light; FILTER_PCF widens the filtered band by
// its window; size 0 and a 1 x 1 window are the 2x2 baseline; a light's own size wins over
// the technique's; refused sizes and modes without filters warn and stay hard. SILHOUETTE_MAP's
// FILTER_SILHOUETTE (Valient and Bujnak 2005) anti-aliases its edges at size 0 and follows the
// same penumbrae.
#include "Classes.h"
#include "GLTestSupport.h"
#include "ModeBounds.h"
#include "NotifyCapture.h"
#include "SoftLights.h"

#include <osg/LightSource>
#include <osg/ValueObject>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

constexpr int W = 512, H = 384;
constexpr unsigned int MAP = 2048;
/** FILTER_SILHOUETTE keeps SILHOUETTE_MAP's hard answer (ModeBounds.h). */
constexpr double SILHOUETTE_HARD_BOUND = osstest::bounds::CLAIMED.silhouette;
/** FILTER_SILHOUETTE on the poles under a 3-degree sun: measured 0.055 (PCSS 0.122); with one
 *  sample across the nearest edge instead of seven, 0.087. */
constexpr double SILHOUETTE_THIN_CASTER_BOUND = 0.065;

struct SoftCase
{
    const char* name;
    const char* light; ///< "sun", "point" or "spot"
    double size;       ///< degrees (sun) or scene units
    /** PCSS's vis_mae_penumbra bound: measured 0.043 (sun), 0.041 (point), 0.039 (spot); the
     *  2x2 baseline measures 0.21-0.22, and PCSS with its penumbra estimate removed too. */
    double penumbraBound;
};

const SoftCase kCases[] = {
    {"Sun2Degrees", "sun", 2.0, 0.06},
    {"Point03", "point", 0.3, 0.06},
    {"Spot03", "spot", 0.3, 0.06},
};

ossref::VisibilityComparison score(ShadowedRender& r, const ossref::VisibilityMask& reference)
{
    const ossref::VisibilityComparison c = ossref::compareVisibility(reference, r.visibility());
    EXPECT_TRUE(c.valid) << c.error;
    return c;
}

/** Pixels whose visibility lies strictly inside (0.02, 0.98): the filtered band. */
long long fractionalPixels(const ossref::VisibilityMask& m)
{
    long long n = 0;
    for (uint16_t v : m.value)
        if (v != ossref::VIS_BACKGROUND)
        {
            const double f = ossref::decodeVisibility(v);
            n += f > 0.02 && f < 0.98;
        }
    return n;
}

/** Case @p c rendered in @p mode, scored against the exact visibility without a filter
 *  (first) and under @p filter (second), both printed. */
std::pair<ossref::VisibilityComparison, ossref::VisibilityComparison>
hardAndFiltered(const SoftCase& c, const char* mode, SilhouetteShadowTechnique::Filter filter)
{
    ShadowedRender r(osstest::softLightOptions(c.light), mode, MAP, W, H);
    EXPECT_TRUE(r.valid());
    if (!r.valid()) return {};
    const ossref::VisibilityMask reference = r.referenceVisibility(0, c.size);
    r.technique->setLightSize(float(c.size));
    const ossref::VisibilityComparison hard = score(r, reference);
    r.technique->setFilter(filter);
    const ossref::VisibilityComparison soft = score(r, reference);
    std::printf("[ soft     ] %s %s: penumbra pixels %lld; vis_mae_penumbra hard %.4f, filter %d %.4f; "
                "vis_mae %.5f, %.5f; hard_wrong_pct %.4f, %.4f\n",
                mode, c.name, soft.penumbraPixels, hard.visMaePenumbra, int(filter), soft.visMaePenumbra, hard.visMae,
                soft.visMae, hard.hardWrongPct, soft.hardWrongPct);
    return {hard, soft};
}

class SoftFilter : public ::testing::TestWithParam<SoftCase>
{
};

TEST_P(SoftFilter, PcssFollowsTheExactPenumbra)
{
    const SoftCase& c = GetParam();
    const auto [hard, pcss] = hardAndFiltered(c, "shadowmap", SilhouetteShadowTechnique::FILTER_PCSS);
    EXPECT_GT(pcss.penumbraPixels, 500); // the light's size makes penumbrae to score
    EXPECT_LE(pcss.visMaePenumbra, c.penumbraBound);
    EXPECT_LT(pcss.visMaePenumbra, 0.35 * hard.visMaePenumbra);
    EXPECT_LE(pcss.visMae, 0.5 * hard.visMae);
    EXPECT_LE(pcss.hardWrongPct, 0.15); // SHADOW_MAP's hard bound (ModeBounds.h)
}

INSTANTIATE_TEST_SUITE_P(Lights, SoftFilter, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<SoftCase>& info) { return info.param.name; });

/** FILTER_SILHOUETTE's vis_mae_penumbra bounds: measured 0.0069 (sun), 0.0330 (point),
 *  0.0190 (spot). Broken, it fails: one sample across the nearest edge instead of seven 0.0110
 *  (sun); the distances' sign flipped 0.144 / 0.149 / 0.139; a linear ramp instead of the
 *  disc's F 0.0114 (sun; the point and spot lights' 0.031 and 0.018 pass: across seven samples
 *  the profile matters less than the band's cap and the cube faces, and a ramp is as close). */
const SoftCase kSilhouetteCases[] = {
    {"Sun2Degrees", "sun", 2.0, 0.009},
    {"Point03", "point", 0.3, 0.036},
    {"Spot03", "spot", 0.3, 0.022},
};

class SilhouetteFilter : public ::testing::TestWithParam<SoftCase>
{
};

TEST_P(SilhouetteFilter, FollowsTheExactPenumbra)
{
    const SoftCase& c = GetParam();
    const auto [hard, soft] = hardAndFiltered(c, "silhouette", SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    EXPECT_GT(soft.penumbraPixels, 500);
    EXPECT_LE(soft.visMaePenumbra, c.penumbraBound);
    EXPECT_LE(soft.visMae, 0.5 * hard.visMae);
    EXPECT_LE(soft.hardWrongPct, SILHOUETTE_HARD_BOUND);
}

INSTANTIATE_TEST_SUITE_P(Lights, SilhouetteFilter, ::testing::ValuesIn(kSilhouetteCases),
                         [](const ::testing::TestParamInfo<SoftCase>& info) { return info.param.name; });

// The debug views under FILTER_SILHOUETTE: the classes mark the pixels whose answer is a
// visible fraction, about as many as the exact penumbra's (measured 1838 against 1264; any
// fraction, 0 < v < 1, marked 2679: rounding scattered some 840 over the lit ground);
// DEBUG_SILHOUETTE_MAP shows the distance band along the shadows' edges, not the whole ground.
TEST(SoftFilters, SilhouetteFilterDebugViewsShowFractionsAndDistances)
{
    ShadowedRender r("default", "silhouette", MAP, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::VisibilityMask reference = r.referenceVisibility(0, 2.0);
    const long long penumbra = ossref::compareVisibility(reference, reference).penumbraPixels;
    r.technique->setLightSize(2.0f);
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    const osshar::ClassCounts classes = osshar::countClasses(*osshar::renderClasses(*r.renderer, *r.technique, 0));
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
    osg::ref_ptr<osg::Image> plain = r.renderer->renderAndCapture();
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SILHOUETTE_MAP);
    osg::ref_ptr<osg::Image> distances = r.renderer->renderAndCapture();
    long long overlaid = 0;
    for (int y = 0; y < plain->t(); ++y)
        for (int x = 0; x < plain->s(); ++x) overlaid += std::memcmp(plain->data(x, y), distances->data(x, y), 3) != 0;
    std::printf("[ soft     ] debug views: %lld fractional pixels (exact penumbra %lld), %lld of %lld under the "
                "distance overlay\n",
                classes.silhouette(), penumbra, overlaid, classes.geometry);
    EXPECT_EQ(classes.other, 0);
    EXPECT_GT(classes.silhouette(), penumbra / 2);
    EXPECT_LT(classes.silhouette(), 7 * penumbra / 4);
    EXPECT_GT(overlaid, penumbra / 2);
    EXPECT_LT(overlaid, classes.geometry / 5);
}

TEST(SoftFilters, SilhouetteFilterAntiAliasesHardEdges)
{
    ShadowedRender r("default", "silhouette", MAP, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::VisibilityMask reference = r.referenceVisibility(0, 0.0); // 4 x 4 rays per pixel
    const ossref::VisibilityComparison hard = score(r, reference);
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    const ossref::VisibilityComparison aa = score(r, reference);
    std::printf("[ soft     ] silhouette size 0: penumbra pixels %lld; vis_mae_penumbra hard %.4f, filter %.4f; "
                "hard_wrong_pct %.4f, %.4f\n",
                aa.penumbraPixels, hard.visMaePenumbra, aa.visMaePenumbra, hard.hardWrongPct, aa.hardWrongPct);
    EXPECT_GT(aa.penumbraPixels, 200); // the reference's anti-aliased edge pixels
    // Measured 0.186 where the hard answer is 0.264 (the sign flipped: 0.282): most of what
    // remains are pixels across the eye's own geometric edges (a caster's side against its
    // shadow, a faceted sphere's terminator), which no shadow term can anti-alias.
    EXPECT_LE(aa.visMaePenumbra, 0.2);
    EXPECT_LT(aa.visMaePenumbra, 0.75 * hard.visMaePenumbra);
    EXPECT_LE(aa.hardWrongPct, SILHOUETTE_HARD_BOUND);
    // Thresholded at one half, the filtered edge is the silhouette map's (0.0342% both; the
    // nearest texel's distance instead of the bilinear one: 0.0456%).
    EXPECT_LE(aa.hardWrongPct, hard.hardWrongPct + 0.005);
}

// The cubes scene: a thousand casters, most in each other's shadows, where the nearest edge
// of a texel often belongs to a caster behind the point. Such an edge cannot shadow the point
// and the depth map must answer (a caster nearer the light may): when the filter took the
// point for lit instead, 3.70% of the pixels were wrong (light leaking into shadows); with the
// depth map's 2x2 comparison there instead of its all-four-blocked test, the point light
// case's hard_wrong_pct rose from 0.010% to 0.069% (caster faces beside their own rims).
TEST(SoftFilters, SilhouetteFilterKeepsOtherCastersShadows)
{
    ShadowedRender r("cubes", "silhouette", MAP, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::VisibilityMask reference = r.referenceVisibility(0, 1.0);
    r.technique->setLightSize(1.0f);
    const ossref::VisibilityComparison hard = score(r, reference);
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    const ossref::VisibilityComparison soft = score(r, reference);
    const ossref::Comparison mask = ossref::compareMasks(r.mask(), r.reference());
    std::printf("[ soft     ] cubes, sun 1 degree: vis_mae_penumbra hard %.4f, filter %.4f; vis_mae %.5f, %.5f; "
                "mask wrong_pct %.4f\n",
                hard.visMaePenumbra, soft.visMaePenumbra, hard.visMae, soft.visMae, mask.wrongPct);
    // Measured 0.33% (the hard silhouette map 0.019%; against the sized light's exact
    // visibility thresholded at one half: 0.27%) and 0.102 against 0.233.
    EXPECT_LE(mask.wrongPct, 0.5);
    EXPECT_LE(soft.hardWrongPct, 0.3);
    EXPECT_LT(soft.visMaePenumbra, 0.6 * hard.visMaePenumbra);
}

// The poles scene under a sun of 3 degrees: poles thinner than their penumbrae, whose shadows
// have no umbra. Across the nearest edge alone (one sample) a pole's shadow is a half-plane's,
// too dark and too wide; the samples around the point see its other side.
TEST(SoftFilters, SilhouetteFilterSeesBothSidesOfThinCasters)
{
    ShadowedRender r("poles", "silhouette", MAP, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::VisibilityMask reference = r.referenceVisibility(0, 3.0);
    r.technique->setLightSize(3.0f);
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    const ossref::VisibilityComparison soft = score(r, reference);
    r.technique->setMode(SilhouetteShadowTechnique::SHADOW_MAP);
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_PCSS);
    const ossref::VisibilityComparison pcss = score(r, reference);
    std::printf("[ soft     ] poles, sun 3 degrees: penumbra pixels %lld; vis_mae_penumbra %.4f (PCSS %.4f); "
                "hard_wrong_pct %.4f\n",
                soft.penumbraPixels, soft.visMaePenumbra, pcss.visMaePenumbra, soft.hardWrongPct);
    EXPECT_GT(soft.penumbraPixels, 5000);
    EXPECT_LE(soft.visMaePenumbra, SILHOUETTE_THIN_CASTER_BOUND);
    EXPECT_LT(soft.visMaePenumbra, pcss.visMaePenumbra);
}

TEST(SoftFilters, SizeZeroAndAOneTexelWindowAreTheBaseline)
{
    ShadowedRender r("default", "shadowmap", MAP, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask reference = r.reference();
    const ossref::Comparison baseline = ossref::compareMasks(r.mask(), reference);
    for (SilhouetteShadowTechnique::Filter filter :
         {SilhouetteShadowTechnique::FILTER_PCSS, SilhouetteShadowTechnique::FILTER_PCF})
    {
        r.technique->setFilter(filter);
        r.technique->setFilterWindow(1);
        const ossref::Comparison c = ossref::compareMasks(r.mask(), reference);
        std::printf("[ soft     ] filter %d at size 0 / window 1: %lld wrong pixels (2x2 PCF: %lld)\n", int(filter),
                    c.wrongPixels, baseline.wrongPixels);
        // The same 2x2 PCF, its comparisons made in the shader (against the receiver's plane)
        // instead of by the texture unit: a few pixels apart along the edges.
        EXPECT_LE(std::llabs(c.wrongPixels - baseline.wrongPixels), 20 + baseline.wrongPixels / 2);
        EXPECT_LE(c.wrongPct, 0.15);
    }
}

TEST(SoftFilters, ThePcfWindowWidensTheFilteredBand)
{
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_PCF);
    r.technique->setFilterWindow(1);
    const long long one = fractionalPixels(r.visibility());
    r.technique->setFilterWindow(7);
    const long long seven = fractionalPixels(r.visibility());
    const ossref::Comparison hard = ossref::compareMasks(r.mask(), r.reference());
    std::printf("[ soft     ] fractional pixels: window 1 %lld, window 7 %lld; window 7 hard wrong_pct %.4f\n", one,
                seven, hard.wrongPct);
    // The band is about N texels wide: seven texels are more than four times one texel's
    // 1 to 2 (less where the edge meets another shadow).
    EXPECT_GT(seven, 4 * one);
    EXPECT_LE(hard.wrongPct, 0.3); // a blurred hard edge still crosses 0.5 at the edge
}

TEST(SoftFilters, ALightsOwnSizeWins)
{
    ShadowedRender r("default", "shadowmap", MAP, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_PCSS);
    r.technique->setLightSize(2.0f);
    const ossref::VisibilityMask technique = r.visibility();
    r.technique->setLightSize(0.0f);
    const ossref::VisibilityMask hard = r.visibility();
    osg::Light* light = r.scene.lights.at(0).source->getLight();
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 2.0f);
    const ossref::VisibilityMask own = r.visibility();
    EXPECT_EQ(own.value, technique.value) << "a size of 2 on the osg::Light renders as LightSize 2";
    EXPECT_NE(own.value, hard.value);

    // On the LightSource (found by init()), as a double.
    light->getUserDataContainer()->removeUserObject(
        light->getUserDataContainer()->getUserObjectIndex(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE));
    r.scene.lights.at(0).source->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 2.0);
    r.technique->dirty();
    EXPECT_EQ(r.visibility(0, 3).value, technique.value) << "a size of 2 on the LightSource renders as LightSize 2";

    // A size no sun can have: a warning naming it, and the hard shadow.
    osstest::NotifyCapture capture;
    r.scene.lights.at(0).source->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 60.0);
    EXPECT_EQ(r.visibility().value, hard.value);
    EXPECT_TRUE(capture.warned("60 degrees is no directional light's angular radius")) << capture.warnings();
    EXPECT_TRUE(capture.warned("casts a hard shadow")) << capture.warnings();
}

TEST(SoftFilters, OtherModesWarnAndStayHard)
{
    ShadowedRender r("default", "silhouette", MAP, W, H);
    ASSERT_TRUE(r.valid());
    osstest::NotifyCapture capture;
    r.technique->setFilter(SilhouetteShadowTechnique::FILTER_PCSS);
    r.technique->setLightSize(2.0f);
    const ossref::VisibilityMask v = r.visibility();
    EXPECT_EQ(fractionalPixels(v), 0);
    EXPECT_TRUE(capture.warned("applies to SHADOW_MAP only")) << capture.warnings();
    EXPECT_EQ(capture.count("applies to SHADOW_MAP only"), 1);

    // FILTER_SILHOUETTE is SILHOUETTE_MAP's: SHADOW_MAP warns and keeps its 2x2 PCF.
    ShadowedRender m("default", "shadowmap", MAP, W, H);
    ASSERT_TRUE(m.valid());
    const ossref::VisibilityMask baseline = m.visibility();
    m.technique->setFilter(SilhouetteShadowTechnique::FILTER_SILHOUETTE);
    m.technique->setLightSize(2.0f);
    EXPECT_EQ(m.visibility().value, baseline.value);
    EXPECT_TRUE(capture.warned("applies to SILHOUETTE_MAP only")) << capture.warnings();
}

} // namespace
