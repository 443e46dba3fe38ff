/* -*-c++-*- */
/* osgShadowSilhouette - exact reference shadow masks.
 *
 * Ray casting with Embree 3 following the conventions of MEASURE.md: one primary ray
 * through each pixel centre, one shadow ray from the visible point toward the light; for
 * lights with a size, the visible fraction of the light (visibility masks).
 * Used by the tests, the renderer (--mask) and the benchmark to score every mode.
 */
#ifndef OSGSHADOWSILHOUETTE_REFERENCE
#define OSGSHADOWSILHOUETTE_REFERENCE 1

#include <osg/AlphaFunc>
#include <osg/Camera>
#include <osg/Image>
#include <osg/Light>
#include <osg/LightSource>
#include <osg/Matrixd>
#include <osg/Node>
#include <osg/Texture>
#include <osg/Vec2f>
#include <osg/Vec3d>
#include <osg/ref_ptr>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ossref {

/** A width x height mask (Mask, VisibilityMask) of `fill` values, grazing all 0. */
template <class MaskT, class Value>
MaskT filledMask(int width, int height, Value fill)
{
    MaskT m;
    m.width = width > 0 ? width : 0;
    m.height = height > 0 ? height : 0;
    m.value.assign(size_t(m.width) * size_t(m.height), fill);
    m.grazing.assign(m.value.size(), 0);
    return m;
}

/** Mask values (MEASURE.md). */
enum MaskValue : uint8_t { MASK_NO_LIGHT = 0, MASK_BACKGROUND = 128, MASK_LIT = 255 };

/** N.L below this (and above 0) puts a pixel in the grazing band. */
constexpr double GRAZING_NDOTL = 0.05;

/** A pinhole camera exactly as OSG builds it: osg::Matrixd::lookAt(eye, center, up) and
 *  osg::Matrixd::perspective(fovyDeg, width / (double)height, near, far). Near and far do
 *  not change the rays and are not part of the camera. Pixels are in GL window
 *  coordinates: (0, 0) is the bottom-left pixel, its centre is at (0.5, 0.5). */
struct Camera
{
    osg::Vec3d eye{0.0, 0.0, 10.0};
    osg::Vec3d center{0.0, 0.0, 0.0};
    osg::Vec3d up{0.0, 1.0, 0.0};
    double fovyDeg = 30.0;
    int width = 1024;
    int height = 768;
};

/** The Camera of an osg::Camera: its view matrix (taken apart with getViewMatrixAsLookAt),
 *  its projection and its viewport size. False (and `out` untouched) when there is no
 *  viewport, the projection is not a symmetric perspective, or its aspect ratio differs
 *  from the viewport's by more than 1e-6 (relative): then no Camera gives the same rays. */
bool cameraFromOsg(const osg::Camera& camera, Camera& out);

/** The world-space ray through the window point (winX, winY) (GL window coordinates,
 *  pixel centres at +0.5). The direction is normalised; the origin is the eye. */
void primaryRay(const Camera& camera, double winX, double winY,
                osg::Vec3d& origin, osg::Vec3d& direction);

/** One light. DIRECTIONAL: `vector` is the direction TOWARD the light (need not be
 *  normalised). POINT and SPOT: `vector` is the world position. SPOT: points whose
 *  direction from the light makes an angle larger than spotCutoffDeg with spotDirection
 *  receive no light. `size` (MEASURE.md, "Soft shadows"): for POINT and SPOT the radius
 *  of the sphere around `vector` that emits, in scene units; for DIRECTIONAL the angular
 *  radius in degrees of the cone of directions around `vector` (as the renderer's
 *  --light-size). 0 (or anything not above 0) is a point or a single direction; a spot's
 *  cone still cuts by the direction from the light's centre. */
struct Light
{
    enum Type { DIRECTIONAL, POINT, SPOT };
    Type type = DIRECTIONAL;
    osg::Vec3d vector{0.0, 0.0, 1.0};
    osg::Vec3d spotDirection{0.0, 0.0, -1.0};
    double spotCutoffDeg = 180.0;
    double size = 0.0;
};

