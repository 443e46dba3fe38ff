#include "RenderOptions.h"

#include <osgShadowSilhouette/PropertyRanges>

#include <algorithm>
#include <cmath>
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

/** The value of an option that sets a technique property, checked against the property's
 *  range (PropertyRanges): "--map-size 4294967297" is refused, not wrapped. */
bool readProperty(const char* option, const char* property, const std::string& text, unsigned int& value,
                  std::string& error)
{
    const osgShadowSilhouette::NumericPropertyRange& range = *osgShadowSilhouette::numericPropertyRange(property);
    double number = 0.0;
    const bool isNumber = osgShadowSilhouette::parseNumber(text, number);
    if (isNumber && osgShadowSilhouette::inRange(range, number))
    {
        value = static_cast<unsigned int>(number);
        return true;
    }
    error = std::string(option) + " " + text + (isNumber ? " is out of range (" : " is not a number (") +
            osgShadowSilhouette::describeRange(range) + ")";
    return false;
}

} // namespace

bool parseRenderOptions(osg::ArgumentParser& a, RenderOptions& o, std::string& error)
{
    a.read("--scene", o.scene);
    a.read("--mode", o.mode);
    std::string mapSize;
    while (a.read("--map-size", mapSize))
        if (!readProperty("--map-size", "ShadowMapSize", mapSize, o.mapSize, error)) return false;
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
    std::string budget;
    if (a.read("--max-shadow-lights", budget) &&
        !readProperty("--max-shadow-lights", "MaxShadowLights", budget, o.maxShadowLights, error))
        return false;
    a.read("--frames", o.frames);
    a.read("--warmup", o.warmup);
    a.read("--out", o.out);
    a.read("--mask", o.mask);
    a.read("--compare", o.compare);
    a.read("--reference", o.reference);
    a.read("--diff", o.diff);
    a.read("--classes", o.classes);
    if (!readOnOff(a, "--blocker-culling", o.blockerCulling, error)) return false;
    if (!readOnOff(a, "--hybrid-edges", o.hybridEdgeMask, error)) return false;
    if (!readOnOff(a, "--per-pixel-lighting", o.perPixelLighting, error)) return false;
    if (!readOnOff(a, "--skip-empty-faces", o.skipEmptyFaces, error)) return false;
    if (a.read("--hybrid-method", o.hybridMethod) && o.hybridMethod != "auto" && o.hybridMethod != "stencil" &&
        o.hybridMethod != "lists")
    {
        error = "--hybrid-method takes auto, stencil or lists";
        return false;
    }
    if (a.read("--depth-prepass", o.depthPrepass) && o.depthPrepass != "auto" && o.depthPrepass != "on" &&
        o.depthPrepass != "off")
    {
        error = "--depth-prepass takes auto, on or off";
        return false;
    }
    if (a.read("--shadow-ray-offset", o.shadowRayOffset) && !(o.shadowRayOffset >= 0.0f && std::isfinite(o.shadowRayOffset)))
    {
        error = "--shadow-ray-offset takes a finite number of at least 0";
        return false;
    }
    if (a.read("--reference-offset", o.referenceOffset) && !(o.referenceOffset >= 0.0 && std::isfinite(o.referenceOffset)))
    {
        error = "--reference-offset takes a finite number of at least 0";
        return false;
    }
    if (a.read("--polygon-offset", o.polygonOffsetFactor, o.polygonOffsetUnits) &&
        !(o.polygonOffsetFactor >= 0.0f && o.polygonOffsetUnits >= 0.0f))
    {
        error = "--polygon-offset takes two non-negative numbers, FACTOR UNITS";
        return false;
    }
    if (a.read("--offscreen")) o.offscreen = true;
    if (a.read("--ground")) o.ground = true;
    if (a.read("--check-gl-errors")) o.checkGLErrors = true;
    if (a.read("--moving-light")) o.movingLight = true;
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
      << "            osgShadow:LightSpacePerspectiveShadowMapCB|osgShadow:ViewDependentShadowMap]\n"
      << "    [--map-size N] [--size W H] [--eye X Y Z] [--center X Y Z] [--up X Y Z] [--fovy DEG]\n"
      << "    [--light-dir X Y Z | --light-pos X Y Z [--spot-dir X Y Z] [--spot-cutoff DEG]]...\n"
      << "    [--max-shadow-lights N] [--frames N] [--warmup N]\n"
      << "    [--out color.png] [--mask mask%d.png] [--offscreen]\n"
      << "    [--reference ref%d.png] [--reference-offset S] [--compare ref%d.png] [--diff diff%d.png] [--classes classes%d.png]\n"
      << "    [--blocker-culling on|off] [--hybrid-method auto|stencil|lists] [--hybrid-edges on|off] [--polygon-offset FACTOR UNITS]\n"
      << "    [--depth-prepass auto|on|off] [--shadow-ray-offset F] [--skip-empty-faces on|off] [--per-pixel-lighting on|off]\n"
      << "    [--moving-light] [--ground] [--check-gl-errors]\n";
    return s.str();
}

} // namespace osshar
