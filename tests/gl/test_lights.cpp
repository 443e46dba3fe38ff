// Several lights of each type (directional, spot, point) in every mode, each light's mask
// against the exact ray-cast reference (MEASURE.md); the light budget and its warning; lights
// that cannot affect the view skipped. 256x192 images keep the suite fast.
#include "GLTestSupport.h"
#include "Meshes.h"
#include "NotifyCapture.h"

#include <osg/LightSource>
#include <osg/Material>
#include <osg/Notify>
#include <osgShadow/ShadowSettings>

#include <cmath>
#include <iostream>

using osstest::glVersionText;
using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

constexpr int W = 256, H = 192;

enum class LightType { DIRECTIONAL, SPOT, POINT };

const char* typeName(LightType t)
{
    return t == LightType::DIRECTIONAL ? "directional" : t == LightType::SPOT ? "spot" : "point";
}

/** Light i of a type, placed around the default scene (ground 24 x 24 at z = 0, casters in
 *  the middle); spots aim at the middle with cones that end on the visible ground. */
osshar::LightArg lightArg(LightType type, int i)
{
    static const osg::Vec3d directions[] = {
        {0.45, -0.35, 0.82}, {-0.5, -0.4, 0.77}, {0.3, 0.5, 0.81}, {-0.35, 0.45, 0.82}, {0.6, 0.1, 0.79}};
    static const osg::Vec3d positions[] = {
        {5.0, -4.0, 9.0}, {-6.0, -2.6, 10.0}, {3.0, 6.0, 9.0}, {-4.0, 5.0, 11.0}, {7.0, 2.0, 10.0}};
    osshar::LightArg a;
    a.directional = type == LightType::DIRECTIONAL;
    a.vector = a.directional ? directions[i] : positions[i];
    if (type == LightType::SPOT)
    {
        a.spotDirection = osg::Vec3d(0.0, 0.0, 0.5) - a.vector;
        a.spotCutoff = 32.0 + 2.0 * i;
    }
    return a;
}

osshar::RenderOptions optionsWith(LightType type, int count)
{
    osshar::RenderOptions o;
    o.scene = "default";
    for (int i = 0; i < count; ++i) o.lights.push_back(lightArg(type, i));
    return o;
}

ossref::Comparison compare(ShadowedRender& r, unsigned int light)
{
    const ossref::Comparison c = ossref::compareMasks(r.mask(light), r.reference(light));
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.coverageMismatch, 10) << "the mask and the reference disagree on where geometry is";
    return c;
}

struct ModeBound
{
    const char* mode;
    unsigned int mapSize;
    /** Per light type (directional, spot, point): the bound of the mode's single-light tests
     *  where the light's single-light error stays under it; otherwise the single-light error
     *  of the type measured here (256x192) with a margin. */
    double boundPct[3];

    double ringBoundPct; ///< the point light amid its casters (cube faces in the map modes)

    double bound(LightType t) const { return boundPct[int(t)]; }
};

// Measured, largest over the lights of 1, 2, 3 and 5 (the point column: the first light's,
// alone or not): shadowmap 0.070 / 0.054 / 0.169, silhouette 0.003 / 0.008 / 0.075, hybrid
// 0.003 / 0.003 / 0.003, volume 0.003 / 0.005 / 0.005. The point lights over this scene see
// it over more than 120 degrees and get cube faces; in SHADOW_MAP (one texture unit per slot:
// 24 slots) all five lights' faces fit, in the other modes (12 slots) the later lights keep one
// wide perspective map, whose error stays under the first light's with faces. The point light
// amid its casters ("ring", cube faces): shadowmap 0.088, silhouette 0.035, hybrid 0.035,
// volume 0.
const ModeBound MODES[] = {{"shadowmap", 1024, {0.15, 0.15, 0.2}, 0.15},
                           {"silhouette", 512, {0.02, 0.02, 0.1}, 0.06},
                           {"hybrid", 512, {0.01, 0.01, 0.01}, 0.06},
                           {"volume", 512, {0.01, 0.01, 0.01}, 0.01}};

