#include <osgShadowSilhouette/SilhouetteShadowTechnique>
#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/ShaderConstants>

#include "EyePass.h"
#include "FrameData.h"
#include "DepthMapPass.h"
#include "LightPlanning.h"
#include "ViewState.h"
#include "Warnings.h"
#include "ModePass.h"
#include "RenderLeaves.h"
#include "ScreenVisibility.h"
#include "SharedResources.h"
#include "SceneVisitors.h"
#include "SoftFilter.h"

#include <osg/Depth>
#include <osg/GLExtensions>
#include <osg/Viewport>
#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>
#include <osgUtil/RenderStage>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace osgShadowSilhouette {

namespace {

using detail::boundsOf;
using detail::CasterSignatureVisitor;
using detail::prunePrepass;
using detail::TagShaderDefinesVisitor;
using detail::FoundLight;
using detail::FrameContext;
using detail::LightPass;
using detail::ModeFrame;
using detail::ModePass;
using detail::PassInputs;
using detail::SlotPlan;
using detail::ViewData;
using namespace detail; // WarningKey

/** The passes of @p mode: stateless, one for every view and thread. */
ModePass& modePassFor(SilhouetteShadowTechnique::Mode mode)
{
    static const osg::ref_ptr<ModePass> passes[] = {
        detail::createModePass(SilhouetteShadowTechnique::SHADOW_MAP),
        detail::createModePass(SilhouetteShadowTechnique::SILHOUETTE_MAP),
        detail::createModePass(SilhouetteShadowTechnique::HYBRID),
        detail::createModePass(SilhouetteShadowTechnique::SHADOW_VOLUME)};
    return *passes[mode >= 0 && mode < 4 ? mode : 0];
}

/** Whether @p value is one property @p name takes (Properties); a warning naming the
 *  property, the value, its range and the value kept otherwise. */
template<typename T>
bool acceptValue(const char* name, T value, T kept)
{
    const NumericPropertyRange* range = numericPropertyRange(name);
    if (!range || inRange(*range, double(value))) return true;
    std::ostringstream text, keeping;
    text << value;
    keeping << kept;
    OSG_WARN << refusedValueMessage("osgShadowSilhouette", *range, text.str(), std::isfinite(double(value)),
                                    keeping.str())
             << std::endl;
    return false;
}

/** @p value if it is one of enum property @p name's values (Properties), else its default,
 *  with a warning naming the property, the number and the values it takes. */
template <typename E>
E acceptEnum(const char* name, E value)
{
    const PropertyInfo& p = *findProperty(name);
    if (isPropertyValue(p, double(value))) return value;
    const E fallback = static_cast<E>(static_cast<int>(p.defaultValue));
    OSG_WARN << "osgShadowSilhouette: " << name << " " << int(value) << " is not one of " << describePropertyValues(p)
             << "; using " << formatPropertyValue(p, double(fallback)) << std::endl;
    return fallback;
}

} // namespace

SilhouetteShadowTechnique::SilhouetteShadowTechnique() : _warnings(new detail::WarningLog) {}

SilhouetteShadowTechnique::SilhouetteShadowTechnique(Mode mode) : SilhouetteShadowTechnique()
{
    setMode(mode);
}

SilhouetteShadowTechnique::SilhouetteShadowTechnique(const SilhouetteShadowTechnique& copy, const osg::CopyOp& copyop)
    : osgShadow::ShadowTechnique(copy, copyop), _mode(copy._mode), _properties(copy._properties),
      _shadowMapSize(copy._shadowMapSize), _polygonOffsetFactor(copy._polygonOffsetFactor),
      _polygonOffsetUnits(copy._polygonOffsetUnits), _lightNum(copy._lightNum), _maxShadowLights(copy._maxShadowLights),
      _baseTextureUnit(copy._baseTextureUnit), _useDefaultShading(copy._useDefaultShading),
      _perPixelLighting(copy._perPixelLighting), _debugView(copy._debugView), _debugLight(copy._debugLight),
      _blockerCulling(copy._blockerCulling), _hybridMethod(copy._hybridMethod), _hybridEdgeMask(copy._hybridEdgeMask),
      _depthPrepass(copy._depthPrepass), _shadowRayOffset(copy._shadowRayOffset), _filter(copy._filter),
      _filterWindow(copy._filterWindow), _lightSize(copy._lightSize), _softSamples(copy._softSamples),
      _tuning(copy._tuning), _warnings(new detail::WarningLog)
{
}

