// What osgviewer shows of the scene files in data/. Each file is loaded through osgDB as
// osgviewer loads it (so through the serializer plugin found by OSG_LIBRARY_PATH), seen from
// osgviewer's home position, and rendered offscreen with osgviewer's headlight (GL light 0,
// like the scenes' own light, which GL ends up using) and without it (as applications that
// bring their own light):
//  - the technique really runs: its statistics report a shadowed light and a shadow pass;
//  - its shadow mask (DebugView DEBUG_SHADOW_MASK) has shadowed and lit pixels;
//  - the shaded image is darker than the same scene rendered without the technique on a
//    share of the pixels like the mask's shadowed share.
// tests/ecosystem runs the stock osgviewer itself on the same files.
#include "Offscreen.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <gtest/gtest.h>

#include <osgDB/ReadFile>
#include <osgShadow/ShadowedScene>

#include <cstdlib>
#include <ostream>
#include <filesystem>

namespace fs = std::filesystem;
using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;

namespace {

constexpr int WIDTH = 320, HEIGHT = 240;

/** data/<scene>.osgt of the source tree ($OSS_SOURCE_DIR, else found from this file's path). */
std::string dataFile(const std::string& scene)
{
    const char* env = std::getenv("OSS_SOURCE_DIR");
    const std::string source = env && *env ? std::string(env) : fs::path(__FILE__).parent_path().parent_path().parent_path().string();
    return source + "/data/" + scene + ".osgt";
}

/** A renderer set up like osgviewer: 8 stencil bits (--stencil), the home view. */
std::unique_ptr<osshar::Renderer> osgviewerLikeRenderer(osg::Node* root, osg::View::LightingMode lighting)
{
    auto renderer = std::make_unique<osshar::Renderer>(WIDTH, HEIGHT, true);
    renderer->viewer().setLightingMode(lighting);
    renderer->setSceneData(root);
    renderer->setView(osshar::defaultView(root->getBound()));
    return renderer;
}

double luminance(const unsigned char* p)
{
    return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

/** Share of pixels with luminance below `threshold`. */
double shareBelow(const osg::Image& image, double threshold)
{
    const int n = image.s() * image.t();
    int count = 0;
    for (int i = 0; i < n; ++i) count += luminance(image.data() + 3 * i) < threshold;
    return double(count) / n;
}

/** Share of pixels where `a` is darker than `b` by more than `margin`. */
double shareDarker(const osg::Image& a, const osg::Image& b, double margin)
{
    const int n = a.s() * a.t();
    int count = 0;
    for (int i = 0; i < n; ++i) count += luminance(a.data() + 3 * i) + margin < luminance(b.data() + 3 * i);
    return double(count) / n;
}

/** One frame after two warm-up frames, in a new context. */
osg::ref_ptr<osg::Image> render(osg::Node* root, const osg::Vec4& clear, osg::View::LightingMode lighting)
{
    if (osgShadow::ShadowedScene* scene = dynamic_cast<osgShadow::ShadowedScene*>(root))
        scene->getShadowTechnique()->dirty(); // no per-view state from an earlier context
    std::unique_ptr<osshar::Renderer> renderer = osgviewerLikeRenderer(root, lighting);
    if (!renderer->valid()) return nullptr;
    renderer->timeFrames(1, 1);
    return renderer->renderAndCapture(clear);
}

} // namespace

struct Case
{
    std::string scene;
    osg::View::LightingMode lighting;
};

void PrintTo(const Case& c, std::ostream* os)
{
    *os << c.scene << (c.lighting == osg::View::HEADLIGHT ? " with the headlight" : " with its own light only");
}

class OsgviewerScene : public ::testing::TestWithParam<Case>
{
protected:
    void SetUp() override
    {
        const std::string file = dataFile(GetParam().scene);
        osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file);
        scene = dynamic_cast<osgShadow::ShadowedScene*>(node.get());
        ASSERT_NE(scene, nullptr) << file;
        technique = dynamic_cast<Technique*>(scene->getShadowTechnique());
        ASSERT_NE(technique, nullptr) << "the serializer plugin was not found";
    }

    osg::ref_ptr<osgShadow::ShadowedScene> scene;
    osg::ref_ptr<Technique> technique;

    osg::ref_ptr<osg::Image> render(osg::Node* root, const osg::Vec4& clear) const
    {
        return ::render(root, clear, GetParam().lighting);
    }
};