struct LightsCase
{
    ModeBound mode;
    LightType type;
    int count;
};

class SeveralLights : public ::testing::TestWithParam<LightsCase>
{
};

std::vector<LightsCase> allCases()
{
    std::vector<LightsCase> cases;
    for (const ModeBound& m : MODES)
        for (LightType t : {LightType::DIRECTIONAL, LightType::SPOT, LightType::POINT})
            for (int n : {1, 2, 3, 5}) cases.push_back({m, t, n});
    return cases;
}

/** How often `text` occurs in what a NotifyCapture collected. */
int occurrences(const osstest::NotifyCapture& capture, const std::string& text)
{
    const std::string all = capture.warnings();
    int n = 0;
    for (std::size_t at = all.find(text); at != std::string::npos; at = all.find(text, at + text.size())) ++n;
    return n;
}

/** Mean luminance (0-255) of image over the pixels where pick (GL window x, y) is true. */
template <typename Pick>
double meanLuminance(const osg::Image& image, Pick pick, long long& pixels)
{
    double sum = 0.0;
    pixels = 0;
    for (int y = 0; y < image.t(); ++y)
        for (int x = 0; x < image.s(); ++x)
        {
            if (!pick(x, y)) continue;
            const osg::Vec4 c = image.getColor(x, y);
            sum += 255.0 * (0.299 * c.r() + 0.587 * c.g() + 0.114 * c.b());
            ++pixels;
        }
    return pixels ? sum / pixels : 0.0;
}

/** Dims a light so that three of them do not saturate the picture. */
void dim(osg::Light& light)
{
    light.setAmbient(osg::Vec4(0, 0, 0, 1));
    light.setDiffuse(osg::Vec4(0.3f, 0.3f, 0.3f, 1));
    light.setSpecular(osg::Vec4(0, 0, 0, 1));
}

} // namespace

TEST_P(SeveralLights, EachLightMatchesTheReference)
{
    const LightsCase& c = GetParam();
    ShadowedRender r(optionsWith(c.type, c.count), c.mode.mode, c.mode.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    ASSERT_EQ(r.scene.lights.size(), std::size_t(c.count));
    r.technique->setMaxShadowLights(5);
    for (int i = 0; i < c.count; ++i)
    {
        const ossref::Comparison cmp = compare(r, i);
        std::cout << "wrong_pct " << c.mode.mode << " " << typeName(c.type) << " lights=" << c.count << " light=" << i
                  << " " << cmp.wrongPct << "\n";
        EXPECT_GT(cmp.geometryPixels, W * H / 2);
        EXPECT_LT(cmp.wrongPct, c.mode.bound(c.type))
            << c.mode.mode << ", " << c.count << " " << typeName(c.type) << " lights, light " << i << ": "
            << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels;
    }
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, unsigned(c.count));
    EXPECT_EQ(s.lightsShadowed, unsigned(c.count));
}

INSTANTIATE_TEST_SUITE_P(ModesTypesCounts, SeveralLights, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<LightsCase>& info) {
                             return std::string(info.param.mode.mode) + "_" + typeName(info.param.type) + "_" +
                                    std::to_string(info.param.count);
                         });

// The spot cone ends on the visible ground: outside it the mask says 0 (no light), as the
// reference does, in every mode.
TEST(LightConventions, OutsideTheSpotConeIsUnlit)
{
    for (const ModeBound& m : MODES)
    {
        ShadowedRender r(optionsWith(LightType::SPOT, 1), m.mode, m.mapSize, W, H);
        ASSERT_TRUE(r.valid());
        const ossref::Mask mask = r.mask(0);
        // Pixels outside the cone: lit by the light without casters and without a cone, unlit
        // by the light without casters.
        const ossref::Camera camera = osshar::referenceCamera(r.scene.view, W, H);
        ossref::Light spot = osshar::referenceLight(r.scene.lights[0]);
        ASSERT_EQ(spot.type, ossref::Light::SPOT);
        ossref::Light point = spot;
        point.type = ossref::Light::POINT;
        point.spotCutoffDeg = 180.0;
        const ossref::Mask cone = ossref::computeReferenceMask(*r.scene.content, camera, spot, 0u);
        const ossref::Mask free = ossref::computeReferenceMask(*r.scene.content, camera, point, 0u);
        long long outside = 0, agree = 0;
        for (std::size_t i = 0; i < cone.value.size(); ++i)
        {
            if (cone.value[i] != ossref::MASK_NO_LIGHT || free.value[i] != ossref::MASK_LIT) continue;
            ++outside;
            agree += mask.value[i] == ossref::MASK_NO_LIGHT ? 1 : 0;
        }
        EXPECT_GT(outside, W * H / 10) << m.mode << ": the cone should end on the visible ground";
        EXPECT_GE(agree, outside - outside / 500) << m.mode;
    }
}

