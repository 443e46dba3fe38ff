#include "CasterVertexStages.h"

#include "RenderLeaves.h"

#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/ValueObject>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

const osg::Program* CasterVertexStages::casterProgram(const osgUtil::StateGraph& graph, const osg::StateSet& passState)
{
    bool under = false;
    const osg::Program* program = programBelow(graph, &passState, under);
    return under && program && hasOwnVertexStage(*program) ? program : nullptr;
}

const osg::Program* CasterVertexStages::programBelow(const osgUtil::StateGraph& graph, const osg::StateSet* top,
                                                     bool& under)
{
    // The path from the leaves up to `top` (or the root), then applied top down.
    std::vector<const osg::StateSet*> path;
    const osgUtil::StateGraph* sg = &graph;
    for (; sg && (!top || sg->getStateSet() != top); sg = sg->_parent)
        if (sg->getStateSet()) path.push_back(sg->getStateSet());
    under = !top || sg;
    const osg::Program* program = nullptr;
    bool overridden = false;
    for (auto it = path.rbegin(); it != path.rend(); ++it)
    {
        const osg::StateSet::RefAttributePair* pair = (*it)->getAttributePair(osg::StateAttribute::PROGRAM);
        if (!pair || (overridden && !(pair->second & osg::StateAttribute::PROTECTED))) continue;
        program = dynamic_cast<const osg::Program*>(pair->first.get());
        overridden = (pair->second & osg::StateAttribute::OVERRIDE) != 0;
    }
    return program;
}

std::size_t CasterVertexStages::keepMovedReceivers(osgUtil::RenderBin& bin, const osg::StateSet& pass, bool base)
{
    std::size_t changed = 0;
    const std::vector<osgUtil::StateGraph*> graphs = bin.getStateGraphList(); // grows below
    for (osgUtil::StateGraph* graph : graphs)
    {
        bool under = false;
        const osg::Program* own = graph->_leaves.empty() ? nullptr : programBelow(*graph, &pass, under);
        if (!under || !own) continue;
        // A light pass whose state leaves the program alone draws them as they are. The base
        // pass keeps them under their own program whatever its state says now: the technique
        // culls it before it knows the mode, and sets a stencil mode's program on that state
        // afterwards, in the same frame (the first frame of SHADOW_VOLUME or HYBRID's stencil
        // method drew them at their rest pose, into the depth the volumes count against).
        if (!base && programBelow(*graph, nullptr, under) == own) continue;
        auto& leaves = graph->_leaves;
        const auto moved = std::stable_partition(leaves.begin(), leaves.end(), [&](const auto& leaf) {
            return !leaf->getDrawable() || !movesVertices(*own, *leaf->getDrawable());
        });
        if (moved == leaves.end()) continue;
        changed += std::size_t(leaves.end() - moved);
        if (base)
        {
            osg::StateSet* ss = nullptr;
            {
                OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
                ss = ownProgramState(*own);
            }
            osgUtil::StateGraph* child = graph->find_or_insert(ss);
            if (child->_leaves.empty()) bin.addStateGraph(child);
            for (auto it = moved; it != leaves.end(); ++it) child->addLeaf(it->get());
        }
        leaves.erase(moved, leaves.end());
    }
    dropEmptyGraphs(bin);
    for (auto& nested : bin.getRenderBinList()) changed += keepMovedReceivers(*nested.second, pass, base);
    return changed;
}

osg::StateSet* CasterVertexStages::ownProgramState(const osg::Program& program)
{
    prune();
    for (auto& entry : _own)
        if (entry.first.get() == &program) return entry.second.get();
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    const auto protectedOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;
    ss->setAttributeAndModes(const_cast<osg::Program*>(&program), protectedOn);
    _own.emplace_back(&program, ss);
    return ss.get();
}

bool CasterVertexStages::hasOwnVertexStage(const osg::Program& program)
{
    bool vertex = false;
    for (unsigned int i = 0; i < program.getNumShaders(); ++i)
    {
        const osg::Shader* shader = program.getShader(i);
        if (!shader) continue;
        const osg::Shader::Type type = shader->getType();
        if (type == osg::Shader::GEOMETRY || type == osg::Shader::TESSCONTROL || type == osg::Shader::TESSEVALUATION)
            return false;
        vertex = vertex || type == osg::Shader::VERTEX;
    }
    return vertex;
}

bool CasterVertexStages::movesVertices(const osg::Program& program, const osg::Drawable& drawable)
{
    if (!hasOwnVertexStage(program)) return false;
    bool moves = false;
    if (program.getUserValue(SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE, moves)) return moves;
    return std::string(drawable.libraryName()) == "osgAnimation";
}

