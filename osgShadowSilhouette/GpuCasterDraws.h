// Internal: casters drawn through a geometry stage that finds their shadow geometry on the
// GPU (silhouette edges, shadow volumes) from their welded meshes with adjacency, each through
// its own vertex stage: for the casters whose final positions exist only on the GPU (a
// skinning or displacing shader) and, where the technique says so, for all.
#ifndef OSGSHADOWSILHOUETTE_GPUCASTERDRAWS_H
#define OSGSHADOWSILHOUETTE_GPUCASTERDRAWS_H

#include "CasterVertexStages.h"

#include <osgShadowSilhouette/CasterEdges>

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

/** What the passes that find casters' shadow geometry on the GPU share (GpuVolumes,
 *  GpuEdges): which casters they take, and the edit of a pass's culled caster leaves into
 *  draws of their adjacency stand-ins through their own vertex stages, each under its rule. */
class GpuCasterDraws : public osg::Referenced
{
public:
    /** Culls the shadowed scene's casters under a pass state set into the current bin. */
    using CullCasters = std::function<void(osg::StateSet* pass)>;
    /** Casters taken here, by drawable (takenByDrawable()). */
    using TakenCasters = std::unordered_map<const osg::Drawable*, const Caster*>;

    /** Whether every caster is taken here (true) or only the casters moved on the GPU (false,
     *  the default). */
    void setAllCasters(bool all) { _all = all; }
    bool getAllCasters() const { return _all; }
    /** Whether @p caster's shadow geometry is found here (and not on the CPU). */
    bool takes(const Caster& caster) const { return _all || caster.movedOnGpu; }
    /** Whether any of @p casters is. */
    bool takesAny(const std::vector<Caster>& casters) const;
    /** @p casters with the ones taken here marked movedOnGpu, so that the CPU path leaves
     *  them out; in the list's order. */
    std::vector<Caster> leftToCpu(const std::vector<Caster>& casters) const;
    /** The casters of @p casters taken here, by drawable (pointing into @p casters). */
    TakenCasters takenByDrawable(const std::vector<Caster>& casters) const;

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state = nullptr) const;

protected:
    GpuCasterDraws(CasterVertexStages* stages, AdjacencyDrawables* adjacency);
    ~GpuCasterDraws() override;

    /** After a pass's cull: each leaf under @p pass draws its caster's adjacency stand-in
     *  through its own vertex stage under its rule's state (ruleOf()), or nothing (not taken
     *  here). Returns the number of leaves kept. */
    std::size_t prepareLeaves(osgUtil::RenderBin& stage, osg::StateSet& pass,
                              const std::unordered_map<const osg::Drawable*, const Caster*>& casters);
    /** The rule bits (uniform oss_gpuVolumeRule) a draw of @p caster takes, @p mirrored: its
     *  model-view mirrors; 0: the pass's own. */
    virtual unsigned int ruleOf(const Caster& caster, bool mirrored) const = 0;

    osg::ref_ptr<CasterVertexStages> _stages;
    osg::ref_ptr<AdjacencyDrawables> _adjacency;

private:
    /** Moves the leaves under @p pass whose rule is not 0 under its state; @p byStandIn: the
     *  casters of the stand-ins they draw. */
    void applyRules(osgUtil::RenderBin& bin, const osg::StateSet& pass,
                    const std::unordered_map<const osg::Drawable*, const Caster*>& byStandIn);
    /** The state of a rule's draws, or null for rule 0. */
    osg::StateSet* ruleState(unsigned int rule);

    std::map<unsigned int, osg::ref_ptr<osg::StateSet>> _rules; ///< by rule
    bool _all = false;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
