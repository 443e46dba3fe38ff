#include "LightPlanning.h"

#include "SceneVisitors.h"

#include <osgShadowSilhouette/CasterEdges>
#include <osgShadowSilhouette/ShaderConstants>

#include <osgUtil/RenderStage>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace osgShadowSilhouette {
namespace detail {

namespace {

/** Shadow slot per light (-1: unshadowed): LightNum's light or the first MaxShadowLights of
 *  the casting lights that reach what the view sees (reaches[i]). */
std::vector<int> assignShadowSlots(const std::vector<FoundLight>& lights, const std::vector<bool>& reaches,
                                   const SlotBudget& budget, const Warn& warn)
{
    std::vector<int> slots(lights.size(), -1);
    unsigned int slot = 0;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (!castsShadow(lights[i], budget.lightNum) || !reaches[i]) continue;
        if (slot >= budget.maxShadowLights)
        {
            warn(WARN_OVER_BUDGET, "more shadow-casting lights than MaxShadowLights (" +
                                       std::to_string(budget.maxShadowLights) + "); the rest are lit unshadowed");
            break;
        }
        slots[i] = static_cast<int>(slot++);
    }
    return slots;
}

/** Fits the light frustum of one light to the casters that can shadow the visible region. */
LightFrustum fitLightFrustum(const LightDescription& light, const FrameContext& frame, const SlotBudget& budget,
                             double warpNearFloor = 0.0)
{
    if (light.type != LightDescription::DIRECTIONAL) return fitPerspectiveFrustum(light, frame.region, frame.casters);
    if (!budget.warp || !frame.view.valid)
        return fitDirectionalFrustum(light.direction, frame.region, frame.casters, budget.mapSize);
    const osg::Matrixd eyeToWorld = osg::Matrixd::inverse(frame.view.view);
    return fitWarpedDirectionalFrustum(
        light.direction, frame.region, frame.casters, budget.mapSize, osg::Vec3d() * eyeToWorld,
        osg::Matrixd::transform3x3(osg::Vec3d(0.0, 0.0, -1.0), eyeToWorld), warpNearFloor);
}

/** A directional light's cascades (budget.cascades > 1): the view's visible region cut into
 *  ranges of view depth (cascadeSplits()), each fitted as the light's only map would be (warped
 *  or not); each answers for its range (the first from 0, the last to infinity). A range with
 *  nothing to shadow gets no map: its points are lit. Empty: nothing to shadow at all. */
std::vector<LightFrustum> fitCascades(const LightDescription& light, const FrameContext& frame,
                                      const SlotBudget& budget)
{
    double lo = std::numeric_limits<double>::max(), hi = 0.0;
    for (const osg::Vec3d& p : frame.region)
    {
        const double depth = -(p * frame.view.view).z();
        lo = std::min(lo, depth), hi = std::max(hi, depth);
    }
    std::vector<LightFrustum> cascades;
    if (!(hi > 0.0)) return cascades;
    const std::vector<double> splits = cascadeSplits(std::max(lo, 0.0), hi, budget.cascades);
    FrameContext slice;
    slice.casters = frame.casters;
    slice.view = frame.view;
    for (std::size_t i = 0; i + 1 < splits.size(); ++i)
    {
        const osg::Matrixd projection = withDepthRange(frame.view.projection, splits[i], splits[i + 1]);
        slice.region = visibleRegion(frustumCorners(frame.view.view, projection), frame.receivers);
        LightFrustum f = slice.region.empty() ? LightFrustum() : fitLightFrustum(light, slice, budget, 1e-3 * hi);
        if (!f.valid) continue;
        f.viewDepthFrom = i == 0 ? 0.0 : splits[i];
        f.viewDepthTo = i + 2 == splits.size() ? std::numeric_limits<double>::infinity() : splits[i + 1];
        cascades.push_back(f);
    }
    return cascades;
}

/** The frusta of a light: one, or a point light's cube faces, which take the slots from
 *  nextFreeSlot on when they fit below the slot limit (else one perspective map, with a
 *  warning). A point light with nothing to shadow gets one invalid frustum. */
std::vector<LightFrustum> planLightFrusta(const FrameContext& frame, const LightDescription& light,
                                          unsigned int& nextFreeSlot, const SlotBudget& budget, const Warn& warn)
{
    std::vector<LightFrustum> frusta;
    if (budget.cubeFaces && light.type == LightDescription::POINT && needsCubeFaces(light, frame.region))
    {
        // Only the faces where a caster that can shadow a receiver lies: a flat caster (a
        // ground) that every receiver stands on or above, seen from the light, shadows nothing.
        std::vector<osg::BoundingBoxd> parts;
        for (const CasterPart& part : frame.casterParts)
            if (canShadow(light, part, frame.receivers)) parts.push_back(part.box);
        if (parts.empty() && !frame.casterParts.empty())
            return {LightFrustum()}; // nothing to shadow: the light is lit unshadowed
        frusta = fitCubeFaces(light, frame.region, frame.casters, budget.mapSize,
                              frame.casterParts.empty() ? nullptr : &parts, budget.faceMarginTexels);
        const unsigned int slotLimit = budget.slotLimit;
        if (frusta.size() > 1 && nextFreeSlot + frusta.size() - 1 > slotLimit)
        {
            warn(WARN_FACE_SLOTS, "light " + std::to_string(light.lightNum) + " needs " +
                                      std::to_string(frusta.size()) + " cube faces and only " +
                                      std::to_string(slotLimit - nextFreeSlot + 1) + " of the " +
                                      std::to_string(slotLimit) +
                                      " shadow slots are free; it gets one perspective map (see BaseTextureUnit)");
            frusta.clear();
        }
    }
    if (budget.cascades > 1 && light.type == LightDescription::DIRECTIONAL && frame.view.valid)
    {
        frusta = fitCascades(light, frame, budget);
        if (frusta.empty()) return {LightFrustum()}; // nothing to shadow: the light is lit unshadowed
        if (frusta.size() > 1 && nextFreeSlot + frusta.size() - 1 > budget.slotLimit)
        {
            warn(WARN_CASCADE_SLOTS, "light " + std::to_string(light.lightNum) + " needs " +
                                         std::to_string(frusta.size()) + " cascades and only " +
                                         std::to_string(budget.slotLimit - nextFreeSlot + 1) + " of the " +
                                         std::to_string(budget.slotLimit) +
                                         " shadow slots are free; it gets one map (see BaseTextureUnit)");
            frusta.clear();
        }
    }
    if (frusta.empty()) frusta.push_back(fitLightFrustum(light, frame, budget));
    if (frusta.size() > 1) nextFreeSlot += static_cast<unsigned int>(frusta.size() - 1);
    return frusta;
}

} // namespace

