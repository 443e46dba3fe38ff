#include <osgShadowSilhouette/SilhouetteMapPass>
#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouettePoints>

#include "GpuEdges.h"
#include "ShaderSource.h"

#include <osg/BlendEquation>
#include <osg/GLExtensions>
#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Image>
#include <osg/PolygonMode>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <cstring>

namespace osgShadowSilhouette {

namespace {

osg::ref_ptr<osg::Texture2D> nearestTexture(GLint internalFormat, GLenum format, GLenum type,
                                            osg::Texture::WrapMode wrap)
{
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
    t->setInternalFormat(internalFormat);
    t->setSourceFormat(format);
    t->setSourceType(type);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, wrap);
    t->setWrap(osg::Texture::WRAP_T, wrap);
    return t;
}

osg::ref_ptr<osg::Texture2D> silhouetteTexture()
{
    // Outside: the default point.
    osg::ref_ptr<osg::Texture2D> t = nearestTexture(GL_R32F, GL_RED, GL_FLOAT, osg::Texture::CLAMP_TO_BORDER);
    const double centre = defaultSilhouetteValue();
    t->setBorderColor(osg::Vec4d(centre, centre, centre, centre));
    return t;
}

osg::ref_ptr<osg::Texture2D> neighbourhoodTexture()
{
    // Read with texelFetch only, clamped by the shader.
    return nearestTexture(GL_RGBA32UI_EXT, GL_RGBA_INTEGER_EXT, GL_UNSIGNED_INT, osg::Texture::CLAMP_TO_EDGE);
}

/** Clears the bound colour buffer 0 to the default neighbourhood: integer buffers cannot be
 *  cleared with glClear (the result is undefined), so the neighbourhood camera draws this
 *  first (render bin -1) instead of clearing. */
class ClearNeighbourhood : public osg::Drawable
{
    using ClearBufferuiv = void(GL_APIENTRY*)(GLenum, GLint, const GLuint*);

public:
    ClearNeighbourhood()
    {
        setSupportsDisplayList(false);
        setCullingActive(false);
        setName("osgShadowSilhouette clear neighbourhood map");
    }

    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(0, 0, 0, 0, 0, 0); }

    void drawImplementation(osg::RenderInfo& renderInfo) const override
    {
        const unsigned int id = renderInfo.getContextID();
        if (id >= _clear.size()) _clear.resize(id + 1, nullptr);
        if (!_clear[id])
        {
            osg::setGLExtensionFuncPtr(_clear[id], "glClearBufferuiv");
            if (!_clear[id])
            {
                OSG_WARN << "osgShadowSilhouette: glClearBufferuiv is missing (OpenGL 3.0); the silhouette "
                            "map's neighbourhood map is not cleared" << std::endl;
                return;
            }
        }
        const std::array<std::uint32_t, 4> value = defaultNeighbourhood();
        _clear[id](GL_COLOR, 0, value.data());
    }

private:
    mutable std::vector<ClearBufferuiv> _clear;
};

} // namespace

/** The GPU's edges (setGpuEdges()): per map the state of their draws, and this cull's casters
 *  and light. */
struct SilhouetteMapPass::GpuEdgePasses
{
    osg::ref_ptr<detail::GpuEdges> gpu;
    CullCasters cullCasters;
    osg::ref_ptr<osg::Uniform> light = new osg::Uniform(shader::GPU_EDGE_LIGHT, osg::Vec4f());
    osg::ref_ptr<osg::StateSet> passes[detail::GpuEdges::MAP_COUNT];
    std::vector<Caster> casters; ///< empty: the GPU takes none of this cull's casters
    detail::GpuEdges::TakenCasters taken; ///< those of `casters` it takes, by drawable
    osg::Matrixd view;
};

/** An edge camera's cull callback: its own children (the CPU's edge lines), then the GPU's. */
class SilhouetteMapPass::GpuEdgesCallback : public osg::NodeCallback
{
public:
    GpuEdgesCallback(SilhouetteMapPass& pass, int map) : _pass(pass), _map(map) {}
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        traverse(node, nv);
        if (osgUtil::CullVisitor* cv = nv->asCullVisitor()) _pass.cullGpuEdges(*cv, _map);
    }

private:
    SilhouetteMapPass& _pass; ///< owns the camera
    int _map;
};

