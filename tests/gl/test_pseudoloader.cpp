// The .silhouette pseudo-loader (plugins/silhouette): model.<ext>[.<mode>].silhouette wraps
// any model in a ShadowedScene with SilhouetteShadowTechnique, takes options from osgDB's
// option string, adds a light to a model without one, and the result renders shadows.
#include "Meshes.h"
#include "Offscreen.h"
#include "Scenes.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <gtest/gtest.h>

#include <osg/Geode>
#include <osg/LightSource>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgShadow/ShadowedScene>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;

namespace {

/** A folder of this process, removed at exit. */
fs::path tempDir()
{
    struct Folder
    {
        fs::path path = fs::temp_directory_path() / ("oss_pseudoloader_" + std::to_string(::getpid()));
        ~Folder() { fs::remove_all(path); }
    };
    static Folder folder;
    fs::create_directories(folder.path);
    return folder.path;
}

/** A ground and a box above it, without any light: the kind of model osgviewer is given. */
std::string modelWithoutLight()
{
    const fs::path file = tempDir() / "box.osgt";
    if (!fs::exists(file))
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(osshar::makeGround(0, 0, 10).get());
        geode->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 1.5f), osg::Vec3(1.5f, 1.5f, 1.5f)).get());
        EXPECT_TRUE(osgDB::writeNodeFile(*geode, file.string()));
    }
    return file.string();
}

/** data/<scene>.osgt of the source tree ($OSS_SOURCE_DIR, else found from this file's path). */
std::string dataFile(const std::string& scene)
{
    const char* env = std::getenv("OSS_SOURCE_DIR");
    const std::string source = env && *env ? std::string(env) : fs::path(__FILE__).parent_path().parent_path().parent_path().string();
    return source + "/data/" + scene + ".osgt";
}

osg::ref_ptr<osgShadow::ShadowedScene> load(const std::string& file, const std::string& optionString = "")
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options(optionString);
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file, options.get());
    return dynamic_cast<osgShadow::ShadowedScene*>(node.get());
}

Technique* techniqueOf(osgShadow::ShadowedScene* scene)
{
    return scene ? dynamic_cast<Technique*>(scene->getShadowTechnique()) : nullptr;
}

class CapturedNotify : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity, const char* message) override { text += message; }
    std::string text;
};

/** Captures OSG's messages down to NOTICE while it lives. */
class NotifyCapture
{
public:
    NotifyCapture() : _handler(new CapturedNotify), _level(osg::getNotifyLevel())
    {
        osg::setNotifyLevel(osg::NOTICE);
        osg::setNotifyHandler(_handler.get());
    }
    ~NotifyCapture()
    {
        osg::setNotifyHandler(new osg::StandardNotifyHandler);
        osg::setNotifyLevel(_level);
    }
    const std::string& text() const { return _handler->text; }

private:
    osg::ref_ptr<CapturedNotify> _handler;
    osg::NotifySeverity _level;
};

size_t occurrences(const std::string& text, const std::string& word)
{
    size_t n = 0;
    for (size_t pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) ++n;
    return n;
}

double shareBelow(const osg::Image& image, double threshold)
{
    const int n = image.s() * image.t();
    int count = 0;
    for (int i = 0; i < n; ++i) count += image.data()[3 * i + 1] < threshold * 255.0;
    return double(count) / n;
}

} // namespace

TEST(PseudoLoader, WrapsAModelInTheDefaultMode)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = load(modelWithoutLight() + ".silhouette");
    ASSERT_NE(techniqueOf(scene.get()), nullptr);
    EXPECT_EQ(techniqueOf(scene.get())->getMode(), Technique::SHADOW_MAP);
    EXPECT_EQ(techniqueOf(scene.get())->getShadowMapSize(), osg::ref_ptr<Technique>(new Technique)->getShadowMapSize());
}