/** The Light equivalent of an osg::Light placed by the local-to-world matrix `world`
 *  (the matrix of its LightSource). Position w == 0 gives DIRECTIONAL (the direction is
 *  transformed by the upper 3x3 of `world`); otherwise the position is transformed by
 *  `world` and divided by w, and a spot cutoff below 180 degrees gives SPOT with the
 *  spot direction transformed by the upper 3x3. */
Light lightFromOsg(const osg::Light& light, const osg::Matrixd& world = osg::Matrixd::identity());

/** lightFromOsg() for a LightSource: the first of its world matrices (identity for a
 *  parentless or ABSOLUTE_RF source). A LightSource without a light gives the default
 *  Light. */
Light lightFromLightSource(const osg::LightSource& source);

/** A shadow mask, row 0 = TOP row (as in the PNG). value: 128 background, 0 no light,
 *  255 lit. grazing: 1 where the reference point lies in the band 0 < N.L < 0.05 (empty
 *  or all 0 for masks that come from images). */
struct Mask
{
    int width = 0;
    int height = 0;
    std::vector<uint8_t> value;
    std::vector<uint8_t> grazing;
    /** Per pixel the distance from the eye to the point the primary ray sees, in scene
     *  units (+inf on background), as the reference fills it; empty for masks from images. */
    std::vector<float> distance;

    /** A width x height mask filled with `fill`, grazing all 0, no distances. */
    static Mask filled(int width, int height, uint8_t fill = MASK_BACKGROUND)
    {
        return filledMask<Mask>(width, height, fill);
    }

    bool empty() const { return width <= 0 || height <= 0; }
    /** Value at (column x, row from the top). */
    uint8_t at(int x, int rowFromTop) const { return value[size_t(rowFromTop) * width + x]; }
    /** Value at GL window pixel (x, y), origin bottom-left. */
    uint8_t atGL(int x, int y) const { return at(x, height - 1 - y); }
    bool isGrazing(size_t i) const { return i < grazing.size() && grazing[i] != 0; }
    /** Number of pixels equal to v. */
    long long count(uint8_t v) const;
};

/** Visibility mask values (MEASURE.md, "Soft shadows"): round(v * VIS_FULL) for a
 *  visibility v in [0, 1], VIS_BACKGROUND where no geometry is seen. */
enum VisibilityValue : uint16_t
{
    VIS_NONE = 0,
    VIS_FULL = 65534,
    VIS_BACKGROUND = 65535
};

/** round(v * VIS_FULL), v clamped to [0, 1] (NaN gives 0). */
uint16_t encodeVisibility(double v);

/** The visibility of a mask value that is not VIS_BACKGROUND: value / VIS_FULL. */
inline double decodeVisibility(uint16_t value)
{
    return value / double(VIS_FULL);
}

/** A visibility mask: per pixel the fraction of the light a visible point sees, row 0 =
 *  TOP row (as in the PNG). grazing: 1 where the point lies in the band 0 < N.L < 0.05 of
 *  the light's centre (empty or all 0 for masks that come from images). */
struct VisibilityMask
{
    int width = 0;
    int height = 0;
    std::vector<uint16_t> value;
    std::vector<uint8_t> grazing;

    /** A width x height mask filled with `fill`, grazing all 0. */
    static VisibilityMask filled(int width, int height, uint16_t fill = VIS_BACKGROUND)
    {
        return filledMask<VisibilityMask>(width, height, fill);
    }

    bool empty() const { return width <= 0 || height <= 0; }
    /** Value at (column x, row from the top). */
    uint16_t at(int x, int rowFromTop) const { return value[size_t(rowFromTop) * width + x]; }
    /** Value at GL window pixel (x, y), origin bottom-left. */
    uint16_t atGL(int x, int y) const { return at(x, height - 1 - y); }
    /** Visibility at GL window pixel (x, y); not meaningful on background. */
    double visibilityGL(int x, int y) const { return decodeVisibility(atGL(x, y)); }
    bool isGrazing(size_t i) const { return i < grazing.size() && grazing[i] != 0; }
};

