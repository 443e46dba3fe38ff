#include <osgShadowSilhouette/ShadowVolumes>

#include "GLConstants.h"
#include "GpuVolumes.h"
#include "RenderLeaves.h"
#include <osgShadowSilhouette/ShaderConstants>

#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/FrontFace>
#include <osg/PolygonOffset>
#include <osg/Stencil>
#include <osg/StencilTwoSided>

#include <algorithm>
#include <cmath>

namespace osgShadowSilhouette {

namespace {

/** Polygon offset factor of the light cap (in units of the cap's own depth slope per pixel). */
constexpr float LIGHT_CAP_SLOPE_OFFSET = 1.0f;
/** Polygon offset units of the light cap (depth buffer units), on top of its slope. */
constexpr float LIGHT_CAP_UNITS = 4.0f;
/** Polygon offset units of a light cap seen from a culled side (culledCapState()): enough
 *  for a face of the same caster that the eye pass draws in the same plane (a concave
 *  polygon's fan, whose triangles overlap with opposite windings), no slope term. */
constexpr float CULLED_CAP_UNITS = 4.0f;

/** A caster whose frame's origin lies farther from its centre than this many radii of its
 *  bounding box has its volume's sides drawn about its centre (ShadowVolumeGroup::rebuild):
 *  the model-view-projection's float terms grow with that distance, and the rounding of
 *  terms some hundred times the caster's size moved the outlines of its shadow on the
 *  receivers (OBJ/regr_3429812.obj of the corpus: 200 radii, a fifth of a pixel). Nearer,
 *  the caster's own frame is kept: its rounding is the eye pass's, and moving the frame by
 *  a fraction of a radius only trades some outline pixels for others (teapots.DAE). */
constexpr double FAR_ORIGIN_RADII = 8.0;

/** Bounds of a volume's geometry: the caster's own box (its vertices at infinity have none). */
class CasterBoundCallback : public osg::Drawable::ComputeBoundingBoxCallback
{
public:
    explicit CasterBoundCallback(const osg::BoundingBox& box) : _box(box) {}
    osg::BoundingBox computeBound(const osg::Drawable&) const override { return _box; }
    void setBox(const osg::BoundingBox& box) { _box = box; }

private:
    osg::BoundingBox _box;
};

/** Clears the stencil buffer (its StateSet opens the write mask). */
class StencilClearDrawable : public osg::Drawable
{
public:
    StencilClearDrawable() { setUseDisplayList(false); }
    StencilClearDrawable(const StencilClearDrawable& d, const osg::CopyOp& op) : osg::Drawable(d, op) {}
    META_Object(osgShadowSilhouette, StencilClearDrawable);
    void drawImplementation(osg::RenderInfo&) const override
    {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    // No bounds: a state change, not geometry. A box (around the origin of the frame it is
    // drawn in) would take part in the view's near/far computation and, with the scene far
    // from the origin, push the near plane past it. Culling is off for it.
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); }
};

osg::ref_ptr<osg::Geometry> volumeGeometry(osg::Vec4Array* vertices, osg::PrimitiveSet* indices,
                                           const osg::BoundingBox& box)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setDataVariance(osg::Object::DYNAMIC); // its draw callback changes between frames
    g->setVertexArray(vertices);
    g->addPrimitiveSet(indices);
    g->setComputeBoundingBoxCallback(new CasterBoundCallback(box));
    g->setCullingActive(false);
    return g;
}

/** Points @p geometry (made on the first call) at @p vertices and @p indices within @p box. */
void setVolumeGeometry(osg::ref_ptr<osg::Geometry>& geometry, osg::Vec4Array* vertices, osg::PrimitiveSet* indices,
                       const osg::BoundingBox& box)
{
    if (!geometry)
    {
        geometry = volumeGeometry(vertices, indices, box);
        return;
    }
    if (geometry->getVertexArray() != vertices) geometry->setVertexArray(vertices);
    static_cast<CasterBoundCallback*>(geometry->getComputeBoundingBoxCallback())->setBox(box);
    geometry->dirtyBound();
}

/** Writes into @p out the volume's @p vertices about @p origin: the finite ones (w = 1) less
 *  @p origin, in double, those at infinity (w = 0, directions) as they are. */
void verticesAbout(const osg::Vec4Array& vertices, const osg::Vec3d& origin, osg::Vec4Array& out)
{
    out.resize(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
        const osg::Vec4f& v = vertices[i];
        if (v.w() == 0.0f)
            out[i] = v;
        else
            out[i].set(float(double(v.x()) - origin.x()), float(double(v.y()) - origin.y()),
                       float(double(v.z()) - origin.z()), 1.0f);
    }
    out.dirty();
}

/** The light cap lies on its caster's faces, which the eye pass has drawn already, but
 *  not from the same triangles: its corners come in another order (OpenMesh starts a face
 *  where it likes, a strip's odd triangles and the faces a TWO_SIDED rule turns are
 *  reversed), so the rasterizer's depth plane is set up from another vertex and its depths
 *  differ from the surface's in the last bits, by an amount that grows with the depth slope
 *  (llvmpipe: whole triangles of false shadow on faces seen edge-on). So the cap, and only
 *  the cap, is pushed back by its slope and LIGHT_CAP_UNITS. The sides and the dark cap
 *  have no offset: any moves the shadow's outline on the receivers (one unit: 36 / 55
 *  wrong pixels on the corpus's Spider_ascii.stl against 21 / 25 without). */
osg::ref_ptr<osg::StateSet> lightCapState()
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::PROTECTED;
    ss->setAttributeAndModes(new osg::PolygonOffset(LIGHT_CAP_SLOPE_OFFSET, LIGHT_CAP_UNITS), on);
    return ss;
}

/** Where a caster's faces are culled, the eye sees some of them from a culled side: such a
 *  face is not in the depth buffer, and its light cap, pushed back by its slope, could land
 *  behind the surface the eye sees through it (teapots.DAE: whole runs of pixels where a
 *  wall seen edge-on from inside lies a few hundredths in front of the lid). So the cap is
 *  drawn twice, each time with GL's face culling keeping the cap triangles seen from one
 *  side: with the slope offset (`offset`) where the eye sees the side of the face the eye
 *  pass draws, with CULLED_CAP_UNITS only where it sees the culled side. `cull` names the
 *  side this draw leaves out (the volume's FrontFace makes FRONT the side its triangles'
 *  own counter-clockwise winding faces, mirrored or not). */
