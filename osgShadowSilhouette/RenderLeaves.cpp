#include "RenderLeaves.h"

#include <osg/Matrix>

namespace osgShadowSilhouette {
namespace detail {

bool under(const osgUtil::StateGraph* sg, const osg::StateSet* ss)
{
    for (; sg; sg = sg->_parent)
        if (sg->getStateSet() == ss) return true;
    return false;
}

namespace {

/** Whether state set ss sets attribute `type`; above the receivers' state set only an
 *  OVERRIDE one reaches the eye pass (the receivers' program and LEQUAL replace the rest). */
bool setsAttribute(const osg::StateSet& ss, osg::StateAttribute::Type type, bool aboveReceivers)
{
    const osg::StateSet::RefAttributePair* pair = ss.getAttributePair(type);
    return pair && (!aboveReceivers || (pair->second & osg::StateAttribute::OVERRIDE) != 0);
}

/** Whether the depth prepass draws the leaves of `sg` as the eye pass does: no state set on
 *  their path (besides the prepass's and the receivers' own) sets a program (a vertex stage
 *  of its own may place them elsewhere), an osg::Depth (the eye pass keeps that test, not
 *  LEQUAL), blending, or a render bin after the opaque one or depth sorted (transparent:
 *  their depth must not hide what shows through them). */
bool prepassDraws(const osgUtil::StateGraph* sg, const osg::StateSet* prepass, const osg::StateSet* receivers)
{
    bool above = false;
    for (; sg; sg = sg->_parent)
    {
        const osg::StateSet* ss = sg->getStateSet();
        if (ss == receivers) above = true;
        if (!ss || ss == prepass || ss == receivers) continue;
        if (setsAttribute(*ss, osg::StateAttribute::PROGRAM, above) || setsAttribute(*ss, osg::StateAttribute::DEPTH, above))
            return false;
        if ((ss->getMode(GL_BLEND) & osg::StateAttribute::ON) != 0) return false;
        if (ss->getRenderingHint() == osg::StateSet::TRANSPARENT_BIN) return false;
        if (ss->useRenderBinDetails() && (ss->getBinNumber() > 0 || ss->getBinName() == "DepthSortedBin")) return false;
    }
    return true;
}

} // namespace

bool holdsLeaves(osgUtil::RenderBin& bin)
{
    if (!bin.getRenderLeafList().empty()) return true;
    for (const osgUtil::StateGraph* graph : bin.getStateGraphList())
        if (!graph->_leaves.empty()) return true;
    for (auto& nested : bin.getRenderBinList())
        if (holdsLeaves(*nested.second)) return true;
    return false;
}

int lastBinWithLeaves(osgUtil::RenderBin& bin, int after)
{
    int last = after;
    for (auto& nested : bin.getRenderBinList())
        if (nested.first > after && holdsLeaves(*nested.second)) last = std::max(last, nested.first);
    return last;
}

void keepByBin(osgUtil::RenderBin& bin, int after, bool keepLate)
{
    osgUtil::RenderBin::RenderBinList& nested = bin.getRenderBinList();
    for (auto it = nested.begin(); it != nested.end();)
    {
        if ((it->first > after) != keepLate)
            it = nested.erase(it);
        else
            ++it;
    }
    if (keepLate) bin.getStateGraphList().clear();
}

/** Removes from a render bin (and its nested bins) the leaves that draw one of @p drawables. */
void removeLeaves(osgUtil::RenderBin& bin, const std::vector<const osg::Drawable*>& drawables)
{
    detail::eraseLeaves(bin, [&](const osgUtil::RenderLeaf& leaf) {
        return std::find(drawables.begin(), drawables.end(), leaf.getDrawable()) != drawables.end();
    });
}

/** Whether a leaf's model-view matrix mirrors (negative determinant of its 3x3 part). */
std::vector<const osg::Array*> attributeArrays(const osg::Geometry& geometry)
{
    std::vector<const osg::Array*> arrays{geometry.getNormalArray(), geometry.getColorArray(),
                                          geometry.getSecondaryColorArray(), geometry.getFogCoordArray()};
    for (const osg::ref_ptr<osg::Array>& array : geometry.getTexCoordArrayList()) arrays.push_back(array.get());
    for (const osg::ref_ptr<osg::Array>& array : geometry.getVertexAttribArrayList()) arrays.push_back(array.get());
    return arrays;
}

void shareArrays(osg::Geometry& standIn, osg::Geometry& source)
{
    standIn.setUseVertexBufferObjects(source.getUseVertexBufferObjects());
    standIn.setVertexArray(source.getVertexArray());
    standIn.setNormalArray(source.getNormalArray());
    standIn.setColorArray(source.getColorArray());
    standIn.setSecondaryColorArray(source.getSecondaryColorArray());
    standIn.setFogCoordArray(source.getFogCoordArray());
    standIn.setTexCoordArrayList(source.getTexCoordArrayList());
    standIn.setVertexAttribArrayList(source.getVertexAttribArrayList());
}

bool mirrors(const osgUtil::RenderLeaf& leaf)
{
    if (!leaf._modelview) return false;
    const osg::Matrix& m = *leaf._modelview;
    const double det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
                       m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                       m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
    return det < 0.0;
}

/** Moves the leaves of @p drawables under their state graph's child of @p ss (added to @p bin
 *  where new this frame): draws of those drawables that also apply @p ss. Mirrored draws stay
 *  (the triangle lists: a mirror turns a closed caster's counter-clockwise half into the
 *  half facing away from the light, which misses the rays leaving it from inside). */
void moveLeaves(osgUtil::RenderBin& bin, const std::unordered_set<const osg::Drawable*>& drawables, osg::StateSet* ss)
{
    const std::vector<osgUtil::StateGraph*> graphs = bin.getStateGraphList(); // grows below
    for (osgUtil::StateGraph* graph : graphs)
    {
        if (graph->getStateSet() == ss) continue;
        auto& leaves = graph->_leaves;
        const auto moved = std::stable_partition(leaves.begin(), leaves.end(), [&](const osg::ref_ptr<osgUtil::RenderLeaf>& leaf) {
            return drawables.count(leaf->getDrawable()) == 0 || mirrors(*leaf);
        });
        if (moved == leaves.end()) continue;
        osgUtil::StateGraph* child = graph->find_or_insert(ss);
        if (child->_leaves.empty()) bin.addStateGraph(child); // state graphs outlive frames, their leaves do not
        for (auto it = moved; it != leaves.end(); ++it) child->addLeaf(it->get());
        leaves.erase(moved, leaves.end());
    }
    for (auto& nested : bin.getRenderBinList()) moveLeaves(*nested.second, drawables, ss);
}

/** Turns the leaves of billboard drawables in a light pass's @p bin (whose camera has the
 *  view matrix @p lightView) as the eye's view turned them: OSG's cull turns them toward the
 *  light camera. An instance is told by where its origin stands (the billboard's position
 *  of the drawable); each leaf takes the nearest of the view's instances. */
void turnBillboardLeaves(osgUtil::RenderBin& bin, const BillboardMatrices& billboards, const osg::Matrixd& lightView)
{
    const osg::Matrixd lightToWorld = osg::Matrixd::inverse(lightView);
    detail::forEachLeaf(bin, [&](osgUtil::RenderLeaf& leaf) {
        const auto found = billboards.find(leaf.getDrawable());
        if (found == billboards.end() || found->second.empty() || !leaf._modelview) return;
        const osg::Vec3d origin = leaf._modelview->getTrans() * lightToWorld;
        const osg::Matrixd* nearest = nullptr;
        double best = 0.0;
        for (const osg::Matrixd& world : found->second)
        {
            const double d = (world.getTrans() - origin).length2();
            if (!nearest || d < best) nearest = &world, best = d;
        }
        leaf._modelview = new osg::RefMatrix(*nearest * lightView);
    });
}

/** Removes from `bin` and the bins under it the prepass's state graphs (those under
 *  `prepass`) that prepassDraws() rejects, and any that a protected render bin kept out of
 *  the prepass's bin. */
void prunePrepass(osgUtil::RenderBin& bin, const osg::StateSet* prepass, const osg::StateSet* receivers, bool prepassBin,
                  int prepassBinNumber)
{
    osgUtil::RenderBin::StateGraphList& graphs = bin.getStateGraphList();
    graphs.erase(std::remove_if(graphs.begin(), graphs.end(),
                                [&](osgUtil::StateGraph* sg) {
                                    return under(sg, prepass) && !(prepassBin && prepassDraws(sg, prepass, receivers));
                                }),
                 graphs.end());
    for (auto& child : bin.getRenderBinList())
        prunePrepass(*child.second, prepass, receivers, child.first == prepassBinNumber, prepassBinNumber);
}

} // namespace detail
} // namespace osgShadowSilhouette
