#include <osgShadowSilhouette/TriangleListPass>
#include "GLConstants.h"
#include <osgShadowSilhouette/ShaderConstants>

#include "RenderLeaves.h"
#include "ShaderSource.h"

#include <osg/ColorMask>
#include <osg/GLExtensions>
#include <osg/observer_ptr>
#include <osgUtil/CullVisitor>

#include <OpenThreads/Mutex>
#include <cmath>
#include <OpenThreads/ScopedLock>
#include <osg/Geode>
#include <osg/TriangleIndexFunctor>
#include <algorithm>
#include <atomic>
#include <map>
#include <vector>

namespace osgShadowSilhouette {

namespace {

constexpr GLbitfield ALL_LIST_BARRIERS =
    GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT;

void memoryBarrier(osg::RenderInfo& info)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    if (ext && ext->glMemoryBarrier) ext->glMemoryBarrier(ALL_LIST_BARRIERS);
}

/** The eye pass's limits of one context, 0 until a list pass has asked. */
struct ContextLimits
{
    std::atomic<unsigned int> storageBlocks{0}; ///< GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS
    std::atomic<unsigned int> imageUniforms{0}; ///< GL_MAX_FRAGMENT_IMAGE_UNIFORMS
    std::atomic<unsigned int> bufferTexels{0};  ///< GL_MAX_TEXTURE_BUFFER_SIZE
    std::atomic<unsigned int> outputResources{0}; ///< GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES
};

std::vector<ContextLimits>& contextLimits()
{
    static std::vector<ContextLimits> limits(64);
    return limits;
}

unsigned int queryLimit(GLenum name)
{
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value > 0 ? static_cast<unsigned int>(value) : 0u;
}

/** The list buffer's storage: `bytes` bytes that GL allocates and the passes fill. The
 *  host holds zeros only until the first upload (OSG uploads a buffer's data when it creates
 *  the GL object): releaseHostCopy() frees them, and a context that creates the object again
 *  gets zeros made anew. A pass's buffer is 30-70 MB, a cube face's lists included, so the
 *  host need not keep one per slot. */
class ListStorage : public osg::BufferData
{
public:
    explicit ListStorage(std::size_t bytes = 0) : _bytes(bytes) {}
    ListStorage(const ListStorage& other, const osg::CopyOp& op) : osg::BufferData(other, op), _bytes(other._bytes) {}
    osg::Object* cloneType() const override { return new ListStorage(); }
    osg::Object* clone(const osg::CopyOp& op) const override { return new ListStorage(*this, op); }
    const char* libraryName() const override { return "osgShadowSilhouette"; }
    const char* className() const override { return "TriangleListStorage"; }

    const GLvoid* getDataPointer() const override
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
        if (_zeros.size() * sizeof(GLuint) < _bytes) _zeros.assign((_bytes + sizeof(GLuint) - 1) / sizeof(GLuint), 0u);
        return _zeros.data();
    }
    unsigned int getTotalDataSize() const override { return static_cast<unsigned int>(_bytes); }

    void releaseHostCopy()
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
        std::vector<GLuint>().swap(_zeros);
    }

private:
    std::size_t _bytes;
    mutable OpenThreads::Mutex _mutex;
    mutable std::vector<GLuint> _zeros;
};

using ClearBufferSubData = void(GL_APIENTRY*)(GLenum, GLenum, GLintptr, GLsizeiptr, GLenum, GLenum, const void*);

/** Empties the lists before the pass: the counters, heads and counts (the first
 *  countsOffset + grid * grid uints) set to 0 by one buffer clear (a buffer update, ordered
 *  with the draws around it on every driver, where a shader write from a clear quad is not:
 *  tiled rasterizers run its tiles in parallel with the casters' fragments). */