/** The alpha test that decides which fragments of a cut-out ("alpha-tested") triangle the
 *  rasterizer keeps, for camera and shadow passes alike. The fragment's alpha at texture
 *  coordinate (s, t) is alphaScale times the alpha of `image` sampled there as GL samples
 *  level 0 of a 2D texture (alphaScale alone without an image); the fragment is kept when
 *  `alpha func ref` holds. */
struct AlphaCutout
{
    /** The unit-0 osg::Texture2D's image (row 0 is t = 0, as GL uploads it); null when the
     *  triangle is not textured. Alphas come from osg::Image::getColor (1 for formats
     *  without alpha). */
    osg::ref_ptr<const osg::Image> image;
    osg::Texture::WrapMode wrapS = osg::Texture::REPEAT; ///< REPEAT, MIRROR, else clamp to edge
    osg::Texture::WrapMode wrapT = osg::Texture::REPEAT;
    bool nearest = false; ///< mag filter NEAREST: nearest texel; else bilinear
    osg::AlphaFunc::ComparisonFunction func = osg::AlphaFunc::ALWAYS;
    float ref = 0.0f;        ///< the AlphaFunc's reference value clamped to [0, 1]
    float alphaScale = 1.0f; ///< front diffuse alpha of the osg::Material (1 without), in [0, 1]
};

/** The sides of a triangle that the eye pass culls (GL_CULL_FACE), named by the winding
 *  of its vertices as collected, in world coordinates: the CCW side is the one from which
 *  they run counter-clockwise, the side that (v1 - v0) x (v2 - v0) points to. A bit mask. */
enum CulledSide : uint8_t
{
    CULL_NONE = 0,
    CULL_CCW_SIDE = 1,
    CULL_CW_SIDE = 2,
    CULL_BOTH_SIDES = 3
};

/** World-space triangles of a scene, as the reference sees them. Cut-outs are described by
 *  cutout, texCoords and cutouts; a scene without them leaves all three empty. */
struct TriangleSoup
{
    std::vector<osg::Vec3d> vertices;  ///< three per triangle, world coordinates
    std::vector<uint8_t> casts;         ///< per triangle: 1 if it casts shadows
    long long skipped = 0;              ///< triangles dropped: NaN/Inf or zero area
    /** Per triangle: index into `cutouts` of its alpha test, -1 for an opaque triangle.
     *  Empty when every triangle is opaque (read it through cutoutOf()). */
    std::vector<int> cutout;
    /** Three unit-0 texture coordinates per cut-out triangle, in triangle order: the k-th
     *  triangle whose cutout is not -1 owns texCoords[3k .. 3k + 2]. (0, 0) when its
     *  cut-out has no image. */
    std::vector<osg::Vec2f> texCoords;
    std::vector<AlphaCutout> cutouts; ///< the distinct alpha tests of the scene
    /** Per triangle: the CulledSide the eye pass culls. Empty when no triangle is culled
     *  (read it through culledOf()). */
    std::vector<uint8_t> culled;

    size_t size() const { return casts.size(); }
    int cutoutOf(size_t triangle) const { return cutout.empty() ? -1 : cutout[triangle]; }
    uint8_t culledOf(size_t triangle) const { return culled.empty() ? uint8_t(CULL_NONE) : culled[triangle]; }
};

