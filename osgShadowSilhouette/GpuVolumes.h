// Internal: shadow volumes extruded on the GPU, from the casters' welded meshes drawn with
// adjacency through their own vertex stages, for the casters whose final positions exist only
// on the GPU (a skinning or displacing shader) and, where the technique says so, for all.
#ifndef OSGSHADOWSILHOUETTE_GPUVOLUMES_H
#define OSGSHADOWSILHOUETTE_GPUVOLUMES_H

#include "CasterVertexStages.h"

#include <osgShadowSilhouette/CasterEdges>
#include <osgShadowSilhouette/ShadowVolumes>

#include <OpenThreads/Mutex>
#include <osg/Geometry>
#include <osg/observer_ptr>
#include <osgUtil/CullVisitor>

#include <functional>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** The welded triangles of a caster as GL_TRIANGLES_ADJACENCY over its own arrays: per face
 *  of its MeshAdjacency, the face's three corners and between them the corner of the face
 *  across each edge that lies off the edge, or, where the edge has no single face across (a
 *  border, an edge OpenMesh refused as non-manifold), the face's own third corner. The
 *  indices are the vertex array's (MeshWelding::sourceOf: the first vertex of each weld
 *  group), so the caster's own vertex stage, which moves every vertex of a weld group alike,
 *  runs on them with their attributes. Faces the mesh dropped (degenerate, non-finite) are
 *  left out. Kept per geometry while its arrays and its mesh's topology (the welding) stay
 *  the same. Thread safe: every view's passes share one. */
class AdjacencyDrawables : public osg::Referenced
{
public:
    /** The stand-in of @p caster, or null (no faces, or a mesh without a welding record). */
    osg::Geometry* get(const Caster& caster);
    /** Stand-ins held (tests). */
    std::size_t size() const;

    /** The adjacency indices of @p mesh, in the vertex array's indices (@p welding). */
    static osg::ref_ptr<osg::DrawElementsUInt> adjacencyIndices(const MeshAdjacency& mesh, const MeshWelding& welding);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state = nullptr) const;

protected:
    struct StandIn
    {
        osg::observer_ptr<const osg::Geometry> source;
        const osg::Array* vertices = nullptr;
        std::vector<const osg::Array*> attributes;
        std::shared_ptr<const MeshWelding> welding;
        osg::ref_ptr<osg::Geometry> geometry;
    };
    void prune();

    mutable OpenThreads::Mutex _mutex;
    std::map<const osg::Geometry*, StandIn> _standIns;
};

/** The shadow volumes a geometry stage extrudes (oss_gpuvolume.geom.glsl) in the stencil
 *  modes' volume passes. Per light two draws of every such caster, culled from the scene
 *  like the receivers (its own state, its own vertex stage joined to the volume stages by
 *  CasterVertexStages, outside the view frustum too): its sides and dark cap, and its light
 *  cap with the CPU volumes' light-cap offset; always counted z-fail. The rule per caster is
 *  the technique's CPU volumes': the classic one for a closed caster wound outward, TWO_SIDED
 *  otherwise. One instance per view (StencilShadowPasses). */
class GpuVolumes : public osg::Referenced
{
public:
    /** Culls the shadowed scene's casters under a pass state set into the current bin. */
    using CullCasters = std::function<void(osg::StateSet* pass)>;

    /** @p sides: oss_volume.vert + oss_gpuvolume.geom + oss_volume.frag; @p cap: the same
     *  with OSS_GPU_VOLUME_LIGHT_CAP defined in the geometry stage; @p stages and @p adjacency
     *  are the technique's, shared by the views. */
    GpuVolumes(osg::Program* sides, osg::Program* cap, CasterVertexStages* stages, AdjacencyDrawables* adjacency);

    /** Whether every caster's volume is extruded here (true) or only those of the casters
     *  moved on the GPU (false, the default). */
    void setAllCasters(bool all) { _all = all; }
    bool getAllCasters() const { return _all; }
    /** Whether @p caster's volume is extruded here (and not by ShadowVolumeGroup). */
    bool extrudes(const Caster& caster) const { return _all || caster.movedOnGpu; }
    /** Whether any of @p casters is. */
    bool extrudesAny(const std::vector<Caster>& casters) const;
    /** @p casters with the ones extruded here marked movedOnGpu: ShadowVolumeGroup builds no
     *  volume of them, and keeps the list's order. */
    std::vector<Caster> leftToCpu(const std::vector<Caster>& casters) const;

    /** The passes of one light: state sets built from the light's volume pass (@p volumeState:
     *  its render bin, colour, depth and program state) and its z-fail stencil operations. */
    using Light = GpuVolumePasses;
    Light createLight(const osg::StateSet& volumeState, const osg::StateSet& zfailStencil,
                      const osg::StateSet& lightCapOffset) const;

    /** Culls both draws of the extruded casters of @p casters for the homogeneous light
     *  @p light (in the frame of the casters' world matrices, whose view matrix is cv's
     *  current model-view). Returns the number of caster draws culled per pass. */
    std::size_t cull(osgUtil::CullVisitor& cv, Light& passes, const osg::Vec4d& light,
                     const std::vector<Caster>& casters, const CullCasters& cullCasters);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state = nullptr) const;

protected:
    ~GpuVolumes() override;
    /** After a pass's cull: each leaf under @p pass draws its caster's adjacency stand-in
     *  through its own vertex stage under its rule's state, or nothing (not extruded here). */
    std::size_t prepareLeaves(osgUtil::RenderBin& stage, osg::StateSet& pass,
                              const std::unordered_map<const osg::Drawable*, const Caster*>& casters);
    /** Moves the leaves under @p pass that need a rule state (two-sided, mirrored, culled
     *  faces) under it; @p byStandIn: the casters of the stand-ins they draw. */
    void applyRules(osgUtil::RenderBin& bin, const osg::StateSet& pass,
                    const std::unordered_map<const osg::Drawable*, const Caster*>& byStandIn);

    osg::ref_ptr<osg::Program> _sidesProgram, _capProgram;
    osg::ref_ptr<CasterVertexStages> _stages;
    osg::ref_ptr<AdjacencyDrawables> _adjacency;
    /** The state of a rule's draws (its oss_gpuVolumeRule), or null for the classic rule's
     *  unmirrored draws of a caster without culled faces (the passes' own 0). */
    osg::StateSet* ruleState(bool twoSided, bool mirrored, unsigned char culledWindings);

    std::map<unsigned int, osg::ref_ptr<osg::StateSet>> _rules; ///< by ruleState()'s key
    bool _all = false;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
