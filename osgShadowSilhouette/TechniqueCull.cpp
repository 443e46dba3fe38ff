#include "TechniqueCull.h"

#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/ShaderConstants>

#include "DepthMapPass.h"
#include "LightPlanning.h"
#include "SharedResources.h"
#include "SoftFilter.h"
#include "RenderLeaves.h"
#include "ViewState.h"

#include <osg/GLExtensions>
#include <osg/Viewport>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

namespace {

using Technique = SilhouetteShadowTechnique;

/** The passes of @p mode: stateless, one for every view and thread. */
ModePass& modePassFor(Technique::Mode mode)
{
    static const osg::ref_ptr<ModePass> passes[] = {
        createModePass(Technique::SHADOW_MAP), createModePass(Technique::SILHOUETTE_MAP),
        createModePass(Technique::HYBRID), createModePass(Technique::SHADOW_VOLUME)};
    return *passes[mode >= 0 && mode < 4 ? mode : 0];
}

const osg::GLExtensions* extensionsOf(const osgUtil::CullVisitor& cv)
{
    // GLExtensions holds the context's limits once it has been made current: no query here.
    // Before that (the very first frame) there are none.
    const osg::State* state = cv.getState();
    return state ? osg::GLExtensions::Get(state->getContextID(), false) : nullptr;
}

} // namespace

TechniqueCull::TechniqueCull(SilhouetteShadowTechnique& technique, osgUtil::CullVisitor& cv)
    : _t(technique), _cv(cv), _vd(viewData()), _mf{_cv, _vd, _frame, _stats, _eye, _settings, _services}
{
    _frame.mode = effectiveMode();
    _mode = &modePassFor(_frame.mode);
    _settings = passSettings();
    _services = passServices();
    // The eye pass's configuration, filled in as the frame is planned and applied at the end.
    _eye.mode = _frame.mode;
    _eye.debugView = _t._debugView;
    _eye.perPixelLighting = _t._perPixelLighting;
}

ViewData& TechniqueCull::viewData()
{
    // The map size is clamped before the view's data are made: they are laid out for it.
    clampMapSizeToContext();
    return *_t.getViewData(_cv);
}

void TechniqueCull::clampMapSizeToContext()
{
    const osg::GLExtensions* ext = extensionsOf(_cv);
    if (!ext || ext->maxTextureSize <= 0 || _t._shadowMapSize <= static_cast<unsigned int>(ext->maxTextureSize)) return;
    _t.warnOnce(WARN_CONTEXT_MAP_SIZE, "ShadowMapSize " + std::to_string(_t._shadowMapSize) +
                                           " exceeds the context's GL_MAX_TEXTURE_SIZE (" +
                                           std::to_string(ext->maxTextureSize) + "); clamped to it");
    if (_t._properties.shadowMapSize == _t._shadowMapSize)
        _t._properties.shadowMapSize = static_cast<unsigned int>(ext->maxTextureSize);
    _t._shadowMapSize = static_cast<unsigned int>(ext->maxTextureSize);
}

TechniqueCull::Mode TechniqueCull::effectiveMode() const
{
    const Mode mode = _t._mode;
    if (mode != Technique::SHADOW_VOLUME && mode != Technique::HYBRID) return mode;
    const osg::State* state = _cv.getState();
    const osg::GraphicsContext* gc = state ? state->getGraphicsContext() : nullptr;
    const osg::GraphicsContext::Traits* traits = gc ? gc->getTraits() : nullptr;
    if (!traits || traits->stencil > 0) return mode;
    _t.warnOnce(WARN_NO_STENCIL, std::string("Mode ") + Technique::modeName(mode) +
                                     " needs a stencil buffer and the graphics context has none (call "
                                     "osg::DisplaySettings::instance()->setMinimumNumStencilBits(8) before creating "
                                     "it, or run osgviewer with --stencil); rendering SHADOW_MAP");
    return Technique::SHADOW_MAP;
}

