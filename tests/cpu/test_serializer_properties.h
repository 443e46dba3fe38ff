// The properties of SilhouetteShadowTechnique as the serializer tests see them: one row per
// row of the table of properties (osgShadowSilhouette/Properties), with its example value.
#ifndef OSS_TESTS_SERIALIZER_PROPERTIES_H
#define OSS_TESTS_SERIALIZER_PROPERTIES_H

#include <osgShadowSilhouette/Properties>
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

/** One row per property of the table (osgShadowSilhouette/Properties), set to its example:
 *  a property added to the table is covered by every test of these rows. */
inline const std::vector<PropertyRow>& propertyRows()
{
    static const std::vector<PropertyRow> rows = [] {
        std::vector<PropertyRow> list;
        for (const osgShadowSilhouette::PropertyInfo& p : osgShadowSilhouette::properties())
        {
            list.push_back(
                {p.name, [&p](Technique& t) { p.set(t, p.example); },
                 [&p](const Technique& t) { return osgShadowSilhouette::formatPropertyValue(p, p.get(t)); }});
        }
        return list;
    }();
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
