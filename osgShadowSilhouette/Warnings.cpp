#include "Warnings.h"

#include <osg/LightSource>
#include <osg/NodeVisitor>
#include <osg/Notify>
#include <OpenThreads/ScopedLock>

namespace osgShadowSilhouette {
namespace detail {

namespace {

using Lock = OpenThreads::ScopedLock<OpenThreads::Mutex>;

/** The first LightSource below the root that holds a light. */
class FindSource : public osg::NodeVisitor
{
public:
    explicit FindSource(const osg::Light* light) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), _light(light)
    {
        setNodeMaskOverride(~0u);
    }
    void apply(osg::LightSource& ls) override
    {
        if (ls.getLight() == _light && !found) found = &ls;
        traverse(ls);
    }
    const osg::LightSource* found = nullptr;

private:
    const osg::Light* _light;
};

/** "'a', 'b', 'c', 'd' and 2 more named, 3 unnamed" */
std::string listOf(const std::vector<std::string>& names, std::size_t unnamed)
{
    constexpr std::size_t shown = 4;
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < shown; ++i) list += (i ? ", " : "") + names[i];
    if (names.size() > shown) list += " and " + std::to_string(names.size() - shown) + " more named";
    if (unnamed > 0) list += (list.empty() ? "" : ", ") + std::to_string(unnamed) + " unnamed";
    return list;
}

} // namespace

void WarningLog::once(int key, const std::string& message)
{
    Lock lock(_mutex);
    if (!_keys.insert(key).second) return;
    OSG_WARN << "osgShadowSilhouette: " << message << std::endl;
}

void WarningLog::nonFinite(const osg::Drawable& drawable)
{
    Lock lock(_mutex);
    if (!_nonFinite.insert(&drawable).second) return;
    OSG_WARN << "osgShadowSilhouette: geometry \"" << drawable.getName()
             << "\" has vertices with NaN or infinite coordinates; it casts no shadow" << std::endl;
}

void WarningLog::refusedLight(osg::Node* root, const osg::Light& light, const std::string& refusal)
{
    Lock lock(_mutex);
    if (!_lights.insert(&light).second) return;
    FindSource find(&light);
    if (root) root->accept(find);
    const std::string source = !find.found                     ? "no LightSource found"
                               : find.found->getName().empty() ? "an unnamed LightSource"
                                                               : "LightSource \"" + find.found->getName() + "\"";
    OSG_WARN << "osgShadowSilhouette: light " << light.getLightNum() << " (" << source << ") has a non-finite "
             << refusal << "; it lights nothing and casts no shadow" << std::endl;
}

void WarningLog::refusedLightSize(const osg::Light& light, const std::string& refusal)
{
    Lock lock(_mutex);
    if (!_sizedLights.insert(&light).second) return;
    OSG_WARN << "osgShadowSilhouette: light " << light.getLightNum() << ": " << refusal << "; it casts a hard shadow"
             << std::endl;
}

void WarningLog::setAlphaTested(std::vector<osg::observer_ptr<osg::Drawable>> drawables)
{
    Lock lock(_mutex);
    _alphaTested = std::move(drawables);
}

void WarningLog::alphaTested(bool hybrid, bool lists)
{
    // One message per mode for the drawables not yet named in it: a forest of billboards is
    // hundreds of alpha-tested drawables.
    Lock lock(_mutex);
    std::vector<std::string> names;
    std::size_t count = 0, unnamed = 0;
    const int variant = hybrid ? (lists ? 2 : 1) : 0;
    for (const osg::observer_ptr<osg::Drawable>& weak : _alphaTested)
    {
        osg::ref_ptr<osg::Drawable> drawable;
        if (!weak.lock(drawable) || !_alphaTestedNamed.insert({variant, drawable.get()}).second) continue;
        ++count;
        if (drawable->getName().empty())
            ++unnamed;
        else
            names.push_back("'" + drawable->getName() + "'");
    }
    if (count == 0) return;
    OSG_WARN << "osgShadowSilhouette: " << (hybrid ? "HYBRID" : "SHADOW_VOLUME") << ": " << count
             << (count == 1 ? " drawable is" : " drawables are")
             << " alpha-tested (GL_ALPHA_TEST): " << listOf(names, unnamed) << "; "
             << (!hybrid ? "stencil shadow volumes cannot cut their shapes out, so they cast their whole triangles"
                 : lists ? "where only their triangles stand between a silhouette pixel and the light, the triangle "
                           "lists keep the shadow map's answer there, not an exact one"
                         : "the stencil volumes of the exact test take their triangles as opaque, so light through "
                           "their cut-outs is lost along the shadows' edges")
             << " (SHADOW_MAP and SILHOUETTE_MAP cast the cut-out shapes)" << std::endl;
}

} // namespace detail
} // namespace osgShadowSilhouette
