// Internal: each slot's depth map, the pass every mode but SHADOW_VOLUME draws: an RTT camera
// per slot rendering the casters' depth from the light, kept while what it depends on
// (PassInputs) holds still, with a mode's queries drawn in it (ModePass::depthPassQueries()).
#ifndef OSGSHADOWSILHOUETTE_DEPTHMAPPASS_H
#define OSGSHADOWSILHOUETTE_DEPTHMAPPASS_H

#include "ModePass.h"

#include <osg/StateSet>
#include <osg/Texture2D>

namespace osgShadowSilhouette {
namespace detail {

/** A size x size 24-bit depth texture sampled with hardware comparison and linear filtering
 *  (2x2 PCF), lit (1) outside its border. */
osg::ref_ptr<osg::Texture2D> createDepthTexture(unsigned int size);

/** A 1x1 depth texture at the far plane: every lookup is lit. Bound to unused shadow slots. */
osg::ref_ptr<osg::Texture2D> createLitTexture();

/** The state every depth pass shares: the depth program (alpha-tested cut-outs), the polygon
 *  offset, no colour, every caster writing its depth (LESS), both faces, no lighting or blending. */
osg::ref_ptr<osg::StateSet> createDepthPassStateSet(float polygonOffsetFactor, float polygonOffsetUnits);

/** Makes the slot's depth camera and texture anew when there are none, the map size changed,
 *  or the texture's comparison does not suit the mode (@p rawDepth: SILHOUETTE_MAP compares
 *  depths itself); a texture's comparison mode is fixed once GL has it. */
void fitDepthMap(LightPass& pass, unsigned int slot, unsigned int mapSize, bool rawDepth,
                 const osg::StateSet& depthPassState, osgShadow::ShadowedScene* scene);

/** Culls the slot's depth pass for pass.frustum with the mode's queries, or only the queries
 *  when its maps still hold what this frame would render (PassInputs unchanged and
 *  ModePass::keepsSlotPasses()). True when the depth map is drawn this frame. */
bool cullDepthMap(ModeFrame& mf, ModePass& mode, LightPass& pass, const LightDescription& light);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