/** Every triangle of every drawable under `scene`, in world coordinates (matrices of
 *  osg::Transform nodes accumulated; osg::Geometry through osg::TriangleIndexFunctor with
 *  float or double vertex arrays, other drawables through osg::TriangleFunctor). Nodes
 *  with (nodeMask & traversalMask) == 0 are skipped with their subgraph; a triangle casts
 *  when every node on its path passes (nodeMask & traversalMask & castsMask), as
 *  osgShadow's casts pass does. Only active children of switches are visited. An
 *  osg::Camera at the root is looked through (its children are the scene, its view matrix
 *  is ignored); nested osg::Camera nodes (render passes, HUDs) are skipped.
 *
 *  Cut-outs: the StateSets of the nodes and drawables on a triangle's path are accumulated
 *  as osg::State does (the innermost value wins, except that a value set with OVERRIDE
 *  keeps its descendants' values out unless they are PROTECTED) for GL_ALPHA_TEST, the
 *  osg::AlphaFunc, the osg::Material, and on texture unit 0 the texture attribute and the
 *  GL_TEXTURE_2D mode. A triangle is a cut-out when GL_ALPHA_TEST is ON and an AlphaFunc is
 *  present; its alpha is the Material's front diffuse alpha (1 without a Material) times,
 *  when an osg::Texture2D with an image is on unit 0 with GL_TEXTURE_2D ON and the
 *  osg::Geometry has a per-vertex osg::Vec2Array as texture coordinate array 0, the
 *  texture's alpha (AlphaCutout). Not modelled: vertex colours, osg::TexMat and texture
 *  coordinate generation, the texture environment (alphas are multiplied, as GL_MODULATE
 *  does), lighting (the Material's alpha is used with lighting on or off), mipmaps and the
 *  min filter (level 0 through the mag filter), border colours, other texture types and
 *  units, shaders that discard fragments themselves. A cut-out whose alpha cannot vary
 *  and passes (no texture, or func ALWAYS) is stored as opaque.
 *
 *  Face culling: GL_CULL_FACE, the osg::CullFace and the osg::FrontFace are accumulated by
 *  the same rules, from OpenGL's defaults (culling off, BACK, COUNTER_CLOCKWISE). With
 *  GL_CULL_FACE ON a triangle records in `culled` the side the CullFace's mode culls: BACK
 *  the side from which its front face (FrontFace) is not seen, FRONT the other, and
 *  FRONT_AND_BACK both. The winding is the world-space one, so a mirroring transform turns
 *  the culled side over as it does in GL. */
TriangleSoup collectTriangles(const osg::Node& scene, unsigned int castsMask = ~0u,
                              unsigned int traversalMask = ~0u);

/** collectTriangles() as a view through `camera` draws the scene: osg::LOD children chosen
 *  by the camera's distance to their centre or their pixel size on its viewport (LOD scale
 *  1, as osgUtil::CullVisitor), osg::Billboard drawables turned toward its eye. A null
 *  camera gives the overload above (LOD children in range at distance 0, billboards as
 *  they are stored). */
TriangleSoup collectTriangles(const osg::Node& scene, const Camera* camera, unsigned int castsMask = ~0u,
                              unsigned int traversalMask = ~0u);

/** A scene prepared for ray casting (Embree BVHs built once), to render reference masks
 *  for several cameras and lights. Cut-out triangles (TriangleSoup::cutouts) go into an
 *  Embree geometry of their own whose intersection and occlusion filters sample the alpha
 *  test at each hit, so that primary and shadow rays pass through the fragments the
 *  rasterizer discards. Culled sides (TriangleSoup::culled) are seen through by the primary
 *  rays alone (an intersection filter; triangles culled on both sides are left out of the
 *  primary scene): the eye pass honours the model's face culling, while the technique's
 *  light passes draw the casters with culling off, so shadow rays stay two-sided.
 *  render() is const and may be called from several threads. Throws
 *  std::runtime_error if Embree cannot be initialised, or if the soup has cut-outs or
 *  culled triangles and Embree was built without filter functions. Measured on two cores: 100k triangles
 *  build in ~0.1 s and render 1024x768 in ~0.2-0.4 s; 1M triangles build in ~1 s. */
class Tracer
{
public:
    explicit Tracer(const TriangleSoup& triangles);
    Tracer(const osg::Node& scene, unsigned int castsMask = ~0u, unsigned int traversalMask = ~0u);
    ~Tracer();
    Tracer(const Tracer&) = delete;
    Tracer& operator=(const Tracer&) = delete;

    /** The reference mask (see computeReferenceMask). `threads` 0 = all cores. */
    Mask render(const Camera& camera, const Light& light, unsigned int threads = 0) const;

    /** The reference visibility mask (see computeReferenceVisibility). `threads` 0 = all
     *  cores; the result does not depend on it. */
    VisibilityMask renderVisibility(const Camera& camera, const Light& light, unsigned int threads = 0) const;

    /** Shadow-ray offset used at world point p (see computeReferenceMask). */
    double epsilonAt(const osg::Vec3d& p) const;

    /** The offset's share of the scene's radius (DEFAULT_OFFSET_SCALE); for convergence
     *  studies (renderer --reference-offset). Not thread-safe against render(). */
    void setOffsetScale(double scale);
    double getOffsetScale() const;