namespace {

/** What of a caster's own state the edges found on the GPU (drawn under the caster's state
 *  sets, GpuEdges) must not take: its alpha, stencil and scissor tests, polygon mode and
 *  colour mask (the texture on unit 0, the map the stages read, each camera binds
 *  `OVERRIDE`). */
void overrideCasterState(osg::StateSet& ss)
{
    const auto off = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE;
    for (GLenum mode : {GLenum(GL_ALPHA_TEST), GLenum(GL_STENCIL_TEST), GLenum(GL_SCISSOR_TEST)}) ss.setMode(mode, off);
    ss.setAttribute(new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::FILL),
                    osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    ss.setAttribute(new osg::ColorMask(true, true, true, true),
                    osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
}

/** The state of a pass over the edge lines: the silhouette-map vertex and geometry stages with
 *  fragment stage `fragment`; no depth test, culling, blending or lighting. */
osg::ref_ptr<osg::StateSet> edgePassState(const char* name, const char* fragment)
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(name);
    program->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_SILMAP_VERT));
    program->addShader(detail::loadShader(osg::Shader::GEOMETRY, shader::FILE_SILMAP_GEOM));
    program->addShader(detail::loadShader(osg::Shader::FRAGMENT, fragment));
    ss->setAttributeAndModes(program.get(), osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    for (GLenum mode : {GLenum(GL_DEPTH_TEST), GLenum(GL_CULL_FACE), GLenum(GL_BLEND), GLenum(GL_LIGHTING)})
        ss->setMode(mode, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    overrideCasterState(*ss);
    return ss;
}

} // namespace

osg::ref_ptr<osg::StateSet> SilhouetteMapPass::createSharedStateSet()
{
    osg::ref_ptr<osg::StateSet> ss = edgePassState("osgShadowSilhouette silhouette map", shader::FILE_SILMAP_FRAG);
    ss->addUniform(new osg::Uniform(shader::SILMAP_DEPTH, 0));
    ss->addUniform(new osg::Uniform(shader::SILMAP_DEPTH_BIAS, shader::SILMAP_DEFAULT_DEPTH_BIAS));
    // The neighbourhood pass: the same edges, widened, packing each texel's five points.
    osg::ref_ptr<osg::StateSet> nbr =
        edgePassState("osgShadowSilhouette silhouette neighbourhood map", shader::FILE_SILNBR_FRAG);
    nbr->setDefine(shader::DEFINE_SILMAP_NEIGHBOURHOOD);
    nbr->addUniform(new osg::Uniform(shader::SILMAP_POINTS, 0));
    ss->setUserData(nbr.get());
    return ss;
}

osg::ref_ptr<osg::StateSet> SilhouetteMapPass::createDistanceStateSet()
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("osgShadowSilhouette silhouette distance map");
    program->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_SILMAP_VERT));
    program->addShader(detail::loadShader(osg::Shader::GEOMETRY, shader::FILE_SILMAP_GEOM));
    program->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SILDIST_FRAG));
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    ss->setAttributeAndModes(program.get(), overrideOn);
    ss->setDefine(shader::DEFINE_SILMAP_DISTANCE);
    // The nearest edge per texel wins: the fragment's depth is its distance over the width.
    ss->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), overrideOn);
    for (GLenum mode : {GLenum(GL_CULL_FACE), GLenum(GL_BLEND), GLenum(GL_LIGHTING)})
        ss->setMode(mode, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    overrideCasterState(*ss);
    return ss;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createDefaultDistanceTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_RG, GL_FLOAT);
    image->setInternalTextureFormat(GL_RG32F);
    float* texel = reinterpret_cast<float*>(image->data());
    texel[0] = shader::SILDIST_NO_EDGE;
    texel[1] = 1.0f;
    osg::ref_ptr<osg::Texture2D> t = nearestTexture(GL_RG32F, GL_RG, GL_FLOAT, osg::Texture::CLAMP_TO_BORDER);
    t->setBorderColor(osg::Vec4d(shader::SILDIST_NO_EDGE, 1.0, 0.0, 0.0));
    t->setImage(image.get());
    return t;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createTexture(unsigned int size)
{
    osg::ref_ptr<osg::Texture2D> t = silhouetteTexture();
    t->setTextureSize(size, size);
    return t;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createDefaultTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_RED, GL_FLOAT);
    *reinterpret_cast<float*>(image->data()) = defaultSilhouetteValue();
    osg::ref_ptr<osg::Texture2D> t = silhouetteTexture();
    t->setImage(image.get());
    return t;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createNeighbourhoodTexture(unsigned int size)
{
    osg::ref_ptr<osg::Texture2D> t = neighbourhoodTexture();
    t->setTextureSize(size + 1, size + 1);
    return t;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createDefaultNeighbourhoodTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_RGBA_INTEGER_EXT, GL_UNSIGNED_INT);
    image->setInternalTextureFormat(GL_RGBA32UI_EXT);
    const std::array<std::uint32_t, 4> value = defaultNeighbourhood();
    std::memcpy(image->data(), value.data(), sizeof(value));
    osg::ref_ptr<osg::Texture2D> t = neighbourhoodTexture();
    t->setImage(image.get());
    return t;
}

