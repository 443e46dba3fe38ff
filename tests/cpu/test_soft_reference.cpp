// The exact visibility reference (tests/reference, MEASURE.md "Soft shadows"): penumbrae of
// scenes whose visibility can be computed on paper, a light of size 0 against the hard
// reference, the sample patterns, the scores and the 16-bit mask files.
//
// How close the sampled visibility must come to the closed form. A pixel's v counts 1024
// shadow rays, one in each stratum of a 32 x 32 grid of the unit square, mapped onto the
// light by area (solid angle for a cone) so that each stratum holds exactly 1/1024 of the
// light. A stratum that lies wholly on one side of the shadow's boundary (on the light)
// contributes exactly its share; only the K strata that the boundary cuts contribute an
// error, each an independent draw X_k - p_k within a range of 1. By Hoeffding's
// inequality P(|v - v_exact| >= t) <= 2 exp(-2 (1024 t)^2 / K), and the mean error is at
// most sqrt(K / 4) / 1024. The map sends the grid's lines to 31 inner circles (or, on the
// sphere, small circles around the axis) and 32 spokes (half great circles from the axis):
// a straight boundary (a chord, or a great circle) crosses each circle at most twice and
// each spoke at most once, so it cuts at most K = 1 + 62 + 32 = 95 strata. Then t = 0.03
// has a probability below 5e-9 per pixel, and the mean error is at most 0.0048.
#include "reference/Reference.h"
#include "test_reference_scenes.h"

#include <gtest/gtest.h>

#include <osgDB/ReadFile>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

namespace {

using ossref::Camera;
using ossref::Light;
using ossref::Mask;
using ossref::VisibilityMask;
using namespace reftest;

/** Bound on one pixel's error for a straight boundary (see the top of the file). */
const double kEdgeMaxError = 0.03;
/** Bound on the mean error for a straight boundary, sqrt(95 / 4) / 1024, rounded up. */
const double kEdgeMeanError = 0.0048;

/** Height of the half-plane occluder {x < 0, z = kEdgeHeight} of the edge scenes. */
const double kEdgeHeight = 2.0;

/** Ground [-10, 10]^2 at z = 0 and the half-plane occluder x < 0 at z = 2 (a quad large
 *  enough that every shadow ray of the tests crosses z = 2 inside it where x < 0). */
osg::ref_ptr<osg::Group> edgeScene()
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    root->addChild(geode(quad(-60, 0, -60, 60, kEdgeHeight).get()));
    return root;
}

/** Looking straight down at the strip x in [-1.2, 5.2], y in [-0.8, 0.8] of the ground: 64
 *  x 16 pixels of about 0.1 x 0.1. */
Camera stripCamera()
{
    Camera c;
    c.eye = osg::Vec3d(2.0, 0.0, 1000.0);
    c.center = osg::Vec3d(2.0, 0.0, 0.0);
    c.up = osg::Vec3d(0.0, 1.0, 0.0);
    c.fovyDeg = osg::RadiansToDegrees(2.0 * std::atan(0.0008));
    c.width = 64;
    c.height = 16;
    return c;
}

/** The ground point (z = 0) that the centre of GL pixel (x, y) sees. */
osg::Vec3d groundPoint(const Camera& camera, int x, int y)
{
    osg::Vec3d origin, direction;
    ossref::primaryRay(camera, x + 0.5, y + 0.5, origin, direction);
    return origin - direction * (origin.z() / direction.z());
}

/** The plane through ground point p and the occluder's edge {x = 0, z = 2}: its unit
 *  normal, and the sign sigma that makes sigma n.(q - e) > 0 on the occluder's side
 *  (a point (-a, y, 2) of the occluder gives n.(q - e) = -a n.x). */