osg::ref_ptr<osg::StateSet> culledCapState(bool offset, osg::CullFace::Mode cull)
{
    osg::ref_ptr<osg::StateSet> ss = offset ? lightCapState() : osg::ref_ptr<osg::StateSet>(new osg::StateSet);
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::PROTECTED;
    if (!offset) ss->setAttributeAndModes(new osg::PolygonOffset(0.0f, CULLED_CAP_UNITS), on);
    ss->setMode(GL_CULL_FACE, on);
    ss->setAttribute(new osg::CullFace(cull), on);
    return ss;
}

/** Whether a matrix mirrors (negative determinant of its 3x3 part). */
bool mirrors(const osg::Matrixd& m)
{
    const osg::Vec3d x(m(0, 0), m(0, 1), m(0, 2)), y(m(1, 0), m(1, 1), m(1, 2)), z(m(2, 0), m(2, 1), m(2, 2));
    return (x ^ y) * z < 0.0;
}

/** The light cap's triangles (@p lightCap of @p indices) by their winding against their
 *  face's: kept (a face toward the light) and turned (a face away from it that a TWO_SIDED
 *  rule turns toward it). Only a cap of every face can hold turned ones (SilhouetteExtractor's
 *  writeCaps()). */
void splitLightCap(const std::vector<GLuint>& indices, const IndexRange& lightCap, std::size_t faces,
                   const std::vector<std::uint8_t>& lit, osg::DrawElementsUInt& kept, osg::DrawElementsUInt& turned)
{
    const auto first = indices.begin() + lightCap.first;
    const std::size_t count = lightCap.count / 3;
    const bool everyFace = count == faces && lit.size() == faces;
    for (std::size_t k = 0; k < count; ++k)
    {
        osg::DrawElementsUInt& out = everyFace && !lit[k] ? turned : kept;
        out.insert(out.end(), first + 3 * k, first + 3 * k + 3);
    }
}

} // namespace

bool needsZFail(const osg::BoundingSphered& caster, const osg::Vec4d& light, const osg::Vec3d& eye, double nearRadius)
{
    if (!caster.valid()) return false;
    const osg::Vec3d c = caster.center();
    const double r = caster.radius() + nearRadius;
    osg::Vec3d axis;       // away from the light
    double tanHalf = 0.0;  // widening of the swept region per unit along the axis
    if (light.w() == 0.0)
        axis = -osg::Vec3d(light.x(), light.y(), light.z());
    else
    {
        const osg::Vec3d l(light.x() / light.w(), light.y() / light.w(), light.z() / light.w());
        axis = c - l;
        const double d = axis.length();
        if (d <= r) return true; // the light is inside the (widened) caster bound
        tanHalf = r / std::sqrt(d * d - r * r);
    }
    if (axis.length2() == 0.0) return true;
    axis.normalize();
    const osg::Vec3d toEye = eye - c;
    const double t = toEye * axis; // distance along the axis, from the caster's centre
    if (t < -r) return false;      // between the light and the caster, beyond its bound
    const double radial = (toEye - axis * t).length();
    return radial <= r + std::max(0.0, t) * tanHalf;
}

/** One range of a shared index array, drawn from that array's element buffer: a volume's
 *  sides, dark cap and light cap are written once per build into one array (the sides and
 *  dark cap next to each other) and drawn as ranges of it, not copied into primitive sets
 *  of their own. */
class ShadowVolumeGroup::RangeDraw : public osg::PrimitiveSet
{
public:
    RangeDraw() : osg::PrimitiveSet(PrimitiveType, GL_TRIANGLES) {}
    explicit RangeDraw(osg::DrawElementsUInt* indices) : RangeDraw() { _indices = indices; }
    RangeDraw(const RangeDraw& r, const osg::CopyOp& op)
        : osg::PrimitiveSet(r, op), _indices(r._indices), _first(r._first), _count(r._count)
    {
    }
    META_Object(osgShadowSilhouette, RangeDraw);

    void setRange(const IndexRange& range)
    {
        _first = range.first;
        _count = range.count;
    }

    void draw(osg::State& state, bool useVertexBufferObjects) const override
    {
        if (_count == 0) return;
        osg::VertexArrayState* vas = state.getCurrentVertexArrayState();
        osg::GLBufferObject* ebo =
            useVertexBufferObjects ? _indices->getOrCreateGLBufferObject(state.getContextID()) : nullptr;
        if (!ebo)
        {
            vas->unbindElementBufferObject();
            glDrawElements(_mode, GLsizei(_count), GL_UNSIGNED_INT, &(*_indices)[_first]);
            return;
        }
        vas->bindElementBufferObject(ebo);
        const GLsizeiptr offset = ebo->getOffset(_indices->getBufferIndex()) + GLsizeiptr(_first * sizeof(GLuint));
        glDrawElements(_mode, GLsizei(_count), GL_UNSIGNED_INT, reinterpret_cast<const GLvoid*>(offset));
    }
    void accept(osg::PrimitiveFunctor& functor) const override
    {
        if (_count) functor.drawElements(_mode, GLsizei(_count), &(*_indices)[_first]);
    }
    void accept(osg::PrimitiveIndexFunctor& functor) const override
    {
        if (_count) functor.drawElements(_mode, GLsizei(_count), &(*_indices)[_first]);
    }
    unsigned int index(unsigned int pos) const override { return (*_indices)[_first + pos]; }
    unsigned int getNumIndices() const override { return _count; }
    void offsetIndices(int offset) override
    {
        for (std::uint32_t i = _first; i < _first + _count; ++i) (*_indices)[i] += offset;
        _indices->dirty();
    }
    // The element buffer is the shared array's: these reach it (a Geometry calls them of its
    // DrawElements only, so ShadowVolumeGroup releases the arrays itself too).
    void resizeGLObjectBuffers(unsigned int maxSize) override { _indices->resizeGLObjectBuffers(maxSize); }
    void releaseGLObjects(osg::State* state) const override { _indices->releaseGLObjects(state); }

private:
    osg::ref_ptr<osg::DrawElementsUInt> _indices = new osg::DrawElementsUInt(GL_TRIANGLES);
    std::uint32_t _first = 0, _count = 0;
};

