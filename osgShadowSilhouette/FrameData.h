// Internal: what SilhouetteShadowTechnique keeps per view and per shadow slot, and what one
// cull of one view shares between its lights and its mode's passes (ModePass.h).
#ifndef OSGSHADOWSILHOUETTE_FRAMEDATA_H
#define OSGSHADOWSILHOUETTE_FRAMEDATA_H

#include "GpuEdges.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Camera>
#include <osg/Depth>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osg/Uniform>

#include <memory>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** Everything a light's depth and silhouette maps depend on. Equal inputs: the maps still
 *  hold this frame's content and need not be rendered again. */
struct PassInputs
{
    bool valid = false;
    unsigned int glGeneration = 0; ///< SilhouetteShadowTechnique::getGLGeneration() when rendered
    SilhouetteShadowTechnique::Mode mode = SilhouetteShadowTechnique::SHADOW_MAP;
    std::size_t casters = 0; ///< FrameContext::casterSignature
    osg::Matrixd view, projection;
    osg::Vec4d light;
    float polygonOffsetFactor = 0.0f; ///< getEffectivePolygonOffsetFactor() when rendered
    /** getGpuExtraction() when rendered: which casters' edges the silhouette maps took from the GPU. */
    SilhouetteShadowTechnique::GpuExtraction gpuExtraction = SilhouetteShadowTechnique::GPU_EXTRACTION_MOVED_CASTERS;
    bool operator==(const PassInputs& o) const
    {
        return valid && o.valid && glGeneration == o.glGeneration && mode == o.mode && casters == o.casters &&
               view == o.view && projection == o.projection && light == o.light &&
               polygonOffsetFactor == o.polygonOffsetFactor && gpuExtraction == o.gpuExtraction;
    }
};

/** A positional light found in the view, in world coordinates. */
struct FoundLight
{
    osg::ref_ptr<const osg::Light> light;
    LightDescription description;
};

/** The state of one shadow slot (a light's map, or one cube face of a point light) in one view. */
struct LightPass
{
    osg::ref_ptr<osg::Camera> depthCamera;
    osg::ref_ptr<osg::Texture2D> depthTexture;
    osg::ref_ptr<SilhouetteMapPass> silhouettePass; ///< SILHOUETTE_MAP, and HYBRID's edge mask; made on first use
    osg::ref_ptr<BlockerQueries> blockers;          ///< HYBRID with BlockerCulling, made on first use
    osg::ref_ptr<TriangleListPass> listPass;        ///< HYBRID with triangle lists, made on first use
    osg::ref_ptr<DrawnSamples> samples;             ///< whether the depth pass's newest build drew a caster
    PassInputs listRendered;                        ///< what the lists were last built from
    osg::BoundingBoxd listReceivers;                ///< ... and the receivers' box they were tested against
    PassInputs edgesRendered;                       ///< what HYBRID's edge mask was last drawn from
    LightFrustum frustum;
    PassInputs rendered; ///< what the maps were last rendered from (invalid: never)
};