void edgePlane(const osg::Vec3d& p, osg::Vec3d& normal, osg::Vec3d& onEdge, double& sigma)
{
    onEdge = osg::Vec3d(0.0, p.y(), kEdgeHeight);
    normal = osg::Vec3d(0.0, 1.0, 0.0) ^ (onEdge - p);
    normal.normalize();
    sigma = normal.x() < 0.0 ? 1.0 : -1.0;
}

/** Disk light over the edge. A ray from p to a point q of the light (above z = 2) crosses
 *  z = 2 on the same side of the plane P through p and the edge as q, and P meets z = 2 in
 *  the edge itself: the ray is blocked exactly when q lies on the occluder's side of P. P
 *  cuts the light's disk (centre c, radius r, normal m = (c - p) / |c - p|) along a chord
 *  at distance |n.(c - e)| / sqrt(1 - (n.m)^2) from c (distance to the plane over the sine
 *  of the angle between the planes). With t that distance in radii, signed positive when c
 *  lies on the occluder's side, the part of the disk beyond the chord (the visible part)
 *  is the circular segment (acos t - t sqrt(1 - t^2)) / pi, which is also right for t < 0
 *  (it equals 1 minus the segment of -t). */
double diskOverEdge(const osg::Vec3d& p, const osg::Vec3d& c, double r)
{
    osg::Vec3d n, e;
    double sigma = 0.0;
    edgePlane(p, n, e, sigma);
    osg::Vec3d m = c - p;
    m.normalize();
    const double cosPlanes = n * m;
    const double t = sigma * (n * (c - e)) / (r * std::sqrt(1.0 - cosPlanes * cosPlanes));
    const double tc = std::max(-1.0, std::min(1.0, t));
    return (std::acos(tc) - tc * std::sqrt(1.0 - tc * tc)) / osg::PI;
}

/** Share by solid angle of a cap of angular radius theta beyond a great circle at angular
 *  distance beta >= 0 from the cap's axis. Gauss-Bonnet on the region R (bounded by an arc
 *  of the cap's rim and an arc of the great circle): area = 2 pi - (integral of geodesic
 *  curvature along the rim arc) - (exterior angles at the two corners). The rim is a small
 *  circle of geodesic curvature cot theta; with the great circle's normal at angle pi/2 +
 *  beta from the axis, a rim point at azimuth phi is in R when cos phi >= tan beta / tan
 *  theta, an arc of 2 psi, psi = acos(tan beta / tan theta), length 2 psi sin theta: the
 *  curvature integral is 2 psi cos theta. The corners' interior angle alpha is the angle
 *  between the circles, acos(sin beta / sin theta) (their tangent-plane normals have a dot
 *  product of -sin beta / sin theta). Area = 2 alpha - 2 psi cos theta, out of the cap's
 *  2 pi (1 - cos theta). (beta = 0 gives one half, beta = theta none.) */
double capBeyondGreatCircle(double beta, double theta)
{
    if (beta >= theta) return 0.0;
    const double alpha = std::acos(std::sin(beta) / std::sin(theta));
    const double psi = std::acos(std::tan(beta) / std::tan(theta));
    return (2.0 * alpha - 2.0 * psi * std::cos(theta)) / (2.0 * osg::PI * (1.0 - std::cos(theta)));
}

/** Cone light over the edge: a direction w from p is blocked when it points to the
 *  occluder's side of P (as for the disk); with the cone's axis d at angular distance beta
 *  = asin(sigma n.d) from P (positive on the occluder's side), the visible share is the
 *  part of the cap beyond P, or for beta < 0 all but the part of the cap beyond P. */
double coneOverEdge(const osg::Vec3d& p, const osg::Vec3d& axis, double theta)
{
    osg::Vec3d n, e;
    double sigma = 0.0;
    edgePlane(p, n, e, sigma);
    const double beta = std::asin(sigma * (n * axis));
    return beta >= 0.0 ? capBeyondGreatCircle(beta, theta) : 1.0 - capBeyondGreatCircle(-beta, theta);
}

