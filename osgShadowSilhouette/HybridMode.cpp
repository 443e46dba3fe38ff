// HYBRID's passes (Chan and Durand 2004): the depth map answers where its 2x2 PCF is certain;
// silhouette pixels (and the edge masks' texels) are resolved exactly, by triangle lists per
// light-space texel (TriangleListPass, OpenGL 4.3) or by stencil shadow volumes, with blocker
// queries in the depth pass to skip the volumes of hidden casters.
#include "ModePass.h"
#include "RenderLeaves.h"
#include "SoftFilter.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/BindImageTexture>
#include <osg/BufferIndexBinding>
#include <osg/GLExtensions>

#include <algorithm>
#include <unordered_set>

namespace osgShadowSilhouette {
namespace detail {

namespace {

using Technique = SilhouetteShadowTechnique;

/** Whether this view's HYBRID frames can use triangle lists (HybridMethod, GL version). */
bool useTriangleLists(ModeFrame& mf)
{
    const Technique::HybridMethod method = mf.settings.hybridMethod;
    const osg::State* state = mf.cv.getState();
    const osg::GLExtensions* ext = state ? osg::GLExtensions::Get(state->getContextID(), false) : nullptr;
    const bool supported = ext && ext->glVersion >= 4.3f && ext->glMemoryBarrier;
    if (method == Technique::HYBRID_STENCIL_VOLUMES)
    {
        // The volumes answer for the light's centre alone: a light with a size takes the lists.
        if (!mf.frame.sizedLights) return false;
        mf.services.warnOnce(WARN_STENCIL_SOFT,
                             std::string("HybridMethod HYBRID_STENCIL_VOLUMES casts hard shadows only; a light with a "
                                         "size (LightSize or ShadowLightSize) ") +
                                 (supported ? "takes HYBRID_TRIANGLE_LISTS' soft shadows"
                                            : "casts its hard shadow (triangle lists need OpenGL 4.3)"));
        return supported;
    }
    if (!supported && method == Technique::HYBRID_TRIANGLE_LISTS)
        mf.services.warnOnce(WARN_NO_TRIANGLE_LISTS,
                             "HybridMethod HYBRID_TRIANGLE_LISTS needs OpenGL 4.3 (shader storage buffers, image "
                             "atomics) and the context has less; using HYBRID_STENCIL_VOLUMES");
    return supported;
}

/** Whether the frame's slots fit the storage blocks the lists take (one per slot). */
bool listSlotsFit(ModeFrame& mf)
{
    const osg::State* state = mf.cv.getState();
    const unsigned int blocks = state ? TriangleListPass::fragmentStorageBlocks(state->getContextID()) : 0;
    const unsigned int listLimit = blocks > 0 ? std::min(mf.settings.listSlots, blocks) : mf.settings.listSlots;
    if (mf.frame.slotsInUse <= listLimit) return true;
    mf.services.warnOnce(WARN_LIST_SLOTS, "HYBRID: this frame's " + std::to_string(mf.frame.slotsInUse) +
                                              " shadow maps (cube faces included) exceed the " +
                                              std::to_string(listLimit) +
                                              " that triangle lists hold (one fragment shader storage block each: "
                                              "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS is " +
                                              std::to_string(blocks) + "); using HYBRID_STENCIL_VOLUMES");
    return false;
}

/** How the eye pass reads the lists: as images, with each walk's prologue from blocks. */
void planListReads(ModeFrame& mf)
{
    const unsigned int slots = std::max(1u, mf.frame.slotsInUse);
    std::size_t listTexels = 0;
    for (unsigned int slot = 0; slot < mf.frame.slotsInUse && slot < mf.vd.passes.size(); ++slot)
        if (const TriangleListPass* lists = mf.vd.passes[slot].listPass.get())
            listTexels = std::max(listTexels, lists->getBufferSize() / 16);
    const osg::State* state = mf.cv.getState();
    Technique::Statistics& stats = mf.stats;
    stats.listImages = mf.frame.triangleLists && mf.settings.tuning.listImageReads && state &&
                       TriangleListPass::imageReadsFit(state->getContextID(), slots, listTexels);
    stats.listBlockHeads = stats.listImages && mf.settings.tuning.listBlockHeads &&
                           TriangleListPass::blockHeadsFit(state->getContextID(), slots);
    mf.eye.listImages = stats.listImages;
    mf.eye.listBlockHeads = stats.listBlockHeads;
}

/** The lists of a slot that overflowed are rebuilt with room for what they needed (read back
 *  a frame or two after the build): true and the new capacities when they can grow. */
bool listsMustGrow(ModeFrame& mf, const TriangleListPass& lists, unsigned int slot, std::size_t& nodes,
                   std::size_t& triangles)
{
    std::size_t neededNodes = 0, neededTriangles = 0;
    if (!lists.overflowed(neededNodes, neededTriangles)) return false;
    const std::size_t neededListed = std::min(neededTriangles, TriangleListPass::MAX_TRIANGLES);
    nodes = std::min(neededNodes + neededNodes / 4, TriangleListPass::MAX_NODES);
    triangles = std::max(triangles, neededListed);
    const bool grow = nodes > lists.getNodeCapacity() || neededListed > lists.getTriangleCapacity();
    mf.services.warnOnce(grow ? WARN_LIST_OVERFLOW : WARN_LIST_FULL,
                         "HYBRID: the triangle lists of shadow slot " + std::to_string(slot) + " needed " +
                             std::to_string(neededNodes) + " nodes and " + std::to_string(neededTriangles) +
                             " triangles, with room for " + std::to_string(lists.getNodeCapacity()) + " and " +
                             std::to_string(lists.getTriangleCapacity()) +
                             "; that light's silhouette pixels took the shadow map's answer" +
                             (grow ? std::string("; the lists are rebuilt larger")
                                   : "; the lists cannot grow further (" + std::to_string(TriangleListPass::MAX_NODES) +
                                         " nodes, " + std::to_string(TriangleListPass::MAX_TRIANGLES) + " triangles)"));
    return grow;
}

/** The slot's list pass, made anew when the casters' triangles outgrow it or it overflowed. */
void fitListPass(ModeFrame& mf, LightPass& pass, unsigned int slot)
{
    std::size_t triangles = 0;
    for (const Caster& caster : mf.frame.casterList) triangles += caster.mesh->getAdjacency().report.inputTriangles;
    const unsigned int grid = TriangleListPass::MAX_GRID_SIZE;
    std::size_t nodes = 0;
    const bool grow = pass.listPass && listsMustGrow(mf, *pass.listPass, slot, nodes, triangles);
    if (pass.listPass && pass.listPass->fits(grid, triangles) && !grow) return;
    const PassSettings& settings = mf.settings;
    pass.listPass = new TriangleListPass(grid, triangles, *settings.listStateSet,
                                         "osgShadowSilhouette triangle lists " + std::to_string(slot), grow ? nodes : 0,
                                         settings.tuning.listNodeReservePerTexel);
    auto* scene = new TraverseShadowedSceneCallback(settings.shadowedScene);
    scene->setListed(settings.listedDrawables);
    scene->setCasterStages(settings.casterStages);
    pass.listPass->getCamera()->setCullCallback(scene);
    pass.listRendered = PassInputs();
}

/** Builds the slot's lists again unless they still describe its depth map and receivers. */
void cullListBuild(ModeFrame& mf, LightPass& pass, const LightDescription& light)
{
    const FrameContext& frame = mf.frame;
    const bool sameReceivers =
        pass.listReceivers._min == frame.receivers._min && pass.listReceivers._max == frame.receivers._max;
    if (pass.listRendered == pass.rendered && sameReceivers) return;
    if (auto* scene = dynamic_cast<TraverseShadowedSceneCallback*>(pass.listPass->getCamera()->getCullCallback()))
    {
        scene->setExcluded(frame.nonFinite);
        scene->setBillboards(frame.billboards);
        std::unordered_set<const osg::Drawable*> closed;
        for (const Caster& caster : frame.casterList)
            if (caster.closed) closed.insert(caster.geometry.get());
        scene->setMarked(std::move(closed), mf.settings.listFrontOnlyStateSet);
    }
    const unsigned int mask = mf.cv.getTraversalMask();
    osgShadow::ShadowedScene* shadowed = mf.settings.shadowedScene;
    mf.cv.setTraversalMask(mask & shadowed->getShadowSettings()->getCastsShadowTraversalMask());
    pass.listPass->cull(mf.cv, pass.frustum, light.type != LightDescription::DIRECTIONAL, frame.receivers);
    mf.cv.setTraversalMask(mask);
    pass.listRendered = pass.rendered;
    pass.listReceivers = frame.receivers;
}

/** Binds the slot's lists for the eye pass: as a storage block and as a read-only image. */
void bindLists(ModeFrame& mf, const LightPass& pass, unsigned int slot, const LightDescription& light)
{
    osg::StateSet& ss = *mf.vd.receiverStateSet;
    const TriangleListPass& lists = *pass.listPass;
    const unsigned int binding = shader::LIST_READ_BINDING + slot;
    auto* bound = dynamic_cast<osg::ShaderStorageBufferBinding*>(
        ss.getAttribute(osg::StateAttribute::SHADERSTORAGEBUFFERBINDING, binding));
    if (!bound || bound->getBufferData() != lists.getBuffer())
        ss.setAttributeAndModes(
            new osg::ShaderStorageBufferBinding(binding, lists.getBuffer(), 0, lists.getBufferSize()),
            EYE_PASS_BINDING);
    // The same buffer as a read-only image, for eye passes that read images (OSS_LIST_IMAGES).
    const unsigned int unit = shader::LIST_READ_IMAGE_UNIT + slot;
    auto* image = dynamic_cast<osg::BindImageTexture*>(ss.getAttribute(osg::StateAttribute::BINDIMAGETEXTURE, unit));
    if (!image || image->getTexture() != lists.getImageView())
        ss.setAttributeAndModes(
            new osg::BindImageTexture(unit, lists.getImageView(), osg::BindImageTexture::READ_ONLY, GL_RGBA32UI_EXT),
            EYE_PASS_BINDING);
    mf.vd.listCapacity->setElement(slot, lists.getNodeCapacity(), lists.getTriangleCapacity(), lists.getGridSize(), 0u);
    mf.vd.listPerspective->setElement(slot, light.type != LightDescription::DIRECTIONAL ? 1 : 0);
}

/** A light with a size: the eye pass casts shadow rays to it (oss_listSoftTerm()), from the
 *  pixels its blocker search over the light's footprint classifies as penumbra. */
void bindSoftLight(ModeFrame& mf, SlotCull& slot)
{
    const LightDescription& light = slot.light;
    if (!(light.size > 0.0)) return;
    const bool directional = light.type == LightDescription::DIRECTIONAL;
    osg::Vec4d eye = light.homogeneous() * *mf.cv.getModelViewMatrix();
    if (directional)
        eye = osg::Vec4d(osg::Vec3d(eye.x(), eye.y(), eye.z()) / osg::Vec3d(eye.x(), eye.y(), eye.z()).length(), 0.0);
    const double size = directional ? 1.0 - std::cos(osg::DegreesToRadians(light.size)) : light.size;
    mf.vd.listLight->setElement(slot.slot, osg::Vec4f(eye));
    mf.vd.listLightSize->setElement(slot.slot, float(size));
    mf.vd.filterScale->setElement(slot.slot, osg::Vec2f(penumbraScale(slot.pass.frustum, light.type, light.size)));
    const int samples = int(mf.settings.softSamples);
    mf.vd.listSoftSamples->set(samples, softFirstPass(samples));
    mf.eye.listSoft = true;
}

/** The triangle-list pass of one slot (after its depth pass): built unless its lists still
 *  hold what this frame would build, and bound for the eye pass. */
void cullTriangleListPass(ModeFrame& mf, SlotCull& slot)
{
    fitListPass(mf, slot.pass, slot.slot);
    cullListBuild(mf, slot.pass, slot.light);
    // The counts of a finished build come back through the eye pass of a later frame.
    if (slot.pass.listPass->countPending()) slot.pass.listPass->getPollNode()->accept(mf.cv);
    bindLists(mf, slot.pass, slot.slot, slot.light);
    bindSoftLight(mf, slot);
}

/** HybridEdgeMask: the slot's silhouette edges drawn into its silhouette map
 *  (conservatively, occluded edges left out) unless it still holds what this frame would
 *  draw; the eye pass (lists) or the mask pass (stencil volumes) resolves exactly the texels
 *  an edge touches as well as where the 2x2 PCF lies strictly between 0 and 1. */
void cullEdgeMask(ModeFrame& mf, SlotCull& slot)
{
    LightPass& pass = slot.pass;
    if (!pass.silhouettePass || pass.silhouettePass->getMapSize() != mf.settings.shadowMapSize)
        pass.edgesRendered = PassInputs();
    if (!(pass.edgesRendered == pass.rendered)) // the mask describes another depth map
    {
        cullSilhouettePass(mf, pass, slot.light, true);
        pass.edgesRendered = pass.rendered;
    }
    slot.secondMap = pass.silhouettePass->getTexture();
    mf.stats.silhouetteEdges += static_cast<unsigned int>(pass.silhouettePass->getEdges()->getEdgeCount());
}

class HybridModePass : public ModePass
{
public:
    osg::Texture2D* defaultSecondMap(const PassSettings& settings) const override
    {
        return settings.hybridEdgeMask ? settings.defaultSilhouetteTexture : nullptr;
    }

