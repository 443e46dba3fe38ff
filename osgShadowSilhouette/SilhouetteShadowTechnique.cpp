#include <osgShadowSilhouette/SilhouetteShadowTechnique>
#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/ShaderConstants>

#include "FrameData.h"
#include "LightPlanning.h"
#include "SceneVisitors.h"
#include "SharedResources.h"
#include "SoftFilter.h"
#include "TechniqueCull.h"
#include "ViewState.h"
#include "Warnings.h"

#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace osgShadowSilhouette {

namespace {

using detail::TagShaderDefinesVisitor;
using detail::ViewData;
using namespace detail; // WarningKey

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
      _polygonOffsetUnits(copy._polygonOffsetUnits), _perspectiveWarp(copy._perspectiveWarp), _cascades(copy._cascades),
      _lightNum(copy._lightNum), _maxShadowLights(copy._maxShadowLights), _baseTextureUnit(copy._baseTextureUnit),
      _useDefaultShading(copy._useDefaultShading), _perPixelLighting(copy._perPixelLighting),
      _debugView(copy._debugView), _debugLight(copy._debugLight), _blockerCulling(copy._blockerCulling),
      _hybridMethod(copy._hybridMethod), _gpuExtraction(copy._gpuExtraction), _hybridEdgeMask(copy._hybridEdgeMask),
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

float SilhouetteShadowTechnique::getEffectivePolygonOffsetFactor(Mode mode, bool warpedMap) const
{
    if (_polygonOffsetFactor >= 0.0f) return _polygonOffsetFactor;
    if (mode == HYBRID) return 0.0f;
    return mode == SHADOW_MAP && warpedMap ? 2.0f : 1.1f;
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

void SilhouetteShadowTechnique::setPerspectiveWarp(bool flag)
{
    _perspectiveWarp = flag;
}

void SilhouetteShadowTechnique::setCascades(unsigned int count)
{
    if (acceptValue("Cascades", count, _cascades)) _cascades = count;
}

bool SilhouetteShadowTechnique::warpsMaps(Mode mode) const
{
    if (!_perspectiveWarp) return false;
    if (mode == HYBRID) return true; // but not under a light with a size (TechniqueCull)
    return (mode == SHADOW_MAP || mode == SILHOUETTE_MAP) && (_filter == FILTER_PCF_2X2 || _filter == FILTER_PCF);
}

void SilhouetteShadowTechnique::setBlockerCulling(bool flag)
{
    _blockerCulling = flag;
}

void SilhouetteShadowTechnique::setHybridMethod(HybridMethod method)
{
    _hybridMethod = acceptEnum("HybridMethod", method);
}

void SilhouetteShadowTechnique::setGpuExtraction(GpuExtraction extraction)
{
    _gpuExtraction = acceptEnum("GpuExtraction", extraction);
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
// Cull: the order of the passes (TechniqueCull.cpp holds each step)

void SilhouetteShadowTechnique::cull(osgUtil::CullVisitor& cv)
{
    if (_dirty || !_shared)
    {
        _shadowedScene->osg::Group::traverse(cv); // init() has not run yet (it runs in update)
        return;
    }
    detail::TechniqueCull frame(*this, cv);
    // The receivers first: a LightSource among them is known only afterwards.
    frame.cullReceivers();
    frame.cullLights();
    frame.planSlots();
    // The mode's passes: its method and configuration, its passes per slot, then over the eye.
    frame.planMode();
    frame.prepareEyePass();
    frame.cullShadowSlots();
    frame.cullEyePasses();
    frame.finishEyePass();
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

void SilhouetteShadowTechnique::prepareFrame(osgUtil::CullVisitor& cv, detail::FrameContext& frame)
{
    detail::gatherFrame(cv, *_shadowedScene, *_meshCache, _maximumShadowDistance, frame);
    for (const osg::Drawable* drawable : frame.nonFinite) _warnings->nonFinite(*drawable);
}

void SilhouetteShadowTechnique::cullReceivers(osgUtil::CullVisitor& cv, detail::ViewData& vd, osg::StateSet* pass)
{
    detail::cullReceivers(cv, *_shadowedScene, vd, pass, _shared ? _shared->casterStages.get() : nullptr,
                          _listedDrawables.get(), readsEyeDepth());
}

bool SilhouetteShadowTechnique::readsEyeDepth() const
{
    return _mode == SHADOW_VOLUME || (_mode == HYBRID && _hybridMethod == HYBRID_STENCIL_VOLUMES);
}

detail::Warn SilhouetteShadowTechnique::warner() const
{
    return [log = _warnings.get()](int key, const std::string& message) { log->once(key, message); };
}

} // namespace osgShadowSilhouette
