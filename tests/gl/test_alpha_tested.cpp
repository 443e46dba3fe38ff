// Alpha-tested casters (fences, foliage): a texture's alpha and an osg::AlphaFunc cut the
// caster's shape out of the shadow maps exactly where the eye pass cuts it out of the
// picture, and the exact reference (ossref: an Embree filter that samples the same texture)
// agrees, for primary rays (what the eye sees through the holes) and shadow rays alike.
// Scene: the built-in "foliage" (a fence panel with diamond holes, two crossed cards of
// leaves, an opaque box), 512x384. Stencil volumes cannot cut a shape out: SHADOW_VOLUME
// warns, naming them, and casts the whole triangles. HYBRID's triangle lists keep the depth
// map's answer where only cut-out triangles cover a point; its stencil volumes take them as
// opaque; it warns either way (bounds and measurements: ModeBounds.h, ALPHA_TESTED).
#include "GLTestSupport.h"
#include "ModeBounds.h"
#include "NotifyCapture.h"

#include <osg/StateSet>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

struct CutoutCase
{
    const char* name;
    const char* mode;
    bool point;          ///< a point light above the casters instead of the scene's sun
    bool stencil = false; ///< HYBRID by its stencil volumes instead of its triangle lists
};

constexpr unsigned int MAP_SIZE = 2048;

osshar::RenderOptions optionsFor(const CutoutCase& c)
{
    osshar::RenderOptions o;
    o.scene = "foliage";
    if (c.point)
    {
        osshar::LightArg light;
        light.directional = false;
        light.vector = osg::Vec3d(1.0, -6.0, 8.0);
        o.lights.push_back(light);
    }
    return o;
}

/** Pixels the reference sees lit with the cut-outs and shadowed when the casters are taken
 *  as opaque (GL_ALPHA_TEST forced off): the light through the holes. */
long long lightThroughHoles(ShadowedRender& r, const ossref::Mask& reference)
{
    osg::StateSet* ss = r.scene.content->getOrCreateStateSet();
    ss->setMode(GL_ALPHA_TEST, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    const ossref::Mask opaque = r.reference();
    ss->removeMode(GL_ALPHA_TEST);
    long long through = 0;
    for (std::size_t i = 0; i < reference.value.size() && i < opaque.value.size(); ++i)
        through += reference.value[i] == ossref::MASK_LIT && opaque.value[i] == ossref::MASK_NO_LIGHT;
    return through;
}

class AlphaTested : public ::testing::TestWithParam<CutoutCase>
{
};

} // namespace

TEST_P(AlphaTested, CastsTheCutOutShape)
{
    const CutoutCase& c = GetParam();
    osstest::NotifyCapture capture;
    ShadowedRender r(optionsFor(c), c.mode, MAP_SIZE, 512, 384);
    ASSERT_TRUE(r.valid());
    if (c.stencil) r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    const ossref::Mask mask = r.mask(0, 3);
    const ossref::Mask reference = r.reference();
    const ossref::Comparison score = ossref::compareMasks(mask, reference);
    ASSERT_TRUE(score.valid) << score.error;
    std::cout << c.name << ": wrong_pct " << score.wrongPct << " (" << score.wrongPixels << " pixels)\n";

    // The scene means something: light reaches the ground through the holes.
    EXPECT_GT(lightThroughHoles(r, reference), 500);
    // The eye sees through the holes where the reference's primary rays pass.
    EXPECT_EQ(score.coverageMismatch, 0);
    if (std::string(c.mode) == "volume")
    {
        // Known limitation, warned about: the volumes of the whole triangles, so the fence's
        // and the leaves' shadows have no holes (measured 2.29%). A fix lands here.
        EXPECT_GT(score.wrongPct, 1.5) << "SHADOW_VOLUME now cuts the shapes out: bound it by its claim";
        EXPECT_LT(score.wrongPct, 3.0);
    }
    else if (c.stencil)
    {
        // Known limitation, warned about: HYBRID's stencil volumes take the cut-out triangles
        // as opaque at the silhouette pixels of their shadows (measured 0.127%); the shadow
        // map cuts them everywhere else (1.5% and more when it does not either).
        EXPECT_LT(score.wrongPct, 0.2) << c.name << ": " << score.wrongPixels << " wrong pixels";
    }
    else
    {
        EXPECT_LT(score.wrongPct, osstest::bounds::ALPHA_TESTED.of(c.mode))
            << c.name << ": " << score.wrongPixels << " wrong pixels";
    }

    // SHADOW_VOLUME and HYBRID name the three cut-out drawables in one warning, once however
    // many frames are drawn; the map modes cut them and say nothing.
    const bool warns = std::string(c.mode) == "volume" || std::string(c.mode) == "hybrid";
    EXPECT_EQ(capture.count("3 drawables are alpha-tested (GL_ALPHA_TEST): 'fence', 'leaves 1', 'leaves 2';"),
              warns ? 1 : 0)
        << capture.warnings();
    EXPECT_EQ(capture.count("alpha-tested"), warns ? 1 : 0) << capture.warnings();
}

INSTANTIATE_TEST_SUITE_P(
    Modes, AlphaTested,
    ::testing::Values(CutoutCase{"shadowmap_sun", "shadowmap", false}, CutoutCase{"shadowmap_point", "shadowmap", true},
                      CutoutCase{"silhouette_sun", "silhouette", false},
                      CutoutCase{"silhouette_point", "silhouette", true}, CutoutCase{"hybrid_sun", "hybrid", false},
                      CutoutCase{"hybrid_point", "hybrid", true}, CutoutCase{"hybrid_stencil_sun", "hybrid", false, true},
                      CutoutCase{"volume_sun", "volume", false}),
    [](const ::testing::TestParamInfo<CutoutCase>& info) { return std::string(info.param.name); });
