// Internal: which lights of a view get a shadow, in which slots, with which frusta; where the
// lights are and what of the receivers the view sees. Plain functions of the cull's inputs and
// the technique's properties, tested on the CPU (cpu_light_planning).
#ifndef OSGSHADOWSILHOUETTE_LIGHTPLANNING_H
#define OSGSHADOWSILHOUETTE_LIGHTPLANNING_H

#include "FrameData.h"
#include "Warnings.h"

#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>

#include <functional>
#include <string>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** What decides which lights get a shadow and how many slots their maps take. */
struct SlotBudget
{
    int lightNum = -1;                ///< LightNum: only this light casts (-1: every light)
    unsigned int maxShadowLights = 4; ///< MaxShadowLights
    unsigned int mapSize = 2048;      ///< ShadowMapSize, for fitting the frusta to texels
    unsigned int slotLimit = 4;       ///< the slots the mode's texture units hold (cube faces included)
    bool cubeFaces = true;            ///< point lights may take cube faces (not SHADOW_VOLUME)
    double faceMarginTexels = 4.0;    ///< how far a cube face's map reaches past its square (the filter's reach)
    bool warp = false;                ///< directional lights get maps warped toward the eye (PerspectiveWarp)
    unsigned int cascades = 1;        ///< maps per directional light, each for a range of view depths (Cascades)
};

/** Whether @p light casts a shadow under LightNum @p lightNum (-1: every light does). */
bool castsShadow(const FoundLight& light, int lightNum);

/** Each light's slot and frusta for this frame: the casting lights that reach what the view
 *  sees (frame.region), up to MaxShadowLights of them (WARN_OVER_BUDGET for the rest), in
 *  the order of @p lights; a point light takes cube faces where it needs them and they fit
 *  below slotLimit (else one perspective map, WARN_FACE_SLOTS), the faces after the first in
 *  the slots after the lights' own. A light whose reach misses the region counts in
 *  @p lightsSkipped. */
SlotPlan planSlots(const FrameContext& frame, const std::vector<FoundLight>& lights, const SlotBudget& budget,
                   const Warn& warn, unsigned int& lightsSkipped);

/** Called for a light whose position or spot direction is not finite, with what is not. */
using RefusedLight = std::function<void(const osg::Light& light, const std::string& refusal)>;

/** The positional lights of the view, in GL light-number order (of two with one number, the
 *  one OpenGL lights with: the last applied). A light whose position or spot direction is not
 *  finite (LightDescription::fromLight()) is left out, reported to @p refused, and its GL light
 *  number goes to @p refusedNums: OpenGL holds that light's values for the number. */
std::vector<FoundLight> collectLights(osgUtil::CullVisitor& cv, std::vector<int>& refusedNums,
                                      const RefusedLight& refused);

/** Warns once when LightNum or (with a debug view) DebugLight names no light of the view,
 *  saying what exists. */
void warnAboutMissingLights(const std::vector<FoundLight>& lights, int lightNum, bool debugView,
                            unsigned int debugLight, const Warn& warn);

/** World points whose hull holds what the view sees of the receivers (empty: nothing): the
 *  view frustum over the eye range the cull computed (or its projection's, where neither the
 *  view nor @p nearFarOverride computes one), up to @p maximumDistance, cut to @p receivers. */
std::vector<osg::Vec3d> visibleReceiverRegion(osgUtil::CullVisitor& cv, const osg::BoundingBoxd& receivers,
                                              osg::CullSettings::ComputeNearFarMode nearFarOverride,
                                              double maximumDistance);

/** What @p frame needs of @p scene in this cull, for frame.mode: the view's LOD and billboard
 *  choices, the receivers' and casters' bounds, the casters' signature and parts (and those
 *  with non-finite vertices, left out), the visible receiver region (up to the ShadowSettings'
 *  MaximumShadowMapDistance @p maximumDistance in the map modes; the volumes reach any
 *  distance), and but for SHADOW_MAP the triangle casters. */
void gatherFrame(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, MeshCache& meshCache,
                 double maximumDistance, FrameContext& frame);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
