// The table of properties (osgShadowSilhouette/Properties) against the class it describes,
// the strict parser against hand-written cases, and the copies made from it (the README's
// table, the fuzz corpus) against the table.
//
// The README's table is generated: after a change to the table, run
//   scripts/update-properties-table.sh
#include "test_serializer_properties.h"

#include "NotifyCapture.h"

#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace {

using osgShadowSilhouette::findProperty;
using osgShadowSilhouette::properties;
using osgShadowSilhouette::PropertyInfo;
using osstest::Technique;

const std::string BEGIN_MARK = "<!-- BEGIN osgsilhouette-properties -->";
const std::string END_MARK = "<!-- END osgsilhouette-properties -->";

std::string readText(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/** Whether two values are the same in the property's type. */
bool same(const PropertyInfo& p, double a, double b)
{
    return p.type == PropertyInfo::FLOAT ? float(a) == float(b) : a == b;
}

double parsed(const char* property, const std::string& text)
{
    double value = std::nan("");
    std::string error;
    EXPECT_TRUE(osgShadowSilhouette::parsePropertyValue(*findProperty(property), text, value, error))
        << property << " " << text << ": " << error;
    return value;
}

std::string refusal(const char* property, const std::string& text)
{
    double value = 0.0;
    std::string error;
    EXPECT_FALSE(osgShadowSilhouette::parsePropertyValue(*findProperty(property), text, value, error))
        << property << " " << text << " was read as " << value;
    return error;
}

} // namespace

TEST(Properties, NamesAreUniqueAndFoundInAnyCase)
{
    std::set<std::string> names;
    for (const PropertyInfo& p : properties())
    {
        EXPECT_TRUE(names.insert(p.name).second) << p.name << " twice";
        std::string upper = p.name;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        EXPECT_EQ(findProperty(upper), &p) << upper;
        EXPECT_NE(*p.doc, '\0') << p.name << " has no doc";
    }
    EXPECT_EQ(findProperty("Sharpness"), nullptr);
}

// The table's default is what a new technique holds, and its example is another value the
// setter keeps: a row whose default drifted from the class fails here.
TEST(Properties, DefaultsAreTheClasssAndExamplesAreKept)
{
    for (const PropertyInfo& p : properties())
    {
        osg::ref_ptr<Technique> t = new Technique;
        EXPECT_TRUE(same(p, p.get(*t), p.defaultValue)) << p.name << ": the class holds " << p.get(*t);
        EXPECT_TRUE(osgShadowSilhouette::isPropertyValue(p, p.defaultValue)) << p.name;
        EXPECT_TRUE(osgShadowSilhouette::isPropertyValue(p, p.example)) << p.name;
        EXPECT_FALSE(same(p, p.example, p.defaultValue)) << p.name << ": the example is the default";
        p.set(*t, p.example);
        EXPECT_TRUE(same(p, p.get(*t), p.example))
            << p.name << ": the setter made " << p.get(*t) << " of " << p.example;
    }
}

// Each setter refuses what its row refuses (past either end of a range, an enum number no
// value has), with a warning naming the property.
TEST(Properties, SettersRefuseWhatTheTableRefuses)
{
    for (const PropertyInfo& p : properties())
    {
        if (p.type == PropertyInfo::BOOL) continue;
        std::vector<double> outside;
        if (std::isfinite(p.min)) outside.push_back(p.min - 1.0);
        if (std::isfinite(p.max)) outside.push_back(p.max + 1.0);
        if (p.type == PropertyInfo::FLOAT) outside.push_back(std::nan(""));
        for (double bad : outside)
        {
            osstest::NotifyCapture notes;
            osg::ref_ptr<Technique> t = new Technique;
            p.set(*t, p.example);
            p.set(*t, bad);
            const double kept = p.type == PropertyInfo::ENUM ? p.defaultValue : p.example;
            EXPECT_TRUE(same(p, p.get(*t), kept)) << p.name << " took " << bad;
            EXPECT_NE(notes.warnings().find(std::string(p.name) + " "), std::string::npos)
                << p.name << " " << bad << ": no warning naming it\n"
                << notes.warnings();
        }
    }
}