    /** The triangles the camera's rays can hit: all but those culled on both sides. */
    size_t triangleCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};

/** The shadow ray's offset as a share of the scene's radius (computeReferenceMask). */
constexpr double DEFAULT_OFFSET_SCALE = 1e-6;

/** The exact reference mask of the triangles that a view through `camera` draws
 *  (collectTriangles with the camera). For each pixel one primary ray (tnear 0, no far limit)
 *  that passes through culled sides of triangles (TriangleSoup::culled); no hit -> 128. The hit is moved onto its triangle's plane in double precision (Embree's
 *  hit distance is a float). At the hit the geometric normal of the triangle, flipped to
 *  face the camera, is N; L is the normalised direction to the light. N.L <= 0 -> 0; a
 *  SPOT light whose cone excludes the point -> 0; otherwise a shadow ray toward the light
 *  (to infinity for DIRECTIONAL, up to the light position for POINT/SPOT) decides 0 if it
 *  is occluded by a casting triangle and 255 if not. The shadow ray starts at hit + eps*N
 *  and stops eps before the light, with eps = s * R + 1e-6 * |hit - C| (R, C: radius and
 *  centre of the scene's bounding box; s = `offsetScale`, DEFAULT_OFFSET_SCALE): the first
 *  term covers the BVH's float vertices (rounded by at most 6e-8 R: s = 1e-6 is sixteen
 *  times that), the second the float precision of points far from the centre. The answer
 *  is the offset point's: a shadow boundary closer than eps to the hit may fall between
 *  the two (docs/reference.md measures how the masks converge as s shrinks).
 *  grazing = 0 < N.L < 0.05, regardless of shadow or cone. Rows are split over all cores. */
Mask computeReferenceMask(const osg::Node& scene, const Camera& camera, const Light& light,
                          unsigned int castsMask = ~0u, unsigned int traversalMask = ~0u,
                          double offsetScale = DEFAULT_OFFSET_SCALE);

/** Strata per side of a light's shadow rays (MEASURE.md: 32 x 32 = 1024 rays). */
constexpr int LIGHT_STRATA = 32;

/** Strata per side of a pixel's primary rays for a light of size 0 (4 x 4). */
constexpr int PIXEL_STRATA = 4;

/** n x n jittered points of the unit square: out[i * n + j] lies uniformly at random in
 *  the stratum [i / n, (i + 1) / n] x [j / n, (j + 1) / n]. The random numbers come from a
 *  fixed-seed generator keyed by `key` alone: the same key gives the same points, on any
 *  thread. */
void stratifiedSamples(int n, uint64_t key, std::vector<osg::Vec2d>& out);

/** The exact reference visibility mask (MEASURE.md, "Soft shadows") of the triangles that
 *  a view through `camera` draws. The pixel centre's primary ray decides background
 *  (VIS_BACKGROUND), the visible point and its grazing band as computeReferenceMask does,
 *  with L the direction to the light's centre; N.L <= 0 or a point outside a spot's cone
 *  has v = 0.
 *
 *  Light with a size: v is the fraction of LIGHT_STRATA^2 shadow rays, one per stratum of
 *  stratifiedSamples() keyed by the pixel, that reach the light. A POINT or SPOT light of
 *  radius r is sampled uniformly by area on the disk of radius r around its position,
 *  perpendicular to the direction from the point (u, v) -> radius r sqrt(u), angle 2 pi v;
 *  a DIRECTIONAL light of angular radius theta uniformly by solid angle over the cone of
 *  directions within theta of its direction (u, v) -> 1 - cos(angle) = u (1 - cos theta),
 *  azimuth 2 pi v. Both maps keep areas, so each stratum holds 1/1024 of the light. A ray
 *  starts and stops as computeReferenceMask's; one toward a part of the light below the
 *  seen side's horizon (N.dir <= 0) does not reach it (the surface hides it).
 *
 *  Light of size 0: PIXEL_STRATA^2 primary rays through jittered points of the pixel's
 *  strata, each answered as computeReferenceMask answers a pixel centre; v is the lit
 *  fraction of those that hit geometry (the centre's answer when none do). */