PassSettings TechniqueCull::passSettings() const
{
    const SharedResources& shared = *_t._shared;
    PassSettings s;
    s.mode = _t._mode;
    s.shadowMapSize = _t._shadowMapSize;
    s.glGeneration = _t.getGLGeneration();
    s.polygonOffsetFactor = _t.getEffectivePolygonOffsetFactor(_frame.mode);
    s.warpedPolygonOffsetFactor = _t.getEffectivePolygonOffsetFactor(_frame.mode, true);
    s.polygonOffsetUnits = _t._polygonOffsetUnits;
    s.blockerCulling = _t._blockerCulling;
    s.hybridEdgeMask = _t._hybridEdgeMask;
    s.hybridMethod = _t._hybridMethod;
    s.debugView = _t._debugView;
    s.debugLight = _t._debugLight;
    s.filter = _t._filter;
    s.filterWindow = _t._filterWindow;
    s.gpuExtraction = _t._gpuExtraction;
    s.softSamples = _t._softSamples;
    s.tuning = _t._tuning;
    s.listSlots = _t.listSlots();
    s.recordingStats = _t._stats.valid();
    s.shadowedScene = _t._shadowedScene;
    s.silhouetteMapStateSet = shared.silhouetteMapStateSet.get();
    s.listStateSet = shared.listStateSet.get();
    s.listFrontOnlyStateSet = shared.listFrontOnlyStateSet.get();
    s.listedDrawables = _t._listedDrawables.get();
    s.casterStages = shared.casterStages.get();
    s.stencilProgram = shared.stencilProgram.get();
    s.volumeProgram = shared.volumeProgram.get();
    s.defaultSilhouetteTexture = shared.defaultSilhouetteTexture.get();
    s.defaultNeighbourhoodTexture = shared.defaultNeighbourhoodTexture.get();
    s.distanceMapStateSet = shared.distanceMapStateSet.get();
    s.defaultDistanceTexture = shared.defaultDistanceTexture.get();
    return s;
}

PassServices TechniqueCull::passServices()
{
    PassServices services;
    services.warnOnce = _t.warner();
    services.cullReceivers = [this](osg::StateSet* pass) { _t.cullReceivers(_cv, _vd, pass); };
    services.applicationPrograms = [this]() { return _t.hasApplicationPrograms(); };
    services.warnAlphaTested = [log = _t._warnings.get()](bool hybrid, bool lists) { log->alphaTested(hybrid, lists); };
    services.gpuEdges = [this]() {
        const SharedResources& shared = *_t._shared;
        if (!_vd.gpuEdges)
            _vd.gpuEdges = new GpuEdges(shared.gpuEdgePrograms, shared.casterStages.get(), shared.adjacency.get());
        _vd.gpuEdges->setAllCasters(_settings.gpuExtraction == SilhouetteShadowTechnique::GPU_EXTRACTION_ALL_CASTERS);
        return _vd.gpuEdges.get();
    };
    services.cullLightCasters = [this](osg::StateSet* pass) {
        cullCasters(_cv, *_t._shadowedScene, pass);
        osgUtil::RenderBin* bin = _cv.getCurrentRenderBin();
        if (_frame.billboards && !_frame.billboards->empty() && bin && bin->getStage())
            turnBillboardLeaves(*bin->getStage(), *_frame.billboards, *_cv.getModelViewMatrix());
    };
    return services;
}

void TechniqueCull::cullReceivers()
{
    // Their pass state set gets the stencil modes' lighting program once the method is known.
    _t.cullReceivers(_cv, _vd, _vd.receiverPassStateSet.get());
}