TEST(Properties, NumericRangesComeFromTheTable)
{
    std::size_t numeric = 0;
    for (const PropertyInfo& p : properties())
    {
        const osgShadowSilhouette::NumericPropertyRange* range = osgShadowSilhouette::numericPropertyRange(p.name);
        EXPECT_EQ(range != nullptr, p.numeric()) << p.name;
        if (!range) continue;
        ++numeric;
        EXPECT_EQ(range->min, p.min) << p.name;
        EXPECT_EQ(range->max, p.max) << p.name;
        EXPECT_EQ(range->integer, p.type != PropertyInfo::FLOAT) << p.name;
    }
    EXPECT_EQ(osgShadowSilhouette::numericPropertyRanges().size(), numeric);
}

TEST(Properties, TheParserReadsWholeValuesOnly)
{
    EXPECT_EQ(parsed("ShadowMapSize", "1024"), 1024.0);
    EXPECT_EQ(parsed("LightNum", "-1"), -1.0);
    EXPECT_EQ(parsed("ShadowRayOffset", "2.5e-3"), 2.5e-3);
    EXPECT_EQ(parsed("PolygonOffsetFactor", "-7"), -7.0);
    EXPECT_EQ(parsed("BlockerCulling", "On"), 1.0);
    EXPECT_EQ(parsed("BlockerCulling", "FALSE"), 0.0);
    EXPECT_EQ(parsed("UseDefaultShading", "0"), 0.0);
    EXPECT_EQ(parsed("Mode", "Volume"), double(Technique::SHADOW_VOLUME));
    EXPECT_EQ(parsed("Mode", "SILHOUETTE_MAP"), double(Technique::SILHOUETTE_MAP));
    EXPECT_EQ(parsed("DebugView", "silmap"), double(Technique::DEBUG_SILHOUETTE_MAP));
    EXPECT_EQ(parsed("HybridMethod", "lists"), double(Technique::HYBRID_TRIANGLE_LISTS));
    EXPECT_EQ(parsed("DepthPrepass", "off"), double(Technique::DEPTH_PREPASS_OFF));

    EXPECT_EQ(refusal("ShadowMapSize", "12abc"), "is not a finite number (1 to 16384, whole: texels per side; the "
                                                 "context's GL_MAX_TEXTURE_SIZE may lower it)");
    refusal("ShadowMapSize", "0x10");
    refusal("ShadowMapSize", "");
    refusal("ShadowMapSize", " 12");
    EXPECT_EQ(refusal("LightNum", "1.5"), "is out of range (-1 to 7, whole: -1: every light)");
    refusal("LightNum", "8");
    refusal("ShadowRayOffset", "inf");
    EXPECT_EQ(refusal("BlockerCulling", "yes"), "is not one of TRUE, FALSE (or on, off, 1, 0)");
    EXPECT_EQ(refusal("HybridMethod", "fast"),
              "is not one of HYBRID_AUTO, HYBRID_STENCIL_VOLUMES, HYBRID_TRIANGLE_LISTS (or auto, stencil, lists)");
    refusal("Mode", "3");
    refusal("Mode", "SHADOW");
}

