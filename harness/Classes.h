// The pixel classes of DebugView DEBUG_CLASSES (Chan and Durand's colours), counted.
#ifndef OSS_HARNESS_CLASSES_H
#define OSS_HARNESS_CLASSES_H

#include "Offscreen.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Image>

namespace osshar {

/** Pixels of a DEBUG_CLASSES image rendered on the mid-grey background of the masks. */
struct ClassCounts
{
    long long geometry = 0;         ///< not background
    long long silhouetteLit = 0;    ///< green: silhouette pixel, lit by the exact answer
    long long silhouetteShadow = 0; ///< black: silhouette pixel, shadowed
    long long mapLit = 0;           ///< red: the shadow map answers lit
    long long mapShadow = 0;        ///< blue: the shadow map answers shadowed
    long long other = 0;            ///< any other colour (should be 0)

    long long silhouette() const { return silhouetteLit + silhouetteShadow; }
    /** Percent of the geometry pixels treated as silhouette pixels (0 without geometry). */
    double silhouettePercent() const { return geometry ? 100.0 * double(silhouette()) / double(geometry) : 0.0; }
};

/** Classifies an RGB(A) 8-bit image (background 128 grey). */
ClassCounts countClasses(const osg::Image& image);

/** Renders light `light`'s classes with the technique's DEBUG_CLASSES view (the debug view
 *  and light are restored afterwards). */
osg::ref_ptr<osg::Image> renderClasses(Renderer& renderer, osgShadowSilhouette::SilhouetteShadowTechnique& technique,
                                       unsigned int light);

} // namespace osshar

#endif
