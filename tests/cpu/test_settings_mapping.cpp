// osgShadow::ShadowSettings over the technique's properties (docs/shadow-settings.md): a
// setting away from osgShadow's default applies where the property is at the technique's
// default, the property wins otherwise (with a warning), out-of-range values and settings
// without a meaning here warn, each naming the setting and its value.
#include <osgShadowSilhouette/SettingsMapping>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <gtest/gtest.h>

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgShadow/ShadowedScene>

#include <cfloat>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <unistd.h>

using namespace osgShadowSilhouette;

namespace {

/** The settings after @p change, as the technique reads them. */
ShadowSettingsValues settingsWith(const std::function<void(osgShadow::ShadowSettings&)>& change)
{
    osg::ref_ptr<osgShadow::ShadowSettings> s = new osgShadow::ShadowSettings;
    change(*s);
    return ShadowSettingsValues(*s);
}

/** The one warning of @p mapped ("" if none; a failure if more). */
std::string onlyWarning(const MappedSettings& mapped)
{
    EXPECT_LE(mapped.warnings.size(), 1u);
    return mapped.warnings.empty() ? std::string() : mapped.warnings.front().message;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(SettingsMapping, DefaultsChangeNothing)
{
    const MappedSettings mapped = mapShadowSettings(ShadowSettingsValues(), MappedProperties());
    EXPECT_EQ(mapped.values, MappedProperties());
    EXPECT_EQ(mapped.maximumShadowDistance, DBL_MAX);
    EXPECT_TRUE(mapped.warnings.empty());
    EXPECT_EQ(ShadowSettingsValues(), ShadowSettingsValues(*osg::ref_ptr<osgShadow::ShadowSettings>(new osgShadow::ShadowSettings)));
}

TEST(SettingsMapping, TextureSizeSetsTheMapSize)
{
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) { s.setTextureSize(osg::Vec2s(256, 256)); });
    const MappedSettings mapped = mapShadowSettings(s, MappedProperties());
    EXPECT_EQ(mapped.values.shadowMapSize, 256u);
    EXPECT_TRUE(mapped.warnings.empty());
}

TEST(SettingsMapping, ANonSquareTextureSizeTakesTheLargerSideWithAWarning)
{
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) { s.setTextureSize(osg::Vec2s(512, 1024)); });
    const MappedSettings mapped = mapShadowSettings(s, MappedProperties());
    EXPECT_EQ(mapped.values.shadowMapSize, 1024u);
    const std::string w = onlyWarning(mapped);
    EXPECT_TRUE(contains(w, "TextureSize 512x1024 is not square")) << w;
    EXPECT_TRUE(contains(w, "1024x1024 (the larger side)")) << w;
}

TEST(SettingsMapping, AnInvalidTextureSizeIsIgnoredWithAWarning)
{
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) { s.setTextureSize(osg::Vec2s(0, -3)); });
    const MappedSettings mapped = mapShadowSettings(s, MappedProperties());
    EXPECT_EQ(mapped.values.shadowMapSize, 2048u);
    const std::string w = onlyWarning(mapped);
    EXPECT_TRUE(contains(w, "ShadowSettings TextureSize 0x-3 is ignored: ShadowMapSize takes 1 to 16384")) << w;
}

TEST(SettingsMapping, APropertyAwayFromItsDefaultWinsWithAWarning)
{
    MappedProperties own;
    own.shadowMapSize = 1024;
    own.lightNum = 0;
    own.baseTextureUnit = 10;
    own.debugView = SilhouetteShadowTechnique::DEBUG_CLASSES;
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) {
        s.setTextureSize(osg::Vec2s(256, 256));
        s.setLightNum(1);
        s.setBaseShadowTextureUnit(4);
        s.setDebugDraw(true);
    });
    const MappedSettings mapped = mapShadowSettings(s, own);
    EXPECT_EQ(mapped.values, own);
    ASSERT_EQ(mapped.warnings.size(), 4u);
    EXPECT_TRUE(contains(mapped.warnings[0].message,
                         "ShadowSettings TextureSize 256x256 is overridden by the technique's ShadowMapSize 1024"))
        << mapped.warnings[0].message;
    EXPECT_TRUE(contains(mapped.warnings[1].message, "ShadowSettings LightNum 1 is overridden by the technique's LightNum 0"))
        << mapped.warnings[1].message;
    EXPECT_TRUE(contains(mapped.warnings[2].message,
                         "ShadowSettings BaseShadowTextureUnit 4 is overridden by the technique's BaseTextureUnit 10"))
        << mapped.warnings[2].message;
    EXPECT_TRUE(contains(mapped.warnings[3].message, "ShadowSettings DebugDraw true is overridden by the technique's DebugView"))
        << mapped.warnings[3].message;
}