class ClearLists : public osg::Camera::DrawCallback
{
public:
    ClearLists(osg::BufferData* buffer, std::size_t uints) : _buffer(buffer), _uints(uints) {}
    void operator()(osg::RenderInfo& info) const override
    {
        const unsigned int id = info.getContextID();
        auto& limits = contextLimits();
        if (id < limits.size() && limits[id].storageBlocks == 0)
        {
            limits[id].imageUniforms = queryLimit(GL_MAX_FRAGMENT_IMAGE_UNIFORMS);
            limits[id].bufferTexels = queryLimit(GL_MAX_TEXTURE_BUFFER_SIZE);
            limits[id].outputResources = queryLimit(GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES);
            limits[id].storageBlocks = std::max(1u, queryLimit(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS));
        }
        osg::ref_ptr<osg::BufferData> buffer;
        if (!_buffer.lock(buffer) || !buffer->getBufferObject()) return;
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        osg::GLBufferObject* gl = buffer->getBufferObject()->getOrCreateGLBufferObject(id);
        if (!ext || !gl || !ext->glBufferSubData) return;
        if (gl->isDirty()) gl->compileBuffer(); // first use: uploads zeros
        if (auto* storage = dynamic_cast<ListStorage*>(buffer.get())) storage->releaseHostCopy();
        if (!_clear && !_looked)
        {
            _clear = reinterpret_cast<ClearBufferSubData>(osg::getGLExtensionFuncPtr("glClearBufferSubData"));
            _looked = true;
        }
        const GLintptr offset = GLintptr(gl->getOffset(buffer->getBufferIndex()));
        const GLsizeiptr bytes = GLsizeiptr(_uints * sizeof(GLuint));
        ext->glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl->getGLObjectID());
        if (_clear)
        {
            const GLuint zero = 0;
            _clear(GL_SHADER_STORAGE_BUFFER, GL_R32UI, offset, bytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        }
        else
        {
            if (_zeros.size() != _uints) _zeros.assign(_uints, 0u);
            ext->glBufferSubData(GL_SHADER_STORAGE_BUFFER, offset, bytes, _zeros.data());
        }
        ext->glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }

private:
    osg::observer_ptr<osg::BufferData> _buffer;
    std::size_t _uints;
    mutable ClearBufferSubData _clear = nullptr;
    mutable bool _looked = false;
    mutable std::vector<GLuint> _zeros;
};

/** Makes the lists visible to the eye pass that reads them. */
} // namespace

/** The counters of the newest builds on their way back (per context: a small buffer and a
 *  fence), and the last counts read. Builds are numbered on both sides (cull: culled, draw:
 *  drawn), and the counts carry the number of the build they describe (counted). */
struct TriangleListPass::Readback : public osg::Referenced
{
    using CopyBufferSubData = void(GL_APIENTRY*)(GLenum, GLenum, GLintptr, GLintptr, GLsizeiptr);
    struct PerContext
    {
        GLuint buffer = 0;
        GLsync fence = nullptr;
        unsigned int build = 0; ///< the build whose counters the fence guards
    };
    OpenThreads::Mutex mutex;
    std::map<unsigned int, PerContext> contexts;
    std::atomic<bool> pending{false};
    std::atomic<bool> known{false};
    std::atomic<std::size_t> nodes{0}, triangles{0};
    std::atomic<unsigned int> reached{1};
    std::atomic<unsigned int> culled{0}, drawn{0}, counted{0};
    osg::observer_ptr<osg::BufferData> buffer; ///< the list buffer (draw thread)
    CopyBufferSubData copy = nullptr;
    bool looked = false;

    /** After a build: the header's copy and a fence. */
    void request(osg::RenderInfo& info, osg::BufferData* data)
    {
        const unsigned int build = ++drawn;
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(mutex);
        buffer = data;
        copyHeader(info, data, build);
    }