osg::ref_ptr<osg::Texture2D> SilhouetteMapPass::createLitDepthTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT);
    *reinterpret_cast<float*>(image->data()) = 1.0f;
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D(image.get());
    t->setInternalFormat(GL_DEPTH_COMPONENT24);
    t->setShadowComparison(false);
    t->setShadowTextureMode(osg::Texture::LUMINANCE);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    t->setBorderColor(osg::Vec4d(1.0, 1.0, 1.0, 1.0));
    return t;
}

SilhouetteMapPass::SilhouetteMapPass(unsigned int mapSize, const osg::StateSet& shared, const std::string& name)
    : _mapSize(mapSize), _texture(createTexture(mapSize)), _camera(new osg::Camera), _edges(new CasterEdges)
{
    osg::Camera& c = *_camera;
    c.setName(name);
    addGpuEdges(c, detail::GpuEdges::POINTS);
    c.setRenderOrder(osg::Camera::PRE_RENDER, 1); // after the depth pass it reads
    c.setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    c.setImplicitBufferAttachmentMask(0, 0);     // colour only: no depth or stencil buffer
    c.setComputeNearFarMode(osg::Camera::DO_NOT_COMPUTE_NEAR_FAR);
    c.setCullingMode(osg::CullSettings::NO_CULLING);
    c.setClearMask(GL_COLOR_BUFFER_BIT);
    c.setClearColor(osg::Vec4(defaultSilhouetteValue(), 0.0f, 0.0f, 0.0f)); // every texel: its centre
    // Camera::setViewport() stores the viewport in the camera's StateSet: own copy first.
    c.setStateSet(new osg::StateSet(shared, osg::CopyOp::SHALLOW_COPY));
    c.setViewport(0, 0, mapSize, mapSize);
    c.setViewMatrix(osg::Matrixd::identity()); // the edges are already in light view space
    c.attach(osg::Camera::COLOR_BUFFER, _texture.get());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setCullingActive(false);
    geode->addDrawable(_edges->getLines());
    c.addChild(geode.get());
    _neighbourhoodShared = dynamic_cast<const osg::StateSet*>(shared.getUserData());
}