TEST(PseudoLoader, AddsADirectionalLightOnceAndSaysSoOnce)
{
    NotifyCapture capture;
    osg::ref_ptr<osgShadow::ShadowedScene> first = load(modelWithoutLight() + ".silhouette");
    osg::ref_ptr<osgShadow::ShadowedScene> second = load(modelWithoutLight() + ".hybrid.silhouette");
    for (osgShadow::ShadowedScene* scene : {first.get(), second.get()})
    {
        ASSERT_NE(scene, nullptr);
        const std::vector<osshar::LightInScene> lights = osshar::findLights(scene);
        ASSERT_EQ(lights.size(), 1u);
        EXPECT_EQ(lights[0].source->getLight()->getPosition().w(), 0.0f) << "not directional";
        EXPECT_GT(lights[0].source->getLight()->getPosition().z(), 0.0f) << "not from above";
    }
    EXPECT_EQ(occurrences(capture.text(), "added a directional light"), 1u) << capture.text();
}

TEST(PseudoLoader, KeepsTheModelsOwnLight)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = load(dataFile("default") + ".silhouette");
    ASSERT_NE(scene, nullptr);
    EXPECT_EQ(osshar::findLights(scene.get()).size(), 1u);
}

TEST(PseudoLoader, DoesNotWrapAShadowedSceneTwice)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = load(dataFile("default") + ".hybrid.silhouette");
    ASSERT_NE(techniqueOf(scene.get()), nullptr);
    EXPECT_EQ(techniqueOf(scene.get())->getMode(), Technique::HYBRID);
    ASSERT_GE(scene->getNumChildren(), 1u);
    EXPECT_EQ(dynamic_cast<osgShadow::ShadowedScene*>(scene->getChild(0)), nullptr);
}

struct ModeRow
{
    const char* extension;
    Technique::Mode mode;
};

class PseudoLoaderMode : public ::testing::TestWithParam<ModeRow>
{
};

TEST_P(PseudoLoaderMode, TheExtensionChoosesTheMode)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene =
        load(modelWithoutLight() + "." + GetParam().extension + ".silhouette");
    ASSERT_NE(techniqueOf(scene.get()), nullptr);
    EXPECT_EQ(techniqueOf(scene.get())->getMode(), GetParam().mode);
}

INSTANTIATE_TEST_SUITE_P(Modes, PseudoLoaderMode,
                         ::testing::Values(ModeRow{"shadowmap", Technique::SHADOW_MAP},
                                           ModeRow{"silhouette", Technique::SILHOUETTE_MAP},
                                           ModeRow{"hybrid", Technique::HYBRID},
                                           ModeRow{"volume", Technique::SHADOW_VOLUME}),
                         [](const ::testing::TestParamInfo<ModeRow>& info) { return std::string(info.param.extension); });

TEST(PseudoLoader, AppliesTheOptionString)
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = load(
        modelWithoutLight() + ".silhouette",
        "ShadowMapSize=1024 Mode=volume DebugView=mask DebugLight=0 LightNum=0 MaxShadowLights=2 "
        "BaseTextureUnit=6 PolygonOffsetFactor=2 PolygonOffsetUnits=8 UseDefaultShading=off ShadowRayOffset=3e-5 "
        "PerPixelLighting=off PerspectiveWarp=on Cascades=3 SomeOtherPlugin=1");
    Technique* t = techniqueOf(scene.get());
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->getShadowMapSize(), 1024u);
    EXPECT_EQ(t->getMode(), Technique::SHADOW_VOLUME);
    EXPECT_EQ(t->getDebugView(), Technique::DEBUG_SHADOW_MASK);
    EXPECT_EQ(t->getLightNum(), 0);
    EXPECT_EQ(t->getMaxShadowLights(), 2u);
    EXPECT_EQ(t->getBaseTextureUnit(), 6u);
    EXPECT_FLOAT_EQ(t->getPolygonOffsetFactor(), 2.0f);
    EXPECT_FLOAT_EQ(t->getPolygonOffsetUnits(), 8.0f);
    EXPECT_FALSE(t->getUseDefaultShading());
    EXPECT_FLOAT_EQ(t->getShadowRayOffset(), 3e-5f);
    EXPECT_FALSE(t->getPerPixelLighting());
    EXPECT_TRUE(t->getPerspectiveWarp());
    EXPECT_EQ(t->getCascades(), 3u);
}