// Three lights, a budget of two: one warning, and the third light lights the scene without a
// shadow (its mask is the reference without casters; its shadow does not darken the picture).
class OverBudget : public ::testing::TestWithParam<ModeBound>
{
};

TEST_P(OverBudget, WarnsOnceAndLightsTheRestUnshadowed)
{
    const ModeBound& m = GetParam();
    osshar::RenderOptions options = optionsWith(LightType::DIRECTIONAL, 3);
    ShadowedRender r(options, m.mode, m.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    for (const osshar::LightInScene& l : r.scene.lights) dim(*l.source->getLight());
    osstest::NotifyCapture warnings;
    r.technique->setMaxShadowLights(2);
    r.renderer->timeFrames(0, 4);
    const ossref::Mask mask = r.mask(2);
    EXPECT_EQ(occurrences(warnings, "MaxShadowLights"), 1);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 3u);
    EXPECT_EQ(s.lightsShadowed, 2u);

    const ossref::Camera camera = osshar::referenceCamera(r.scene.view, W, H);
    const ossref::Light light2 = osshar::referenceLight(r.scene.lights[2]);
    const ossref::Mask unshadowed = ossref::computeReferenceMask(*r.scene.content, camera, light2, 0u);
    const ossref::Mask shadowed = r.reference(2);
    const ossref::Comparison c = ossref::compareMasks(mask, unshadowed);
    EXPECT_LT(c.wrongPct, 0.05) << "light 2's mask should ignore every caster";
    EXPECT_GT(ossref::compareMasks(mask, shadowed).wrongPct, 1.0) << "light 2 has shadows to ignore";

    // Colour: where only light 2's shadow falls, the over-budget picture is as bright as with
    // a budget of three lights would be without that shadow, and brighter than with it.
    const ossref::Mask m0 = r.reference(0), m1 = r.reference(1);
    auto onlyLight2Shadow = [&](int x, int y) {
        const std::size_t i = std::size_t(H - 1 - y) * W + x;
        return m0.value[i] == ossref::MASK_LIT && m1.value[i] == ossref::MASK_LIT &&
               shadowed.value[i] == ossref::MASK_NO_LIGHT && unshadowed.value[i] == ossref::MASK_LIT &&
               !shadowed.isGrazing(i);
    };
    auto litByAll = [&](int x, int y) {
        const std::size_t i = std::size_t(H - 1 - y) * W + x;
        return m0.value[i] == ossref::MASK_LIT && m1.value[i] == ossref::MASK_LIT && shadowed.value[i] == ossref::MASK_LIT;
    };
    osg::ref_ptr<osg::Image> overBudget = r.renderer->renderAndCapture();
    r.technique->setMaxShadowLights(3);
    r.renderer->timeFrames(0, 3);
    osg::ref_ptr<osg::Image> withinBudget = r.renderer->renderAndCapture();
    long long n = 0, nLit = 0;
    const double over = meanLuminance(*overBudget, onlyLight2Shadow, n);
    const double within = meanLuminance(*withinBudget, onlyLight2Shadow, n);
    const double overLit = meanLuminance(*overBudget, litByAll, nLit);
    const double withinLit = meanLuminance(*withinBudget, litByAll, nLit);
    ASSERT_GT(n, 200) << "light 2 should shadow some ground that lights 0 and 1 reach";
    EXPECT_GT(over - within, 15.0) << "the over-budget light should light its own shadow";
    EXPECT_NEAR(overLit, withinLit, 1.0) << "pixels every light reaches look the same";
}