TEST(SettingsMapping, LightNumBaseUnitAndDebugDrawApply)
{
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) {
        s.setLightNum(1);
        s.setBaseShadowTextureUnit(4);
        s.setDebugDraw(true);
    });
    const MappedSettings mapped = mapShadowSettings(s, MappedProperties());
    EXPECT_EQ(mapped.values.lightNum, 1);
    EXPECT_EQ(mapped.values.baseTextureUnit, 4u);
    EXPECT_EQ(mapped.values.debugView, int(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK));
    EXPECT_TRUE(mapped.warnings.empty());
}

TEST(SettingsMapping, OutOfRangeLightNumAndUnitAreIgnoredWithAWarning)
{
    const auto light = settingsWith([](osgShadow::ShadowSettings& s) { s.setLightNum(12); });
    MappedSettings mapped = mapShadowSettings(light, MappedProperties());
    EXPECT_EQ(mapped.values.lightNum, -1);
    EXPECT_TRUE(contains(onlyWarning(mapped), "ShadowSettings LightNum 12 is ignored: LightNum takes")) << onlyWarning(mapped);
    const auto unit = settingsWith([](osgShadow::ShadowSettings& s) { s.setBaseShadowTextureUnit(40); });
    mapped = mapShadowSettings(unit, MappedProperties());
    EXPECT_EQ(mapped.values.baseTextureUnit, 8u);
    EXPECT_TRUE(contains(onlyWarning(mapped), "ShadowSettings BaseShadowTextureUnit 40 is ignored: BaseTextureUnit takes 1 to 31"))
        << onlyWarning(mapped);
}

TEST(SettingsMapping, UseOverrideForShadowMapTexture)
{
    EXPECT_TRUE(mapShadowSettings(ShadowSettingsValues(), MappedProperties()).mapsOverride);
    const auto s = settingsWith([](osgShadow::ShadowSettings& s) { s.setUseOverrideForShadowMapTexture(false); });
    const MappedSettings mapped = mapShadowSettings(s, MappedProperties());
    EXPECT_FALSE(mapped.mapsOverride);
    EXPECT_TRUE(mapped.warnings.empty());
}

TEST(SettingsMapping, MaximumShadowMapDistance)
{
    const auto near = settingsWith([](osgShadow::ShadowSettings& s) { s.setMaximumShadowMapDistance(40.0); });
    EXPECT_EQ(mapShadowSettings(near, MappedProperties()).maximumShadowDistance, 40.0);
    EXPECT_TRUE(mapShadowSettings(near, MappedProperties()).warnings.empty());
    const auto bad = settingsWith([](osgShadow::ShadowSettings& s) { s.setMaximumShadowMapDistance(-1.0); });
    const MappedSettings mapped = mapShadowSettings(bad, MappedProperties());
    EXPECT_EQ(mapped.maximumShadowDistance, DBL_MAX);
    EXPECT_TRUE(contains(onlyWarning(mapped), "MaximumShadowMapDistance -1 is ignored")) << onlyWarning(mapped);
}

