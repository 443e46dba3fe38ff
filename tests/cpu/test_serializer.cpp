// The serializer plugin osgdb_serializers_osgshadowsilhouette: every property of
// SilhouetteShadowTechnique survives .osgt, .osgb and .osgx (through osgDB and through the
// stock osgconv), enums are written by name, and bad values are reported and refused.
#include "test_serializer_properties.h"

#include <gtest/gtest.h>

#include <osg/Notify>
#include <osgDB/ObjectWrapper>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <osgShadow/ShadowedScene>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;
using osstest::Technique;

namespace {

/** A folder of this process, removed at exit. */
fs::path tempDir()
{
    struct Folder
    {
        fs::path path = fs::temp_directory_path() / ("oss_serializer_" + std::to_string(::getpid()));
        ~Folder() { fs::remove_all(path); }
    };
    static Folder folder;
    fs::create_directories(folder.path);
    return folder.path;
}

std::string readText(const fs::path& file)
{
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeText(const fs::path& file, const std::string& text)
{
    std::ofstream(file) << text;
}

/** A ShadowedScene with a non-default technique, non-default masks and one child. */
osg::ref_ptr<osgShadow::ShadowedScene> nonDefaultScene()
{
    osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene(osstest::nonDefaultTechnique().get());
    scene->getShadowSettings()->setReceivesShadowTraversalMask(0x1);
    scene->getShadowSettings()->setCastsShadowTraversalMask(0x2);
    scene->addChild(new osg::Group);
    return scene;
}

/** The technique of a scene file's ShadowedScene, or null. */
const Technique* techniqueOf(const osg::Node* node)
{
    const osgShadow::ShadowedScene* scene = dynamic_cast<const osgShadow::ShadowedScene*>(node);
    return scene ? dynamic_cast<const Technique*>(scene->getShadowTechnique()) : nullptr;
}

/** Collects what OSG reports while it lives. */
class CapturedNotify : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity, const char* message) override { text += message; }
    std::string text;
};

class NotifyCapture
{
public:
    NotifyCapture() : _handler(new CapturedNotify) { osg::setNotifyHandler(_handler.get()); }
    ~NotifyCapture() { osg::setNotifyHandler(new osg::StandardNotifyHandler); }
    const std::string& text() const { return _handler->text; }

private:
    osg::ref_ptr<CapturedNotify> _handler;
};

/** The technique after writing a non-default scene as `ext` and reading it back. */
osg::ref_ptr<osg::Node> roundTrip(const std::string& ext)
{
    const fs::path file = tempDir() / ("round_trip." + ext);
    EXPECT_TRUE(osgDB::writeNodeFile(*nonDefaultScene(), file.string()));
    return osgDB::readRefNodeFile(file.string());
}

bool commandExists(const std::string& name)
{
    return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

} // namespace

TEST(Serializer, EveryRowSetsANonDefaultValue)
{
    osg::ref_ptr<Technique> defaults = new Technique;
    osg::ref_ptr<Technique> changed = osstest::nonDefaultTechnique();
    for (const osstest::PropertyRow& row : osstest::propertyRows())
        EXPECT_NE(row.get(*defaults), row.get(*changed)) << row.name << ": the row's value is the default";
}

TEST(Serializer, WrapperHasOneSerializerPerRow)
{
    osgDB::ObjectWrapper* wrapper = osgDB::Registry::instance()->getObjectWrapperManager()->findWrapper(
        "osgShadowSilhouette::SilhouetteShadowTechnique");
    ASSERT_NE(wrapper, nullptr) << "osgdb_serializers_osgshadowsilhouette not found (OSG_LIBRARY_PATH?)";
    std::set<std::string> serialized, rows;
    for (const auto& s : wrapper->getSerializerList()) serialized.insert(s->getName());
    for (const osstest::PropertyRow& row : osstest::propertyRows()) rows.insert(row.name);
    EXPECT_EQ(serialized, rows);
}

