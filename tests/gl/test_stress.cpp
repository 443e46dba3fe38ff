// Bad input and awkward configurations: no crash, an image, and where a reference applies,
// the same accuracy bounds as the plain cases.
#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"

#include <osg/Geode>
#include <osg/MatrixTransform>

#include <cmath>
#include <limits>

namespace bounds = osstest::bounds;
using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

const char* const MODES[] = {"shadowmap", "silhouette", "volume", "hybrid"};

double wrongPct(ShadowedRender& r)
{
    const ossref::Comparison c = ossref::compareMasks(r.mask(), r.reference());
    EXPECT_TRUE(c.valid) << c.error;
    return c.wrongPct;
}

class EveryMode : public ::testing::TestWithParam<const char*>
{
};

} // namespace

// A geometry with NaN and Inf vertices is left out of shadow casting with a warning; the
// rest of the scene keeps its accuracy.
TEST_P(EveryMode, NonFiniteVerticesAreLeftOut)
{
    ShadowedRender r("default", GetParam(), 1024);
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::Geometry> bad = osshar::makeBox(osg::Vec3(20, 20, 1), osg::Vec3(1, 1, 1));
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(bad->getVertexArray());
    (*v)[0].x() = std::numeric_limits<float>::quiet_NaN();
    (*v)[5].z() = std::numeric_limits<float>::infinity();
    bad->setName("broken box");
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(bad.get());
    r.scene.content->addChild(geode.get());
    EXPECT_LT(wrongPct(r), bounds::CLAIMED.of(GetParam())) << GetParam();
}

TEST_P(EveryMode, SceneFarFromTheOrigin)
{
    ShadowedRender r("default", GetParam(), 2048);
    ASSERT_TRUE(r.valid());
    const osg::Vec3d offset(2e5, -3e5, 0);
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(offset));
    for (unsigned int i = 0; i < r.scene.content->getNumChildren(); ++i) moved->addChild(r.scene.content->getChild(i));
    r.scene.content->removeChildren(0, r.scene.content->getNumChildren());
    r.scene.content->addChild(moved.get());
    r.scene.lights = osshar::findLights(r.scene.content.get());
    r.scene.view.eye += offset;
    r.scene.view.center += offset;
    r.renderer->setView(r.scene.view);
    // Vertices are floats 3e5 from the origin (0.03 units apart): edges move by up to that.
    EXPECT_LT(wrongPct(r), bounds::CLAIMED.of(GetParam())) << GetParam();
}

TEST_P(EveryMode, MapSizeOneRendersWithoutError)
{
    ShadowedRender r("default", GetParam(), 1);
    ASSERT_TRUE(r.valid());
    const ossref::Mask m = r.mask();
    EXPECT_GT(m.count(ossref::MASK_LIT) + m.count(ossref::MASK_NO_LIGHT), 100000) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Modes, EveryMode, ::testing::ValuesIn(MODES));

TEST(Stress, SwitchingModeEveryFrame)
{
    ShadowedRender r("default", "shadowmap", 1024);
    ASSERT_TRUE(r.valid());
    for (int frame = 0; frame < 12; ++frame)
    {
        r.technique->setMode(SilhouetteShadowTechnique::Mode(frame % 4));
        r.renderer->timeFrames(0, 1);
    }
    // Each mode keeps its accuracy right after another one ran (shared depth maps change
    // their comparison mode between SILHOUETTE_MAP and the others).
    for (int m : {1, 2, 0, 3, 1, 0})
    {
        r.technique->setMode(SilhouetteShadowTechnique::Mode(m));
        EXPECT_LT(wrongPct(r), bounds::CLAIMED.ofMode(m)) << SilhouetteShadowTechnique::modeName(SilhouetteShadowTechnique::Mode(m));
    }
}

TEST(Stress, SceneWithoutLightRendersUnshadowed)
{
    ShadowedRender r("default", "volume", 512);
    ASSERT_TRUE(r.valid());
    for (const osshar::LightInScene& l : r.scene.lights)
        for (osg::Group* parent : l.source->getParents()) parent->removeChild(l.source);
    r.renderer->timeFrames(0, 2);
    const SilhouetteShadowTechnique::Statistics s = r.technique->getStatistics();
    EXPECT_EQ(s.lightsFound, 0u);
    EXPECT_EQ(s.shadowPasses, 0u);
    osg::ref_ptr<osg::Image> image = r.renderer->renderAndCapture();
    ASSERT_TRUE(image.valid());
    EXPECT_EQ(image->s(), 1024);
}

TEST(Stress, EmptySceneRendersBackground)
{
    for (const char* mode : MODES)
    {
        ShadowedRender r("default", mode, 512);
        ASSERT_TRUE(r.valid());
        osg::ref_ptr<osg::LightSource> light = osshar::makeLight(osg::Vec4(0, 0, 1, 0));
        r.scene.content->removeChildren(0, r.scene.content->getNumChildren());
        r.scene.content->addChild(light.get());
        const ossref::Mask m = r.mask();
        EXPECT_EQ(m.count(ossref::MASK_BACKGROUND), 1024LL * 768) << mode;
    }
}

// The stencil modes need a stencil buffer: on a context without one they render SHADOW_MAP
// (and warn once) instead of silently drawing no shadows.
TEST(Stress, StencilModesWithoutStencilBufferFallBackToShadowMap)
{
    osshar::RenderOptions options;
    osshar::PreparedScene scene;
    osg::ref_ptr<osg::Node> root;
    osg::ref_ptr<SilhouetteShadowTechnique> technique;
    std::string error;
    ASSERT_TRUE(osshar::prepareScene(options, scene, error)) << error;
    ASSERT_TRUE(osshar::makeShadowedRoot("volume", 1024, scene, root, technique, error)) << error;
    EXPECT_EQ(technique->getEffectiveMode(), SilhouetteShadowTechnique::SHADOW_VOLUME) << "nothing rendered yet";
    osshar::Renderer renderer(1024, 768, true, 0);
    ASSERT_TRUE(renderer.valid());
    const osg::GraphicsContext* gc = renderer.viewer().getCamera()->getGraphicsContext();
    if (gc->getTraits()->stencil > 0) GTEST_SKIP() << "the display granted a stencil buffer anyway";
    renderer.setSceneData(root.get());
    renderer.setView(scene.view);
    renderer.timeFrames(0, 2);
    const SilhouetteShadowTechnique::Statistics s = technique->getStatistics();
    EXPECT_EQ(s.effectiveMode, SilhouetteShadowTechnique::SHADOW_MAP);
    EXPECT_EQ(technique->getEffectiveMode(), SilhouetteShadowTechnique::SHADOW_MAP);
    EXPECT_EQ(technique->getMode(), SilhouetteShadowTechnique::SHADOW_VOLUME);
    EXPECT_EQ(s.shadowPasses, 1u) << "the fallback renders the shadow map";
    technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    osg::ref_ptr<osg::Image> image = renderer.renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    const ossref::Comparison c = ossref::compareMasks(
        ossref::maskFromImage(*image),
        ossref::computeReferenceMask(*scene.content, osshar::referenceCamera(scene.view, 1024, 768),
                                     osshar::referenceLight(scene.lights.at(0))));
    EXPECT_LT(c.wrongPct, bounds::CLAIMED.shadowMap);
}