    /** Copies the header of the buffer, which holds build `build`, unless an older copy is
     *  still on its way (poll() copies again once it is read). Call with the mutex held. */
    void copyHeader(osg::RenderInfo& info, osg::BufferData* data, unsigned int build)
    {
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        const unsigned int id = info.getContextID();
        if (!ext || !data || !data->getBufferObject() || !ext->glFenceSync || !ext->glGenBuffers ||
            !ext->glMemoryBarrier)
            return;
        osg::GLBufferObject* gl = data->getBufferObject()->getOrCreateGLBufferObject(id);
        if (!gl) return;
        if (!looked)
        {
            copy = reinterpret_cast<CopyBufferSubData>(osg::getGLExtensionFuncPtr("glCopyBufferSubData"));
            looked = true;
        }
        if (!copy) return;
        PerContext& pc = contexts[id];
        if (pc.fence) return; // an older build's counts are still on their way: read those first
        if (!pc.buffer)
        {
            ext->glGenBuffers(1, &pc.buffer);
            ext->glBindBuffer(GL_COPY_WRITE_BUFFER, pc.buffer);
            ext->glBufferData(GL_COPY_WRITE_BUFFER, 4 * sizeof(GLuint), nullptr, GL_STREAM_READ);
            ext->glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        }
        ext->glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); // the shaders' atomics, before the copy
        ext->glBindBuffer(GL_COPY_READ_BUFFER, gl->getGLObjectID());
        ext->glBindBuffer(GL_COPY_WRITE_BUFFER, pc.buffer);
        copy(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GLintptr(gl->getOffset(data->getBufferIndex())), 0,
             4 * sizeof(GLuint));
        ext->glBindBuffer(GL_COPY_READ_BUFFER, 0);
        ext->glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        pc.fence = ext->glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        pc.build = build;
        pending = pc.fence != nullptr;
    }

    /** In a later frame: the counts, where the GPU is past the fence (never waits). */
    void poll(osg::RenderInfo& info)
    {
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        if (!ext || !ext->glClientWaitSync || !ext->glGetBufferSubData) return;
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(mutex);
        auto it = contexts.find(info.getContextID());
        if (it == contexts.end() || !it->second.fence) return;
        PerContext& pc = it->second;
        const GLenum status = ext->glClientWaitSync(pc.fence, 0, 0);
        if (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED) return;
        ext->glDeleteSync(pc.fence);
        pc.fence = nullptr;
        GLuint counts[4] = {0, 0, 0, 0};
        ext->glBindBuffer(GL_COPY_WRITE_BUFFER, pc.buffer);
        ext->glGetBufferSubData(GL_COPY_WRITE_BUFFER, 0, sizeof(counts), counts);
        ext->glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        nodes = counts[0];
        triangles = counts[1];
        reached = counts[2];
        counted = pc.build;
        known = true;
        pending = false;
        // A build drawn while this copy was on its way: the buffer holds it now (this poll
        // runs in the eye pass, after the frame's list passes).
        osg::ref_ptr<osg::BufferData> data;
        if (pc.build != drawn.load() && buffer.lock(data)) copyHeader(info, data.get(), drawn.load());
    }
};

namespace {

/** After the build: the barrier for the eye pass, and the counters' read-back. */
class FinalBarrier : public osg::Camera::DrawCallback
{
public:
    FinalBarrier(osg::BufferData* buffer, TriangleListPass::Readback* readback) : _buffer(buffer), _readback(readback) {}
    void operator()(osg::RenderInfo& info) const override
    {
        memoryBarrier(info);
        osg::ref_ptr<osg::BufferData> buffer;
        if (_buffer.lock(buffer)) _readback->request(info, buffer.get());
    }

private:
    osg::observer_ptr<osg::BufferData> _buffer;
    osg::ref_ptr<TriangleListPass::Readback> _readback;
};

/** Polls the read-back at its place in the eye pass. */
class PollDrawable : public osg::Drawable
{
public:
    explicit PollDrawable(TriangleListPass::Readback* readback) : _readback(readback)
    {
        setUseDisplayList(false);
        setCullingActive(false);
        setDataVariance(osg::Object::DYNAMIC);
    }
    PollDrawable(const PollDrawable& d, const osg::CopyOp& op) : osg::Drawable(d, op), _readback(d._readback) {}
    osg::Object* cloneType() const override { return new PollDrawable(nullptr); }
    osg::Object* clone(const osg::CopyOp& op) const override { return new PollDrawable(*this, op); }
    const char* libraryName() const override { return "osgShadowSilhouette"; }
    const char* className() const override { return "TriangleListPollDrawable"; }
    void drawImplementation(osg::RenderInfo& info) const override
    {
        if (_readback) _readback->poll(info);
    }
    // No bounds: it draws nothing (see GpuQueries.cpp's CallDrawable).
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); }

private:
    osg::ref_ptr<TriangleListPass::Readback> _readback;
};

osg::ref_ptr<osg::Program> program(const char* name, const char* vert, const char* geom, const char* frag)
{
    osg::ref_ptr<osg::Program> p = new osg::Program;
    p->setName(name);
    p->addShader(detail::loadShader(osg::Shader::VERTEX, vert));
    if (geom) p->addShader(detail::loadShader(osg::Shader::GEOMETRY, geom));
    p->addShader(detail::loadShader(osg::Shader::FRAGMENT, frag));
    return p;
}

} // namespace

osg::ref_ptr<osg::StateSet> TriangleListPass::createSharedStateSet()
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    const auto overrideOff = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setAttributeAndModes(program("osgShadowSilhouette triangle lists", shader::FILE_TRILIST_VERT,
                                     shader::FILE_TRILIST_GEOM, shader::FILE_TRILIST_FRAG),
                             overrideOn);
    ss->setAttribute(new osg::ColorMask(false, false, false, false), overrideOn);
    for (GLenum mode : {GLenum(GL_DEPTH_TEST), GLenum(GL_CULL_FACE), GLenum(GL_BLEND), GLenum(GL_LIGHTING)})
        ss->setMode(mode, overrideOff);
    return ss;
}

