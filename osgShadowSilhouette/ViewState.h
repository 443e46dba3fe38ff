// Internal: a view's receiver state (ViewData): how it is laid out once, and the uniforms
// each frame writes into it.
#ifndef OSGSHADOWSILHOUETTE_VIEWSTATE_H
#define OSGSHADOWSILHOUETTE_VIEWSTATE_H

#include "EyePass.h"
#include "FrameData.h"

#include <osgUtil/CullVisitor>

namespace osgShadowSilhouette {
namespace detail {

/** How a view's receiver state is laid out: its shadow slots and their texture units. */
struct ViewLayout
{
    unsigned int slots = 1;       ///< slots a view can use (the larger of the two layouts)
    unsigned int pairedSlots = 1; ///< slots with a second map: the second maps' units follow theirs
    unsigned int baseUnit = 8;    ///< BaseTextureUnit: slot s's depth map is on baseUnit + s
    unsigned int maxShadowLights = 4;
    unsigned int mapSize = 2048;
    unsigned int mapBinding = 0;             ///< how the maps' textures are bound (OVERRIDE or not)
    osg::Program* receiverProgram = nullptr; ///< the technique's receiver shading; null: none
    osg::Texture2D* litTexture = nullptr;    ///< every slot's placeholder: lit everywhere
    osg::ref_ptr<osg::StateSet> prepassStateSet;
};

/** A view's receiver state sets, uniforms, per-slot data and exact-pixel counter. */
osg::ref_ptr<ViewData> createViewData(const ViewLayout& layout);

/** This frame's light and slot uniforms of the view, and the slots the eye pass evaluates
 *  into @p eye (used, skipped, cube faces). */
void updateViewUniforms(osgUtil::CullVisitor& cv, ViewData& vd, const std::vector<FoundLight>& lights,
                        const std::vector<int>& slots, EyePassPlan& eye);

/** The exact test's ray offset and the lookups' depth bias scale with the shadowed scene's
 *  @p bound, in eye space. */
void updateRayFrames(osgUtil::CullVisitor& cv, ViewData& vd, const osg::BoundingSphere& bound, float shadowRayOffset);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
