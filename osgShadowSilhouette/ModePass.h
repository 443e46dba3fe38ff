// Internal: the passes of one mode behind one small interface. The technique culls the
// receivers, finds the lights, assigns slots and renders each slot's depth map; a ModePass
// adds what its mode draws besides: per frame (its method, the eye pass's configuration),
// per slot after the depth pass (silhouette maps, triangle lists, edge masks), and after
// every light (the stencil passes over the eye's receivers). docs/architecture.md.
#ifndef OSGSHADOWSILHOUETTE_MODEPASS_H
#define OSGSHADOWSILHOUETTE_MODEPASS_H

#include "EyePass.h"
#include "FrameData.h"
#include "Warnings.h"

#include <osg/Referenced>
#include <osgShadow/ShadowedScene>
#include <osgUtil/CullVisitor>

#include <functional>
#include <string>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** The eye pass's own bindings (shadow maps, silhouette maps and edge masks, HYBRID's lists)
 *  win over the model's state on the same units: a model's texture on a map's unit would
 *  replace the map, its image or storage-buffer binding the lists. The receiver shading reads
 *  none of the model's units there; a program of the model's own that does needs another
 *  BaseTextureUnit. The maps' textures give up OVERRIDE where the ShadowSettings'
 *  UseOverrideForShadowMapTexture is false (SilhouetteShadowTechnique::mapBinding()). */
constexpr unsigned int EYE_PASS_BINDING = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;

class CasterVertexStages;

/** What a mode's passes read of the technique in one cull: the properties in effect and
 *  the state init() built. The technique fills it; the passes never write it. */
struct PassSettings
{
    SilhouetteShadowTechnique::Mode mode = SilhouetteShadowTechnique::SHADOW_MAP; ///< getMode() (warnings name it)
    unsigned int shadowMapSize = 0;
    unsigned int glGeneration = 0;    ///< maps rendered under another generation hold nothing
    float polygonOffsetFactor = 0.0f; ///< the depth passes' offset for the mode rendered
    float warpedPolygonOffsetFactor = 0.0f; ///< the same for a warped map (LightFrustum::warped)
    float polygonOffsetUnits = 0.0f;
    bool blockerCulling = true;
    bool hybridEdgeMask = true;
    SilhouetteShadowTechnique::HybridMethod hybridMethod = SilhouetteShadowTechnique::HYBRID_AUTO;
    SilhouetteShadowTechnique::DebugView debugView = SilhouetteShadowTechnique::DEBUG_NONE;
    unsigned int debugLight = 0;
    SilhouetteShadowTechnique::Filter filter = SilhouetteShadowTechnique::FILTER_PCF_2X2; ///< the map modes'
    unsigned int filterWindow = 1;                                                        ///< FILTER_PCF's N
    SilhouetteShadowTechnique::GpuExtraction gpuExtraction = SilhouetteShadowTechnique::GPU_EXTRACTION_MOVED_CASTERS;
    unsigned int softSamples = 64; ///< HYBRID's shadow rays per penumbra pixel (SoftSamples)
    SilhouetteShadowTechnique::Tuning tuning;
    unsigned int listSlots = 1;  ///< slots that can have triangle lists
    bool recordingStats = false; ///< setStats() has a live target
    osgShadow::ShadowedScene* shadowedScene = nullptr;
    osg::StateSet* silhouetteMapStateSet = nullptr;
    osg::StateSet* listStateSet = nullptr;
    osg::StateSet* listFrontOnlyStateSet = nullptr;
    ListedDrawables* listedDrawables = nullptr;
    CasterVertexStages* casterStages = nullptr; ///< the casters' own vertex stages in the light passes
    osg::Program* stencilProgram = nullptr;
    osg::Program* volumeProgram = nullptr;
    osg::Texture2D* defaultSilhouetteTexture = nullptr;    ///< an edge mask without edges
    osg::Texture2D* defaultNeighbourhoodTexture = nullptr; ///< a neighbourhood map without edges
    osg::StateSet* distanceMapStateSet = nullptr;          ///< FILTER_SILHOUETTE's distance maps
    osg::Texture2D* defaultDistanceTexture = nullptr;      ///< a distance map without edges
};