    void planFrame(ModeFrame& mf) override
    {
        FrameContext& frame = mf.frame;
        frame.triangleLists = useTriangleLists(mf) && listSlotsFit(mf);
        // One storage block (or image) per slot in use: the eye pass declares no more than it reads.
        mf.eye.triangleLists = frame.triangleLists;
        mf.eye.listSlots = std::max(1u, frame.slotsInUse);
        planListReads(mf);
        mf.stats.triangleLists = frame.triangleLists;
        mf.services.warnAlphaTested(true, frame.triangleLists);
        frame.stencil = !frame.triangleLists;
        // Statistics of the lists: the fragments resolved exactly, counted in the eye pass.
        mf.eye.countExact = frame.triangleLists && mf.settings.recordingStats;
        if (mf.eye.countExact)
        {
            mf.vd.exactBegin->accept(mf.cv);
            mf.vd.exactEnd->accept(mf.cv);
            mf.stats.silhouettePixels = mf.vd.exactCounter->getLastValue();
            if (frame.sizedLights && mf.stats.silhouettePixels >= 0)
            {
                // Soft frames count the penumbra pixels that cast rays (and hard slots' silhouette
                // pixels), and of those the ones that stopped after the first pass.
                const long long samples = mf.settings.softSamples;
                mf.stats.penumbraPixels = mf.stats.silhouettePixels;
                mf.stats.penumbraAgreed = std::max(0LL, mf.vd.exactCounter->getLastValue(1));
                mf.stats.shadowRays = mf.stats.penumbraPixels * samples -
                                      mf.stats.penumbraAgreed * (samples - softFirstPass(int(samples)));
            }
        }
        mf.eye.edgeMasks = mf.settings.hybridEdgeMask;
    }

