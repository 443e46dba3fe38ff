// Internal: the technique's one-time warnings, as the passes and planners raise them.
#ifndef OSGSHADOWSILHOUETTE_WARNINGS_H
#define OSGSHADOWSILHOUETTE_WARNINGS_H

#include <functional>
#include <string>

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
};

/** Raises warning @p key with @p message (the technique's warnOnce()). */
using Warn = std::function<void(int key, const std::string& message)>;

} // namespace detail
} // namespace osgShadowSilhouette

#endif