ShadowVolumeGroup::ShadowVolumeGroup(unsigned int testRef, unsigned int testMask, unsigned int writeMask)
    : _root(new osg::Group)
{
    _root->setName("osgShadowSilhouette shadow volumes");
    _root->setCullingActive(false);
    _zfailState = stencilState(true, testRef, testMask, writeMask);
    _zpassState = stencilState(false, testRef, testMask, writeMask);
    _lightCapState = lightCapState();
    for (const bool mirrored : {false, true})
    {
        _frontFaceStates[mirrored] = new osg::StateSet;
        _frontFaceStates[mirrored]->setAttribute(
            new osg::FrontFace(mirrored ? osg::FrontFace::CLOCKWISE : osg::FrontFace::COUNTER_CLOCKWISE),
            osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    }
    for (const bool offset : {false, true})
        for (const osg::CullFace::Mode cull : {osg::CullFace::FRONT, osg::CullFace::BACK})
            _capCullStates[offset][cull == osg::CullFace::BACK] = culledCapState(offset, cull);
}

ShadowVolumeGroup::~ShadowVolumeGroup() = default;

void ShadowVolumeGroup::resizeGLObjectBuffers(unsigned int maxSize)
{
    _root->resizeGLObjectBuffers(maxSize); // every entry's transform, volumes and state
    // The index arrays the volumes' ranges draw from: a Geometry reaches only DrawElements.
    for (const Entry& e : _entries)
        if (e.indices) e.indices->resizeGLObjectBuffers(maxSize);
    for (osg::StateSet* ss : {_zfailState.get(), _zpassState.get(), _lightCapState.get(), _capCullStates[0][0].get(),
                              _capCullStates[0][1].get(), _capCullStates[1][0].get(), _capCullStates[1][1].get(),
                              _frontFaceStates[0].get(), _frontFaceStates[1].get()})
        if (ss) ss->resizeGLObjectBuffers(maxSize);
}

void ShadowVolumeGroup::releaseGLObjects(osg::State* state) const
{
    _root->releaseGLObjects(state);
    for (const Entry& e : _entries)
        if (e.indices) e.indices->releaseGLObjects(state); // as in resizeGLObjectBuffers()
    for (const osg::StateSet* ss : {_zfailState.get(), _zpassState.get(), _lightCapState.get(),
                                    _capCullStates[0][0].get(), _capCullStates[0][1].get(), _capCullStates[1][0].get(),
                                    _capCullStates[1][1].get(), _frontFaceStates[0].get(), _frontFaceStates[1].get()})
        if (ss) ss->releaseGLObjects(state);
}

osg::ref_ptr<osg::StateSet> ShadowVolumeGroup::stencilState(bool zfail, unsigned int ref, unsigned int mask,
                                                            unsigned int write) const
{
    osg::ref_ptr<osg::StencilTwoSided> stencil = new osg::StencilTwoSided;
    const auto keep = osg::StencilTwoSided::KEEP;
    const auto incr = osg::StencilTwoSided::INCR_WRAP;
    const auto decr = osg::StencilTwoSided::DECR_WRAP;
    for (auto face : {osg::StencilTwoSided::FRONT, osg::StencilTwoSided::BACK})
    {
        stencil->setFunction(face, osg::StencilTwoSided::EQUAL, int(ref), mask);
        stencil->setWriteMask(face, write);
        const bool back = face == osg::StencilTwoSided::BACK;
        if (zfail) // Everitt and Kilgard: count where the volume lies behind the scene
            stencil->setOperation(face, keep, back ? incr : decr, keep);
        else       // z-pass: count where the volume lies in front of the scene
            stencil->setOperation(face, keep, keep, back ? decr : incr);
    }
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setAttributeAndModes(stencil.get(), osg::StateAttribute::ON);
    return ss;
}

ShadowVolumeGroup::Entry ShadowVolumeGroup::createEntry() const
{
    Entry e;
    e.transform = new osg::MatrixTransform;
    e.transform->setCullingActive(false);
    e.zSwitch = new osg::Switch;
    e.zSwitch->setCullingActive(false);
    e.transform->addChild(e.zSwitch.get());
    return e;
}

void ShadowVolumeGroup::assembleSwitch(Entry& e, const osg::Vec3d& origin) const
{
    const bool sameCaps =
        std::equal(e.lightCaps.begin(), e.lightCaps.end(), e.assembledCaps.begin(), e.assembledCaps.end(),
                   [](const osg::ref_ptr<osg::Geometry>& a, osg::Geometry* b) { return a == b; });
    if (e.zSwitch->getNumChildren() == 2 && origin == e.assembledOrigin && sameCaps) return;
    e.assembledOrigin = origin;
    e.assembledCaps.clear();
    for (const osg::ref_ptr<osg::Geometry>& cap : e.lightCaps) e.assembledCaps.push_back(cap.get());
    // A transform only where the volume is drawn about a centre: the other casters' volumes
    // keep one model-view matrix a draw, as before.
    const auto centredAt = [&origin](osg::Drawable* drawable) -> osg::ref_ptr<osg::Node> {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(drawable);
        geode->setCullingActive(false);
        if (origin == osg::Vec3d()) return geode;
        osg::ref_ptr<osg::MatrixTransform> about = new osg::MatrixTransform(osg::Matrixd::translate(origin));
        about->setCullingActive(false);
        about->addChild(geode.get());
        return about;
    };
    osg::ref_ptr<osg::Group> fail = new osg::Group, pass = new osg::Group;
    osg::ref_ptr<osg::Geode> caps = new osg::Geode;
    for (const osg::ref_ptr<osg::Geometry>& cap : e.lightCaps) caps->addDrawable(cap.get());
    caps->setCullingActive(false);
    fail->addChild(centredAt(e.zfail.get()).get());
    fail->addChild(caps.get());
    pass->addChild(centredAt(e.zpass.get()).get());
    fail->setStateSet(_zfailState.get());
    pass->setStateSet(_zpassState.get());
    fail->setCullingActive(false);
    pass->setCullingActive(false);
    e.zSwitch->removeChildren(0, e.zSwitch->getNumChildren());
    e.zSwitch->addChild(fail.get());
    e.zSwitch->addChild(pass.get());
}

void ShadowVolumeGroup::rebuild(Entry& e, const osg::Vec4d& light) const
{
    const MeshAdjacency& mesh = e.caster.mesh->getAdjacency();
    if (e.caster.movedOnGpu) // its vertex array is not where it is drawn: no volume (the technique warns)
    {
        e.silhouette = SilhouetteEdges();
        e.volume = ShadowVolume();
    }
    else
        _extractor.buildVolume(mesh, HomogeneousLight{light}, e.caster.world, e.silhouette, e.volume);

    // The light cap lies on the caster's faces and is drawn in the caster's frame, as the eye
    // pass draws them, so that it rounds as they do. When that frame's origin lies far off
    // for the caster's size, the sides and the dark cap are drawn about the caster's centre
    // (verticesAbout()), so that their depths away from the caster do not carry the frame's
    // rounding; otherwise in the caster's frame too.
    const osg::BoundingBox box = e.caster.geometry->getBoundingBox();
    const bool farOrigin = box.valid() && box.center().length() > FAR_ORIGIN_RADII * box.radius();
    const osg::Vec3d origin(farOrigin ? box.center() : osg::Vec3());
    fillArrays(e, origin);
    osg::Vec4Array* centred = origin != osg::Vec3d() ? e.centred.get() : e.vertices.get(); // about 0: the same
    const osg::BoundingBox centredBox(box._min - osg::Vec3(origin), box._max - osg::Vec3(origin));
    setVolumeGeometry(e.zfail, centred, e.sidesAndDarkCap.get(), centredBox);
    setVolumeGeometry(e.zpass, centred, e.sides.get(), centredBox);
    // A mirroring matrix turns the volume inside out in the window: its counts would be
    // negative and cancel another caster's where their shadows overlap. The volume's
    // FrontFace turns it back, so that GL's front faces are those its triangles' own
    // counter-clockwise winding faces, as without the mirror.
    const bool mirrored = mirrors(e.caster.world);
    e.zSwitch->setStateSet(_frontFaceStates[mirrored].get());
    setLightCaps(e, box, mirrored);
    assembleSwitch(e, origin);
    e.transform->setMatrix(e.caster.world);

    const osg::BoundingSphere local(box);
    e.worldBound = osg::BoundingSphered(osg::Vec3d(local.center()) * e.caster.world, 0.0);
    const double scale =
        std::max({osg::Vec3d(e.caster.world(0, 0), e.caster.world(0, 1), e.caster.world(0, 2)).length(),
                  osg::Vec3d(e.caster.world(1, 0), e.caster.world(1, 1), e.caster.world(1, 2)).length(),
                  osg::Vec3d(e.caster.world(2, 0), e.caster.world(2, 1), e.caster.world(2, 2)).length()});
    e.worldBound.radius() = local.radius() * scale;
}

void ShadowVolumeGroup::setLightCaps(Entry& e, const osg::BoundingBox& box, bool mirrored) const
{
    // The sides of a face the eye pass culls, named by the face's own winding as the volume's
    // FrontFace names them (a mirror swaps the window's).
    const unsigned char both = Caster::CULLS_CCW | Caster::CULLS_CW;
    const unsigned char culled =
        mirrored && e.caster.culledWindings != both ? e.caster.culledWindings ^ both : e.caster.culledWindings;
    e.lightCaps.clear();
    if (!culled)
    {
        setVolumeGeometry(e.lightCapGeometry, e.vertices.get(), e.lightCap.get(), box);
        e.lightCapGeometry->setStateSet(_lightCapState.get());
        e.lightCaps.push_back(e.lightCapGeometry);
        return;
    }
    const auto addCap = [&](osg::DrawElementsUInt* indices, osg::StateSet* state) {
        e.lightCaps.push_back(volumeGeometry(e.vertices.get(), indices, box));
        e.lightCaps.back()->setStateSet(state);
    };
    osg::ref_ptr<osg::DrawElementsUInt> kept = new osg::DrawElementsUInt(GL_TRIANGLES),
                                        turned = new osg::DrawElementsUInt(GL_TRIANGLES);
    splitLightCap(e.indices->asVector(), e.volume.lightCap, e.caster.mesh->getAdjacency().faces.size(),
                  e.silhouette.lit, *kept, *turned);
    for (osg::DrawElementsUInt* part : {kept.get(), turned.get()})
    {
        if (part->empty()) continue;
        // The sides of the cap's triangles from which the eye sees their face's culled
        // side: the face's own, or the other for a turned triangle.
        const unsigned char seenCulled = part == kept.get() || culled == both ? culled : (culled ^ both);
        const bool ccw = seenCulled == Caster::CULLS_CCW;
        if (seenCulled != both) addCap(part, _capCullStates[1][ccw ? 0 : 1].get());        // leaves them out
        addCap(part, seenCulled == both ? nullptr : _capCullStates[0][ccw ? 1 : 0].get()); // keeps only them
    }
}

void ShadowVolumeGroup::fillArrays(Entry& e, const osg::Vec3d& origin)
{
    if (!e.vertices)
    {
        e.vertices = new osg::Vec4Array;
        e.indices = new osg::DrawElementsUInt(GL_TRIANGLES);
        e.indices->setElementBufferObject(new osg::ElementBufferObject);
        e.sidesAndDarkCap = new RangeDraw(e.indices.get());
        e.sides = new RangeDraw(e.indices.get());
        e.lightCap = new RangeDraw(e.indices.get());
    }
    // The volume's vertices and indices go to the drawn arrays without a copy; the arrays'
    // previous ones come back to the volume, whose next build overwrites them in place.
    e.vertices->asVector().swap(e.volume.vertices);
    e.vertices->dirty();
    e.indices->asVector().swap(e.volume.indices);
    e.indices->dirty();
    if (origin != osg::Vec3d())
    {
        if (!e.centred) e.centred = new osg::Vec4Array;
        verticesAbout(*e.vertices, origin, *e.centred);
    }
    const ShadowVolume& v = e.volume;
    e.sidesAndDarkCap->setRange(IndexRange{v.sides.first, v.sides.count + v.darkCap.count}); // one draw, not two
    e.sides->setRange(v.sides);
    e.lightCap->setRange(v.lightCap);
}

unsigned int ShadowVolumeGroup::update(const std::vector<Caster>& casters, const osg::Vec4d& light)
{
    const bool lightChanged = light != _light;
    _light = light;
    if (_entries.size() != casters.size())
    {
        _entries.resize(casters.size());
        _root->removeChildren(0, _root->getNumChildren());
        for (Entry& e : _entries)
        {
            if (!e.transform) e = createEntry();
            _root->addChild(e.transform.get());
        }
    }
    unsigned int rebuilt = 0;
    for (std::size_t i = 0; i < casters.size(); ++i)
    {
        Entry& e = _entries[i];
        if (!lightChanged && e.zfail && e.caster == casters[i] && e.caster.culledWindings == casters[i].culledWindings)
        {
            e.caster.seeThrough = casters[i].seeThrough; // how it is drawn, not its volume
            continue;
        }
        e.caster = casters[i];
        rebuild(e, light);
        ++rebuilt;
    }
    return rebuilt;
}

void ShadowVolumeGroup::cull(osgUtil::CullVisitor& cv, const osg::Vec3d& eye, double nearRadius,
                             const osg::BoundingBoxd& receivers, BlockerQueries* blockers)
{
    _zfail = _zpass = _culled = 0;
    const osg::Viewport* viewport = cv.getViewport();
    const osg::Matrixd worldToClip = *cv.getModelViewMatrix() * *cv.getProjectionMatrix();
    const bool conditional = blockers && blockers->size() == _entries.size();
    for (unsigned int i = 0; i < _entries.size(); ++i)
    {
        Entry& e = _entries[i];
        BlockerQueries* owner = conditional ? blockers : nullptr;
        if (e.conditionalOwner != owner)
        {
            e.conditionalOwner = owner;
            e.conditional = owner ? owner->createConditionalDraw(i) : nullptr;
        }
        if (e.zfail->getDrawCallback() != e.conditional.get()) e.zfail->setDrawCallback(e.conditional.get());
        if (e.zpass->getDrawCallback() != e.conditional.get()) e.zpass->setDrawCallback(e.conditional.get());
        for (const osg::ref_ptr<osg::Geometry>& cap : e.lightCaps)
            if (cap->getDrawCallback() != e.conditional.get()) cap->setDrawCallback(e.conditional.get());
        const bool drawn = applyScissor(e, receivers, worldToClip, viewport);
        e.transform->setNodeMask(drawn ? ~0u : 0u);
        if (!drawn)
        {
            ++_culled;
            continue;
        }
        // z-pass counts from the eye, and takes a view ray that meets the caster for one
        // that ends on it: true only of a caster whose surface is in the depth buffer.
        const bool zfail = e.caster.seeThrough || needsZFail(e.worldBound, _light, eye, nearRadius);
        e.zSwitch->setSingleChildOn(zfail ? 0 : 1);
        ++(zfail ? _zfail : _zpass);
    }
    cullAgain(cv);
}

void ShadowVolumeGroup::cullAgain(osgUtil::CullVisitor& cv)
{
    const osg::CullSettings::ComputeNearFarMode mode = cv.getComputeNearFarMode();
    cv.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR); // volumes reach infinity
    _root->accept(cv);
    cv.setComputeNearFarMode(mode);
}

