#include "PseudoLoaderOptions.h"

#include <osgShadowSilhouette/PropertyRanges>

#include <osg/Notify>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace osssil {

using osgShadowSilhouette::SilhouetteShadowTechnique;

namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

void warnValue(const std::string& key, const std::string& value, const std::string& why)
{
    OSG_WARN << "osgShadowSilhouette pseudo-loader: option " << key << "=" << value << " " << why << std::endl;
}

bool parseBool(const std::string& text, bool& value)
{
    const std::string t = lower(text);
    if (t == "on" || t == "true" || t == "1") value = true;
    else if (t == "off" || t == "false" || t == "0") value = false;
    else return false;
    return true;
}

bool parseDebugView(const std::string& text, SilhouetteShadowTechnique::DebugView& view)
{
    const std::string t = lower(text);
    if (t == "none" || t == "debug_none") view = SilhouetteShadowTechnique::DEBUG_NONE;
    else if (t == "mask" || t == "debug_shadow_mask") view = SilhouetteShadowTechnique::DEBUG_SHADOW_MASK;
    else if (t == "pixels" || t == "debug_silhouette_pixels") view = SilhouetteShadowTechnique::DEBUG_SILHOUETTE_PIXELS;
    else if (t == "silmap" || t == "debug_silhouette_map") view = SilhouetteShadowTechnique::DEBUG_SILHOUETTE_MAP;
    else if (t == "classes" || t == "debug_classes") view = SilhouetteShadowTechnique::DEBUG_CLASSES;
    else return false;
    return true;
}

/** Sets numeric property @p property from option text: a number in its range
 *  (PropertyRanges) goes to the setter; anything else is refused with a warning naming the
 *  property, the text and the range, and the technique keeps its value. */
template<typename T>
void applyNumber(const char* property, const std::string& text, SilhouetteShadowTechnique& t,
                 void (SilhouetteShadowTechnique::*set)(T), T (SilhouetteShadowTechnique::*get)() const)
{
    double number = 0.0;
    const bool isNumber = osgShadowSilhouette::parseNumber(text, number);
    const osgShadowSilhouette::NumericPropertyRange& range = *osgShadowSilhouette::numericPropertyRange(property);
    if (isNumber && osgShadowSilhouette::inRange(range, number))
    {
        (t.*set)(static_cast<T>(number));
        return;
    }
    std::ostringstream kept;
    kept << (t.*get)();
    OSG_WARN << osgShadowSilhouette::refusedValueMessage("osgShadowSilhouette pseudo-loader option", range, text,
                                                         isNumber, kept.str())
             << std::endl;
}

bool applyOne(const std::string& key, const std::string& value, SilhouetteShadowTechnique& t)
{
    const std::string k = lower(key);
    if (k == "mode")
    {
        SilhouetteShadowTechnique::Mode mode;
        if (SilhouetteShadowTechnique::modeFromName(value, mode)) t.setMode(mode);
        else warnValue(key, value, "is not a mode (shadowmap, silhouette, hybrid, volume); ignored");
    }
    else if (k == "shadowmapsize" || k == "mapsize")
        applyNumber("ShadowMapSize", value, t, &SilhouetteShadowTechnique::setShadowMapSize, &SilhouetteShadowTechnique::getShadowMapSize);
    else if (k == "lightnum")
        applyNumber("LightNum", value, t, &SilhouetteShadowTechnique::setLightNum, &SilhouetteShadowTechnique::getLightNum);
    else if (k == "maxshadowlights")
        applyNumber("MaxShadowLights", value, t, &SilhouetteShadowTechnique::setMaxShadowLights, &SilhouetteShadowTechnique::getMaxShadowLights);
    else if (k == "basetextureunit")
        applyNumber("BaseTextureUnit", value, t, &SilhouetteShadowTechnique::setBaseTextureUnit, &SilhouetteShadowTechnique::getBaseTextureUnit);
    else if (k == "debuglight")
        applyNumber("DebugLight", value, t, &SilhouetteShadowTechnique::setDebugLight, &SilhouetteShadowTechnique::getDebugLight);
    else if (k == "debugview")
    {
        SilhouetteShadowTechnique::DebugView view;
        if (parseDebugView(value, view)) t.setDebugView(view);
        else warnValue(key, value, "is not a debug view (none, mask, pixels, silmap, classes); ignored");
    }
    else if (k == "polygonoffsetfactor")
        applyNumber("PolygonOffsetFactor", value, t, &SilhouetteShadowTechnique::setPolygonOffsetFactor,
                    &SilhouetteShadowTechnique::getPolygonOffsetFactor);
    else if (k == "polygonoffsetunits")
        applyNumber("PolygonOffsetUnits", value, t, &SilhouetteShadowTechnique::setPolygonOffsetUnits,
                    &SilhouetteShadowTechnique::getPolygonOffsetUnits);
    else if (k == "shadowrayoffset")
        applyNumber("ShadowRayOffset", value, t, &SilhouetteShadowTechnique::setShadowRayOffset,
                    &SilhouetteShadowTechnique::getShadowRayOffset);
    else if (k == "hybridmethod")
    {
        const std::string m = lower(value);
        if (m == "auto" || m == "hybrid_auto") t.setHybridMethod(SilhouetteShadowTechnique::HYBRID_AUTO);
        else if (m == "stencil" || m == "hybrid_stencil_volumes")
            t.setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
        else if (m == "lists" || m == "hybrid_triangle_lists")
            t.setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
        else warnValue(key, value, "is not auto, stencil or lists; ignored");
    }
    else if (k == "depthprepass")
    {
        const std::string m = lower(value);
        if (m == "auto" || m == "depth_prepass_auto") t.setDepthPrepass(SilhouetteShadowTechnique::DEPTH_PREPASS_AUTO);
        else if (m == "on" || m == "depth_prepass_on") t.setDepthPrepass(SilhouetteShadowTechnique::DEPTH_PREPASS_ON);
        else if (m == "off" || m == "depth_prepass_off") t.setDepthPrepass(SilhouetteShadowTechnique::DEPTH_PREPASS_OFF);
        else warnValue(key, value, "is not auto, on or off; ignored");
    }
    else if (k == "usedefaultshading" || k == "blockerculling" || k == "hybridedgemask" || k == "perpixellighting")
    {
        bool flag = true;
        if (!parseBool(value, flag)) warnValue(key, value, "is not on/off; ignored");
        else if (k == "usedefaultshading") t.setUseDefaultShading(flag);
        else if (k == "blockerculling") t.setBlockerCulling(flag);
        else if (k == "perpixellighting") t.setPerPixelLighting(flag);
        else t.setHybridEdgeMask(flag);
    }
    else return false;
    return true;
}

} // namespace