Light sizedLight(Light light, double size)
{
    light.size = size;
    return light;
}

/** Worst and mean |v - expected(p)| over the ground pixels x > 0.1 of the edge scene seen
 *  by stripCamera() whose expected visibility is in the penumbra (0.02 < expected < 0.98),
 *  and how many they are. */
struct ProfileError
{
    VisibilityMask mask;
    double max = 0.0;
    double mean = 0.0;
    int penumbra = 0;
    int oddCounts = 0; ///< pixels whose count of rays that reach the light is odd
};

template <class Expected>
ProfileError edgeProfileError(const Light& light, Expected&& expected)
{
    const Camera camera = stripCamera();
    ProfileError r;
    r.mask = ossref::Tracer(*edgeScene()).renderVisibility(camera, light);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x)
        {
            const osg::Vec3d p = groundPoint(camera, x, y);
            const double exact = expected(p);
            if (p.x() < 0.1 || !(exact > ossref::PENUMBRA_LOW && exact < ossref::PENUMBRA_HIGH)) continue;
            const double v = r.mask.visibilityGL(x, y);
            const double error = std::fabs(v - exact);
            r.max = std::max(r.max, error);
            r.mean += error;
            ++r.penumbra;
            // v is a count of 1024 rays, stored to 1 / 65534.
            const double count = v * 1024.0;
            EXPECT_NEAR(count, std::round(count), 0.02) << "pixel " << x << ", " << y;
            r.oddCounts += int(std::lround(count)) % 2;
        }
    if (r.penumbra > 0) r.mean /= r.penumbra;
    EXPECT_LT(r.max, kEdgeMaxError);
    EXPECT_LT(r.mean, kEdgeMeanError);
    EXPECT_GT(r.oddCounts, 0) << "fewer than 1024 rays per pixel";
    std::cout << r.penumbra << " penumbra pixels, error max " << r.max << " mean " << r.mean << std::endl;
    return r;
}

// ---------------------------------------------------------------------------------------
// Closed forms

TEST(SoftReferenceSphere, HalfPlaneEdgeFollowsTheDiskSegment)
{
    const osg::Vec3d centre(-4.0, 0.0, 6.0);
    const double radius = 1.5;
    const ProfileError e = edgeProfileError(sizedLight(pointLight(centre), radius),
                                            [&](const osg::Vec3d& p) { return diskOverEdge(p, centre, radius); });
    // The penumbra spans about x in [1.2, 2.8]: 16 columns of 16 rows.
    EXPECT_GT(e.penumbra, 200);
    // Umbra and full light on either side.
    EXPECT_EQ(e.mask.atGL(15, 8), ossref::VIS_NONE); // x = 0.35
    EXPECT_EQ(e.mask.atGL(60, 8), ossref::VIS_FULL); // x = 4.85
    EXPECT_EQ(e.mask.atGL(5, 8), ossref::VIS_FULL);  // the occluder's top, x = -0.65
}

TEST(SoftReferenceDirectional, ConeOverAnEdgeFollowsTheCapShare)
{
    osg::Vec3d axis(-1.0, 0.0, 1.0);
    axis.normalize();
    const double theta = osg::DegreesToRadians(10.0);
    const ProfileError e = edgeProfileError(sizedLight(directional(axis), 10.0),
                                            [&](const osg::Vec3d& p) { return coneOverEdge(p, axis, theta); });
    // The edge's shadow falls at x = 2 with a penumbra about 2 h theta / cos^2(45) = 1.4 wide.
    EXPECT_GT(e.penumbra, 150);
}

