#include "RenderOptions.h"

#include <osgShadowSilhouette/Properties>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace osshar {

namespace {

/** Reads `option on|off` into flag (left alone when absent); false with error otherwise. */
bool readOnOff(osg::ArgumentParser& a, const char* option, bool& flag, std::string& error)
{
    std::string value;
    if (!a.read(option, value)) return true;
    if (value != "on" && value != "off")
    {
        error = std::string(option) + " takes on or off";
        return false;
    }
    flag = value == "on";
    return true;
}

bool readVec3(osg::ArgumentParser& a, const char* name, std::optional<osg::Vec3d>& out)
{
    double x, y, z;
    if (!a.read(name, x, y, z)) return false;
    out = osg::Vec3d(x, y, z);
    return true;
}

bool finite(const osg::Vec3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

/** The light options in command-line order: --spot-dir and --spot-cutoff apply to the
 *  --light-pos before them. */
bool readLights(osg::ArgumentParser& a, std::vector<LightArg>& lights, std::string& error)
{
    for (int i = 1; i < a.argc();)
    {
        const std::string arg = a[i];
        double x = 0.0, y = 0.0, z = 0.0;
        if (arg == "--light-dir" || arg == "--light-pos" || arg == "--spot-dir")
        {
            if (!a.read(i, arg, x, y, z))
            {
                error = arg + " needs three numbers";
                return false;
            }
            const osg::Vec3d v(x, y, z);
            if (!finite(v) || (arg != "--light-pos" && v.length2() == 0.0))
            {
                error = arg + " needs finite values and a non-zero direction";
                return false;
            }
            if (arg != "--spot-dir")
            {
                LightArg light;
                light.directional = arg == "--light-dir";
                light.vector = v;
                lights.push_back(light);
            }
            else if (lights.empty() || lights.back().directional)
            {
                error = "--spot-dir applies to a preceding --light-pos";
                return false;
            }
            else
                lights.back().spotDirection = v;
        }
        else if (arg == "--spot-cutoff")
        {
            if (!a.read(i, arg, x) || !(x >= 0.0 && (x <= 90.0 || x == 180.0)))
            {
                error = "--spot-cutoff needs an angle from 0 to 90 degrees (or 180: no cone)";
                return false;
            }
            if (lights.empty() || lights.back().directional)
            {
                error = "--spot-cutoff applies to a preceding --light-pos";
                return false;
            }
            lights.back().spotCutoff = x;
        }
        else
            ++i;
    }
    return true;
}

/** The one non-option argument left, as the file; a second one is an error. */
bool takeFile(osg::ArgumentParser& a, RenderOptions& o, std::string& error)
{
    for (int i = 1; i < a.argc(); ++i)
    {
        if (a.isOption(i)) continue;
        if (!o.file.empty())
        {
            error = std::string("more than one file: '") + o.file + "' and '" + a[i] + "' (or a value without its option)";
            return false;
        }
        o.file = a[i];
        a.remove(i--);
    }
    return true;
}

/** Options nobody read and values that did not parse ("--map-size abc", an option at the
 *  end without its value), as the ArgumentParser recorded them. */
bool reportErrors(osg::ArgumentParser& a, std::string& error)
{
    a.reportRemainingOptionsAsUnrecognized();
    if (!a.errors()) return true;
    for (const auto& e : a.getErrorMessageMap())
        error += (error.empty() ? "" : "; ") + e.first;
    return false;
}

/** The value of an option that sets a technique property, read by the table of properties
 *  (osgShadowSilhouette/Properties): "--map-size 4294967297" is refused, not wrapped. */
bool readPropertyValue(const std::string& option, const std::string& property, const std::string& text, double& value,
                       std::string& error)
{
    const osgShadowSilhouette::PropertyInfo* info = osgShadowSilhouette::findProperty(property);
    if (!info)
    {
        error = option + ": no property is named " + property;
        return false;
    }
    std::string why;
    if (osgShadowSilhouette::parsePropertyValue(*info, text, value, why)) return true;
    error = option + " " + text + " " + why;
    return false;
}

/** --property NAME=VALUE (repeatable) and the shorthands of propertyOptions(), in order. */
bool readProperties(osg::ArgumentParser& a, RenderOptions& o, std::string& error)
{
    for (int i = 1; i < a.argc();)
    {
        const std::string arg = a[i];
        const auto shorthand = std::find_if(propertyOptions().begin(), propertyOptions().end(),
                                            [&](const auto& option) { return option.first == arg; });
        std::string text, name;
        if (arg == "--property" || shorthand != propertyOptions().end())
        {
            if (!a.read(i, arg, text))
            {
                error = arg + " needs a value";
                return false;
            }
            name = shorthand != propertyOptions().end() ? shorthand->second : text.substr(0, text.find('='));
            if (arg == "--property") text = text.find('=') == std::string::npos ? "" : text.substr(text.find('=') + 1);
            double value = 0.0;
            if (!readPropertyValue(arg == "--property" ? arg + " " + name : arg, name, text, value, error))
                return false;
            o.properties.emplace_back(osgShadowSilhouette::findProperty(name)->name, value);
        }
        else
            ++i;
    }
    return true;
}

} // namespace

const std::vector<std::pair<std::string, std::string>>& propertyOptions()
{
    static const std::vector<std::pair<std::string, std::string>> options = {
        {"--max-shadow-lights", "MaxShadowLights"},
        {"--blocker-culling", "BlockerCulling"},
        {"--hybrid-method", "HybridMethod"},
        {"--hybrid-edges", "HybridEdgeMask"},
        {"--depth-prepass", "DepthPrepass"},
        {"--shadow-ray-offset", "ShadowRayOffset"},
        {"--per-pixel-lighting", "PerPixelLighting"},
        {"--filter", "Filter"},
        {"--filter-window", "FilterWindow"},
        {"--soft-samples", "SoftSamples"},
        {"--warp", "PerspectiveWarp"},
        {"--cascades", "Cascades"}};
    return options;
}

std::optional<double> propertyValue(const RenderOptions& options, const std::string& name)
{
    std::optional<double> value;
    for (const auto& p : options.properties)
        if (p.first == name) value = p.second;
    return value;
}

void applyProperties(const RenderOptions& options, osgShadowSilhouette::SilhouetteShadowTechnique& technique)
{
    for (const auto& p : options.properties) osgShadowSilhouette::findProperty(p.first)->set(technique, p.second);
}

bool parseRenderOptions(osg::ArgumentParser& a, RenderOptions& o, std::string& error)
{
    a.read("--scene", o.scene);
    a.read("--mode", o.mode);
    std::string mapSize;
    double size = 0.0;
    while (a.read("--map-size", mapSize))
    {
        if (!readPropertyValue("--map-size", "ShadowMapSize", mapSize, size, error)) return false;
        o.mapSize = static_cast<unsigned int>(size);
    }
    a.read("--size", o.width, o.height);
    if (o.width < 1 || o.height < 1)
    {
        error = "--size needs a positive width and height";
        return false;
    }
    readVec3(a, "--eye", o.eye);
    readVec3(a, "--center", o.center);
    readVec3(a, "--up", o.up);
    double fovy;
    if (a.read("--fovy", fovy)) o.fovy = fovy;
    if (!readLights(a, o.lights, error)) return false;
    if (!readProperties(a, o, error)) return false;
    a.read("--frames", o.frames);
    a.read("--warmup", o.warmup);
    a.read("--out", o.out);
    a.read("--mask", o.mask);
    a.read("--compare", o.compare);
    a.read("--reference", o.reference);
    a.read("--diff", o.diff);
    a.read("--classes", o.classes);
    if (!readOnOff(a, "--skip-empty-faces", o.skipEmptyFaces, error)) return false;
    if (a.read("--reference-offset", o.referenceOffset) && !(o.referenceOffset >= 0.0 && std::isfinite(o.referenceOffset)))
    {
        error = "--reference-offset takes a finite number of at least 0";
        return false;
    }
    std::string lightSize;
    if (a.read("--light-size", lightSize))
    {
        char* end = nullptr;
        o.lightSize = std::strtod(lightSize.c_str(), &end);
        if (lightSize.empty() || *end != '\0' || !(o.lightSize >= 0.0 && std::isfinite(o.lightSize)))
        {
            error = "--light-size " + lightSize + " is not a finite number of at least 0 (0: a hard shadow)";
            return false;
        }
        o.properties.emplace_back("LightSize", o.lightSize); // the technique's lights are as large
    }
    a.read("--visibility", o.visibility);
    a.read("--reference-visibility", o.referenceVisibility);
    a.read("--compare-visibility", o.compareVisibility);
    a.read("--visibility-error", o.visibilityError);
    std::string factor, units;
    double value = 0.0;
    if (a.read("--polygon-offset", factor, units))
    {
        for (const auto& [property, text] :
             {std::pair{"PolygonOffsetFactor", factor}, std::pair{"PolygonOffsetUnits", units}})
        {
            if (!readPropertyValue("--polygon-offset", property, text, value, error)) return false;
            o.properties.emplace_back(property, value);
        }
    }
    if (a.read("--offscreen")) o.offscreen = true;
    if (a.read("--ground")) o.ground = true;
    if (a.read("--check-gl-errors")) o.checkGLErrors = true;
    if (a.read("--moving-light")) o.movingLight = true;
    if (a.read("--rotating-light", o.lightTurnDeg)) o.movingLight = true;
    if (a.read("--animate")) o.animate = true;
    if (a.read("--score-every-frame")) o.scoreEveryFrame = true;
    a.read("--camera-path", o.cameraPath);
    if (a.read("--time-step", o.timeStep) && !(o.timeStep > 0.0 && std::isfinite(o.timeStep)))
    {
        error = "--time-step takes a finite number of seconds above 0";
        return false;
    }
    if (o.frames < 1 || o.warmup < 0)
    {
        error = "--frames needs at least 1 and --warmup at least 0";
        return false;
    }
    return reportErrors(a, error) && takeFile(a, o, error);
}

std::string renderOptionsUsage(const std::string& program)
{
    std::ostringstream s;
    std::string scenes;
    for (const std::string& name : sceneNames()) scenes += (scenes.empty() ? "" : "|") + name;
    s << program << " [FILE] [--scene " << scenes << "]\n"
      << "    [--mode shadowmap|silhouette|hybrid|volume|none|osgShadow:ShadowMap|osgShadow:SoftShadowMap|\n"
      << "            osgShadow:LightSpacePerspectiveShadowMapCB|osgShadow:ViewDependentShadowMap|\n"
      << "            osgShadow:ParallelSplitShadowMap]\n"
      << "    [--map-size N] [--size W H] [--eye X Y Z] [--center X Y Z] [--up X Y Z] [--fovy DEG]\n"
      << "    [--light-dir X Y Z | --light-pos X Y Z [--spot-dir X Y Z] [--spot-cutoff DEG]]...\n"
      << "    [--frames N] [--warmup N]\n"
      << "    [--out color.png] [--mask mask%d.png] [--offscreen]\n"
      << "    [--reference ref%d.png] [--reference-offset S] [--compare ref%d.png] [--diff diff%d.png] [--classes "
         "classes%d.png]\n"
      << "    [--light-size S] [--visibility vis%d.png] [--reference-visibility ref%d.png] [--compare-visibility "
         "ref%d.png] [--visibility-error err%d.png]\n"
      << "    [--polygon-offset FACTOR UNITS] [--skip-empty-faces on|off]\n"
      << "    [--property NAME=VALUE]... (any property of the technique:";
    for (const osgShadowSilhouette::PropertyInfo& p : osgShadowSilhouette::properties()) s << " " << p.name;
    s << ")\n   ";
    for (const auto& [option, property] : propertyOptions())
        s << " [" << option << " "
          << osgShadowSilhouette::propertyValueSyntax(*osgShadowSilhouette::findProperty(property)) << "]";
    s << "\n"
      << "    [--moving-light | --rotating-light DEG] [--animate] [--time-step S] [--camera-path FILE] "
         "[--score-every-frame] [--ground]\n"
      << "    [--check-gl-errors]\n";
    return s.str();
}

} // namespace osshar