bool castsShadow(const FoundLight& light, int lightNum)
{
    return lightNum < 0 || light.description.lightNum == lightNum;
}

SlotPlan planSlots(const FrameContext& frame, const std::vector<FoundLight>& lights, const SlotBudget& budget,
                   const Warn& warn, unsigned int& lightsSkipped)
{
    // Lights whose cone or range misses what the view sees cost nothing: no passes, no slot.
    std::vector<bool> reaches(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        reaches[i] = lightReachesRegion(lights[i].description, frame.region);
        if (!reaches[i] && castsShadow(lights[i], budget.lightNum)) ++lightsSkipped;
    }
    SlotPlan plan;
    plan.slots = assignShadowSlots(lights, reaches, budget, warn);
    // Each light's frusta; cube faces of point lights take the slots after the lights' own.
    unsigned int nextFreeSlot = 0;
    for (int slot : plan.slots) nextFreeSlot = std::max(nextFreeSlot, static_cast<unsigned int>(slot + 1));
    plan.frusta.resize(lights.size());
    plan.firstFaceSlot.assign(lights.size(), 0);
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (plan.slots[i] < 0) continue;
        plan.firstFaceSlot[i] = nextFreeSlot;
        plan.frusta[i] = planLightFrusta(frame, lights[i].description, nextFreeSlot, budget, warn);
    }
    plan.slotsInUse = nextFreeSlot;
    return plan;
}

std::vector<FoundLight> collectLights(osgUtil::CullVisitor& cv, std::vector<int>& refusedNums,
                                      const RefusedLight& refused)
{
    std::vector<FoundLight> lights;
    osgUtil::RenderStage* stage = cv.getCurrentRenderBin()->getStage();
    osgUtil::PositionalStateContainer* psc = stage ? stage->getPositionalStateContainer() : nullptr;
    if (!psc) return lights;

    // Light positions are stored with the model-view matrix at their LightSource (null:
    // already in eye coordinates); "world" here is the ShadowedScene's own frame.
    const osg::Matrixd eyeToWorld = osg::Matrixd::inverse(*cv.getModelViewMatrix());
    for (const auto& attrMatrix : psc->getAttrMatrixList())
    {
        const osg::Light* light = dynamic_cast<const osg::Light*>(attrMatrix.first.get());
        if (!light) continue;
        const osg::Matrixd lightToWorld =
            attrMatrix.second.valid() ? osg::Matrixd(*attrMatrix.second) * eyeToWorld : eyeToWorld;
        FoundLight found;
        found.light = light;
        std::string refusal;
        const bool usable = LightDescription::fromLight(*light, lightToWorld, found.description, &refusal);
        if (!usable) refused(*light, refusal);
        // Positional state is applied in this order, so of two lights with one number (say
        // the viewer's headlight and the scene's light 0) the last is the one GL lights with.
        const int num = light->getLightNum();
        lights.erase(std::remove_if(lights.begin(), lights.end(),
                                    [&](const FoundLight& l) { return l.description.lightNum == num; }),
                     lights.end());
        refusedNums.erase(std::remove(refusedNums.begin(), refusedNums.end(), num), refusedNums.end());
        if (!usable)
            refusedNums.push_back(num);
        else if (num < shader::MAX_SCENE_LIGHTS)
            lights.push_back(found);
    }
    std::sort(lights.begin(), lights.end(),
              [](const FoundLight& a, const FoundLight& b) { return a.description.lightNum < b.description.lightNum; });
    return lights;
}

