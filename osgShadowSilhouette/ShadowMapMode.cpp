// SHADOW_MAP's passes: the technique's depth maps alone; under a soft filter (Filter) the maps
// hold raw depths and each slot's penumbra scale reaches the eye pass (oss_filter.frag.glsl).
#include "ModePass.h"
#include "SoftFilter.h"

namespace osgShadowSilhouette {
namespace detail {

namespace {

class ShadowMapModePass : public ModePass
{
public:
    bool rawDepthMaps(const PassSettings& settings) const override
    {
        return settings.filter == SilhouetteShadowTechnique::FILTER_PCF ||
               settings.filter == SilhouetteShadowTechnique::FILTER_PCSS; // FILTER_SILHOUETTE is not this mode's
    }

    void planFrame(ModeFrame& mf) override
    {
        mf.eye.filter = mf.settings.filter;
        mf.eye.filterWindow = mf.settings.filterWindow;
    }

    void cullSlot(ModeFrame& mf, SlotCull& cull) override
    {
        if (mf.settings.filter != SilhouetteShadowTechnique::FILTER_PCSS) return;
        const osg::Vec2 scale = penumbraScale(cull.pass.frustum, cull.light.type, cull.light.size);
        mf.vd.filterScale->setElement(cull.slot, osg::Vec2f(scale));
    }
};

} // namespace

osg::ref_ptr<ModePass> createShadowMapModePass()
{
    return new ShadowMapModePass;
}

} // namespace detail
} // namespace osgShadowSilhouette