SilhouetteShadowTechnique::~SilhouetteShadowTechnique() = default;

// ---------------------------------------------------------------------------------------
// Properties

const char* SilhouetteShadowTechnique::modeName(Mode mode)
{
    switch (mode)
    {
    case SHADOW_MAP: return "shadowmap";
    case SILHOUETTE_MAP: return "silhouette";
    case HYBRID: return "hybrid";
    case SHADOW_VOLUME: return "volume";
    }
    return "shadowmap";
}

bool SilhouetteShadowTechnique::modeFromName(const std::string& name, Mode& mode)
{
    for (const PropertyEnumValue& e : findProperty("Mode")->enumValues)
    {
        if (name == e.shortName || name == e.name)
        {
            mode = Mode(e.value);
            return true;
        }
    }
    return false;
}

void SilhouetteShadowTechnique::setMode(Mode mode)
{
    _mode = acceptEnum("Mode", mode);
    _renderedMode = -1;
}

SilhouetteShadowTechnique::Mode SilhouetteShadowTechnique::getEffectiveMode() const
{
    const int rendered = _renderedMode.load();
    return rendered < 0 ? _mode : Mode(rendered);
}

void SilhouetteShadowTechnique::setShadowMapSize(unsigned int size)
{
    if (acceptValue("ShadowMapSize", size, _properties.shadowMapSize)) _properties.shadowMapSize = size;
    if (applyShadowSettings()) dirty();
}

void SilhouetteShadowTechnique::setPolygonOffsetFactor(float factor)
{
    if (!acceptValue("PolygonOffsetFactor", factor, _polygonOffsetFactor)) return;
    _polygonOffsetFactor = factor < 0.0f ? AUTOMATIC_POLYGON_OFFSET_FACTOR : factor;
    dirty();
}

float SilhouetteShadowTechnique::getEffectivePolygonOffsetFactor(Mode mode) const
{
    if (_polygonOffsetFactor >= 0.0f) return _polygonOffsetFactor;
    return mode == HYBRID ? 0.0f : 1.1f;
}

void SilhouetteShadowTechnique::setPolygonOffsetUnits(float units)
{
    if (!acceptValue("PolygonOffsetUnits", units, _polygonOffsetUnits)) return;
    _polygonOffsetUnits = units;
    dirty();
}

void SilhouetteShadowTechnique::setLightNum(int lightNum)
{
    if (acceptValue("LightNum", lightNum, _properties.lightNum)) _properties.lightNum = lightNum;
    if (applyShadowSettings()) dirty();
}

void SilhouetteShadowTechnique::setMaxShadowLights(unsigned int count)
{
    if (!acceptValue("MaxShadowLights", count, _maxShadowLights)) return;
    _maxShadowLights = count;
    dirty();
}

void SilhouetteShadowTechnique::setBaseTextureUnit(unsigned int unit)
{
    if (!acceptValue("BaseTextureUnit", unit, _properties.baseTextureUnit)) return;
    _properties.baseTextureUnit = unit;
    applyShadowSettings();
    dirty();
}

void SilhouetteShadowTechnique::setUseDefaultShading(bool flag)
{
    _useDefaultShading = flag;
    dirty();
}

void SilhouetteShadowTechnique::setPerPixelLighting(bool flag)
{
    _perPixelLighting = flag;
}

void SilhouetteShadowTechnique::setDebugView(DebugView view)
{
    _properties.debugView = acceptEnum("DebugView", view);
    if (applyShadowSettings()) dirty();
}

void SilhouetteShadowTechnique::setDebugLight(unsigned int index)
{
    if (acceptValue("DebugLight", index, _debugLight)) _debugLight = index;
}

void SilhouetteShadowTechnique::setBlockerCulling(bool flag)
{
    _blockerCulling = flag;
}

void SilhouetteShadowTechnique::setHybridMethod(HybridMethod method)
{
    _hybridMethod = acceptEnum("HybridMethod", method);
}

void SilhouetteShadowTechnique::setHybridEdgeMask(bool flag)
{
    _hybridEdgeMask = flag;
}

void SilhouetteShadowTechnique::setDepthPrepass(DepthPrepass prepass)
{
    _depthPrepass = acceptEnum("DepthPrepass", prepass);
}

