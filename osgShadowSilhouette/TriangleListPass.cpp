#include <osgShadowSilhouette/TriangleListPass>
#include <osgShadowSilhouette/ShaderConstants>

#include "ShaderSource.h"

#include <osg/BindImageTexture>
#include <osg/ColorMask>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/GLExtensions>
#include <osg/observer_ptr>
#include <osgUtil/CullVisitor>

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

/** Orders the list pass's image and buffer writes before what follows. */
class BarrierDrawable : public osg::Drawable
{
public:
    BarrierDrawable()
    {
        setUseDisplayList(false);
        setCullingActive(false);
    }
    BarrierDrawable(const BarrierDrawable& d, const osg::CopyOp& op) : osg::Drawable(d, op) {}
    META_Object(osgShadowSilhouette, BarrierDrawable);
    void drawImplementation(osg::RenderInfo& info) const override { memoryBarrier(info); }
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(-1, -1, -1, 1, 1, 1); }
};

/** Resets the node and triangle counts before the pass. A buffer update is ordered with the
 *  draws around it on every driver, where a shader write from the clear quad is not (tiled
 *  rasterizers run its tiles in parallel with the casters' fragments). */
class ResetCounts : public osg::Camera::DrawCallback
{
public:
    explicit ResetCounts(osg::BufferData* buffer) : _buffer(buffer) {}
    void operator()(osg::RenderInfo& info) const override
    {
        osg::ref_ptr<osg::BufferData> buffer;
        if (!_buffer.lock(buffer) || !buffer->getBufferObject()) return;
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        osg::GLBufferObject* gl = buffer->getBufferObject()->getOrCreateGLBufferObject(info.getContextID());
        if (!ext || !gl || !ext->glBufferSubData) return;
        if (gl->isDirty()) gl->compileBuffer(); // first use: uploads zeros
        const GLuint zeros[2] = {0, 0};
        ext->glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl->getGLObjectID());
        ext->glBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(gl->getOffset(buffer->getBufferIndex())), sizeof(zeros), zeros);
        ext->glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }

private:
    osg::observer_ptr<osg::BufferData> _buffer;
};

/** Makes the lists visible to the eye pass that reads them. */
class FinalBarrier : public osg::Camera::DrawCallback
{
public:
    void operator()(osg::RenderInfo& info) const override { memoryBarrier(info); }
};

/** A grid x grid R32UI texture, read with texelFetch and written as an image. */
osg::ref_ptr<osg::Texture2D> listImage(unsigned int grid)
{
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
    t->setTextureSize(grid, grid);
    t->setInternalFormat(GL_R32UI);
    t->setSourceFormat(GL_RED_INTEGER);
    t->setSourceType(GL_UNSIGNED_INT);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    return t;
}

osg::ref_ptr<osg::Program> program(const char* name, const char* vert, const char* geom, const char* frag)
{
    osg::ref_ptr<osg::Program> p = new osg::Program;
    p->setName(name);
    p->addShader(detail::loadShader(osg::Shader::VERTEX, vert));
    if (geom) p->addShader(detail::loadShader(osg::Shader::GEOMETRY, geom));
    p->addShader(detail::loadShader(osg::Shader::FRAGMENT, frag));
    return p;
}

/** The clear pass: a quad over the whole grid (render bin -2), then a memory barrier (bin
 *  -1), both before the casters. */
osg::ref_ptr<osg::Group> createClearPass()
{
    osg::ref_ptr<osg::Geometry> quad = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(-1, -1, 0));
    v->push_back(osg::Vec3(1, -1, 0));
    v->push_back(osg::Vec3(-1, 1, 0));
    v->push_back(osg::Vec3(1, 1, 0));
    quad->setVertexArray(v.get());
    quad->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4));
    quad->setCullingActive(false);
    quad->setUseDisplayList(false);
    quad->setUseVertexBufferObjects(true);
    osg::ref_ptr<osg::Geode> clear = new osg::Geode;
    clear->setCullingActive(false);
    clear->addDrawable(quad.get());
    osg::StateSet* ss = clear->getOrCreateStateSet();
    ss->setRenderBinDetails(-2, "RenderBin");
    ss->setAttributeAndModes(program("osgShadowSilhouette triangle-list clear", shader::FILE_TRILIST_CLEAR_VERT, nullptr,
                                     shader::FILE_TRILIST_CLEAR_FRAG),
                             osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED);

    osg::ref_ptr<osg::Geode> barrier = new osg::Geode;
    barrier->setCullingActive(false);
    barrier->addDrawable(new BarrierDrawable);
    barrier->getOrCreateStateSet()->setRenderBinDetails(-1, "RenderBin");

    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->setCullingActive(false);
    group->addChild(clear.get());
    group->addChild(barrier.get());
    return group;
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
    _buffer = new osg::UIntArray(4 + 2 * std::size_t(_nodeCapacity) + 12 * std::size_t(_triangleCapacity));
    osg::ref_ptr<osg::ShaderStorageBufferObject> sbo = new osg::ShaderStorageBufferObject;
    sbo->setUsage(GL_DYNAMIC_COPY);
    _buffer->setBufferObject(sbo.get());

    _heads = listImage(grid);
    _counts = listImage(grid);

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
    c.setInitialDrawCallback(new ResetCounts(_buffer.get()));
    c.setFinalDrawCallback(new FinalBarrier);
    osg::StateSet* ss = c.getStateSet();
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    ss->setAttribute(new osg::BindImageTexture(0, _heads.get(), osg::BindImageTexture::READ_WRITE, GL_R32UI), on);
    ss->setAttribute(new osg::BindImageTexture(1, _counts.get(), osg::BindImageTexture::READ_WRITE, GL_R32UI), on);
    ss->setAttributeAndModes(new osg::ShaderStorageBufferBinding(0, _buffer.get(), 0, getBufferSize()), on);
    ss->addUniform(new osg::Uniform(shader::LIST_NODE_CAPACITY, _nodeCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_TRIANGLE_CAPACITY, _triangleCapacity));
    ss->addUniform(new osg::Uniform(shader::LIST_GRID_SIZE, osg::Vec2f(grid, grid)));
    ss->addUniform(_perspective.get());
    c.addChild(createClearPass().get());
}

TriangleListPass::~TriangleListPass() = default;

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
    _heads->resizeGLObjectBuffers(maxSize);
    _counts->resizeGLObjectBuffers(maxSize);
    if (_buffer->getBufferObject()) _buffer->getBufferObject()->resizeGLObjectBuffers(maxSize);
}

void TriangleListPass::releaseGLObjects(osg::State* state) const
{
    _camera->releaseGLObjects(state);
    _heads->releaseGLObjects(state);
    _counts->releaseGLObjects(state);
    if (_buffer->getBufferObject()) _buffer->getBufferObject()->releaseGLObjects(state);
}

} // namespace osgShadowSilhouette