bool ShadowVolumeGroup::applyScissor(Entry& e, const osg::BoundingBoxd& receivers, const osg::Matrixd& worldToClip,
                                     const osg::Viewport* viewport)
{
    osg::Vec4i rect;
    const osg::BoundingBox local = e.caster.geometry->getBoundingBox();
    osg::BoundingBoxd world;
    for (unsigned int i = 0; i < 8; ++i) world.expandBy(osg::Vec3d(local.corner(i)) * e.caster.world);
    if (!viewport || !receivers.valid() || !volumeScissor(world, _light, receivers, worldToClip, *viewport, rect))
    {
        e.transform->setStateSet(nullptr);
        return true;
    }
    if (rect.z() <= 0 || rect.w() <= 0) return false;
    if (!e.scissor) e.scissor = new osg::Scissor;
    e.scissor->setScissor(rect.x(), rect.y(), rect.z(), rect.w());
    e.transform->getOrCreateStateSet()->setAttributeAndModes(e.scissor.get(), osg::StateAttribute::ON);
    return true;
}

bool volumeScissor(const osg::BoundingBoxd& caster, const osg::Vec4d& light, const osg::BoundingBoxd& receivers,
                   const osg::Matrixd& worldToClip, const osg::Viewport& viewport, osg::Vec4i& rect)
{
    if (!caster.valid() || !receivers.valid()) return false;
    // How far to sweep: past the far side of the receivers' box, whatever the direction.
    const double sweep = (receivers._max - receivers._min).length() + (caster._max - caster._min).length() +
                         (caster.center() - receivers.center()).length();
    // The world box of the caster's box swept away from the light, cut to the receivers' box
    // (per axis, so it still holds the part of the volume inside the receivers' box).
    osg::BoundingBoxd swept;
    for (unsigned int i = 0; i < 8; ++i)
    {
        const osg::Vec3d p = caster.corner(i);
        osg::Vec3d away = light.w() == 0.0 ? -osg::Vec3d(light.x(), light.y(), light.z())
                                           : p - osg::Vec3d(light.x(), light.y(), light.z()) / light.w();
        if (away.length2() == 0.0) return false;
        away.normalize();
        swept.expandBy(p);
        swept.expandBy(p + away * sweep);
    }
    const osg::BoundingBoxd part = swept.intersect(receivers);
    if (!part.valid())
    {
        rect.set(viewport.x(), viewport.y(), 0, 0); // shadows no receiver: draw nothing
        return true;
    }
    osg::BoundingBoxd screen; // normalized device x, y
    for (unsigned int i = 0; i < 8; ++i)
    {
        const osg::Vec4d c = osg::Vec4d(part.corner(i), 1.0) * worldToClip;
        if (c.w() <= 1e-9) return false;
        screen.expandBy(osg::Vec3d(c.x() / c.w(), c.y() / c.w(), 0.0));
    }
    const double x0 = viewport.x() + (screen.xMin() * 0.5 + 0.5) * viewport.width();
    const double x1 = viewport.x() + (screen.xMax() * 0.5 + 0.5) * viewport.width();
    const double y0 = viewport.y() + (screen.yMin() * 0.5 + 0.5) * viewport.height();
    const double y1 = viewport.y() + (screen.yMax() * 0.5 + 0.5) * viewport.height();
    const int ix0 = std::max(int(viewport.x()), int(std::floor(x0)) - 1);
    const int iy0 = std::max(int(viewport.y()), int(std::floor(y0)) - 1);
    const int ix1 = std::min(int(viewport.x() + viewport.width()), int(std::ceil(x1)) + 1);
    const int iy1 = std::min(int(viewport.y() + viewport.height()), int(std::ceil(y1)) + 1);
    rect.set(ix0, iy0, std::max(0, ix1 - ix0), std::max(0, iy1 - iy0));
    return true;
}