TEST(Serializer, EverySetterOfTheHeaderIsSerialized)
{
    const std::string header = readText(fs::path(osstest::sourceDir()) / "osgShadowSilhouette" / "SilhouetteShadowTechnique");
    ASSERT_FALSE(header.empty());
    std::set<std::string> rows;
    for (const osstest::PropertyRow& row : osstest::propertyRows()) rows.insert(row.name);
    const std::regex setter(R"(\bvoid\s+set(\w+)\s*\()");
    int setters = 0;
    // Stats: where statistics go, an object of the application; Tuning: switches for
    // diagnostics and measurements, which never change the picture.
    const std::set<std::string> runtimeOnly = {"Stats", "Tuning"};
    for (std::sregex_iterator it(header.begin(), header.end(), setter), end; it != end; ++it, ++setters)
        EXPECT_TRUE(rows.count((*it)[1].str()) || runtimeOnly.count((*it)[1].str()))
            << "set" << (*it)[1].str() << " has no serializer row";
    EXPECT_GE(setters, int(rows.size()));
}

TEST(Serializer, EveryEnumValueOfTheHeaderHasAName)
{
    const std::string header = readText(fs::path(osstest::sourceDir()) / "osgShadowSilhouette" / "SilhouetteShadowTechnique");
    osgDB::ObjectWrapper* wrapper = osgDB::Registry::instance()->getObjectWrapperManager()->findWrapper(
        "osgShadowSilhouette::SilhouetteShadowTechnique");
    ASSERT_NE(wrapper, nullptr);
    int enums = 0;
    for (const auto& serializer : wrapper->getSerializerList())
    {
        osgDB::IntLookup* lookup = serializer->getIntLookup();
        if (!lookup) continue;
        ++enums;
        std::smatch block;
        const std::regex enumBlock("enum\\s+" + serializer->getName() + "\\s*\\{([^}]*)\\}");
        ASSERT_TRUE(std::regex_search(header, block, enumBlock)) << "enum " << serializer->getName();
        const std::string body = block[1].str();
        const std::regex value(R"((\w+)\s*=)");
        for (std::sregex_iterator it(body.begin(), body.end(), value), end; it != end; ++it)
            EXPECT_TRUE(lookup->getStringToValue().count((*it)[1].str()))
                << serializer->getName() << "::" << (*it)[1].str() << " has no ADD_ENUM_VALUE";
    }
    EXPECT_EQ(enums, 6); // Mode, GpuExtraction, DebugView, HybridMethod, DepthPrepass, Filter
}

class RoundTrip : public ::testing::TestWithParam<std::tuple<std::string, size_t>>
{
};

TEST_P(RoundTrip, KeepsTheProperty)
{
    const osstest::PropertyRow& row = osstest::propertyRows()[std::get<1>(GetParam())];
    osg::ref_ptr<osg::Node> node = roundTrip(std::get<0>(GetParam()));
    const Technique* read = techniqueOf(node.get());
    ASSERT_NE(read, nullptr);
    EXPECT_EQ(row.get(*read), row.get(*osstest::nonDefaultTechnique())) << row.name;
}

INSTANTIATE_TEST_SUITE_P(
    Formats, RoundTrip,
    ::testing::Combine(::testing::Values("osgt", "osgb", "osgx"),
                       ::testing::Range<size_t>(0, osstest::propertyRows().size())),
    [](const ::testing::TestParamInfo<RoundTrip::ParamType>& info) {
        return std::get<0>(info.param) + "_" + osstest::propertyRows()[std::get<1>(info.param)].name;
    });

class SceneRoundTrip : public ::testing::TestWithParam<std::string>
{
};

TEST_P(SceneRoundTrip, KeepsShadowSettingsMasksAndChildren)
{
    osg::ref_ptr<osg::Node> node = roundTrip(GetParam());
    const osgShadow::ShadowedScene* scene = dynamic_cast<const osgShadow::ShadowedScene*>(node.get());
    ASSERT_NE(scene, nullptr);
    EXPECT_EQ(scene->getReceivesShadowTraversalMask(), 0x1u);
    EXPECT_EQ(scene->getCastsShadowTraversalMask(), 0x2u);
    EXPECT_EQ(scene->getNumChildren(), 1u);
    ASSERT_NE(techniqueOf(node.get()), nullptr);
    EXPECT_EQ(techniqueOf(node.get())->getShadowedScene(), scene);
}

INSTANTIATE_TEST_SUITE_P(Formats, SceneRoundTrip, ::testing::Values("osgt", "osgb", "osgx"));

