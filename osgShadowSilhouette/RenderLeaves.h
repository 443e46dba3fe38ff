// Internal: editing the leaves a cull traversal left in a render bin, and the light-space
// cameras' cull callback that applies those edits to the casters it culls.
#ifndef OSGSHADOWSILHOUETTE_RENDERLEAVES_H
#define OSGSHADOWSILHOUETTE_RENDERLEAVES_H

#include "CasterVertexStages.h"

#include <osgShadowSilhouette/TriangleListPass>
#include <osgShadowSilhouette/ViewPoint>

#include <osg/Geometry>
#include <osg/NodeCallback>
#include <osgShadow/ShadowedScene>
#include <osgUtil/RenderBin>
#include <osgUtil/StateGraph>

#include <algorithm>
#include <memory>
#include <unordered_set>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** Removes from @p bin (not its nested bins) the state graphs without leaves (eraseLeaves()). */
inline void dropEmptyGraphs(osgUtil::RenderBin& bin)
{
    osgUtil::RenderBin::StateGraphList& graphs = bin.getStateGraphList();
    graphs.erase(std::remove_if(graphs.begin(), graphs.end(),
                                [](const osgUtil::StateGraph* graph) { return graph->_leaves.empty(); }),
                 graphs.end());
}

/** Removes from @p bin (and its nested bins) the leaves for which @p drop is true, and the state
 *  graphs left without leaves: a bin never holds an empty state graph otherwise, and after
 *  the cull OSG's SceneView deletes the empty ones (StateGraph::prune) while a depth-sorted
 *  bin, sorted before, would still read them. */
template<class Drop>
void eraseLeaves(osgUtil::RenderBin& bin, const Drop& drop)
{
    osgUtil::RenderBin::StateGraphList& graphs = bin.getStateGraphList();
    for (osgUtil::StateGraph* graph : graphs)
    {
        auto& leaves = graph->_leaves;
        leaves.erase(std::remove_if(leaves.begin(), leaves.end(),
                                    [&](const osg::ref_ptr<osgUtil::RenderLeaf>& leaf) { return drop(*leaf); }),
                     leaves.end());
    }
    dropEmptyGraphs(bin);
    for (auto& nested : bin.getRenderBinList()) eraseLeaves(*nested.second, drop);
}

/** Calls @p visit on every leaf of @p bin and its nested bins. */
template<class Visit>
void forEachLeaf(osgUtil::RenderBin& bin, const Visit& visit)
{
    for (osgUtil::StateGraph* graph : bin.getStateGraphList())
        for (const osg::ref_ptr<osgUtil::RenderLeaf>& leaf : graph->_leaves) visit(*leaf);
    for (auto& nested : bin.getRenderBinList()) forEachLeaf(*nested.second, visit);
}

/** Whether the state graph @p sg lies under the state set @p ss. */
bool under(const osgUtil::StateGraph* sg, const osg::StateSet* ss);

/** Whether @p bin or a bin nested in it holds a leaf. */
bool holdsLeaves(osgUtil::RenderBin& bin);

/** The highest number of the bins nested in @p bin, above @p after, that hold leaves, or
 *  @p after when there is none. */
int lastBinWithLeaves(osgUtil::RenderBin& bin, int after);

/** Splits a pass's bin by where the base pass draws its leaves: keepLate keeps only the
 *  leaves of its nested bins numbered above @p after (drawn after that bin: transparent,
 *  depth sorted or later), !keepLate only the others. */
void keepByBin(osgUtil::RenderBin& bin, int after, bool keepLate);

/** Removes from a render bin (and its nested bins) the leaves that draw one of @p drawables. */
void removeLeaves(osgUtil::RenderBin& bin, const std::vector<const osg::Drawable*>& drawables);

/** The arrays of @p geometry besides its vertices, which a stand-in shares: normals, colours,
 *  texture coordinates (the eye's passes draw stand-ins too) and the vertex attributes (a
 *  skinning program's bone weights, set after its first frames). */
std::vector<const osg::Array*> attributeArrays(const osg::Geometry& geometry);

/** Gives the stand-in @p standIn every array of @p source (shared, not copied), and draws it
 *  with buffer objects where the source does: a stand-in with buffer objects would attach
 *  them to the source's arrays, which the source draws without. */
void shareArrays(osg::Geometry& standIn, osg::Geometry& source);

/** Whether a leaf's model-view matrix mirrors (negative determinant of its 3x3 part). */
bool mirrors(const osgUtil::RenderLeaf& leaf);

/** Moves the leaves of @p drawables under their state graph's child of @p ss (added to @p bin
 *  where new this frame): draws of those drawables that also apply @p ss. Mirrored draws stay
 *  (the triangle lists: a mirror turns a closed caster's counter-clockwise half into the
 *  half facing away from the light, which misses the rays leaving it from inside). */