std::size_t ShadowVolumeGroup::getTriangleCount() const
{
    std::size_t n = 0;
    for (const Entry& e : _entries) n += e.indices ? e.indices->size() / 3 : 0; // the volume's indices are there
    return n;
}

osg::ref_ptr<osg::Geode> createStencilClear()
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setName("osgShadowSilhouette stencil clear");
    osg::ref_ptr<StencilClearDrawable> clear = new StencilClearDrawable;
    clear->setCullingActive(false);
    geode->addDrawable(clear.get());
    geode->setCullingActive(false);
    osg::ref_ptr<osg::Stencil> stencil = new osg::Stencil;
    stencil->setWriteMask(~0u);
    geode->getOrCreateStateSet()->setAttribute(stencil.get(), osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    return geode;
}

osg::ref_ptr<osg::StateSet> createVolumeStateSet(osg::Program* program)
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    if (program) ss->setAttributeAndModes(program, on | osg::StateAttribute::PROTECTED);
    ss->setAttribute(new osg::ColorMask(false, false, false, false), on);
    ss->setAttribute(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false), on);
    ss->setMode(GL_DEPTH_TEST, on);
    ss->setMode(GL_DEPTH_CLAMP, on);
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    ss->setMode(GL_STENCIL_TEST, on);
    // None on the sides and the dark cap (the light caps set their own, lightCapState()).
    ss->setAttributeAndModes(new osg::PolygonOffset(0.0f, 0.0f), on);
    ss->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    return ss;
}

} // namespace osgShadowSilhouette

