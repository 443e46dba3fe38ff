// SILHOUETTE_MAP's passes (Sen, Cammarano, Hanrahan 2003): after each slot's depth map, a
// silhouette map of the light's silhouette edges and its neighbourhood map, which the eye
// pass reads to reconstruct the shadow edge inside each depth texel (docs/silhouette-map.md).
// Under FILTER_SILHOUETTE (Valient and Bujnak 2005; docs/soft-shadows.md) the same edges are
// drawn as signed distances instead (SilhouetteMapPass::cullDistanceMap()), which the eye pass
// filters (oss_silhouette_filter.frag.glsl) with each slot's penumbra scale.
#include "ModePass.h"
#include "SoftFilter.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <algorithm>

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
    pass.silhouettePass->setGpuEdges(mf.services.gpuEdges(), mf.services.cullLightCasters);
    const unsigned int mask = mf.cv.getTraversalMask();
    mf.cv.setTraversalMask(~0u); // the pass draws only its edges, whatever the view's mask
    pass.silhouettePass->cull(mf.cv, pass.frustum, pass.depthTexture.get(), mf.frame.casterList, light.homogeneous());
    mf.cv.setTraversalMask(mask);
}

namespace {

bool filtersEdges(const PassSettings& settings)
{
    return settings.filter == SilhouetteShadowTechnique::FILTER_SILHOUETTE;
}

/** W: how far from an edge, in texels, its distance reaches: the widest penumbra the slot's
 *  light can cast on the map (a blocker at the near plane, a receiver at the far one: the
 *  scale over the whole depth range), at least the 2x2 footprint's, capped. */
float distanceWidth(const osg::Vec2& scale, unsigned int mapSize)
{
    const float widest = std::max(scale.x(), scale.y()) * float(mapSize);
    return std::min(shader::SILDIST_MAX_WIDTH, std::max(shader::SILDIST_MIN_WIDTH, widest));
}

/** FILTER_SILHOUETTE's passes of a slot: its distance map (again where the depth map was
 *  drawn, or where the width changed) and its penumbra scale. */
void cullDistanceSlot(ModeFrame& mf, SlotCull& slot)
{
    const unsigned int size = mf.settings.shadowMapSize;
    const osg::Vec2 scale = penumbraScale(slot.pass.frustum, slot.light.type, slot.light.size);
    mf.vd.filterScale->setElement(slot.slot, osg::Vec2f(scale));
    const float width = distanceWidth(scale, size);
    osg::ref_ptr<SilhouetteMapPass>& pass = slot.pass.silhouettePass;
    if (!pass || pass->getMapSize() != size)
    {
        std::string name = slot.pass.depthCamera->getName();
        name.replace(name.find("depth pass"), std::strlen("depth pass"), "silhouette map");
        pass = new SilhouetteMapPass(size, *mf.settings.silhouetteMapStateSet, name);
    }
    if (slot.depthRendered || !pass->getDistanceTexture() || pass->getDistanceWidth() != width)
    {
        pass->setGpuEdges(mf.services.gpuEdges(), mf.services.cullLightCasters);
        const unsigned int mask = mf.cv.getTraversalMask();
        mf.cv.setTraversalMask(~0u); // the pass draws only its edges, whatever the view's mask
        pass->cullDistanceMap(mf.cv, slot.pass.frustum, *mf.settings.distanceMapStateSet, width, mf.frame.casterList,
                              slot.light.homogeneous());
        mf.cv.setTraversalMask(mask);
        mf.stats.extractionsSkipped += pass->getExtractionSkipped() ? 1 : 0;
    }
    else
    {
        ++mf.stats.silhouettePassesReused; // kept with the depth map
        ++mf.stats.extractionsSkipped;
    }
    slot.secondMap = pass->getDistanceTexture();
    mf.stats.silhouetteEdges += static_cast<unsigned int>(pass->getEdges()->getEdgeCount());
}

class SilhouetteModePass : public ModePass
{
public:
    bool rawDepthMaps(const PassSettings&) const override { return true; }

    osg::Texture2D* defaultSecondMap(const PassSettings& settings) const override
    {
        return filtersEdges(settings) ? settings.defaultDistanceTexture : settings.defaultNeighbourhoodTexture;
    }

    void planFrame(ModeFrame& mf) override
    {
        mf.eye.filter = filtersEdges(mf.settings) ? mf.settings.filter : SilhouetteShadowTechnique::FILTER_PCF_2X2;
    }

    bool keepsSlotPasses(const LightPass& pass, const PassSettings& settings) const override
    {
        // The map kept must be the kind the filter reads: points or distances.
        return pass.silhouettePass && pass.silhouettePass->getMapSize() == settings.shadowMapSize &&
               pass.silhouettePass->getDrewDistances() == filtersEdges(settings);
    }

    void cullSlot(ModeFrame& mf, SlotCull& slot) override
    {
        if (filtersEdges(mf.settings)) return cullDistanceSlot(mf, slot);
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
