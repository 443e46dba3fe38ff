#include "GpuCasterDraws.h"

#include "RenderLeaves.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

// ---------------------------------------------------------------------------------------
// AdjacencyDrawables

namespace {

/** Per face, per edge k (corners k -> k+1): the mesh vertex across it, or the face's own third
 *  corner where no single face lies across. */
std::vector<std::uint32_t> cornersAcross(const MeshAdjacency& mesh)
{
    std::vector<std::uint32_t> across(3 * mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) across[3 * f + k] = mesh.faces[f].v[(k + 2) % 3];
    const auto third = [&](std::uint32_t face, std::uint32_t v0, std::uint32_t v1) {
        const MeshTriangle& t = mesh.faces[face];
        for (std::uint32_t v : t.v)
            if (v != v0 && v != v1) return v;
        return t.v[0];
    };
    const auto edgeSlot = [&](std::uint32_t face, std::uint32_t v0, std::uint32_t v1) {
        const MeshTriangle& t = mesh.faces[face];
        for (int k = 0; k < 3; ++k)
            if (t.v[k] == v0 && t.v[(k + 1) % 3] == v1) return k;
        return -1;
    };
    for (std::size_t e = 0; e < mesh.edgeCount(); ++e)
    {
        const InteriorEdge edge = mesh.edge(e);
        const int k0 = edgeSlot(edge.face0, edge.v0, edge.v1), k1 = edgeSlot(edge.face1, edge.v1, edge.v0);
        if (k0 < 0 || k1 < 0) continue; // not as the mesh says: left open
        across[3 * edge.face0 + k0] = third(edge.face1, edge.v0, edge.v1);
        across[3 * edge.face1 + k1] = third(edge.face0, edge.v0, edge.v1);
    }
    return across;
}

} // namespace

osg::ref_ptr<osg::DrawElementsUInt> AdjacencyDrawables::adjacencyIndices(const MeshAdjacency& mesh,
                                                                         const MeshWelding& welding)
{
    osg::ref_ptr<osg::DrawElementsUInt> indices = new osg::DrawElementsUInt(GL_TRIANGLES_ADJACENCY);
    const std::vector<std::uint32_t> across = cornersAcross(mesh);
    const auto source = [&](std::uint32_t v) {
        return v < welding.sourceOf.size() ? welding.sourceOf[v] : MeshWelding::kUnreferenced;
    };
    indices->reserve(6 * mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    {
        std::uint32_t corners[6];
        for (int k = 0; k < 3; ++k)
        {
            corners[2 * k] = source(mesh.faces[f].v[k]);
            corners[2 * k + 1] = source(across[3 * f + k]);
        }
        if (std::any_of(std::begin(corners), std::end(corners),
                        [](std::uint32_t i) { return i >= MeshWelding::kNonFinite; }))
            continue;
        indices->insert(indices->end(), std::begin(corners), std::end(corners));
    }
    return indices;
}

osg::Geometry* AdjacencyDrawables::get(const Caster& caster)
{
    const osg::Geometry* source = caster.geometry.get();
    const std::shared_ptr<const MeshWelding> welding = caster.mesh ? caster.mesh->getWelding() : nullptr;
    if (!source || !welding) return nullptr;
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto found = _standIns.find(source);
    if (found != _standIns.end() && found->second.source.get() == source && found->second.welding == welding &&
        found->second.vertices == source->getVertexArray() && found->second.attributes == attributeArrays(*source))
        return found->second.geometry.get();
    prune();
    StandIn& made = _standIns[source];
    made = StandIn();
    made.source = source;
    made.vertices = source->getVertexArray();
    made.attributes = attributeArrays(*source);
    made.welding = welding;
    osg::ref_ptr<osg::DrawElementsUInt> indices = adjacencyIndices(caster.mesh->getAdjacency(), *welding);
    if (indices->empty() || !made.vertices) return nullptr;
    auto* from = const_cast<osg::Geometry*>(source); // shared, not modified
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(source->getName() + " (faces with adjacency)");
    geometry->setUseDisplayList(false);
    shareArrays(*geometry, *from);
    geometry->addPrimitiveSet(indices.get());
    made.geometry = geometry;
    return geometry.get();
}

std::size_t AdjacencyDrawables::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return _standIns.size();
}

void AdjacencyDrawables::prune()
{
    for (auto it = _standIns.begin(); it != _standIns.end();)
        it = it->second.source.valid() ? std::next(it) : _standIns.erase(it);
}

