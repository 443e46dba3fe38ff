// SILHOUETTE_MAP's passes (Sen, Cammarano, Hanrahan 2003): after each slot's depth map, a
// silhouette map of the light's silhouette edges and its neighbourhood map, which the eye
// pass reads to reconstruct the shadow edge inside each depth texel (docs/silhouette-map.md).
#include "ModePass.h"

#include <cstring>

namespace osgShadowSilhouette {
namespace detail {

void cullSilhouettePass(ModeFrame& mf, LightPass& pass, const LightDescription& light, bool depthComparison)
{
    const unsigned int size = mf.settings.shadowMapSize;
    if (!pass.silhouettePass || pass.silhouettePass->getMapSize() != size)
    {
        std::string name = pass.depthCamera->getName();
        name.replace(name.find("depth pass"), std::strlen("depth pass"), "silhouette map");
        pass.silhouettePass = new SilhouetteMapPass(size, *mf.settings.silhouetteMapStateSet, name);
    }
    pass.silhouettePass->setDepthComparison(depthComparison);
    const unsigned int mask = mf.cv.getTraversalMask();
    mf.cv.setTraversalMask(~0u); // the pass draws only its edges, whatever the view's mask
    pass.silhouettePass->cull(mf.cv, pass.frustum, pass.depthTexture.get(), mf.frame.casterList, light.homogeneous());
    mf.cv.setTraversalMask(mask);
}

namespace {

class SilhouetteModePass : public ModePass
{
public:
    bool rawDepthMaps(const PassSettings&) const override { return true; }

    osg::Texture2D* defaultSecondMap(const PassSettings& settings) const override
    {
        return settings.defaultNeighbourhoodTexture;
    }

    bool keepsSlotPasses(const LightPass& pass, const PassSettings& settings) const override
    {
        return pass.silhouettePass && pass.silhouettePass->getMapSize() == settings.shadowMapSize;
    }

    void cullSlot(ModeFrame& mf, SlotCull& slot) override
    {
        if (slot.depthRendered)
        {
            cullSilhouettePass(mf, slot.pass, slot.light, false);
            mf.stats.extractionsSkipped += slot.pass.silhouettePass->getExtractionSkipped() ? 1 : 0;
        }
        else
        {
            ++mf.stats.silhouettePassesReused; // kept with the depth map
            ++mf.stats.extractionsSkipped;
        }
        slot.secondMap = slot.pass.silhouettePass->getNeighbourhoodTexture();
        mf.stats.silhouetteEdges += static_cast<unsigned int>(slot.pass.silhouettePass->getEdges()->getEdgeCount());
    }
};

} // namespace

osg::ref_ptr<ModePass> createSilhouetteModePass()
{
    return new SilhouetteModePass;
}

} // namespace detail
} // namespace osgShadowSilhouette