void SilhouetteShadowTechnique::setShadowRayOffset(float offset)
{
    if (acceptValue("ShadowRayOffset", offset, _shadowRayOffset)) _shadowRayOffset = offset;
}

void SilhouetteShadowTechnique::setFilter(Filter filter)
{
    _filter = acceptEnum("Filter", filter);
}

void SilhouetteShadowTechnique::setFilterWindow(unsigned int n)
{
    if (acceptValue("FilterWindow", n, _filterWindow)) _filterWindow = n;
}

void SilhouetteShadowTechnique::setLightSize(float size)
{
    if (acceptValue("LightSize", size, _lightSize)) _lightSize = size;
}

void SilhouetteShadowTechnique::setSoftSamples(unsigned int k)
{
    if (acceptValue("SoftSamples", k, _softSamples)) _softSamples = k;
}

bool SilhouetteShadowTechnique::usesDepthPrepass(Mode mode, bool triangleLists, std::size_t triangles,
                                                 unsigned int slots, double viewportPixels) const
{
    const bool mapModes = mode == SHADOW_MAP || mode == SILHOUETTE_MAP || (mode == HYBRID && triangleLists);
    if (!mapModes || _depthPrepass == DEPTH_PREPASS_OFF) return false;
    if (_depthPrepass == DEPTH_PREPASS_ON) return true;
    // The prepass transforms every triangle once more; it saves the eye pass's shading of
    // hidden fragments, whose cost grows with the slots each fragment evaluates.
    return mode == HYBRID && _useDefaultShading &&
           double(triangles) * PREPASS_PIXELS_PER_TRIANGLE <= double(slots) * viewportPixels;
}

SilhouetteShadowTechnique::Statistics SilhouetteShadowTechnique::getStatistics() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_statsMutex);
    return _statistics;
}

void SilhouetteShadowTechnique::recordStatistics(const Statistics& stats)
{
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_statsMutex);
        _statistics = stats;
    }
    osg::ref_ptr<osg::Stats> target;
    if (!_stats.lock(target)) return;
    const unsigned int frame = stats.frameNumber;
    if (stats.silhouettePixelPercent() >= 0.0)
        target->setAttribute(frame, STATS_SILHOUETTE_PIXEL_PERCENT, stats.silhouettePixelPercent());
    if (stats.volumeOverdraw() >= 0.0) target->setAttribute(frame, STATS_VOLUME_OVERDRAW, stats.volumeOverdraw());
    target->setAttribute(frame, STATS_BLOCKERS_SKIPPED, stats.blockersSkipped);
    target->setAttribute(frame, STATS_SILHOUETTE_EDGES, stats.silhouetteEdges);
    if (stats.penumbraPixels >= 0) target->setAttribute(frame, STATS_PENUMBRA_PIXELS, double(stats.penumbraPixels));
    if (stats.shadowRays >= 0) target->setAttribute(frame, STATS_SHADOW_RAYS, double(stats.shadowRays));
}

void SilhouetteShadowTechnique::warnOnce(int key, const std::string& message) const
{
    _warnings->once(key, message);
}

// ---------------------------------------------------------------------------------------
// init / update / cleanup

void SilhouetteShadowTechnique::init()
{
    if (!_shadowedScene) return;
    _shared = detail::createSharedResources(
        getEffectivePolygonOffsetFactor(SHADOW_MAP), _polygonOffsetUnits,
        [this](osg::Program* program) { linkShadowShaders(program); },
        [this](osg::Program* program) { watchProgramLink(program); });

    TagShaderDefinesVisitor tagger;
    for (unsigned int i = 0; i < _shadowedScene->getNumChildren(); ++i) _shadowedScene->getChild(i)->accept(tagger);
    _warnings->setAlphaTested({tagger.alphaTested.begin(), tagger.alphaTested.end()});
    _sizedLightSources = detail::findSizedLightSources(*_shadowedScene);

    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
        _viewDataMap.clear(); // rebuilt with the new settings on the next cull
    }
    _dirty = false;
}

void SilhouetteShadowTechnique::update(osg::NodeVisitor& nv)
{
    if (applyShadowSettings()) init(); // a new BaseShadowTextureUnit: the views' state anew
    if (_shadowedScene) _shadowedScene->osg::Group::traverse(nv);
}

