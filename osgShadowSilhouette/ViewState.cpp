#include "ViewState.h"

#include "RenderLeaves.h"
#include "SoftFilter.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/Depth>
#include <osgUtil/RenderStage>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

namespace {

/** The lights' uniforms: their count, GL numbers and shadow slots, and per slot its
 *  eye-to-shadow matrix, owner light, cube-face core and PCSS's penumbra scale. */
void createLightUniforms(ViewData& vd, unsigned int slots)
{
    vd.numLights = new osg::Uniform(shader::NUM_LIGHTS, 0);
    vd.lightIndex = new osg::Uniform(osg::Uniform::INT, shader::LIGHT_INDEX, shader::MAX_SCENE_LIGHTS);
    vd.shadowSlot = new osg::Uniform(osg::Uniform::INT, shader::SHADOW_SLOT, shader::MAX_SCENE_LIGHTS);
    vd.eyeToShadow = new osg::Uniform(osg::Uniform::FLOAT_MAT4, shader::EYE_TO_SHADOW, slots);
    vd.slotOwner = new osg::Uniform(osg::Uniform::INT, shader::SLOT_OWNER, slots);
    vd.slotCore = new osg::Uniform(osg::Uniform::FLOAT, shader::SLOT_CORE, slots);
    vd.slotDepths = new osg::Uniform(osg::Uniform::FLOAT_VEC2, shader::SLOT_DEPTHS, slots);
    vd.filterScale = new osg::Uniform(osg::Uniform::FLOAT_VEC2, shader::FILTER_SCALE, slots);
    vd.maskLight = new osg::Uniform(shader::MASK_LIGHT, 0);
    for (int i = 0; i < shader::MAX_SCENE_LIGHTS; ++i)
    {
        vd.lightIndex->setElement(i, i);
        vd.shadowSlot->setElement(i, -1);
    }
}

/** HYBRID's triangle lists: per slot its capacities and projection, and the frames of the
 *  shadow rays' offset and of the lookups' bias. */
void createListUniforms(ViewData& vd, unsigned int slots)
{
    // Triangle lists (HYBRID): per slot its capacities and projection; the buffers are bound
    // per frame, one shader storage block per slot in use (OSS_MAX_LIST_SLOTS, set in cull).
    vd.listCapacity = new osg::Uniform(osg::Uniform::UNSIGNED_INT_VEC4, shader::LIST_CAPACITY, slots);
    vd.listPerspective = new osg::Uniform(osg::Uniform::INT, shader::LIST_SLOT_PERSPECTIVE, slots);
    for (unsigned int slot = 0; slot < slots; ++slot)
    {
        vd.listCapacity->setElement(slot, 0u, 0u, 0u, 0u);
        vd.listPerspective->setElement(slot, 0);
    }
    vd.listRayFrame = new osg::Uniform(shader::LIST_RAY_FRAME, osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
    vd.listLight = new osg::Uniform(osg::Uniform::FLOAT_VEC4, shader::LIST_LIGHT, slots);
    vd.listLightSize = new osg::Uniform(osg::Uniform::FLOAT, shader::LIST_LIGHT_SIZE, slots);
    vd.listSoftSamples = new osg::Uniform(shader::LIST_SOFT_SAMPLES, 64, softFirstPass(64));
    vd.listEyeToPattern = new osg::Uniform(shader::LIST_EYE_TO_PATTERN, osg::Matrixf());
    vd.lookupBiasFrame = new osg::Uniform(shader::LOOKUP_BIAS_FRAME, osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
}

} // namespace

osg::ref_ptr<ViewData> createViewData(const ViewLayout& layout)
{
    osg::ref_ptr<ViewData> vd = new ViewData;
    vd->baseUnit = layout.baseUnit;
    vd->pairedSlots = layout.pairedSlots;
    vd->mapBinding = layout.mapBinding;
    osg::StateSet* ss = new osg::StateSet;
    vd->receiverStateSet = ss;
    vd->receiverPassStateSet = new osg::StateSet;
    vd->receiverPassStateSet->setDataVariance(osg::Object::DYNAMIC); // the stencil modes' program, the prepass's depth
    vd->prepassStateSet = layout.prepassStateSet;
    if (layout.receiverProgram) ss->setAttributeAndModes(layout.receiverProgram, osg::StateAttribute::ON);
    const unsigned int slots = layout.slots;
    ss->setDefine(shader::DEFINE_MAX_SHADOW_LIGHTS, std::to_string(layout.maxShadowLights));
    ss->setDataVariance(osg::Object::DYNAMIC); // its defines, bindings and uniforms change per frame

    createLightUniforms(*vd, slots);
    osg::ref_ptr<osg::Uniform> samplers = new osg::Uniform(osg::Uniform::SAMPLER_2D_SHADOW, shader::SHADOW_MAP, slots);
    osg::ref_ptr<osg::Uniform> silhouetteSamplers =
        new osg::Uniform(osg::Uniform::SAMPLER_2D, shader::SILHOUETTE_MAP, slots);
    const unsigned int paired = layout.pairedSlots;
    for (unsigned int slot = 0; slot < slots; ++slot)
    {
        samplers->setElement(slot, int(layout.baseUnit + slot));
        // Only the paired modes declare silhouette samplers, OSS_MAX_SHADOW_SLOTS = `paired` of
        // them: the elements after those are never read (a valid unit all the same).
        silhouetteSamplers->setElement(slot, int(layout.baseUnit + paired + (slot < paired ? slot : 0)));
        vd->eyeToShadow->setElement(slot, osg::Matrixf());
        ss->setTextureAttributeAndModes(layout.baseUnit + slot, layout.litTexture, layout.mapBinding);
    }
    createListUniforms(*vd, slots);
    for (osg::Uniform* u :
         {vd->numLights.get(), vd->lightIndex.get(), vd->shadowSlot.get(), vd->eyeToShadow.get(), vd->maskLight.get(),
          samplers.get(), silhouetteSamplers.get(), vd->slotOwner.get(), vd->slotCore.get(), vd->slotDepths.get(),
          vd->filterScale.get(), vd->listCapacity.get(), vd->listPerspective.get(), vd->listRayFrame.get(),
          vd->lookupBiasFrame.get(), vd->listLight.get(), vd->listLightSize.get(), vd->listSoftSamples.get(),
          vd->listEyeToPattern.get()})
        ss->addUniform(u);
    ss->addUniform(new osg::Uniform(shader::BASE_TEXTURE, 0));
    ss->addUniform(new osg::Uniform(shader::LIST_RAY_OFFSET_PER_DISTANCE, shader::LIST_RAY_OFFSET_DISTANCE));
    ss->addUniform(new osg::Uniform(shader::LOOKUP_BIAS_PER_DISTANCE, shader::LOOKUP_BIAS));
    ss->addUniform(new osg::Uniform(shader::SHADOW_MAP_SIZE, osg::Vec2f(layout.mapSize, layout.mapSize)));
    vd->exactCounter = new GpuCounter(GL_ATOMIC_COUNTER_BUFFER);
    vd->exactBegin =
        vd->exactCounter->createBeginNode(SilhouetteShadowTechnique::DEPTH_PREPASS_BIN - 1); // before every receiver
    vd->exactEnd = vd->exactCounter->createEndNode(SilhouetteShadowTechnique::COUNT_END_BIN);
    vd->passes.resize(slots);
    vd->slotInUse.assign(slots, false);
    vd->slotSkipped.assign(slots, false);
    return vd;
}

void updateViewUniforms(osgUtil::CullVisitor& cv, ViewData& vd, const std::vector<FoundLight>& lights,
                        const std::vector<int>& slots, EyePassPlan& eye)
{
    const osg::Matrixd eyeToWorld = osg::Matrixd::inverse(*cv.getModelViewMatrix());
    const int n = std::min<int>(static_cast<int>(lights.size()), shader::MAX_SCENE_LIGHTS);
    vd.numLights->set(n);
    // A shadowed light with nothing to shadow is lit as an unshadowed one (slot -1), so the
    // stencil modes light it in their base pass and the receiver compiles only the slots
    // up to the last one in use.
    for (int i = 0; i < n; ++i)
    {
        const bool shadowed = slots[i] >= 0 && vd.passes[slots[i]].frustum.valid;
        vd.lightIndex->setElement(i, lights[i].description.lightNum);
        vd.shadowSlot->setElement(i, shadowed ? slots[i] : -1);
    }
    int used = 0;
    bool faces = false;
    for (unsigned int s = 0; s < vd.passes.size(); ++s)
    {
        const bool lightSlot = std::find(slots.begin(), slots.end(), int(s)) != slots.end();
        if (!vd.passes[s].frustum.valid || !(vd.slotInUse[s] || lightSlot)) continue;
        vd.eyeToShadow->setElement(s, osg::Matrixf(eyeToWorld * vd.passes[s].frustum.worldToTexture()));
        if (!vd.slotInUse[s]) continue;
        used = int(s) + 1;
        faces = faces || vd.passes[s].frustum.partial();
    }
    eye.usedSlots = static_cast<unsigned int>(used);
    eye.skippedSlots = 0;
    for (unsigned int s = 0; s < vd.slotSkipped.size() && s < 32; ++s)
        if (vd.slotInUse[s] && vd.slotSkipped[s]) eye.skippedSlots |= 1u << s;
    eye.cubeFaces = faces;
}

void updateRayFrames(osgUtil::CullVisitor& cv, ViewData& vd, const osg::BoundingSphere& bound, float shadowRayOffset)
{
    if (bound.valid())
    {
        const osg::Matrixd& worldToEye = *cv.getModelViewMatrix();
        const osg::Vec3d centre = bound.center() * worldToEye;
        const double scale = osg::Matrixd::transform3x3(osg::Vec3d(1.0, 0.0, 0.0), worldToEye).length();
        vd.listRayFrame->set(osg::Vec4f(centre, float(double(shadowRayOffset) * bound.radius() * scale)));
        const double cell = shader::LIST_PATTERN_CELL * bound.radius();
        vd.listEyeToPattern->set(
            osg::Matrixf(osg::Matrixd::inverse(worldToEye) * osg::Matrixd::scale(1.0 / cell, 1.0 / cell, 1.0 / cell)));
        vd.lookupBiasFrame->set(osg::Vec4f(centre, float(double(shader::LOOKUP_BIAS) * bound.radius() * scale)));
    }
    else
    {
        vd.listRayFrame->set(osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
        vd.lookupBiasFrame->set(osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
    }
}

void cullReceivers(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, ViewData& vd, osg::StateSet* pass,
                   CasterVertexStages* stages, ListedDrawables* faces, bool tightNear)
{
    const osgShadow::ShadowSettings* settings = scene.getShadowSettings();
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(mask & settings->getReceivesShadowTraversalMask());
    const osg::CullSettings::ComputeNearFarMode nearFar = cv.getComputeNearFarMode();
    osg::CullSettings::ComputeNearFarMode nearFarOverride = settings->getComputeNearFarModeOverride();
    // The stencil volumes compare their faces with the eye's depth buffer: a near plane the
    // near-far ratio clamped (a ground around the eye gives far / 2000) leaves the buffer too
    // coarse where shadow outlines fall (docs/shadow-volumes.md, "Precision").
    if (tightNear && nearFarOverride == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR &&
        nearFar == osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES)
        nearFarOverride = osg::CullSettings::COMPUTE_NEAR_USING_PRIMITIVES;
    if (nearFarOverride != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR) cv.setComputeNearFarMode(nearFarOverride);
    cv.pushStateSet(vd.receiverStateSet.get());
    if (pass) cv.pushStateSet(pass);
    scene.osg::Group::traverse(cv);
    if (pass) cv.popStateSet();
    // Receivers moved by their own vertex stage keep it where a pass overrides programs.
    osgUtil::RenderBin* bin = cv.getCurrentRenderBin();
    if (stages && pass && bin && bin->getStage())
        stages->keepMovedReceivers(*bin->getStage(), *pass, pass == vd.receiverPassStateSet.get());
    // Quads and polygons split as the shadow geometry and the light passes split them.
    if (faces && bin && bin->getStage()) faces->splitFaces(*bin->getStage(), pass ? pass : vd.receiverStateSet.get());
    cv.popStateSet();
    // The primitive modes leave their candidates to the end of the camera's cull: resolve
    // them now, as ViewDependentShadowMap does, or the light passes that follow read an
    // empty depth range and cast nothing.
    if (cv.getComputeNearFarMode() != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR) cv.computeNearPlane();
    cv.setComputeNearFarMode(nearFar);
    cv.setTraversalMask(mask);
}

void cullCasters(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, osg::StateSet* pass)
{
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(mask & scene.getShadowSettings()->getCastsShadowTraversalMask());
    const osg::CullSettings::ComputeNearFarMode nearFar = cv.getComputeNearFarMode();
    cv.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    // The culling sets below copy the projection's (CullStack::pushCullingSet()).
    osg::CullingSet& projection = cv.getProjectionCullingStack().back();
    osg::CullingSet& current = cv.getCurrentCullingSet();
    const osg::CullingSet::Mask projectionMask = projection.getCullingMask(), currentMask = current.getCullingMask();
    projection.setCullingMask(osg::CullingSet::NO_CULLING);
    current.setCullingMask(osg::CullingSet::NO_CULLING);
    cv.pushStateSet(pass);
    scene.osg::Group::traverse(cv);
    cv.popStateSet();
    projection.setCullingMask(projectionMask);
    current.setCullingMask(currentMask);
    cv.setComputeNearFarMode(nearFar);
    cv.setTraversalMask(mask);
}

void cullDepthPrepass(osgUtil::CullVisitor& cv, ViewData& vd,
                      const std::function<void(osg::StateSet* pass)>& cullReceivers)
{
    if (!vd.prepassDepth) vd.prepassDepth = new osg::Depth(osg::Depth::LEQUAL);
    // Not OVERRIDE: a drawable's own osg::Depth stays, and the prepass leaves it out.
    vd.receiverPassStateSet->setAttribute(vd.prepassDepth.get());
    cullReceivers(vd.prepassStateSet.get());
    if (osgUtil::RenderBin* bin = cv.getCurrentRenderBin())
        if (osgUtil::RenderStage* stage = bin->getStage())
            prunePrepass(*stage, vd.prepassStateSet.get(), vd.receiverStateSet.get(), false,
                         SilhouetteShadowTechnique::DEPTH_PREPASS_BIN);
}

void resetSlots(ViewData& vd, unsigned int capacity, osg::Texture2D* litTexture)
{
    for (unsigned int slot = 0; slot < vd.passes.size(); ++slot)
    {
        // SHADOW_MAP's slots after the paired ones take the units of their silhouette maps.
        if (slot < capacity) bindDepthMap(vd, slot, litTexture);
        vd.slotOwner->setElement(slot, int(slot));
        vd.slotCore->setElement(slot, 0.0f);
        vd.slotDepths->setElement(slot, osg::Vec2f(0.0f, ALL_DEPTHS));
        vd.filterScale->setElement(slot, osg::Vec2f());
        vd.listLightSize->setElement(slot, 0.0f);
        vd.slotInUse[slot] = false;
        vd.slotSkipped[slot] = false;
    }
}

void bindDepthMap(ViewData& vd, unsigned int slot, osg::Texture2D* texture)
{
    vd.receiverStateSet->setTextureAttributeAndModes(vd.baseUnit + slot, texture, vd.mapBinding);
}

void bindSecondMaps(ViewData& vd, const std::vector<osg::Texture2D*>& maps, osg::Texture2D* fallback)
{
    osg::StateSet& ss = *vd.receiverStateSet;
    for (unsigned int slot = 0; slot < vd.pairedSlots; ++slot)
    {
        const unsigned int unit = vd.baseUnit + vd.pairedSlots + slot;
        if (maps.empty())
            ss.removeTextureAttribute(unit, osg::StateAttribute::TEXTURE);
        else
            ss.setTextureAttributeAndModes(unit, slot < maps.size() ? maps[slot] : fallback, vd.mapBinding);
    }
}

} // namespace detail
} // namespace osgShadowSilhouette