TEST(SoftReferenceDirectional, ConeBelowTheHorizonIsHiddenByTheSurface)
{
    // An open ground that casts nothing under a cone of 10 degrees whose axis rises 5
    // degrees above it: the rays toward the part of the cone below the horizon do not
    // reach the light. The horizon is a great circle 5 degrees from the axis, so v is one
    // minus the cap's share beyond it.
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get(), 0x1));
    const double beta = osg::DegreesToRadians(5.0);
    const Light light = sizedLight(directional(osg::Vec3d(std::cos(beta), 0.0, std::sin(beta))), 10.0);
    const ossref::Tracer tracer(ossref::collectTriangles(*root, 0x2u));
    Camera camera = stripCamera();
    camera.width = camera.height = 4;
    const VisibilityMask mask = tracer.renderVisibility(camera, light);
    const double expected = 1.0 - capBeyondGreatCircle(beta, osg::DegreesToRadians(10.0));
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(mask.visibilityGL(i % 4, i / 4), expected, kEdgeMaxError) << "pixel " << i;
    // Seen from below, the ground's seen side faces away from the light's centre.
    camera.eye.z() = -1000.0;
    const VisibilityMask below = tracer.renderVisibility(camera, light);
    EXPECT_EQ(std::count(below.value.begin(), below.value.end(), uint16_t(ossref::VIS_NONE)), 16);
}

TEST(SoftReferenceSphere, SmallSquareBlockerCentre)
{
    // A sphere light of radius r = 3 at height H = 6 over the ground point p = 0, a square
    // blocker [-a, a]^2 (a = 0.5) at height h = 2 between them. The disk is horizontal; a
    // ray to its point (x, y) crosses z = h at (x, y) h / H, inside the square when |x|,
    // |y| <= b = a H / h = 1.5. The square [-b, b]^2 lies in the disk (b sqrt 2 < 3): v = 1 -
    // (2b)^2 / (pi r^2) = 1 - 1 / pi. The square's four sides cut at most 224 strata (each
    // side crosses the 23 circles of radius above b twice, and 9 spokes): by Hoeffding's
    // inequality an error of 0.04 has a probability below 1e-6.
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    root->addChild(geode(quad(-0.5, 0.5, -0.5, 0.5, 2.0).get()));
    Camera camera; // one pixel whose centre sees p = 0 from beside the blocker
    camera.eye = osg::Vec3d(20.0, 0.0, 1.0);
    camera.center = osg::Vec3d(0.0, 0.0, 0.0);
    camera.up = osg::Vec3d(0.0, 0.0, 1.0);
    camera.fovyDeg = 1.0;
    camera.width = camera.height = 1;
    const ossref::Tracer tracer(*root);
    const VisibilityMask mask = tracer.renderVisibility(camera, sizedLight(pointLight(osg::Vec3d(0, 0, 6)), 3.0));
    EXPECT_NEAR(mask.visibilityGL(0, 0), 1.0 - 1.0 / osg::PI, 0.04);
}

// ---------------------------------------------------------------------------------------
// Size 0: anti-aliased hard shadows

struct CoverageCase
{
    const char* name;
    Light light;
};

class SizeZero : public testing::TestWithParam<CoverageCase>
{
};