void SilhouetteShadowTechnique::cleanSceneGraph()
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
    _viewDataMap.clear();
}

/** What releaseGLObjects() and resizeGLObjectBuffers() do to each holder of GL objects that
 *  applyToGLObjects() visits: both walk the same list, so neither can miss a holder. */
struct SilhouetteShadowTechnique::GLObjectsOp
{
    bool release = true;
    osg::State* state = nullptr; ///< release: the context's state, or every context (nullptr)
    unsigned int maxSize = 0;    ///< resize: the number of contexts

    template<class Holder>
    void operator()(Holder* holder) const
    {
        if (!holder) return;
        if (release)
            holder->releaseGLObjects(state);
        else
            holder->resizeGLObjectBuffers(maxSize);
    }
};

void SilhouetteShadowTechnique::applyToGLObjects(const GLObjectsOp& op) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
    ++_glGeneration; // the maps are rendered again before they are read
    if (_shared) _shared->forEachGLObjectHolder(op);
    op(_listedDrawables.get());
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> shaders(_shadowShadersMutex);
        op(_shadowFragmentShader.get());
        op(_silhouetteFragmentShader.get());
        op(_listTermFragmentShader.get());
        op(_screenVisibilityFragmentShader.get());
        op(_programLinkCheck.get());
    }
    for (const auto& entry : _viewDataMap) detail::forEachGLObjectHolder(*entry.second, op);
}

void SilhouetteShadowTechnique::resizeGLObjectBuffers(unsigned int maxSize)
{
    GLObjectsOp op;
    op.release = false;
    op.maxSize = maxSize;
    applyToGLObjects(op);
}

void SilhouetteShadowTechnique::releaseGLObjects(osg::State* state) const
{
    GLObjectsOp op;
    op.state = state;
    applyToGLObjects(op);
}

// ---------------------------------------------------------------------------------------
// Per-view data

ViewData* SilhouetteShadowTechnique::getViewData(osgUtil::CullVisitor& cv)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
    osg::ref_ptr<ViewData>& vd = _viewDataMap[&cv];
    if (!vd) vd = createViewData();
    return vd.get();
}

ViewData* SilhouetteShadowTechnique::createViewData()
{
    detail::ViewLayout layout;
    layout.slots = slotCapacity();
    layout.pairedSlots = slotCapacity(true);
    layout.baseUnit = _baseTextureUnit;
    layout.maxShadowLights = _maxShadowLights;
    layout.mapSize = _shadowMapSize;
    layout.mapBinding = mapBinding();
    layout.receiverProgram = _useDefaultShading ? _shared->receiverProgram.get() : nullptr;
    layout.litTexture = _shared->litDepthTexture.get();
    layout.prepassStateSet = _shared->createPrepassStateSet();
    return detail::createViewData(layout).release();
}

// ---------------------------------------------------------------------------------------
// Cull

void SilhouetteShadowTechnique::cull(osgUtil::CullVisitor& cv)
{
    if (_dirty || !_shared)
    {
        _shadowedScene->osg::Group::traverse(cv); // init() has not run yet (it runs in update)
        return;
    }
    clampMapSizeToContext(cv);
    ViewData& vd = *getViewData(cv);
    FrameContext frame;
    frame.mode = effectiveModeFor(cv);
    // The eye pass's configuration, filled in as the frame is planned and applied at the end.
    detail::EyePassPlan eye;
    eye.mode = frame.mode;
    eye.debugView = _debugView;
    eye.perPixelLighting = _perPixelLighting;
    // The receivers are culled first: a LightSource among them is known only afterwards. Their
    // pass state set gets the stencil modes' lighting program once the method is known.
    cullReceivers(cv, vd, vd.receiverPassStateSet.get());
    Statistics stats;
    const std::vector<FoundLight> lights = cullLights(cv, vd, stats);
    for (const FoundLight& found : lights) frame.sizedLights = frame.sizedLights || found.description.size > 0.0;
    stats.effectiveMode = frame.mode;
    _renderedMode = int(frame.mode);
    if (lights.empty()) warnOnce(WARN_NO_LIGHT, "no positional light (osg::LightSource) in the view; nothing to shadow");
    else prepareFrame(cv, frame);
    detail::warnAboutMissingLights(lights, _lightNum, _debugView != DEBUG_NONE, _debugLight, warner());
    const SlotPlan plan = planSlots(frame, lights, stats);
    stats.silhouetteCasters = static_cast<unsigned int>(frame.casterList.size());

    // The mode's passes: its method and configuration, its passes per slot, then over the eye.
    const detail::PassSettings settings = passSettings(frame.mode);
    detail::PassServices services;
    services.warnOnce = warner();
    services.cullReceivers = [&](osg::StateSet* pass) { cullReceivers(cv, vd, pass); };
    services.applicationPrograms = [this]() { return hasApplicationPrograms(); };
    services.warnAlphaTested = [log = _warnings.get()](bool hybrid, bool lists) { log->alphaTested(hybrid, lists); };
    ModeFrame mf{cv, vd, frame, stats, eye, settings, services};
    ModePass& mode = modePassFor(frame.mode);
    warnFilterMode(frame.mode);
    mode.planFrame(mf);
    prepareEyePass(mf);
    cullShadowSlots(mf, mode, lights, plan);
    mode.cullEyePasses(mf, lights, plan.slots);
    detail::updateViewUniforms(cv, vd, lights, plan.slots, eye);
    vd.maskLight->set(static_cast<int>(_debugLight));
    detail::updateRayFrames(cv, vd, _shadowedScene ? _shadowedScene->getBound() : osg::BoundingSphere(),
                            _shadowRayOffset);
    finishEyePass(mf);
}