TEST(PseudoLoader, WarnsAboutBadOptionsNamingThem)
{
    NotifyCapture capture;
    osg::ref_ptr<osgShadow::ShadowedScene> scene =
        load(modelWithoutLight() + ".silhouette", "ShadowMapSize=big Mode=fancy DebugView=xray MaxShadowLights=99");
    Technique* t = techniqueOf(scene.get());
    ASSERT_NE(t, nullptr);
    EXPECT_NE(capture.text().find("ShadowMapSize big is not a finite number"), std::string::npos) << capture.text();
    EXPECT_NE(capture.text().find("Mode fancy is not one of SHADOW_MAP, SILHOUETTE_MAP, HYBRID, SHADOW_VOLUME (or "
                                  "shadowmap, silhouette, hybrid, volume); keeping SHADOW_MAP"),
              std::string::npos)
        << capture.text();
    EXPECT_NE(capture.text().find("DebugView xray is not one of DEBUG_NONE"), std::string::npos) << capture.text();
    EXPECT_NE(capture.text().find("MaxShadowLights 99 is out of range (1 to 8, whole); keeping 4"), std::string::npos)
        << capture.text();
    EXPECT_EQ(t->getShadowMapSize(), osg::ref_ptr<Technique>(new Technique)->getShadowMapSize());
    EXPECT_EQ(t->getMode(), Technique::SHADOW_MAP);
    EXPECT_EQ(t->getMaxShadowLights(), 4u);
}

// Values that would wrap or be clamped quietly are refused, and the defaults kept.
TEST(PseudoLoader, RefusesValuesOutsideTheRange)
{
    NotifyCapture capture;
    osg::ref_ptr<osgShadow::ShadowedScene> scene =
        load(modelWithoutLight() + ".silhouette", "ShadowMapSize=4294967297 DebugLight=-1 ShadowRayOffset=nan");
    Technique* t = techniqueOf(scene.get());
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->getShadowMapSize(), 2048u);
    EXPECT_EQ(t->getDebugLight(), 0u);
    EXPECT_EQ(t->getShadowRayOffset(), Technique::DEFAULT_SHADOW_RAY_OFFSET);
    for (const char* part : {"ShadowMapSize 4294967297 is out of range (1 to 16384", "DebugLight -1 is out of range",
                             "ShadowRayOffset nan is not a finite number"})
        EXPECT_NE(capture.text().find(part), std::string::npos) << part << "\n" << capture.text();
}

TEST(PseudoLoader, NamesAnUnknownModeAndTheValidOnes)
{
    NotifyCapture capture;
    EXPECT_EQ(load(modelWithoutLight() + ".fancy.silhouette"), nullptr);
    EXPECT_NE(capture.text().find("unknown mode \"fancy\""), std::string::npos) << capture.text();
    for (const char* mode : {"shadowmap", "silhouette", "hybrid", "volume"})
        EXPECT_NE(capture.text().find(mode), std::string::npos) << capture.text();
}

TEST(PseudoLoader, UnknownModelIsNotLoaded)
{
    EXPECT_EQ(load((tempDir() / "missing.osgt.silhouette").string()), nullptr);
}

TEST(PseudoLoader, RendersShadowsAndReportsStatistics)
{
    const fs::path report = tempDir() / "report.txt";
    osg::ref_ptr<osgShadow::ShadowedScene> scene =
        load(modelWithoutLight() + ".silhouette", "DebugView=mask ShadowMapSize=1024 Report=" + report.string());
    ASSERT_NE(techniqueOf(scene.get()), nullptr);
    osshar::Renderer renderer(320, 240, true);
    if (!renderer.valid()) GTEST_SKIP() << "no graphics context";
    renderer.setSceneData(scene.get());
    renderer.setView(osshar::defaultView(scene->getBound()));
    renderer.timeFrames(1, 1);
    osg::ref_ptr<osg::Image> mask = renderer.renderAndCapture(osg::Vec4(1, 1, 1, 1));
    ASSERT_NE(mask, nullptr);
    EXPECT_GT(shareBelow(*mask, 0.5), 0.004) << "the box casts no shadow";
    EXPECT_LT(shareBelow(*mask, 0.5), 0.9);

    std::ifstream in(report);
    std::string line, last;
    int lines = 0;
    while (std::getline(in, line)) last = line, ++lines;
    EXPECT_GE(lines, 3);
    EXPECT_NE(last.find("lightsShadowed=1"), std::string::npos) << last;
    EXPECT_EQ(last.find("shadowPasses=0 depthPassesReused=0"), std::string::npos) << last;
}