TEST_P(OsgviewerScene, TechniqueRunsAndShadowsTheLight)
{
    osg::ref_ptr<osg::Image> image = render(scene.get(), osg::Vec4(0, 0, 0, 1));
    if (!image) GTEST_SKIP() << "no graphics context";
    const Technique::Statistics stats = technique->getStatistics();
    EXPECT_GE(stats.lightsShadowed, 1u);
    EXPECT_GE(stats.shadowPasses, 1u);
}

TEST_P(OsgviewerScene, MaskHasShadowedAndLitPixels)
{
    technique->setDebugView(Technique::DEBUG_SHADOW_MASK);
    osg::ref_ptr<osg::Image> mask = render(scene.get(), osg::Vec4(1, 1, 1, 1));
    if (!mask) GTEST_SKIP() << "no graphics context";
    const double shadowed = shareBelow(*mask, 0.5);
    EXPECT_GT(shadowed, 0.004) << "no shadow in the mask";
    EXPECT_LT(shadowed, 0.9) << "nothing lit in the mask";
}

// osgviewer's home view looks level from -y at the bounding sphere (CameraManipulator::
// computeHomePosition, fovy 30): the scene file must show its shadows from there, not the
// ground edge-on.
TEST_P(OsgviewerScene, HomeViewShowsTheShadows)
{
    technique->setDebugView(Technique::DEBUG_SHADOW_MASK);
    technique->dirty();
    const osg::BoundingSphere bound = scene->getBound();
    auto renderer = std::make_unique<osshar::Renderer>(WIDTH, HEIGHT, true);
    if (!renderer->valid()) GTEST_SKIP() << "no graphics context";
    renderer->viewer().setLightingMode(GetParam().lighting);
    renderer->setSceneData(scene.get());
    const double distance = bound.radius() / std::sin(osg::DegreesToRadians(15.0));
    renderer->setView({osg::Vec3d(bound.center()) + osg::Vec3d(0.0, -distance, 0.0), bound.center(), {0, 0, 1}, 30.0});
    renderer->timeFrames(1, 1);
    osg::ref_ptr<osg::Image> mask = renderer->renderAndCapture(osg::Vec4(0.5f, 0.5f, 0.5f, 1));
    const int n = mask->s() * mask->t();
    int geometry = 0, shadowed = 0;
    for (int i = 0; i < n; ++i)
    {
        const double v = luminance(mask->data() + 3 * i);
        geometry += std::fabs(v - 0.5) > 0.1;
        shadowed += v < 0.1;
    }
    // Level with the ground, the scene covers a sliver of the view.
    EXPECT_GT(double(geometry) / n, 0.1) << "the scene is seen edge-on from osgviewer's home view";
    EXPECT_GT(double(shadowed) / n, 0.003) << "too little shadow in sight from osgviewer's home view";
}

TEST_P(OsgviewerScene, ShadowsDarkenWhatTheMaskShadows)
{
    // The reference is the same scene and shading with nothing casting a shadow.
    const osg::Vec4 clear(0.2f, 0.2f, 0.3f, 1.0f);
    const unsigned int casts = scene->getCastsShadowTraversalMask();
    scene->setCastsShadowTraversalMask(0);
    osg::ref_ptr<osg::Image> without = render(scene.get(), clear);
    scene->setCastsShadowTraversalMask(casts);
    osg::ref_ptr<osg::Image> with = render(scene.get(), clear);
    technique->setDebugView(Technique::DEBUG_SHADOW_MASK);
    osg::ref_ptr<osg::Image> mask = render(scene.get(), osg::Vec4(1, 1, 1, 1));
    if (!without || !with || !mask) GTEST_SKIP() << "no graphics context";
    const double darker = shareDarker(*with, *without, 0.05);
    const double shadowed = shareBelow(*mask, 0.5);
    EXPECT_GT(darker, 0.004) << "the shaded image shows no shadow";
    // Where the mask is black the light is blocked or faces away; only the blocked part
    // is darker than without shadows, so `darker` is at most about `shadowed`.
    EXPECT_LT(darker, shadowed + 0.01);
}

INSTANTIATE_TEST_SUITE_P(
    DataFiles, OsgviewerScene,
    ::testing::Values(Case{"default", osg::View::HEADLIGHT}, Case{"poles", osg::View::HEADLIGHT},
                      Case{"cubes", osg::View::HEADLIGHT}, Case{"default", osg::View::NO_LIGHT},
                      Case{"poles", osg::View::NO_LIGHT}, Case{"cubes", osg::View::NO_LIGHT}),
    [](const ::testing::TestParamInfo<Case>& info) {
        return info.param.scene + (info.param.lighting == osg::View::HEADLIGHT ? "_headlight" : "_ownLight");
    });