/** What the passes call back in the technique. */
struct PassServices
{
    Warn warnOnce;
    /** Culls the eye's receivers under the view's receiver state and @p pass. */
    std::function<void(osg::StateSet* pass)> cullReceivers;
    /** Whether a program given to addShadowShaders() lives (a lock and a scan: asked only
     *  where a stencil frame could draw the receivers with their own programs). */
    std::function<bool()> applicationPrograms;
    /** Names the alpha-tested drawables a stencil method takes as opaque, once each. */
    std::function<void(bool hybrid, bool lists)> warnAlphaTested;
    /** The view's silhouette edges found on the GPU, taking the casters GpuExtraction names. */
    std::function<GpuEdges*()> gpuEdges;
    /** Culls the shadowed scene's casters under @p pass into the current bin of a light-space
     *  pass whose model-view is the light's view (billboards turned as the eye sees them). */
    std::function<void(osg::StateSet* pass)> cullLightCasters;
};

/** One cull of one view, as a mode's passes see it. */
struct ModeFrame
{
    osgUtil::CullVisitor& cv;
    ViewData& vd;
    FrameContext& frame;
    SilhouetteShadowTechnique::Statistics& stats;
    EyePassPlan& eye;
    const PassSettings& settings;
    const PassServices& services;
};

/** One slot after its depth pass. */
struct SlotCull
{
    const LightDescription& light;
    unsigned int slot;
    LightPass& pass;
    bool depthRendered;         ///< the depth map was drawn this frame (not kept from an earlier one)
    osg::Texture2D*& secondMap; ///< the slot's silhouette map or edge mask, for the eye pass
};

/** The passes one mode adds to the technique's. Stateless: a view's state lives in its
 *  ViewData and LightPass, so one ModePass serves every view and thread. */
class ModePass : public osg::Referenced
{
public:
    /** Whether each slot has a depth map (every mode but SHADOW_VOLUME). */
    virtual bool drawsMaps() const { return true; }
    /** Whether the maps hold raw depths, compared by the eye pass (SILHOUETTE_MAP, SHADOW_MAP
     *  under a soft filter), not through hardware comparison. */
    virtual bool rawDepthMaps(const PassSettings&) const { return false; }
    /** The texture the slots' second units hold where a slot has no map of its own
     *  (SILHOUETTE_MAP's neighbourhood maps, HYBRID's edge masks); null: the mode binds none. */
    virtual osg::Texture2D* defaultSecondMap(const PassSettings&) const { return nullptr; }
    /** Before the lights, once the slots are planned (frame.slotsInUse): the frame's method
     *  (frame.triangleLists, frame.stencil) and the eye pass's configuration of the mode. */
    virtual void planFrame(ModeFrame&) {}
    /** Whether the slot's passes besides the depth map still suit the settings; false makes
     *  the slot render again even where its depth map could be kept. */
    virtual bool keepsSlotPasses(const LightPass&, const PassSettings&) const { return true; }
    /** Before a slot's depth pass: what the depth camera draws besides the casters (HYBRID's
     *  blocker queries), or null. */
    virtual osg::Node* depthPassQueries(ModeFrame&, LightPass&) { return nullptr; }
    /** After a slot's depth pass: the mode's own light-space passes, and the slot's second map. */
    virtual void cullSlot(ModeFrame&, SlotCull&) {}
    /** After every light's slots: the passes over the eye's receivers. */
    virtual void cullEyePasses(ModeFrame&, const std::vector<FoundLight>&, const std::vector<int>& /*slots*/) {}
};

/** The passes of @p mode, in a file each (ShadowMapMode.cpp: the technique's depth maps
 *  alone, SilhouetteMode.cpp, VolumeMode.cpp, HybridMode.cpp). */
osg::ref_ptr<ModePass> createModePass(SilhouetteShadowTechnique::Mode mode);
osg::ref_ptr<ModePass> createShadowMapModePass();
osg::ref_ptr<ModePass> createSilhouetteModePass();
osg::ref_ptr<ModePass> createVolumeModePass();
osg::ref_ptr<ModePass> createHybridModePass();

/** Culls a slot's silhouette-map pass (after its depth pass), reading the depth map raw
 *  (SILHOUETTE_MAP) or, with @p depthComparison (HYBRID's edge mask), through its comparison. */
void cullSilhouettePass(ModeFrame& mf, LightPass& pass, const LightDescription& light, bool depthComparison);

/** The stencil passes (volumes, masks, light passes) of SHADOW_VOLUME and HYBRID's stencil
 *  volumes over the eye's receivers, and their statistics. */
void cullStencilPasses(ModeFrame& mf, bool hybrid, const std::vector<FoundLight>& lights,
                       const std::vector<int>& slots);

/** Whether this frame's stencil passes leave a screen-space visibility for the receivers'
 *  own programs (and sets the view's passes up for it, or takes it down). */
bool cullScreenVisibility(ModeFrame& mf);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
