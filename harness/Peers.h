// osgShadow's own techniques ("peers") set up and measured as MEASURE.md's section "Masks of
// techniques that cannot write one" describes, so that their masks compare with the exact
// reference exactly like ours.
//
// The measurement setup: one light (ambient 0, diffuse 1, specular 0), a white osg::Material
// and zero global ambient applied with OVERRIDE, texture unit 0 replaced by a white texture
// with OVERRIDE (textures off), ambient bias (0, 1) where the technique has one, and a magenta
// clear colour that marks background. A pixel is shadowed where its luminance is at most half
// of the same pixel of a frame rendered without shadows, or where that frame is itself black.
// The frame time of a peer is measured in this same setup (the one its mask comes from).
#ifndef OSS_HARNESS_PEERS_H
#define OSS_HARNESS_PEERS_H

#include "Offscreen.h"
#include "Setup.h"

#include <osgShadow/ShadowSettings>
#include <osgShadow/ShadowTechnique>

#include <string>
#include <vector>

namespace osshar {

/** "osgShadow:" */
extern const char* const PEER_PREFIX;

/** The clear colour that marks background in peer frames (magenta: lit geometry is gray). */
osg::Vec4 peerBackground();

/** "osgShadow:ShadowMap", "osgShadow:SoftShadowMap", "osgShadow:LightSpacePerspectiveShadowMapCB",
 *  "osgShadow:ViewDependentShadowMap", "osgShadow:ParallelSplitShadowMap". */
std::vector<std::string> peerModes();

/** Whether mode names a peer (starts with "osgShadow:"). */
bool isPeerMode(const std::string& mode);

/** The peer technique of `mode` with a mapSize x mapSize map (PSSM: each of its 3 splits),
 *  ambient bias (0, 1) where it has one, shadowing `light` (when not null; PSSM's user light,
 *  its position taken in world coordinates, which makePeerRoot() makes exact); settings
 *  receives the texture size and the light number (VDSM reads them there). Null with a
 *  message for an unknown peer. */
osg::ref_ptr<osgShadow::ShadowTechnique> createPeerTechnique(const std::string& mode, unsigned int mapSize, osg::Light* light,
                                                             osgShadow::ShadowSettings& settings, std::string& error);

/** Sets the measurement light on the scene: light 0 (the first of scene.lights) gets ambient 0,
 *  diffuse 1, specular 0; the others are switched off by measurementStateSet(). */
void applyMeasurementLight(PreparedScene& scene);

/** The OVERRIDE state of the measurement setup for the scene's first light. */
osg::ref_ptr<osg::StateSet> measurementStateSet(const PreparedScene& scene);

/** The peer's root: a ShadowedScene with the technique over the content, carrying the
 *  measurement state; applies the measurement light (PSSM's user light shines in the world
 *  direction of the scene's first light). False with a message for an unknown peer. */
bool makePeerRoot(const std::string& mode, unsigned int mapSize, PreparedScene& scene, osg::ref_ptr<osg::Node>& root,
                  std::string& error);

/** The same content with the measurement state and no shadows (the unshadowed frame). */
osg::ref_ptr<osg::Node> makeUnshadowedRoot(const PreparedScene& scene);

/** What the two frames of a peer give. Both masks are MEASURE.md masks (row 0 at the top). */
struct PeerMask
{
    ossref::Mask mask;          ///< 0 shadowed, 255 lit, 128 background
    ossref::Mask vertexFacing;  ///< 0 where the unshadowed frame is black, 255 where lit, 128 background
    /** The shadowed frame's luminance over the unshadowed one's, clamped to [0, 1] (MEASURE.md's
     *  visibility of a technique without a visibility output: a soft technique's fraction); 0
     *  where the unshadowed frame is black, VIS_BACKGROUND on background. */
    ossref::VisibilityMask visibility;
};

/** Rec. 601 luma of an RGB(A) GL_UNSIGNED_BYTE pixel, 0..255. */
double luminance(const unsigned char* rgb);

/** Classifies a shadowed and an unshadowed RGB frame (bottom row first, as read back). */
PeerMask classifyPeerFrames(const osg::Image& shadowed, const osg::Image& unshadowed);

/** Renders the two frames of a peer: the renderer's current scene (the peer's root) and then
 *  `unshadowed`, and classifies them. The renderer's scene is restored. */
PeerMask renderPeerMask(Renderer& renderer, osg::Node* peerRoot, osg::Node* unshadowed);

/** The geometric facing of each pixel, as the reference sees it: the reference mask with no
 *  casters (0 where the face normal faces away from the light, 255 where it faces it). */
ossref::Mask referenceFacing(const osg::Node& content, const ossref::Camera& camera, const ossref::Light& light);

/** The reference with the pixels where vertex normals and face normals disagree on facing
 *  (vertexFacing against faceFacing) added to its grazing band, so that compareMasks leaves
 *  them out. `excluded` receives their number (pixels already in the band not counted). */
ossref::Mask excludeFacingDisagreement(const ossref::Mask& reference, const ossref::Mask& faceFacing,
                                       const ossref::Mask& vertexFacing, long long& excluded);

} // namespace osshar

#endif