TriangleListPass::TriangleListPass(unsigned int grid, std::size_t triangles, const osg::StateSet& shared,
                                   const std::string& name, std::size_t nodes, unsigned int reservePerTexel)
    : _grid(grid), _camera(new osg::Camera), _perspective(new osg::Uniform(shader::LIST_PERSPECTIVE, false)),
      _readback(new Readback)
{
    // Room for every triangle (with a margin for growth) and for about three triangles per
    // texel plus four texels per triangle.
    _triangleCapacity = static_cast<unsigned int>(std::min<std::size_t>(triangles + triangles / 4 + 64, MAX_TRIANGLES));
    _nodeCapacity = static_cast<unsigned int>(std::min<std::size_t>(
        std::max(nodes, std::size_t(grid) * grid * reservePerTexel + std::size_t(_triangleCapacity) * 4),
        MAX_NODES));
    _nodeCapacity += _nodeCapacity % 2; // the triangles start on a 16-byte boundary
    _buffer = new ListStorage(sizeof(GLuint) * (trianglesOffset() + 12 * std::size_t(_triangleCapacity)));
    osg::ref_ptr<osg::ShaderStorageBufferObject> sbo = new osg::ShaderStorageBufferObject;
    sbo->setUsage(GL_DYNAMIC_COPY);
    _buffer->setBufferObject(sbo.get());
    _imageView = new osg::TextureBuffer;
    _imageView->setInternalFormat(GL_RGBA32UI_EXT);
    _imageView->setBufferData(_buffer.get());

    osg::Camera& c = *_camera;
    c.setName(name);
    c.setReferenceFrame(osg::Camera::ABSOLUTE_RF_INHERIT_VIEWPOINT); // LODs chosen by the view's eye, as the depth pass
    c.setRenderOrder(osg::Camera::PRE_RENDER, 2); // after the depth pass
    c.setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    c.setImplicitBufferAttachmentMask(0, 0);
    c.setComputeNearFarMode(osg::Camera::DO_NOT_COMPUTE_NEAR_FAR);
    c.setCullingMode(c.getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    c.setClearMask(0);
    c.setStateSet(new osg::StateSet(shared, osg::CopyOp::SHALLOW_COPY));
    c.setViewport(0, 0, grid, grid);
    c.attach(osg::Camera::COLOR_BUFFER, GL_R8); // a render target for the rasterizer; nothing is written
    c.setInitialDrawCallback(new ClearLists(_buffer.get(), countsOffset() + std::size_t(grid) * grid));
    c.setFinalDrawCallback(new FinalBarrier(_buffer.get(), _readback.get()));
    osg::ref_ptr<osg::Geode> poll = new osg::Geode;
    poll->addDrawable(new PollDrawable(_readback.get()));
    poll->setCullingActive(false);
    _pollNode = poll;
    osg::StateSet* ss = c.getStateSet();
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    ss->setAttributeAndModes(new osg::ShaderStorageBufferBinding(0, _buffer.get(), 0, getBufferSize()), on);
    ss->addUniform(new osg::Uniform(shader::LIST_NODE_CAPACITY, _nodeCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_TRIANGLE_CAPACITY, _triangleCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_GRID_SIZE, osg::Vec2f(grid, grid)));
    ss->addUniform(_perspective.get());
    ss->addUniform(new osg::Uniform(shader::LIST_FRONT_ONLY, false));
    _receivers = new osg::Uniform(osg::Uniform::FLOAT_VEC3, shader::LIST_RECEIVERS, 8);
    _receiverSlack = new osg::Uniform(shader::LIST_RECEIVER_SLACK, 0.0f);
    ss->addUniform(_receivers.get());
    ss->addUniform(_receiverSlack.get());
}

TriangleListPass::~TriangleListPass() = default;

unsigned int TriangleListPass::fragmentStorageBlocks(unsigned int contextID)
{
    auto& limits = contextLimits();
    return contextID < limits.size() ? limits[contextID].storageBlocks.load() : 0u;
}

bool TriangleListPass::imageReadsFit(unsigned int contextID, unsigned int slots, std::size_t texels)
{
    auto& limits = contextLimits();
    if (contextID >= limits.size() || limits[contextID].storageBlocks == 0) return false;
    return slots <= limits[contextID].imageUniforms && texels <= limits[contextID].bufferTexels;
}

bool TriangleListPass::blockHeadsFit(unsigned int contextID, unsigned int slots)
{
    auto& limits = contextLimits();
    if (contextID >= limits.size() || limits[contextID].storageBlocks == 0) return false;
    return slots <= limits[contextID].storageBlocks && 2u * slots + 1u <= limits[contextID].outputResources;
}

bool TriangleListPass::countPending() const
{
    return _readback->pending.load() || _readback->counted.load() != _readback->culled.load();
}

bool TriangleListPass::listedNothing() const
{
    const Readback& r = *_readback;
    return r.known && r.counted.load() == r.culled.load() && r.nodes == 0 && r.triangles == 0 && r.reached == 0;
}

bool TriangleListPass::overflowed(std::size_t& nodes, std::size_t& triangles) const
{
    if (!_readback->known) return false;
    nodes = _readback->nodes;
    triangles = _readback->triangles;
    return nodes > _nodeCapacity || triangles > _triangleCapacity;
}

std::size_t TriangleListPass::getBufferSize() const
{
    return _buffer->getTotalDataSize();
}

void TriangleListPass::cull(osgUtil::CullVisitor& cv, const LightFrustum& frustum, bool perspective,
                            const osg::BoundingBoxd& receivers)
{
    _camera->setViewMatrix(frustum.view);
    _camera->setProjectionMatrix(frustum.projection);
    _perspective->set(perspective);
    // Without receivers (or with a box that is not finite) every triangle is kept: the corners
    // lie far beyond every plane.
    const bool box = receivers.valid() && std::isfinite(receivers.radius());
    for (unsigned int i = 0; i < 8; ++i)
    {
        const osg::Vec3d corner = box ? receivers.corner(i) * frustum.view : osg::Vec3d();
        const osg::Vec3f everywhere((i & 1) ? 1e30f : -1e30f, (i & 2) ? 1e30f : -1e30f, (i & 4) ? 1e30f : -1e30f);
        _receivers->setElement(i, box ? osg::Vec3f(corner) : everywhere);
    }
    _receiverSlack->set(box ? float(1e-5 * 2.0 * receivers.radius()) : 0.0f);
    ++_readback->culled;
    _camera->accept(cv);
}

// ---------------------------------------------------------------------------------------
// ListedDrawables

namespace {

/** Collects the triangles a primitive set's faces split into, in their winding. */
struct TriangleIndexSink
{
    osg::DrawElementsUInt* out = nullptr;
    void operator()(unsigned int a, unsigned int b, unsigned int c)
    {
        out->push_back(a);
        out->push_back(b);
        out->push_back(c);
    }
};

/** Whether a primitive mode draws faces that OSG's functors and GL may split differently. */
bool splitFace(GLenum mode)
{
    return mode == GL_QUADS || mode == GL_QUAD_STRIP || mode == GL_POLYGON;
}

} // namespace

bool ListedDrawables::isTriangleMode(GLenum mode)
{
    return mode == GL_TRIANGLES || mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN;
}

osg::Drawable* ListedDrawables::get(osg::Drawable& drawable)
{
    osg::Geometry* geometry = drawable.asGeometry();
    if (!geometry) return nullptr;
    const osg::Geometry::PrimitiveSetList& sets = geometry->getPrimitiveSetList();
    if (std::all_of(sets.begin(), sets.end(), [](const osg::ref_ptr<osg::PrimitiveSet>& p) {
            return !p || isTriangleMode(p->getMode());
        }))
        return geometry;
    return standIn(*geometry);
}

osg::Geometry* ListedDrawables::standIn(osg::Geometry& geometry)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto found = _standIns.find(&geometry);
    if (found != _standIns.end() && isCurrent(found->second, geometry)) return found->second.geometry.get();
    prune();
    StandIn& made = _standIns[&geometry];
    made = makeStandIn(geometry);
    return made.geometry.get();
}

