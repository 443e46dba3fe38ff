// Internal: one cull of one view by SilhouetteShadowTechnique. The technique's cull() takes
// the steps below in order (docs/architecture.md, "The frame, from cull to draw"); each step
// reads the technique's properties and shared state and fills this frame's plan.
#ifndef OSGSHADOWSILHOUETTE_TECHNIQUECULL_H
#define OSGSHADOWSILHOUETTE_TECHNIQUECULL_H

#include "EyePass.h"
#include "FrameData.h"
#include "ModePass.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <vector>

namespace osgShadowSilhouette {
namespace detail {

class TechniqueCull
{
public:
    using Mode = SilhouetteShadowTechnique::Mode;

    /** Lowers the technique's ShadowMapSize to the context's limit, picks the mode the view
     *  can render and fixes the settings the mode's passes read for this cull. */
    TechniqueCull(SilhouetteShadowTechnique& technique, osgUtil::CullVisitor& cv);

    /** The eye's receivers under the view's receiver state and pass state set. */
    void cullReceivers();
    /** The view's lights, their sizes; the GL lights of those refused turned off. */
    void cullLights();
    /** Bounds, visible region and casters (the technique's prepareFrame()), then each
     *  light's slot and frusta. */
    void planSlots();
    /** The mode's method and its part of the eye pass's configuration. */
    void planMode();
    /** The stencil modes' program, the GLSL 4.30 shaders, the screen-space visibility and
     *  the depth prepass. */
    void prepareEyePass();
    /** Every slot's placeholders and second maps, and each shadowed light's slots. */
    void cullShadowSlots();
    /** The mode's passes over the eye's receivers, and the view's uniforms. */
    void cullEyePasses();
    /** The eye pass's defines and modes, and the statistics. */
    void finishEyePass();

private:
    void cullLight(const LightDescription& light, unsigned int slot, const std::vector<LightFrustum>& frusta,
                   unsigned int firstFaceSlot, std::vector<osg::Texture2D*>& secondMaps);
    void cullSlot(const LightDescription& light, unsigned int slot, const LightFrustum& frustum,
                  osg::Texture2D*& secondMap);
    ViewData& viewData();
    void clampMapSizeToContext();
    Mode effectiveMode() const;
    void warnFilterMode() const;
    PassSettings passSettings() const;
    PassServices passServices();

    SilhouetteShadowTechnique& _t;
    osgUtil::CullVisitor& _cv;
    ViewData& _vd;
    FrameContext _frame;
    SilhouetteShadowTechnique::Statistics _stats;
    EyePassPlan _eye;
    PassSettings _settings;
    PassServices _services;
    ModeFrame _mf;
    ModePass* _mode = nullptr;
    std::vector<FoundLight> _lights;
    SlotPlan _plan;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
