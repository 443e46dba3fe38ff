#include <osgShadowSilhouette/SettingsMapping>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osgShadow/ShadowedScene>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace osgShadowSilhouette {

ShadowSettingsValues::ShadowSettingsValues() : ShadowSettingsValues(*osg::ref_ptr<osgShadow::ShadowSettings>(new osgShadow::ShadowSettings)) {}

ShadowSettingsValues::ShadowSettingsValues(const osgShadow::ShadowSettings& s)
    : textureSize(s.getTextureSize()),
      lightNum(s.getLightNum()),
      baseShadowTextureUnit(s.getBaseShadowTextureUnit()),
      useOverrideForShadowMapTexture(s.getUseOverrideForShadowMapTexture()),
      minimumShadowMapNearFarRatio(s.getMinimumShadowMapNearFarRatio()),
      maximumShadowMapDistance(s.getMaximumShadowMapDistance()),
      computeNearFarModeOverride(s.getComputeNearFarModeOverride()),
      shadowMapProjectionHint(s.getShadowMapProjectionHint()),
      perspectiveShadowMapCutOffAngle(s.getPerspectiveShadowMapCutOffAngle()),
      numShadowMapsPerLight(s.getNumShadowMapsPerLight()),
      multipleShadowMapHint(s.getMultipleShadowMapHint()),
      shaderHint(s.getShaderHint()),
      debugDraw(s.getDebugDraw())
{
}

bool ShadowSettingsValues::operator==(const ShadowSettingsValues& o) const
{
    // NaN settings compare unequal and are mapped again each frame: warnings stay once.
    return textureSize == o.textureSize && lightNum == o.lightNum && baseShadowTextureUnit == o.baseShadowTextureUnit &&
           useOverrideForShadowMapTexture == o.useOverrideForShadowMapTexture &&
           minimumShadowMapNearFarRatio == o.minimumShadowMapNearFarRatio &&
           maximumShadowMapDistance == o.maximumShadowMapDistance &&
           computeNearFarModeOverride == o.computeNearFarModeOverride &&
           shadowMapProjectionHint == o.shadowMapProjectionHint &&
           perspectiveShadowMapCutOffAngle == o.perspectiveShadowMapCutOffAngle &&
           numShadowMapsPerLight == o.numShadowMapsPerLight && multipleShadowMapHint == o.multipleShadowMapHint &&
           shaderHint == o.shaderHint && debugDraw == o.debugDraw;
}