// Each setting without a meaning here: one warning naming it and its value.
TEST(SettingsMapping, SettingsWithoutMeaningWarn)
{
    const struct
    {
        std::function<void(osgShadow::ShadowSettings&)> change;
        const char* named;
        int key;
    } cases[] = {
        {[](osgShadow::ShadowSettings& s) { s.setShadowMapProjectionHint(osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP); },
         "ShadowMapProjectionHint ORTHOGRAPHIC_SHADOW_MAP is ignored", WARN_SETTINGS_PROJECTION_HINT},
        {[](osgShadow::ShadowSettings& s) { s.setPerspectiveShadowMapCutOffAngle(10.0); },
         "PerspectiveShadowMapCutOffAngle 10 is ignored", WARN_SETTINGS_CUT_OFF_ANGLE},
        {[](osgShadow::ShadowSettings& s) { s.setNumShadowMapsPerLight(2); }, "NumShadowMapsPerLight 2 is ignored",
         WARN_SETTINGS_MAPS_PER_LIGHT},
        {[](osgShadow::ShadowSettings& s) { s.setMultipleShadowMapHint(osgShadow::ShadowSettings::CASCADED); },
         "MultipleShadowMapHint CASCADED is ignored", WARN_SETTINGS_MULTIPLE_MAP_HINT},
        {[](osgShadow::ShadowSettings& s) { s.setShaderHint(osgShadow::ShadowSettings::PROVIDE_FRAGMENT_SHADER); },
         "ShaderHint PROVIDE_FRAGMENT_SHADER is ignored", WARN_SETTINGS_SHADER_HINT},
        {[](osgShadow::ShadowSettings& s) { s.setMinimumShadowMapNearFarRatio(0.2); },
         "MinimumShadowMapNearFarRatio 0.2 is ignored", WARN_SETTINGS_NEAR_FAR_RATIO},
    };
    for (const auto& c : cases)
    {
        const MappedSettings mapped = mapShadowSettings(settingsWith(c.change), MappedProperties());
        EXPECT_EQ(mapped.values, MappedProperties()) << c.named;
        ASSERT_EQ(mapped.warnings.size(), 1u) << c.named;
        EXPECT_EQ(mapped.warnings[0].key, c.key) << c.named;
        EXPECT_TRUE(contains(mapped.warnings[0].message, std::string("ShadowSettings ") + c.named))
            << mapped.warnings[0].message;
    }
}

// The technique's getters keep the properties as set; the effective values follow the
// scene's settings as soon as the technique looks at them.
TEST(SettingsMapping, TechniqueKeepsItsPropertiesApart)
{
    osg::ref_ptr<SilhouetteShadowTechnique> t = new SilhouetteShadowTechnique;
    osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene(t.get());
    scene->getShadowSettings()->setTextureSize(osg::Vec2s(256, 256));
    scene->getShadowSettings()->setLightNum(2);
    t->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE); // the mapped setters look at the settings again
    EXPECT_EQ(t->getShadowMapSize(), 2048u);
    EXPECT_EQ(t->getEffectiveShadowMapSize(), 256u);
    EXPECT_EQ(t->getLightNum(), -1);
    EXPECT_EQ(t->getEffectiveLightNum(), 2);
    t->setShadowMapSize(512);
    EXPECT_EQ(t->getEffectiveShadowMapSize(), 512u);
    t->setShadowMapSize(2048);
    EXPECT_EQ(t->getEffectiveShadowMapSize(), 256u);
}

// The serializers write the properties, not the values the settings put in effect
// (osgShadow 3.6's ShadowedScene wrapper writes the settings' traversal masks alone).
TEST(SettingsMapping, FilesKeepThePropertiesAsSet)
{
    osg::ref_ptr<SilhouetteShadowTechnique> t = new SilhouetteShadowTechnique;
    osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene(t.get());
    scene->getShadowSettings()->setTextureSize(osg::Vec2s(256, 256));
    scene->getShadowSettings()->setBaseShadowTextureUnit(4);
    t->setLightNum(1);
    ASSERT_EQ(t->getEffectiveShadowMapSize(), 256u);
    ASSERT_EQ(t->getEffectiveBaseTextureUnit(), 4u);
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("oss_settings_" + std::to_string(::getpid()) + ".osgt")).string();
    ASSERT_TRUE(osgDB::writeNodeFile(*scene, file));
    osg::ref_ptr<osg::Node> node = osgDB::readNodeFile(file);
    std::remove(file.c_str());
    auto* read = dynamic_cast<osgShadow::ShadowedScene*>(node.get());
    ASSERT_TRUE(read);
    auto* technique = dynamic_cast<SilhouetteShadowTechnique*>(read->getShadowTechnique());
    ASSERT_TRUE(technique);
    EXPECT_EQ(technique->getShadowMapSize(), 2048u);
    EXPECT_EQ(technique->getBaseTextureUnit(), 8u);
    EXPECT_EQ(technique->getLightNum(), 1);
    EXPECT_EQ(technique->getEffectiveLightNum(), 1);
}