TEST(Properties, ValuesAreWrittenAsFilesHoldThem)
{
    const PropertyInfo& offset = *findProperty("ShadowRayOffset");
    EXPECT_EQ(osgShadowSilhouette::formatPropertyValue(offset, offset.defaultValue), "1e-06");
    EXPECT_EQ(osgShadowSilhouette::formatPropertyValue(offset, 2.5e-4f), "0.00025");
    EXPECT_EQ(osgShadowSilhouette::formatPropertyValue(*findProperty("ShadowMapSize"), 2048), "2048");
    EXPECT_EQ(osgShadowSilhouette::formatPropertyValue(*findProperty("PerPixelLighting"), 1), "TRUE");
    EXPECT_EQ(osgShadowSilhouette::formatPropertyValue(*findProperty("Mode"), 2), "HYBRID");
    EXPECT_EQ(osgShadowSilhouette::propertyValueSyntax(*findProperty("DepthPrepass")), "auto|on|off");
    EXPECT_EQ(osgShadowSilhouette::propertyValueSyntax(*findProperty("LightNum")), "n");
    // Every value a row formats, the parser reads back to the same value.
    for (const PropertyInfo& p : properties())
        for (double v : {p.defaultValue, p.example})
            EXPECT_TRUE(same(p, parsed(p.name, osgShadowSilhouette::formatPropertyValue(p, v)), v)) << p.name;
}

TEST(Properties, SettingFromTextWarnsAndKeeps)
{
    osstest::NotifyCapture notes;
    osg::ref_ptr<Technique> t = new Technique;
    EXPECT_TRUE(osgShadowSilhouette::setPropertyFromText(*t, "hybridmethod", "stencil", "here"));
    EXPECT_EQ(t->getHybridMethod(), Technique::HYBRID_STENCIL_VOLUMES);
    EXPECT_FALSE(osgShadowSilhouette::setPropertyFromText(*t, "HybridMethod", "quick", "here"));
    EXPECT_EQ(t->getHybridMethod(), Technique::HYBRID_STENCIL_VOLUMES);
    EXPECT_TRUE(notes.warned("here: HybridMethod quick is not one of HYBRID_AUTO")) << notes.warnings();
    EXPECT_TRUE(notes.warned("; keeping HYBRID_STENCIL_VOLUMES")) << notes.warnings();
    EXPECT_FALSE(osgShadowSilhouette::setPropertyFromText(*t, "Sharpness", "3", "here"));
    EXPECT_TRUE(notes.warned("here: no property is named Sharpness")) << notes.warnings();
}

// The README's table of properties is propertiesMarkdown(), between its markers. With
// OSS_UPDATE_PROPERTIES_TABLE=1 the test writes it there instead.
TEST(Properties, TheReadmeTableIsTheTables)
{
    const std::string path = osstest::sourceDir() + "/README.md";
    std::string readme = readText(path);
    const std::size_t begin = readme.find(BEGIN_MARK), end = readme.find(END_MARK);
    ASSERT_NE(begin, std::string::npos) << path << " has no " << BEGIN_MARK;
    ASSERT_NE(end, std::string::npos) << path << " has no " << END_MARK;
    const std::size_t from = begin + BEGIN_MARK.size() + 1;
    const std::string expected = osgShadowSilhouette::propertiesMarkdown();
    const char* update = std::getenv("OSS_UPDATE_PROPERTIES_TABLE");
    if (update && std::string(update) == "1")
    {
        readme.replace(from, end - from, expected);
        std::ofstream(path) << readme;
        return;
    }
    EXPECT_EQ(readme.substr(from, end - from), expected)
        << "README.md's table of properties differs from the table: run scripts/update-properties-table.sh";
}

// The fuzzer's seed of every property holds each property at a value other than its default.
TEST(Properties, TheFuzzSeedHoldsEveryProperty)
{
    const std::string seed = readText(osstest::sourceDir() + "/fuzz/corpus/fuzz_osgt_technique/all_properties.osgt");
    ASSERT_FALSE(seed.empty());
    for (const PropertyInfo& p : properties())
    {
        const std::size_t at = seed.find(std::string("\n   ") + p.name + " ");
        ASSERT_NE(at, std::string::npos) << p.name << " is missing from all_properties.osgt";
        std::istringstream line(seed.substr(at));
        std::string name, text;
        line >> name >> text;
        const double value = parsed(p.name, text);
        EXPECT_FALSE(same(p, value, p.defaultValue)) << p.name << " is at its default in all_properties.osgt";
    }
}