// ---------------------------------------------------------------------------------------
// The eye passes of the stencil modes

namespace osgShadowSilhouette {

namespace {

constexpr unsigned int MASK_BIT = 0x80;   // HYBRID: silhouette pixel
constexpr unsigned int COUNT_BITS = 0x7f; // HYBRID: the volumes' count
constexpr int OUTER_BIN = 5;              // after the opaque bin (0), before transparent (10)
constexpr int BLENDED_MIN_BIN = 11;       // the blended round: after transparent (10) at least
constexpr int BINS_PER_LIGHT = 10;
// Screen-space visibility's final pass: after every light's bins (slots < 64).
constexpr int FINAL_BIN = 1 + BINS_PER_LIGHT * 64;
// Bins of one light, from 1 + BINS_PER_LIGHT * slot on.
enum LightBin
{
    BIN_CLEAR = 0,
    BIN_MASK_BEGIN,
    BIN_MASK,
    BIN_MASK_END,
    BIN_VOLUME_BEGIN,
    BIN_VOLUMES,
    BIN_VOLUME_END,
    BIN_LIT,
    BIN_LIT_SHADOW_MAP
};

/** A node holding one drawable (a counter's begin or end) in render bin `bin`. */
osg::ref_ptr<osg::StateSet> passState(int bin, osg::Program* program)
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setRenderBinDetails(bin, "RenderBin");
    if (program) ss->setAttributeAndModes(program, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    return ss;
}

/** Stencil test (func ref mask), no stencil writes, and blending that adds the pass (alpha
 *  times the pass where `blended`: the blended round's receivers). */
void addLightState(osg::StateSet& ss, unsigned int ref, unsigned int mask, bool additive, bool blended)
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::Stencil> stencil = new osg::Stencil;
    stencil->setFunction(osg::Stencil::EQUAL, int(ref), mask);
    stencil->setOperation(osg::Stencil::KEEP, osg::Stencil::KEEP, osg::Stencil::KEEP);
    stencil->setWriteMask(0u);
    ss.setAttributeAndModes(stencil.get(), on);
    ss.setAttribute(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false), on);
    if (additive)
        ss.setAttributeAndModes(new osg::BlendFunc(blended ? GL_SRC_ALPHA : GL_ONE, GL_ONE), on);
    else
        ss.setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
}

/** Screen-space visibility: a light pass marks its bit (OSS_VISIBILITY_MARK) and writes no colour. */
void addMarkState(osg::StateSet& ss)
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    ss.setDefine(shader::DEFINE_VISIBILITY_MARK);
    ss.setAttribute(new osg::ColorMask(false, false, false, false), on);
    ss.setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
}

/** HYBRID mask pass: sets MASK_BIT where the fragment survives; writes no colour or depth. */
void addMaskState(osg::StateSet& ss)
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::Stencil> stencil = new osg::Stencil;
    stencil->setFunction(osg::Stencil::ALWAYS, int(MASK_BIT), MASK_BIT);
    stencil->setOperation(osg::Stencil::KEEP, osg::Stencil::KEEP, osg::Stencil::REPLACE);
    stencil->setWriteMask(MASK_BIT);
    ss.setAttributeAndModes(stencil.get(), on);
    ss.setAttribute(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false), on);
    ss.setAttribute(new osg::ColorMask(false, false, false, false), on);
}

double nearPlaneRadius(osgUtil::CullVisitor& cv)
{
    const osg::Matrixd& p = *cv.getProjectionMatrix();
    const double tx = p(0, 0) != 0.0 ? 1.0 / p(0, 0) : 1.0, ty = p(1, 1) != 0.0 ? 1.0 / p(1, 1) : 1.0;
    double fovy, aspect, zNear = 0.0, zFar;
    if (!p.getPerspective(fovy, aspect, zNear, zFar)) zNear = 0.0;
    const double n = std::max({zNear, static_cast<double>(cv.getCalculatedNearPlane()),
                               cv.getCalculatedFarPlane() * cv.getNearFarRatio()});
    return 1.5 * std::max(n, 1e-6) * std::sqrt(1.0 + tx * tx + ty * ty);
}

} // namespace

StencilShadowPasses::StencilShadowPasses(osg::Program* lighting, osg::Program* volume)
    : _lighting(lighting), _volume(volume)
{
    _base = new osg::StateSet;
    _base->setAttributeAndModes(lighting, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    _outer = new osg::StateSet;
    _outer->setRenderBinDetails(OUTER_BIN, "RenderBin");
    _blendedOuter = new osg::StateSet;
    _blendedOuter->setRenderBinDetails(BLENDED_MIN_BIN, "RenderBin");
    // The nearest blended layer's depth, where the volumes count and the light passes meet
    // (a blended surface often writes none of its own).
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    _blendedDepth = passState(0, lighting);
    _blendedDepth->setAttribute(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, true), on);
    _blendedDepth->setAttribute(new osg::ColorMask(false, false, false, false), on);
    _blendedDepth->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
}

StencilShadowPasses::~StencilShadowPasses() = default;

template<class Apply>
void StencilShadowPasses::forEachHolder(const Apply& apply) const
{
    apply(_lighting.get());
    apply(_volume.get());
    apply(_base.get());
    apply(_outer.get());
    apply(_blendedOuter.get());
    apply(_blendedDepth.get());
    apply(_barrier.get());
    apply(_finalPass.get());
    apply(_finalBarrierState.get());
    apply(_gpu.get());
    for (const Slot& s : _slots)
    {
        apply(s.volumes.get());
        apply(s.clear.get());
        apply(s.maskCounter.get());
        apply(s.volumeCounter.get());
        for (osg::Node* node : {s.maskBegin.get(), s.maskEnd.get(), s.volumeBegin.get(), s.volumeEnd.get()}) apply(node);
        for (osg::StateSet* ss : {s.clearState.get(), s.maskState.get(), s.volumeState.get(), s.litState.get(),
                                  s.litShadowMapState.get(), s.blendedClearState.get(), s.blendedMaskState.get(),
                                  s.blendedVolumeState.get(), s.blendedLitState.get(), s.blendedLitShadowMapState.get(),
                                  s.gpu.sides.get(), s.gpu.cap.get(), s.gpuBlended.sides.get(), s.gpuBlended.cap.get()})
            apply(ss);
    }
}

