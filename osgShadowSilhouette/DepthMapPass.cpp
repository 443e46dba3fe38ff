#include "DepthMapPass.h"
#include "RenderLeaves.h"
#include "ShaderSource.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Image>
#include <osg/PolygonOffset>

namespace osgShadowSilhouette {
namespace detail {

namespace {

/** A slot's depth camera and texture. */
LightPass createLightPass(unsigned int slot, unsigned int mapSize, const osg::StateSet& depthPassState,
                          osgShadow::ShadowedScene* scene)
{
    LightPass pass;
    pass.depthTexture = createDepthTexture(mapSize);
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    camera->setName("osgShadowSilhouette depth pass " + std::to_string(slot));
    // The view's eye point for LODs by distance (as osgShadow's techniques do); billboards
    // are turned after the cull (turnBillboardLeaves).
    camera->setReferenceFrame(osg::Camera::ABSOLUTE_RF_INHERIT_VIEWPOINT);
    camera->setRenderOrder(osg::Camera::PRE_RENDER);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->setComputeNearFarMode(osg::Camera::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setCullingMode(camera->getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    camera->setClearMask(GL_DEPTH_BUFFER_BIT);
    // Camera::setViewport() stores the viewport in the camera's StateSet: give each camera
    // its own (shallow) copy of the shared depth-pass state before setting it.
    camera->setStateSet(new osg::StateSet(depthPassState, osg::CopyOp::SHALLOW_COPY));
    camera->setViewport(0, 0, mapSize, mapSize);
    camera->setDrawBuffer(GL_NONE);
    camera->setReadBuffer(GL_NONE);
    camera->attach(osg::Camera::DEPTH_BUFFER, pass.depthTexture.get());
    camera->setCullCallback(new TraverseShadowedSceneCallback(scene));
    pass.samples = new DrawnSamples;
    camera->setInitialDrawCallback(pass.samples->createBegin());
    camera->setFinalDrawCallback(pass.samples->createEnd());
    pass.depthCamera = camera;
    return pass;
}

/** The depth camera draws @p queries (or nothing) besides the casters; its sample query, which
 *  finds cube faces with nothing to shadow, runs only without them (one query at a time). */
void drawQueries(LightPass& pass, osg::Node* queries)
{
    if (!queries) pass.blockers = nullptr;
    pass.samples->setEnabled(!queries && pass.frustum.faceCore > 0.0); // only faces skip
    if (pass.depthCamera->getNumChildren() != (queries ? 1u : 0u) ||
        (queries && pass.depthCamera->getChild(0) != queries))
    {
        pass.depthCamera->removeChildren(0, pass.depthCamera->getNumChildren());
        if (queries) pass.depthCamera->addChild(queries);
    }
}

/** Culls the depth camera of one slot for pass.frustum, under the casts mask. */
void cullDepthPass(osgUtil::CullVisitor& cv, LightPass& pass, const osgShadow::ShadowedScene& scene)
{
    pass.depthCamera->setViewMatrix(pass.frustum.view);
    pass.depthCamera->setProjectionMatrix(pass.frustum.projection);
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(mask & scene.getShadowSettings()->getCastsShadowTraversalMask());
    pass.samples->culled(); // one more build to count (or the blocker queries alone: not empty)
    pass.depthCamera->accept(cv);
    cv.setTraversalMask(mask);
}

} // namespace

osg::ref_ptr<osg::Texture2D> createDepthTexture(unsigned int size)
{
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
    t->setTextureSize(size, size);
    t->setInternalFormat(GL_DEPTH_COMPONENT24);
    t->setSourceFormat(GL_DEPTH_COMPONENT);
    t->setSourceType(GL_FLOAT);
    t->setShadowComparison(true);
    t->setShadowCompareFunc(osg::Texture::LEQUAL);
    t->setShadowTextureMode(osg::Texture::LUMINANCE);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR); // 2x2 hardware PCF
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    t->setBorderColor(osg::Vec4d(1.0, 1.0, 1.0, 1.0)); // outside the map: lit
    return t;
}

/** A 1x1 depth texture at the far plane: every lookup is lit. Bound to unused shadow slots. */
osg::ref_ptr<osg::Texture2D> createLitTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT);
    *reinterpret_cast<float*>(image->data()) = 1.0f;
    osg::ref_ptr<osg::Texture2D> t = createDepthTexture(1);
    t->setImage(image.get());
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    return t;
}

osg::ref_ptr<osg::StateSet> createDepthPassStateSet(float polygonOffsetFactor, float polygonOffsetUnits)
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("osgShadowSilhouette depth");
    program->addShader(loadShader(osg::Shader::VERTEX, shader::FILE_DEPTH_VERT));
    program->addShader(loadShader(osg::Shader::FRAGMENT, shader::FILE_DEPTH_FRAG));
    ss->setAttributeAndModes(program.get(), overrideOn);
    ss->setAttributeAndModes(new osg::PolygonOffset(polygonOffsetFactor, polygonOffsetUnits), overrideOn);
    ss->setAttribute(new osg::ColorMask(false, false, false, false), overrideOn);
    // A caster's own osg::Depth (a blended pane that writes no depth, a decal's ALWAYS)
    // is the eye's business: every caster writes its depth into the map, as the reference
    // and the volumes take every triangle as opaque.
    ss->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), overrideOn);
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE); // open casters too
    ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    ss->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    ss->addUniform(new osg::Uniform(shader::BASE_TEXTURE, 0)); // alpha-tested casters' cut-outs
    return ss;
}