osg::Drawable* ListedDrawables::faces(osg::Drawable& drawable)
{
    osg::Geometry* geometry = drawable.asGeometry();
    if (!geometry || geometry->getDrawCallback()) return &drawable;
    // An array bound per primitive set would pair its values with the stand-in's sets.
    for (const osg::Array* array : detail::attributeArrays(*geometry))
        if (array && array->getBinding() == osg::Array::BIND_PER_PRIMITIVE_SET) return &drawable;
    bool split = false;
    for (const osg::ref_ptr<osg::PrimitiveSet>& p : geometry->getPrimitiveSetList())
    {
        if (!p) continue;
        if (!isTriangleMode(p->getMode()) && !splitFace(p->getMode())) return &drawable; // lines, points
        split = split || splitFace(p->getMode());
    }
    osg::Geometry* made = split ? standIn(*geometry) : nullptr;
    return made ? made : &drawable;
}

void ListedDrawables::splitFaces(osgUtil::RenderBin& bin, const osg::StateSet* under)
{
    for (osgUtil::StateGraph* graph : bin.getStateGraphList())
    {
        if (under && !detail::under(graph, under)) continue;
        for (const osg::ref_ptr<osgUtil::RenderLeaf>& leaf : graph->_leaves)
            if (leaf->_drawable) leaf->_drawable = faces(*leaf->_drawable);
    }
    for (auto& nested : bin.getRenderBinList()) splitFaces(*nested.second, under);
}

