// Internal: the eye pass's configuration for one frame of one view, as a plain value.
#ifndef OSGSHADOWSILHOUETTE_EYEPASS_H
#define OSGSHADOWSILHOUETTE_EYEPASS_H

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/StateSet>

#include <map>
#include <string>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** What the receivers' shading needs to know of one frame of one view, as cull() decides it
 *  (mode, method, slots in use). eyePassDefines() turns it into the shader defines. */
struct EyePassPlan
{
    SilhouetteShadowTechnique::Mode mode = SilhouetteShadowTechnique::SHADOW_MAP; ///< the mode rendered
    SilhouetteShadowTechnique::DebugView debugView = SilhouetteShadowTechnique::DEBUG_NONE;
    bool perPixelLighting = true;
    bool triangleLists = false;  ///< HYBRID resolves silhouette pixels with triangle lists
    bool listImages = false;     ///< ... read as images
    bool listBlockHeads = false; ///< ... with each walk's prologue from storage blocks
    bool countExact = false;     ///< ... counting the pixels it resolves (statistics)
    bool listSoft = false;       ///< ... casting shadow rays to lights with a size (soft shadows)
    bool edgeMasks = false;      ///< HYBRID's edge masks
    unsigned int listSlots = 1;  ///< slots with triangle lists (their storage blocks or images)
    unsigned int slotCapacity = 1; ///< slots the eye pass declares (sizes the map arrays)
    unsigned int usedSlots = 0;  ///< slots 0 .. usedSlots-1 are evaluated
    unsigned int skippedSlots = 0; ///< bit s: slot s is a cube face with nothing to shadow, left out
    bool cubeFaces = false;      ///< a point light's cube faces take slots
    /** SHADOW_MAP's filter, or SILHOUETTE_MAP's FILTER_SILHOUETTE (the other modes' eye passes
     *  ignore it). */
    SilhouetteShadowTechnique::Filter filter = SilhouetteShadowTechnique::FILTER_PCF_2X2;
    unsigned int filterWindow = 1; ///< FILTER_PCF's N
};

/** The defines a plan sets (name -> value; "" for a define without a value). Every other
 *  define of eyePassDefineNames() is absent. A pure function. */
std::map<std::string, std::string> eyePassDefines(const EyePassPlan& plan);

/** Every define eyePassDefines() may set: those the eye pass's configuration owns. */
const std::vector<std::string>& eyePassDefineNames();

/** Sets @p defines on @p ss and removes the other defines of eyePassDefineNames(); leaves
 *  every other define of @p ss (OSS_MAX_SHADOW_LIGHTS, a user's own) as it is. */
void applyEyePassDefines(osg::StateSet& ss, const std::map<std::string, std::string>& defines);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
