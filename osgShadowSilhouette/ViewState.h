// Internal: a view's receiver state (ViewData): how it is laid out once, and the uniforms
// each frame writes into it.
#ifndef OSGSHADOWSILHOUETTE_VIEWSTATE_H
#define OSGSHADOWSILHOUETTE_VIEWSTATE_H

#include "CasterVertexStages.h"
#include "EyePass.h"
#include "FrameData.h"
#include "ScreenVisibility.h"

#include <osgShadowSilhouette/TriangleListPass>

#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>

#include <functional>

namespace osgShadowSilhouette {
namespace detail {

/** oss_slotDepths' far end for a map that answers at every view depth (a float's range). */
constexpr float ALL_DEPTHS = 3.0e38f;

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

/** Every slot of the view with nothing to shadow this frame: owned by itself, no cube face,
 *  not in use; the slots below @p capacity read @p litTexture as their depth map. */
void resetSlots(ViewData& vd, unsigned int capacity, osg::Texture2D* litTexture);

/** Binds @p texture as slot @p slot's depth map in the eye pass. */
void bindDepthMap(ViewData& vd, unsigned int slot, osg::Texture2D* texture);

/** Binds each paired slot's second map (silhouette map or edge mask): maps[slot], or
 *  @p fallback past their end; unbinds them all when @p maps is empty. */
void bindSecondMaps(ViewData& vd, const std::vector<osg::Texture2D*>& maps, osg::Texture2D* fallback);

/** Culls @p scene's children for the eye under the receivers' traversal mask, inside the
 *  view's receiver state and @p pass (may be null); the ShadowSettings'
 *  ComputeNearFarModeOverride decides how the view computes its near and far planes over the
 *  receivers (as ViewDependentShadowMap), and so the range visibleReceiverRegion() fits.
 *  Without an override, @p tightNear (the stencil modes) takes the near plane from the
 *  receivers' primitives where the view computes it from bounding volumes. The primitive
 *  modes' deferred drawables are resolved before it returns. */
void cullReceivers(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, ViewData& vd, osg::StateSet* pass,
                   CasterVertexStages* stages = nullptr, ListedDrawables* faces = nullptr, bool tightNear = false);

/** Culls @p scene's children for the eye under the casters' traversal mask inside @p pass
 *  alone (the view's receiver state stays out), without view-frustum or small-feature
 *  culling (a caster outside the view shadows what is in it) and without computing near and
 *  far (the view's planes stay those of what it sees): volumes extruded on the GPU. */
void cullCasters(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, osg::StateSet* pass);

/** Culls the depth prepass of the receivers (DepthPrepass) through @p cullReceivers under the
 *  view's prepass state, and keeps of it only what it draws exactly as the eye pass does. */
void cullDepthPrepass(osgUtil::CullVisitor& cv, ViewData& vd,
                      const std::function<void(osg::StateSet* pass)>& cullReceivers);

/** Calls @p op on every object of the view that holds GL objects: its state sets, stencil
 *  passes, screen-space visibility, counters, and each slot's camera, maps and queries. */
template <class Op>
void forEachGLObjectHolder(ViewData& vd, const Op& op)
{
    op(vd.receiverStateSet.get());
    op(vd.receiverPassStateSet.get());
    op(vd.prepassStateSet.get());
    op(vd.stencil.get());
    op(static_cast<ScreenVisibility*>(vd.screenVisibility.get()));
    op(vd.exactCounter.get());
    op(vd.exactBegin.get());
    op(vd.exactEnd.get());
    for (LightPass& pass : vd.passes)
    {
        op(pass.depthCamera.get());
        op(pass.depthTexture.get());
        op(pass.silhouettePass.get());
        op(pass.blockers.get());
        op(pass.listPass.get());
        op(pass.samples.get());
    }
}

} // namespace detail
} // namespace osgShadowSilhouette

#endif
