// Internal: silhouette edges found on the GPU, from the casters' welded meshes drawn with
// adjacency through their own vertex stages, in the silhouette-map passes (the silhouette
// map and its neighbourhood map, HYBRID's edge mask, FILTER_SILHOUETTE's distance map).
#ifndef OSGSHADOWSILHOUETTE_GPUEDGES_H
#define OSGSHADOWSILHOUETTE_GPUEDGES_H

#include "GpuCasterDraws.h"

#include <osg/Program>
#include <osg/Uniform>

namespace osgShadowSilhouette {
namespace detail {

/** The silhouette edges a geometry stage finds (oss_silmap.geom.glsl compiled with
 *  OSS_SILMAP_ADJACENCY): each edge camera of a light (SilhouetteMapPass) draws, besides the
 *  CPU's edge lines, every caster taken here, culled from the scene like the depth pass's
 *  casters (its own state, its own vertex stage joined to the map's stages by
 *  CasterVertexStages, the light's view as model-view, no frustum culling). Per face the
 *  stage emits the edges the CPU path's extraction finds along it (SilhouetteExtractor: a lit
 *  face against an unlit one, an open edge of a casting face; the rule TWO_SIDED for a caster
 *  that is not closed and wound outward), once each and in the same direction, widened as the
 *  map's lines are. Shared by the views and threads (it keeps only the rules' state sets). */
class GpuEdges : public GpuCasterDraws
{
public:
    /** The maps a light's edges are drawn into, each with its fragment stage. */
    enum Map
    {
        POINTS,        ///< the silhouette map, or HYBRID's edge mask (oss_silmap.frag.glsl)
        NEIGHBOURHOOD, ///< the neighbourhood map (oss_silnbr.frag.glsl)
        DISTANCES,     ///< FILTER_SILHOUETTE's distance map (oss_sildist.frag.glsl)
        MAP_COUNT
    };

    /** @p programs: per Map, oss_silmap.vert + the adjacency geometry stage + the map's
     *  fragment stage; @p stages and @p adjacency are the technique's. */
    GpuEdges(const osg::ref_ptr<osg::Program> (&programs)[MAP_COUNT], CasterVertexStages* stages,
             AdjacencyDrawables* adjacency);

    /** The state of one map's draws of one light: its program (`OVERRIDE | PROTECTED`, over
     *  the edge camera's), rule 0 and @p light (uniform oss_gpuEdgeLight: the light in the
     *  light's view space, shared by the light's maps). */
    osg::ref_ptr<osg::StateSet> createPass(Map map, osg::Uniform* light) const;

    /** Within an edge camera's cull (its render stage current): culls the casters @p taken
     *  (takenByDrawable() of the light's casters) under @p pass, with @p view (the light's
     *  view: world to light view space) as their model-view. Returns the number of caster
     *  draws kept. */
    std::size_t cull(osgUtil::CullVisitor& cv, osg::StateSet& pass, const osg::Matrixd& view, const TakenCasters& taken,
                     const CullCasters& cullCasters);

protected:
    ~GpuEdges() override;
    /** TWO_SIDED (1) for a caster that is not closed and wound outward. A mirror turns
     *  which faces are lit and so no edge but the edges' direction, which the stage takes
     *  from the faces' winding in the map: the caster's side of each edge on its left. */
    unsigned int ruleOf(const Caster& caster, bool mirrored) const override;

    osg::ref_ptr<osg::Program> _programs[MAP_COUNT];
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
