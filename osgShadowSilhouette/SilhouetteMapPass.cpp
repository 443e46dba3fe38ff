#include <osgShadowSilhouette/SilhouetteMapPass>
#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouettePoints>

#include "ShaderSource.h"

#include <osg/BlendEquation>
#include <osg/BlendFunc>
#include <osg/Geode>
#include <osg/Image>
#include <osgUtil/CullVisitor>

namespace osgShadowSilhouette {

namespace {

osg::ref_ptr<osg::Texture2D> silhouetteTexture()
{
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
    t->setInternalFormat(GL_R32F);
    t->setSourceFormat(GL_RED);
    t->setSourceType(GL_FLOAT);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER); // outside: the default point
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    const double centre = defaultSilhouetteValue();
    t->setBorderColor(osg::Vec4d(centre, centre, centre, centre));
    return t;
}

} // namespace

osg::ref_ptr<osg::StateSet> SilhouetteMapPass::createSharedStateSet()
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    const auto overrideOff = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("osgShadowSilhouette silhouette map");
    program->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_SILMAP_VERT));
    program->addShader(detail::loadShader(osg::Shader::GEOMETRY, shader::FILE_SILMAP_GEOM));
    program->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SILMAP_FRAG));
    ss->setAttributeAndModes(program.get(), overrideOn);
    ss->addUniform(new osg::Uniform(shader::SILMAP_DEPTH, 0));
    ss->addUniform(new osg::Uniform(shader::SILMAP_DEPTH_BIAS, shader::SILMAP_DEFAULT_DEPTH_BIAS));
    for (GLenum mode : {GLenum(GL_DEPTH_TEST), GLenum(GL_CULL_FACE), GLenum(GL_BLEND), GLenum(GL_LIGHTING)})
        ss->setMode(mode, overrideOff);
    return ss;
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
    c.setReferenceFrame(osg::Camera::ABSOLUTE_RF);
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
}

SilhouetteMapPass::~SilhouetteMapPass() = default;

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
    _extractionSkipped = !_edges->update(casters, light);
    _edges->writeLines(frustum.view);
    _camera->setProjectionMatrix(frustum.projection);
    osg::StateSet* ss = _camera->getStateSet();
    if (ss->getTextureAttribute(0, osg::StateAttribute::TEXTURE) != depthTexture)
        ss->setTextureAttributeAndModes(0, depthTexture, osg::StateAttribute::ON);
    _camera->accept(cv);
}

void SilhouetteMapPass::resizeGLObjectBuffers(unsigned int maxSize)
{
    _camera->resizeGLObjectBuffers(maxSize);
    _texture->resizeGLObjectBuffers(maxSize);
}

void SilhouetteMapPass::releaseGLObjects(osg::State* state) const
{
    _camera->releaseGLObjects(state);
    _texture->releaseGLObjects(state);
}

} // namespace osgShadowSilhouette
