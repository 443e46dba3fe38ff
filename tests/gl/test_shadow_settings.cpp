// The ShadowedScene's osgShadow::ShadowSettings drive the technique where its own property
// is at its default (docs/shadow-settings.md): each setting with a meaning here changes the
// picture as the property would, read again every frame; the property set wins with one
// warning; the settings without a meaning here leave the picture alone and warn once.
#include "GLTestSupport.h"
#include "NotifyCapture.h"
#include "Meshes.h"
#include "cpu/test_soups.h"

#include <osg/Geode>
#include <osgDB/WriteFile>

#include <osgShadow/ShadowSettings>
#include <osgUtil/CullVisitor>
#include <osgUtil/SceneView>
#include <osgViewer/Renderer>

#include <cfloat>
#include <functional>
#include <map>

using osstest::NotifyCapture;
using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

constexpr int W = 256, H = 192;

osgShadow::ShadowSettings& settingsOf(ShadowedRender& r)
{
    return *r.technique->getShadowedScene()->getShadowSettings();
}

/** Pixels where two masks differ (all of them if the sizes differ). */
long long differing(const ossref::Mask& a, const ossref::Mask& b)
{
    if (a.width != b.width || a.height != b.height) return std::max<long long>(a.value.size(), b.value.size());
    long long n = 0;
    for (std::size_t i = 0; i < a.value.size(); ++i) n += a.value[i] != b.value[i] ? 1 : 0;
    return n;
}

/** The default scene lit by the directional lights `directions`. */
osshar::RenderOptions directionalLights(std::initializer_list<osg::Vec3d> directions)
{
    osshar::RenderOptions o;
    o.scene = "default";
    for (const osg::Vec3d& d : directions) o.lights.push_back({true, d});
    return o;
}

/** A point light amid the ring's casters next to two directional lights: in SHADOW_MAP the
 *  point light's cube faces take the slots after the lights' own. */
osshar::RenderOptions ringWithThreeLights()
{
    osshar::RenderOptions o;
    o.scene = "ring";
    o.lights.push_back({false, osg::Vec3d(0.0, 0.0, 1.6)});
    o.lights.push_back({true, osg::Vec3d(0.45, -0.35, 0.82)});
    o.lights.push_back({true, osg::Vec3d(-0.5, -0.4, 0.77)});
    return o;
}

const osg::Vec4 GREY(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1);

/** With `change(true)` light 0's mask has more than `fewer` unlit pixels less than `before`
 *  (`why`); after `change(false)` it is `before` again. */
void expectFewerUnlitUntilUndone(ShadowedRender& r, const ossref::Mask& before, long long fewer,
                                 const std::function<void(bool)>& change, const char* why)
{
    change(true);
    EXPECT_LT(r.mask().count(ossref::MASK_NO_LIGHT), before.count(ossref::MASK_NO_LIGHT) - fewer) << why;
    change(false);
    EXPECT_EQ(differing(r.mask(), before), 0) << "undone";
}

} // namespace