void moveLeaves(osgUtil::RenderBin& bin, const std::unordered_set<const osg::Drawable*>& drawables, osg::StateSet* ss);

/** Turns the leaves of billboard drawables in a light pass's @p bin (whose camera has the
 *  view matrix @p lightView) as the eye's view turned them: OSG's cull turns them toward the
 *  light camera. An instance is told by where its origin stands (the billboard's position
 *  of the drawable); each leaf takes the nearest of the view's instances. */
void turnBillboardLeaves(osgUtil::RenderBin& bin, const BillboardMatrices& billboards, const osg::Matrixd& lightView);

/** Removes from `bin` and the bins under it the depth prepass's state graphs (those under
 *  `prepass`) that it would not draw as the eye pass does (a program, an osg::Depth, blending
 *  or a transparent bin of their own on the path), and any that a protected render bin kept
 *  out of the prepass's bin (number `prepassBinNumber`; `prepassBin`: `bin` is that bin). */
void prunePrepass(osgUtil::RenderBin& bin, const osg::StateSet* prepass, const osg::StateSet* receivers, bool prepassBin,
                  int prepassBinNumber);

/** The cull callback of a light-space camera (depth pass, triangle lists): culls the
 *  shadowed scene's casters into the camera's own render stage, leaving out the geometry
 *  with non-finite vertices, then the camera's own children. With setCasters(false) only
 *  the camera's own children (a depth map kept from an earlier frame is tested, not redrawn). */
class TraverseShadowedSceneCallback : public osg::NodeCallback
{
public:
    explicit TraverseShadowedSceneCallback(osgShadow::ShadowedScene* scene) : _scene(scene) {}
    void setCasters(bool flag) { _casters = flag; }
    void setExcluded(const std::vector<const osg::Drawable*>& drawables) { _excluded = drawables; }
    /** The draws of @p drawables also apply @p ss (the triangle lists' closed casters). */
    void setMarked(std::unordered_set<const osg::Drawable*> drawables, osg::StateSet* ss)
    {
        _marked = std::move(drawables);
        _markedStateSet = ss;
    }
    /** The casters with a vertex stage of their own keep it (@p stages: the technique's). */
    void setCasterStages(CasterVertexStages* stages) { _casterStages = stages; }
    /** The casters' quads and polygons are drawn as @p faces splits them (ListedDrawables::faces()). */
    void setSplitFaces(ListedDrawables* faces) { _faces = faces; }
    /** The draws are those @p listed gives (the triangle lists: triangles only). */
    void setListed(ListedDrawables* listed) { _listed = listed; }
    /** The billboard drawables are drawn as the view turned them (FrameContext::billboards). */
    void setBillboards(std::shared_ptr<const BillboardMatrices> billboards) { _billboards = std::move(billboards); }
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (_scene && _casters)
        {
            _scene->osg::Group::traverse(*nv);
            osgUtil::CullVisitor* cv = nv->asCullVisitor();
            if (cv && !_excluded.empty() && cv->getCurrentRenderBin()) removeLeaves(*cv->getCurrentRenderBin(), _excluded);
            const osg::StateSet* passState =
                cv && cv->getCurrentCamera() ? cv->getCurrentCamera()->getStateSet() : nullptr;
            if (_casterStages && passState && cv->getCurrentRenderBin())
                _casterStages->apply(*cv->getCurrentRenderBin(), *passState);
            if (cv && !_marked.empty() && _markedStateSet && cv->getCurrentRenderBin())
                moveLeaves(*cv->getCurrentRenderBin(), _marked, _markedStateSet.get());
            if (cv && _billboards && !_billboards->empty() && cv->getCurrentRenderBin() && cv->getCurrentCamera())
                turnBillboardLeaves(*cv->getCurrentRenderBin(), *_billboards, cv->getCurrentCamera()->getViewMatrix());
            if (cv && _listed && cv->getCurrentRenderBin()) _listed->apply(*cv->getCurrentRenderBin());
            if (cv && _faces && cv->getCurrentRenderBin()) _faces->splitFaces(*cv->getCurrentRenderBin());
        }
        traverse(node, nv); // the camera's own children (BlockerQueries), after the casters
    }

private:
    osgShadow::ShadowedScene* _scene;
    bool _casters = true;
    std::vector<const osg::Drawable*> _excluded;
    std::unordered_set<const osg::Drawable*> _marked;
    osg::ref_ptr<osg::StateSet> _markedStateSet;
    osg::ref_ptr<ListedDrawables> _listed;
    osg::ref_ptr<ListedDrawables> _faces;
    osg::ref_ptr<CasterVertexStages> _casterStages;
    std::shared_ptr<const BillboardMatrices> _billboards;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