// PolygonOffsetFactor: negative (the default) picks the factor per mode; a value of one's
// own applies to every mode.
TEST(PolygonOffsetFactor, AutomaticLeavesHybridsMapUnbiased)
{
    osg::ref_ptr<Technique> t = new Technique;
    EXPECT_EQ(t->getPolygonOffsetFactor(), Technique::AUTOMATIC_POLYGON_OFFSET_FACTOR);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::HYBRID), 0.0f); // plane tests in the lookup
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SHADOW_MAP), 1.1f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SILHOUETTE_MAP), 1.1f);
    // A warped map (PerspectiveWarp): SHADOW_MAP's acne on surfaces the light grazes.
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SHADOW_MAP, true), 2.0f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SILHOUETTE_MAP, true), 1.1f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::HYBRID, true), 0.0f);
    t->setHybridEdgeMask(false);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::HYBRID), 0.0f);
    t->setHybridEdgeMask(true);
    t->setPolygonOffsetFactor(0.5f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::HYBRID), 0.5f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SHADOW_MAP), 0.5f);
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::SHADOW_MAP, true), 0.5f);
    t->setPolygonOffsetFactor(-3.0f);
    EXPECT_EQ(t->getPolygonOffsetFactor(), Technique::AUTOMATIC_POLYGON_OFFSET_FACTOR);
    NotifyCapture capture;
    t->setPolygonOffsetFactor(std::numeric_limits<float>::infinity());
    EXPECT_NE(capture.text().find("PolygonOffsetFactor inf is not a finite number"), std::string::npos) << capture.text();
    EXPECT_FLOAT_EQ(t->getEffectivePolygonOffsetFactor(Technique::HYBRID), 0.0f);
}

TEST(Serializer, TextWritesEnumsByName)
{
    const fs::path file = tempDir() / "names.osgt";
    ASSERT_TRUE(osgDB::writeNodeFile(*nonDefaultScene(), file.string()));
    const std::string text = readText(file);
    EXPECT_NE(text.find("osgShadowSilhouette::SilhouetteShadowTechnique"), std::string::npos);
    EXPECT_NE(text.find("Mode HYBRID"), std::string::npos) << text;
    EXPECT_NE(text.find("DebugView DEBUG_SHADOW_MASK"), std::string::npos) << text;
}

TEST(Serializer, ReadsTheShortModeNames)
{
    const fs::path file = tempDir() / "short.osgt";
    ASSERT_TRUE(osgDB::writeNodeFile(*nonDefaultScene(), file.string()));
    writeText(file, std::regex_replace(readText(file), std::regex("Mode HYBRID"), "Mode volume"));
    NotifyCapture capture;
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file.string());
    ASSERT_NE(techniqueOf(node.get()), nullptr);
    EXPECT_EQ(techniqueOf(node.get())->getMode(), Technique::SHADOW_VOLUME);
    EXPECT_EQ(capture.text().find("Mode"), std::string::npos) << capture.text();
}

struct BadValue
{
    const char* name;
    const char* replace;      ///< regex of the line in the written file
    const char* with;         ///< the bad line
    const char* expectedText; ///< must appear in the warning
    std::function<bool(const Technique&)> clamped;
};

class BadInput : public ::testing::TestWithParam<BadValue>
{
};

TEST_P(BadInput, WarnsNamingPropertyValueAndRangeAndKeepsTheDefault)
{
    const BadValue& bad = GetParam();
    const fs::path file = tempDir() / (std::string("bad_") + bad.name + ".osgt");
    ASSERT_TRUE(osgDB::writeNodeFile(*nonDefaultScene(), file.string()));
    const std::string text = std::regex_replace(readText(file), std::regex(bad.replace), bad.with);
    ASSERT_NE(text.find(bad.with), std::string::npos);
    writeText(file, text);

    NotifyCapture capture;
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file.string());
    const Technique* t = techniqueOf(node.get());
    ASSERT_NE(t, nullptr) << capture.text();
    EXPECT_NE(capture.text().find(bad.expectedText), std::string::npos) << capture.text();
    EXPECT_TRUE(bad.clamped(*t));
    // The properties after the bad one are still read.
    EXPECT_EQ(t->getDebugLight(), 2u);
}

