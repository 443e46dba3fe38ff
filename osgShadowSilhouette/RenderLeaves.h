// Internal: editing the leaves a cull traversal left in a render bin.
#ifndef OSGSHADOWSILHOUETTE_RENDERLEAVES_H
#define OSGSHADOWSILHOUETTE_RENDERLEAVES_H

#include <osgUtil/RenderBin>
#include <osgUtil/StateGraph>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

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
    graphs.erase(std::remove_if(graphs.begin(), graphs.end(),
                                [](const osgUtil::StateGraph* graph) { return graph->_leaves.empty(); }),
                 graphs.end());
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

} // namespace detail
} // namespace osgShadowSilhouette

#endif
