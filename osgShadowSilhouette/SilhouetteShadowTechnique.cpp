#include <osgShadowSilhouette/SilhouetteShadowTechnique>
#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/ShaderConstants>

#include "EyePass.h"
#include "RenderLeaves.h"
#include "ScreenVisibility.h"
#include "SceneVisitors.h"
#include "ShaderSource.h"

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/ComputeBoundsVisitor>
#include <osg/LightSource>
#include <osg/BufferIndexBinding>
#include <osg/CullFace>
#include <osg/GLExtensions>
#include <osg/Image>
#include <osg/BindImageTexture>
#include <osg/PolygonOffset>
#include <osg/Viewport>
#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>
#include <osgUtil/RenderStage>
#include <osgUtil/StateGraph>

#include <algorithm>
#include <unordered_set>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>

namespace osgShadowSilhouette {

namespace {

using detail::boundsOf;
using detail::CasterSignatureVisitor;
using detail::prunePrepass;
using detail::TagShaderDefinesVisitor;
using detail::TraverseShadowedSceneCallback;

constexpr unsigned int MAX_MAP_SIZE = 16384;

/** The eye pass's own bindings (shadow maps, silhouette maps and edge masks, HYBRID's lists)
 *  win over the model's state on the same units: a model's texture on a map's unit would
 *  replace the map, its image or storage-buffer binding the lists. The receiver shading reads
 *  none of the model's units there; a program of the model's own that does needs another
 *  BaseTextureUnit. The maps' textures give up OVERRIDE where the ShadowSettings'
 *  UseOverrideForShadowMapTexture is false (mapBinding()). */
constexpr unsigned int EYE_PASS_BINDING = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;

/** Whether @p value is one property @p name takes (PropertyRanges); a warning naming the
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

enum WarningKey
{
    WARN_OVER_BUDGET = 1,
    WARN_NO_LIGHT,
    WARN_MAP_SIZE,
    WARN_NO_STENCIL,
    WARN_FACE_SLOTS,
    WARN_NO_TRIANGLE_LISTS,
    WARN_LIST_SLOTS,
    WARN_LIST_OVERFLOW,
    WARN_LIST_FULL,
    WARN_CONTEXT_MAP_SIZE,
    WARN_LIGHT_NUM,
    WARN_DEBUG_LIGHT,
    WARN_SCREEN_VISIBILITY,
    WARN_BLENDED_VISIBILITY,
};

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


} // namespace

SilhouetteShadowTechnique::SilhouetteShadowTechnique() = default;

SilhouetteShadowTechnique::SilhouetteShadowTechnique(Mode mode)
{
    setMode(mode);
}

SilhouetteShadowTechnique::SilhouetteShadowTechnique(const SilhouetteShadowTechnique& copy, const osg::CopyOp& copyop)
    : osgShadow::ShadowTechnique(copy, copyop),
      _mode(copy._mode),
      _properties(copy._properties),
      _shadowMapSize(copy._shadowMapSize),
      _polygonOffsetFactor(copy._polygonOffsetFactor),
      _polygonOffsetUnits(copy._polygonOffsetUnits),
      _lightNum(copy._lightNum),
      _maxShadowLights(copy._maxShadowLights),
      _baseTextureUnit(copy._baseTextureUnit),
      _useDefaultShading(copy._useDefaultShading),
      _perPixelLighting(copy._perPixelLighting),
      _debugView(copy._debugView),
      _debugLight(copy._debugLight),
      _blockerCulling(copy._blockerCulling),
      _hybridMethod(copy._hybridMethod),
      _hybridEdgeMask(copy._hybridEdgeMask),
      _depthPrepass(copy._depthPrepass),
      _shadowRayOffset(copy._shadowRayOffset),
      _tuning(copy._tuning)
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
    static const struct { const char* a; const char* b; Mode m; } names[] = {
        {"shadowmap", "SHADOW_MAP", SHADOW_MAP},
        {"silhouette", "SILHOUETTE_MAP", SILHOUETTE_MAP},
        {"hybrid", "HYBRID", HYBRID},
        {"volume", "SHADOW_VOLUME", SHADOW_VOLUME},
    };
    for (const auto& n : names)
    {
        if (name == n.a || name == n.b)
        {
            mode = n.m;
            return true;
        }
    }
    return false;
}

void SilhouetteShadowTechnique::setMode(Mode mode)
{
    if (mode < SHADOW_MAP || mode > SHADOW_VOLUME)
    {
        OSG_WARN << "osgShadowSilhouette: Mode " << int(mode) << " is not a mode; using SHADOW_MAP" << std::endl;
        mode = SHADOW_MAP;
    }
    _mode = mode;
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
    _properties.debugView = (view >= DEBUG_NONE && view <= DEBUG_CLASSES) ? view : DEBUG_NONE;
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
    _hybridMethod = (method >= HYBRID_AUTO && method <= HYBRID_TRIANGLE_LISTS) ? method : HYBRID_AUTO;
}

void SilhouetteShadowTechnique::setHybridEdgeMask(bool flag)
{
    _hybridEdgeMask = flag;
}

void SilhouetteShadowTechnique::setDepthPrepass(DepthPrepass prepass)
{
    _depthPrepass = (prepass >= DEPTH_PREPASS_AUTO && prepass <= DEPTH_PREPASS_OFF) ? prepass : DEPTH_PREPASS_AUTO;
}

void SilhouetteShadowTechnique::setShadowRayOffset(float offset)
{
    if (acceptValue("ShadowRayOffset", offset, _shadowRayOffset)) _shadowRayOffset = offset;
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
}

void SilhouetteShadowTechnique::warnNonFinite(const osg::Drawable& drawable) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_warnMutex);
    if (!_warnedNonFinite.insert(&drawable).second) return;
    OSG_WARN << "osgShadowSilhouette: geometry \"" << drawable.getName()
             << "\" has vertices with NaN or infinite coordinates; it casts no shadow" << std::endl;
}

void SilhouetteShadowTechnique::warnRefusedLight(osgUtil::CullVisitor& cv, const osg::Light& light,
                                                 const std::string& refusal) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_warnMutex);
    if (!_warnedLights.insert(&light).second) return;
    struct FindSource : public osg::NodeVisitor
    {
        explicit FindSource(const osg::Light* l) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), light(l)
        {
            setNodeMaskOverride(~0u);
        }
        void apply(osg::LightSource& ls) override
        {
            if (ls.getLight() == light && !found) found = &ls;
            traverse(ls);
        }
        const osg::Light* light;
        const osg::LightSource* found = nullptr;
    } find(&light);
    if (!cv.getNodePath().empty()) cv.getNodePath().front()->accept(find);
    const std::string source = !find.found                   ? "no LightSource found"
                               : find.found->getName().empty() ? "an unnamed LightSource"
                                                               : "LightSource \"" + find.found->getName() + "\"";
    OSG_WARN << "osgShadowSilhouette: light " << light.getLightNum() << " (" << source << ") has a non-finite "
             << refusal << "; it lights nothing and casts no shadow" << std::endl;
}

void SilhouetteShadowTechnique::warnOnce(int key, const std::string& message) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_warnMutex);
    if (_warned[key]) return;
    _warned[key] = true;
    OSG_WARN << "osgShadowSilhouette: " << message << std::endl;
}

// ---------------------------------------------------------------------------------------
// init / update / cleanup

void SilhouetteShadowTechnique::init()
{
    if (!_shadowedScene) return;

    _receiverProgram = new osg::Program;
    _receiverProgram->setName("osgShadowSilhouette receiver");
    _receiverProgram->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_RECEIVER_VERT));
    _receiverProgram->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_RECEIVER_FRAG));
    linkShadowShaders(_receiverProgram.get());
    _listStateSet = TriangleListPass::createSharedStateSet();
    _listFrontOnlyStateSet = new osg::StateSet;
    _listFrontOnlyStateSet->addUniform(new osg::Uniform(shader::LIST_FRONT_ONLY, true));
    _silhouetteMapStateSet = SilhouetteMapPass::createSharedStateSet();
    _defaultSilhouetteTexture = SilhouetteMapPass::createDefaultTexture();
    _defaultNeighbourhoodTexture = SilhouetteMapPass::createDefaultNeighbourhoodTexture();
    _litRawDepthTexture = SilhouetteMapPass::createLitDepthTexture();

    _stencilProgram = new osg::Program;
    _stencilProgram->setName("osgShadowSilhouette stencil passes");
    _stencilProgram->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_RECEIVER_VERT));
    _stencilProgram->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_STENCIL_FRAG));
    linkShadowShaders(_stencilProgram.get());
    // The lighting equation in the receivers' vertex and fragment stages, one source
    // (PerPixelLighting chooses where it runs).
    for (const osg::ref_ptr<osg::Shader>& lighting :
         {detail::loadShader(osg::Shader::VERTEX, shader::FILE_LIGHTING),
          detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_LIGHTING),
          detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_FRAGMENT_LIGHTING)})
    {
        _receiverProgram->addShader(lighting.get());
        _stencilProgram->addShader(lighting.get());
    }
    _volumeProgram = new osg::Program;
    _volumeProgram->setName("osgShadowSilhouette shadow volumes");
    _volumeProgram->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_VOLUME_VERT));
    _volumeProgram->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_VOLUME_FRAG));

    _depthPassStateSet = createDepthPassStateSet();
    _prepassProgram = new osg::Program;
    _prepassProgram->setName("osgShadowSilhouette depth prepass");
    _prepassProgram->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_DEPTH_VERT));
    _prepassProgram->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_DEPTH_FRAG));
    _litDummyTexture = createLitTexture();
    for (osg::Program* program : {_volumeProgram.get(), _prepassProgram.get()}) watchProgramLink(program);
    for (osg::StateSet* ss : {_depthPassStateSet.get(), _listStateSet.get(), _silhouetteMapStateSet.get(),
                              dynamic_cast<osg::StateSet*>(_silhouetteMapStateSet->getUserData())})
        if (ss) watchProgramLink(dynamic_cast<osg::Program*>(ss->getAttribute(osg::StateAttribute::PROGRAM)));

    TagShaderDefinesVisitor tagger;
    for (unsigned int i = 0; i < _shadowedScene->getNumChildren(); ++i) _shadowedScene->getChild(i)->accept(tagger);
    _alphaTested.assign(tagger.alphaTested.begin(), tagger.alphaTested.end());

    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
        _viewDataMap.clear(); // rebuilt with the new settings on the next cull
    }
    _dirty = false;
}

osg::ref_ptr<osg::StateSet> SilhouetteShadowTechnique::createPrepassStateSet() const
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setAttributeAndModes(_prepassProgram.get(), overrideOn); // ftransform(), as the receivers' program
    ss->setAttribute(new osg::ColorMask(false, false, false, false), overrideOn);
    ss->addUniform(new osg::Uniform(shader::BASE_TEXTURE, 0)); // alpha-tested receivers' cut-outs
    ss->setRenderBinDetails(DEPTH_PREPASS_BIN, "RenderBin", osg::StateSet::OVERRIDE_RENDERBIN_DETAILS);
    return ss;
}

osg::ref_ptr<osg::StateSet> SilhouetteShadowTechnique::createDepthPassStateSet() const
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("osgShadowSilhouette depth");
    program->addShader(detail::loadShader(osg::Shader::VERTEX, shader::FILE_DEPTH_VERT));
    program->addShader(detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_DEPTH_FRAG));
    ss->setAttributeAndModes(program.get(), overrideOn);
    ss->setAttributeAndModes(new osg::PolygonOffset(getEffectivePolygonOffsetFactor(SHADOW_MAP), _polygonOffsetUnits),
                             overrideOn); // each pass sets its mode's factor (cullLightPasses)
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

void SilhouetteShadowTechnique::warnAlphaTested(bool hybrid, bool lists) const
{
    // One message per mode for the drawables not yet named in it: a forest of billboards is
    // hundreds of alpha-tested drawables.
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_warnMutex);
    std::vector<std::string> names;
    std::size_t count = 0, unnamed = 0;
    for (const osg::observer_ptr<osg::Drawable>& weak : _alphaTested)
    {
        osg::ref_ptr<osg::Drawable> drawable;
        const int variant = hybrid ? (lists ? 2 : 1) : 0;
        if (!weak.lock(drawable) || !_warnedAlphaTested.insert({variant, drawable.get()}).second) continue;
        ++count;
        if (drawable->getName().empty())
            ++unnamed;
        else
            names.push_back("'" + drawable->getName() + "'");
    }
    if (count == 0) return;
    constexpr std::size_t shown = 4;
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < shown; ++i) list += (i ? ", " : "") + names[i];
    if (names.size() > shown) list += " and " + std::to_string(names.size() - shown) + " more named";
    if (unnamed > 0) list += (list.empty() ? "" : ", ") + std::to_string(unnamed) + " unnamed";
    OSG_WARN << "osgShadowSilhouette: " << (hybrid ? "HYBRID" : "SHADOW_VOLUME") << ": " << count
             << (count == 1 ? " drawable is" : " drawables are") << " alpha-tested (GL_ALPHA_TEST): " << list << "; "
             << (!hybrid ? "stencil shadow volumes cannot cut their shapes out, so they cast their whole triangles"
                 : lists  ? "where only their triangles stand between a silhouette pixel and the light, the triangle "
                            "lists keep the shadow map's answer there, not an exact one"
                          : "the stencil volumes of the exact test take their triangles as opaque, so light through "
                            "their cut-outs is lost along the shadows' edges")
             << " (SHADOW_MAP and SILHOUETTE_MAP cast the cut-out shapes)" << std::endl;
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
    op(_receiverProgram.get());
    op(_depthPassStateSet.get());
    op(_prepassProgram.get());
    op(_litDummyTexture.get());
    op(_silhouetteMapStateSet.get());
    op(_defaultSilhouetteTexture.get());
    op(_defaultNeighbourhoodTexture.get());
    op(_litRawDepthTexture.get());
    op(_listStateSet.get());
    op(_listFrontOnlyStateSet.get());
    op(_listedDrawables.get());
    op(_stencilProgram.get());
    op(_volumeProgram.get());
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> shaders(_shadowShadersMutex);
        op(_shadowFragmentShader.get());
        op(_silhouetteFragmentShader.get());
        op(_listTermFragmentShader.get());
        op(_screenVisibilityFragmentShader.get());
        op(_programLinkCheck.get());
    }
    for (const auto& entry : _viewDataMap)
    {
        ViewData& vd = *entry.second;
        op(vd.receiverStateSet.get());
        op(vd.receiverPassStateSet.get());
        op(vd.prepassStateSet.get());
        op(vd.stencil.get());
        op(static_cast<detail::ScreenVisibility*>(vd.screenVisibility.get()));
        op(vd.exactCounter.get());
        op(vd.exactBegin.get());
        op(vd.exactEnd.get());
        for (LightPass& pass : vd.passes)
        {
            op(pass.depthCamera.get());
            op(pass.depthTexture.get());
            op(pass.silhouettePass.get());
            op(pass.blockers.get());
            op(pass.listPass.get());
            op(pass.samples.get());
        }
    }
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

SilhouetteShadowTechnique::ViewData* SilhouetteShadowTechnique::getViewData(osgUtil::CullVisitor& cv)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_viewDataMutex);
    osg::ref_ptr<ViewData>& vd = _viewDataMap[&cv];
    if (!vd) vd = createViewData();
    return vd.get();
}

SilhouetteShadowTechnique::ViewData* SilhouetteShadowTechnique::createViewData()
{
    osg::ref_ptr<ViewData> vd = new ViewData;
    osg::StateSet* ss = new osg::StateSet;
    vd->receiverStateSet = ss;
    vd->receiverPassStateSet = new osg::StateSet;
    vd->receiverPassStateSet->setDataVariance(osg::Object::DYNAMIC); // the stencil modes' program, the prepass's depth
    vd->prepassStateSet = createPrepassStateSet();
    if (_useDefaultShading) ss->setAttributeAndModes(_receiverProgram.get(), osg::StateAttribute::ON);
    const unsigned int slots = slotCapacity();
    ss->setDefine(shader::DEFINE_MAX_SHADOW_LIGHTS, std::to_string(_maxShadowLights));
    ss->setDataVariance(osg::Object::DYNAMIC); // its defines, bindings and uniforms change per frame

    vd->numLights = new osg::Uniform(shader::NUM_LIGHTS, 0);
    vd->lightIndex = new osg::Uniform(osg::Uniform::INT, shader::LIGHT_INDEX, shader::MAX_SCENE_LIGHTS);
    vd->shadowSlot = new osg::Uniform(osg::Uniform::INT, shader::SHADOW_SLOT, shader::MAX_SCENE_LIGHTS);
    vd->eyeToShadow = new osg::Uniform(osg::Uniform::FLOAT_MAT4, shader::EYE_TO_SHADOW, slots);
    vd->slotOwner = new osg::Uniform(osg::Uniform::INT, shader::SLOT_OWNER, slots);
    vd->slotCore = new osg::Uniform(osg::Uniform::FLOAT, shader::SLOT_CORE, slots);
    vd->maskLight = new osg::Uniform(shader::MASK_LIGHT, 0);
    osg::ref_ptr<osg::Uniform> samplers =
        new osg::Uniform(osg::Uniform::SAMPLER_2D_SHADOW, shader::SHADOW_MAP, slots);
    osg::ref_ptr<osg::Uniform> silhouetteSamplers =
        new osg::Uniform(osg::Uniform::SAMPLER_2D, shader::SILHOUETTE_MAP, slots);
    const unsigned int paired = slotCapacity(true);
    for (unsigned int slot = 0; slot < slots; ++slot)
    {
        samplers->setElement(slot, int(_baseTextureUnit + slot));
        // Only the paired modes declare silhouette samplers, OSS_MAX_SHADOW_SLOTS = `paired` of
        // them: the elements after those are never read (a valid unit all the same).
        silhouetteSamplers->setElement(slot, int(silhouetteUnit(slot < paired ? slot : 0)));
        vd->eyeToShadow->setElement(slot, osg::Matrixf());
        ss->setTextureAttributeAndModes(_baseTextureUnit + slot, _litDummyTexture.get(), mapBinding());
    }
    for (int i = 0; i < shader::MAX_SCENE_LIGHTS; ++i)
    {
        vd->lightIndex->setElement(i, i);
        vd->shadowSlot->setElement(i, -1);
    }
    // Triangle lists (HYBRID): per slot its capacities and projection; the buffers are bound
    // per frame, one shader storage block per slot in use (OSS_MAX_LIST_SLOTS, set in cull).
    vd->listCapacity = new osg::Uniform(osg::Uniform::UNSIGNED_INT_VEC4, shader::LIST_CAPACITY, slots);
    vd->listPerspective = new osg::Uniform(osg::Uniform::INT, shader::LIST_SLOT_PERSPECTIVE, slots);
    for (unsigned int slot = 0; slot < slots; ++slot)
    {
        vd->listCapacity->setElement(slot, 0u, 0u, 0u, 0u);
        vd->listPerspective->setElement(slot, 0);
    }
    vd->listRayFrame = new osg::Uniform(shader::LIST_RAY_FRAME, osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
    vd->lookupBiasFrame = new osg::Uniform(shader::LOOKUP_BIAS_FRAME, osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
    for (osg::Uniform* u : {vd->numLights.get(), vd->lightIndex.get(), vd->shadowSlot.get(), vd->eyeToShadow.get(),
                            vd->maskLight.get(), samplers.get(), silhouetteSamplers.get(), vd->slotOwner.get(),
                            vd->slotCore.get(), vd->listCapacity.get(), vd->listPerspective.get(), vd->listRayFrame.get(),
                            vd->lookupBiasFrame.get()})
        ss->addUniform(u);
    ss->addUniform(new osg::Uniform(shader::BASE_TEXTURE, 0));
    ss->addUniform(new osg::Uniform(shader::LIST_RAY_OFFSET_PER_DISTANCE, shader::LIST_RAY_OFFSET_DISTANCE));
    ss->addUniform(new osg::Uniform(shader::LOOKUP_BIAS_PER_DISTANCE, shader::LOOKUP_BIAS));
    ss->addUniform(new osg::Uniform(shader::SHADOW_MAP_SIZE, osg::Vec2f(_shadowMapSize, _shadowMapSize)));
    vd->exactCounter = new GpuCounter(GL_ATOMIC_COUNTER_BUFFER);
    vd->exactBegin = vd->exactCounter->createBeginNode(DEPTH_PREPASS_BIN - 1); // before every receiver
    vd->exactEnd = vd->exactCounter->createEndNode(COUNT_END_BIN);
    vd->passes.resize(slots);
    vd->slotInUse.assign(slots, false);
    vd->slotSkipped.assign(slots, false);
    return vd.release();
}

SilhouetteShadowTechnique::LightPass SilhouetteShadowTechnique::createLightPass(unsigned int slot) const
{
    LightPass pass;
    pass.depthTexture = createDepthTexture(_shadowMapSize);
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
    camera->setStateSet(new osg::StateSet(*_depthPassStateSet, osg::CopyOp::SHALLOW_COPY));
    camera->setViewport(0, 0, _shadowMapSize, _shadowMapSize);
    camera->setDrawBuffer(GL_NONE);
    camera->setReadBuffer(GL_NONE);
    camera->attach(osg::Camera::DEPTH_BUFFER, pass.depthTexture.get());
    camera->setCullCallback(new TraverseShadowedSceneCallback(_shadowedScene));
    pass.samples = new DrawnSamples;
    camera->setInitialDrawCallback(pass.samples->createBegin());
    camera->setFinalDrawCallback(pass.samples->createEnd());
    pass.depthCamera = camera;
    return pass;
}

// ---------------------------------------------------------------------------------------
// Cull

void SilhouetteShadowTechnique::cull(osgUtil::CullVisitor& cv)
{
    if (_dirty || !_receiverProgram)
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

    std::vector<int> refused;
    const std::vector<FoundLight> lights = collectLights(cv, refused);
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
    Statistics stats;
    stats.frameNumber = cv.getFrameStamp() ? cv.getFrameStamp()->getFrameNumber() : 0;
    stats.lightsFound = static_cast<unsigned int>(lights.size());
    stats.effectiveMode = frame.mode;
    _renderedMode = int(frame.mode);
    if (lights.empty()) warnOnce(WARN_NO_LIGHT, "no positional light (osg::LightSource) in the view; nothing to shadow");
    else prepareFrame(cv, frame);
    warnAboutMissingLights(lights);
    // Lights whose cone or range misses what the view sees cost nothing: no passes, no slot.
    std::vector<bool> reaches(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        reaches[i] = lightReachesRegion(lights[i].description, frame.region);
        if (!reaches[i] && castsShadow(lights[i])) ++stats.lightsSkipped;
    }
    const std::vector<int> slots = assignShadowSlots(lights, reaches);
    stats.silhouetteCasters = static_cast<unsigned int>(frame.casterList.size());

    // Each light's frusta; cube faces of point lights take the slots after the lights' own.
    unsigned int nextFreeSlot = 0;
    for (int slot : slots) nextFreeSlot = std::max(nextFreeSlot, static_cast<unsigned int>(slot + 1));
    std::vector<std::vector<LightFrustum>> frusta(lights.size());
    std::vector<unsigned int> firstFaceSlot(lights.size(), 0);
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (slots[i] >= 0)
            firstFaceSlot[i] = nextFreeSlot, frusta[i] = planLightFrusta(frame, lights[i].description, nextFreeSlot,
                                                                         slotCapacity(pairedSlots(frame.mode)));
    frame.triangleLists = frame.mode == HYBRID && useTriangleLists(cv);
    const unsigned int blocks = cv.getState() ? TriangleListPass::fragmentStorageBlocks(cv.getState()->getContextID()) : 0;
    const unsigned int listLimit = blocks > 0 ? std::min(listSlots(), blocks) : listSlots();
    if (frame.triangleLists && nextFreeSlot > listLimit)
    {
        warnOnce(WARN_LIST_SLOTS, "HYBRID: this frame's " + std::to_string(nextFreeSlot) +
                                      " shadow maps (cube faces included) exceed the " + std::to_string(listLimit) +
                                      " that triangle lists hold (one fragment shader storage block each: "
                                      "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS is " + std::to_string(blocks) +
                                      "); using HYBRID_STENCIL_VOLUMES");
        frame.triangleLists = false;
    }
    // One storage block (or image) per slot in use: the eye pass declares no more than it reads.
    eye.triangleLists = frame.triangleLists;
    eye.listSlots = std::max(1u, nextFreeSlot);
    std::size_t listTexels = 0;
    for (unsigned int slot = 0; slot < nextFreeSlot && slot < vd.passes.size(); ++slot)
        if (vd.passes[slot].listPass) listTexels = std::max(listTexels, vd.passes[slot].listPass->getBufferSize() / 16);
    stats.listImages = frame.triangleLists && _tuning.listImageReads && cv.getState() &&
                       TriangleListPass::imageReadsFit(cv.getState()->getContextID(), std::max(1u, nextFreeSlot), listTexels);
    eye.listImages = stats.listImages;
    stats.listBlockHeads = stats.listImages && _tuning.listBlockHeads &&
                           TriangleListPass::blockHeadsFit(cv.getState()->getContextID(), std::max(1u, nextFreeSlot));
    eye.listBlockHeads = stats.listBlockHeads;
    stats.triangleLists = frame.triangleLists;
    if ((frame.mode == SHADOW_VOLUME || frame.mode == HYBRID) && !_alphaTested.empty())
        warnAlphaTested(frame.mode == HYBRID, frame.triangleLists);
    const bool stencilMode = frame.mode == SHADOW_VOLUME || (frame.mode == HYBRID && !frame.triangleLists);
    // Statistics of HYBRID's lists: the fragments resolved exactly, counted in the eye pass.
    const bool countExact = frame.triangleLists && _stats.valid();
    eye.countExact = countExact;
    if (countExact)
    {
        vd.exactBegin->accept(cv);
        vd.exactEnd->accept(cv);
        stats.silhouettePixels = vd.exactCounter->getLastValue();
    }
    if (stencilMode && !vd.stencil) vd.stencil = new StencilShadowPasses(_stencilProgram.get(), _volumeProgram.get());
    if (stencilMode)
        vd.receiverPassStateSet->setAttributeAndModes(_stencilProgram.get(),
                                                      osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    else
        vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::PROGRAM);
    // The GLSL 4.30 shaders join the receivers' programs only where the context runs them.
    const osg::GLExtensions* ext = cv.getState() ? osg::GLExtensions::Get(cv.getState()->getContextID(), false) : nullptr;
    if (ext && ext->glVersion >= 4.3f)
        vd.receiverStateSet->setDefine(shader::DEFINE_GLSL_430);
    else
        vd.receiverStateSet->removeDefine(shader::DEFINE_GLSL_430);
    stats.screenVisibility = cullScreenVisibility(cv, vd, stencilMode);
    std::size_t casterTriangles = 0;
    for (const Caster& caster : frame.casterList) casterTriangles += caster.mesh->getAdjacency().report.inputTriangles;
    const osg::Viewport* eyeViewport = cv.getViewport();
    stats.depthPrepass = usesDepthPrepass(frame.mode, frame.triangleLists, casterTriangles, std::max(1u, nextFreeSlot),
                                          eyeViewport ? eyeViewport->width() * eyeViewport->height() : 0.0);
    if (stats.depthPrepass)
        cullDepthPrepass(cv, vd);
    else
        vd.receiverPassStateSet->removeAttribute(osg::StateAttribute::DEPTH);

    const bool silhouette = frame.mode == SILHOUETTE_MAP;
    const bool paired = pairedSlots(frame.mode);
    const unsigned int capacity = slotCapacity(paired);
    eye.slotCapacity = capacity;
    // SILHOUETTE_MAP's eye pass reads neighbourhood maps (usampler2D), HYBRID's the edge masks.
    std::vector<osg::Texture2D*> silhouetteMaps(
        capacity, silhouette ? _defaultNeighbourhoodTexture.get() : _defaultSilhouetteTexture.get());
    for (unsigned int slot = 0; slot < vd.passes.size(); ++slot)
    {
        // SHADOW_MAP's slots after the paired ones take the units of their silhouette maps.
        if (slot < capacity)
            vd.receiverStateSet->setTextureAttributeAndModes(_baseTextureUnit + slot, litTexture(silhouette),
                                                             mapBinding());
        vd.slotOwner->setElement(slot, int(slot));
        vd.slotCore->setElement(slot, 0.0f);
        vd.slotInUse[slot] = false;
        vd.slotSkipped[slot] = false;
    }
    // SILHOUETTE_MAP's silhouette maps, and HYBRID's edge masks (silhouette maps too); in
    // SHADOW_MAP their units hold the depth maps bound above.
    const bool edgeMasks = frame.mode == HYBRID && _hybridEdgeMask;
    if (paired) bindSilhouetteMaps(vd, silhouette || edgeMasks ? silhouetteMaps : std::vector<osg::Texture2D*>());
    eye.edgeMasks = edgeMasks;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (slots[i] < 0) continue;
        ++stats.lightsShadowed;
        cullLight(cv, vd, frame, lights[i].description, static_cast<unsigned int>(slots[i]), frusta[i],
                  firstFaceSlot[i], silhouetteMaps, stats);
    }
    if (silhouette || edgeMasks) bindSilhouetteMaps(vd, silhouetteMaps);

    if (stencilMode)
        cullStencilPasses(cv, vd, frame.mode == HYBRID, lights, slots, frame.casterList, frame.receivers, stats);
    updateViewUniforms(cv, vd, lights, slots, eye);
    detail::applyEyePassDefines(*vd.receiverStateSet, detail::eyePassDefines(eye));
    // A mask is 0 or 1: a blended scene (an alpha-tested tree that also blends) must not
    // mix it with what lies behind. The alpha still reaches the scene's osg::AlphaFunc.
    if (_debugView == DEBUG_SHADOW_MASK || _debugView == DEBUG_CLASSES)
        vd.receiverStateSet->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    else
        vd.receiverStateSet->removeMode(GL_BLEND);
    cullProgramLinkCheck(cv);
    if (const osg::Viewport* viewport = cv.getViewport())
        stats.viewportPixels = static_cast<unsigned int>(viewport->width() * viewport->height());
    recordStatistics(stats);
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

void SilhouetteShadowTechnique::warnAboutMissingLights(const std::vector<FoundLight>& lights) const
{
    std::string found;
    for (const FoundLight& l : lights) found += (found.empty() ? "" : ", ") + std::to_string(l.description.lightNum);
    const std::string what = lights.empty() ? "the view has no light" : "the view's GL lights are " + found;
    const bool named = std::any_of(lights.begin(), lights.end(),
                                   [&](const FoundLight& l) { return l.description.lightNum == _lightNum; });
    if (_lightNum >= 0 && !named)
        warnOnce(WARN_LIGHT_NUM, "LightNum " + std::to_string(_lightNum) + " names no light (" + what +
                                     "); nothing casts a shadow (LightNum -1: every light)");
    if (_debugView != DEBUG_NONE && _debugLight >= lights.size())
        warnOnce(WARN_DEBUG_LIGHT, "DebugLight " + std::to_string(_debugLight) + " is not a light of the view (" +
                                       std::to_string(lights.size()) + " found, DebugLight counts from 0); the " +
                                       "debug view shows it unlit");
}

bool SilhouetteShadowTechnique::castsShadow(const FoundLight& light) const
{
    return _lightNum < 0 || light.description.lightNum == _lightNum;
}

std::vector<int> SilhouetteShadowTechnique::assignShadowSlots(const std::vector<FoundLight>& lights,
                                                              const std::vector<bool>& reaches) const
{
    std::vector<int> slots(lights.size(), -1);
    unsigned int slot = 0;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (!castsShadow(lights[i]) || !reaches[i]) continue;
        if (slot >= _maxShadowLights)
        {
            warnOnce(WARN_OVER_BUDGET, "more shadow-casting lights than MaxShadowLights (" +
                                           std::to_string(_maxShadowLights) + "); the rest are lit unshadowed");
            break;
        }
        slots[i] = static_cast<int>(slot++);
    }
    return slots;
}

void SilhouetteShadowTechnique::prepareFrame(osgUtil::CullVisitor& cv, FrameContext& frame)
{
    const osgShadow::ShadowSettings* settings = _shadowedScene->getShadowSettings();
    frame.view = ViewPoint::fromCullVisitor(cv);
    frame.receivers = boundsOf(*_shadowedScene, settings->getReceivesShadowTraversalMask(), *_meshCache, frame.view);
    CasterSignatureVisitor casters(*_meshCache, frame.view);
    casters.setTraversalMask(settings->getCastsShadowTraversalMask());
    for (unsigned int i = 0; i < _shadowedScene->getNumChildren(); ++i) _shadowedScene->getChild(i)->accept(casters);
    casters.mix(cv.getTraversalMask()); // the depth pass culls under the view's mask too
    const osg::BoundingBox& box = casters.getBoundingBox();
    frame.casters = box.valid() ? osg::BoundingBoxd(box._min, box._max) : osg::BoundingBoxd();
    frame.casterSignature = casters.signature;
    frame.casterParts = std::move(casters.parts);
    frame.nonFinite = casters.nonFinite;
    if (!casters.billboards.empty())
        frame.billboards = std::make_shared<const BillboardMatrices>(std::move(casters.billboards));
    for (const osg::Drawable* drawable : frame.nonFinite) warnNonFinite(*drawable);
    frame.region = visibleReceiverRegion(cv, frame.receivers);
    if (frame.mode != SHADOW_MAP)
        frame.casterList = collectCasters(*_shadowedScene, cv.getTraversalMask() & settings->getCastsShadowTraversalMask(),
                                          *_meshCache, frame.view);
}

std::vector<LightFrustum> SilhouetteShadowTechnique::planLightFrusta(const FrameContext& frame,
                                                                     const LightDescription& light,
                                                                     unsigned int& nextFreeSlot,
                                                                     unsigned int slotLimit) const
{
    std::vector<LightFrustum> frusta;
    if (frame.mode != SHADOW_VOLUME && light.type == LightDescription::POINT && needsCubeFaces(light, frame.region))
    {
        // Only the faces where a caster that can shadow a receiver lies: a flat caster (a
        // ground) that every receiver stands on or above, seen from the light, shadows nothing.
        std::vector<osg::BoundingBoxd> parts;
        for (const CasterPart& part : frame.casterParts)
            if (canShadow(light, part, frame.receivers)) parts.push_back(part.box);
        if (parts.empty() && !frame.casterParts.empty())
            return {LightFrustum()}; // nothing to shadow: the light is lit unshadowed
        frusta = fitCubeFaces(light, frame.region, frame.casters, _shadowMapSize,
                              frame.casterParts.empty() ? nullptr : &parts);
        if (frusta.size() > 1 && nextFreeSlot + frusta.size() - 1 > slotLimit)
        {
            warnOnce(WARN_FACE_SLOTS, "light " + std::to_string(light.lightNum) + " needs " +
                                          std::to_string(frusta.size()) + " cube faces and only " +
                                          std::to_string(slotLimit - nextFreeSlot + 1) + " of the " +
                                          std::to_string(slotLimit) +
                                          " shadow slots are free; it gets one perspective map (see BaseTextureUnit)");
            frusta.clear();
        }
    }
    if (frusta.empty()) frusta.push_back(fitLightFrustum(light, frame.region, frame.casters));
    if (frusta.size() > 1) nextFreeSlot += static_cast<unsigned int>(frusta.size() - 1);
    return frusta;
}

void SilhouetteShadowTechnique::cullLight(osgUtil::CullVisitor& cv, ViewData& vd, const FrameContext& frame,
                                          const LightDescription& light, unsigned int slot,
                                          const std::vector<LightFrustum>& frusta, unsigned int firstFaceSlot,
                                          std::vector<osg::Texture2D*>& silhouetteMaps, Statistics& stats)
{
    if (!frusta.front().valid)
    {
        vd.passes[slot].frustum = LightFrustum();
        ++stats.lightsSkipped; // nothing can shadow what this view sees
        return;
    }
    for (std::size_t k = 0; k < frusta.size(); ++k)
    {
        const unsigned int s = k == 0 ? slot : firstFaceSlot + static_cast<unsigned int>(k - 1);
        vd.slotOwner->setElement(s, int(slot));
        vd.slotCore->setElement(s, float(frusta[k].faceCore));
        cullSlot(cv, vd, frame, light, s, frusta[k], silhouetteMaps[s], stats);
    }
}

void SilhouetteShadowTechnique::cullSlot(osgUtil::CullVisitor& cv, ViewData& vd, const FrameContext& frame,
                                         const LightDescription& light, unsigned int slot, const LightFrustum& frustum,
                                         osg::Texture2D*& silhouetteMap, Statistics& stats)
{
    const bool silhouette = frame.mode == SILHOUETTE_MAP;
    LightPass& pass = vd.passes[slot];
    // SILHOUETTE_MAP reads raw depths and compares them itself; the other modes sample with
    // hardware comparison. A texture's comparison mode is fixed at creation: toggling it on a
    // texture GL already has is not reliably re-applied, so switching rebuilds.
    if (!pass.depthCamera || pass.depthTexture->getTextureWidth() != int(_shadowMapSize) ||
        pass.depthTexture->getShadowComparison() == silhouette)
    {
        pass = createLightPass(slot);
        pass.depthTexture->setShadowComparison(!silhouette);
    }
    pass.frustum = frustum;
    if (frame.mode == SHADOW_VOLUME) return; // volumes only, no map
    vd.slotInUse[slot] = true;
    // Blocker culling tests casters against this map alone: not for a cube face, which sees
    // only part of the light's casters; triangle lists need no volumes to skip; and not with
    // the edge mask: a caster the map's samples call hidden may still shadow what shows
    // through gaps thinner than a texel, which is what the edge mask resolves.
    const bool blockers = frame.mode == HYBRID && _blockerCulling && !_hybridEdgeMask && !frame.triangleLists &&
                          frustum.faceCore == 0.0;
    if (blockers && !pass.blockers) pass.blockers = new BlockerQueries;
    if (!blockers) pass.blockers = nullptr;
    if (blockers) pass.blockers->update(frame.casterList);
    osg::Node* queries = blockers ? pass.blockers->getNode() : nullptr;
    pass.samples->setEnabled(!blockers && frustum.faceCore > 0.0); // one sample query at a time; only faces skip
    if (pass.depthCamera->getNumChildren() != (queries ? 1u : 0u) || (queries && pass.depthCamera->getChild(0) != queries))
    {
        pass.depthCamera->removeChildren(0, pass.depthCamera->getNumChildren());
        if (queries) pass.depthCamera->addChild(queries);
    }
    cullLightPasses(cv, pass, frame, light, stats);
    vd.receiverStateSet->setTextureAttributeAndModes(_baseTextureUnit + slot, pass.depthTexture.get(), mapBinding());
    if (frame.triangleLists) cullTriangleListPass(cv, vd, pass, slot, frame, light);
    if (frame.mode == HYBRID && _hybridEdgeMask) cullEdgeMask(cv, pass, frame, light, silhouetteMap, stats);
    // A cube face whose newest build (this light, these casters) drew no caster shadows
    // nothing: the eye pass leaves it out. The counts come back a frame or two late; until
    // then, and in every frame that rebuilds, the face is evaluated.
    const bool receiverProgram = frame.mode == SHADOW_MAP || frame.mode == SILHOUETTE_MAP || frame.triangleLists;
    vd.slotSkipped[slot] = _tuning.skipEmptyFaces && receiverProgram && frustum.faceCore > 0.0 &&
                           (frame.triangleLists ? pass.listPass && pass.listPass->listedNothing()
                                                : pass.samples->drewNothing());
    if (vd.slotSkipped[slot]) ++stats.slotsSkipped;
    if (pass.samples->getEnabled() && pass.samples->pending()) pass.samples->getPollNode()->accept(cv);
    if (!silhouette) return;
    silhouetteMap = pass.silhouettePass->getNeighbourhoodTexture();
    stats.silhouetteEdges += static_cast<unsigned int>(pass.silhouettePass->getEdges()->getEdgeCount());
}

void SilhouetteShadowTechnique::cullLightPasses(osgUtil::CullVisitor& cv, LightPass& pass, const FrameContext& frame,
                                                const LightDescription& light, Statistics& stats)
{
    PassInputs inputs;
    inputs.valid = true;
    inputs.glGeneration = getGLGeneration();
    inputs.mode = frame.mode;
    inputs.casters = frame.casterSignature;
    inputs.view = pass.frustum.view;
    inputs.projection = pass.frustum.projection;
    inputs.light = light.homogeneous();
    inputs.polygonOffsetFactor = getEffectivePolygonOffsetFactor(frame.mode);
    const bool silhouette = frame.mode == SILHOUETTE_MAP;
    const bool reuse = inputs == pass.rendered &&
                       (!silhouette || (pass.silhouettePass && pass.silhouettePass->getMapSize() == _shadowMapSize));
    if (auto* scene = dynamic_cast<TraverseShadowedSceneCallback*>(pass.depthCamera->getCullCallback()))
    {
        scene->setCasters(!reuse);
        scene->setExcluded(frame.nonFinite);
        scene->setBillboards(frame.billboards);
    }
    pass.depthCamera->setClearMask(reuse ? 0 : GL_DEPTH_BUFFER_BIT);
    if (reuse)
    {
        if (pass.depthCamera->getNumChildren() > 0) cullDepthPass(cv, pass); // the blocker queries alone
        ++stats.depthPassesReused;
        ++stats.shadowPasses; // in use, kept from an earlier frame
        stats.silhouettePassesReused += silhouette ? 1 : 0;
        stats.extractionsSkipped += silhouette ? 1 : 0;
        return;
    }
    const float factor = inputs.polygonOffsetFactor;
    osg::StateSet* depthState = pass.depthCamera->getStateSet(); // the pass's own (shallow) copy
    const auto* offset = dynamic_cast<const osg::PolygonOffset*>(depthState->getAttribute(osg::StateAttribute::POLYGONOFFSET));
    if (!offset || offset->getFactor() != factor || offset->getUnits() != _polygonOffsetUnits)
        depthState->setAttributeAndModes(new osg::PolygonOffset(factor, _polygonOffsetUnits),
                                         osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    cullDepthPass(cv, pass);
    ++stats.shadowPasses;
    pass.rendered = inputs;
    if (!silhouette) return;
    cullSilhouettePass(cv, pass, light, frame.casterList, false);
    stats.extractionsSkipped += pass.silhouettePass->getExtractionSkipped() ? 1 : 0;
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

bool SilhouetteShadowTechnique::useTriangleLists(osgUtil::CullVisitor& cv) const
{
    if (_hybridMethod == HYBRID_STENCIL_VOLUMES) return false;
    const osg::State* state = cv.getState();
    const osg::GLExtensions* ext = state ? osg::GLExtensions::Get(state->getContextID(), false) : nullptr;
    const bool supported = ext && ext->glVersion >= 4.3f && ext->glMemoryBarrier;
    if (!supported && _hybridMethod == HYBRID_TRIANGLE_LISTS)
        warnOnce(WARN_NO_TRIANGLE_LISTS, "HybridMethod HYBRID_TRIANGLE_LISTS needs OpenGL 4.3 (shader storage "
                                         "buffers, image atomics) and the context has less; using HYBRID_STENCIL_VOLUMES");
    return supported;
}

void SilhouetteShadowTechnique::cullTriangleListPass(osgUtil::CullVisitor& cv, ViewData& vd, LightPass& pass,
                                                     unsigned int slot, const FrameContext& frame,
                                                     const LightDescription& light)
{
    std::size_t triangles = 0;
    for (const Caster& caster : frame.casterList) triangles += caster.mesh->getAdjacency().report.inputTriangles;
    const unsigned int grid = TriangleListPass::MAX_GRID_SIZE;
    // A build that listed more than the pass holds (read back a frame or two later) left that
    // slot's silhouette pixels to the shadow map: rebuild with room for what it needed.
    std::size_t neededNodes = 0, neededTriangles = 0;
    bool grow = false;
    if (pass.listPass && pass.listPass->overflowed(neededNodes, neededTriangles))
    {
        const std::size_t nodes = std::min(neededNodes + neededNodes / 4, TriangleListPass::MAX_NODES);
        const std::size_t tris = std::min(neededTriangles, TriangleListPass::MAX_TRIANGLES);
        grow = nodes > pass.listPass->getNodeCapacity() || tris > pass.listPass->getTriangleCapacity();
        warnOnce(grow ? WARN_LIST_OVERFLOW : WARN_LIST_FULL,
                 "HYBRID: the triangle lists of shadow slot " + std::to_string(slot) + " needed " +
                     std::to_string(neededNodes) + " nodes and " + std::to_string(neededTriangles) +
                     " triangles, with room for " + std::to_string(pass.listPass->getNodeCapacity()) + " and " +
                     std::to_string(pass.listPass->getTriangleCapacity()) +
                     "; that light's silhouette pixels took the shadow map's answer" +
                     (grow ? std::string("; the lists are rebuilt larger")
                           : "; the lists cannot grow further (" + std::to_string(TriangleListPass::MAX_NODES) +
                                 " nodes, " + std::to_string(TriangleListPass::MAX_TRIANGLES) + " triangles)"));
        triangles = std::max(triangles, tris);
        neededNodes = nodes;
    }
    if (!pass.listPass || !pass.listPass->fits(grid, triangles) || grow)
    {
        pass.listPass = new TriangleListPass(grid, triangles, *_listStateSet,
                                             "osgShadowSilhouette triangle lists " + std::to_string(slot),
                                             grow ? neededNodes : 0, _tuning.listNodeReservePerTexel);
        auto* scene = new TraverseShadowedSceneCallback(_shadowedScene);
        scene->setListed(_listedDrawables.get());
        pass.listPass->getCamera()->setCullCallback(scene);
        pass.listRendered = PassInputs();
    }
    const bool sameReceivers = pass.listReceivers._min == frame.receivers._min &&
                               pass.listReceivers._max == frame.receivers._max;
    if (!(pass.listRendered == pass.rendered) || !sameReceivers) // the lists describe another depth map
    {
        if (auto* scene = dynamic_cast<TraverseShadowedSceneCallback*>(pass.listPass->getCamera()->getCullCallback()))
        {
            scene->setExcluded(frame.nonFinite);
            scene->setBillboards(frame.billboards);
            std::unordered_set<const osg::Drawable*> closed;
            for (const Caster& caster : frame.casterList)
                if (caster.closed) closed.insert(caster.geometry.get());
            scene->setMarked(std::move(closed), _listFrontOnlyStateSet.get());
        }
        const unsigned int mask = cv.getTraversalMask();
        cv.setTraversalMask(mask & _shadowedScene->getShadowSettings()->getCastsShadowTraversalMask());
        pass.listPass->cull(cv, pass.frustum, light.type != LightDescription::DIRECTIONAL, frame.receivers);
        cv.setTraversalMask(mask);
        pass.listRendered = pass.rendered;
        pass.listReceivers = frame.receivers;
    }
    // The counts of a finished build come back through the eye pass of a later frame.
    if (pass.listPass->countPending()) pass.listPass->getPollNode()->accept(cv);
    osg::StateSet& ss = *vd.receiverStateSet;
    const unsigned int binding = shader::LIST_READ_BINDING + slot;
    auto* bound = dynamic_cast<osg::ShaderStorageBufferBinding*>(
        ss.getAttribute(osg::StateAttribute::SHADERSTORAGEBUFFERBINDING, binding));
    if (!bound || bound->getBufferData() != pass.listPass->getBuffer())
        ss.setAttributeAndModes(new osg::ShaderStorageBufferBinding(binding, pass.listPass->getBuffer(), 0,
                                                                    pass.listPass->getBufferSize()),
                                EYE_PASS_BINDING);
    // The same buffer as a read-only image, for eye passes that read images (OSS_LIST_IMAGES).
    const unsigned int unit = shader::LIST_READ_IMAGE_UNIT + slot;
    auto* image = dynamic_cast<osg::BindImageTexture*>(ss.getAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit));
    if (!image || image->getTexture() != pass.listPass->getImageView())
        ss.setAttributeAndModes(new osg::BindImageTexture(unit, pass.listPass->getImageView(),
                                                          osg::BindImageTexture::READ_ONLY, GL_RGBA32UI_EXT),
                                EYE_PASS_BINDING);
    vd.listCapacity->setElement(slot, pass.listPass->getNodeCapacity(), pass.listPass->getTriangleCapacity(),
                                pass.listPass->getGridSize(), 0u);
    vd.listPerspective->setElement(slot, light.type != LightDescription::DIRECTIONAL ? 1 : 0);
}

void SilhouetteShadowTechnique::cullEdgeMask(osgUtil::CullVisitor& cv, LightPass& pass, const FrameContext& frame,
                                             const LightDescription& light, osg::Texture2D*& silhouetteMap,
                                             Statistics& stats)
{
    if (!pass.silhouettePass || pass.silhouettePass->getMapSize() != _shadowMapSize) pass.edgesRendered = PassInputs();
    if (!(pass.edgesRendered == pass.rendered)) // the mask describes another depth map
    {
        cullSilhouettePass(cv, pass, light, frame.casterList, true);
        pass.edgesRendered = pass.rendered;
    }
    silhouetteMap = pass.silhouettePass->getTexture();
    stats.silhouetteEdges += static_cast<unsigned int>(pass.silhouettePass->getEdges()->getEdgeCount());
}


void SilhouetteShadowTechnique::cullDepthPrepass(osgUtil::CullVisitor& cv, ViewData& vd)
{
    if (!vd.prepassDepth) vd.prepassDepth = new osg::Depth(osg::Depth::LEQUAL);
    // Not OVERRIDE: a drawable's own osg::Depth stays, and the prepass leaves it out.
    vd.receiverPassStateSet->setAttribute(vd.prepassDepth.get());
    cullReceivers(cv, vd, vd.prepassStateSet.get());
    if (osgUtil::RenderBin* bin = cv.getCurrentRenderBin())
        if (osgUtil::RenderStage* stage = bin->getStage())
            prunePrepass(*stage, vd.prepassStateSet.get(), vd.receiverStateSet.get(), false, DEPTH_PREPASS_BIN);
}

void SilhouetteShadowTechnique::cullReceivers(osgUtil::CullVisitor& cv, ViewData& vd, osg::StateSet* pass)
{
    const osgShadow::ShadowSettings* settings = _shadowedScene->getShadowSettings();
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(mask & settings->getReceivesShadowTraversalMask());
    // ComputeNearFarModeOverride: how the view computes its near and far planes over the
    // receivers (as ViewDependentShadowMap), and so the range visibleReceiverRegion() fits.
    const osg::CullSettings::ComputeNearFarMode nearFar = cv.getComputeNearFarMode();
    const osg::CullSettings::ComputeNearFarMode nearFarOverride = settings->getComputeNearFarModeOverride();
    if (nearFarOverride != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR) cv.setComputeNearFarMode(nearFarOverride);
    cv.pushStateSet(vd.receiverStateSet.get());
    if (pass) cv.pushStateSet(pass);
    _shadowedScene->osg::Group::traverse(cv);
    if (pass) cv.popStateSet();
    cv.popStateSet();
    if (nearFarOverride != osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR) cv.computeNearPlane();
    cv.setComputeNearFarMode(nearFar);
    cv.setTraversalMask(mask);
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

void SilhouetteShadowTechnique::cullStencilPasses(osgUtil::CullVisitor& cv, ViewData& vd, bool hybrid,
                                                  const std::vector<FoundLight>& lights, const std::vector<int>& slots,
                                                  const std::vector<Caster>& casters,
                                                  const osg::BoundingBoxd& receivers, Statistics& stats)
{
    std::vector<StencilLight> stencilLights;
    const bool oneLight = _debugView == DEBUG_SHADOW_MASK || _debugView == DEBUG_CLASSES; // only its passes
    int maskSlot = -1;
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
        if (slots[i] < 0 || !vd.passes[slots[i]].frustum.valid) continue;
        const LightPass& pass = vd.passes[slots[i]];
        unsigned int faceSlots = 0;
        for (unsigned int s = 0; s < vd.slotInUse.size(); ++s)
        {
            int owner = -1;
            vd.slotOwner->getElement(s, owner);
            if (owner == slots[i]) faceSlots |= 1u << s;
        }
        stencilLights.push_back({static_cast<unsigned int>(slots[i]), lights[i].description.lightNum,
                                 lights[i].description.homogeneous(),
                                 hybrid && _blockerCulling ? pass.blockers : nullptr, faceSlots});
        if (oneLight && i == _debugLight) maskSlot = slots[i];
    }
    if (oneLight && maskSlot < 0) stencilLights.clear(); // the debug light casts nothing
    vd.stencil->cull(cv, hybrid, oneLight ? maskSlot : -1, stencilLights, casters, receivers,
                     [&](osg::StateSet* pass) { cullReceivers(cv, vd, pass); });
    stats.zfailCasters = vd.stencil->getZFailCasters();
    stats.zpassCasters = vd.stencil->getZPassCasters();
    stats.volumesRebuilt = vd.stencil->getVolumesRebuilt();
    stats.volumesCulled = vd.stencil->getVolumesCulled();
    stats.blendedRound = vd.stencil->getBlendedRound();
    if (vd.stencil->getBlendedSkipped())
        warnOnce(WARN_BLENDED_VISIBILITY,
                 std::string("Mode ") + modeName(_mode) +
                     ": receivers in the transparent bin (or a later one) get no shadow of their own while a "
                     "program given to addShadowShaders() draws the receivers: the screen-space visibility has "
                     "no blended round yet; they show the opaque surface's shadow behind them");
    stats.silhouettePixels = hybrid ? vd.stencil->getSilhouettePixels() : -1;
    stats.volumeFragments = vd.stencil->getVolumeFragments();
    stats.blockersTested = vd.stencil->getBlockersTested();
    stats.blockersSkipped = vd.stencil->getBlockersHidden();
}

bool SilhouetteShadowTechnique::cullScreenVisibility(osgUtil::CullVisitor& cv, ViewData& vd, bool stencilMode)
{
    // The mask and class views draw the technique's own answer, one light at a time.
    bool use = stencilMode && _debugView != DEBUG_SHADOW_MASK && _debugView != DEBUG_CLASSES && hasApplicationPrograms();
    const osg::Viewport* viewport = cv.getViewport();
    if (use && (!viewport || !cv.getState() || !detail::ScreenVisibility::supported(cv.getState()->getContextID())))
    {
        warnOnce(WARN_SCREEN_VISIBILITY,
                 std::string("Mode ") + modeName(_mode) +
                     ": the graphics context runs no OpenGL 4.3 (GLSL 4.30, image load/store), which the stencil modes need to "
                     "draw the receivers with the programs given to addShadowShaders(); those receivers show the "
                     "technique's shading instead");
        use = false;
    }
    auto* visibility = static_cast<detail::ScreenVisibility*>(vd.screenVisibility.get());
    if (use && !visibility) vd.screenVisibility = visibility = new detail::ScreenVisibility;
    const unsigned int unit = shader::SCREEN_VISIBILITY_IMAGE_UNIT;
    if (use)
    {
        visibility->fit(*viewport);
        vd.receiverStateSet->setAttributeAndModes(visibility->getBinding(), EYE_PASS_BINDING);
        vd.receiverPassStateSet->setDefine(shader::DEFINE_VISIBILITY_CLEAR);
    }
    else
    {
        if (visibility && vd.receiverStateSet->getAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit) ==
                              visibility->getBinding())
            vd.receiverStateSet->removeAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit);
        vd.receiverPassStateSet->removeDefine(shader::DEFINE_VISIBILITY_CLEAR);
    }
    if (vd.stencil)
        vd.stencil->setScreenVisibility(use ? visibility->getBarrier() : nullptr,
                                        use ? visibility->getFinalPass() : nullptr);
    return use;
}

void SilhouetteShadowTechnique::bindSilhouetteMaps(ViewData& vd, const std::vector<osg::Texture2D*>& maps) const
{
    osg::StateSet& ss = *vd.receiverStateSet;
    for (unsigned int slot = 0; slot < slotCapacity(true); ++slot)
    {
        if (maps.empty())
            ss.removeTextureAttribute(silhouetteUnit(slot), osg::StateAttribute::TEXTURE);
        else
            ss.setTextureAttributeAndModes(silhouetteUnit(slot),
                                           slot < maps.size() ? maps[slot] : _defaultSilhouetteTexture.get(),
                                           mapBinding());
    }
}

std::vector<SilhouetteShadowTechnique::FoundLight> SilhouetteShadowTechnique::collectLights(
    osgUtil::CullVisitor& cv, std::vector<int>& refused) const
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
        if (!usable) warnRefusedLight(cv, *light, refusal);
        // Positional state is applied in this order, so of two lights with one number (say
        // the viewer's headlight and the scene's light 0) the last is the one GL lights with.
        const int num = light->getLightNum();
        lights.erase(std::remove_if(lights.begin(), lights.end(),
                                    [&](const FoundLight& l) { return l.description.lightNum == num; }),
                     lights.end());
        refused.erase(std::remove(refused.begin(), refused.end(), num), refused.end());
        if (!usable)
            refused.push_back(num);
        else if (num < shader::MAX_SCENE_LIGHTS)
            lights.push_back(found);
    }
    std::sort(lights.begin(), lights.end(), [](const FoundLight& a, const FoundLight& b) {
        return a.description.lightNum < b.description.lightNum;
    });
    return lights;
}

std::vector<osg::Vec3d> SilhouetteShadowTechnique::visibleReceiverRegion(osgUtil::CullVisitor& cv,
                                                                          const osg::BoundingBoxd& receivers) const
{
    if (!receivers.valid()) return {};
    double zNear = cv.getCalculatedNearPlane();
    double zFar = cv.getCalculatedFarPlane();
    const osg::Matrixd& projection = *cv.getProjectionMatrix();
    if (cv.getComputeNearFarMode() == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR &&
        _shadowedScene->getShadowSettings()->getComputeNearFarModeOverride() == osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR)
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
    if (_maximumShadowDistance < zFar && effectiveModeFor(cv) != SHADOW_VOLUME)
    {
        // ShadowSettings' MaximumShadowMapDistance: the maps cover the eye range up to it,
        // as in ViewDependentShadowMap; beyond, the receivers fall outside them (lit). A
        // distance before the near plane leaves nothing to cover.
        zFar = _maximumShadowDistance;
    }
    if (!(zNear <= zFar) || !std::isfinite(zNear) || !std::isfinite(zFar) || zFar <= 0.0) return {}; // nothing visible
    zNear = std::max(zNear, zFar * 1e-6);
    const double margin = 1e-3 * (zFar - zNear) + 1e-6 * zFar;
    const osg::Matrixd fitted = withDepthRange(projection, std::max(zNear - margin, zNear * 0.5), zFar + margin);
    return visibleRegion(frustumCorners(*cv.getModelViewMatrix(), fitted), receivers);
}

LightFrustum SilhouetteShadowTechnique::fitLightFrustum(const LightDescription& light,
                                                        const std::vector<osg::Vec3d>& region,
                                                        const osg::BoundingBoxd& casters) const
{
    if (light.type == LightDescription::DIRECTIONAL)
        return fitDirectionalFrustum(light.direction, region, casters, _shadowMapSize);
    return fitPerspectiveFrustum(light, region, casters);
}

void SilhouetteShadowTechnique::cullDepthPass(osgUtil::CullVisitor& cv, LightPass& pass)
{
    pass.depthCamera->setViewMatrix(pass.frustum.view);
    pass.depthCamera->setProjectionMatrix(pass.frustum.projection);
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(mask & _shadowedScene->getShadowSettings()->getCastsShadowTraversalMask());
    pass.samples->culled(); // one more build to count (or the blocker queries alone: not empty)
    pass.depthCamera->accept(cv);
    cv.setTraversalMask(mask);
}

void SilhouetteShadowTechnique::cullSilhouettePass(osgUtil::CullVisitor& cv, LightPass& pass,
                                                   const LightDescription& light, const std::vector<Caster>& casters,
                                                   bool depthComparison)
{
    if (!pass.silhouettePass || pass.silhouettePass->getMapSize() != _shadowMapSize)
    {
        std::string name = pass.depthCamera->getName();
        name.replace(name.find("depth pass"), std::strlen("depth pass"), "silhouette map");
        pass.silhouettePass = new SilhouetteMapPass(_shadowMapSize, *_silhouetteMapStateSet, name);
    }
    pass.silhouettePass->setDepthComparison(depthComparison);
    const unsigned int mask = cv.getTraversalMask();
    cv.setTraversalMask(~0u); // the pass draws only its edges, whatever the view's mask
    pass.silhouettePass->cull(cv, pass.frustum, pass.depthTexture.get(), casters, light.homogeneous());
    cv.setTraversalMask(mask);
}

void SilhouetteShadowTechnique::updateViewUniforms(osgUtil::CullVisitor& cv, ViewData& vd,
                                                   const std::vector<FoundLight>& lights,
                                                   const std::vector<int>& slots, detail::EyePassPlan& eye)
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
        faces = faces || vd.passes[s].frustum.faceCore > 0.0;
    }
    eye.usedSlots = static_cast<unsigned int>(used);
    eye.skippedSlots = 0;
    for (unsigned int s = 0; s < vd.slotSkipped.size() && s < 32; ++s)
        if (vd.slotInUse[s] && vd.slotSkipped[s]) eye.skippedSlots |= 1u << s;
    eye.cubeFaces = faces;
    vd.maskLight->set(static_cast<int>(_debugLight));
    // The exact test's ray offset and the lookups' depth bias scale with the shadowed scene's
    // bound, in eye space.
    const osg::BoundingSphere& bound = _shadowedScene ? _shadowedScene->getBound() : osg::BoundingSphere();
    if (bound.valid())
    {
        const osg::Matrixd& worldToEye = *cv.getModelViewMatrix();
        const osg::Vec3d centre = bound.center() * worldToEye;
        const double scale = osg::Matrixd::transform3x3(osg::Vec3d(1.0, 0.0, 0.0), worldToEye).length();
        vd.listRayFrame->set(osg::Vec4f(centre, float(double(_shadowRayOffset) * bound.radius() * scale)));
        vd.lookupBiasFrame->set(osg::Vec4f(centre, float(double(shader::LOOKUP_BIAS) * bound.radius() * scale)));
    }
    else
    {
        vd.listRayFrame->set(osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
        vd.lookupBiasFrame->set(osg::Vec4f(0.0f, 0.0f, 0.0f, 0.0f));
    }
}

} // namespace osgShadowSilhouette
