// SHADOW_VOLUME's passes: no maps; after the lights, the stencil passes over the eye's
// receivers (ShadowVolumes: base pass, per light the stencil clear, volumes, mask and light
// passes, and the blended round), shared with HYBRID's stencil volumes; and the screen-space
// visibility that lets the receivers' own programs read their answer (ScreenVisibility).
#include "ModePass.h"
#include "ScreenVisibility.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/Viewport>

namespace osgShadowSilhouette {
namespace detail {

namespace {

bool oneLightDebugView(const PassSettings& settings)
{
    return settings.debugView == SilhouetteShadowTechnique::DEBUG_SHADOW_MASK ||
           settings.debugView == SilhouetteShadowTechnique::DEBUG_CLASSES ||
           settings.debugView == SilhouetteShadowTechnique::DEBUG_VISIBILITY;
}

/** The slots a light's cube faces take (bit s: slot s), its own among them. */
unsigned int faceSlotsOf(const ViewData& vd, int lightSlot)
{
    unsigned int faceSlots = 0;
    for (unsigned int s = 0; s < vd.slotInUse.size(); ++s)
    {
        int owner = -1;
        vd.slotOwner->getElement(s, owner);
        if (owner == lightSlot) faceSlots |= 1u << s;
    }
    return faceSlots;
}

void recordStencilStatistics(ModeFrame& mf, bool hybrid)
{
    const StencilShadowPasses& stencil = *mf.vd.stencil;
    SilhouetteShadowTechnique::Statistics& stats = mf.stats;
    stats.zfailCasters = stencil.getZFailCasters();
    stats.zpassCasters = stencil.getZPassCasters();
    stats.volumesRebuilt = stencil.getVolumesRebuilt();
    stats.volumesCulled = stencil.getVolumesCulled();
    stats.blendedRound = stencil.getBlendedRound();
    stats.silhouettePixels = hybrid ? stencil.getSilhouettePixels() : -1;
    stats.volumeFragments = stencil.getVolumeFragments();
    stats.blockersTested = stencil.getBlockersTested();
    stats.blockersSkipped = stencil.getBlockersHidden();
}

class VolumeModePass : public ModePass
{
public:
    bool drawsMaps() const override { return false; }

    void planFrame(ModeFrame& mf) override
    {
        mf.frame.stencil = true;
        mf.services.warnAlphaTested(false, false);
    }

    void cullEyePasses(ModeFrame& mf, const std::vector<FoundLight>& lights, const std::vector<int>& slots) override
    {
        cullStencilPasses(mf, false, lights, slots);
    }
};

} // namespace

void cullStencilPasses(ModeFrame& mf, bool hybrid, const std::vector<FoundLight>& lights, const std::vector<int>& slots)
{
    ViewData& vd = mf.vd;
    const PassSettings& settings = mf.settings;
    std::vector<StencilLight> stencilLights;
    const bool oneLight = oneLightDebugView(settings); // only its passes
    int maskSlot = -1;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (slots[i] < 0 || !vd.passes[slots[i]].frustum.valid) continue;
        const LightPass& pass = vd.passes[slots[i]];
        stencilLights.push_back(
            {static_cast<unsigned int>(slots[i]), lights[i].description.lightNum, lights[i].description.homogeneous(),
             hybrid && settings.blockerCulling ? pass.blockers : nullptr, faceSlotsOf(vd, slots[i])});
        if (oneLight && i == settings.debugLight) maskSlot = slots[i];
    }
    if (oneLight && maskSlot < 0) stencilLights.clear(); // the debug light casts nothing
    vd.stencil->cull(mf.cv, hybrid, oneLight ? maskSlot : -1, stencilLights, mf.frame.casterList, mf.frame.receivers,
                     [&](osg::StateSet* pass) { mf.services.cullReceivers(pass); });
    recordStencilStatistics(mf, hybrid);
    if (vd.stencil->getBlendedSkipped())
        mf.services.warnOnce(
            WARN_BLENDED_VISIBILITY,
            std::string("Mode ") + SilhouetteShadowTechnique::modeName(settings.mode) +
                ": receivers in the transparent bin (or a later one) get no shadow of their own while a "
                "program given to addShadowShaders() draws the receivers: the screen-space visibility has "
                "no blended round yet; they show the opaque surface's shadow behind them");
}

bool cullScreenVisibility(ModeFrame& mf)
{
    ViewData& vd = mf.vd;
    osgUtil::CullVisitor& cv = mf.cv;
    // The mask and class views draw the technique's own answer, one light at a time.
    bool use = mf.frame.stencil && !oneLightDebugView(mf.settings) && mf.services.applicationPrograms();
    const osg::Viewport* viewport = cv.getViewport();
    if (use && (!viewport || !cv.getState() || !ScreenVisibility::supported(cv.getState()->getContextID())))
    {
        mf.services.warnOnce(
            WARN_SCREEN_VISIBILITY,
            std::string("Mode ") + SilhouetteShadowTechnique::modeName(mf.settings.mode) +
                ": the graphics context runs no OpenGL 4.3 (GLSL 4.30, image load/store), which the stencil modes "
                "need to draw the receivers with the programs given to addShadowShaders(); those receivers show the "
                "technique's shading instead");
        use = false;
    }
    auto* visibility = static_cast<ScreenVisibility*>(vd.screenVisibility.get());
    if (use && !visibility) vd.screenVisibility = visibility = new ScreenVisibility;
    const unsigned int unit = shader::SCREEN_VISIBILITY_IMAGE_UNIT;
    if (use)
    {
        visibility->fit(*viewport);
        vd.receiverStateSet->setAttributeAndModes(visibility->getBinding(), EYE_PASS_BINDING);
        vd.receiverPassStateSet->setDefine(shader::DEFINE_VISIBILITY_CLEAR);
    }
    else
    {
        if (visibility &&
            vd.receiverStateSet->getAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit) == visibility->getBinding())
            vd.receiverStateSet->removeAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit);
        vd.receiverPassStateSet->removeDefine(shader::DEFINE_VISIBILITY_CLEAR);
    }
    if (vd.stencil)
        vd.stencil->setScreenVisibility(use ? visibility->getBarrier() : nullptr,
                                        use ? visibility->getFinalPass() : nullptr);
    return use;
}

osg::ref_ptr<ModePass> createVolumeModePass()
{
    return new VolumeModePass;
}

} // namespace detail
} // namespace osgShadowSilhouette