TEST_P(SizeZero, AgreesWithTheHardReference)
{
    const osg::ref_ptr<osg::Group> scene = groundScene(Occluder::Quad);
    const ossref::Tracer tracer(*scene);
    const Mask hard = tracer.render(topCamera(), GetParam().light);
    const VisibilityMask soft = tracer.renderVisibility(topCamera(), GetParam().light);
    ASSERT_EQ(soft.value.size(), hard.value.size());
    long long partial = 0;
    const std::vector<float> distance = ossref::boundaryDistance(hard);
    for (size_t i = 0; i < hard.value.size(); ++i)
    {
        const uint16_t v = soft.value[i];
        ASSERT_EQ(v == ossref::VIS_BACKGROUND, hard.value[i] == ossref::MASK_BACKGROUND) << i;
        ASSERT_EQ(soft.grazing[i], hard.grazing[i]) << i;
        if (v == ossref::VIS_NONE)
        {
            EXPECT_EQ(hard.value[i], ossref::MASK_NO_LIGHT) << i;
        }
        if (v == ossref::VIS_FULL)
        {
            EXPECT_EQ(hard.value[i], ossref::MASK_LIT) << i;
        }
        if (v == ossref::VIS_NONE || v == ossref::VIS_FULL || v == ossref::VIS_BACKGROUND) continue;
        ++partial; // a pixel that the shadow's edge crosses lies next to the hard boundary
        EXPECT_LE(distance[i], 1.5f) << i;
    }
    // The occluder's shadow has a perimeter of 80 pixels (2 x 2 units under the directional
    // light, 0.1 a pixel) or 160 (4 x 4 under the point light), its edges between pixel
    // centres.
    EXPECT_GT(partial, 60);
    EXPECT_LT(partial, 300);
    // Thresholded at 0.5, the two disagree only where the edge crosses the pixel.
    const Mask thresholded = ossref::thresholdVisibility(soft);
    long long disagree = 0;
    for (size_t i = 0; i < hard.value.size(); ++i)
    {
        if (thresholded.value[i] == hard.value[i]) continue;
        ++disagree;
        EXPECT_NE(soft.value[i], ossref::VIS_NONE);
        EXPECT_NE(soft.value[i], ossref::VIS_FULL);
    }
    EXPECT_LT(disagree, partial / 4);
    std::cout << GetParam().name << ": " << partial << " partial pixels, " << disagree
              << " of them on the other side of 0.5 from the hard mask" << std::endl;
}

INSTANTIATE_TEST_SUITE_P(SoftReferenceCoverage, SizeZero,
                         testing::Values(CoverageCase{"directional", directional(osg::Vec3d(1.13, 0.37, 2.0))},
                                         CoverageCase{"point", pointLight(osg::Vec3d(3.07, 2.13, 8.0))}),
                         [](const testing::TestParamInfo<CoverageCase>& info) { return info.param.name; });

// ---------------------------------------------------------------------------------------
// Sampling

TEST(SoftReferenceSampling, StrataAreJitteredAndKeyed)
{
    const int n = ossref::LIGHT_STRATA;
    EXPECT_EQ(n, 32); // MEASURE.md: 32 x 32 shadow rays
    EXPECT_EQ(ossref::PIXEL_STRATA, 4);
    std::vector<osg::Vec2d> a, b, c;
    ossref::stratifiedSamples(n, 7, a);
    ossref::stratifiedSamples(n, 7, b);
    ossref::stratifiedSamples(n, 8, c);
    ASSERT_EQ(a.size(), size_t(n * n));
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    // Offsets within the strata are uniform on [0, 1]: mean 1/2, variance 1/12 (the
    // estimates over 2048 offsets have standard deviations 0.0064 and 0.0019).
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
            const osg::Vec2d s = a[size_t(i) * n + j];
            const double du = s.x() * n - i, dv = s.y() * n - j;
            ASSERT_GE(du, 0.0);
            ASSERT_LE(du, 1.0);
            ASSERT_GE(dv, 0.0);
            ASSERT_LE(dv, 1.0);
            sum += du + dv;
            sum2 += du * du + dv * dv;
        }
    const double mean = sum / (2.0 * n * n);
    EXPECT_NEAR(mean, 0.5, 0.03);
    EXPECT_NEAR(sum2 / (2.0 * n * n) - mean * mean, 1.0 / 12.0, 0.01);
}

