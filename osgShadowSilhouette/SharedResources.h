// Internal: the GL objects every view of a technique shares, built by its init().
#ifndef OSGSHADOWSILHOUETTE_SHARED_RESOURCES_H
#define OSGSHADOWSILHOUETTE_SHARED_RESOURCES_H

#include "CasterVertexStages.h"
#include "GpuEdges.h"
#include "GpuVolumes.h"

#include <osg/Program>
#include <osg/Referenced>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osg/ref_ptr>

#include <functional>

namespace osgShadowSilhouette {
namespace detail {

/** The programs, the light-space passes' shared state sets and the placeholder textures of
 *  one technique: built together by createSharedResources(), read-only afterwards, shared by
 *  every view and cull thread. */
struct SharedResources : public osg::Referenced
{
    osg::ref_ptr<osg::Program> receiverProgram; ///< the receivers' default shading
    osg::ref_ptr<osg::Program> stencilProgram;  ///< the receivers in the stencil modes' eye passes
    osg::ref_ptr<osg::Program> volumeProgram;   ///< the shadow volumes' extrusion
    osg::ref_ptr<osg::Program> prepassProgram;  ///< the eye pass's depth prepass
    osg::ref_ptr<osg::Program> gpuVolumeProgram;    ///< volumes extruded by a geometry stage (GpuVolumes)
    osg::ref_ptr<osg::Program> gpuVolumeCapProgram; ///< ... their light caps
    /** Silhouette edges found by a geometry stage (GpuEdges), per GpuEdges::Map. */
    osg::ref_ptr<osg::Program> gpuEdgePrograms[GpuEdges::MAP_COUNT];
    osg::ref_ptr<osg::StateSet> depthPassStateSet;
    osg::ref_ptr<osg::StateSet> silhouetteMapStateSet;
    osg::ref_ptr<osg::StateSet> listStateSet;
    osg::ref_ptr<osg::StateSet> listFrontOnlyStateSet;        ///< the lists' closed casters
    osg::ref_ptr<osg::Texture2D> litDepthTexture;             ///< a slot's depth map with nothing to shadow
    osg::ref_ptr<osg::Texture2D> litRawDepthTexture;          ///< ... as SILHOUETTE_MAP reads it (raw depths)
    osg::ref_ptr<osg::Texture2D> defaultSilhouetteTexture;    ///< an edge mask without edges
    osg::ref_ptr<osg::Texture2D> defaultNeighbourhoodTexture; ///< a neighbourhood map without edges
    osg::ref_ptr<osg::StateSet> distanceMapStateSet;          ///< FILTER_SILHOUETTE's distance maps
    osg::ref_ptr<osg::Texture2D> defaultDistanceTexture;      ///< a distance map without edges
    /** The casters' own vertex stages in the light passes (a cache, itself thread safe). */
    osg::ref_ptr<CasterVertexStages> casterStages;
    /** The casters' welded faces with adjacency, for the edges and volumes a geometry stage finds. */
    osg::ref_ptr<AdjacencyDrawables> adjacency;

    /** The depth texture of a slot with nothing to shadow. */
    osg::Texture2D* litTexture(bool rawDepth) const
    {
        return rawDepth ? litRawDepthTexture.get() : litDepthTexture.get();
    }

    /** A view's depth prepass state: colour writes off, the prepass program, its own bin. */
    osg::ref_ptr<osg::StateSet> createPrepassStateSet() const;

    /** Calls @p op on every object above that holds GL objects (releaseGLObjects() and
     *  resizeGLObjectBuffers() of the technique). */
    template <class Op>
    void forEachGLObjectHolder(const Op& op) const
    {
        for (osg::Program* program : {receiverProgram.get(), stencilProgram.get(), volumeProgram.get(),
                                      prepassProgram.get(), gpuVolumeProgram.get(), gpuVolumeCapProgram.get()})
            op(program);
        for (const osg::ref_ptr<osg::Program>& program : gpuEdgePrograms) op(program.get());
        for (osg::StateSet* ss : {depthPassStateSet.get(), silhouetteMapStateSet.get(), listStateSet.get(),
                                  listFrontOnlyStateSet.get(), distanceMapStateSet.get()})
            op(ss);
        for (osg::Texture2D* texture : {litDepthTexture.get(), litRawDepthTexture.get(), defaultSilhouetteTexture.get(),
                                        defaultNeighbourhoodTexture.get(), defaultDistanceTexture.get()})
            op(texture);
        op(casterStages.get());
        op(adjacency.get());
    }
};

/** The shared objects of a technique whose depth passes start from the given polygon offset.
 *  @p linkShadowShaders adds the shadow term's shaders to the receivers' programs;
 *  @p watchLink has a program's link checked (both the technique's). */
osg::ref_ptr<SharedResources> createSharedResources(float polygonOffsetFactor, float polygonOffsetUnits,
                                                    const std::function<void(osg::Program*)>& linkShadowShaders,
                                                    const std::function<void(osg::Program*)>& watchLink);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