void TechniqueCull::cullLights()
{
    std::vector<int> refused;
    _lights = collectLights(_cv, refused, [this](const osg::Light& light, const std::string& refusal) {
        _t._warnings->refusedLight(_cv.getNodePath().empty() ? nullptr : _cv.getNodePath().front(), light, refusal);
    });
    // The receiver shading lights only the lights found (oss_lightIndex); drawables under a
    // program of their own, or all with UseDefaultShading false, are lit by OpenGL, which
    // would spread a refused light's NaN: its GL light is turned off for them.
    for (int num = 0; num < shader::MAX_SCENE_LIGHTS; ++num)
    {
        if (std::find(refused.begin(), refused.end(), num) != refused.end())
            _vd.receiverStateSet->setMode(GL_LIGHT0 + num, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
        else
            _vd.receiverStateSet->removeMode(GL_LIGHT0 + num);
    }
    for (FoundLight& found : _lights)
        for (const LightDescription& last : _vd.lastLights)
            if (last.lightNum == found.description.lightNum) found.description = steadied(found.description, last);
    _vd.lastLights.clear();
    for (const FoundLight& found : _lights) _vd.lastLights.push_back(found.description);
    for (FoundLight& found : _lights)
    {
        std::string refusal;
        found.description.size =
            lightSize(*found.light, _t._sizedLightSources.get(), found.description.type, _t._lightSize, refusal);
        if (!refusal.empty()) _t._warnings->refusedLightSize(*found.light, refusal);
        _frame.sizedLights = _frame.sizedLights || found.description.size > 0.0;
    }
    _stats.frameNumber = _cv.getFrameStamp() ? _cv.getFrameStamp()->getFrameNumber() : 0;
    _stats.lightsFound = static_cast<unsigned int>(_lights.size());
    _stats.effectiveMode = _frame.mode;
    _t._renderedMode = int(_frame.mode);
}

void TechniqueCull::planSlots()
{
    if (_lights.empty())
        _t.warnOnce(WARN_NO_LIGHT, "no positional light (osg::LightSource) in the view; nothing to shadow");
    else
        _t.prepareFrame(_cv, _frame);
    warnAboutMissingLights(_lights, _t._lightNum, _t._debugView != Technique::DEBUG_NONE, _t._debugLight, _t.warner());
    SlotBudget budget;
    budget.lightNum = _t._lightNum;
    budget.maxShadowLights = _t._maxShadowLights;
    budget.mapSize = _t._shadowMapSize;
    budget.slotLimit = _t.slotCapacity(Technique::pairedSlots(_frame.mode));
    budget.cubeFaces = _frame.mode != Technique::SHADOW_VOLUME; // the volumes reach every direction
    // HYBRID's rays toward a light with a size walk an orthographic map's texels.
    budget.warp = _t.warpsMaps(_frame.mode) && !(_frame.mode == Technique::HYBRID && _frame.sizedLights);
    budget.cascades = budget.cubeFaces ? _t._cascades : 1;
    if (_t._perspectiveWarp && !budget.warp)
        _t.warnOnce(WARN_WARP_MODE,
                    std::string("PerspectiveWarp applies to SHADOW_MAP and SILHOUETTE_MAP under FILTER_PCF_2X2 or "
                                "FILTER_PCF, and to HYBRID under lights without a size; ") +
                        (_frame.mode == Technique::HYBRID
                             ? std::string("HYBRID under a light with a size")
                             : "mode " + std::string(Technique::modeName(_frame.mode)) + " with Filter " +
                                   formatPropertyValue(*findProperty("Filter"), _t._filter)) +
                        " keeps uniform maps");
    const Technique::Filter filter = _t._filter;
    if (_frame.mode == Technique::SHADOW_MAP ||
        (_frame.mode == Technique::SILHOUETTE_MAP && filter == Technique::FILTER_SILHOUETTE))
        budget.faceMarginTexels = filterReachTexels(filter, _t._filterWindow);
    // HYBRID's shadow rays to a light with a size reach as far as PCSS's taps.
    if (_frame.mode == Technique::HYBRID && _frame.sizedLights)
        budget.faceMarginTexels = filterReachTexels(Technique::FILTER_PCSS, 1);
    _plan = detail::planSlots(_frame, _lights, budget, _t.warner(), _stats.lightsSkipped);
    _frame.slotsInUse = _plan.slotsInUse;
    _stats.silhouetteCasters = static_cast<unsigned int>(_frame.casterList.size());
}

void TechniqueCull::warnFilterMode() const
{
    // FILTER_PCF and FILTER_PCSS are SHADOW_MAP's, FILTER_SILHOUETTE is SILHOUETTE_MAP's.
    const Technique::Filter filter = _t._filter;
    const Mode mode = _frame.mode;
    const Mode owner = filter == Technique::FILTER_SILHOUETTE ? Technique::SILHOUETTE_MAP : Technique::SHADOW_MAP;
    if (filter == Technique::FILTER_PCF_2X2 || mode == owner) return;
    _t.warnOnce(WARN_FILTER_MODE,
                "Filter " + formatPropertyValue(*findProperty("Filter"), filter) + " applies to " +
                    (owner == Technique::SHADOW_MAP ? "SHADOW_MAP" : "SILHOUETTE_MAP") + " only; mode " +
                    Technique::modeName(mode) + " renders its own " +
                    (mode == Technique::HYBRID ? "shadows (soft by its shadow rays under a light with a size)"
                                               : "hard shadows"));
}

void TechniqueCull::planMode()
{
    warnFilterMode();
    _mode->planFrame(_mf);
}

void TechniqueCull::prepareEyePass()
{
    const SharedResources& shared = *_t._shared;
    if (_frame.stencil && !_vd.stencil)
        _vd.stencil = new StencilShadowPasses(shared.stencilProgram.get(), shared.volumeProgram.get());
    if (_frame.stencil)
    {
        _vd.receiverPassStateSet->setAttributeAndModes(shared.stencilProgram.get(),
                                                       osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        GpuVolumes* gpu = _vd.stencil->getGpuVolumes();
        if (!gpu)
            gpu = new GpuVolumes(shared.gpuVolumeProgram.get(), shared.gpuVolumeCapProgram.get(),
                                 shared.casterStages.get(), shared.adjacency.get());
        gpu->setAllCasters(_t._gpuExtraction == SilhouetteShadowTechnique::GPU_EXTRACTION_ALL_CASTERS);
        _vd.stencil->setGpuVolumes(gpu, [this](osg::StateSet* pass) { cullCasters(_cv, *_t._shadowedScene, pass); });
    }
    else
        _vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::PROGRAM);
    // The GLSL 4.30 shaders join the receivers' programs only where the context runs them.
    const osg::GLExtensions* ext = extensionsOf(_cv);
    if (ext && ext->glVersion >= 4.3f)
        _vd.receiverStateSet->setDefine(shader::DEFINE_GLSL_430);
    else
        _vd.receiverStateSet->removeDefine(shader::DEFINE_GLSL_430);
    _stats.screenVisibility = cullScreenVisibility(_mf);
    std::size_t casterTriangles = 0;
    for (const Caster& caster : _frame.casterList) casterTriangles += caster.mesh->getAdjacency().report.inputTriangles;
    const osg::Viewport* eyeViewport = _cv.getViewport();
    _stats.depthPrepass =
        _t.usesDepthPrepass(_frame.mode, _frame.triangleLists, casterTriangles, std::max(1u, _frame.slotsInUse),
                            eyeViewport ? eyeViewport->width() * eyeViewport->height() : 0.0);
    if (_stats.depthPrepass)
        cullDepthPrepass(_cv, _vd, [this](osg::StateSet* pass) { _t.cullReceivers(_cv, _vd, pass); });
    else
        _vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::DEPTH);
}