void fitDepthMap(LightPass& pass, unsigned int slot, unsigned int mapSize, bool rawDepth,
                 const osg::StateSet& depthPassState, osgShadow::ShadowedScene* scene)
{
    if (pass.depthCamera && pass.depthTexture->getTextureWidth() == int(mapSize) &&
        pass.depthTexture->getShadowComparison() != rawDepth)
        return;
    pass = createLightPass(slot, mapSize, depthPassState, scene);
    pass.depthTexture->setShadowComparison(!rawDepth);
}

bool cullDepthMap(ModeFrame& mf, ModePass& mode, LightPass& pass, const LightDescription& light)
{
    drawQueries(pass, mode.depthPassQueries(mf, pass));
    const FrameContext& frame = mf.frame;
    PassInputs inputs;
    inputs.valid = true;
    inputs.glGeneration = mf.settings.glGeneration;
    inputs.mode = frame.mode;
    inputs.casters = frame.casterSignature;
    inputs.view = pass.frustum.view;
    inputs.projection = pass.frustum.projection;
    inputs.light = light.homogeneous();
    inputs.polygonOffsetFactor =
        pass.frustum.warped ? mf.settings.warpedPolygonOffsetFactor : mf.settings.polygonOffsetFactor;
    inputs.gpuExtraction = mf.settings.gpuExtraction;
    const bool reuse = inputs == pass.rendered && mode.keepsSlotPasses(pass, mf.settings);
    if (auto* scene = dynamic_cast<TraverseShadowedSceneCallback*>(pass.depthCamera->getCullCallback()))
    {
        scene->setCasters(!reuse);
        scene->setCasterStages(mf.settings.casterStages);
        scene->setSplitFaces(mf.settings.listedDrawables);
        scene->setExcluded(frame.nonFinite);
        scene->setBillboards(frame.billboards);
    }
    pass.depthCamera->setClearMask(reuse ? 0 : GL_DEPTH_BUFFER_BIT);
    if (reuse)
    {
        if (pass.depthCamera->getNumChildren() > 0)
            cullDepthPass(mf.cv, pass, *mf.settings.shadowedScene); // the blocker queries alone
        ++mf.stats.depthPassesReused;
        ++mf.stats.shadowPasses; // in use, kept from an earlier frame
        return false;
    }
    const float factor = inputs.polygonOffsetFactor;
    osg::StateSet* depthState = pass.depthCamera->getStateSet(); // the pass's own (shallow) copy
    const auto* offset =
        dynamic_cast<const osg::PolygonOffset*>(depthState->getAttribute(osg::StateAttribute::POLYGONOFFSET));
    const float units = mf.settings.polygonOffsetUnits;
    if (!offset || offset->getFactor() != factor || offset->getUnits() != units)
        depthState->setAttributeAndModes(new osg::PolygonOffset(factor, units),
                                         osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    cullDepthPass(mf.cv, pass, *mf.settings.shadowedScene);
    ++mf.stats.shadowPasses;
    pass.rendered = inputs;
    return true;
}

} // namespace detail
} // namespace osgShadowSilhouette