// TextureSize 64x64 renders as ShadowMapSize 64 does, and differs from the default 2048.
TEST(ShadowSettingsGL, TextureSizeIsTheMapSize)
{
    ShadowedRender r("default", "shadowmap", 2048, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask fine = r.mask();
    settingsOf(r).setTextureSize(osg::Vec2s(64, 64));
    const ossref::Mask fromSettings = r.mask();
    EXPECT_EQ(r.technique->getEffectiveShadowMapSize(), 64u);
    EXPECT_EQ(r.technique->getShadowMapSize(), 2048u) << "the property keeps its value";
    settingsOf(r).setTextureSize(osg::Vec2s(2048, 2048));
    r.technique->setShadowMapSize(64);
    const ossref::Mask fromProperty = r.mask();
    EXPECT_EQ(differing(fromSettings, fromProperty), 0);
    EXPECT_GT(differing(fromSettings, fine), 100) << "a 64-texel map is coarser than the default";
}

// The maps are square: a TextureSize of 64x32 takes the larger side, with one warning.
TEST(ShadowSettingsGL, ANonSquareTextureSizeTakesTheLargerSide)
{
    NotifyCapture warnings;
    ShadowedRender r("default", "shadowmap", 2048, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setShadowMapSize(64);
    const ossref::Mask square = r.mask();
    r.technique->setShadowMapSize(2048);
    settingsOf(r).setTextureSize(osg::Vec2s(64, 32));
    const ossref::Mask oblong = r.mask(0, 3);
    EXPECT_EQ(differing(square, oblong), 0);
    EXPECT_EQ(warnings.count("TextureSize 64x32 is not square"), 1) << warnings.warnings();
}

// The technique's own ShadowMapSize (the harness sets 1024) wins over TextureSize: the
// picture stays, and one warning says so.
TEST(ShadowSettingsGL, TheTechniquesOwnMapSizeWins)
{
    NotifyCapture warnings;
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask own = r.mask();
    settingsOf(r).setTextureSize(osg::Vec2s(64, 64));
    const ossref::Mask withSetting = r.mask(0, 3);
    EXPECT_EQ(differing(own, withSetting), 0);
    EXPECT_EQ(r.technique->getEffectiveShadowMapSize(), 1024u);
    EXPECT_EQ(warnings.count("ShadowSettings TextureSize 64x64 is overridden by the technique's ShadowMapSize 1024"), 1)
        << warnings.warnings();
}

// LightNum 1 shadows only light 1, as the technique's LightNum 1 does.
TEST(ShadowSettingsGL, LightNumShadowsOnlyThatLight)
{
    ShadowedRender r(directionalLights({{0.45, -0.35, 0.82}, {-0.5, -0.4, 0.77}}), "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask both0 = r.mask(0), both1 = r.mask(1);
    EXPECT_EQ(r.technique->getStatistics().lightsShadowed, 2u);
    settingsOf(r).setLightNum(1);
    const ossref::Mask settings0 = r.mask(0), settings1 = r.mask(1);
    EXPECT_EQ(r.technique->getStatistics().lightsShadowed, 1u);
    settingsOf(r).setLightNum(-1);
    r.technique->setLightNum(1);
    const ossref::Mask property0 = r.mask(0), property1 = r.mask(1);
    EXPECT_EQ(differing(settings0, property0), 0);
    EXPECT_EQ(differing(settings1, property1), 0);
    EXPECT_EQ(differing(settings1, both1), 0) << "light 1 keeps its shadow";
    EXPECT_GT(differing(settings0, both0), 100) << "light 0 casts no shadow";
    EXPECT_LT(settings0.count(ossref::MASK_NO_LIGHT), both0.count(ossref::MASK_NO_LIGHT));
}

// BaseShadowTextureUnit 28 leaves 4 units (SHADOW_MAP: a slot each): the point light's cube
// faces no longer fit next to the two directional lights, as with BaseTextureUnit 28.
TEST(ShadowSettingsGL, BaseShadowTextureUnitMovesTheMaps)
{
    NotifyCapture warnings;
    ShadowedRender r(ringWithThreeLights(), "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    r.renderer->timeFrames(0, 2);
    EXPECT_GE(r.technique->getStatistics().shadowPasses, 7u);
    EXPECT_EQ(warnings.count("cube faces"), 0);
    settingsOf(r).setBaseShadowTextureUnit(28);
    const ossref::Mask settings1 = r.mask(1, 3);
    EXPECT_EQ(r.technique->getEffectiveBaseTextureUnit(), 28u);
    EXPECT_EQ(r.technique->getStatistics().shadowPasses, 3u);
    EXPECT_EQ(warnings.count("cube faces"), 1) << warnings.warnings();
    const ossref::Mask settings0 = r.mask(0);

    ShadowedRender p(ringWithThreeLights(), "shadowmap", 1024, W, H);
    ASSERT_TRUE(p.valid());
    p.technique->setBaseTextureUnit(28);
    EXPECT_EQ(differing(settings0, p.mask(0, 3)), 0);
    EXPECT_EQ(differing(settings1, p.mask(1)), 0);
}

// DebugDraw shows the technique's debug view: the shadow mask of light 0.
TEST(ShadowSettingsGL, DebugDrawShowsTheShadowMask)
{
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    r.renderer->timeFrames(0, 2);
    osg::ref_ptr<osg::Image> shaded = r.renderer->renderAndCapture(GREY);
    settingsOf(r).setDebugDraw(true);
    r.renderer->timeFrames(0, 1);
    osg::ref_ptr<osg::Image> debug = r.renderer->renderAndCapture(GREY);
    EXPECT_EQ(r.technique->getEffectiveDebugView(), SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    const ossref::Mask fromSettings = ossref::maskFromImage(*debug);
    settingsOf(r).setDebugDraw(false);
    const ossref::Mask fromProperty = r.mask(); // DebugView DEBUG_SHADOW_MASK
    EXPECT_EQ(differing(fromSettings, fromProperty), 0);
    EXPECT_GT(differing(fromSettings, ossref::maskFromImage(*shaded)), 1000) << "the shaded scene is no mask";
}

namespace {

/** Records the near/far mode of the cull visitor while it culls the receivers for `camera`. */
struct RecordNearFarMode : public osg::NodeCallback
{
    explicit RecordNearFarMode(osg::Camera* c) : camera(c) {}
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (osgUtil::CullVisitor* cv = nv->asCullVisitor())
            if (cv->getCurrentCamera() == camera) seen.push_back(cv->getComputeNearFarMode());
        traverse(node, nv);
    }
    osg::Camera* camera;
    std::vector<osg::CullSettings::ComputeNearFarMode> seen;
};

} // namespace

// ComputeNearFarModeOverride is how the view computes its near and far planes over the
// receivers, as in ViewDependentShadowMap; the camera keeps its own mode.
TEST(ShadowSettingsGL, ComputeNearFarModeOverrideAppliesToTheReceivers)
{
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    osg::Camera* camera = r.renderer->viewer().getCamera();
    const osg::CullSettings::ComputeNearFarMode own = camera->getComputeNearFarMode();
    ASSERT_NE(own, osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES);
    osg::ref_ptr<RecordNearFarMode> record = new RecordNearFarMode(camera);
    r.scene.content->addCullCallback(record.get());
    r.renderer->timeFrames(0, 1);
    ASSERT_FALSE(record->seen.empty());
    EXPECT_EQ(record->seen.back(), own);
    record->seen.clear();
    settingsOf(r).setComputeNearFarModeOverride(osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES);
    r.renderer->timeFrames(0, 2);
    ASSERT_FALSE(record->seen.empty());
    for (osg::CullSettings::ComputeNearFarMode m : record->seen)
        EXPECT_EQ(m, osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES);
    EXPECT_EQ(camera->getComputeNearFarMode(), own);
    r.scene.content->removeCullCallback(record.get());
}

namespace {

/** A ground wider than the view and one drawable of three boxes and a pole that rises past
 *  the view's top, written where the renderer's options can load them: both drawables cross
 *  the view's sides, as a framed model on a ground often does. */
osshar::RenderOptions boxesOnAGround()
{
    std::vector<souptest::Triangle> boxes = souptest::box({-3, -1, 0}, {-1, 1, 3});
    for (const souptest::Triangle& t : souptest::box({0, -2, 0}, {1, -1, 1})) boxes.push_back(t);
    for (const souptest::Triangle& t : souptest::box({1, 1, 0}, {3, 2, 2})) boxes.push_back(t);
    for (const souptest::Triangle& t : souptest::box({-0.2f, 2.8f, 0}, {0.2f, 3.2f, 40})) boxes.push_back(t);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeGround(0, 0, 200));
    geode->addDrawable(souptest::soupGeometry(boxes, "boxes and a pole"));
    osshar::RenderOptions o;
    o.file = ::testing::TempDir() + "oss_boxes_on_a_ground.osgt";
    EXPECT_TRUE(osgDB::writeNodeFile(*geode, o.file));
    o.eye = osg::Vec3d(2, -14, 6), o.center = osg::Vec3d(0, 0, 0);
    o.lights.push_back({true, osg::Vec3d(0.5, -0.6, 0.6)});
    return o;
}

} // namespace

// A camera that computes its near and far planes from primitives (COMPUTE_NEAR_FAR_USING_
// PRIMITIVES, COMPUTE_NEAR_USING_PRIMITIVES) defers every drawable that crosses the view's
// sides, here the ground, to the end of its cull; the technique resolves them before its
// light passes read the view's depth range. Every mode then casts the shadows it casts under
// bounding volumes: before, the range read empty and no light cast a shadow.
TEST(ShadowSettingsGL, ThePrimitiveNearFarModesCastTheSameShadows)
{
    using NearFar = osg::CullSettings::ComputeNearFarMode;
    const osshar::RenderOptions options = boxesOnAGround();
    for (const char* mode : {"shadowmap", "silhouette", "hybrid", "volume"})
    {
        SCOPED_TRACE(mode);
        std::map<NearFar, ossref::Comparison> scores;
        for (const NearFar m :
             {osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES,
              osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES, osg::CullSettings::COMPUTE_NEAR_USING_PRIMITIVES})
        {
            SCOPED_TRACE(int(m));
            ShadowedRender r(options, mode, 1024, W, H); // the camera's mode from the first frame
            ASSERT_TRUE(r.valid());
            r.renderer->viewer().getCamera()->setComputeNearFarMode(m);
            const ossref::Mask reference = r.reference();
            ASSERT_GT(reference.count(ossref::MASK_NO_LIGHT), 500); // the boxes' shadows are in view
            scores[m] = ossref::compareMasks(r.mask(), reference);
        }
        const double volumes = scores[osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES].wrongPct;
        EXPECT_LT(volumes, 0.2);
        EXPECT_LE(scores[osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES].wrongPct, volumes + 0.02);
        EXPECT_LE(scores[osg::CullSettings::COMPUTE_NEAR_USING_PRIMITIVES].wrongPct, volumes + 0.02);
    }
}

namespace {

/** The near and far planes the view's last cull computed. */
std::pair<double, double> computedNearFar(ShadowedRender& r)
{
    osg::Camera* camera = r.renderer->viewer().getCamera();
    osgViewer::Renderer* renderer = dynamic_cast<osgViewer::Renderer*>(camera->getRenderer());
    osgUtil::SceneView* view = renderer ? renderer->getSceneView(0) : nullptr;
    osgUtil::CullVisitor* cv = view ? view->getCullVisitor() : nullptr;
    if (!cv) return {0.0, 0.0};
    return {cv->getCalculatedNearPlane(), cv->getCalculatedFarPlane()};
}

} // namespace

// The stencil volumes compare their faces with the eye's depth buffer. A ground around the
// eye makes a bounding-volume near plane negative, and the near-far ratio clamps it to far /
// 2000, too coarse a buffer where outlines fall (docs/shadow-volumes.md, "Precision"). In
// SHADOW_VOLUME and HYBRID_STENCIL_VOLUMES the receivers' cull takes the near plane from
// primitives: here the nearest ground in view, at 8.3 units. The other modes, and an
// explicit ComputeNearFarModeOverride, keep the view's own.
TEST(ShadowSettingsGL, TheStencilModesTakeTheNearPlaneFromPrimitives)
{
    const osshar::RenderOptions options = boxesOnAGround();
    for (const char* mode : {"volume", "hybrid", "hybrid-stencil", "shadowmap", "volume-override"})
    {
        SCOPED_TRACE(mode);
        const std::string name(mode);
        ShadowedRender r(options, name.substr(0, name.find('-')), 1024, W, H);
        ASSERT_TRUE(r.valid());
        if (name == "hybrid-stencil") r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
        if (name == "volume-override")
            settingsOf(r).setComputeNearFarModeOverride(osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
        r.renderer->timeFrames(0, 2);
        const std::pair<double, double> nearFar = computedNearFar(r);
        ASSERT_GT(nearFar.second, 50.0); // the ground's far side
        const double ratio = r.renderer->viewer().getCamera()->getNearFarRatio();
        if (name == "volume" || name == "hybrid-stencil")
            EXPECT_GT(nearFar.first, 5.0) << "far " << nearFar.second;
        else
            EXPECT_LT(nearFar.first, 0.0) << "the ground's sphere holds the eye; clamped to far * " << ratio;
    }
}

// MaximumShadowMapDistance: the maps cover the receivers up to that eye distance; beyond
// they are lit, in every mode with a map. Back to DBL_MAX, the picture is the default's
// again. SHADOW_VOLUME has no map and keeps its shadows.
TEST(ShadowSettingsGL, MaximumShadowMapDistanceEndsTheShadows)
{
    // The default view looks at the casters from 19 units; the light throws their shadows
    // away from the eye. Within 13 units lies only the near ground, which nothing shadows:
    // the casters' shadows, all beyond, are gone.
    const double nearGround = 13.0;
    for (const char* mode : {"shadowmap", "silhouette", "hybrid"})
    {
        ShadowedRender r("default", mode, 1024, W, H);
        ASSERT_TRUE(r.valid());
        ASSERT_GT((r.scene.view.eye - r.scene.view.center).length(), 18.0);
        const ossref::Mask all = r.mask();
        SCOPED_TRACE(mode);
        expectFewerUnlitUntilUndone(
            r, all, 500, [&](bool on) { settingsOf(r).setMaximumShadowMapDistance(on ? nearGround : DBL_MAX); },
            "the far shadows are gone");
    }

    ShadowedRender v("default", "volume", 1024, W, H);
    ASSERT_TRUE(v.valid());
    const ossref::Mask volumes = v.mask();
    settingsOf(v).setMaximumShadowMapDistance(nearGround);
    EXPECT_EQ(differing(v.mask(), volumes), 0);
}

namespace {

/** A 1x1 depth texture at the far plane, compared as the shadow maps are: lit everywhere. */
osg::ref_ptr<osg::Texture2D> litDepthTexture()
{
    osg::ref_ptr<osg::Texture2D> t = osgShadowSilhouette::SilhouetteMapPass::createLitDepthTexture();
    t->setShadowComparison(true);
    t->setShadowCompareFunc(osg::Texture::LEQUAL);
    return t;
}

} // namespace

// UseOverrideForShadowMapTexture false: a texture of the model on the shadow map's unit
// replaces the map below it; here a lit depth texture on the whole model leaves it
// unshadowed. With the default (true) the map wins and the picture stays.
TEST(ShadowSettingsGL, UseOverrideForShadowMapTextureFalseLetsTheModelsTextureWin)
{
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask shadowed = r.mask();
    r.scene.content->getOrCreateStateSet()->setTextureAttributeAndModes(r.technique->getEffectiveBaseTextureUnit(),
                                                                         litDepthTexture().get());
    EXPECT_EQ(differing(r.mask(), shadowed), 0) << "the map overrides the model's texture";
    expectFewerUnlitUntilUndone(
        r, shadowed, 300, [&](bool on) { settingsOf(r).setUseOverrideForShadowMapTexture(!on); },
        "the model's lit texture replaces the map: only the faces turned away stay dark");
}

// The settings without a meaning here: the picture stays, and each warns exactly once,
// naming itself and its value.
TEST(ShadowSettingsGL, SettingsWithoutMeaningWarnOnce)
{
    NotifyCapture warnings;
    ShadowedRender r("default", "shadowmap", 1024, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::Mask before = r.mask();
    osgShadow::ShadowSettings& s = settingsOf(r);
    s.setShadowMapProjectionHint(osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP);
    s.setPerspectiveShadowMapCutOffAngle(10.0);
    s.setNumShadowMapsPerLight(2);
    s.setMultipleShadowMapHint(osgShadow::ShadowSettings::CASCADED);
    s.setShaderHint(osgShadow::ShadowSettings::PROVIDE_VERTEX_AND_FRAGMENT_SHADER);
    s.setMinimumShadowMapNearFarRatio(0.2);
    const ossref::Mask after = r.mask(0, 4);
    EXPECT_EQ(differing(before, after), 0);
    for (const char* named :
         {"ShadowMapProjectionHint ORTHOGRAPHIC_SHADOW_MAP is ignored", "PerspectiveShadowMapCutOffAngle 10 is ignored",
          "NumShadowMapsPerLight 2 is ignored", "MultipleShadowMapHint CASCADED is ignored",
          "ShaderHint PROVIDE_VERTEX_AND_FRAGMENT_SHADER is ignored", "MinimumShadowMapNearFarRatio 0.2 is ignored"})
        EXPECT_EQ(warnings.count(std::string("ShadowSettings ") + named), 1) << named << "\n" << warnings.warnings();
    r.renderer->timeFrames(0, 2);
    EXPECT_EQ(warnings.count("ShadowSettings "), 6) << warnings.warnings();
}