VisibilityMask computeReferenceVisibility(const osg::Node& scene, const Camera& camera, const Light& light,
                                          unsigned int castsMask = ~0u, unsigned int traversalMask = ~0u);

/** Error of a mask against the reference (MEASURE.md). */
struct Comparison
{
    bool valid = false;             ///< false when the sizes differ or a mask is empty
    std::string error;              ///< why not valid
    long long geometryPixels = 0;   ///< both have geometry, reference outside grazing band
    long long wrongPixels = 0;      ///< among those: one says 0 and the other 255
    long long coverageMismatch = 0; ///< background in one mask and not in the other
    long long grazingExcluded = 0;  ///< both have geometry, reference in the grazing band
    double wrongPct = 0.0;          ///< 100 * wrongPixels / geometryPixels (0 if none)
    /** Mean Euclidean distance in pixels from each wrong pixel to the nearest pixel of
     *  the reference shadow boundary (pixels of value 0 or 255 4-adjacent to the other
     *  value). 0 when there are no wrong pixels, -1 when the reference has no boundary. */
    double meanWrongDistance = 0.0;
};

/** Compare `test` with `reference`. Values are classified as in maskFromImage (<64 -> 0,
 *  >192 -> 255, else background); the grazing band is the reference's. */
Comparison compareMasks(const Mask& test, const Mask& reference);

/** The score of the pixels whose reference point lies in [from, to) from the eye. */
struct BandScore
{
    double from = 0.0, to = 0.0;  ///< eye distances, scene units (to may be +inf)
    long long geometryPixels = 0; ///< as Comparison::geometryPixels, within the band
    long long wrongPixels = 0;    ///< as Comparison::wrongPixels, within the band
    double wrongPct = 0.0;        ///< 100 * wrongPixels / geometryPixels (0 if none)
};

/** compareMasks() split by the eye distance of the reference's visible point
 *  (Mask::distance): `edges` {20, 200} give the bands [0, 20), [20, 200) and [200, inf).
 *  The bands' pixels add up to compareMasks()'s. Empty when the masks differ in size or the
 *  reference has no distances. */
std::vector<BandScore> compareMasksByDistance(const Mask& test, const Mask& reference,
                                              const std::vector<double>& edges);

/** Pixels whose mask changes from one frame to the next while the reference's does not. */
struct FlickerCount
{
    bool valid = false;           ///< false when the four masks differ in size or one is empty
    long long geometryPixels = 0; ///< this frame's geometry pixels (as Comparison::geometryPixels)
    /** Among them: pixels with geometry in both frames' masks whose test value changed
     *  (0 to 255 or back) while the reference's value stayed the same. */
    long long flickerPixels = 0;
    double flickerPct = 0.0; ///< 100 * flickerPixels / geometryPixels (0 if none)
};

/** The flicker of `test` against its previous frame `previousTest`, where the exact
 *  reference went from `previousReference` to `reference` (values classified by classify();
 *  the grazing band is this frame's reference's). */
FlickerCount countFlicker(const Mask& previousTest, const Mask& test, const Mask& previousReference,
                          const Mask& reference);

/** Per pixel Euclidean distance (in pixels) to the nearest shadow-boundary pixel of
 *  `mask` (see Comparison::meanWrongDistance); row 0 = top. All +inf when there is no
 *  boundary. */
std::vector<float> boundaryDistance(const Mask& mask);

/** Classify one 8-bit value: <64 -> 0, >192 -> 255, else 128. */
uint8_t classify(uint8_t v);

/** A mask from an image whose data is bottom row first (as OSG keeps it). The first
 *  channel of GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RED, GL_RGB, GL_RGBA, GL_BGR, GL_BGRA
 *  images, GL_UNSIGNED_BYTE or GL_FLOAT (0..1) data, is classified by classify(). Any
 *  other image gives an empty mask. */
Mask maskFromImage(const osg::Image& image);

/** A GL_LUMINANCE/GL_UNSIGNED_BYTE image of the mask values, bottom row first, so that
 *  osgDB writes the PNG top row first. */
osg::ref_ptr<osg::Image> imageFromMask(const Mask& mask);