std::vector<FoundLight> SilhouetteShadowTechnique::cullLights(osgUtil::CullVisitor& cv, ViewData& vd, Statistics& stats)
{
    std::vector<int> refused;
    std::vector<FoundLight> lights =
        detail::collectLights(cv, refused, [&](const osg::Light& light, const std::string& refusal) {
            _warnings->refusedLight(cv.getNodePath().empty() ? nullptr : cv.getNodePath().front(), light, refusal);
        });
    // The receiver shading lights only the lights found (oss_lightIndex); drawables under a
    // program of their own, or all with UseDefaultShading false, are lit by OpenGL, which
    // would spread a refused light's NaN: its GL light is turned off for them.
    for (int num = 0; num < shader::MAX_SCENE_LIGHTS; ++num)
    {
        if (std::find(refused.begin(), refused.end(), num) != refused.end())
            vd.receiverStateSet->setMode(GL_LIGHT0 + num, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
        else
            vd.receiverStateSet->removeMode(GL_LIGHT0 + num);
    }
    for (FoundLight& found : lights)
    {
        std::string refusal;
        found.description.size =
            detail::lightSize(*found.light, _sizedLightSources.get(), found.description.type, _lightSize, refusal);
        if (!refusal.empty()) _warnings->refusedLightSize(*found.light, refusal);
    }
    stats.frameNumber = cv.getFrameStamp() ? cv.getFrameStamp()->getFrameNumber() : 0;
    stats.lightsFound = static_cast<unsigned int>(lights.size());
    return lights;
}

SlotPlan SilhouetteShadowTechnique::planSlots(FrameContext& frame, const std::vector<FoundLight>& lights,
                                              Statistics& stats) const
{
    detail::SlotBudget budget;
    budget.lightNum = _lightNum;
    budget.maxShadowLights = _maxShadowLights;
    budget.mapSize = _shadowMapSize;
    budget.slotLimit = slotCapacity(pairedSlots(frame.mode));
    budget.cubeFaces = frame.mode != SHADOW_VOLUME; // the volumes reach every direction
    if (frame.mode == SHADOW_MAP || (frame.mode == SILHOUETTE_MAP && _filter == FILTER_SILHOUETTE))
        budget.faceMarginTexels = detail::filterReachTexels(_filter, _filterWindow);
    // HYBRID's shadow rays to a light with a size reach as far as PCSS's taps.
    if (frame.mode == HYBRID && frame.sizedLights) budget.faceMarginTexels = detail::filterReachTexels(FILTER_PCSS, 1);
    SlotPlan plan = detail::planSlots(frame, lights, budget, warner(), stats.lightsSkipped);
    frame.slotsInUse = plan.slotsInUse;
    return plan;
}

detail::Warn SilhouetteShadowTechnique::warner() const
{
    return [log = _warnings.get()](int key, const std::string& message) { log->once(key, message); };
}

detail::PassSettings SilhouetteShadowTechnique::passSettings(Mode rendered) const
{
    detail::PassSettings s;
    s.mode = _mode;
    s.shadowMapSize = _shadowMapSize;
    s.glGeneration = getGLGeneration();
    s.polygonOffsetFactor = getEffectivePolygonOffsetFactor(rendered);
    s.polygonOffsetUnits = _polygonOffsetUnits;
    s.blockerCulling = _blockerCulling;
    s.hybridEdgeMask = _hybridEdgeMask;
    s.hybridMethod = _hybridMethod;
    s.debugView = _debugView;
    s.debugLight = _debugLight;
    s.filter = _filter;
    s.filterWindow = _filterWindow;
    s.softSamples = _softSamples;
    s.tuning = _tuning;
    s.listSlots = listSlots();
    s.recordingStats = _stats.valid();
    s.shadowedScene = _shadowedScene;
    s.silhouetteMapStateSet = _shared->silhouetteMapStateSet.get();
    s.listStateSet = _shared->listStateSet.get();
    s.listFrontOnlyStateSet = _shared->listFrontOnlyStateSet.get();
    s.listedDrawables = _listedDrawables.get();
    s.stencilProgram = _shared->stencilProgram.get();
    s.volumeProgram = _shared->volumeProgram.get();
    s.defaultSilhouetteTexture = _shared->defaultSilhouetteTexture.get();
    s.defaultNeighbourhoodTexture = _shared->defaultNeighbourhoodTexture.get();
    s.distanceMapStateSet = _shared->distanceMapStateSet.get();
    s.defaultDistanceTexture = _shared->defaultDistanceTexture.get();
    return s;
}

void SilhouetteShadowTechnique::warnFilterMode(Mode mode) const
{
    // FILTER_PCF and FILTER_PCSS are SHADOW_MAP's, FILTER_SILHOUETTE is SILHOUETTE_MAP's.
    const Mode owner = _filter == FILTER_SILHOUETTE ? SILHOUETTE_MAP : SHADOW_MAP;
    if (_filter == FILTER_PCF_2X2 || mode == owner) return;
    warnOnce(detail::WARN_FILTER_MODE,
             "Filter " + formatPropertyValue(*findProperty("Filter"), _filter) + " applies to " +
                 (owner == SHADOW_MAP ? "SHADOW_MAP" : "SILHOUETTE_MAP") + " only; mode " + modeName(mode) +
                 " renders its own " +
                 (mode == HYBRID ? "shadows (soft by its shadow rays under a light with a size)" : "hard shadows"));
}

void SilhouetteShadowTechnique::prepareEyePass(ModeFrame& mf)
{
    osgUtil::CullVisitor& cv = mf.cv;
    ViewData& vd = mf.vd;
    const FrameContext& frame = mf.frame;
    if (frame.stencil && !vd.stencil)
        vd.stencil = new StencilShadowPasses(_shared->stencilProgram.get(), _shared->volumeProgram.get());
    if (frame.stencil)
        vd.receiverPassStateSet->setAttributeAndModes(_shared->stencilProgram.get(),
                                                      osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    else
        vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::PROGRAM);
    // The GLSL 4.30 shaders join the receivers' programs only where the context runs them.
    const osg::GLExtensions* ext = cv.getState() ? osg::GLExtensions::Get(cv.getState()->getContextID(), false) : nullptr;
    if (ext && ext->glVersion >= 4.3f)
        vd.receiverStateSet->setDefine(shader::DEFINE_GLSL_430);
    else
        vd.receiverStateSet->removeDefine(shader::DEFINE_GLSL_430);
    mf.stats.screenVisibility = detail::cullScreenVisibility(mf);
    std::size_t casterTriangles = 0;
    for (const Caster& caster : frame.casterList) casterTriangles += caster.mesh->getAdjacency().report.inputTriangles;
    const osg::Viewport* eyeViewport = cv.getViewport();
    mf.stats.depthPrepass =
        usesDepthPrepass(frame.mode, frame.triangleLists, casterTriangles, std::max(1u, frame.slotsInUse),
                         eyeViewport ? eyeViewport->width() * eyeViewport->height() : 0.0);
    if (mf.stats.depthPrepass)
        detail::cullDepthPrepass(cv, vd, [&](osg::StateSet* pass) { cullReceivers(cv, vd, pass); });
    else
        vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::DEPTH);
}