INSTANTIATE_TEST_SUITE_P(Modes, OverBudget, ::testing::ValuesIn(MODES),
                         [](const ::testing::TestParamInfo<ModeBound>& info) { return std::string(info.param.mode); });

// Lights that cannot affect what the view sees: no passes that frame, and the picture and the
// masks as before.
class UnreachableLights : public ::testing::TestWithParam<ModeBound>
{
};

TEST_P(UnreachableLights, CostNothing)
{
    const ModeBound& m = GetParam();
    osshar::RenderOptions options = optionsWith(LightType::DIRECTIONAL, 1);
    osshar::LightArg away;                      // a spot over the scene aiming up, away from it
    away.directional = false;
    away.vector = osg::Vec3d(2.0, -1.0, 8.0);
    away.spotDirection = osg::Vec3d(0.05, 0.1, 1.0);
    away.spotCutoff = 30.0;
    osshar::LightArg far;                       // a point light whose range ends far above the scene
    far.directional = false;
    far.vector = osg::Vec3d(-3.0, 2.0, 60.0);
    osshar::LightArg aimed = lightArg(LightType::SPOT, 1); // reaches the view: shadowed
    options.lights.push_back(away);
    options.lights.push_back(far);
    options.lights.push_back(aimed);
    ShadowedRender r(options, m.mode, m.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    ASSERT_EQ(r.scene.lights.size(), 4u);
    r.scene.lights[2].source->getLight()->setQuadraticAttenuation(0.5f); // range ~ 29 units
    r.technique->setMaxShadowLights(2); // the two lights that reach the view fit the budget
    osstest::NotifyCapture warnings;
    r.renderer->timeFrames(0, 3);
    SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 4u);
    EXPECT_EQ(s.lightsSkipped, 2u);
    EXPECT_EQ(s.lightsShadowed, 2u);
    EXPECT_EQ(occurrences(warnings, "MaxShadowLights"), 0) << "skipped lights take no part of the budget";
    const std::string mode = m.mode;
    if (mode == "shadowmap" || mode == "hybrid")
    {
        EXPECT_EQ(s.shadowPasses, 2u);
    }
    if (mode == "silhouette")
    {
        EXPECT_EQ(s.shadowPasses, 2u);
    }
    if (mode == "volume")
    {
        EXPECT_EQ(s.shadowPasses, 0u);
    }
    const unsigned int volumes = s.zfailCasters + s.zpassCasters;

    // The masks: the lights that reach the view and the spot whose cone misses it (unlit
    // everywhere) agree with the reference; the light beyond its range is lit unshadowed (its
    // light is below half an 8-bit step), so its mask is the reference without casters.
    EXPECT_LT(compare(r, 0).wrongPct, m.bound(LightType::DIRECTIONAL)) << m.mode;
    EXPECT_LT(compare(r, 1).wrongPct, m.bound(LightType::SPOT)) << m.mode;
    EXPECT_LT(compare(r, 3).wrongPct, m.bound(LightType::SPOT)) << m.mode;
    const ossref::Mask farMask = r.mask(2);
    const ossref::Comparison farUnshadowed = ossref::compareMasks(
        farMask, ossref::computeReferenceMask(*r.scene.content, osshar::referenceCamera(r.scene.view, W, H),
                                              osshar::referenceLight(r.scene.lights[2]), 0u));
    EXPECT_LT(farUnshadowed.wrongPct, 0.05) << m.mode;

    // The same view without the two skipped lights draws as many volumes.
    r.scene.lights[1].source->getLight()->setPosition(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f));
    r.scene.lights[1].source->getLight()->setSpotCutoff(180.0f);
    r.technique->setMaxShadowLights(3);
    r.renderer->timeFrames(0, 3);
    s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsSkipped, 1u);
    EXPECT_EQ(s.lightsShadowed, 3u);
    if (mode == "volume" || (mode == "hybrid" && !s.triangleLists))
        EXPECT_GT(s.zfailCasters + s.zpassCasters, volumes);
    else
        EXPECT_EQ(s.shadowPasses, 3u);
}