/** Write the mask as an 8-bit gray image through osgDB (PNG for a .png path). */
bool writeMask(const Mask& mask, const std::string& path);

/** Read a mask through osgDB; false (and `mask` untouched) if unreadable. */
bool readMask(const std::string& path, Mask& mask);

/** Scores of a visibility mask against the reference (MEASURE.md, "Soft shadows"), over
 *  the geometry pixels: both masks have geometry and the reference is outside the grazing
 *  band of the light's centre. */
struct VisibilityComparison
{
    bool valid = false;             ///< false when the sizes differ or a mask is empty
    std::string error;              ///< why not valid
    long long geometryPixels = 0;   ///< as Comparison::geometryPixels
    long long coverageMismatch = 0; ///< background in one mask and not in the other
    long long grazingExcluded = 0;  ///< both have geometry, reference in the grazing band
    long long penumbraPixels = 0;   ///< geometry pixels with 0.02 < v_ref < 0.98
    double visMae = 0.0;            ///< mean |v - v_ref| over geometry pixels (0 if none)
    double visMaePenumbra = 0.0;    ///< the same over penumbra pixels (0 if none)
    /** 99th percentile of |v - v_ref| over penumbra pixels, by nearest rank: the k-th
     *  smallest with k = ceil(0.99 n) (0 if none). */
    double visP99Penumbra = 0.0;
    long long hardWrongPixels = 0; ///< Comparison::wrongPixels of both masks thresholded
    double hardWrongPct = 0.0;     ///< Comparison::wrongPct of both masks thresholded
};

/** Penumbra: 0.02 < v_ref < 0.98 (MEASURE.md). */
constexpr double PENUMBRA_LOW = 0.02;
constexpr double PENUMBRA_HIGH = 0.98;

/** Score `candidate` against `reference` (note the order: reference first). */
VisibilityComparison compareVisibility(const VisibilityMask& reference, const VisibilityMask& candidate);

/** The hard mask of a visibility mask: v > 0.5 -> 255, else 0; background -> 128; the
 *  grazing band kept. Empty for an empty mask or one whose values do not fill it. */
Mask thresholdVisibility(const VisibilityMask& mask);

/** The visibility mask of a hard mask: 255 -> 1, 0 -> 0, background -> VIS_BACKGROUND
 *  (values classified by classify()); the grazing band kept. */
VisibilityMask visibilityFromMask(const Mask& mask);

/** A GL_LUMINANCE/GL_UNSIGNED_SHORT image of the mask values, bottom row first, so that
 *  osgDB writes a 16-bit grey PNG top row first. Null for an empty mask. */
osg::ref_ptr<osg::Image> imageFromVisibility(const VisibilityMask& mask);

/** A visibility mask from an image whose data is bottom row first: the first channel of
 *  the formats maskFromImage() reads, GL_UNSIGNED_SHORT data as mask values;
 *  GL_UNSIGNED_BYTE and GL_FLOAT data through maskFromImage() and visibilityFromMask().
 *  Any other image gives an empty mask. */
VisibilityMask visibilityFromImage(const osg::Image& image);

/** A visibility mask from a rendered visibility view (SilhouetteShadowTechnique's
 *  DEBUG_VISIBILITY, 8-bit RGB or RGBA, bottom row first): a grey level g gives visibility
 *  g / 255; a pixel whose red and green differ (the view's magenta clear colour) is
 *  background. Any other image gives an empty mask. */
VisibilityMask visibilityFromRender(const osg::Image& image);

/** Write the mask as a 16-bit grey image through osgDB (PNG for a .png path). */
bool writeVisibility(const VisibilityMask& mask, const std::string& path);

/** Read a visibility mask through osgDB; false (and `mask` untouched) if unreadable. */
bool readVisibility(const std::string& path, VisibilityMask& mask);

/** An RGB image (bottom row first) showing the error of `test`: red where test says
 *  shadow and the reference lit, green the reverse, blue where coverage differs, the
 *  reference's gray levels at half brightness elsewhere. Null if the sizes differ. */
osg::ref_ptr<osg::Image> diffImage(const Mask& test, const Mask& reference);

} // namespace ossref

#endif
