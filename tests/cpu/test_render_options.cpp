// The renderer's command line (MEASURE.md) refuses what it cannot honour: unknown options,
// values that do not parse, options at the end without their value, a second file name.
#include "Peers.h"
#include "RenderOptions.h"

#include <osgShadowSilhouette/Properties>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

struct Parsed
{
    bool ok = false;
    std::string error;
    osshar::RenderOptions options;
};

Parsed parse(std::vector<std::string> words)
{
    words.insert(words.begin(), "osgsilhouetteshadow");
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    int argc = static_cast<int>(argv.size());
    argv.push_back(nullptr);
    osg::ArgumentParser arguments(&argc, argv.data());
    Parsed p;
    p.ok = osshar::parseRenderOptions(arguments, p.options, p.error);
    return p;
}

struct BadLine
{
    const char* name;
    std::vector<std::string> words;
    const char* named; ///< what the message must name
};

class RefusedLines : public ::testing::TestWithParam<BadLine>
{
};

} // namespace

TEST(RenderOptions, AGoodLineParses)
{
    const Parsed p = parse({"model.osgt", "--mode", "hybrid", "--map-size", "512", "--frames", "3", "--light-dir", "0",
                            "-1", "2", "--offscreen", "--ground", "--per-pixel-lighting", "off"});
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.options.file, "model.osgt");
    EXPECT_EQ(p.options.mode, "hybrid");
    EXPECT_EQ(p.options.mapSize, 512u);
    EXPECT_EQ(p.options.frames, 3);
    ASSERT_EQ(p.options.lights.size(), 1u);
    EXPECT_EQ(p.options.lights[0].vector, osg::Vec3d(0, -1, 2));
    EXPECT_TRUE(p.options.offscreen);
    EXPECT_TRUE(p.options.ground);
    EXPECT_EQ(osshar::propertyValue(p.options, "PerPixelLighting"), 0.0);
    EXPECT_EQ(osshar::propertyValue(p.options, "HybridMethod"), std::nullopt);
}

// MEASURE.md's soft options: a light's size for the exact visibility, and the two masks.
TEST(RenderOptions, SoftShadowOptionsParse)
{
    const Parsed p = parse({"--light-size", "0.25", "--visibility", "vis%d.png", "--reference-visibility", "ref.png"});
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.options.lightSize, 0.25);
    EXPECT_EQ(p.options.visibility, "vis%d.png");
    EXPECT_EQ(p.options.referenceVisibility, "ref.png");
    EXPECT_EQ(parse({"--compare-visibility", "ref%d.png"}).options.compareVisibility, "ref%d.png");
    EXPECT_EQ(parse({}).options.lightSize, 0.0); // a hard shadow unless asked
}

// A walk through a scene: a camera path played one frame per --time-step, scored per frame.
TEST(RenderOptions, CameraPathParses)
{
    const Parsed p =
        parse({"--scene", "outdoor", "--camera-path", "walk.path", "--time-step", "0.25", "--score-every-frame"});
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(p.options.cameraPath, "walk.path");
    EXPECT_EQ(p.options.timeStep, 0.25);
    EXPECT_TRUE(p.options.scoreEveryFrame);
    EXPECT_TRUE(parse({}).options.cameraPath.empty());
    EXPECT_NE(osshar::renderOptionsUsage("osgsilhouetteshadow").find("--camera-path FILE"), std::string::npos);
    // A slow sun: light 0 turns on by the angle every frame.
    const Parsed turning = parse({"--rotating-light", "0.05"});
    ASSERT_TRUE(turning.ok) << turning.error;
    EXPECT_NEAR(turning.options.lightTurnDeg, 0.05, 1e-7);
    EXPECT_TRUE(turning.options.movingLight);
    EXPECT_EQ(parse({"--moving-light"}).options.lightTurnDeg, 0.0);
    EXPECT_NE(osshar::renderOptionsUsage("osgsilhouetteshadow").find("--rotating-light DEG"), std::string::npos);
}