void warnAboutMissingLights(const std::vector<FoundLight>& lights, int lightNum, bool debugView,
                            unsigned int debugLight, const Warn& warn)
{
    std::string found;
    for (const FoundLight& l : lights) found += (found.empty() ? "" : ", ") + std::to_string(l.description.lightNum);
    const std::string what = lights.empty() ? "the view has no light" : "the view's GL lights are " + found;
    const bool named = std::any_of(lights.begin(), lights.end(),
                                   [&](const FoundLight& l) { return l.description.lightNum == lightNum; });
    if (lightNum >= 0 && !named)
        warn(WARN_LIGHT_NUM, "LightNum " + std::to_string(lightNum) + " names no light (" + what +
                                 "); nothing casts a shadow (LightNum -1: every light)");
    if (debugView && debugLight >= lights.size())
        warn(WARN_DEBUG_LIGHT, "DebugLight " + std::to_string(debugLight) + " is not a light of the view (" +
                                   std::to_string(lights.size()) + " found, DebugLight counts from 0); the " +
                                   "debug view shows it unlit");
}

std::vector<osg::Vec3d> visibleReceiverRegion(osgUtil::CullVisitor& cv, const osg::BoundingBoxd& receivers,
                                              osg::CullSettings::ComputeNearFarMode nearFarOverride,
                                              double maximumDistance)
{
    if (!receivers.valid()) return {};
    double zNear = cv.getCalculatedNearPlane();
    double zFar = cv.getCalculatedFarPlane();
    const osg::Matrixd& projection = *cv.getProjectionMatrix();
    if (cv.getComputeNearFarMode() == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR &&
        nearFarOverride == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR)
    {
        const std::array<osg::Vec3d, 8> c = frustumCorners(osg::Matrixd(), projection);
        zNear = -c[0].z(), zFar = -c[4].z();
    }
    if (!std::isfinite(zNear) || !std::isfinite(zFar))
    {
        // A drawable with non-finite vertices (left out of casting) gave the view a
        // non-finite depth range: take the receivers' own depth range instead.
        zNear = std::numeric_limits<double>::max(), zFar = -zNear;
        const osg::Matrixd& modelView = *cv.getModelViewMatrix();
        for (unsigned int i = 0; i < 8; ++i)
        {
            const double z = -(receivers.corner(i) * modelView).z();
            zNear = std::min(zNear, z), zFar = std::max(zFar, z);
        }
        zNear = std::max(zNear, 0.0);
    }
    // ShadowSettings' MaximumShadowMapDistance: the maps cover the eye range up to it, as in
    // ViewDependentShadowMap; beyond, the receivers fall outside them (lit). A distance
    // before the near plane leaves nothing to cover.
    if (maximumDistance < zFar) zFar = maximumDistance;
    if (!(zNear <= zFar) || !std::isfinite(zNear) || !std::isfinite(zFar) || zFar <= 0.0) return {}; // nothing visible
    zNear = std::max(zNear, zFar * 1e-6);
    const double margin = 1e-3 * (zFar - zNear) + 1e-6 * zFar;
    const osg::Matrixd fitted = withDepthRange(projection, std::max(zNear - margin, zNear * 0.5), zFar + margin);
    return visibleRegion(frustumCorners(*cv.getModelViewMatrix(), fitted), receivers);
}

void gatherFrame(osgUtil::CullVisitor& cv, osgShadow::ShadowedScene& scene, MeshCache& meshCache,
                 double maximumDistance, FrameContext& frame)
{
    using Technique = SilhouetteShadowTechnique;
    const osgShadow::ShadowSettings* settings = scene.getShadowSettings();
    frame.view = ViewPoint::fromCullVisitor(cv);
    frame.receivers = boundsOf(scene, settings->getReceivesShadowTraversalMask(), meshCache, frame.view);
    CasterSignatureVisitor casters(meshCache, frame.view);
    casters.setTraversalMask(settings->getCastsShadowTraversalMask());
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) scene.getChild(i)->accept(casters);
    casters.mix(cv.getTraversalMask()); // the depth pass culls under the view's mask too
    const osg::BoundingBox& box = casters.getBoundingBox();
    frame.casters = box.valid() ? osg::BoundingBoxd(box._min, box._max) : osg::BoundingBoxd();
    frame.casterSignature = casters.signature;
    frame.casterParts = std::move(casters.parts);
    frame.nonFinite = casters.nonFinite;
    if (!casters.billboards.empty())
        frame.billboards = std::make_shared<const BillboardMatrices>(std::move(casters.billboards));
    frame.region = visibleReceiverRegion(cv, frame.receivers, settings->getComputeNearFarModeOverride(),
                                         frame.mode != Technique::SHADOW_VOLUME ? maximumDistance : DBL_MAX);
    if (frame.mode != Technique::SHADOW_MAP)
        frame.casterList = collectCasters(scene, cv.getTraversalMask() & settings->getCastsShadowTraversalMask(),
                                          meshCache, frame.view);
}

} // namespace detail
} // namespace osgShadowSilhouette