INSTANTIATE_TEST_SUITE_P(
    Values, BadInput,
    ::testing::Values(
        BadValue{"UnknownMode", "Mode HYBRID", "Mode FANCY", "Mode FANCY is not one of SHADOW_MAP, SILHOUETTE_MAP",
                 [](const Technique& t) { return t.getMode() == Technique::SHADOW_MAP; }},
        BadValue{"NumericMode", "Mode HYBRID", "Mode 7", "Mode 7 is not one of SHADOW_MAP",
                 [](const Technique& t) { return t.getMode() == Technique::SHADOW_MAP; }},
        BadValue{"UnknownDebugView", "DebugView DEBUG_SHADOW_MASK", "DebugView XRAY",
                 "DebugView XRAY is not one of DEBUG_NONE",
                 [](const Technique& t) { return t.getDebugView() == Technique::DEBUG_NONE; }},
        BadValue{"ZeroMapSize", "ShadowMapSize 1024", "ShadowMapSize 0", "ShadowMapSize 0 is out of range (1 to 16384",
                 [](const Technique& t) { return t.getShadowMapSize() == 2048u; }},
        BadValue{"HugeMapSize", "ShadowMapSize 1024", "ShadowMapSize 99999", "ShadowMapSize 99999 is out of range",
                 [](const Technique& t) { return t.getShadowMapSize() == 2048u; }},
        BadValue{"WrappingMapSize", "ShadowMapSize 1024", "ShadowMapSize 4294967297",
                 "ShadowMapSize 4294967297 is out of range (1 to 16384, whole",
                 [](const Technique& t) { return t.getShadowMapSize() == 2048u; }},
        BadValue{"NegativeMapSize", "ShadowMapSize 1024", "ShadowMapSize -5", "ShadowMapSize -5 is out of range",
                 [](const Technique& t) { return t.getShadowMapSize() == 2048u; }},
        BadValue{"WordMapSize", "ShadowMapSize 1024", "ShadowMapSize abc", "ShadowMapSize abc is not a finite number",
                 [](const Technique& t) { return t.getShadowMapSize() == 2048u; }},
        BadValue{"TooManyLights", "MaxShadowLights 2", "MaxShadowLights 99",
                 "MaxShadowLights 99 is out of range (1 to 8",
                 [](const Technique& t) { return t.getMaxShadowLights() == 4u; }},
        BadValue{"NegativeLightNum", "LightNum 3", "LightNum -7",
                 "LightNum -7 is out of range (-1 to 7, whole: -1: every light); keeping -1",
                 [](const Technique& t) { return t.getLightNum() == -1; }},
        BadValue{"TextureUnitZero", "BaseTextureUnit 5", "BaseTextureUnit 0", "BaseTextureUnit 0 is out of range",
                 [](const Technique& t) { return t.getBaseTextureUnit() == 8u; }},
        BadValue{"UnknownBool", "UseDefaultShading FALSE", "UseDefaultShading MAYBE",
                 "UseDefaultShading MAYBE is not one of TRUE, FALSE",
                 [](const Technique& t) { return t.getUseDefaultShading(); }},
        BadValue{"NegativeRayOffset", "ShadowRayOffset [0-9.e-]+", "ShadowRayOffset -0.5",
                 "ShadowRayOffset -0.5 is out of range (0 to 1",
                 [](const Technique& t) { return t.getShadowRayOffset() == Technique::DEFAULT_SHADOW_RAY_OFFSET; }}),
    [](const ::testing::TestParamInfo<BadValue>& info) { return std::string(info.param.name); });

TEST(Serializer, OsgconvRoundTripKeepsEveryProperty)
{
    if (!commandExists("osgconv")) GTEST_SKIP() << "osgconv (Debian package openscenegraph) is not installed";
    const fs::path dir = tempDir();
    const fs::path start = dir / "osgconv_0.osgt";
    ASSERT_TRUE(osgDB::writeNodeFile(*nonDefaultScene(), start.string()));
    const std::vector<std::string> chain = {"osgconv_0.osgt", "osgconv_1.osgb", "osgconv_2.osgx", "osgconv_3.osgt"};
    for (size_t i = 1; i < chain.size(); ++i)
    {
        const std::string cmd = "osgconv " + (dir / chain[i - 1]).string() + " " + (dir / chain[i]).string() + " >/dev/null 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    }
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile((dir / chain.back()).string());
    const Technique* read = techniqueOf(node.get());
    ASSERT_NE(read, nullptr);
    osg::ref_ptr<Technique> expected = osstest::nonDefaultTechnique();
    for (const osstest::PropertyRow& row : osstest::propertyRows())
        EXPECT_EQ(row.get(*read), row.get(*expected)) << row.name;
}