std::size_t CasterVertexStages::apply(osgUtil::RenderBin& bin, const osg::StateSet& passState)
{
    const auto* passProgram = dynamic_cast<const osg::Program*>(passState.getAttribute(osg::StateAttribute::PROGRAM));
    if (!passProgram) return 0;
    std::size_t moved = 0;
    const std::vector<osgUtil::StateGraph*> graphs = bin.getStateGraphList(); // grows below
    for (osgUtil::StateGraph* graph : graphs)
    {
        if (graph->_leaves.empty()) continue;
        const osg::Program* caster = casterProgram(*graph, passState);
        if (!caster) continue;
        osg::StateSet* ss = nullptr;
        {
            OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
            ss = joined(*caster, *passProgram);
        }
        osgUtil::StateGraph* child = graph->find_or_insert(ss);
        if (child->_leaves.empty()) bin.addStateGraph(child); // state graphs outlive frames, their leaves do not
        for (const osg::ref_ptr<osgUtil::RenderLeaf>& leaf : graph->_leaves) child->addLeaf(leaf.get());
        moved += graph->_leaves.size();
        graph->_leaves.clear();
    }
    dropEmptyGraphs(bin); // a bin holds no empty state graph otherwise
    for (auto& nested : bin.getRenderBinList()) moved += apply(*nested.second, passState);
    return moved;
}

std::vector<const osg::Shader*> CasterVertexStages::joinedShaders(const osg::Program& caster, const osg::Program& pass)
{
    std::vector<const osg::Shader*> shaders;
    for (unsigned int i = 0; i < caster.getNumShaders(); ++i)
        if (caster.getShader(i) && caster.getShader(i)->getType() == osg::Shader::VERTEX)
            shaders.push_back(caster.getShader(i));
    for (unsigned int i = 0; i < pass.getNumShaders(); ++i)
        if (pass.getShader(i) && pass.getShader(i)->getType() != osg::Shader::VERTEX)
            shaders.push_back(pass.getShader(i));
    return shaders;
}

osg::StateSet* CasterVertexStages::joined(const osg::Program& caster, const osg::Program& pass)
{
    // A skinning program gains its shader and bindings after its first frames
    // (RigTransformHardware::init()): the joined program follows what the caster's holds now.
    std::vector<const osg::Shader*> shaders = joinedShaders(caster, pass);
    Joined& entry = _joined[{&caster, &pass}];
    if (entry.stateSet && entry.caster.get() == &caster && entry.pass.get() == &pass && entry.shaders == shaders &&
        entry.bindings == caster.getAttribBindingList())
        return entry.stateSet.get();
    prune();
    Joined& fresh = _joined[{&caster, &pass}];
    fresh.caster = &caster;
    fresh.pass = &pass;
    fresh.shaders = shaders;
    fresh.bindings = caster.getAttribBindingList();
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName((caster.getName().empty() ? std::string("a caster's program") : "'" + caster.getName() + "'") +
                     "'s vertex stage in " + pass.getName());
    for (const osg::Shader* shader : shaders) program->addShader(const_cast<osg::Shader*>(shader));
    for (const auto& binding : fresh.bindings) program->addBindAttribLocation(binding.first, binding.second);
    const auto protectedOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;
    fresh.stateSet = new osg::StateSet;
    fresh.stateSet->setAttributeAndModes(program.get(), protectedOn);
    fresh.stateSet->setDefine(shader::DEFINE_CASTER_VERTEX_STAGE, protectedOn);
    if (_watchLink) _watchLink(program.get());
    return fresh.stateSet.get();
}

void CasterVertexStages::prune()
{
    _own.erase(std::remove_if(_own.begin(), _own.end(), [](const auto& entry) { return !entry.first.valid(); }),
               _own.end());
    for (auto it = _joined.begin(); it != _joined.end();)
        it = it->second.caster.valid() && it->second.pass.valid() ? std::next(it) : _joined.erase(it);
}

std::size_t CasterVertexStages::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return _joined.size();
}

void CasterVertexStages::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (auto& entry : _joined)
        if (entry.second.stateSet) entry.second.stateSet->resizeGLObjectBuffers(maxSize);
    for (auto& entry : _own) entry.second->resizeGLObjectBuffers(maxSize);
}

void CasterVertexStages::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& entry : _joined)
        if (entry.second.stateSet) entry.second.stateSet->releaseGLObjects(state);
    // Not the state sets of _own: their programs are the scene's, which the scene releases.
}

} // namespace detail
} // namespace osgShadowSilhouette