void StencilShadowPasses::resizeGLObjectBuffers(unsigned int maxSize)
{
    forEachHolder([maxSize](auto* holder) {
        if (holder) holder->resizeGLObjectBuffers(maxSize);
    });
}

void StencilShadowPasses::releaseGLObjects(osg::State* state) const
{
    forEachHolder([state](auto* holder) {
        if (holder) holder->releaseGLObjects(state);
    });
}

void StencilShadowPasses::build(Slot& s) const
{
    const int bin = 1 + BINS_PER_LIGHT * static_cast<int>(s.slot);
    const std::string slot = std::to_string(s.slot), light = std::to_string(s.lightNum);
    s.clear = createStencilClear();
    s.clearState = passState(bin + BIN_CLEAR, nullptr);
    s.faceSlots = 0; // new pass states: slotFor() names the light's slots
    s.volumeState = createVolumeStateSet(_volume.get());
    s.volumeState->setRenderBinDetails(bin + BIN_VOLUMES, "RenderBin");
    s.blendedClearState = passState(bin + BIN_CLEAR, nullptr);
    s.blendedVolumeState = new osg::StateSet(*s.volumeState, osg::CopyOp::SHALLOW_COPY);
    s.volumes = s.hybrid ? new ShadowVolumeGroup(MASK_BIT, MASK_BIT, COUNT_BITS) : new ShadowVolumeGroup;
    s.gpu = s.gpuBlended = GpuVolumePasses(); // made from the volume states on first use
    s.volumeCounter = new GpuCounter(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    s.volumeBegin = s.volumeCounter->createBeginNode(bin + BIN_VOLUME_BEGIN);
    s.volumeEnd = s.volumeCounter->createEndNode(bin + BIN_VOLUME_END);

    // A light pass: the receivers where the stencil holds ref under readMask.
    const auto lightPass = [&](int binOffset, unsigned int ref, unsigned int readMask, bool blended) {
        osg::ref_ptr<osg::StateSet> ss = passState(bin + binOffset, _lighting.get());
        ss->setDefine("OSS_LIGHT_PASS", slot);
        ss->setDefine("OSS_LIGHT_NUM", light);
        if (blended) ss->setDefine(shader::DEFINE_BLENDED_PASS);
        addLightState(*ss, ref, readMask, !s.mask, blended);
        if (s.mark) addMarkState(*ss);
        return ss;
    };
    // Count 0 is lit; HYBRID: only at silhouette pixels (mask bit set, count 0).
    s.litState = lightPass(BIN_LIT, s.hybrid ? MASK_BIT : 0u, 0xffu, false);
    s.blendedLitState = lightPass(BIN_LIT, s.hybrid ? MASK_BIT : 0u, 0xffu, true);
    if (!s.hybrid) return;

    s.maskCounter = new GpuCounter(GL_SAMPLES_PASSED);
    s.maskBegin = s.maskCounter->createBeginNode(bin + BIN_MASK_BEGIN);
    s.maskEnd = s.maskCounter->createEndNode(bin + BIN_MASK_END);
    s.maskState = passState(bin + BIN_MASK, _lighting.get());
    s.maskState->setDefine("OSS_HYBRID_MASK", slot);
    s.maskState->setDefine("OSS_LIGHT_NUM", light);
    addMaskState(*s.maskState);
    s.blendedMaskState = new osg::StateSet(*s.maskState, osg::CopyOp::SHALLOW_COPY);
    // The other pixels (mask bit clear): the shadow map's answer.
    s.litShadowMapState = lightPass(BIN_LIT_SHADOW_MAP, 0u, MASK_BIT, false);
    s.litShadowMapState->setDefine("OSS_HYBRID_SHADOW_MAP");
    s.blendedLitShadowMapState = lightPass(BIN_LIT_SHADOW_MAP, 0u, MASK_BIT, true);
    s.blendedLitShadowMapState->setDefine("OSS_HYBRID_SHADOW_MAP");
}

void StencilShadowPasses::setScreenVisibility(osg::Node* barrier, osg::StateSet* finalPass)
{
    _barrier = finalPass ? barrier : nullptr;
    _finalPass = barrier ? finalPass : nullptr;
    if (!_finalPass) return;
    _finalPass->setRenderBinDetails(FINAL_BIN, "RenderBin");
    if (!_finalBarrierState) _finalBarrierState = passState(FINAL_BIN - 1, nullptr);
}

StencilShadowPasses::Slot& StencilShadowPasses::slotFor(const StencilLight& light, bool hybrid, bool mask,
                                                         bool mark)
{
    if (_slots.size() <= light.slot) _slots.resize(light.slot + 1);
    Slot& s = _slots[light.slot];
    if (!s.volumes || s.lightNum != light.lightNum || s.hybrid != hybrid || s.mask != mask || s.mark != mark)
    {
        const bool keepVolumes = s.volumes && s.hybrid == hybrid;
        s.slot = light.slot;
        s.lightNum = light.lightNum;
        s.hybrid = hybrid;
        s.mask = mask;
        s.mark = mark;
        // The volumes depend on the light and the mode only: a debug view keeps them.
        const osg::ref_ptr<ShadowVolumeGroup> volumes = keepVolumes ? s.volumes : nullptr;
        build(s);
        if (volumes) s.volumes = volumes;
    }
    if (s.hybrid && s.faceSlots != light.faceSlots)
    {
        // The mask and shadow-map light passes sample only the maps of their own light.
        s.faceSlots = light.faceSlots;
        const std::string faces = std::to_string(light.faceSlots);
        s.maskState->setDefine("OSS_LIGHT_FACES", faces);
        s.blendedMaskState->setDefine("OSS_LIGHT_FACES", faces);
        s.litShadowMapState->setDefine("OSS_LIGHT_FACES", faces);
        s.blendedLitShadowMapState->setDefine("OSS_LIGHT_FACES", faces);
    }
    return s;
}

void StencilShadowPasses::cull(osgUtil::CullVisitor& cv, bool hybrid, int maskSlot,
                               const std::vector<StencilLight>& lights, const std::vector<Caster>& casters,
                               const osg::BoundingBoxd& receivers, const CullReceivers& cullReceivers)
{
    _zfail = _zpass = _rebuilt = _culled = _gpuCasters = 0;
    _silhouettePixels = _volumeFragments = -1;
    _blockersHidden = _blockersTested = 0;
    const VolumeView view{osg::Matrixd::inverse(*cv.getModelViewMatrix()).getTrans(), nearPlaneRadius(cv), receivers};
    const bool mask = maskSlot >= 0;
    const bool mark = _finalPass && !mask;
    // Receivers the base pass draws after the light passes (see cull() in the header).
    const int lastLate = detail::lastBinWithLeaves(*cv.getCurrentRenderBin(), OUTER_BIN);
    cv.pushStateSet(_outer.get());
    osgUtil::RenderBin* outer = cv.getCurrentRenderBin();
    // A light's receiver pass, without the receivers of the blended round.
    const CullReceivers opaquePass = [&](osg::StateSet* pass) {
        cullReceivers(pass);
        auto bin = outer->getRenderBinList().find(pass->getBinNumber());
        if (bin != outer->getRenderBinList().end()) detail::keepByBin(*bin->second, OUTER_BIN, false);
    };
    std::vector<StencilLight> culled; // the lights of this cull, for the blended round
    const bool gpu = _gpu && _cullCasters && _gpu->takesAny(casters);
    std::vector<Caster> marked; // every caster's volume on the GPU: none left to the CPU
    if (gpu && _gpu->getAllCasters()) marked = _gpu->leftToCpu(casters);
    const std::vector<Caster>& cpuCasters = marked.empty() ? casters : marked;
    for (const StencilLight& light : lights)
    {
        if (mask && int(light.slot) != maskSlot) continue;
        culled.push_back(light);
        Slot& s = slotFor(light, hybrid, mask, mark);
        cullLight(cv, s, light, cpuCasters, view, opaquePass);
        if (gpu) cullGpuVolumes(cv, s, light, casters, false);
    }
    if (mark)
    {
        cv.pushStateSet(_finalBarrierState.get());
        _barrier->accept(cv);
        cv.popStateSet();
        cullReceivers(_finalPass.get());
    }
    cv.popStateSet();
    _blendedRound = false;
    _blendedSkipped = lastLate > OUTER_BIN && mark;
    if (lastLate > OUTER_BIN && !mark)
        cullBlended(cv, std::max(BLENDED_MIN_BIN, lastLate + 1), culled, gpu ? &casters : nullptr, cullReceivers);
}

void StencilShadowPasses::cullLight(osgUtil::CullVisitor& cv, Slot& s, const StencilLight& light,
                                    const std::vector<Caster>& casters, const VolumeView& view,
                                    const CullReceivers& opaquePass)
{
    const auto add = [](long long& sum, long long value) {
        if (value >= 0) sum = std::max(sum, 0LL) + value;
    };
    cv.pushStateSet(s.clearState.get());
    s.clear->accept(cv);
    if (s.mark) _barrier->accept(cv); // the base pass's clear (or the last light's marks) first
    cv.popStateSet();
    if (s.hybrid)
    {
        s.maskBegin->accept(cv);
        opaquePass(s.maskState.get());
        s.maskEnd->accept(cv);
        add(_silhouettePixels, s.maskCounter->getLastValue());
    }
    _rebuilt += s.volumes->update(casters, light.position);
    s.volumeBegin->accept(cv);
    cv.pushStateSet(s.volumeState.get());
    s.volumes->cull(cv, view.eye, view.nearRadius, view.receivers, light.blockers.get());
    cv.popStateSet();
    s.volumeEnd->accept(cv);
    add(_volumeFragments, s.volumeCounter->getLastValue());
    if (light.blockers)
    {
        _blockersHidden += light.blockers->getHidden();
        _blockersTested += light.blockers->getTested();
    }
    _zfail += s.volumes->getZFailCount();
    _zpass += s.volumes->getZPassCount();
    _culled += s.volumes->getCulledCount();
    opaquePass(s.litState.get());
    if (s.hybrid) opaquePass(s.litShadowMapState.get());
}

void StencilShadowPasses::cullGpuVolumes(osgUtil::CullVisitor& cv, Slot& s, const StencilLight& light,
                                         const std::vector<Caster>& casters, bool blended)
{
    GpuVolumePasses& passes = blended ? s.gpuBlended : s.gpu;
    if (!passes.sides)
        passes = _gpu->createLight(blended ? *s.blendedVolumeState : *s.volumeState, *s.volumes->getZFailState(),
                                   *s.volumes->getLightCapState());
    const auto culled = static_cast<unsigned int>(_gpu->cull(cv, passes, light.position, casters, _cullCasters));
    if (!blended) _gpuCasters += culled;
}

void StencilShadowPasses::setGpuVolumes(detail::GpuVolumes* gpu, CullReceivers cullCasters)
{
    _gpu = gpu;
    _cullCasters = std::move(cullCasters);
}

void StencilShadowPasses::cullBlended(osgUtil::CullVisitor& cv, int outerBin, const std::vector<StencilLight>& lights,
                                      const std::vector<Caster>* gpuCasters, const CullReceivers& cullReceivers)
{
    if (_blendedOuter->getBinNumber() != outerBin) _blendedOuter->setRenderBinDetails(outerBin, "RenderBin");
    cv.pushStateSet(_blendedOuter.get());
    osgUtil::RenderBin* outer = cv.getCurrentRenderBin();
    // A pass over the blended receivers alone; false when there is none.
    const auto blendedPass = [&](osg::StateSet* pass) {
        cullReceivers(pass);
        auto bin = outer->getRenderBinList().find(pass->getBinNumber());
        if (bin == outer->getRenderBinList().end()) return false;
        detail::keepByBin(*bin->second, OUTER_BIN, true);
        if (detail::holdsLeaves(*bin->second)) return true;
        outer->getRenderBinList().erase(bin);
        return false;
    };
    if (blendedPass(_blendedDepth.get()))
    {
        _blendedRound = true;
        // In slot order: a light pass fills what the slots before it left (oss_stencil.frag).
        std::vector<StencilLight> bySlot = lights;
        std::sort(bySlot.begin(), bySlot.end(),
                  [](const StencilLight& a, const StencilLight& b) { return a.slot < b.slot; });
        for (const StencilLight& light : bySlot)
        {
            if (light.slot >= _slots.size() || !_slots[light.slot].volumes) continue;
            Slot& s = _slots[light.slot];
            cv.pushStateSet(s.blendedClearState.get());
            s.clear->accept(cv);
            cv.popStateSet();
            if (s.hybrid) blendedPass(s.blendedMaskState.get());
            cv.pushStateSet(s.blendedVolumeState.get());
            s.volumes->cullAgain(cv);
            cv.popStateSet();
            if (gpuCasters) cullGpuVolumes(cv, s, light, *gpuCasters, true);
            blendedPass(s.blendedLitState.get());
            if (s.hybrid) blendedPass(s.blendedLitShadowMapState.get());
        }
    }
    cv.popStateSet();
}

} // namespace osgShadowSilhouette