void AdjacencyDrawables::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (auto& entry : _standIns)
        if (entry.second.geometry) entry.second.geometry->resizeGLObjectBuffers(maxSize);
}

void AdjacencyDrawables::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& entry : _standIns)
        if (entry.second.geometry) entry.second.geometry->releaseGLObjects(state);
}

// ---------------------------------------------------------------------------------------
// GpuCasterDraws

GpuCasterDraws::GpuCasterDraws(CasterVertexStages* stages, AdjacencyDrawables* adjacency)
    : _stages(stages), _adjacency(adjacency)
{
}

GpuCasterDraws::~GpuCasterDraws() = default;

osg::StateSet* GpuCasterDraws::ruleState(unsigned int rule)
{
    if (rule == 0) return nullptr;
    osg::ref_ptr<osg::StateSet>& ss = _rules[rule];
    if (ss) return ss.get();
    ss = new osg::StateSet;
    ss->addUniform(new osg::Uniform(shader::GPU_VOLUME_RULE, int(rule)),
                   osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    return ss.get();
}

bool GpuCasterDraws::takesAny(const std::vector<Caster>& casters) const
{
    return std::any_of(casters.begin(), casters.end(), [this](const Caster& c) { return takes(c); });
}

std::vector<Caster> GpuCasterDraws::leftToCpu(const std::vector<Caster>& casters) const
{
    std::vector<Caster> out = casters;
    if (_all)
        for (Caster& caster : out) caster.movedOnGpu = true;
    return out;
}

GpuCasterDraws::TakenCasters GpuCasterDraws::takenByDrawable(const std::vector<Caster>& casters) const
{
    std::unordered_map<const osg::Drawable*, const Caster*> taken;
    for (const Caster& caster : casters)
        if (takes(caster) && caster.geometry) taken.emplace(caster.geometry.get(), &caster);
    return taken;
}

std::size_t GpuCasterDraws::prepareLeaves(osgUtil::RenderBin& stage, osg::StateSet& pass,
                                          const std::unordered_map<const osg::Drawable*, const Caster*>& casters)
{
    std::size_t kept = 0;
    std::unordered_map<const osg::Drawable*, const Caster*> byStandIn; // the leaves' casters from here on
    eraseLeaves(stage, [&](osgUtil::RenderLeaf& leaf) {
        if (!leaf._parent || !under(leaf._parent, &pass)) return false;
        const auto found = leaf._drawable ? casters.find(leaf._drawable.get()) : casters.end();
        osg::Geometry* standIn = found == casters.end() ? nullptr : _adjacency->get(*found->second);
        if (!standIn) return true;
        leaf._drawable = standIn;
        byStandIn.emplace(standIn, found->second);
        ++kept;
        return false;
    });
    if (kept == 0) return 0;
    if (_stages) _stages->apply(stage, pass);
    applyRules(stage, pass, byStandIn);
    return kept;
}

void GpuCasterDraws::applyRules(osgUtil::RenderBin& bin, const osg::StateSet& pass,
                                const std::unordered_map<const osg::Drawable*, const Caster*>& byStandIn)
{
    const std::vector<osgUtil::StateGraph*> graphs = bin.getStateGraphList(); // grows below
    for (osgUtil::StateGraph* graph : graphs)
    {
        if (graph->_leaves.empty() || !under(graph, &pass)) continue;
        auto& leaves = graph->_leaves;
        for (auto it = leaves.begin(); it != leaves.end();)
        {
            const auto found = byStandIn.find((*it)->_drawable.get());
            osg::StateSet* rule = found == byStandIn.end() ? nullptr : ruleState(ruleOf(*found->second, mirrors(**it)));
            if (!rule)
            {
                ++it;
                continue;
            }
            osgUtil::StateGraph* child = graph->find_or_insert(rule);
            if (child->_leaves.empty()) bin.addStateGraph(child);
            child->addLeaf(it->get());
            it = leaves.erase(it);
        }
    }
    dropEmptyGraphs(bin);
    for (auto& nested : bin.getRenderBinList()) applyRules(*nested.second, pass, byStandIn);
}

void GpuCasterDraws::resizeGLObjectBuffers(unsigned int maxSize)
{
    for (auto& rule : _rules) rule.second->resizeGLObjectBuffers(maxSize);
}

void GpuCasterDraws::releaseGLObjects(osg::State* state) const
{
    for (const auto& rule : _rules) rule.second->releaseGLObjects(state);
}

} // namespace detail
} // namespace osgShadowSilhouette
