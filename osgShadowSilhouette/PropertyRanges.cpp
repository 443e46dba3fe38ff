#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/ShaderConstants>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace osgShadowSilhouette {

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

} // namespace

const std::vector<NumericPropertyRange>& numericPropertyRanges()
{
    static const std::vector<NumericPropertyRange> ranges = {
        {"ShadowMapSize", 1, 16384, true, "texels per side; the context's GL_MAX_TEXTURE_SIZE may lower it"},
        {"PolygonOffsetFactor", -INF, INF, false, "negative: automatic"},
        {"PolygonOffsetUnits", -INF, INF, false, ""},
        {"LightNum", -1, shader::MAX_SCENE_LIGHTS - 1, true, "-1: every light"},
        {"MaxShadowLights", 1, shader::MAX_SHADOW_LIGHTS, true, ""},
        {"BaseTextureUnit", 1, 31, true, ""},
        {"DebugLight", 0, shader::MAX_SCENE_LIGHTS - 1, true, "an index among the lights found"},
        {"ShadowRayOffset", 0, 1, false, "a share of the shadowed scene's radius"},
    };
    return ranges;
}

const NumericPropertyRange* numericPropertyRange(const std::string& name)
{
    for (const NumericPropertyRange& r : numericPropertyRanges())
        if (name == r.name) return &r;
    return nullptr;
}

std::string describeRange(const NumericPropertyRange& range)
{
    std::ostringstream s;
    if (std::isinf(range.min) && std::isinf(range.max)) s << "any finite number";
    else if (std::isinf(range.max)) s << "at least " << range.min;
    else s << range.min << " to " << range.max;
    if (range.integer && !(std::isinf(range.min) && std::isinf(range.max))) s << ", whole";
    if (*range.note) s << ": " << range.note;
    return s.str();
}

bool inRange(const NumericPropertyRange& range, double value)
{
    return std::isfinite(value) && value >= range.min && value <= range.max &&
           (!range.integer || std::floor(value) == value);
}

bool parseNumber(const std::string& text, double& value)
{
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
    if (text.find_first_of("xXpP") != std::string::npos) return false; // strtod's hexadecimal forms
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return false;
    value = v;
    return true;
}

std::string refusedValueMessage(const std::string& where, const NumericPropertyRange& range, const std::string& text,
                                bool isNumber, const std::string& kept)
{
    return where + ": " + range.name + " " + text + (isNumber ? " is out of range (" : " is not a finite number (") +
           describeRange(range) + "); keeping " + kept;
}

}