INSTANTIATE_TEST_SUITE_P(Modes, UnreachableLights, ::testing::ValuesIn(MODES),
                         [](const ::testing::TestParamInfo<ModeBound>& info) { return std::string(info.param.mode); });

// A point light amid its casters (the "ring" scene): one perspective map cannot hold the
// shadows that fall all around it; the map modes shadow it with cube faces, each face its own
// depth map and silhouette map.
class PointLightAmidCasters : public ::testing::TestWithParam<ModeBound>
{
};

TEST_P(PointLightAmidCasters, MatchesTheReference)
{
    const ModeBound& m = GetParam();
    ShadowedRender r("ring", m.mode, m.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Comparison c = compare(r, 0);
    std::cout << "wrong_pct " << m.mode << " ring point light: " << c.wrongPct << "\n";
    EXPECT_GT(c.geometryPixels, W * H / 2);
    EXPECT_LT(c.wrongPct, m.ringBoundPct) << c.wrongPixels << " wrong pixels of " << c.geometryPixels;
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsShadowed, 1u);
    if (std::string(m.mode) != "volume")
    {
        EXPECT_GE(s.shadowPasses, 5u) << "one pass per cube face that matters";
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, PointLightAmidCasters, ::testing::ValuesIn(MODES),
                         [](const ::testing::TestParamInfo<ModeBound>& info) { return std::string(info.param.mode); });

// Cube faces take the slots after the lights' own: a point light amid casters next to two
// directional lights, each light's shadow as exact as alone; without the slots for all its
// faces the light warns once and falls back to one perspective map.
TEST(PointLightAmidCasters, SharesTheSlotsWithOtherLights)
{
    osshar::RenderOptions options;
    options.scene = "ring";
    options.lights.push_back({false, osg::Vec3d(0.0, 0.0, 1.6)});
    options.lights.push_back({true, osg::Vec3d(0.45, -0.35, 0.82)});
    options.lights.push_back({true, osg::Vec3d(-0.5, -0.4, 0.77)});
    ShadowedRender r(options, "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    for (unsigned int i = 0; i < 3; ++i)
    {
        const ossref::Comparison c = compare(r, i);
        EXPECT_LT(c.wrongPct, i == 0 ? MODES[0].ringBoundPct : MODES[0].bound(LightType::DIRECTIONAL)) << "light " << i;
    }
    EXPECT_GE(r.technique->getStatistics().shadowPasses, 7u);

    osstest::NotifyCapture warnings;
    r.technique->setBaseTextureUnit(28); // 4 slots (one unit each in SHADOW_MAP): the lights' 3 and one face
    r.renderer->timeFrames(0, 3);
    EXPECT_EQ(occurrences(warnings, "cube faces"), 1);
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, 3u);
    EXPECT_LT(compare(r, 1).wrongPct, MODES[0].bound(LightType::DIRECTIONAL)) << "the other lights keep their shadows";
}

// A SHADOW_MAP slot takes one texture unit (its depth map), so the 24 units from
// BaseTextureUnit 8 hold 24 slots: five point lights over the default scene get all their
// cube faces, with no warning, each light within the single-light bound. The modes whose
// slots take two units (a silhouette map or an edge mask too) have 12: there the later lights
// keep one perspective map, with one warning.
TEST(PointLightFaces, ShadowMapHasASlotPerTextureUnit)
{
    osstest::NotifyCapture warnings;
    ShadowedRender r(optionsWith(LightType::POINT, 5), "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setMaxShadowLights(5);
    r.renderer->timeFrames(0, 2);
    const unsigned int faces = r.technique->getStatistics().shadowPasses;
    EXPECT_GT(faces, 12u) << "more maps than two texture units per slot allow";
    EXPECT_LE(faces, 24u);
    EXPECT_EQ(occurrences(warnings, "cube faces"), 0);
    for (int i = 0; i < 5; ++i) EXPECT_LT(compare(r, i).wrongPct, MODES[0].bound(LightType::POINT)) << "light " << i;

    r.technique->setMode(SilhouetteShadowTechnique::SILHOUETTE_MAP);
    r.renderer->timeFrames(0, 2);
    EXPECT_LE(r.technique->getStatistics().shadowPasses, 12u);
    EXPECT_EQ(occurrences(warnings, "cube faces"), 1);
    for (int i = 0; i < 5; ++i) EXPECT_LT(compare(r, i).wrongPct, MODES[1].bound(LightType::POINT)) << "light " << i;

    // Back to SHADOW_MAP: the slots after the twelfth take the silhouette maps' units again.
    r.technique->setMode(SilhouetteShadowTechnique::SHADOW_MAP);
    r.renderer->timeFrames(0, 2);
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, faces);
    for (int i = 0; i < 5; ++i) EXPECT_LT(compare(r, i).wrongPct, MODES[0].bound(LightType::POINT)) << "light " << i;
}

// HYBRID's triangle lists take one shader storage block per slot and no texture unit, so
// every slot can have them: five point lights whose cube faces fill all 12 slots are still
// resolved with lists (no fallback to stencil volumes, no warning), each light as exact as
// the single-light bound of its type.
TEST(HybridTriangleLists, EveryCubeFaceHasLists)
{
    osstest::NotifyCapture warnings;
    ShadowedRender r(optionsWith(LightType::POINT, 5), "hybrid", 512, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setMaxShadowLights(5);
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    r.renderer->timeFrames(0, 3);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    const float version = contextGLVersion(r);
    if (version < 4.3f) GTEST_SKIP() << "the context runs OpenGL " << glVersionText(version) << ": no triangle lists";
    EXPECT_TRUE(s.triangleLists) << "the context runs OpenGL " << glVersionText(version);
    EXPECT_GT(s.shadowPasses, 6u) << "more slots than the 6 that texture units allowed the lists before";
    EXPECT_EQ(s.zfailCasters + s.zpassCasters, 0u) << "no shadow volumes drawn";
    EXPECT_EQ(occurrences(warnings, "triangle lists hold"), 0);
    const ModeBound& hybrid = MODES[2];
    for (int i = 0; i < 5; ++i)
    {
        const ossref::Comparison c = compare(r, i);
        std::cout << "wrong_pct hybrid lists point lights=5 light=" << i << " " << c.wrongPct << "\n";
        EXPECT_LT(c.wrongPct, hybrid.bound(LightType::POINT)) << "light " << i;
    }
}

// A point light between two boxes on a ground, the boxes one drawable: of its cube faces,
// -x and +x see a box; -z meets the drawable's bounding box (it spans the ground under the
// light) but sees no box, so it gets a slot and draws nothing that can shadow a receiver.
// Once its build is read back (a frame or two), it is left out of the eye pass, and the
// picture is the same, pixel for pixel, as with every face evaluated. A ground that casts is
// in its depth map, so SHADOW_MAP and SILHOUETTE_MAP keep it then; HYBRID's lists leave the
// ground out (no receiver lies below it) and still skip it. (With the boxes as two
// drawables, -z takes no slot at all: OnlyFacesWithACasterTakeSlots below.)
namespace {

constexpr unsigned int PAIR_RECEIVES = 0x1, PAIR_CASTS = 0x2;

osg::ref_ptr<osg::Geode> pairPart(osg::ref_ptr<osg::Geometry> g, const osg::Vec4& colour, unsigned int mask)
{
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setColorMode(osg::Material::OFF);
    m->setAmbient(osg::Material::FRONT_AND_BACK, colour);
    m->setDiffuse(osg::Material::FRONT_AND_BACK, colour);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(g.get());
    geode->getOrCreateStateSet()->setAttributeAndModes(m.get());
    geode->setNodeMask(mask);
    return geode;
}

/** The pair scene in r (made from the default scene with the light of pairOptions()): the
 *  boxes one drawable (`oneDrawable`) or two. */
void makePair(ShadowedRender& r, bool groundCasts, bool oneDrawable = true)
{
    osgShadow::ShadowSettings* settings = r.technique->getShadowedScene()->getShadowSettings();
    settings->setReceivesShadowTraversalMask(PAIR_RECEIVES);
    settings->setCastsShadowTraversalMask(PAIR_CASTS);
    osg::Group& content = *r.scene.content;
    for (unsigned int i = content.getNumChildren(); i-- > 0;)
        if (!dynamic_cast<osg::LightSource*>(content.getChild(i))) content.removeChild(i);
    const unsigned int both = PAIR_RECEIVES | PAIR_CASTS;
    content.addChild(pairPart(osshar::makeGround(0, 0, 24), osg::Vec4(0.75f, 0.75f, 0.72f, 1), groundCasts ? both : PAIR_RECEIVES));
    const osg::ref_ptr<osg::Geometry> left = osshar::makeBox(osg::Vec3(-5.0f, 0.0f, 0.5f), osg::Vec3(1, 1, 1));
    const osg::ref_ptr<osg::Geometry> right = osshar::makeBox(osg::Vec3(5.0f, 0.0f, 0.5f), osg::Vec3(1, 1, 1));
    const osg::Vec4 green(0.3f, 0.6f, 0.3f, 1);
    if (oneDrawable)
        content.addChild(pairPart(osshar::merge(*left, *right), green, both));
    else
        for (const osg::ref_ptr<osg::Geometry>& box : {left, right}) content.addChild(pairPart(box, green, both));
}

osshar::RenderOptions pairOptions()
{
    osshar::RenderOptions options;
    options.scene = "default";
    options.lights.push_back({false, osg::Vec3d(0.0, 0.0, 3.0)});
    return options;
}

/** The pixels the exact reference calls shadowed (grazing ones left out). */
long long shadowedPixels(const ossref::Mask& reference)
{
    long long shadowed = 0;
    for (std::size_t i = 0; i < reference.value.size(); ++i)
        shadowed += reference.value[i] == 0 && reference.grazing[i] == 0 ? 1 : 0;
    return shadowed;
}

long long differingPixels(const osg::Image& a, const osg::Image& b)
{
    if (a.s() != b.s() || a.t() != b.t()) return -1;
    long long n = 0;
    for (int y = 0; y < a.t(); ++y)
        for (int x = 0; x < a.s(); ++x)
            if (a.getColor(x, y) != b.getColor(x, y)) ++n;
    return n;
}

struct PairCase
{
    const char* mode;
    bool groundCasts;
    bool skips; ///< whether the faces without boxes are left out
};

class EmptyCubeFaces : public ::testing::TestWithParam<PairCase>
{
};

} // namespace

TEST_P(EmptyCubeFaces, AreLeftOutAndThePictureStays)
{
    const PairCase& c = GetParam();
    ShadowedRender r(pairOptions(), c.mode, 512, W, H);
    ASSERT_TRUE(r.valid());
    makePair(r, c.groundCasts);
    SilhouetteShadowTechnique::Tuning tuning = r.technique->getTuning();
    ASSERT_TRUE(tuning.skipEmptyFaces) << "the default";
    tuning.skipEmptyFaces = false;
    r.technique->setTuning(tuning);
    r.renderer->timeFrames(0, 3);
    osg::ref_ptr<osg::Image> every = r.renderer->renderAndCapture();
    const SilhouetteShadowTechnique::Statistics all = r.technique->getStatistics();
    EXPECT_EQ(all.slotsSkipped, 0u);
    ASSERT_EQ(all.shadowPasses, 3u) << "the point light needs cube faces: -x, +x and -z (the boxes' drawable)";

    tuning.skipEmptyFaces = true;
    r.technique->setTuning(tuning);
    r.renderer->timeFrames(0, 3);
    osg::ref_ptr<osg::Image> skipping = r.renderer->renderAndCapture();
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.shadowPasses, all.shadowPasses);
    EXPECT_EQ(s.slotsSkipped, c.skips ? s.shadowPasses - 2 : 0u) << "every face but -x and +x holds no box";
    EXPECT_EQ(differingPixels(*every, *skipping), 0) << "a face left out shadows nothing";
    const ModeBound* bound = &MODES[0];
    for (const ModeBound& m : MODES)
        if (m.mode == std::string(c.mode)) bound = &m;
    const ossref::Comparison cmp = compare(r, 0);
    EXPECT_LT(cmp.wrongPct, bound->bound(LightType::POINT)) << cmp.wrongPixels << " wrong pixels";
    const long long shadowed = shadowedPixels(r.reference(0));
    std::cout << "pair " << c.mode << ": " << s.slotsSkipped << " of " << s.shadowPasses << " faces left out; "
              << shadowed << " shadowed pixels in the reference, " << cmp.wrongPixels << " wrong\n";
    EXPECT_GT(shadowed, 10 * cmp.wrongPixels + 200) << "the boxes' shadows are in view, and in the picture";

    // Moving the light rebuilds every face: none is left out until the new builds are back.
    r.scene.lights[0].source->getLight()->setPosition(osg::Vec4(0.0f, 0.2f, 3.0f, 1.0f));
    r.renderer->timeFrames(0, 1);
    EXPECT_EQ(r.technique->getStatistics().slotsSkipped, 0u) << "the frame that rebuilt";
    r.renderer->timeFrames(0, 3);
    EXPECT_EQ(r.technique->getStatistics().slotsSkipped, c.skips ? s.shadowPasses - 2 : 0u);
}

INSTANTIATE_TEST_SUITE_P(Modes, EmptyCubeFaces,
                         ::testing::Values(PairCase{"shadowmap", false, true}, PairCase{"shadowmap", true, false},
                                           PairCase{"silhouette", false, true}, PairCase{"silhouette", true, false},
                                           PairCase{"hybrid", false, true}, PairCase{"hybrid", true, true}),
                         [](const ::testing::TestParamInfo<PairCase>& info) {
                             return std::string(info.param.mode) + (info.param.groundCasts ? "_casting_ground" : "");
                         });

// The same light and boxes, each box a drawable of its own, on a ground that casts: only -x
// and +x hold a caster that can shadow a receiver (the ground is flat and every receiver
// stands on it), so only they take a slot: two maps, none left out afterwards, in every map
// mode, and the shadows as exact as the mode's single-light bound.
class FacesWithCasters : public ::testing::TestWithParam<const char*>
{
};

TEST_P(FacesWithCasters, OnlyFacesWithACasterTakeSlots)
{
    ShadowedRender r(pairOptions(), GetParam(), 512, W, H);
    ASSERT_TRUE(r.valid());
    makePair(r, true, false);
    r.renderer->timeFrames(0, 3);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.shadowPasses, 2u) << "-x and +x";
    EXPECT_EQ(s.slotsSkipped, 0u);
    EXPECT_EQ(s.lightsShadowed, 1u);
    const ModeBound* bound = &MODES[0];
    for (const ModeBound& m : MODES)
        if (m.mode == std::string(GetParam())) bound = &m;
    const ossref::Comparison cmp = compare(r, 0);
    EXPECT_LT(cmp.wrongPct, bound->bound(LightType::POINT)) << cmp.wrongPixels << " wrong pixels";
    const long long shadowed = shadowedPixels(r.reference(0));
    EXPECT_GT(shadowed, 10 * cmp.wrongPixels + 200) << "the boxes' shadows are in view, and in the picture";

    // A receiver below the ground (a box under it) can be shadowed by the ground: then the
    // ground counts, and -z takes a slot again.
    osg::ref_ptr<osg::Geode> under = pairPart(osshar::makeBox(osg::Vec3(0.0f, 0.0f, -2.0f), osg::Vec3(1, 1, 1)),
                                              osg::Vec4(0.5f, 0.5f, 0.5f, 1), PAIR_RECEIVES);
    r.scene.content->addChild(under.get());
    r.renderer->timeFrames(0, 2);
    EXPECT_GT(r.technique->getStatistics().shadowPasses, 2u) << "the ground can shadow the box under it";
}

INSTANTIATE_TEST_SUITE_P(Modes, FacesWithCasters, ::testing::Values("shadowmap", "silhouette", "hybrid"));