TEST(SoftReferenceSampling, RendersAreDeterministic)
{
    const ossref::Tracer tracer(*edgeScene());
    const Light light = sizedLight(pointLight(osg::Vec3d(-4.0, 0.0, 6.0)), 1.5);
    const VisibilityMask one = tracer.renderVisibility(stripCamera(), light, 1);
    const VisibilityMask two = tracer.renderVisibility(stripCamera(), light, 2);
    EXPECT_EQ(one.value, two.value);
    EXPECT_EQ(one.grazing, two.grazing);
    const std::string pathOne = testing::TempDir() + "soft_one.png";
    const std::string pathTwo = testing::TempDir() + "soft_two.png";
    ASSERT_TRUE(ossref::writeVisibility(one, pathOne));
    ASSERT_TRUE(ossref::writeVisibility(tracer.renderVisibility(stripCamera(), light, 2), pathTwo));
    std::ifstream fileOne(pathOne, std::ios::binary), fileTwo(pathTwo, std::ios::binary);
    const std::vector<char> bytesOne((std::istreambuf_iterator<char>(fileOne)), std::istreambuf_iterator<char>());
    const std::vector<char> bytesTwo((std::istreambuf_iterator<char>(fileTwo)), std::istreambuf_iterator<char>());
    EXPECT_FALSE(bytesOne.empty());
    EXPECT_EQ(bytesOne, bytesTwo);
}

// ---------------------------------------------------------------------------------------
// Scores

/** A mask from rows of visibilities, top row first; -1 is background. */
VisibilityMask visibilityRows(const std::vector<std::vector<double>>& rows)
{
    VisibilityMask m = VisibilityMask::filled(int(rows[0].size()), int(rows.size()));
    for (size_t r = 0; r < rows.size(); ++r)
        for (size_t x = 0; x < rows[r].size(); ++x)
            m.value[r * m.width + x] =
                rows[r][x] < 0.0 ? uint16_t(ossref::VIS_BACKGROUND) : ossref::encodeVisibility(rows[r][x]);
    return m;
}

TEST(SoftReferenceScores, HandMadeMasks)
{
    // Reference and candidate, top row first (-1: background); the reference's pixel (3, 1)
    // lies in the grazing band.
    VisibilityMask reference = visibilityRows({{1.0, 0.5, 0.01, -1}, {0.0, 0.3, 0.9, 0.5}});
    reference.grazing[7] = 1;
    const VisibilityMask candidate = visibilityRows({{1.0, 0.2, 0.6, -1}, {-1, 0.3, 0.4, 0.0}});
    const ossref::VisibilityComparison c = ossref::compareVisibility(reference, candidate);
    ASSERT_TRUE(c.valid) << c.error;
    // Geometry pixels: (0,0) 0, (1,0) 0.3, (2,0) 0.59, (1,1) 0, (2,1) 0.5; (0,1) is a
    // coverage mismatch, (3,1) grazing.
    EXPECT_EQ(c.geometryPixels, 5);
    EXPECT_EQ(c.coverageMismatch, 1);
    EXPECT_EQ(c.grazingExcluded, 1);
    EXPECT_NEAR(c.visMae, 1.39 / 5.0, 1e-4);
    // Penumbra (0.02 < v_ref < 0.98): (1,0), (1,1), (2,1); not 0.01, nor 1 or 0.
    EXPECT_EQ(c.penumbraPixels, 3);
    EXPECT_NEAR(c.visMaePenumbra, 0.8 / 3.0, 1e-4);
    EXPECT_NEAR(c.visP99Penumbra, 0.5, 1e-4); // ceil(0.99 * 3) = 3rd of 3
    // Thresholded (lit when v > 0.5): reference lit at (0,0), (2,1); candidate at (0,0),
    // (2,0): wrong at (2,0) and (2,1).
    EXPECT_EQ(c.hardWrongPixels, 2);
    EXPECT_NEAR(c.hardWrongPct, 40.0, 1e-9);
}

