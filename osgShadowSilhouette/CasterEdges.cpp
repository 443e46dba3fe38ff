#include <osgShadowSilhouette/CasterEdges>

#include "CasterVertexStages.h"

#include <osg/Camera>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/FrontFace>
#include <osg/Transform>

namespace osgShadowSilhouette {

// ---------------------------------------------------------------------------------------
// CasterCollector

bool seeThrough(const osg::StateSet& ss)
{
    if (ss.getRenderingHint() == osg::StateSet::TRANSPARENT_BIN) return true;
    if (ss.useRenderBinDetails() && (ss.getBinNumber() > 0 || ss.getBinName() == "DepthSortedBin")) return true;
    const auto* depth = dynamic_cast<const osg::Depth*>(ss.getAttribute(osg::StateAttribute::DEPTH));
    return depth && !depth->getWriteMask();
}

namespace {

/** One value along a node path as osg::State applies it: a value set with OVERRIDE stays in
 *  force below unless the incoming one is PROTECTED; otherwise the innermost wins. (The
 *  exact reference has its own, StateSlot in tests/reference: it shares no code with what
 *  it judges.) */
struct PathValue
{
    const osg::StateAttribute* attribute = nullptr;
    unsigned int value = 0;
    bool set = false;

    void push(const osg::StateAttribute* incoming, unsigned int incomingValue)
    {
        if (set && (value & osg::StateAttribute::OVERRIDE) && !(incomingValue & osg::StateAttribute::PROTECTED)) return;
        attribute = incoming;
        value = incomingValue;
        set = true;
    }
};

/** Face culling as the eye pass draws a geometry with the state sets of `path` (then
 *  `own`): the window windings it culls (Caster::CULLS_CCW, CULLS_CW). */
unsigned char culledWindings(const osg::NodePath& path, const osg::StateSet* own)
{
    PathValue mode, cullFace, frontFace;
    const auto apply = [&](const osg::StateSet& ss) {
        const osg::StateSet::ModeList& modes = ss.getModeList();
        const auto m = modes.find(GL_CULL_FACE);
        if (m != modes.end()) mode.push(nullptr, m->second);
        if (const osg::StateSet::RefAttributePair* p = ss.getAttributePair(osg::StateAttribute::CULLFACE))
            cullFace.push(p->first.get(), p->second);
        if (const osg::StateSet::RefAttributePair* p = ss.getAttributePair(osg::StateAttribute::FRONTFACE))
            frontFace.push(p->first.get(), p->second);
    };
    for (const osg::Node* node : path)
        if (node->getStateSet()) apply(*node->getStateSet());
    if (own && (path.empty() || path.back()->getStateSet() != own)) apply(*own);
    if (!mode.set || !(mode.value & osg::StateAttribute::ON)) return 0;
    const auto* cull = dynamic_cast<const osg::CullFace*>(cullFace.attribute);
    const auto* front = dynamic_cast<const osg::FrontFace*>(frontFace.attribute);
    const osg::CullFace::Mode culled = cull ? cull->getMode() : osg::CullFace::BACK;
    if (culled == osg::CullFace::FRONT_AND_BACK) return Caster::CULLS_CCW | Caster::CULLS_CW;
    const bool ccwIsFront = !front || front->getMode() != osg::FrontFace::CLOCKWISE;
    return (culled == osg::CullFace::FRONT) == ccwIsFront ? Caster::CULLS_CCW : Caster::CULLS_CW;
}

} // namespace

bool drawnMovedOnGpu(const osg::NodePath& path, const osg::Geometry& geometry)
{
    const osg::StateSet* own = geometry.getStateSet();
    PathValue program;
    const auto apply = [&](const osg::StateSet& ss) {
        if (const osg::StateSet::RefAttributePair* p = ss.getAttributePair(osg::StateAttribute::PROGRAM))
            program.push(p->first.get(), p->second);
    };
    for (const osg::Node* node : path)
        if (node->getStateSet()) apply(*node->getStateSet());
    if (own && (path.empty() || path.back()->getStateSet() != own)) apply(*own);
    const auto* p = dynamic_cast<const osg::Program*>(program.attribute);
    return p && detail::CasterVertexStages::movesVertices(*p, geometry);
}

namespace {

/** Whether @p world mirrors (negative determinant of its 3x3 part). */
bool worldMirrors(const osg::Matrixd& world)
{
    return (osg::Vec3d(world(0, 0), world(0, 1), world(0, 2)) ^ osg::Vec3d(world(1, 0), world(1, 1), world(1, 2))) *
               osg::Vec3d(world(2, 0), world(2, 1), world(2, 2)) <
           0.0;
}

/** Whether the culling `windings` (culledWindings()) culls a side of a geometry that a view
 *  ray may pass, so that the ray goes on behind the surface. A closed mesh wound outward
 *  whose inside alone is culled hides that inside behind its outside; any other culling
 *  lets a ray through. */
bool cullsASeenSide(unsigned char windings, bool closedOutward, const osg::Matrixd& world)
{
    if (!windings) return false;
    if (!closedOutward || windings == (Caster::CULLS_CCW | Caster::CULLS_CW)) return true;
    // The outside is the counter-clockwise side, turned over by a mirroring world matrix.
    const unsigned char outside = worldMirrors(world) ? Caster::CULLS_CW : Caster::CULLS_CCW;
    return windings == outside;
}

} // namespace

CasterCollector::CasterCollector(MeshCache& cache, unsigned int traversalMask, const ViewPoint& view)
    : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _cache(cache), _view(view)
{
    setTraversalMask(traversalMask);
    _matrices.emplace_back();
}

void CasterCollector::apply(osg::Transform& transform)
{
    osg::Matrixd m = _matrices.back();
    transform.computeLocalToWorldMatrix(m, this);
    _matrices.push_back(m);
    traverse(transform);
    _matrices.pop_back();
}

void CasterCollector::apply(osg::LOD& lod)
{
    if (!_view.valid) return traverse(lod); // OSG's choice for a visitor that is not a cull visitor
    for (unsigned int i = 0; i < lod.getNumChildren(); ++i)
        if (_view.isActive(lod, i, _matrices.back())) lod.getChild(i)->accept(*this);
}

void CasterCollector::apply(osg::Billboard& billboard)
{
    const osg::Matrixd world = _matrices.back();
    for (unsigned int i = 0; i < billboard.getNumDrawables(); ++i)
    {
        osg::Geometry* geometry = billboard.getDrawable(i) ? billboard.getDrawable(i)->asGeometry() : nullptr;
        if (!geometry || !validNodeMask(*geometry)) continue;
        _matrices.push_back(_view.billboardMatrix(billboard, i, world));
        apply(*geometry);
        _matrices.pop_back();
    }
}

void CasterCollector::apply(osg::Camera&)
{
    // A nested camera draws its own subgraph with its own matrices: not a caster of ours.
}

void CasterCollector::apply(osg::Geometry& geometry)
{
    if (!_cache.hasFiniteVertices(geometry)) return; // casts no shadow at all (the technique warns)
    osg::ref_ptr<const CachedMesh> mesh = _cache.get(geometry);
    if (!mesh || mesh->getAdjacency().empty()) return;
    Caster caster;
    caster.geometry = &geometry;
    caster.closed = mesh->getAdjacency().isClosedOutward();
    caster.mesh = mesh;
    caster.world = _matrices.back();
    for (const osg::Node* node : getNodePath())
        if (node->getStateSet() && seeThrough(*node->getStateSet())) caster.seeThrough = true;
    if (geometry.getStateSet() && seeThrough(*geometry.getStateSet())) caster.seeThrough = true; // a billboard's
    caster.culledWindings = culledWindings(getNodePath(), geometry.getStateSet());
    if (cullsASeenSide(caster.culledWindings, caster.closed, caster.world)) caster.seeThrough = true;
    caster.movedOnGpu = drawnMovedOnGpu(getNodePath(), geometry);
    _casters.push_back(caster);
}

std::vector<Caster> collectCasters(osg::Group& group, unsigned int castsMask, MeshCache& cache, const ViewPoint& view)
{
    CasterCollector collector(cache, castsMask, view);
    for (unsigned int i = 0; i < group.getNumChildren(); ++i) group.getChild(i)->accept(collector);
    return std::move(collector.getCasters());
}

// ---------------------------------------------------------------------------------------
// CasterEdges

CasterEdges::CasterEdges()
{
    _vertices = new osg::Vec3Array;
    _drawArrays = new osg::DrawArrays(GL_LINES, 0, 0);
    _lines = new osg::Geometry;
    _lines->setName("osgShadowSilhouette silhouette edges");
    _lines->setDataVariance(osg::Object::DYNAMIC);
    _lines->setUseDisplayList(false);
    _lines->setUseVertexBufferObjects(true);
    _lines->setVertexArray(_vertices.get());
    _lines->addPrimitiveSet(_drawArrays.get());
    _lines->setCullingActive(false); // its bound changes every frame; the pass draws all of it
}

CasterEdges::~CasterEdges() = default;

void CasterEdges::setOpenCasterRule(OpenCasterRule rule)
{
    if (rule == _extractor.getOpenCasterRule()) return;
    _extractor.setOpenCasterRule(rule);
    _extracted = false;
}

bool CasterEdges::update(const std::vector<Caster>& casters, const osg::Vec4d& light)
{
    if (_extracted && light == _light && casters == _casters) return false;
    _casters = casters;
    _light = light;
    _extracted = true;
    ++_extractions;
    _silhouettes.resize(casters.size());
    _world.clear();
    const HomogeneousLight worldLight{light};
    for (std::size_t i = 0; i < casters.size(); ++i)
    {
        SilhouetteEdges& edges = _silhouettes[i];
        if (casters[i].movedOnGpu)
        {
            edges = SilhouetteEdges(); // its vertex array is not where it is drawn
            continue;
        }
        _extractor.extract(casters[i].mesh->getAdjacency(), worldLight, casters[i].world, edges);
        // A mirror turns the lit faces' winding as the light sees it: b -> a keeps the caster on the left.
        const bool mirrored = worldMirrors(casters[i].world);
        for (std::size_t k = 0; k + 1 < edges.positions.size(); k += 2)
        {
            const osg::Vec3d a = osg::Vec3d(edges.positions[k]) * casters[i].world;
            const osg::Vec3d b = osg::Vec3d(edges.positions[k + 1]) * casters[i].world;
            _world.push_back(mirrored ? b : a);
            _world.push_back(mirrored ? a : b);
        }
    }
    _written = false;
    return true;
}

bool CasterEdges::writeLines(const osg::Matrixd& worldToView)
{
    if (_written && worldToView == _view) return false;
    _view = worldToView;
    _written = true;
    _vertices->resize(_world.size());
    for (std::size_t i = 0; i < _world.size(); ++i) (*_vertices)[i] = osg::Vec3f(_world[i] * worldToView);
    _drawArrays->setCount(static_cast<GLsizei>(_world.size()));
    _vertices->dirty();
    _drawArrays->dirty();
    _lines->dirtyBound();
    return true;
}

} // namespace osgShadowSilhouette