const std::vector<OptionDescription>& optionDescriptions()
{
    static const std::vector<OptionDescription> options = {
        {"Mode=<shadowmap|silhouette|hybrid|volume>", "Shadow algorithm (overrides the mode named in the file name)"},
        {"ShadowMapSize=<n>", "Width and height of each light's shadow map (MapSize=<n> also works)"},
        {"DebugView=<none|mask|pixels|silmap|classes>",
         "mask: the shadow mask of DebugLight; pixels / silmap: its silhouette pixels / silhouette map "
         "(silhouette mode); classes: red/blue shadow-map answers, green/black silhouette pixels"},
        {"DebugLight=<n>", "The light (index among the lights found) that DebugView shows"},
        {"LightNum=<n>", "GL light number that casts shadows; -1 shadows every light"},
        {"MaxShadowLights=<n>", "Most lights shadowed at once (1..8)"},
        {"BaseTextureUnit=<n>", "First texture unit of the shadow textures"},
        {"PolygonOffsetFactor=<f>", "Slope-scaled depth bias (negative: automatic, 2 in HYBRID with its edge mask, else 1.1)"},
        {"PolygonOffsetUnits=<f>", "Constant depth bias"},
        {"UseDefaultShading=<on|off>", "Whether the technique installs its receiver shading"},
        {"PerPixelLighting=<on|off>", "Light the receivers per pixel (on) or per vertex, as the fixed function"},
        {"BlockerCulling=<on|off>", "HYBRID: skip the volumes of casters hidden from the light"},
        {"HybridMethod=<auto|stencil|lists>", "HYBRID: silhouette pixels by stencil-masked volumes or triangle lists"},
        {"HybridEdgeMask=<on|off>", "HYBRID: also resolve exactly the pixels a silhouette edge crosses"},
        {"DepthPrepass=<auto|on|off>", "Draw the receivers' depth before the eye pass (auto: HYBRID with triangle lists)"},
        {"ShadowRayOffset=<f>", "HYBRID's exact test: shadow rays start this fraction of the scene's radius off the surface"},
        {"Report=<file>", "Write the technique's statistics of every frame to <file>"},
    };
    return options;
}

std::vector<std::pair<std::string, std::string>> splitOptions(const std::string& optionString)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::istringstream in(optionString);
    std::string word;
    while (in >> word)
    {
        const std::string::size_type eq = word.find('=');
        if (eq == std::string::npos) pairs.emplace_back(word, std::string());
        else pairs.emplace_back(word.substr(0, eq), word.substr(eq + 1));
    }
    return pairs;
}

std::string applyOptions(const std::string& optionString, SilhouetteShadowTechnique& technique)
{
    std::string report;
    for (const auto& kv : splitOptions(optionString))
    {
        if (lower(kv.first) == "report") report = kv.second;
        else if (!applyOne(kv.first, kv.second, technique))
            OSG_INFO << "osgShadowSilhouette pseudo-loader: option " << kv.first << " is not ours" << std::endl;
    }
    return report;
}

} // namespace osssil