void TechniqueCull::cullShadowSlots()
{
    const bool paired = Technique::pairedSlots(_frame.mode);
    const unsigned int capacity = _t.slotCapacity(paired);
    _eye.slotCapacity = capacity;
    const SharedResources& shared = *_t._shared;
    // SILHOUETTE_MAP's eye pass reads neighbourhood maps (usampler2D), HYBRID's the edge masks.
    osg::Texture2D* second = _mode->defaultSecondMap(_settings);
    osg::Texture2D* fallback = shared.defaultSilhouetteTexture.get();
    std::vector<osg::Texture2D*> secondMaps(capacity, second ? second : fallback);
    resetSlots(_vd, capacity, shared.litTexture(_mode->rawDepthMaps(_settings)));
    // The second maps' units; in SHADOW_MAP they hold the depth maps bound above.
    if (paired) bindSecondMaps(_vd, second ? secondMaps : std::vector<osg::Texture2D*>(), fallback);
    for (std::size_t i = 0; i < _lights.size(); ++i)
    {
        if (_plan.slots[i] < 0) continue;
        ++_stats.lightsShadowed;
        cullLight(_lights[i].description, static_cast<unsigned int>(_plan.slots[i]), _plan.frusta[i],
                  _plan.firstFaceSlot[i], secondMaps);
    }
    if (second) bindSecondMaps(_vd, secondMaps, fallback);
}

