// Internal: what SHADOW_MAP's soft filters (oss_filter.frag.glsl) need of each light: its size
// (the technique's LightSize or the light's own) and PCSS's penumbra scale for each of its
// maps. Plain functions, tested on the CPU (cpu_soft_filter). docs/soft-shadows.md.
#ifndef OSGSHADOWSILHOUETTE_SOFTFILTER_H
#define OSGSHADOWSILHOUETTE_SOFTFILTER_H

#include <osgShadowSilhouette/LightSpace>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Light>
#include <osg/LightSource>
#include <osg/Vec2>
#include <osg/observer_ptr>

#include <string>
#include <utility>
#include <vector>

namespace osgShadowSilhouette {
namespace detail {

/** The largest angular radius, in degrees, a directional light's size may have: a light
 *  half as wide as the sky is no sun, and PCSS's tangent grows without bound toward 90. */
constexpr double MAX_DIRECTIONAL_SIZE_DEG = 45.0;

/** The LightSources of a scene that carry SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE,
 *  with their lights (found by init()). */
struct SizedLightSources : public osg::Referenced
{
    std::vector<std::pair<osg::observer_ptr<const osg::Light>, osg::observer_ptr<const osg::LightSource>>> sources;
};

/** The LightSources under @p node with a size of their own. */
osg::ref_ptr<SizedLightSources> findSizedLightSources(osg::Node& node);

/** A light's size for the soft filters (MEASURE.md: radius in scene units for point and spot
 *  lights, angular radius in degrees for directional ones): the user value
 *  LIGHT_SIZE_USER_VALUE of @p light, else of its LightSource in @p sources, else
 *  @p techniqueSize. A value that cannot be used (not a number, NaN, infinite, negative; a
 *  directional light's at MAX_DIRECTIONAL_SIZE_DEG or more) gives 0, a hard shadow, and
 *  @p refusal says why (empty otherwise). */
double lightSize(const osg::Light& light, const SizedLightSources* sources, LightDescription::Type type,
                 double techniqueSize, std::string& refusal);

/** PCSS's penumbra scale of one map: the radius, in the map's texture coordinates (x, y), of
 *  the penumbra a blocker casts on a receiver per unit of window depth between them, for a
 *  light of size @p size (lightSize()). Orthographic maps (directional light of angular
 *  radius theta): (z_r - z_b) (far - near) tan(theta) / width; perspective maps (sphere of
 *  radius R at the centre of projection): R (1/d_b - 1/d_r) / (2 tan(fov/2)), which is
 *  linear in window depth too. Both read the projection matrix: -P00 tan(theta) / P22 and
 *  -P00 R / P32 (OSG's row-vector matrices). 0 for size 0 or an invalid frustum. */
osg::Vec2 penumbraScale(const LightFrustum& frustum, LightDescription::Type type, double size);

/** HYBRID's shadow rays under a light with a size: of @p samples rays per pixel, the first
 *  pass (a quarter: one point of each ring of four of the rays' spiral, when there are at
 *  least 32 and a multiple of 4), whose answer a pixel keeps when its rays and its 2 x 2
 *  quad's all agree (oss_listSoftTerm()); @p samples where there is no first pass. */
inline int softFirstPass(int samples)
{
    return samples >= 32 && samples % 4 == 0 ? samples / 4 : samples;
}

/** How far, in texels, a filter reads around a point (a cube face's map must reach that far
 *  past its own square): 4 for the 2x2 PCF (the default margin), the window's half and two
 *  for FILTER_PCF, PCSS's largest radius and two for FILTER_PCSS; for SILHOUETTE_MAP's
 *  FILTER_SILHOUETTE, its samples' reach (SILDIST_SAMPLE_REACH) and the distance band's
 *  width beyond it, and two. */
double filterReachTexels(SilhouetteShadowTechnique::Filter filter, unsigned int window);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