void SilhouetteShadowTechnique::cullShadowSlots(ModeFrame& mf, ModePass& mode, const std::vector<FoundLight>& lights,
                                                const SlotPlan& plan)
{
    ViewData& vd = mf.vd;
    const bool paired = pairedSlots(mf.frame.mode);
    const unsigned int capacity = slotCapacity(paired);
    mf.eye.slotCapacity = capacity;
    // SILHOUETTE_MAP's eye pass reads neighbourhood maps (usampler2D), HYBRID's the edge masks.
    osg::Texture2D* second = mode.defaultSecondMap(mf.settings);
    std::vector<osg::Texture2D*> secondMaps(capacity, second ? second : _shared->defaultSilhouetteTexture.get());
    osg::Texture2D* fallback = _shared->defaultSilhouetteTexture.get();
    detail::resetSlots(vd, capacity, _shared->litTexture(mode.rawDepthMaps(mf.settings)));
    // The second maps' units; in SHADOW_MAP they hold the depth maps bound above.
    if (paired) detail::bindSecondMaps(vd, second ? secondMaps : std::vector<osg::Texture2D*>(), fallback);
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (plan.slots[i] < 0) continue;
        ++mf.stats.lightsShadowed;
        cullLight(mf, mode, lights[i].description, static_cast<unsigned int>(plan.slots[i]), plan.frusta[i],
                  plan.firstFaceSlot[i], secondMaps);
    }
    if (second) detail::bindSecondMaps(vd, secondMaps, fallback);
}