void SilhouetteMapPass::createNeighbourhoodPass()
{
    _neighbourhoodTexture = createNeighbourhoodTexture(_mapSize);
    _neighbourhoodCamera = new osg::Camera;
    osg::Camera& c = *_neighbourhoodCamera;
    c.setName(_camera->getName() + " neighbourhood");
    addGpuEdges(c, detail::GpuEdges::NEIGHBOURHOOD);
    c.setRenderOrder(osg::Camera::PRE_RENDER, 2); // after the silhouette map it reads
    c.setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    c.setImplicitBufferAttachmentMask(0, 0);
    c.setComputeNearFarMode(osg::Camera::DO_NOT_COMPUTE_NEAR_FAR);
    c.setCullingMode(osg::CullSettings::NO_CULLING);
    c.setClearMask(0); // ClearNeighbourhood clears the integer buffer
    c.setStateSet(_neighbourhoodShared ? new osg::StateSet(*_neighbourhoodShared, osg::CopyOp::SHALLOW_COPY)
                                       : new osg::StateSet);
    // OVERRIDE: the casters' own textures on unit 0 do not replace it under the GPU's edges.
    c.getStateSet()->setTextureAttributeAndModes(0, _texture.get(),
                                                 osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    c.setViewport(0, 0, _mapSize + 1, _mapSize + 1);
    c.setViewMatrix(osg::Matrixd::identity());
    c.attach(osg::Camera::COLOR_BUFFER, _neighbourhoodTexture.get());
    osg::ref_ptr<osg::Geode> clear = new osg::Geode;
    clear->setCullingActive(false);
    clear->getOrCreateStateSet()->setRenderBinDetails(-1, "RenderBin");
    clear->addDrawable(new ClearNeighbourhood);
    c.addChild(clear.get());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setCullingActive(false);
    geode->addDrawable(_edges->getLines());
    c.addChild(geode.get());
}

void SilhouetteMapPass::createDistancePass(const osg::StateSet& shared)
{
    _distanceTexture = nearestTexture(GL_RG32F, GL_RG, GL_FLOAT, osg::Texture::CLAMP_TO_BORDER);
    _distanceTexture->setBorderColor(osg::Vec4d(shader::SILDIST_NO_EDGE, 1.0, 0.0, 0.0));
    _distanceTexture->setTextureSize(_mapSize, _mapSize);
    _distanceCamera = new osg::Camera;
    osg::Camera& c = *_distanceCamera;
    c.setName(_camera->getName() + " distances");
    addGpuEdges(c, detail::GpuEdges::DISTANCES);
    c.setRenderOrder(osg::Camera::PRE_RENDER, 1); // after the depth pass
    c.setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    c.setComputeNearFarMode(osg::Camera::DO_NOT_COMPUTE_NEAR_FAR);
    c.setCullingMode(osg::CullSettings::NO_CULLING);
    c.setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    c.setClearColor(osg::Vec4(shader::SILDIST_NO_EDGE, 1.0f, 0.0f, 0.0f));
    c.setClearDepth(1.0);
    c.setStateSet(new osg::StateSet(shared, osg::CopyOp::SHALLOW_COPY));
    _distanceWidthUniform = new osg::Uniform(shader::SILDIST_WIDTH, shader::SILDIST_MIN_WIDTH);
    c.getStateSet()->addUniform(_distanceWidthUniform.get());
    c.getStateSet()->addUniform(new osg::Uniform(shader::SILDIST_SIZE, osg::Vec2f(float(_mapSize), float(_mapSize))));
    c.setViewport(0, 0, _mapSize, _mapSize);
    c.setViewMatrix(osg::Matrixd::identity());
    c.attach(osg::Camera::COLOR_BUFFER, _distanceTexture.get());
    c.attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setCullingActive(false);
    geode->addDrawable(_edges->getLines());
    c.addChild(geode.get());
}

void SilhouetteMapPass::cullDistanceMap(osgUtil::CullVisitor& cv, const LightFrustum& frustum,
                                        const osg::StateSet& shared, float width, const std::vector<Caster>& casters,
                                        const osg::Vec4d& light)
{
    _extractionSkipped = !updateEdges(casters, light, frustum);
    _edges->writeLines(frustum.view);
    if (!_distanceCamera) createDistancePass(shared);
    _drewDistances = true;
    _distanceWidth = width;
    _distanceWidthUniform->set(width);
    _distanceCamera->setProjectionMatrix(frustum.projection);
    _distanceCamera->accept(cv);
}

SilhouetteMapPass::~SilhouetteMapPass() = default;

void SilhouetteMapPass::addGpuEdges(osg::Camera& camera, int map)
{
    // The view's eye chooses the LODs, as in the depth pass (the edges' camera has no view).
    camera.setReferenceFrame(osg::Camera::ABSOLUTE_RF_INHERIT_VIEWPOINT);
    camera.setCullCallback(new GpuEdgesCallback(*this, map));
}

void SilhouetteMapPass::setGpuEdges(detail::GpuEdges* gpu, CullCasters cullCasters)
{
    if (!gpu)
    {
        _gpu.reset();
        return;
    }
    if (!_gpu || _gpu->gpu != gpu)
    {
        _gpu.reset(new GpuEdgePasses);
        _gpu->gpu = gpu;
    }
    _gpu->cullCasters = std::move(cullCasters);
}

bool SilhouetteMapPass::updateEdges(const std::vector<Caster>& casters, const osg::Vec4d& light,
                                    const LightFrustum& frustum)
{
    if (_gpu)
    {
        _gpu->casters.clear();
        _gpu->taken.clear();
    }
    if (!_gpu || !_gpu->gpu->takesAny(casters)) return _edges->update(casters, light);
    _gpu->casters = casters;
    _gpu->taken = _gpu->gpu->takenByDrawable(_gpu->casters); // once for every map of the light
    _gpu->view = frustum.view;
    osg::Vec4d viewLight = light * frustum.view;
    if (viewLight.w() != 0.0) viewLight /= viewLight.w();
    _gpu->light->set(osg::Vec4f(viewLight));
    return _edges->update(_gpu->gpu->getAllCasters() ? _gpu->gpu->leftToCpu(casters) : casters, light);
}

void SilhouetteMapPass::cullGpuEdges(osgUtil::CullVisitor& cv, int map)
{
    if (!_gpu || _gpu->casters.empty()) return;
    osg::ref_ptr<osg::StateSet>& pass = _gpu->passes[map];
    if (!pass) pass = _gpu->gpu->createPass(detail::GpuEdges::Map(map), _gpu->light.get());
    _gpu->gpu->cull(cv, *pass, _gpu->view, _gpu->taken, _gpu->cullCasters);
}

void SilhouetteMapPass::setDepthComparison(bool compare)
{
    if (compare == _depthComparison) return;
    _depthComparison = compare;
    osg::StateSet* ss = _camera->getStateSet();
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    if (compare)
    {
        // HYBRID's edge mask: each texel keeps the nearest edge depth (the clear value, the
        // default point, is far beyond any depth in [0, 1]).
        ss->setDefine(shader::DEFINE_SILMAP_COMPARE);
        ss->setAttributeAndModes(new osg::BlendEquation(osg::BlendEquation::RGBA_MIN), overrideOn);
        ss->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE), overrideOn);
    }
    else
    {
        ss->removeDefine(shader::DEFINE_SILMAP_COMPARE);
        ss->removeAttribute(osg::StateAttribute::BLENDEQUATION);
        ss->removeAttribute(osg::StateAttribute::BLENDFUNC);
        ss->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    }
}