TEST(SoftReferenceScores, NinetyNinthPercentileByNearestRank)
{
    // 200 penumbra pixels with errors 0.001, 0.002, ..., 0.2: the 198th smallest is 0.198.
    std::vector<double> ref(200, 0.5), test(200);
    for (int i = 0; i < 200; ++i) test[size_t(i)] = 0.5 + 0.001 * (i + 1) * (i % 2 ? 1.0 : -1.0);
    const ossref::VisibilityComparison c = ossref::compareVisibility(visibilityRows({ref}), visibilityRows({test}));
    EXPECT_EQ(c.penumbraPixels, 200);
    EXPECT_NEAR(c.visP99Penumbra, 0.198, 1e-4);
    EXPECT_NEAR(c.visMaePenumbra, 0.1005, 1e-4);
    EXPECT_NEAR(c.visMae, 0.1005, 1e-4);
    EXPECT_EQ(c.hardWrongPixels, 100); // the reference's 0.5 is not lit; the odd ones above it are
    const ossref::VisibilityComparison same = ossref::compareVisibility(visibilityRows({ref}), visibilityRows({ref}));
    EXPECT_EQ(same.visMae, 0.0);
    EXPECT_EQ(same.visP99Penumbra, 0.0);
}

TEST(SoftReferenceScores, PenumbraIsStrictlyBetweenTwoAndNinetyEightPercent)
{
    const ossref::VisibilityComparison c = ossref::compareVisibility(
        visibilityRows({{0.019, 0.021, 0.5, 0.979, 0.981}}), visibilityRows({{0.5, 0.5, 0.5, 0.5, 0.5}}));
    EXPECT_EQ(c.geometryPixels, 5);
    EXPECT_EQ(c.penumbraPixels, 3);
    EXPECT_NEAR(c.visMaePenumbra, (0.479 + 0.0 + 0.479) / 3.0, 1e-4);
    EXPECT_NEAR(c.visP99Penumbra, 0.479, 1e-4);
    EXPECT_NEAR(c.visMae, (0.481 + 0.479 + 0.0 + 0.479 + 0.481) / 5.0, 1e-4);
}

TEST(SoftReferenceScores, MismatchedSizesAreReportedNotFatal)
{
    const ossref::VisibilityComparison c =
        ossref::compareVisibility(VisibilityMask::filled(4, 4), VisibilityMask::filled(4, 5));
    EXPECT_FALSE(c.valid);
    EXPECT_NE(c.error.find("size mismatch"), std::string::npos);
    EXPECT_FALSE(ossref::compareVisibility(VisibilityMask(), VisibilityMask::filled(1, 1)).valid);
}

TEST(SoftReferenceScores, EncodingAndHardMasks)
{
    EXPECT_EQ(ossref::encodeVisibility(0.0), 0);
    EXPECT_EQ(ossref::encodeVisibility(1.0), 65534);
    EXPECT_EQ(ossref::encodeVisibility(0.5), 32767);
    EXPECT_EQ(ossref::encodeVisibility(1.0 / 1024.0), 64); // 63.998 rounded
    EXPECT_EQ(ossref::encodeVisibility(2.0), 65534);
    EXPECT_EQ(ossref::encodeVisibility(-1.0), 0);
    EXPECT_EQ(ossref::encodeVisibility(std::nan("")), 0);
    Mask hard = Mask::filled(3, 1);
    hard.value = {0, 128, 255};
    hard.grazing = {0, 0, 1};
    const VisibilityMask soft = ossref::visibilityFromMask(hard);
    EXPECT_EQ(soft.value, (std::vector<uint16_t>{0, ossref::VIS_BACKGROUND, ossref::VIS_FULL}));
    EXPECT_EQ(soft.grazing, hard.grazing);
    const Mask back = ossref::thresholdVisibility(soft);
    EXPECT_EQ(back.value, hard.value);
    EXPECT_EQ(back.grazing, hard.grazing);
}

// ---------------------------------------------------------------------------------------
// Files