namespace {

const ShadowSettingsValues& osgShadowDefaults()
{
    static const ShadowSettingsValues defaults;
    return defaults;
}

template<typename T>
std::string text(T value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

const char* projectionHintName(osgShadow::ShadowSettings::ShadowMapProjectionHint hint)
{
    return hint == osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP ? "ORTHOGRAPHIC_SHADOW_MAP" : "PERSPECTIVE_SHADOW_MAP";
}

const char* multipleMapHintName(osgShadow::ShadowSettings::MultipleShadowMapHint hint)
{
    return hint == osgShadow::ShadowSettings::CASCADED ? "CASCADED" : "PARALLEL_SPLIT";
}

const char* shaderHintName(osgShadow::ShadowSettings::ShaderHint hint)
{
    switch (hint)
    {
    case osgShadow::ShadowSettings::NO_SHADERS: return "NO_SHADERS";
    case osgShadow::ShadowSettings::PROVIDE_FRAGMENT_SHADER: return "PROVIDE_FRAGMENT_SHADER";
    case osgShadow::ShadowSettings::PROVIDE_VERTEX_AND_FRAGMENT_SHADER: return "PROVIDE_VERTEX_AND_FRAGMENT_SHADER";
    }
    return "unknown";
}

/** Maps one setting onto one property (the precedence of mapShadowSettings()). */
class PropertyMapping
{
public:
    explicit PropertyMapping(std::vector<SettingsWarning>& warnings) : _warnings(warnings) {}

    /** Sets @p effective to @p mapped (the setting @p setting = @p settingText, mapped) when
     *  the setting differs from osgShadow's default and the property @p property (value
     *  @p own, default @p ownDefault) does not differ from its own; warns when the property
     *  wins or @p mapped is outside the property's range. */
    template<typename T>
    void apply(int key, const char* setting, const std::string& settingText, bool settingSet, const char* property,
               T own, T ownDefault, T mapped, T& effective)
    {
        effective = own;
        if (!settingSet) return;
        const std::string named = std::string("ShadowSettings ") + setting + " " + settingText;
        if (own != ownDefault)
        {
            warn(key, named + " is overridden by the technique's " + property + " " + text(own) +
                          " (set the property to its default " + text(ownDefault) + " to use the setting)");
            return;
        }
        const NumericPropertyRange* range = numericPropertyRange(property);
        if (range && !inRange(*range, double(mapped)))
        {
            ignore(key, setting, settingText,
                   std::string(property) + " takes " + describeRange(*range) + "; keeping " + text(own));
            return;
        }
        effective = mapped;
    }

    /** "ShadowSettings <setting> <value> is ignored: <why>". */
    void ignore(int key, const char* setting, const std::string& value, const std::string& why)
    {
        warn(key, std::string("ShadowSettings ") + setting + " " + value + " is ignored: " + why);
    }

    void warn(int key, const std::string& message) { _warnings.push_back({key, message}); }

private:
    std::vector<SettingsWarning>& _warnings;
};

/** TextureSize -> ShadowMapSize; the maps are square: the larger side. */
void mapTextureSize(const osg::Vec2s& size, const osg::Vec2s& osgDefault, unsigned int own, PropertyMapping& mapping,
                    unsigned int& effective)
{
    const unsigned int ownDefault = MappedProperties().shadowMapSize;
    const int side = std::max<int>(size.x(), size.y());
    const std::string sizeText = text(size.x()) + "x" + text(size.y());
    mapping.apply(WARN_SETTINGS_TEXTURE_SIZE, "TextureSize", sizeText, size != osgDefault, "ShadowMapSize", own,
                  ownDefault, static_cast<unsigned int>(std::max(side, 0)), effective);
    if (size.x() != size.y() && effective == static_cast<unsigned int>(side) && side > 0 && own == ownDefault)
        mapping.warn(WARN_SETTINGS_TEXTURE_SIZE_SQUARE, "ShadowSettings TextureSize " + sizeText +
                                                           " is not square; the shadow maps are: " + text(side) + "x" +
                                                           text(side) + " (the larger side)");
}

/** The settings without a meaning here warn where they differ from osgShadow's default. */
void ignoreMeaningless(const ShadowSettingsValues& settings, const ShadowSettingsValues& osgDefaults,
                       PropertyMapping& mapping)
{
    const struct
    {
        int key;
        bool set;
        const char* setting;
        std::string value;
        const char* why;
    } meaningless[] = {
        {WARN_SETTINGS_NEAR_FAR_RATIO, settings.minimumShadowMapNearFarRatio != osgDefaults.minimumShadowMapNearFarRatio,
         "MinimumShadowMapNearFarRatio", text(settings.minimumShadowMapNearFarRatio),
         "it bounds the near plane of warped (perspective) shadow maps, and the maps here are not warped"},
        {WARN_SETTINGS_PROJECTION_HINT, settings.shadowMapProjectionHint != osgDefaults.shadowMapProjectionHint,
         "ShadowMapProjectionHint", projectionHintName(settings.shadowMapProjectionHint),
         "each light's maps take its own projection (orthographic for directional lights, perspective for spot "
         "and point lights)"},
        {WARN_SETTINGS_CUT_OFF_ANGLE, settings.perspectiveShadowMapCutOffAngle != osgDefaults.perspectiveShadowMapCutOffAngle,
         "PerspectiveShadowMapCutOffAngle", text(settings.perspectiveShadowMapCutOffAngle),
         "the shadow maps are not warped to the view (no perspective shadow maps)"},
        {WARN_SETTINGS_MAPS_PER_LIGHT, settings.numShadowMapsPerLight != osgDefaults.numShadowMapsPerLight,
         "NumShadowMapsPerLight", text(settings.numShadowMapsPerLight),
         "one map per light (a point light's cube faces apart), no cascades"},
        {WARN_SETTINGS_MULTIPLE_MAP_HINT, settings.multipleShadowMapHint != osgDefaults.multipleShadowMapHint,
         "MultipleShadowMapHint", multipleMapHintName(settings.multipleShadowMapHint),
         "one map per light, no cascades or parallel splits"},
        {WARN_SETTINGS_SHADER_HINT, settings.shaderHint != osgDefaults.shaderHint, "ShaderHint",
         shaderHintName(settings.shaderHint),
         "the technique's UseDefaultShading says whether it installs the receivers' program"},
    };
    for (const auto& m : meaningless)
        if (m.set) mapping.ignore(m.key, m.setting, m.value, m.why);
}

} // namespace

MappedSettings mapShadowSettings(const ShadowSettingsValues& settings, const MappedProperties& properties)
{
    const ShadowSettingsValues& osgDefaults = osgShadowDefaults();
    const MappedProperties ownDefaults;
    MappedSettings mapped;
    mapped.maximumShadowDistance = DBL_MAX;
    // UseOverrideForShadowMapTexture false: a texture of the model on a map's unit replaces
    // the map below it (a depth texture of 1s leaves a subgraph unshadowed).
    mapped.mapsOverride = settings.useOverrideForShadowMapTexture;
    PropertyMapping mapping(mapped.warnings);
    MappedProperties& v = mapped.values;

    mapTextureSize(settings.textureSize, osgDefaults.textureSize, properties.shadowMapSize, mapping, v.shadowMapSize);

    mapping.apply(WARN_SETTINGS_LIGHT_NUM, "LightNum", text(settings.lightNum), settings.lightNum != osgDefaults.lightNum,
                  "LightNum", properties.lightNum, ownDefaults.lightNum, settings.lightNum, v.lightNum);

    mapping.apply(WARN_SETTINGS_BASE_UNIT, "BaseShadowTextureUnit", text(settings.baseShadowTextureUnit),
                  settings.baseShadowTextureUnit != osgDefaults.baseShadowTextureUnit, "BaseTextureUnit",
                  properties.baseTextureUnit, ownDefaults.baseTextureUnit, settings.baseShadowTextureUnit,
                  v.baseTextureUnit);

    mapping.apply(WARN_SETTINGS_DEBUG_DRAW, "DebugDraw", settings.debugDraw ? "true" : "false",
                  settings.debugDraw != osgDefaults.debugDraw, "DebugView", properties.debugView, ownDefaults.debugView,
                  int(settings.debugDraw ? SilhouetteShadowTechnique::DEBUG_SHADOW_MASK : ownDefaults.debugView),
                  v.debugView);

    // MaximumShadowMapDistance bounds the eye range the maps are fitted to, as in
    // ViewDependentShadowMap.
    const double distance = settings.maximumShadowMapDistance;
    if (distance != osgDefaults.maximumShadowMapDistance)
    {
        if (distance > 0.0 && !std::isnan(distance))
            mapped.maximumShadowDistance = distance;
        else
            mapping.ignore(WARN_SETTINGS_MAXIMUM_DISTANCE, "MaximumShadowMapDistance", text(distance),
                           "it takes a distance above 0");
    }

    ignoreMeaningless(settings, osgDefaults, mapping);
    return mapped;
}

bool SilhouetteShadowTechnique::applyShadowSettings()
{
    const osgShadow::ShadowSettings* settings = _shadowedScene ? _shadowedScene->getShadowSettings() : nullptr;
    const ShadowSettingsValues values = settings ? ShadowSettingsValues(*settings) : osgShadowDefaults();
    if (_settingsApplied && values == _appliedSettings && _properties == _appliedProperties) return false;
    const MappedSettings mapped = mapShadowSettings(values, _properties);
    for (const SettingsWarning& warning : mapped.warnings) warnOnce(warning.key, warning.message);
    const bool rebuild = mapped.values.baseTextureUnit != _baseTextureUnit || mapped.mapsOverride != _mapsOverride;
    _shadowMapSize = mapped.values.shadowMapSize;
    _lightNum = mapped.values.lightNum;
    _baseTextureUnit = mapped.values.baseTextureUnit;
    _debugView = static_cast<DebugView>(mapped.values.debugView);
    _maximumShadowDistance = mapped.maximumShadowDistance;
    _mapsOverride = mapped.mapsOverride;
    _appliedSettings = values;
    _appliedProperties = _properties;
    _settingsApplied = true;
    return rebuild;
}

} // namespace osgShadowSilhouette