void ListedDrawables::apply(osgUtil::RenderBin& bin)
{
    detail::eraseLeaves(bin, [this](osgUtil::RenderLeaf& leaf) {
        if (leaf._drawable) leaf._drawable = get(*leaf._drawable);
        return !leaf._drawable;
    });
}

std::size_t ListedDrawables::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return _standIns.size();
}

bool ListedDrawables::isCurrent(const StandIn& standIn, const osg::Geometry& source)
{
    const osg::Geometry::PrimitiveSetList& sets = source.getPrimitiveSetList();
    if (standIn.source.get() != &source || standIn.vertices != source.getVertexArray() ||
        standIn.primitives.size() != sets.size() || standIn.attributes != detail::attributeArrays(source))
        return false;
    for (std::size_t i = 0; i < sets.size(); ++i)
        if (standIn.primitives[i].first != sets[i].get() ||
            (sets[i] && standIn.primitives[i].second != sets[i]->getModifiedCount()))
            return false;
    return true;
}

ListedDrawables::StandIn ListedDrawables::makeStandIn(osg::Geometry& source)
{
    StandIn standIn;
    standIn.source = &source;
    standIn.vertices = source.getVertexArray();
    standIn.attributes = detail::attributeArrays(source);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(source.getName() + " (list pass triangles)");
    geometry->setUseDisplayList(false);
    // Every array, for a vertex stage of the caster's own too (a skinning shader's bone
    // weights: CasterVertexStages.h); shared, not copied, and with buffer objects as the
    // source draws (they would attach to its arrays and primitive sets, shared here).
    detail::shareArrays(*geometry, source);
    osg::ref_ptr<osg::DrawElementsUInt> faces = new osg::DrawElementsUInt(GL_TRIANGLES);
    osg::TriangleIndexFunctor<TriangleIndexSink> split;
    split.out = faces.get();
    for (const osg::ref_ptr<osg::PrimitiveSet>& primitives : source.getPrimitiveSetList())
    {
        standIn.primitives.emplace_back(primitives.get(), primitives ? primitives->getModifiedCount() : 0u);
        if (!primitives) continue;
        if (isTriangleMode(primitives->getMode()))
            geometry->addPrimitiveSet(primitives.get());
        else
            primitives->accept(split); // quads and polygons split; lines and points give nothing
    }
    if (!faces->empty()) geometry->addPrimitiveSet(faces.get());
    if (standIn.vertices && geometry->getNumPrimitiveSets() > 0) standIn.geometry = geometry;
    return standIn;
}

void ListedDrawables::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (auto& entry : _standIns)
        if (entry.second.geometry) entry.second.geometry->resizeGLObjectBuffers(maxSize);
}

void ListedDrawables::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& entry : _standIns)
        if (entry.second.geometry) entry.second.geometry->releaseGLObjects(state);
}

void ListedDrawables::prune()
{
    for (auto it = _standIns.begin(); it != _standIns.end();)
        it = it->second.source.valid() ? std::next(it) : _standIns.erase(it);
}

void TriangleListPass::resizeGLObjectBuffers(unsigned int maxSize)
{
    _camera->resizeGLObjectBuffers(maxSize);
    if (_buffer->getBufferObject()) _buffer->getBufferObject()->resizeGLObjectBuffers(maxSize);
    _imageView->resizeGLObjectBuffers(maxSize);
}

void TriangleListPass::releaseGLObjects(osg::State* state) const
{
    _camera->releaseGLObjects(state);
    if (_buffer->getBufferObject()) _buffer->getBufferObject()->releaseGLObjects(state);
    _imageView->releaseGLObjects(state);
}

} // namespace osgShadowSilhouette