TEST(SoftReferenceImages, SixteenBitPngRoundTrip)
{
    // Values whose two bytes differ (258 = 0x0102) show a byte-order slip; rows differ so a
    // flipped image shows too.
    VisibilityMask mask = VisibilityMask::filled(4, 2);
    mask.value = {0, 1, 258, 32767, 65533, 65534, 65535, 40000};
    const std::string path = testing::TempDir() + "visibility_round_trip.png";
    ASSERT_TRUE(ossref::writeVisibility(mask, path));
    VisibilityMask read;
    ASSERT_TRUE(ossref::readVisibility(path, read));
    EXPECT_EQ(read.width, 4);
    EXPECT_EQ(read.height, 2);
    EXPECT_EQ(read.value, mask.value);
    // The file is a 16-bit grey PNG (IHDR: bit depth at byte 24, colour type 0 at 25) whose
    // first row is the mask's top row, as osgDB reads it (bottom row first).
    std::ifstream file(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 26u);
    EXPECT_EQ(bytes[24], 16);
    EXPECT_EQ(bytes[25], 0);
    const osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(path);
    ASSERT_TRUE(image.valid());
    EXPECT_EQ(image->getDataType(), GLenum(GL_UNSIGNED_SHORT));
    EXPECT_EQ(*reinterpret_cast<const uint16_t*>(image->data(0, 1)), 0);
    EXPECT_EQ(*reinterpret_cast<const uint16_t*>(image->data(2, 1)), 258);
    EXPECT_EQ(*reinterpret_cast<const uint16_t*>(image->data(0, 0)), 65533);
}

TEST(SoftReferenceImages, EightBitMasksReadAsHardVisibility)
{
    Mask hard = Mask::filled(3, 1);
    hard.value = {0, 128, 255};
    const std::string path = testing::TempDir() + "hard_as_visibility.png";
    ASSERT_TRUE(ossref::writeMask(hard, path));
    VisibilityMask read;
    ASSERT_TRUE(ossref::readVisibility(path, read));
    EXPECT_EQ(read.value, (std::vector<uint16_t>{0, ossref::VIS_BACKGROUND, ossref::VIS_FULL}));
    EXPECT_FALSE(ossref::readVisibility(testing::TempDir() + "no_such_file.png", read));
    EXPECT_EQ(read.width, 3); // untouched
}

// ---------------------------------------------------------------------------------------
// Cost: printed and recorded for docs/reference.md; no bound on time, only on what was computed.

/** Milliseconds of one visibility render of the bumpy terrain (100352 triangles) seen by
 *  terrainCamera() at width x height, under a directional light toward (1, 0.3, 0.4). */
double terrainVisibilityMs(int width, int height, double lightSizeDeg, VisibilityMask& mask)
{
    const ossref::Tracer tracer(*bumpyTerrain());
    Camera camera = terrainCamera();
    camera.width = width;
    camera.height = height;
    const auto start = std::chrono::steady_clock::now();
    mask = tracer.renderVisibility(camera, sizedLight(directional({1, 0.3, 0.4}), lightSizeDeg));
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

TEST(SoftReferenceSpeed, HundredThousandTriangles)
{
    VisibilityMask soft, hard;
    const double softMs = terrainVisibilityMs(256, 192, 2.0, soft);
    const double hardMs = terrainVisibilityMs(1024, 768, 0.0, hard);
    std::cout << "renderVisibility, 100352 triangles: 256x192 light 2 degrees " << softMs
              << " ms; 1024x768 size 0 (4 x 4 sub-pixel rays) " << hardMs << " ms" << std::endl;
    RecordProperty("soft_256x192_ms", std::to_string(softMs));
    RecordProperty("size0_1024x768_ms", std::to_string(hardMs));
    const ossref::VisibilityComparison self = ossref::compareVisibility(soft, soft);
    EXPECT_GT(self.penumbraPixels, 1000);
    EXPECT_GT(std::count(hard.value.begin(), hard.value.end(), uint16_t(0)), 10000);
    EXPECT_GT(std::count(hard.value.begin(), hard.value.end(), ossref::VIS_FULL), 10000);
}

} // namespace