void SilhouetteMapPass::cull(osgUtil::CullVisitor& cv, const LightFrustum& frustum, osg::Texture2D* depthTexture,
                             const std::vector<Caster>& casters, const osg::Vec4d& light)
{
    _extractionSkipped = !updateEdges(casters, light, frustum);
    _edges->writeLines(frustum.view);
    _drewDistances = false;
    _camera->setProjectionMatrix(frustum.projection);
    osg::StateSet* ss = _camera->getStateSet();
    if (ss->getTextureAttribute(0, osg::StateAttribute::TEXTURE) != depthTexture)
        ss->setTextureAttributeAndModes(0, depthTexture, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    _camera->accept(cv);
    if (_depthComparison) return; // HYBRID's edge mask reads the map itself
    if (!_neighbourhoodCamera) createNeighbourhoodPass();
    _neighbourhoodCamera->setProjectionMatrix(frustum.projection);
    _neighbourhoodCamera->accept(cv);
}

osg::Texture2D* SilhouetteMapPass::getNeighbourhoodTexture()
{
    if (!_neighbourhoodCamera) createNeighbourhoodPass();
    return _neighbourhoodTexture.get();
}

osg::Camera* SilhouetteMapPass::getNeighbourhoodCamera()
{
    if (!_neighbourhoodCamera) createNeighbourhoodPass();
    return _neighbourhoodCamera.get();
}

void SilhouetteMapPass::resizeGLObjectBuffers(unsigned int maxSize)
{
    _camera->resizeGLObjectBuffers(maxSize);
    _texture->resizeGLObjectBuffers(maxSize);
    if (_neighbourhoodCamera) _neighbourhoodCamera->resizeGLObjectBuffers(maxSize);
    if (_neighbourhoodTexture) _neighbourhoodTexture->resizeGLObjectBuffers(maxSize);
    if (_distanceCamera) _distanceCamera->resizeGLObjectBuffers(maxSize);
    if (_distanceTexture) _distanceTexture->resizeGLObjectBuffers(maxSize);
}

void SilhouetteMapPass::releaseGLObjects(osg::State* state) const
{
    _camera->releaseGLObjects(state);
    _texture->releaseGLObjects(state);
    if (_neighbourhoodCamera) _neighbourhoodCamera->releaseGLObjects(state);
    if (_neighbourhoodTexture) _neighbourhoodTexture->releaseGLObjects(state);
    if (_distanceCamera) _distanceCamera->releaseGLObjects(state);
    if (_distanceTexture) _distanceTexture->releaseGLObjects(state);
}

} // namespace osgShadowSilhouette
