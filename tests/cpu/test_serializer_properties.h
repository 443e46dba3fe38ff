// The properties of SilhouetteShadowTechnique as the serializer tests see them: one row per
// property, with a value that is not the default. A property added to the technique needs a
// row here and a line in plugins/serializers/SilhouetteShadowTechnique.cpp;
// test_serializer.cpp fails until both exist.
#ifndef OSS_TESTS_SERIALIZER_PROPERTIES_H
#define OSS_TESTS_SERIALIZER_PROPERTIES_H

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace osstest {

using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;

struct PropertyRow
{
    std::string name;                                ///< the serializer's (and setter's) name
    std::function<void(Technique&)> setNonDefault;   ///< sets a value that is not the default
    std::function<std::string(const Technique&)> get;///< the getter's value as text
};

template<typename T>
std::string propertyText(const T& value)
{
    std::ostringstream s;
    s.precision(9);
    s << value;
    return s.str();
}

#define OSS_PROPERTY_ROW(PROP, VALUE)                                       \
    osstest::PropertyRow{#PROP, [](osstest::Technique& t) { t.set##PROP(VALUE); }, \
                         [](const osstest::Technique& t) { return osstest::propertyText(t.get##PROP()); }}

inline const std::vector<PropertyRow>& propertyRows()
{
    static const std::vector<PropertyRow> rows = {
        OSS_PROPERTY_ROW(Mode, Technique::HYBRID),
        OSS_PROPERTY_ROW(ShadowMapSize, 1024u),
        OSS_PROPERTY_ROW(PolygonOffsetFactor, 2.25f),
        OSS_PROPERTY_ROW(PolygonOffsetUnits, 7.5f),
        OSS_PROPERTY_ROW(LightNum, 3),
        OSS_PROPERTY_ROW(MaxShadowLights, 2u),
        OSS_PROPERTY_ROW(BaseTextureUnit, 5u),
        OSS_PROPERTY_ROW(UseDefaultShading, false),
        OSS_PROPERTY_ROW(DebugView, Technique::DEBUG_SHADOW_MASK),
        OSS_PROPERTY_ROW(DebugLight, 2u),
        OSS_PROPERTY_ROW(BlockerCulling, false),
        OSS_PROPERTY_ROW(HybridMethod, Technique::HYBRID_TRIANGLE_LISTS),
        OSS_PROPERTY_ROW(HybridEdgeMask, false),
        OSS_PROPERTY_ROW(DepthPrepass, Technique::DEPTH_PREPASS_OFF),
        OSS_PROPERTY_ROW(ShadowRayOffset, 2.5e-4f),
        OSS_PROPERTY_ROW(PerPixelLighting, false),
    };
    return rows;
}

/** The source tree: $OSS_SOURCE_DIR, else found from this header's path. */
inline std::string sourceDir()
{
    const char* env = std::getenv("OSS_SOURCE_DIR");
    if (env && *env) return env;
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}

/** A technique with every property of propertyRows() set to its non-default value. */
inline osg::ref_ptr<Technique> nonDefaultTechnique()
{
    osg::ref_ptr<Technique> t = new Technique;
    for (const PropertyRow& row : propertyRows()) row.setNonDefault(*t);
    return t;
}

} // namespace osstest

#endif