    osg::Node* depthPassQueries(ModeFrame& mf, LightPass& pass) override
    {
        // Blocker culling tests casters against this map alone: not for a cube face or a
        // cascade, which sees only part of the light's casters; triangle lists need no volumes to skip; and
        // not with the edge mask: a caster the map's samples call hidden may still shadow
        // what shows through gaps thinner than a texel, which is what the edge mask resolves.
        const PassSettings& settings = mf.settings;
        const bool blockers =
            settings.blockerCulling && !settings.hybridEdgeMask && !mf.frame.triangleLists && !pass.frustum.partial();
        if (!blockers) return nullptr; // and cullDepthMap() drops the slot's queries
        if (!pass.blockers) pass.blockers = new BlockerQueries;
        pass.blockers->update(mf.frame.casterList);
        return pass.blockers->getNode();
    }

    void cullSlot(ModeFrame& mf, SlotCull& slot) override
    {
        if (mf.frame.triangleLists) cullTriangleListPass(mf, slot);
        if (mf.settings.hybridEdgeMask) cullEdgeMask(mf, slot);
    }

    void cullEyePasses(ModeFrame& mf, const std::vector<FoundLight>& lights, const std::vector<int>& slots) override
    {
        if (mf.frame.stencil) cullStencilPasses(mf, true, lights, slots);
    }
};

} // namespace

osg::ref_ptr<ModePass> createHybridModePass()
{
    return new HybridModePass;
}

} // namespace detail
} // namespace osgShadowSilhouette
