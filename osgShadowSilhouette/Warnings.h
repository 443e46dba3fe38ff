// Internal: the technique's one-time warnings, as the passes and planners raise them, and
// the log that gives each once.
#ifndef OSGSHADOWSILHOUETTE_WARNINGS_H
#define OSGSHADOWSILHOUETTE_WARNINGS_H

#include <osgShadowSilhouette/CasterEdges>

#include <osg/Drawable>
#include <osg/Light>
#include <osg/Node>
#include <osg/observer_ptr>
#include <OpenThreads/Mutex>

#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** The keys of SilhouetteShadowTechnique::warnOnce(): each warns once per technique. */
enum WarningKey
{
    WARN_OVER_BUDGET = 1,
    WARN_NO_LIGHT,
    WARN_MAP_SIZE,
    WARN_NO_STENCIL,
    WARN_FACE_SLOTS,
    WARN_NO_TRIANGLE_LISTS,
    WARN_LIST_SLOTS,
    WARN_LIST_OVERFLOW,
    WARN_LIST_FULL,
    WARN_CONTEXT_MAP_SIZE,
    WARN_LIGHT_NUM,
    WARN_DEBUG_LIGHT,
    WARN_SCREEN_VISIBILITY,
    WARN_BLENDED_VISIBILITY,
    WARN_FILTER_MODE,
    WARN_STENCIL_SOFT,
    WARN_WARP_MODE,
    WARN_CASCADE_SLOTS,
};

/** Raises warning @p key with @p message (the technique's warnOnce()). */
using Warn = std::function<void(int key, const std::string& message)>;

/** What a technique has warned about, so that each warning is given once: by key, by
 *  drawable or by light. Thread-safe (cull threads of several views share it). */
class WarningLog
{
public:
    /** Warning @p key, the first time it is raised. */
    void once(int key, const std::string& message);

    /** Once per drawable: its NaN or infinite vertices leave it out of casting. */
    void nonFinite(const osg::Drawable& drawable);

    /** Once per light: @p refusal (its non-finite value) leaves it out; names its
     *  LightSource, found below @p root (may be null). */
    void refusedLight(osg::Node* root, const osg::Light& light, const std::string& refusal);

    /** Once per light: its size (@p refusal says which and why) cannot be used, so it
     *  casts a hard shadow. */
    void refusedLightSize(const osg::Light& light, const std::string& refusal);

    /** The drawables under GL_ALPHA_TEST (found by the technique's init()). */
    void setAlphaTested(std::vector<osg::observer_ptr<osg::Drawable>> drawables);
    /** One message per mode (SHADOW_VOLUME; HYBRID with stencil volumes or with @p lists)
     *  naming the alpha-tested drawables not yet named in it: the exact tests take their
     *  triangles whole. */
    void alphaTested(bool hybrid, bool lists);

private:
    OpenThreads::Mutex _mutex;
    std::set<int> _keys;
    std::set<const osg::Drawable*> _nonFinite;
    std::set<const osg::Light*> _lights, _sizedLights;
    std::vector<osg::observer_ptr<osg::Drawable>> _alphaTested;
    std::set<std::pair<int, const osg::Drawable*>>
        _alphaTestedNamed; ///< (0 volumes, 1 HYBRID stencil, 2 lists; drawable)
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