// Every property of the technique can be set by --property NAME=VALUE, read by its table row,
// in order with the shorthands: the last one given wins.
TEST(RenderOptions, PropertiesComeFromTheTable)
{
    using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;
    const Parsed p = parse({"--property", "hybridmethod=lists", "--hybrid-method", "stencil", "--property",
                            "DebugView=mask", "--polygon-offset", "2", "-1", "--property", "ShadowRayOffset=2.5e-4"});
    ASSERT_TRUE(p.ok) << p.error;
    EXPECT_EQ(osshar::propertyValue(p.options, "HybridMethod"), double(Technique::HYBRID_STENCIL_VOLUMES));
    EXPECT_EQ(osshar::propertyValue(p.options, "DebugView"), double(Technique::DEBUG_SHADOW_MASK));
    EXPECT_EQ(osshar::propertyValue(p.options, "PolygonOffsetFactor"), 2.0);
    EXPECT_EQ(osshar::propertyValue(p.options, "PolygonOffsetUnits"), -1.0);
    osg::ref_ptr<Technique> t = new Technique;
    osshar::applyProperties(p.options, *t);
    EXPECT_EQ(t->getHybridMethod(), Technique::HYBRID_STENCIL_VOLUMES);
    EXPECT_EQ(t->getDebugView(), Technique::DEBUG_SHADOW_MASK);
    EXPECT_EQ(t->getPolygonOffsetFactor(), 2.0f);
    EXPECT_EQ(t->getShadowRayOffset(), 2.5e-4f);
    for (const auto& [option, property] : osshar::propertyOptions())
        EXPECT_NE(osgShadowSilhouette::findProperty(property), nullptr) << option << " sets no property";
}

TEST_P(RefusedLines, WithAMessageNamingTheProblem)
{
    const BadLine& c = GetParam();
    const Parsed p = parse(c.words);
    EXPECT_FALSE(p.ok) << c.name << " was accepted";
    EXPECT_NE(p.error.find(c.named), std::string::npos) << c.name << ": the message '" << p.error << "' does not name "
                                                        << c.named;
}

INSTANTIATE_TEST_SUITE_P(
    Lines, RefusedLines,
    ::testing::Values(BadLine{"UnknownOption", {"--bogus-flag"}, "--bogus-flag"},
                      BadLine{"MapSizeNotANumber", {"--map-size", "abc"}, "--map-size"},
                      BadLine{"TrailingOptionWithoutValue", {"--mode", "volume", "--out"}, "--out"},
                      BadLine{"CameraPathWithoutFile", {"--camera-path"}, "--camera-path"},
                      BadLine{"RotatingLightWithoutAngle", {"--rotating-light"}, "--rotating-light"},
                      BadLine{"ZeroFrames", {"--frames", "0"}, "--frames"},
                      BadLine{"TwoFiles", {"a.osgt", "b.osgt"}, "b.osgt"},
                      BadLine{"NegativeMapSize", {"--map-size", "-5"}, "--map-size -5 is out of range (1 to 16384"},
                      BadLine{"WrappingMapSize", {"--map-size", "4294967297"}, "--map-size 4294967297 is out of range"},
                      BadLine{"TooManyLights", {"--max-shadow-lights", "9"}, "--max-shadow-lights 9 is out of range"},
                      BadLine{"SizeNotNumbers", {"--size", "wide", "tall"}, "--size"},
                      BadLine{"UnknownProperty", {"--property", "Sharpness=3"}, "no property is named Sharpness"},
                      BadLine{"UnknownMethod", {"--hybrid-method", "fast"}, "--hybrid-method fast is not one of"},
                      BadLine{"NotOnOff", {"--blocker-culling", "maybe"}, "--blocker-culling maybe is not one of TRUE"},
                      BadLine{"PropertyOutOfRange",
                              {"--property", "BaseTextureUnit=40"},
                              "--property BaseTextureUnit 40 is out of range (1 to 31"},
                      BadLine{
                          "NaNRayOffset", {"--shadow-ray-offset", "nan"}, "--shadow-ray-offset nan is not a finite"},
                      BadLine{"NegativeLightSize", {"--light-size", "-1"}, "--light-size -1 is not a finite number"},
                      BadLine{"NaNLightSize", {"--light-size", "nan"}, "--light-size nan is not a finite number"},
                      BadLine{"LightSizeNotANumber", {"--light-size", "big"}, "--light-size big is not a finite"}),
    [](const ::testing::TestParamInfo<BadLine>& info) { return std::string(info.param.name); });

TEST(RenderOptions, UsageListsEveryBuiltInScene)
{
    const std::string usage = osshar::renderOptionsUsage("osgsilhouetteshadow");
    for (const std::string& scene : osshar::sceneNames())
        EXPECT_NE(usage.find(scene), std::string::npos) << "--help does not list scene " << scene;
}

TEST(RenderOptions, UsageListsEveryPeer)
{
    const std::string usage = osshar::renderOptionsUsage("osgsilhouetteshadow");
    for (const std::string& peer : osshar::peerModes())
        EXPECT_NE(usage.find(peer), std::string::npos) << "--help does not list peer " << peer;
}