void TechniqueCull::cullLight(const LightDescription& light, unsigned int slot, const std::vector<LightFrustum>& frusta,
                              unsigned int firstFaceSlot, std::vector<osg::Texture2D*>& secondMaps)
{
    if (!frusta.front().valid)
    {
        _vd.passes[slot].frustum = LightFrustum();
        ++_stats.lightsSkipped; // nothing can shadow what this view sees
        return;
    }
    for (std::size_t k = 0; k < frusta.size(); ++k)
    {
        const unsigned int s = k == 0 ? slot : firstFaceSlot + static_cast<unsigned int>(k - 1);
        _vd.slotOwner->setElement(s, int(slot));
        _vd.slotCore->setElement(s, float(frusta[k].faceCore));
        _vd.slotDepths->setElement(
            s, osg::Vec2f(float(frusta[k].viewDepthFrom), float(std::min<double>(frusta[k].viewDepthTo, ALL_DEPTHS))));
        cullSlot(light, s, frusta[k], secondMaps[s]);
    }
}

void TechniqueCull::cullSlot(const LightDescription& light, unsigned int slot, const LightFrustum& frustum,
                             osg::Texture2D*& secondMap)
{
    LightPass& pass = _vd.passes[slot];
    fitDepthMap(pass, slot, _t._shadowMapSize, _mode->rawDepthMaps(_settings), *_t._shared->depthPassStateSet,
                _t._shadowedScene);
    // A warped map that still holds what this frame needs keeps its projection, and with it
    // every pass drawn with it (the eye walking within a step of the warp).
    LightFrustum fitted = frustum;
    if (keepsWarpedFit(pass.frustum, frustum))
        fitted.projection = pass.frustum.projection, fitted.warpFit = pass.frustum.warpFit;
    pass.frustum = fitted;
    if (!_mode->drawsMaps()) return; // volumes only, no map
    _vd.slotInUse[slot] = true;
    SlotCull cull{light, slot, pass, cullDepthMap(_mf, *_mode, pass, light), secondMap};
    bindDepthMap(_vd, slot, pass.depthTexture.get());
    _mode->cullSlot(_mf, cull);
    // A cube face whose newest build (this light, these casters) drew no caster shadows
    // nothing: the eye pass leaves it out. The counts come back a frame or two late; until
    // then, and in every frame that rebuilds, the face is evaluated. Not the stencil passes.
    _vd.slotSkipped[slot] =
        _t._tuning.skipEmptyFaces && !_frame.stencil && frustum.faceCore > 0.0 &&
        (_frame.triangleLists ? pass.listPass && pass.listPass->listedNothing() : pass.samples->drewNothing());
    if (_vd.slotSkipped[slot]) ++_stats.slotsSkipped;
    if (pass.samples->getEnabled() && pass.samples->pending()) pass.samples->getPollNode()->accept(_cv);
}

void TechniqueCull::cullEyePasses()
{
    _mode->cullEyePasses(_mf, _lights, _plan.slots);
    updateViewUniforms(_cv, _vd, _lights, _plan.slots, _eye);
    _vd.maskLight->set(static_cast<int>(_t._debugLight));
    updateRayFrames(_cv, _vd, _t._shadowedScene ? _t._shadowedScene->getBound() : osg::BoundingSphere(),
                    _t._shadowRayOffset);
}

void TechniqueCull::finishEyePass()
{
    applyEyePassDefines(*_vd.receiverStateSet, eyePassDefines(_eye));
    // A mask is 0 or 1: a blended scene (an alpha-tested tree that also blends) must not
    // mix it with what lies behind. The alpha still reaches the scene's osg::AlphaFunc.
    const Technique::DebugView view = _t._debugView;
    if (view == Technique::DEBUG_SHADOW_MASK || view == Technique::DEBUG_CLASSES || view == Technique::DEBUG_VISIBILITY)
        _vd.receiverStateSet->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    else
        _vd.receiverStateSet->removeMode(GL_BLEND);
    _t.cullProgramLinkCheck(_cv);
    if (const osg::Viewport* viewport = _cv.getViewport())
        _stats.viewportPixels = static_cast<unsigned int>(viewport->width() * viewport->height());
    _t.recordStatistics(_stats);
}

} // namespace detail
} // namespace osgShadowSilhouette
