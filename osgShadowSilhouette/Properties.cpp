// The table of SilhouetteShadowTechnique's properties (Properties) and what reads and
// writes values through it.
#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Notify>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <type_traits>

namespace osgShadowSilhouette {

namespace {

using T = SilhouetteShadowTechnique;
using P = PropertyInfo;

constexpr double INF = std::numeric_limits<double>::infinity();

template <typename S>
struct SetterArgument;
template <typename V>
struct SetterArgument<void (T::*)(V)>
{
    using type = V;
};

template <auto Get>
double getValue(const T& t)
{
    return double((t.*Get)());
}

template <auto Set>
void setValue(T& t, double value)
{
    using V = typename SetterArgument<decltype(Set)>::type;
    if constexpr (std::is_enum_v<V>)
        (t.*Set)(static_cast<V>(static_cast<int>(value)));
    else if constexpr (std::is_same_v<V, bool>)
        (t.*Set)(value != 0.0);
    else if constexpr (std::is_integral_v<V>)
    {
        // A value the type cannot hold becomes one past every range, which the setter refuses
        // with its warning (a conversion would be undefined).
        const bool fits =
            value >= double(std::numeric_limits<V>::lowest()) && value <= double(std::numeric_limits<V>::max());
        (t.*Set)(fits ? static_cast<V>(value) : std::numeric_limits<V>::max());
    }
    else
        (t.*Set)(static_cast<V>(value));
}

// A row a property reads better than clang-format's one field a line:
// clang-format off
/** The name and the accessors of a row: OSS_PROPERTY(ShadowMapSize). */
#define OSS_PROPERTY(NAME) #NAME, &getValue<&T::get##NAME>, &setValue<&T::set##NAME>

constexpr int LAST_LIGHT = shader::MAX_SCENE_LIGHTS - 1;

// The table in three parts, in the serializer's order: the algorithm and its depth maps;
// lights, texture units, shading and debug views; HYBRID and the eye pass.

std::vector<PropertyInfo> algorithmRows()
{
    return {
        {OSS_PROPERTY(Mode), P::ENUM, T::SHADOW_MAP, T::HYBRID, 0, 3, "",
         {{"SHADOW_MAP", T::SHADOW_MAP, "shadowmap"},
          {"SILHOUETTE_MAP", T::SILHOUETTE_MAP, "silhouette"},
          {"HYBRID", T::HYBRID, "hybrid"},
          {"SHADOW_VOLUME", T::SHADOW_VOLUME, "volume"}},
         "the shadow algorithm",
         "`getEffectiveMode()` tells what is rendered"},
        {OSS_PROPERTY(ShadowMapSize), P::UINT, 2048, 1024, 1, 16384,
         "texels per side; the context's GL_MAX_TEXTURE_SIZE may lower it", {},
         "width and height of each light's depth map",
         "a size past the context's GL_MAX_TEXTURE_SIZE is clamped to it with a warning"},
        {OSS_PROPERTY(PolygonOffsetFactor), P::FLOAT, T::AUTOMATIC_POLYGON_OFFSET_FACTOR, 2.25, -INF, INF,
         "negative means automatic", {},
         "slope-scaled depth bias of the depth pass (glPolygonOffset factor)",
         "negative: 0 in HYBRID (its lookup compares each depth sample with the receiver's plane and sends "
         "the pixels the bias decides to the exact test), 2 for SHADOW_MAP's maps warped by `PerspectiveWarp`, "
         "1.1 otherwise; every lookup also subtracts a "
         "world-space bias, a share of the scene's radius converted into the map's depth at the receiver "
         "([docs/bias.md](docs/bias.md))"},
        {OSS_PROPERTY(PolygonOffsetUnits), P::FLOAT, 4, 7.5, -INF, INF, "", {},
         "constant depth bias of the depth pass (glPolygonOffset units)",
         ""},
        {OSS_PROPERTY(GpuExtraction), P::ENUM, T::GPU_EXTRACTION_MOVED_CASTERS, T::GPU_EXTRACTION_ALL_CASTERS, 0, 1, "",
         {{"GPU_EXTRACTION_MOVED_CASTERS", T::GPU_EXTRACTION_MOVED_CASTERS, "moved"},
          {"GPU_EXTRACTION_ALL_CASTERS", T::GPU_EXTRACTION_ALL_CASTERS, "all"}},
         "which casters' silhouette edges and shadow volumes a geometry stage finds on the GPU",
         "`GPU_EXTRACTION_MOVED_CASTERS`: those a vertex stage of their own moves (hardware skinning, "
         "`ShadowMovesVertices`), whose final positions the CPU never sees; `GPU_EXTRACTION_ALL_CASTERS`: "
         "every caster, none extracted on the CPU. SILHOUETTE_MAP's maps, FILTER_SILHOUETTE's distance maps "
         "and HYBRID's edge masks ([docs/animation.md](docs/animation.md#silhouette-edges-found-on-the-gpu)); "
         "SHADOW_VOLUME and HYBRID's stencil volumes "
         "([docs/animation.md](docs/animation.md#volumes-extruded-on-the-gpu))"},
        {OSS_PROPERTY(PerspectiveWarp), P::BOOL, 0, 1, 0, 1, "", {},
         "warp directional lights' maps in perspective toward the eye (light space perspective shadow maps)",
         "SHADOW_MAP and SILHOUETTE_MAP under `FILTER_PCF_2X2` and `FILTER_PCF`, HYBRID's classification map "
         "and triangle lists under lights without a size; the warp's axis, centre and texels move in steps, so "
         "that shadows hold still while the eye moves; elsewhere one warning and uniform maps ([docs/outdoor.md](docs/outdoor.md#the-perspective-warp-property-perspectivewarp))"},
        {OSS_PROPERTY(Cascades), P::UINT, 1, 3, 1, 4, "", {},
         "maps per directional light, each for a range of the view's depths (parallel split shadow maps)",
         "the splits mix the logarithmic and the uniform split (weight 0.9 on the logarithmic); each map "
         "answers for its range alone, warped under `PerspectiveWarp`; every mode with maps; each takes a "
         "shadow slot, and a light the slots cannot hold gets one map, with a warning "
         "([docs/outdoor.md](docs/outdoor.md#cascades-property-cascades))"},
    };
}

std::vector<PropertyInfo> lightRows()
{
    return {
        {OSS_PROPERTY(LightNum), P::INT, -1, 3, -1, LAST_LIGHT, "-1: every light", {},
         "the GL light number that casts shadows; -1: every light found, in light-number order",
         "one that names no light of the view is warned about, naming the lights found"},
        {OSS_PROPERTY(MaxShadowLights), P::UINT, 4, 2, 1, shader::MAX_SHADOW_LIGHTS, "", {},
         "most lights shadowed at once",
         "the rest are lit unshadowed, with one warning; lights whose cone or range misses the view take "
         "no part of it"},
        {OSS_PROPERTY(BaseTextureUnit), P::UINT, 8, 5, 1, 31, "", {},
         "first texture unit of the shadow maps",
         "one per shadow slot (a shadowed light, or a further cube face of a point light), then, in "
         "SILHOUETTE_MAP and HYBRID, one more per slot for the silhouette maps (SILHOUETTE_MAP's, and "
         "HYBRID's edge masks); below unit 32 that makes 24 slots in SHADOW_MAP and 12 in the other modes "
         "by default (HYBRID's triangle lists take no texture unit: per slot one read-only image on image "
         "unit 0 + slot where the context has the image uniforms, else one shader storage block on binding "
         "1 + slot); in the eye pass these bindings override the model's own on the same units (unless the "
         "ShadowSettings' `UseOverrideForShadowMapTexture` is false; a program of the model's own that "
         "samples them needs another BaseTextureUnit)"},
        {OSS_PROPERTY(UseDefaultShading), P::BOOL, 1, 0, 0, 1, "", {},
         "whether the technique installs its receiver shading program",
         ""},
        {OSS_PROPERTY(DebugView), P::ENUM, T::DEBUG_NONE, T::DEBUG_SHADOW_MASK, 0, 5, "",
         {{"DEBUG_NONE", T::DEBUG_NONE, "none"},
          {"DEBUG_SHADOW_MASK", T::DEBUG_SHADOW_MASK, "mask"},
          {"DEBUG_SILHOUETTE_PIXELS", T::DEBUG_SILHOUETTE_PIXELS, "pixels"},
          {"DEBUG_SILHOUETTE_MAP", T::DEBUG_SILHOUETTE_MAP, "silmap"},
          {"DEBUG_CLASSES", T::DEBUG_CLASSES, "classes"},
          {"DEBUG_VISIBILITY", T::DEBUG_VISIBILITY, "visibility"}},
         "what the eye pass shows of light DebugLight instead of the shaded scene",
         "`DEBUG_SHADOW_MASK`: the MEASURE.md mask; `DEBUG_SILHOUETTE_PIXELS`, `DEBUG_SILHOUETTE_MAP`: "
         "SILHOUETTE_MAP's silhouette pixels (green) and its silhouette map (under `FILTER_SILHOUETTE`: "
         "its edge distances, orange on the casting side, blue outside); `DEBUG_CLASSES`: every "
         "mode's pixel classes in Chan and Durand's colours (below); `DEBUG_VISIBILITY`: the light's "
         "visibility as a grey level, the mask before its threshold (fractions under a soft `Filter`)"},
        {OSS_PROPERTY(DebugLight), P::UINT, 0, 2, 0, LAST_LIGHT, "an index among the lights found", {},
         "the light the debug views show",
         "past the view's lights: a warning"},
    };
}

std::vector<PropertyInfo> hybridRows()
{
    return {
        {OSS_PROPERTY(BlockerCulling), P::BOOL, 1, 0, 0, 1, "", {},
         "HYBRID: skip the shadow volumes of casters hidden from the light",
         "with stencil volumes and `HybridEdgeMask` false (occlusion queries against its depth map, "
         "conditional rendering); with the edge mask no caster is skipped, since one the map calls hidden "
         "may shadow what shows through gaps thinner than a texel"},
        {OSS_PROPERTY(HybridMethod), P::ENUM, T::HYBRID_AUTO, T::HYBRID_TRIANGLE_LISTS, 0, 2, "",
         {{"HYBRID_AUTO", T::HYBRID_AUTO, "auto"},
          {"HYBRID_STENCIL_VOLUMES", T::HYBRID_STENCIL_VOLUMES, "stencil"},
          {"HYBRID_TRIANGLE_LISTS", T::HYBRID_TRIANGLE_LISTS, "lists"}},
         "how HYBRID resolves silhouette pixels: triangle lists or stencil-masked volumes",
         "`HYBRID_TRIANGLE_LISTS`: a shadow ray against the caster triangles listed per light-space texel "
         "(GL 4.3); `HYBRID_STENCIL_VOLUMES`: Chan and Durand's stencil-masked volumes; AUTO takes the "
         "lists where GL 4.3 is available ([measurements](docs/shadow-volumes.md))"},
        {OSS_PROPERTY(HybridEdgeMask), P::BOOL, 1, 0, 0, 1, "", {},
         "HYBRID: also resolve exactly the pixels a silhouette edge of the light crosses",
         "the pixels whose four depth samples a silhouette edge passes between, in front of the point "
         "(casters and gaps thinner than a texel, which 2x2 PCF cannot see), from an edge mask per light: "
         "a silhouette map holding the nearest edge depth per texel; makes HYBRID at map size 256 at least "
         "as accurate as SHADOW_VOLUME "
         "([measurements](docs/shadow-volumes.md#hybrids-edge-mask-property-hybridedgemask))"},
        {OSS_PROPERTY(DepthPrepass), P::ENUM, T::DEPTH_PREPASS_AUTO, T::DEPTH_PREPASS_OFF, 0, 2, "",
         {{"DEPTH_PREPASS_AUTO", T::DEPTH_PREPASS_AUTO, "auto"},
          {"DEPTH_PREPASS_ON", T::DEPTH_PREPASS_ON, "on"},
          {"DEPTH_PREPASS_OFF", T::DEPTH_PREPASS_OFF, "off"}},
         "draw the receivers' depth before the eye pass, so that its shading runs once per pixel",
         "AUTO: in HYBRID with triangle lists and the default shading, `DEPTH_PREPASS_ON`: in every "
         "shadow-map mode; drawables with a program, an `osg::Depth` or blending of their own, or in a "
         "transparent or later bin, stay out of it "
         "([measurements](docs/shadow-volumes.md#the-eye-passs-depth-prepass-property-depthprepass))"},
        {OSS_PROPERTY(ShadowRayOffset), P::FLOAT, T::DEFAULT_SHADOW_RAY_OFFSET, 2.5e-4, 0, 1,
         "a share of the shadowed scene's radius", {},
         "HYBRID's exact test: shadow rays start this fraction of the scene's radius off the surface",
         "the offset, plus 1e-6 per unit of distance from the scene's centre, is taken along the geometric "
         "normal, as a ray tracer's and the exact reference's is; points that close to a shadow boundary "
         "take the offset point's answer "
         "([measurements](docs/shadow-volumes.md#where-the-lists-shadow-rays-start), "
         "[the reference's offset](docs/reference.md))"},
        {OSS_PROPERTY(PerPixelLighting), P::BOOL, 1, 0, 0, 1, "", {},
         "light the receivers per pixel (true) or per vertex, as the fixed function does",
         "the receiver shading evaluates OpenGL's fixed-function lighting (gl_LightSource, osg::Material, "
         "spot cone and exponent, attenuation); per vertex, a spot light's lit disc on coarse geometry (a "
         "ground of four vertices, none inside the cone) does not show while its shadow does; per pixel it "
         "shows, as users of spot lights expect "
         "([docs/lights.md](docs/lights.md#lighting-per-pixel-or-per-vertex-property-perpixellighting))"},
    };
}

std::vector<PropertyInfo> filterRows()
{
    return {
        {OSS_PROPERTY(Filter), P::ENUM, T::FILTER_PCF_2X2, T::FILTER_PCSS, 0, 3, "",
         {{"FILTER_PCF_2X2", T::FILTER_PCF_2X2, "pcf2x2"},
          {"FILTER_PCF", T::FILTER_PCF, "pcf"},
          {"FILTER_PCSS", T::FILTER_PCSS, "pcss"},
          {"FILTER_SILHOUETTE", T::FILTER_SILHOUETTE, "silhouette"}},
         "how SHADOW_MAP filters its depth maps (2x2 PCF, an N x N PCF window, PCSS soft shadows), or "
         "SILHOUETTE_MAP its edges (silhouette distances: anti-aliased or soft)",
         "`FILTER_PCF`: Doverspike's `FilterWindow` x `FilterWindow` window of bilinear PCF taps; "
         "`FILTER_PCSS`: a blocker search, a penumbra as wide as `LightSize` and the blockers' depth say, "
         "and a disc of PCF taps that wide; `FILTER_SILHOUETTE` (SILHOUETTE_MAP): signed distances to "
         "the silhouette edges, a disc light's penumbra across each edge; the other modes keep their hard "
         "answer and warn once "
         "([docs/soft-shadows.md](docs/soft-shadows.md))"},
        {OSS_PROPERTY(FilterWindow), P::UINT, 3, 5, 1, shader::FILTER_WINDOW_MAX, "", {},
         "`FILTER_PCF`: the N of its N x N window of taps, one texel apart",
         "1 is the 2x2 baseline"},
        {OSS_PROPERTY(LightSize), P::FLOAT, 0, 1.5, 0, 1e6,
         "scene units (point, spot) or degrees (directional)", {},
         "every light's size for the soft filters: a sphere's radius, or a directional light's angular radius",
         "0: hard shadows; a light's own size, the float user value `ShadowLightSize` on its `osg::Light` "
         "or `osg::LightSource`, wins (a directional light's below 45 degrees; others warn and cast hard)"},
        {OSS_PROPERTY(SoftSamples), P::UINT, 64, 256, 1, 1024, "", {},
         "HYBRID (triangle lists) under a light with a size: the shadow rays cast from each penumbra pixel "
         "toward the light, each tested against the caster triangles of every texel it crosses",
         "the answer converges to the exact visibility as it grows; from 32 on (a multiple of 4) a pixel whose "
         "first quarter of rays all agree, and its 2 x 2 quad's too, casts no more "
         "([docs/soft-shadows.md](docs/soft-shadows.md#hybrid-exact-penumbrae-shadow-rays-through-the-triangle-lists))"},
    };
}

#undef OSS_PROPERTY
// clang-format on

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

NumericPropertyRange rangeOf(const PropertyInfo& p)
{
    return {p.name, p.min, p.max, p.type != PropertyInfo::FLOAT, p.rangeNote};
}

const PropertyEnumValue* enumValue(const PropertyInfo& p, double value)
{
    for (const PropertyEnumValue& e : p.enumValues)
        if (double(e.value) == value) return &e;
    return nullptr;
}

bool parseBool(const std::string& text, double& value)
{
    const std::string t = lower(text);
    if (t == "on" || t == "true" || t == "1")
        value = 1.0;
    else if (t == "off" || t == "false" || t == "0")
        value = 0.0;
    else
        return false;
    return true;
}

bool parseEnum(const PropertyInfo& p, const std::string& text, double& value)
{
    const std::string t = lower(text);
    for (const PropertyEnumValue& e : p.enumValues)
    {
        if (t == lower(e.name) || t == e.shortName)
        {
            value = e.value;
            return true;
        }
    }
    return false;
}

/** The enum's names (or short names), each between quotes, joined by separator. */
std::string enumNames(const PropertyInfo& p, bool shortNames, const std::string& separator = ", ",
                      const std::string& quote = "")
{
    std::string names;
    for (const PropertyEnumValue& e : p.enumValues)
        names += (names.empty() ? "" : separator) + quote + (shortNames ? e.shortName : e.name) + quote;
    return names;
}

/** A markdown table cell: a '|' would end it. */
std::string cell(const std::string& text)
{
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

} // namespace

const std::vector<PropertyInfo>& properties()
{
    static const std::vector<PropertyInfo> table = [] {
        std::vector<PropertyInfo> rows;
        for (auto part : {algorithmRows, lightRows, hybridRows, filterRows})
            for (PropertyInfo& row : part()) rows.push_back(std::move(row));
        return rows;
    }();
    return table;
}

const PropertyInfo* findProperty(const std::string& name)
{
    const std::string wanted = lower(name);
    for (const PropertyInfo& p : properties())
        if (lower(p.name) == wanted) return &p;
    return nullptr;
}

bool isPropertyValue(const PropertyInfo& p, double value)
{
    switch (p.type)
    {
    case PropertyInfo::BOOL: return value == 0.0 || value == 1.0;
    case PropertyInfo::ENUM: return enumValue(p, value) != nullptr;
    default: return inRange(rangeOf(p), value);
    }
}

bool parsePropertyValue(const PropertyInfo& p, const std::string& text, double& value, std::string& error)
{
    double parsed = 0.0;
    bool ok = false;
    switch (p.type)
    {
    case PropertyInfo::BOOL: ok = parseBool(text, parsed); break;
    case PropertyInfo::ENUM: ok = parseEnum(p, text, parsed); break;
    default:
        if (!parseNumber(text, parsed))
        {
            error = "is not a finite number (" + describePropertyValues(p) + ")";
            return false;
        }
        ok = isPropertyValue(p, parsed);
        if (!ok)
        {
            error = "is out of range (" + describePropertyValues(p) + ")";
            return false;
        }
    }
    if (!ok)
    {
        error = "is not one of " + (p.type == PropertyInfo::BOOL
                                        ? std::string("TRUE, FALSE (or on, off, 1, 0)")
                                        : enumNames(p, false) + " (or " + enumNames(p, true) + ")");
        return false;
    }
    value = parsed;
    return true;
}

std::string formatPropertyValue(const PropertyInfo& p, double value)
{
    if (p.type == PropertyInfo::BOOL && isPropertyValue(p, value)) return value != 0.0 ? "TRUE" : "FALSE";
    if (p.type == PropertyInfo::ENUM)
        if (const PropertyEnumValue* e = enumValue(p, value)) return e->name;
    // The fewest digits that read back as the same float ("1e-06", not "9.99999997e-07").
    for (int digits = 6;; ++digits)
    {
        std::ostringstream s;
        s.precision(digits);
        s << value;
        if (p.type != PropertyInfo::FLOAT || digits >= 9 ||
            float(std::strtod(s.str().c_str(), nullptr)) == float(value))
            return s.str();
    }
}

std::string describePropertyValues(const PropertyInfo& p)
{
    switch (p.type)
    {
    case PropertyInfo::BOOL: return "on|off";
    case PropertyInfo::ENUM: return enumNames(p, true, "|");
    default: return describeRange(rangeOf(p));
    }
}

std::string propertyValueSyntax(const PropertyInfo& p)
{
    return p.type == PropertyInfo::FLOAT ? "f" : p.numeric() ? "n" : describePropertyValues(p);
}

bool setPropertyFromText(SilhouetteShadowTechnique& technique, const std::string& name, const std::string& text,
                         const std::string& where)
{
    const PropertyInfo* p = findProperty(name);
    if (!p)
    {
        OSG_WARN << where << ": no property is named " << name << "; ignored" << std::endl;
        return false;
    }
    double value = 0.0;
    std::string error;
    if (!parsePropertyValue(*p, text, value, error))
    {
        OSG_WARN << where << ": " << p->name << " " << text << " " << error << "; keeping "
                 << formatPropertyValue(*p, p->get(technique)) << std::endl;
        return false;
    }
    p->set(technique, value);
    return true;
}

std::string propertiesMarkdown()
{
    std::ostringstream s;
    s << "| property | values | default | meaning |\n| --- | --- | --- | --- |\n";
    for (const PropertyInfo& p : properties())
    {
        const std::string values = p.type == PropertyInfo::ENUM   ? enumNames(p, false, ", ", "`")
                                   : p.type == PropertyInfo::BOOL ? std::string("`TRUE`, `FALSE`")
                                                                  : describePropertyValues(p);
        s << "| `" << p.name << "` | " << cell(values) << " | `" << formatPropertyValue(p, p.defaultValue) << "` | "
          << cell(p.doc) << (*p.more ? "; " + cell(p.more) : std::string()) << " |\n";
    }
    return s.str();
}

} // namespace osgShadowSilhouette
