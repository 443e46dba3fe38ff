#include <osgShadowSilhouette/TriangleListPass>
#include <osgShadowSilhouette/ShaderConstants>

#include "ShaderSource.h"

#include <osg/ColorMask>
#include <osg/GLExtensions>
#include <osg/observer_ptr>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <atomic>
#include <vector>

#ifndef GL_SHADER_STORAGE_BARRIER_BIT
#define GL_SHADER_STORAGE_BARRIER_BIT 0x00002000
#endif
#ifndef GL_SHADER_IMAGE_ACCESS_BARRIER_BIT
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#endif
#ifndef GL_TEXTURE_FETCH_BARRIER_BIT
#define GL_TEXTURE_FETCH_BARRIER_BIT 0x00000008
#endif
#ifndef GL_SHADER_STORAGE_BUFFER
#define GL_SHADER_STORAGE_BUFFER 0x90D2
#endif
#ifndef GL_R32UI
#define GL_R32UI 0x8236
#endif
#ifndef GL_RED_INTEGER
#define GL_RED_INTEGER 0x8D94
#endif

namespace osgShadowSilhouette {

namespace {

constexpr GLbitfield ALL_LIST_BARRIERS =
    GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT;

void memoryBarrier(osg::RenderInfo& info)
{
    const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
    if (ext && ext->glMemoryBarrier) ext->glMemoryBarrier(ALL_LIST_BARRIERS);
}

#ifndef GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS
#define GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS 0x90DA
#endif

#ifndef GL_MAX_FRAGMENT_IMAGE_UNIFORMS
#define GL_MAX_FRAGMENT_IMAGE_UNIFORMS 0x90CE
#endif
#ifndef GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES
#define GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES 0x8F39
#endif
#ifndef GL_MAX_TEXTURE_BUFFER_SIZE
#define GL_MAX_TEXTURE_BUFFER_SIZE 0x8C2B
#endif

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

std::atomic<bool>& imageReadsAllowed()
{
    static std::atomic<bool> allowed{true};
    return allowed;
}

std::atomic<bool>& blockHeadsAllowed()
{
    static std::atomic<bool> allowed{true};
    return allowed;
}

unsigned int queryLimit(GLenum name)
{
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value > 0 ? static_cast<unsigned int>(value) : 0u;
}

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
class FinalBarrier : public osg::Camera::DrawCallback
{
public:
    void operator()(osg::RenderInfo& info) const override { memoryBarrier(info); }
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
                                   const std::string& name)
    : _grid(grid), _camera(new osg::Camera), _perspective(new osg::Uniform(shader::LIST_PERSPECTIVE, false))
{
    // Room for every triangle (with a margin for growth) and for about three triangles per
    // texel plus four texels per triangle.
    _triangleCapacity = static_cast<unsigned int>(std::min<std::size_t>(triangles + triangles / 4 + 64, 1u << 22));
    _nodeCapacity = static_cast<unsigned int>(
        std::min<std::size_t>(std::size_t(grid) * grid * 3 + std::size_t(_triangleCapacity) * 4, 1u << 24));
    _nodeCapacity += _nodeCapacity % 2; // the triangles start on a 16-byte boundary
    _buffer = new osg::UIntArray(trianglesOffset() + 12 * std::size_t(_triangleCapacity));
    osg::ref_ptr<osg::ShaderStorageBufferObject> sbo = new osg::ShaderStorageBufferObject;
    sbo->setUsage(GL_DYNAMIC_COPY);
    _buffer->setBufferObject(sbo.get());
    _imageView = new osg::TextureBuffer;
    _imageView->setInternalFormat(GL_RGBA32UI_EXT);
    _imageView->setBufferData(_buffer.get());

    osg::Camera& c = *_camera;
    c.setName(name);
    c.setReferenceFrame(osg::Camera::ABSOLUTE_RF);
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
    c.setFinalDrawCallback(new FinalBarrier);
    osg::StateSet* ss = c.getStateSet();
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    ss->setAttributeAndModes(new osg::ShaderStorageBufferBinding(0, _buffer.get(), 0, getBufferSize()), on);
    ss->addUniform(new osg::Uniform(shader::LIST_NODE_CAPACITY, _nodeCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_TRIANGLE_CAPACITY, _triangleCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_GRID_SIZE, osg::Vec2f(grid, grid)));
    ss->addUniform(_perspective.get());
    ss->addUniform(new osg::Uniform(shader::LIST_FRONT_ONLY, false));
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
    if (!imageReadsAllowed() || contextID >= limits.size() || limits[contextID].storageBlocks == 0) return false;
    return slots <= limits[contextID].imageUniforms && texels <= limits[contextID].bufferTexels;
}

bool TriangleListPass::blockHeadsFit(unsigned int contextID, unsigned int slots)
{
    auto& limits = contextLimits();
    if (!blockHeadsAllowed() || contextID >= limits.size() || limits[contextID].storageBlocks == 0) return false;
    return slots <= limits[contextID].storageBlocks && 2u * slots + 1u <= limits[contextID].outputResources;
}

void TriangleListPass::setBlockHeadsAllowed(bool allowed)
{
    blockHeadsAllowed() = allowed;
}

bool TriangleListPass::getBlockHeadsAllowed()
{
    return blockHeadsAllowed();
}

void TriangleListPass::setImageReadsAllowed(bool allowed)
{
    imageReadsAllowed() = allowed;
}

bool TriangleListPass::getImageReadsAllowed()
{
    return imageReadsAllowed();
}

std::size_t TriangleListPass::getBufferSize() const
{
    return _buffer->getTotalDataSize();
}

void TriangleListPass::cull(osgUtil::CullVisitor& cv, const LightFrustum& frustum, bool perspective)
{
    _camera->setViewMatrix(frustum.view);
    _camera->setProjectionMatrix(frustum.projection);
    _perspective->set(perspective);
    _camera->accept(cv);
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