/** Everything one view (CullVisitor) needs per frame. */
struct ViewData : public osg::Referenced
{
    unsigned int baseUnit = 8;    ///< slot s's depth map is on texture unit baseUnit + s
    unsigned int pairedSlots = 1; ///< the paired slots' second maps follow on baseUnit + pairedSlots + s
    unsigned int mapBinding = 0;  ///< how the maps' textures are bound (OVERRIDE or not)
    osg::ref_ptr<osg::StateSet> receiverStateSet;
    osg::ref_ptr<osg::StateSet> receiverPassStateSet; ///< inside receiverStateSet: the stencil modes' lighting program
    osg::ref_ptr<osg::StateSet> prepassStateSet;      ///< inside receiverStateSet: the depth prepass (DepthPrepass)
    osg::ref_ptr<osg::Depth> prepassDepth;            ///< the eye pass's LEQUAL after the prepass
    osg::ref_ptr<osg::Uniform> numLights, lightIndex, shadowSlot, eyeToShadow, maskLight, slotOwner, slotCore,
        slotDepths;
    osg::ref_ptr<osg::Uniform> filterScale; ///< PCSS: each slot's penumbraScale() (SoftFilter.h)
    osg::ref_ptr<osg::Uniform> listCapacity, listPerspective, listRayFrame; ///< HYBRID with triangle lists
    osg::ref_ptr<osg::Uniform> listLight, listLightSize, listSoftSamples, listEyeToPattern; ///< ... and soft shadows
    osg::ref_ptr<osg::Uniform> lookupBiasFrame; ///< the map lookups' depth bias (LOOKUP_BIAS_FRAME)
    std::vector<LightPass> passes;              ///< per shadow slot: the lights' own, then cube faces
    std::vector<LightDescription> lastLights;   ///< the lights of this view's last cull (steadied())
    std::vector<bool> slotInUse;                ///< slots whose map this frame's receivers read
    std::vector<bool> slotSkipped;             ///< ... of those, cube faces the eye pass leaves out (nothing to shadow)
    osg::ref_ptr<StencilShadowPasses> stencil; ///< SHADOW_VOLUME and HYBRID eye passes
    osg::ref_ptr<GpuEdges> gpuEdges;           ///< the edges found on the GPU (maps, edge masks); null until needed
    /** ... and their screen-space visibility (detail::ScreenVisibility) for the receivers'
     *  own programs; null until needed. */
    osg::ref_ptr<osg::Referenced> screenVisibility;
    /** HYBRID with triangle lists, while statistics are recorded (setStats()): the fragments
     *  the eye pass resolves exactly (an atomic counter), and the nodes that bind it before
     *  the receivers and read it back after them. */
    osg::ref_ptr<GpuCounter> exactCounter;
    osg::ref_ptr<osg::Node> exactBegin, exactEnd;
};

/** What one cull of one view shares between its lights. */
struct FrameContext
{
    SilhouetteShadowTechnique::Mode mode = SilhouetteShadowTechnique::SHADOW_MAP; ///< the mode this view renders
    osg::BoundingBoxd receivers, casters; ///< world bounds under the receive / cast masks
    std::vector<osg::Vec3d> region;       ///< hull points of what the view sees of the receivers
    std::vector<Caster> casterList;       ///< triangle casters (not needed by SHADOW_MAP)
    std::size_t casterSignature = 0;      ///< hash of the casters' drawables, matrices and array versions
    std::vector<CasterPart> casterParts;  ///< the casters drawable by drawable (cube faces' choice)
    bool triangleLists = false;           ///< HYBRID resolves silhouette pixels with triangle lists
    bool sizedLights = false;             ///< a light found has a size (soft shadows)
    bool stencil = false;        ///< the eye pass runs stencil passes (SHADOW_VOLUME, HYBRID's stencil volumes)
    unsigned int slotsInUse = 0; ///< slots 0 .. slotsInUse-1 hold this frame's lights and cube faces
    std::vector<const osg::Drawable*> nonFinite; ///< casters with NaN or infinite vertices: left out
    ViewPoint view;                              ///< the view's LOD choices and billboard turns
    /** The casters' billboard drawables: each instance's matrix (drawable -> world) as the
     *  view turns it; the light passes draw them so, not turned toward the light. */
    std::shared_ptr<const BillboardMatrices> billboards;
};

/** This frame's shadow slots: per light its slot (-1: unshadowed), its frusta (one, or a
 *  point light's cube faces) and the slot of its second face; the faces after the first
 *  take the slots after the lights' own. */
struct SlotPlan
{
    std::vector<int> slots;
    std::vector<std::vector<LightFrustum>> frusta;
    std::vector<unsigned int> firstFaceSlot;
    unsigned int slotsInUse = 0; ///< slots 0 .. slotsInUse-1 hold the lights and their cube faces
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
