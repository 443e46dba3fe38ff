// Internal: shadow volumes extruded on the GPU, from the casters' welded meshes drawn with
// adjacency through their own vertex stages, for the casters whose final positions exist only
// on the GPU (a skinning or displacing shader) and, where the technique says so, for all.
#ifndef OSGSHADOWSILHOUETTE_GPUVOLUMES_H
#define OSGSHADOWSILHOUETTE_GPUVOLUMES_H

#include "GpuCasterDraws.h"

#include <osgShadowSilhouette/ShadowVolumes>

namespace osgShadowSilhouette {
namespace detail {

/** The shadow volumes a geometry stage extrudes (oss_gpuvolume.geom.glsl) in the stencil
 *  modes' volume passes. Per light two draws of every such caster, culled from the scene
 *  like the receivers (its own state, its own vertex stage joined to the volume stages by
 *  CasterVertexStages, outside the view frustum too): its sides and dark cap, and its light
 *  cap with the CPU volumes' light-cap offset; always counted z-fail. The rule per caster is
 *  the technique's CPU volumes': the classic one for a closed caster wound outward, TWO_SIDED
 *  otherwise. One instance per view (StencilShadowPasses). */
class GpuVolumes : public GpuCasterDraws
{
public:
    /** @p sides: oss_volume.vert + oss_gpuvolume.geom + oss_volume.frag; @p cap: the same
     *  with OSS_GPU_VOLUME_LIGHT_CAP defined in the geometry stage; @p stages and @p adjacency
     *  are the technique's, shared by the views. */
    GpuVolumes(osg::Program* sides, osg::Program* cap, CasterVertexStages* stages, AdjacencyDrawables* adjacency);

    /** The passes of one light: state sets built from the light's volume pass (@p volumeState:
     *  its render bin, colour, depth and program state) and its z-fail stencil operations. */
    using Light = GpuVolumePasses;
    Light createLight(const osg::StateSet& volumeState, const osg::StateSet& zfailStencil,
                      const osg::StateSet& lightCapOffset) const;

    /** Culls both draws of the casters of @p casters taken here (takes()) for the homogeneous
     *  light @p light (in the frame of the casters' world matrices, whose view matrix is cv's
     *  current model-view). Returns the number of caster draws culled per pass. */
    std::size_t cull(osgUtil::CullVisitor& cv, Light& passes, const osg::Vec4d& light,
                     const std::vector<Caster>& casters, const CullCasters& cullCasters);

protected:
    ~GpuVolumes() override;
    /** The classic rule (0) for a closed caster wound outward, TWO_SIDED otherwise (where a
     *  mirror changes nothing); the windings the eye culls. */
    unsigned int ruleOf(const Caster& caster, bool mirrored) const override;

    osg::ref_ptr<osg::Program> _sidesProgram, _capProgram;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
