#include "ModePass.h"

namespace osgShadowSilhouette {
namespace detail {

osg::ref_ptr<ModePass> createModePass(SilhouetteShadowTechnique::Mode mode)
{
    switch (mode)
    {
    case SilhouetteShadowTechnique::SILHOUETTE_MAP: return createSilhouetteModePass();
    case SilhouetteShadowTechnique::SHADOW_VOLUME: return createVolumeModePass();
    case SilhouetteShadowTechnique::HYBRID: return createHybridModePass();
    case SilhouetteShadowTechnique::SHADOW_MAP: break;
    }
    return createShadowMapModePass();
}

} // namespace detail
} // namespace osgShadowSilhouette