void SilhouetteShadowTechnique::finishEyePass(ModeFrame& mf)
{
    ViewData& vd = mf.vd;
    detail::applyEyePassDefines(*vd.receiverStateSet, detail::eyePassDefines(mf.eye));
    // A mask is 0 or 1: a blended scene (an alpha-tested tree that also blends) must not
    // mix it with what lies behind. The alpha still reaches the scene's osg::AlphaFunc.
    if (_debugView == DEBUG_SHADOW_MASK || _debugView == DEBUG_CLASSES || _debugView == DEBUG_VISIBILITY)
        vd.receiverStateSet->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    else
        vd.receiverStateSet->removeMode(GL_BLEND);
    cullProgramLinkCheck(mf.cv);
    if (const osg::Viewport* viewport = mf.cv.getViewport())
        mf.stats.viewportPixels = static_cast<unsigned int>(viewport->width() * viewport->height());
    recordStatistics(mf.stats);
}

unsigned int SilhouetteShadowTechnique::slotCapacity(bool paired) const
{
    // One texture unit per slot (depth map), or two (and a silhouette map), from
    // BaseTextureUnit, within the 32 image units of a fragment stage; never fewer than the
    // light budget.
    const unsigned int units = _baseTextureUnit < 32 ? 32 - _baseTextureUnit : 0;
    return paired ? std::max(_maxShadowLights, std::min<unsigned int>(shader::MAX_PAIRED_SLOTS, units / 2))
                  : std::max(_maxShadowLights, std::min<unsigned int>(shader::MAX_SHADOW_SLOTS, units));
}

unsigned int SilhouetteShadowTechnique::listSlots() const
{
    // Every slot can have lists: they take no texture unit, one shader storage block each.
    return std::min<unsigned int>(shader::MAX_LIST_SLOTS, slotCapacity(true));
}

void SilhouetteShadowTechnique::prepareFrame(osgUtil::CullVisitor& cv, FrameContext& frame)
{
    detail::gatherFrame(cv, *_shadowedScene, *_meshCache, _maximumShadowDistance, frame);
    for (const osg::Drawable* drawable : frame.nonFinite) _warnings->nonFinite(*drawable);
}

void SilhouetteShadowTechnique::cullLight(ModeFrame& mf, ModePass& mode, const LightDescription& light,
                                          unsigned int slot, const std::vector<LightFrustum>& frusta,
                                          unsigned int firstFaceSlot, std::vector<osg::Texture2D*>& secondMaps)
{
    ViewData& vd = mf.vd;
    if (!frusta.front().valid)
    {
        vd.passes[slot].frustum = LightFrustum();
        ++mf.stats.lightsSkipped; // nothing can shadow what this view sees
        return;
    }
    for (std::size_t k = 0; k < frusta.size(); ++k)
    {
        const unsigned int s = k == 0 ? slot : firstFaceSlot + static_cast<unsigned int>(k - 1);
        vd.slotOwner->setElement(s, int(slot));
        vd.slotCore->setElement(s, float(frusta[k].faceCore));
        cullSlot(mf, mode, light, s, frusta[k], secondMaps[s]);
    }
}

void SilhouetteShadowTechnique::cullSlot(ModeFrame& mf, ModePass& mode, const LightDescription& light,
                                         unsigned int slot, const LightFrustum& frustum, osg::Texture2D*& secondMap)
{
    ViewData& vd = mf.vd;
    LightPass& pass = vd.passes[slot];
    detail::fitDepthMap(pass, slot, _shadowMapSize, mode.rawDepthMaps(mf.settings), *_shared->depthPassStateSet,
                        _shadowedScene);
    pass.frustum = frustum;
    if (!mode.drawsMaps()) return; // volumes only, no map
    vd.slotInUse[slot] = true;
    detail::SlotCull cull{light, slot, pass, detail::cullDepthMap(mf, mode, pass, light), secondMap};
    detail::bindDepthMap(vd, slot, pass.depthTexture.get());
    mode.cullSlot(mf, cull);
    // A cube face whose newest build (this light, these casters) drew no caster shadows
    // nothing: the eye pass leaves it out. The counts come back a frame or two late; until
    // then, and in every frame that rebuilds, the face is evaluated. Not the stencil passes.
    const FrameContext& frame = mf.frame;
    vd.slotSkipped[slot] = _tuning.skipEmptyFaces && !frame.stencil && frustum.faceCore > 0.0 &&
                           (frame.triangleLists ? pass.listPass && pass.listPass->listedNothing()
                                                : pass.samples->drewNothing());
    if (vd.slotSkipped[slot]) ++mf.stats.slotsSkipped;
    if (pass.samples->getEnabled() && pass.samples->pending()) pass.samples->getPollNode()->accept(mf.cv);
}

void SilhouetteShadowTechnique::clampMapSizeToContext(osgUtil::CullVisitor& cv)
{
    // GLExtensions holds GL_MAX_TEXTURE_SIZE once the context has been made current: no
    // query here. Before that (the very first frame) nothing is clamped.
    const osg::State* state = cv.getState();
    const osg::GLExtensions* ext = state ? osg::GLExtensions::Get(state->getContextID(), false) : nullptr;
    if (!ext || ext->maxTextureSize <= 0 || _shadowMapSize <= static_cast<unsigned int>(ext->maxTextureSize)) return;
    warnOnce(WARN_CONTEXT_MAP_SIZE, "ShadowMapSize " + std::to_string(_shadowMapSize) +
                                        " exceeds the context's GL_MAX_TEXTURE_SIZE (" +
                                        std::to_string(ext->maxTextureSize) + "); clamped to it");
    if (_properties.shadowMapSize == _shadowMapSize) _properties.shadowMapSize = static_cast<unsigned int>(ext->maxTextureSize);
    _shadowMapSize = static_cast<unsigned int>(ext->maxTextureSize);
}

void SilhouetteShadowTechnique::cullReceivers(osgUtil::CullVisitor& cv, ViewData& vd, osg::StateSet* pass)
{
    detail::cullReceivers(cv, *_shadowedScene, vd, pass);
}

SilhouetteShadowTechnique::Mode SilhouetteShadowTechnique::effectiveModeFor(osgUtil::CullVisitor& cv) const
{
    const Mode mode = _mode;
    if (mode != SHADOW_VOLUME && mode != HYBRID) return mode;
    const osg::State* state = cv.getState();
    const osg::GraphicsContext* gc = state ? state->getGraphicsContext() : nullptr;
    const osg::GraphicsContext::Traits* traits = gc ? gc->getTraits() : nullptr;
    if (!traits || traits->stencil > 0) return mode;
    warnOnce(WARN_NO_STENCIL, std::string("Mode ") + modeName(mode) +
                                  " needs a stencil buffer and the graphics context has none (call "
                                  "osg::DisplaySettings::instance()->setMinimumNumStencilBits(8) before creating "
                                  "it, or run osgviewer with --stencil); rendering SHADOW_MAP");
    return SHADOW_MAP;
}

} // namespace osgShadowSilhouette
