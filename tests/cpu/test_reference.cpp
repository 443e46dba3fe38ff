// The exact reference (tests/reference): hand-derived masks on scenes whose shadows can be
// computed on paper, the mask comparison of MEASURE.md, and the mask image conventions.
//
// Most scenes are seen by one camera: eye (0, 0, 1000) looking straight down, up +y,
// 300 x 300 pixels, tan(fovy/2) = 0.015. At z = 0 the image spans [-15, 15]^2, one pixel
// is 0.1 x 0.1, pixel (i, j) (GL window coordinates) sees the ground point
// (-15 + 0.1 (i + 0.5), -15 + 0.1 (j + 0.5)). The ground quad [-10, 10]^2 covers
// 200 x 200 = 40000 pixels; the other 90000 - 40000 = 50000 are background. A point at
// height z projects 1000 / (1000 - z) times farther from the centre than at z = 0.
#include "reference/Reference.h"
#include "test_reference_scenes.h"

#include <gtest/gtest.h>

#include <osg/AlphaFunc>
#include <osg/Billboard>
#include <osg/CullFace>
#include <osg/FrontFace>
#include <osg/Geode>
#include <osg/LOD>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/Shape>
#include <osg/ShapeDrawable>
#include <osg/Switch>
#include <osg/Texture2D>
#include <osg/Viewport>
#include <osgDB/ReadFile>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <vector>

namespace {

using ossref::Camera;
using ossref::Comparison;
using ossref::Light;
using ossref::Mask;
using namespace reftest;

const long long kGround = 40000;
const long long kBackground = 50000;

/** The pixel column (or row, GL) whose centre sees world coordinate w on the ground. */
int pixelOf(double w) { return int(std::floor((w + 15.0) / 0.1)); }

/** Mask value at the pixel that sees ground point (x, y). */
uint8_t ground(const Mask& m, double x, double y) { return m.atGL(pixelOf(x), pixelOf(y)); }

/** Pixel centres (one axis) whose ground coordinate lies strictly inside (lo, hi). */
long long centresInside(double lo, double hi)
{
    long long n = 0;
    for (int i = 0; i < kSize; ++i)
    {
        const double c = -15.0 + 0.1 * (i + 0.5);
        n += (c > lo && c < hi) ? 1 : 0;
    }
    return n;
}

long long grazingCount(const Mask& m)
{
    long long n = 0;
    for (uint8_t g : m.grazing) n += g;
    return n;
}

Mask maskFromRows(int width, const std::vector<std::vector<int>>& rows)
{
    Mask m = Mask::filled(width, int(rows.size()));
    for (size_t r = 0; r < rows.size(); ++r)
        for (int x = 0; x < width; ++x) m.value[r * width + x] = uint8_t(rows[r][x]);
    return m;
}

std::string tempPath(const std::string& name)
{
    return (testing::TempDir().empty() ? std::string("/tmp/") : testing::TempDir()) + name;
}

// ---------------------------------------------------------------------------------------
// Camera convention

TEST(ReferenceCamera, PrimaryRaysMatchOsgUnprojection)
{
    Camera c;
    c.eye = osg::Vec3d(3, -7, 5);
    c.center = osg::Vec3d(0.5, 1, 0);
    c.up = osg::Vec3d(0, 0, 1);
    c.fovyDeg = 40;
    c.width = 640;
    c.height = 360;
    const osg::Matrixd toWindow = osg::Matrixd::lookAt(c.eye, c.center, c.up) *
                                  osg::Matrixd::perspective(c.fovyDeg, 640.0 / 360.0, 1.0, 100.0) *
                                  osg::ref_ptr<osg::Viewport>(new osg::Viewport(0, 0, 640, 360))->computeWindowMatrix();
    const osg::Matrixd fromWindow = osg::Matrixd::inverse(toWindow);
    for (const osg::Vec2d& w : {osg::Vec2d(0.5, 0.5), osg::Vec2d(639.5, 0.5), osg::Vec2d(320, 180), osg::Vec2d(17.5, 300.5)})
    {
        osg::Vec3d expected = osg::Vec3d(w.x(), w.y(), 1.0) * fromWindow - osg::Vec3d(w.x(), w.y(), 0.0) * fromWindow;
        expected.normalize();
        osg::Vec3d origin, dir;
        ossref::primaryRay(c, w.x(), w.y(), origin, dir);
        EXPECT_NEAR((origin - c.eye).length(), 0.0, 1e-9);
        EXPECT_NEAR((dir - expected).length(), 0.0, 1e-9) << "window point " << w.x() << ", " << w.y();
    }
}

TEST(ReferenceCamera, FromOsgCamera)
{
    osg::ref_ptr<osg::Camera> cam = new osg::Camera;
    cam->setViewMatrixAsLookAt(osg::Vec3d(3, -7, 5), osg::Vec3d(0.5, 1, 0), osg::Vec3d(0, 0, 1));
    cam->setProjectionMatrixAsPerspective(40, 640.0 / 360.0, 0.5, 200.0);
    cam->setViewport(0, 0, 640, 360);
    Camera c;
    ASSERT_TRUE(ossref::cameraFromOsg(*cam, c));
    EXPECT_EQ(c.width, 640);
    EXPECT_EQ(c.height, 360);
    EXPECT_NEAR(c.fovyDeg, 40.0, 1e-9);
    const osg::Matrixd fromWindow =
        osg::Matrixd::inverse(cam->getViewMatrix() * cam->getProjectionMatrix() * cam->getViewport()->computeWindowMatrix());
    osg::Vec3d expected = osg::Vec3d(100.5, 50.5, 1.0) * fromWindow - osg::Vec3d(100.5, 50.5, 0.0) * fromWindow;
    expected.normalize();
    osg::Vec3d origin, dir;
    ossref::primaryRay(c, 100.5, 50.5, origin, dir);
    EXPECT_NEAR((dir - expected).length(), 0.0, 1e-9);

    Camera untouched;
    cam->setProjectionMatrixAsPerspective(40, 1.0, 0.5, 200.0);  // aspect differs from the viewport
    EXPECT_FALSE(ossref::cameraFromOsg(*cam, untouched));
    cam->setProjectionMatrixAsFrustum(-1, 2, -1, 1, 1, 10);  // off-axis
    EXPECT_FALSE(ossref::cameraFromOsg(*cam, untouched));
    EXPECT_EQ(untouched.width, Camera().width);
}

TEST(ReferenceCamera, TopCameraSeesPixelCentresOnTheGround)
{
    osg::Vec3d origin, dir;
    ossref::primaryRay(topCamera(), 0.5, 299.5, origin, dir);
    const osg::Vec3d hit = origin + dir * (-origin.z() / dir.z());
    EXPECT_NEAR(hit.x(), -14.95, 1e-9);  // left column
    EXPECT_NEAR(hit.y(), 14.95, 1e-9);   // top row
}

// ---------------------------------------------------------------------------------------
// Directional lights: shadows on the ground

struct DirectionalCase
{
    const char* name;
    Occluder occluder;
    osg::Vec3d towardLight;
    long long shadowPixels;  // derived in the comment of each row
    osg::Vec2d shadowCentre; // a ground point inside the shadow
};

// Occluder top [-1, 1]^2 at z = 4 seen as 20 x 20 pixels (|x| <= 0.95 * 1000/996 < 1).
const DirectionalCase kDirectionalCases[] = {
    // Light toward +x at 45 degrees: top edges x = -1, 1 land at x = -5, -3: 20 x 20 pixels.
    {"QuadTiltedX", Occluder::Quad, {1, 0, 1}, 400, {-4, 0}},
    // Toward +y: the shadow is at y in [-5, -3], i.e. in the lower part of the image.
    {"QuadTiltedY", Occluder::Quad, {0, 1, 1}, 400, {0, -4}},
    // Same quad built at z = 0 under a translate(0, 0, 4).
    {"QuadUnderTransform", Occluder::QuadUnderTransform, {1, 0, 1}, 400, {-4, 0}},
    // Box [-1,1]^2 x [3,4]: shadow x in [-5, -2] (bottom edge x = 1, z = 3 -> -2): 30 x 20.
    {"BoxTiltedX", Occluder::Box, {1, 0, 1}, 600, {-3.5, 0}},
    // Light straight up: the shadow [-1,1]^2 lies under the occluder, which perspective
    // enlarges by 1000/996: no shadow pixel is visible.
    {"QuadStraightUp", Occluder::Quad, {0, 0, 1}, 0, {0, 0}},
};

void PrintTo(const DirectionalCase& c, std::ostream* os) { *os << c.name; }

class DirectionalShadow : public testing::TestWithParam<DirectionalCase>
{
};

TEST_P(DirectionalShadow, CountsAndPixels)
{
    const DirectionalCase& c = GetParam();
    const Mask m = ossref::computeReferenceMask(*groundScene(c.occluder), topCamera(), directional(c.towardLight));
    ASSERT_EQ(m.width, kSize);
    ASSERT_EQ(m.height, kSize);
    EXPECT_EQ(m.count(0), c.shadowPixels);
    EXPECT_EQ(m.count(255), kGround - c.shadowPixels);
    EXPECT_EQ(m.count(128), kBackground);
    EXPECT_EQ(grazingCount(m), 0);
    if (c.shadowPixels > 0)
    {
        EXPECT_EQ(ground(m, c.shadowCentre.x(), c.shadowCentre.y()), 0);
    }
    EXPECT_EQ(ground(m, 0, 0), 255);      // occluder top, lit
    EXPECT_EQ(ground(m, 8, 8), 255);      // open ground
    EXPECT_EQ(ground(m, 14, 14), 128);    // beyond the ground
    EXPECT_EQ(ground(m, -12, 0), 128);
}

INSTANTIATE_TEST_SUITE_P(Reference, DirectionalShadow, testing::ValuesIn(kDirectionalCases),
                         [](const testing::TestParamInfo<DirectionalCase>& info) { return info.param.name; });

TEST(ReferenceDirectional, ShadowFootprintFollowsFromTheCamera)
{
    // QuadTiltedX again, counted from the camera model instead of by hand.
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), directional({1, 0, 1}));
    EXPECT_EQ(m.count(0), centresInside(-5, -3) * centresInside(-1, 1));
    EXPECT_EQ(ground(m, -5.05, 0), 255);
    EXPECT_EQ(ground(m, -4.95, 0), 0);
    EXPECT_EQ(ground(m, -3.05, 0), 0);
    EXPECT_EQ(ground(m, -2.95, 0), 255);
    EXPECT_EQ(ground(m, -4, 1.05), 255);
}

TEST(ReferenceDirectional, WindingDoesNotMatter)
{
    // The same scene with every triangle wound clockwise seen from above: the normal is
    // flipped toward the camera, so nothing changes.
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(10, -10, -10, 10, 0).get()));
    root->addChild(geode(quad(1, -1, -1, 1, 4).get()));
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), directional({1, 0, 1}));
    EXPECT_EQ(m.count(0), 400);
    EXPECT_EQ(m.count(255), kGround - 400);
    EXPECT_EQ(grazingCount(m), 0);
}

TEST(ReferenceDirectional, LightBelowTheGroundLightsNothing)
{
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), directional({0, 0, -1}));
    EXPECT_EQ(m.count(0), kGround);
    EXPECT_EQ(m.count(255), 0);
    EXPECT_EQ(m.count(128), kBackground);
}

struct MaskCase
{
    const char* name;
    unsigned int occluderMask;
    unsigned int castsMask;
    unsigned int traversalMask;
    long long shadowPixels;
    uint8_t occluderPixel;  // what the pixel at the ground centre shows
};

// The occluder of QuadTiltedX under different node masks.
const MaskCase kMaskCases[] = {
    {"AllMasks", 0x1u, ~0u, ~0u, 400, 255},
    {"OccluderDoesNotCast", 0x1u, 0x2u, ~0u, 0, 255},      // visible, casts nothing
    {"OccluderInvisible", 0x1u, ~0u, ~0x1u, 0, 255},       // the ground under it is seen, lit
    {"OccluderCastsByItsBit", 0x3u, 0x2u, ~0u, 400, 255},
    // 0x3 passes the traversal mask 0x1 and the casts mask 0x2, but not both at once:
    // osgShadow's casts pass traverses with (traversal & casts) = 0.
    {"CastsAndTraversalCombined", 0x3u, 0x2u, 0x1u, 0, 255},
};

void PrintTo(const MaskCase& c, std::ostream* os) { *os << c.name; }

class NodeMasks : public testing::TestWithParam<MaskCase>
{
};

TEST_P(NodeMasks, DecideWhatIsSeenAndWhatCasts)
{
    const MaskCase& c = GetParam();
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad, c.occluderMask), topCamera(),
                                                directional({1, 0, 1}), c.castsMask, c.traversalMask);
    EXPECT_EQ(m.count(0), c.shadowPixels);
    EXPECT_EQ(m.count(255), kGround - c.shadowPixels);
    EXPECT_EQ(ground(m, 0, 0), c.occluderPixel);
}

INSTANTIATE_TEST_SUITE_P(Reference, NodeMasks, testing::ValuesIn(kMaskCases),
                         [](const testing::TestParamInfo<MaskCase>& info) { return info.param.name; });

TEST(ReferenceDirectional, CamerasAndSwitches)
{
    // Under a root camera: the scene. A nested (HUD) camera and an inactive switch child
    // contribute nothing.
    osg::ref_ptr<osg::Camera> root = new osg::Camera;
    root->setViewMatrix(osg::Matrixd::translate(100, 0, 0));
    root->addChild(groundScene(Occluder::Quad).get());
    osg::ref_ptr<osg::Camera> hud = new osg::Camera;
    hud->addChild(geode(quad(-50, 50, -50, 50, 10).get()));
    root->addChild(hud.get());
    osg::ref_ptr<osg::Switch> sw = new osg::Switch;
    sw->addChild(geode(quad(-50, 50, -50, 50, 20).get()), false);
    root->addChild(sw.get());
    EXPECT_EQ(ossref::collectTriangles(*root).size(), 4u);
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), directional({1, 0, 1}));
    EXPECT_EQ(m.count(0), 400);
    EXPECT_EQ(m.count(128), kBackground);
}

/** Heights of the collected triangles' vertices, to tell which LOD child was collected. */
std::vector<double> heights(const ossref::TriangleSoup& soup)
{
    std::vector<double> z;
    for (const osg::Vec3d& v : soup.vertices) z.push_back(v.z());
    return z;
}

/** An LOD whose children are quads [-5, 5]^2 at heights 1 (range [0, split)) and 2
 *  ([split, 1e9)). */
osg::ref_ptr<osg::LOD> twoLevels(osg::LOD::RangeMode mode, float split)
{
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->setRangeMode(mode);
    lod->addChild(geode(quad(-5, 5, -5, 5, 1).get()), 0.0f, split);
    lod->addChild(geode(quad(-5, 5, -5, 5, 2).get()), split, 1e9f);
    return lod;
}

TEST(ReferenceViewpoint, LodByDistanceFromTheEye)
{
    // The eye is ~999 units from the LOD's centre: a cull traversal draws the far child;
    // without a camera the collector takes the child in range at distance 0.
    const osg::ref_ptr<osg::LOD> lod = twoLevels(osg::LOD::DISTANCE_FROM_EYE_POINT, 500.0f);
    const Camera far = topCamera();
    EXPECT_EQ(heights(ossref::collectTriangles(*lod, &far)), std::vector<double>(6, 2.0));
    EXPECT_EQ(heights(ossref::collectTriangles(*lod)), std::vector<double>(6, 1.0));
    Camera near = far;
    near.eye.z() = 400.0;
    EXPECT_EQ(heights(ossref::collectTriangles(*lod, &near)), std::vector<double>(6, 1.0));
}

TEST(ReferenceViewpoint, LodByPixelSizeOnScreen)
{
    // The LOD's bounding sphere (radius ~7.1) seen from 1000 units spans ~140 pixels of the
    // 300-pixel viewport (10 pixels a unit), from 3000 units ~47: OSG's pixel size is the
    // sphere's diameter on screen.
    const osg::ref_ptr<osg::LOD> lod = twoLevels(osg::LOD::PIXEL_SIZE_ON_SCREEN, 100.0f);
    Camera c = topCamera();
    EXPECT_EQ(heights(ossref::collectTriangles(*lod, &c)), std::vector<double>(6, 2.0));
    c.eye.z() = 3000.0;
    EXPECT_EQ(heights(ossref::collectTriangles(*lod, &c)), std::vector<double>(6, 1.0));
}

TEST(ReferenceViewpoint, BillboardsTurnTowardTheEye)
{
    // A square in the x-z plane (a billboard's front faces -y) turned toward the eye above
    // lies flat: all its corners at one height. Stored, it stands upright.
    osg::ref_ptr<osg::Geometry> upright = quad(-1, 1, -1, 1, 0);
    osg::Vec3Array& corners = static_cast<osg::Vec3Array&>(*upright->getVertexArray());
    for (osg::Vec3& corner : corners) corner.set(corner.x(), 0.0f, corner.y()); // (x, y, 0) -> (x, 0, y)
    osg::ref_ptr<osg::Billboard> billboard = new osg::Billboard;
    billboard->setMode(osg::Billboard::POINT_ROT_EYE);
    billboard->addDrawable(upright.get(), osg::Vec3(0, 0, 0));
    const Camera c = topCamera();
    const std::vector<double> turned = heights(ossref::collectTriangles(*billboard, &c));
    ASSERT_EQ(turned.size(), 6u);
    for (double z : turned) EXPECT_NEAR(z, turned[0], 1e-6);
    const std::vector<double> stored = heights(ossref::collectTriangles(*billboard));
    EXPECT_NE(*std::min_element(stored.begin(), stored.end()), *std::max_element(stored.begin(), stored.end()));
}

TEST(ReferenceDirectional, CastsMaskCountsTrianglesThatCast)
{
    const ossref::TriangleSoup soup = ossref::collectTriangles(*groundScene(Occluder::Quad, 0x1u), 0x2u);
    ASSERT_EQ(soup.size(), 4u);  // two quads, two triangles each
    EXPECT_EQ(soup.casts[0] + soup.casts[1], 2);  // the ground
    EXPECT_EQ(soup.casts[2] + soup.casts[3], 0);  // the occluder
}

// ---------------------------------------------------------------------------------------
// Point and spot lights

TEST(ReferencePoint, LightBetweenOccluderAndGround)
{
    // Light at z = 2 under the occluder (z = 4): the ground is all lit, the occluder's top
    // faces the camera and away from the light.
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), pointLight({0, 0, 2}));
    EXPECT_EQ(m.count(0), 400);
    EXPECT_EQ(m.count(255), kGround - 400);
    EXPECT_EQ(ground(m, 0, 0), 0);
    EXPECT_EQ(ground(m, 5, 0), 255);
}

TEST(ReferencePoint, LightAboveOccluderCastsAnEnlargedShadow)
{
    // Light at z = 8: the top [-1,1]^2 at z = 4 shadows [-2,2]^2 (scale 8/4), of which the
    // inner 20 x 20 pixels show the occluder: 40 * 40 - 20 * 20 = 1200 shadow pixels.
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), pointLight({0, 0, 8}));
    EXPECT_EQ(m.count(0), 1200);
    EXPECT_EQ(ground(m, 0, 0), 255);
    EXPECT_EQ(ground(m, 1.5, 0), 0);
    EXPECT_EQ(ground(m, -1.95, -1.95), 0);
    EXPECT_EQ(ground(m, 1.95, 0), 0);   // to the light: x = 0.975 at z = 4, inside
    EXPECT_EQ(ground(m, 2.05, 0), 255); // x = 1.025 at z = 4, outside
}

TEST(ReferenceSpot, ConeLimitsTheLitRegion)
{
    // Spot at z = 8 pointing down with a 30 degree cutoff: the cone meets the ground in a
    // disc of radius 8 tan(30) = 4.6188; the occluder's shadow is still [-2, 2]^2.
    Light spot = pointLight({0, 0, 8});
    spot.type = Light::SPOT;
    spot.spotDirection = osg::Vec3d(0, 0, -1);
    spot.spotCutoffDeg = 30.0;
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), spot);

    EXPECT_EQ(ground(m, 0, 0), 255);    // occluder top, on the axis
    EXPECT_EQ(ground(m, 1.5, 0), 0);    // shadow
    EXPECT_EQ(ground(m, 3, 0), 255);    // 20.6 degrees off axis
    EXPECT_EQ(ground(m, 3, 3), 255);    // 27.9 degrees
    EXPECT_EQ(ground(m, 4, 3), 0);      // 32.0 degrees: outside
    EXPECT_EQ(ground(m, 6, 0), 0);      // 36.9 degrees
    EXPECT_EQ(ground(m, 9, 9), 0);

    const double radius = 8.0 * std::tan(osg::DegreesToRadians(30.0));
    long long lit = 400;  // the occluder top: at most 16.3 degrees off axis
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
        {
            const double x = -15 + 0.1 * (i + 0.5), y = -15 + 0.1 * (j + 0.5);
            const bool inShadowSquare = std::fabs(x) < 2 && std::fabs(y) < 2;
            lit += (std::hypot(x, y) < radius && !inShadowSquare) ? 1 : 0;
        }
    EXPECT_EQ(m.count(255), lit);
    EXPECT_EQ(m.count(0), kGround - lit);
}

TEST(ReferenceSpot, ConePointingAwayLightsNothing)
{
    Light spot = pointLight({0, 0, 8});
    spot.type = Light::SPOT;
    spot.spotDirection = osg::Vec3d(0, 0, 1);
    spot.spotCutoffDeg = 60.0;
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), spot);
    EXPECT_EQ(m.count(255), 0);
    EXPECT_EQ(m.count(0), kGround);
}

// ---------------------------------------------------------------------------------------
// Grazing band

struct GrazingCase
{
    const char* name;
    double elevationDeg;  // of a directional light above the ground plane
    long long grazing;
    long long lit;
};

const GrazingCase kGrazingCases[] = {
    {"OneDegree", 1.0, kGround, kGround},      // N.L = sin 1 = 0.0175
    {"JustInside", 2.8, kGround, kGround},     // sin 2.8 = 0.0488
    {"JustOutside", 3.0, 0, kGround},          // sin 3.0 = 0.0523
    {"Steep", 10.0, 0, kGround},
    {"BelowHorizon", -1.0, 0, 0},              // N.L < 0: not grazing, no light
};

void PrintTo(const GrazingCase& c, std::ostream* os) { *os << c.name; }

class Grazing : public testing::TestWithParam<GrazingCase>
{
};

TEST_P(Grazing, BandIsZeroToFivePercent)
{
    const GrazingCase& c = GetParam();
    const double a = osg::DegreesToRadians(c.elevationDeg);
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::None), topCamera(),
                                                directional({std::cos(a), 0, std::sin(a)}));
    EXPECT_EQ(grazingCount(m), c.grazing);
    EXPECT_EQ(m.count(255), c.lit);
    EXPECT_EQ(m.count(128), kBackground);
}

INSTANTIATE_TEST_SUITE_P(Reference, Grazing, testing::ValuesIn(kGrazingCases),
                         [](const testing::TestParamInfo<GrazingCase>& info) { return info.param.name; });

TEST(ReferenceGrazing, ComparisonExcludesTheBand)
{
    const double a = osg::DegreesToRadians(1.0);
    const Mask ref = ossref::computeReferenceMask(*groundScene(Occluder::None), topCamera(),
                                                  directional({std::cos(a), 0, std::sin(a)}));
    const Mask allDark = Mask::filled(kSize, kSize, 0);
    const Comparison c = ossref::compareMasks(allDark, ref);
    ASSERT_TRUE(c.valid);
    EXPECT_EQ(c.grazingExcluded, kGround);
    EXPECT_EQ(c.geometryPixels, 0);
    EXPECT_EQ(c.wrongPixels, 0);
    EXPECT_EQ(c.wrongPct, 0.0);
    EXPECT_EQ(c.coverageMismatch, kBackground);
}

// ---------------------------------------------------------------------------------------
// Robustness

TEST(ReferenceRobustness, BadTrianglesAreSkipped)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    osg::ref_ptr<osg::Geometry> g = quad(-10, 10, -10, 10, 0);
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    const std::array<osg::Vec3, 12> bad = {{{0, 0, 1}, {nan, 0, 1}, {1, 1, 1},      // NaN
                                            {0, 0, 2}, {1, 0, 2}, {0, inf, 2},      // Inf
                                            {0, 0, 3}, {1, 1, 3}, {2, 2, 3},        // collinear
                                            {5, 5, 5}, {5, 5, 5}, {6, 5, 5}}};      // repeated vertex
    for (const osg::Vec3& p : bad) v->push_back(p);
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 4, 12));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(g.get()));
    osg::ref_ptr<osg::MatrixTransform> nanTransform = new osg::MatrixTransform;
    osg::Matrixd nanMatrix;
    nanMatrix(3, 0) = nan;
    nanTransform->setMatrix(nanMatrix);
    nanTransform->addChild(geode(quad(-1, 1, -1, 1, 4).get()));
    root->addChild(nanTransform.get());

    const ossref::TriangleSoup soup = ossref::collectTriangles(*root);
    EXPECT_EQ(soup.size(), 2u);
    EXPECT_EQ(soup.skipped, 4 + 2);
    for (const osg::Vec3d& p : soup.vertices) EXPECT_TRUE(std::isfinite(p.length2()));

    const Mask m = ossref::computeReferenceMask(*root, topCamera(), directional({0, 0, 1}));
    EXPECT_EQ(m.count(255), kGround);
    EXPECT_EQ(m.count(128), kBackground);
}

TEST(ReferenceRobustness, EmptySceneAndDegenerateInputs)
{
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    const Mask m = ossref::computeReferenceMask(*empty, topCamera(), directional({0, 0, 1}));
    EXPECT_EQ(m.count(128), kSize * kSize);

    Camera noPixels = topCamera();
    noPixels.width = 0;
    EXPECT_TRUE(ossref::computeReferenceMask(*groundScene(Occluder::Quad), noPixels, directional({0, 0, 1})).empty());

    // A zero light direction lights nothing but still shows the geometry.
    const Mask dark = ossref::computeReferenceMask(*groundScene(Occluder::Quad), topCamera(), directional({0, 0, 0}));
    EXPECT_EQ(dark.count(0), kGround);
}

TEST(ReferenceTracer, OneBvhManyLights)
{
    const ossref::Tracer tracer(*groundScene(Occluder::Quad));
    EXPECT_EQ(tracer.triangleCount(), 4u);
    EXPECT_EQ(tracer.render(topCamera(), directional({1, 0, 1})).count(0), 400);
    EXPECT_EQ(tracer.render(topCamera(), pointLight({0, 0, 8}), 1).count(0), 1200);
    // eps = 1e-6 R + 1e-6 |p - C| with R = half the diagonal of [-10,10]^2 x [0,4], C = (0,0,2).
    EXPECT_NEAR(tracer.epsilonAt(osg::Vec3d(0, 0, 2)), 1e-6 * std::sqrt(204.0), 1e-12);
    EXPECT_NEAR(tracer.epsilonAt(osg::Vec3d(3, 4, 2)), 1e-6 * std::sqrt(204.0) + 5e-6, 1e-12);
}

// The reference answers for the offset point hit + eps N. A shadow boundary that passes
// 5e-5 units from a pixel's ground point, inside the shadow, must not fall between the two.
// Light toward (1, 0, 1); an occluder quad at z = 2 over x in [a, a + 4], y in [-2, 2]:
// ground point (x, y, 0) is shadowed for x in [a - 2, a + 2], and a point at height e for
// x in [a - 2 + e, a + 2 - e]. Pixel column 150 sees x = 0.05; with a - 2 = 0.05 - 5e-5 its
// centre lies 5e-5 inside the shadow: shadowed at offsets below 5e-5 (the default's,
// 1e-6 R + 1e-6 |p - C| ~ 1.6e-5 here), lit from the earlier 1e-5 R (1.4e-4).
TEST(ReferenceTracer, ShadowBoundaryCloserThanTheOldOffset)
{
    const double a = 2.05 - 5e-5;
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    root->addChild(geode(quad(a, a + 4, -2, 2, 2).get()));
    ossref::Tracer tracer(*root);
    const Light light = directional({1, 0, 1});
    ASSERT_LT(tracer.epsilonAt(osg::Vec3d(0.05, 0.05, 0)), 2e-5);
    const Mask fine = tracer.render(topCamera(), light);
    EXPECT_EQ(fine.atGL(150, 150), ossref::MASK_NO_LIGHT);
    EXPECT_EQ(fine.atGL(149, 150), ossref::MASK_LIT); // x = -0.05: 0.1 outside
    EXPECT_EQ(fine.atGL(151, 150), ossref::MASK_NO_LIGHT);
    tracer.setOffsetScale(1e-5);
    EXPECT_DOUBLE_EQ(tracer.getOffsetScale(), 1e-5);
    EXPECT_EQ(tracer.render(topCamera(), light).atGL(150, 150), ossref::MASK_LIT);
}

// Embree's hit distance is a float: from a camera 1000 units away it is good to about
// 1000 x 6e-8 = 6e-5 units, four times the shadow ray's offset over this ground (1.4e-5).
// The hit is moved onto its triangle's plane in double precision, so a lit ground with
// nothing above it is lit at every pixel (without that, points below the plane shadow
// themselves).
TEST(ReferenceTracer, FarCameraDoesNotShadowALitGround)
{
    const Mask m = ossref::computeReferenceMask(*groundScene(Occluder::None), topCamera(), directional({1, 0.3, 0.2}));
    EXPECT_EQ(m.count(ossref::MASK_LIT), kGround);
    Camera farther = topCamera();
    farther.eye = osg::Vec3d(0.0, 0.0, 20000.0);
    farther.fovyDeg = osg::RadiansToDegrees(2.0 * std::atan(0.015 / 20.0));
    const Mask m2 = ossref::computeReferenceMask(*groundScene(Occluder::None), farther, directional({1, 0.3, 0.2}));
    EXPECT_EQ(m2.count(ossref::MASK_LIT), kGround);
}

// ---------------------------------------------------------------------------------------
// Alpha-tested cut-outs
//
// The caster is the occluder quad [-1, 1]^2 at z = 4 with texture coordinates
// s = (x + 1) / 2, t = (y + 1) / 2. A light straight down would hide its shadow from the
// top camera (the quad covers its own footprint, as in QuadStraightUp), so the light is
// toward (1, 0, 1): ground point (x, y) lies under quad point (x + 4, y), the footprint is
// [-5, -3] x [-1, 1] (20 x 20 pixels) and ground point (x, y) in it sees the texture at
// s = (x + 5) / 2, t = (y + 1) / 2. Every texel edge used below falls on a multiple of 0.1
// on the ground, 0.05 from the nearest pixel centres, so the counts are exact.

/** An RGBA image, width = alphas[0].size(), alphas[j][i] the alpha of texel (i, j): row 0
 *  of the image, t = 0, comes first. */
osg::ref_ptr<osg::Image> rgbaImage(const std::vector<std::vector<int>>& alphas)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    const int width = int(alphas[0].size());
    const int height = int(alphas.size());
    image->allocateImage(width, height, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
        {
            unsigned char* texel = image->data(i, j);
            texel[0] = texel[1] = texel[2] = 200;
            texel[3] = (unsigned char)alphas[j][i];
        }
    return image;
}

/** 4 x 4 checkerboard: texel (i, j) opaque (255) when i + j is even, transparent (0) else. */
osg::ref_ptr<osg::Image> checkerboard()
{
    std::vector<std::vector<int>> alphas(4, std::vector<int>(4));
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) alphas[j][i] = (i + j) % 2 == 0 ? 255 : 0;
    return rgbaImage(alphas);
}

osg::ref_ptr<osg::Texture2D> texture2D(osg::Image* image, osg::Texture::FilterMode filter,
                                       osg::Texture::WrapMode wrap = osg::Texture::CLAMP_TO_EDGE)
{
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image);
    texture->setFilter(osg::Texture::MIN_FILTER, filter);
    texture->setFilter(osg::Texture::MAG_FILTER, filter);
    texture->setWrap(osg::Texture::WRAP_S, wrap);
    texture->setWrap(osg::Texture::WRAP_T, wrap);
    return texture;
}

/** quad() with texture coordinates (0, 0) .. (sMax, 1) over its corners. */
osg::ref_ptr<osg::Geometry> texturedQuad(double x0, double x1, double y0, double y1, double z, float sMax = 1.0f)
{
    osg::ref_ptr<osg::Geometry> g = quad(x0, x1, y0, y1, z);
    osg::ref_ptr<osg::Vec2Array> tc = new osg::Vec2Array;
    tc->push_back(osg::Vec2(0, 0));
    tc->push_back(osg::Vec2(sMax, 0));
    tc->push_back(osg::Vec2(sMax, 1));
    tc->push_back(osg::Vec2(0, 1));
    g->setTexCoordArray(0, tc.get(), osg::Array::BIND_PER_VERTEX);
    return g;
}

/** The ground [-10, 10]^2 and the caster, returned through `caster` to hang state on. */
osg::ref_ptr<osg::Group> cutoutScene(osg::ref_ptr<osg::Geometry>& caster)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    caster = texturedQuad(-1, 1, -1, 1, 4);
    root->addChild(geode(caster.get()));
    return root;
}

/** The checkerboard caster: texture (NEAREST) on the drawable; the alpha test on the
 *  drawable too unless `alphaTestOn` is null. */
osg::ref_ptr<osg::Group> checkerboardScene(osg::ref_ptr<osg::Geometry>& caster, const bool* alphaTestOn)
{
    osg::ref_ptr<osg::Group> root = cutoutScene(caster);
    osg::StateSet* ss = caster->getOrCreateStateSet();
    ss->setTextureAttributeAndModes(0, texture2D(checkerboard().get(), osg::Texture::NEAREST).get());
    if (alphaTestOn)
    {
        ss->setAttribute(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
        ss->setMode(GL_ALPHA_TEST, *alphaTestOn ? osg::StateAttribute::ON : osg::StateAttribute::OFF);
    }
    return root;
}

/** Pixels of value v whose ground point lies in [x0, x1] x [y0, y1]. */
long long countIn(const Mask& m, double x0, double x1, double y0, double y1, uint8_t v)
{
    long long n = 0;
    for (int j = pixelOf(y0); j <= pixelOf(y1); ++j)
        for (int i = pixelOf(x0); i <= pixelOf(x1); ++i)
        {
            const double cx = -15.0 + 0.1 * (i + 0.5);
            const double cy = -15.0 + 0.1 * (j + 0.5);
            if (cx > x0 && cx < x1 && cy > y0 && cy < y1 && m.atGL(i, j) == v) ++n;
        }
    return n;
}

/** Shadowed pixels of the caster's footprint [-5, -3] x [-1, 1] (400 pixels). */
long long footprintShadow(const Mask& m)
{
    return countIn(m, -5, -3, -1, 1, ossref::MASK_NO_LIGHT);
}

const Light kCutoutLight = directional({1, 0, 1});

TEST(ReferenceCutout, CheckerboardCasterShadowHasHoles)
{
    osg::ref_ptr<osg::Geometry> caster;
    const bool on = true;
    osg::ref_ptr<osg::Group> root = checkerboardScene(caster, &on);

    const ossref::TriangleSoup soup = ossref::collectTriangles(*root);
    ASSERT_EQ(soup.size(), 4u);
    ASSERT_EQ(soup.cutouts.size(), 1u);
    EXPECT_EQ(soup.cutout, (std::vector<int>{-1, -1, 0, 0}));
    EXPECT_EQ(soup.texCoords.size(), 6u);
    EXPECT_TRUE(soup.cutouts[0].nearest);
    EXPECT_EQ(soup.cutouts[0].func, osg::AlphaFunc::GREATER);
    EXPECT_FLOAT_EQ(soup.cutouts[0].ref, 0.5f);
    EXPECT_FLOAT_EQ(soup.cutouts[0].alphaScale, 1.0f);

    // 8 of the 16 texels are transparent: half the 400 footprint pixels (5 x 5 per texel)
    // stay lit.
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
    EXPECT_EQ(countIn(m, -5, -3, -1, 1, ossref::MASK_LIT), 200);
    EXPECT_EQ(footprintShadow(m), 200);
    EXPECT_EQ(m.count(ossref::MASK_NO_LIGHT), 200);
    EXPECT_EQ(m.count(ossref::MASK_BACKGROUND), kBackground);
    // Texel (0, 0) is opaque and texel (1, 0), (0, 1) are not: image row 0 is t = 0.
    EXPECT_EQ(ground(m, -4.75, -0.75), ossref::MASK_NO_LIGHT);
    EXPECT_EQ(ground(m, -4.25, -0.75), ossref::MASK_LIT);
    EXPECT_EQ(ground(m, -4.75, -0.25), ossref::MASK_LIT);
    EXPECT_EQ(ground(m, -3.25, 0.75), ossref::MASK_NO_LIGHT); // texel (3, 3)
}

TEST(ReferenceCutout, AlphaTestOffCastsTheWholeQuad)
{
    osg::ref_ptr<osg::Geometry> caster;
    const bool off = false;
    osg::ref_ptr<osg::Group> root = checkerboardScene(caster, &off);
    const ossref::TriangleSoup soup = ossref::collectTriangles(*root);
    EXPECT_TRUE(soup.cutout.empty()); // opaque scenes carry no per-triangle table
    EXPECT_TRUE(soup.cutouts.empty());
    EXPECT_TRUE(soup.texCoords.empty());
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
    EXPECT_EQ(footprintShadow(m), 400);
    EXPECT_EQ(m.count(ossref::MASK_NO_LIGHT), 400);
}

/** A Group inserted between the root of a cutoutScene and the caster's Geode; the ground
 *  stays out of its state. */
osg::StateSet* casterParentState(osg::Group& root)
{
    osg::ref_ptr<osg::Group> parent = new osg::Group;
    osg::ref_ptr<osg::Node> casterNode = root.getChild(1);
    root.replaceChild(casterNode.get(), parent.get());
    parent->addChild(casterNode.get());
    return parent->getOrCreateStateSet();
}

TEST(ReferenceCutout, AlphaTestInheritedFromAParentGroup)
{
    osg::ref_ptr<osg::Geometry> caster;
    osg::ref_ptr<osg::Group> root = checkerboardScene(caster, nullptr);
    casterParentState(*root)->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
    EXPECT_EQ(footprintShadow(m), 200);
    EXPECT_EQ(ground(m, -4.75, -0.75), ossref::MASK_NO_LIGHT);
    EXPECT_EQ(ground(m, -4.25, -0.75), ossref::MASK_LIT);
}

TEST(ReferenceCutout, OverrideAndProtected)
{
    osg::ref_ptr<osg::Geometry> caster;
    const bool on = true;
    osg::ref_ptr<osg::Group> root = checkerboardScene(caster, &on);
    osg::StateSet* parentState = casterParentState(*root);

    // The parent's OFF with OVERRIDE beats the drawable's ON: the whole quad casts.
    parentState->setMode(GL_ALPHA_TEST, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    EXPECT_EQ(footprintShadow(ossref::computeReferenceMask(*root, topCamera(), kCutoutLight)), 400);

    // ... unless the drawable's ON is PROTECTED.
    caster->getStateSet()->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    const Mask isProtected = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
    EXPECT_EQ(footprintShadow(isProtected), 200);
    EXPECT_EQ(ground(isProtected, -4.75, -0.75), ossref::MASK_NO_LIGHT);

    // Attributes follow the same rule: the parent's LESS 0.5 with OVERRIDE replaces the
    // drawable's GREATER 0.5, and keeps the transparent texels instead.
    parentState->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON);
    parentState->setAttribute(new osg::AlphaFunc(osg::AlphaFunc::LESS, 0.5f), osg::StateAttribute::OVERRIDE);
    const Mask inverted = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
    EXPECT_EQ(footprintShadow(inverted), 200);
    EXPECT_EQ(ground(inverted, -4.75, -0.75), ossref::MASK_LIT);
    EXPECT_EQ(ground(inverted, -4.25, -0.75), ossref::MASK_NO_LIGHT);
}

// Primary rays: the checkerboard quad alone (no ground), light straight down. The quad seen
// from the top camera spans 20 x 20 pixels (its edges at +-1.004 on the ground scale, texel
// edges at +-0.502 and 0, each 0.05 or more from the nearest pixel centre): 200 pixels see
// opaque texels (lit) and 200 see the background through the transparent ones.
TEST(ReferenceCutout, PrimaryRaysSeeThroughHoles)
{
    osg::ref_ptr<osg::Geometry> caster = texturedQuad(-1, 1, -1, 1, 4);
    osg::StateSet* ss = caster->getOrCreateStateSet();
    ss->setTextureAttributeAndModes(0, texture2D(checkerboard().get(), osg::Texture::NEAREST).get());
    ss->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(caster.get()));
    const Mask m = ossref::computeReferenceMask(*root, topCamera(), directional({0, 0, 1}));
    EXPECT_EQ(m.count(ossref::MASK_LIT), 200);
    EXPECT_EQ(m.count(ossref::MASK_NO_LIGHT), 0);
    EXPECT_EQ(m.count(ossref::MASK_BACKGROUND), kSize * kSize - 200);
    EXPECT_EQ(ground(m, -0.75, -0.75), ossref::MASK_LIT);        // texel (0, 0)
    EXPECT_EQ(ground(m, -0.25, -0.75), ossref::MASK_BACKGROUND); // texel (1, 0)

    // With the ground under it (drawn first: opaque triangles before the cut-outs) every
    // pixel shows geometry and is lit: the opaque texels face the light, and the ground
    // seen through a hole lies at most 0.004 units outward of the hole's point, which is
    // 0.05 or more inside the hole. A hit shaded with another triangle's plane (the ground's
    // under an opaque texel) would come out shadowed.
    osg::ref_ptr<osg::Group> groundFirst = new osg::Group;
    groundFirst->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    groundFirst->addChild(root->getChild(0));
    const Mask withGround = ossref::computeReferenceMask(*groundFirst, topCamera(), directional({0, 0, 1}));
    EXPECT_EQ(withGround.count(ossref::MASK_LIT), kGround);
    EXPECT_EQ(withGround.count(ossref::MASK_BACKGROUND), kBackground);
}

// A 2 x 1 texture, alphas 0 and 1, CLAMP_TO_EDGE, on the caster: texel centres at s = 0.25
// and 0.75, so LINEAR gives alpha 0 for s <= 0.25, 2 s - 0.5 between, 1 from 0.75 on. The
// shadow covers the ground points (x, y) with s = (x + 5) / 2 kept by the test:
//   GREATER 0.5, LINEAR: s > 0.5, x in (-4, -3]: 10 columns x 20 rows = 200;
//   GREATER 0.3, LINEAR: s > 0.4, x in (-4.2, -3]: 12 columns = 240;
//   GREATER 0.3, NEAREST: texel 1, s >= 0.5: 200 again.
TEST(ReferenceCutout, BilinearAlphaCutsBetweenTexelCentres)
{
    struct Case
    {
        osg::Texture::FilterMode filter;
        float ref;
        long long shadow;
        double firstShadowedX; // the footprint's leftmost shadowed pixel centre
    };
    for (const Case& c : {Case{osg::Texture::LINEAR, 0.5f, 200, -3.95}, Case{osg::Texture::LINEAR, 0.3f, 240, -4.15},
                          Case{osg::Texture::NEAREST, 0.3f, 200, -3.95}})
    {
        SCOPED_TRACE(testing::Message() << "filter " << c.filter << ", GREATER " << c.ref);
        osg::ref_ptr<osg::Geometry> caster;
        osg::ref_ptr<osg::Group> root = cutoutScene(caster);
        osg::StateSet* ss = caster->getOrCreateStateSet();
        ss->setTextureAttributeAndModes(0, texture2D(rgbaImage({{0, 255}}).get(), c.filter).get());
        ss->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, c.ref));
        const Mask m = ossref::computeReferenceMask(*root, topCamera(), kCutoutLight);
        EXPECT_EQ(footprintShadow(m), c.shadow);
        EXPECT_EQ(ground(m, c.firstShadowedX, 0.05), ossref::MASK_NO_LIGHT);
        EXPECT_EQ(ground(m, c.firstShadowedX - 0.1, 0.05), ossref::MASK_LIT);
    }
}

// Wrap modes, primary rays: a quad [-10, 10] x [-1, 1] at z = 0 (no perspective) with s from
// 0 to 2, the 2 x 1 texture (alphas 0, 1) with NEAREST: s = (x + 10) / 10, texel index
// floor(2 s) = 0, 1, 2, 3 on the quarters starting at x = -10, -5, 0, 5. Indices 2 and 3
// wrap to 0, 1 (REPEAT), 1, 0 (MIRROR) or 1, 1 (clamp to edge). Kept quarters are lit
// (light straight down), cut ones background; 50 columns x 20 rows per quarter.
TEST(ReferenceCutout, WrapModes)
{
    struct Case
    {
        osg::Texture::WrapMode wrap;
        long long lit;
        uint8_t third;  // at x = 2.5
        uint8_t fourth; // at x = 7.5
    };
    const uint8_t lit = ossref::MASK_LIT;
    const uint8_t none = ossref::MASK_BACKGROUND;
    for (const Case& c : {Case{osg::Texture::REPEAT, 2000, none, lit}, Case{osg::Texture::MIRROR, 2000, lit, none},
                          Case{osg::Texture::CLAMP_TO_EDGE, 3000, lit, lit}})
    {
        SCOPED_TRACE(testing::Message() << "wrap " << c.wrap);
        osg::ref_ptr<osg::Geometry> strip = texturedQuad(-10, 10, -1, 1, 0, 2.0f);
        osg::StateSet* ss = strip->getOrCreateStateSet();
        ss->setTextureAttributeAndModes(0, texture2D(rgbaImage({{0, 255}}).get(), osg::Texture::NEAREST, c.wrap).get());
        ss->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
        osg::ref_ptr<osg::Group> root = new osg::Group;
        root->addChild(geode(strip.get()));
        const Mask m = ossref::computeReferenceMask(*root, topCamera(), directional({0, 0, 1}));
        EXPECT_EQ(m.count(lit), c.lit);
        EXPECT_EQ(ground(m, -7.5, 0), none);
        EXPECT_EQ(ground(m, -2.5, 0), lit);
        EXPECT_EQ(ground(m, 2.5, 0), c.third);
        EXPECT_EQ(ground(m, 7.5, 0), c.fourth);
    }
}

// The Material's front diffuse alpha scales the texture's: 0.6 x 1 > 0.5 keeps the opaque
// texels, 0.4 x 1 does not. Without a texture the alpha cannot vary: a passing test leaves
// the triangles opaque, a failing one discards them entirely.
TEST(ReferenceCutout, MaterialAlphaScalesTheTexture)
{
    for (const float alpha : {0.6f, 0.4f})
    {
        SCOPED_TRACE(testing::Message() << "material alpha " << alpha);
        osg::ref_ptr<osg::Material> material = new osg::Material;
        material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 1, 1, alpha));

        osg::ref_ptr<osg::Geometry> caster;
        const bool on = true;
        osg::ref_ptr<osg::Group> textured = checkerboardScene(caster, &on);
        caster->getStateSet()->setAttribute(material.get());
        EXPECT_EQ(footprintShadow(ossref::computeReferenceMask(*textured, topCamera(), kCutoutLight)),
                  alpha > 0.5f ? 200 : 0);

        osg::ref_ptr<osg::Group> plain = cutoutScene(caster);
        caster->getOrCreateStateSet()->setAttribute(material.get());
        caster->getStateSet()->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
        EXPECT_EQ(ossref::collectTriangles(*plain).cutouts.size(), alpha > 0.5f ? 0u : 1u);
        EXPECT_EQ(footprintShadow(ossref::computeReferenceMask(*plain, topCamera(), kCutoutLight)),
                  alpha > 0.5f ? 400 : 0);
    }
}

// The shadow scene holds only the casters: a cut-out that does not cast leaves no shadow,
// a cut-out caster filters the shadow rays of the casters-only scene too.
TEST(ReferenceCutout, CastersOnlyShadowSceneFiltersToo)
{
    osg::ref_ptr<osg::Geometry> caster;
    const bool on = true;
    osg::ref_ptr<osg::Group> root = checkerboardScene(caster, &on);
    root->getChild(0)->setNodeMask(0x1); // the ground: seen, does not cast
    root->getChild(1)->setNodeMask(0x3);
    const ossref::Tracer tracer(ossref::collectTriangles(*root, 0x2u));
    const Mask m = tracer.render(topCamera(), kCutoutLight);
    EXPECT_EQ(footprintShadow(m), 200);
    EXPECT_EQ(ground(m, -4.25, -0.75), ossref::MASK_LIT);
}

// ---------------------------------------------------------------------------------------
// Face culling
//
// The quad [-1, 1]^2 at z = 4 over the ground, wound clockwise as the top camera sees it:
// the camera sees its back under OpenGL's default FrontFace (COUNTER_CLOCKWISE). Light
// toward (0.25, 0, 1): ground point (x, y) lies under quad point (x + 1, y), the shadow is
// [-2, 0] x [-1, 1]. The quad covers the 20 x 20 pixels whose ground points lie in
// (-1, 1)^2 (its edges at +-1.004): seen, they are its top, lit; seen through, the ground,
// shadowed for x < 0 (200 pixels) and lit for x > 0 (200). The shadow outside the quad,
// x in (-2, -1), is 10 x 20 = 200 pixels either way: shadow rays see both sides.

const Light kCullLight = directional({0.25, 0, 1});

/** The ground and the quad, returned through `caster` to hang state on. */
osg::ref_ptr<osg::Group> culledQuadScene(osg::ref_ptr<osg::Geometry>& caster)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    caster = quad(1, -1, -1, 1, 4); // (1, -1), (-1, -1), (-1, 1), (1, 1): clockwise from above
    root->addChild(geode(caster.get()));
    return root;
}

enum class Seen
{
    Quad,
    Ground
};

Mask cullMask(const osg::Node& root)
{
    return ossref::computeReferenceMask(root, topCamera(), kCullLight);
}

/** The mask of a culledQuadScene: what the camera sees where the quad is, and the quad's
 *  shadow beside it. */
void expectSeen(const Mask& m, Seen seen)
{
    const bool through = seen == Seen::Ground;
    EXPECT_EQ(countIn(m, -2, -1, -1, 1, ossref::MASK_NO_LIGHT), 200); // the quad casts
    EXPECT_EQ(countIn(m, -1, 0, -1, 1, ossref::MASK_NO_LIGHT), through ? 200 : 0);
    EXPECT_EQ(countIn(m, 0, 1, -1, 1, ossref::MASK_LIT), 200);
    EXPECT_EQ(m.count(ossref::MASK_NO_LIGHT), through ? 400 : 200);
    EXPECT_EQ(m.count(ossref::MASK_BACKGROUND), kBackground);
    EXPECT_EQ(ground(m, -0.45, 0.05), through ? ossref::MASK_NO_LIGHT : ossref::MASK_LIT);
}

TEST(ReferenceCulling, BackFaceSeenThroughWithCullingOn)
{
    osg::ref_ptr<osg::Geometry> caster;
    osg::ref_ptr<osg::Group> root = culledQuadScene(caster);
    caster->getOrCreateStateSet()->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
    const ossref::TriangleSoup soup = ossref::collectTriangles(*root);
    EXPECT_EQ(soup.culled,
              (std::vector<uint8_t>{ossref::CULL_NONE, ossref::CULL_NONE, ossref::CULL_CW_SIDE, ossref::CULL_CW_SIDE}));
    expectSeen(cullMask(*root), Seen::Ground);

    // The visibility mask's primary rays see through it too.
    const ossref::VisibilityMask v = ossref::computeReferenceVisibility(*root, topCamera(), kCullLight);
    EXPECT_EQ(v.visibilityGL(pixelOf(-0.45), pixelOf(0.05)), 0.0);
    EXPECT_EQ(v.visibilityGL(pixelOf(0.45), pixelOf(0.05)), 1.0);

    // An osg::CullFace BACK is the default's.
    caster->getStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
    expectSeen(cullMask(*root), Seen::Ground);
}

TEST(ReferenceCulling, CullingOffShowsTheQuad)
{
    osg::ref_ptr<osg::Geometry> caster;
    osg::ref_ptr<osg::Group> root = culledQuadScene(caster);
    EXPECT_TRUE(ossref::collectTriangles(*root).culled.empty()); // no culling, no table
    expectSeen(cullMask(*root), Seen::Quad);

    // A CullFace without GL_CULL_FACE, or with it OFF, culls nothing.
    caster->getOrCreateStateSet()->setAttribute(new osg::CullFace(osg::CullFace::FRONT_AND_BACK));
    expectSeen(cullMask(*root), Seen::Quad);
    caster->getStateSet()->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    EXPECT_TRUE(ossref::collectTriangles(*root).culled.empty());
    expectSeen(cullMask(*root), Seen::Quad);
}

TEST(ReferenceCulling, CullFaceAndFrontFaceDecideTheSide)
{
    struct Case
    {
        osg::CullFace::Mode cull;
        osg::FrontFace::Mode front;
        uint8_t culled;
        Seen seen; // the camera sees the quad's clockwise side
    };
    const auto ccw = osg::FrontFace::COUNTER_CLOCKWISE;
    const auto cw = osg::FrontFace::CLOCKWISE;
    for (const Case& c : {Case{osg::CullFace::BACK, ccw, ossref::CULL_CW_SIDE, Seen::Ground},
                          Case{osg::CullFace::BACK, cw, ossref::CULL_CCW_SIDE, Seen::Quad},
                          Case{osg::CullFace::FRONT, ccw, ossref::CULL_CCW_SIDE, Seen::Quad},
                          Case{osg::CullFace::FRONT, cw, ossref::CULL_CW_SIDE, Seen::Ground},
                          Case{osg::CullFace::FRONT_AND_BACK, ccw, ossref::CULL_BOTH_SIDES, Seen::Ground},
                          Case{osg::CullFace::FRONT_AND_BACK, cw, ossref::CULL_BOTH_SIDES, Seen::Ground}})
    {
        SCOPED_TRACE(testing::Message() << "CullFace " << c.cull << ", FrontFace " << c.front);
        osg::ref_ptr<osg::Geometry> caster;
        osg::ref_ptr<osg::Group> root = culledQuadScene(caster);
        osg::StateSet* ss = caster->getOrCreateStateSet();
        ss->setAttributeAndModes(new osg::CullFace(c.cull));
        ss->setAttribute(new osg::FrontFace(c.front));
        const ossref::TriangleSoup soup = ossref::collectTriangles(*root);
        ASSERT_EQ(soup.culled.size(), 4u);
        EXPECT_EQ(soup.culled[2], c.culled);
        EXPECT_EQ(soup.culled[3], c.culled);
        expectSeen(cullMask(*root), c.seen);
    }
}

// The quad alone, seen from above and from below (the camera mirrored through z = 0 sees
// the quad on the same 20 x 20 pixels, its edges at +-0.996), lit from the camera's side.
TEST(ReferenceCulling, FrontAndBackHidesTheQuadFromBothSides)
{
    Camera below = topCamera();
    below.eye = osg::Vec3d(0, 0, -1000);
    for (const osg::CullFace::Mode mode : {osg::CullFace::BACK, osg::CullFace::FRONT_AND_BACK})
    {
        SCOPED_TRACE(testing::Message() << "CullFace " << mode);
        osg::ref_ptr<osg::Geometry> caster = quad(1, -1, -1, 1, 4);
        caster->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(mode));
        const ossref::Tracer tracer(ossref::collectTriangles(*geode(caster.get())));
        const bool both = mode == osg::CullFace::FRONT_AND_BACK;
        EXPECT_EQ(tracer.triangleCount(), both ? 0u : 2u);
        // From above the camera sees the back; from below the front, unless both are culled.
        EXPECT_EQ(tracer.render(topCamera(), directional({0, 0, 1})).count(ossref::MASK_LIT), 0);
        EXPECT_EQ(tracer.render(below, directional({0, 0, -1})).count(ossref::MASK_LIT), both ? 0 : 400);
    }
}

TEST(ReferenceCulling, OverrideAndProtected)
{
    osg::ref_ptr<osg::Geometry> caster;
    osg::ref_ptr<osg::Group> root = culledQuadScene(caster);
    osg::StateSet* child = caster->getOrCreateStateSet();
    child->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
    osg::StateSet* parent = casterParentState(*root);
    const auto expectStep = [&](const char* step, Seen seen) {
        SCOPED_TRACE(step);
        expectSeen(cullMask(*root), seen);
    };

    // The mode: the parent's OFF with OVERRIDE beats the drawable's ON, unless that is
    // PROTECTED.
    parent->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    expectStep("parent OFF | OVERRIDE", Seen::Quad);
    child->setMode(GL_CULL_FACE, osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    expectStep("child ON | PROTECTED", Seen::Ground);

    // The CullFace: the parent's FRONT with OVERRIDE beats the drawable's BACK and culls
    // the side the camera does not see, unless the drawable's is PROTECTED.
    parent->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
    child->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
    parent->setAttribute(new osg::CullFace(osg::CullFace::FRONT), osg::StateAttribute::OVERRIDE);
    child->setAttribute(new osg::CullFace(osg::CullFace::BACK));
    expectStep("parent FRONT | OVERRIDE", Seen::Quad);
    child->setAttribute(new osg::CullFace(osg::CullFace::BACK), osg::StateAttribute::PROTECTED);
    expectStep("child BACK | PROTECTED", Seen::Ground);

    // The FrontFace alike: the parent's CLOCKWISE with OVERRIDE makes the seen side the
    // front, unless the drawable's COUNTER_CLOCKWISE is PROTECTED.
    parent->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE), osg::StateAttribute::OVERRIDE);
    child->setAttribute(new osg::FrontFace(osg::FrontFace::COUNTER_CLOCKWISE));
    expectStep("parent CLOCKWISE | OVERRIDE", Seen::Quad);
    child->setAttribute(new osg::FrontFace(osg::FrontFace::COUNTER_CLOCKWISE), osg::StateAttribute::PROTECTED);
    expectStep("child COUNTER_CLOCKWISE | PROTECTED", Seen::Ground);
}

// The winding is the world's: a quad wound counter-clockwise from above, mirrored by its
// transform, shows its back to the camera, as GL draws it.
TEST(ReferenceCulling, MirroringTransformTurnsTheQuadOver)
{
    for (const bool mirrored : {false, true})
    {
        SCOPED_TRACE(testing::Message() << "mirrored " << mirrored);
        osg::ref_ptr<osg::Group> root = new osg::Group;
        root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
        osg::ref_ptr<osg::MatrixTransform> t =
            new osg::MatrixTransform(mirrored ? osg::Matrixd::scale(-1, 1, 1) : osg::Matrixd::identity());
        t->addChild(geode(quad(-1, 1, -1, 1, 4).get()));
        t->getOrCreateStateSet()->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
        root->addChild(t.get());
        expectSeen(cullMask(*root), mirrored ? Seen::Ground : Seen::Quad);
    }
}

// A culled cut-out: the checkerboard quad, wound clockwise from above. Alone under a light
// straight down, its opaque texels show (200 pixels, as in PrimaryRaysSeeThroughHoles)
// when the camera sees its front (FrontFace CLOCKWISE) and nothing when it sees the culled
// back; over the ground its shadow keeps its holes either way (200 of the 400 footprint
// pixels of the light toward (1, 0, 1)).
TEST(ReferenceCulling, CulledCutouts)
{
    for (const bool frontSeen : {false, true})
    {
        SCOPED_TRACE(testing::Message() << "front seen " << frontSeen);
        osg::ref_ptr<osg::Geometry> caster = texturedQuad(1, -1, -1, 1, 4);
        osg::StateSet* ss = caster->getOrCreateStateSet();
        ss->setTextureAttributeAndModes(0, texture2D(checkerboard().get(), osg::Texture::NEAREST).get());
        ss->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
        ss->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
        if (frontSeen) ss->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE));

        osg::ref_ptr<osg::Group> alone = new osg::Group;
        alone->addChild(geode(caster.get()));
        const ossref::TriangleSoup soup = ossref::collectTriangles(*alone);
        EXPECT_EQ(soup.cutout, (std::vector<int>{0, 0}));
        ASSERT_EQ(soup.culled.size(), 2u);
        const Mask m = ossref::computeReferenceMask(*alone, topCamera(), directional({0, 0, 1}));
        EXPECT_EQ(m.count(ossref::MASK_LIT), frontSeen ? 200 : 0);

        osg::ref_ptr<osg::Group> withGround = new osg::Group;
        withGround->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
        withGround->addChild(alone->getChild(0));
        const Mask shadow = ossref::computeReferenceMask(*withGround, topCamera(), kCutoutLight);
        EXPECT_EQ(footprintShadow(shadow), 200);
        EXPECT_EQ(shadow.count(ossref::MASK_NO_LIGHT), 200);
    }
}

// ---------------------------------------------------------------------------------------
// Lights from OSG

TEST(ReferenceLight, FromOsgLight)
{
    osg::ref_ptr<osg::Light> l = new osg::Light;
    l->setPosition(osg::Vec4(0, 0, 1, 0));
    const osg::Matrixd rotX90 = osg::Matrixd::rotate(osg::PI_2, osg::Vec3d(1, 0, 0)) * osg::Matrixd::translate(5, 5, 5);
    Light d = ossref::lightFromOsg(*l, rotX90);
    EXPECT_EQ(d.type, Light::DIRECTIONAL);
    EXPECT_NEAR((d.vector - osg::Vec3d(0, -1, 0)).length(), 0.0, 1e-12);  // z rotated about x, not translated

    l->setPosition(osg::Vec4(1, 2, 3, 1));
    Light p = ossref::lightFromOsg(*l, osg::Matrixd::translate(10, 0, 0));
    EXPECT_EQ(p.type, Light::POINT);
    EXPECT_NEAR((p.vector - osg::Vec3d(11, 2, 3)).length(), 0.0, 1e-12);

    l->setPosition(osg::Vec4(2, 4, 6, 2));  // homogeneous
    l->setDirection(osg::Vec3(0, 0, -1));
    l->setSpotCutoff(25);
    Light s = ossref::lightFromOsg(*l, rotX90);
    EXPECT_EQ(s.type, Light::SPOT);
    EXPECT_NEAR((s.vector - osg::Vec3d(6, 2, 7)).length(), 0.0, 1e-12);  // (1,2,3) -> (1,-3,2) + 5
    EXPECT_NEAR((s.spotDirection - osg::Vec3d(0, 1, 0)).length(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.spotCutoffDeg, 25.0);
}

TEST(ReferenceLight, FromLightSourceUsesItsWorldMatrix)
{
    osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
    source->getLight()->setPosition(osg::Vec4(0, 0, 0, 1));
    osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(osg::Matrixd::translate(1, 2, 3));
    t->addChild(source.get());
    const Light l = ossref::lightFromLightSource(*source);
    EXPECT_EQ(l.type, Light::POINT);
    EXPECT_NEAR((l.vector - osg::Vec3d(1, 2, 3)).length(), 0.0, 1e-12);
}

// ---------------------------------------------------------------------------------------
// Comparison

TEST(ReferenceCompare, HandMadeMasks)
{
    Mask ref = maskFromRows(4, {{255, 255, 0, 0}, {255, 255, 0, 0}, {128, 128, 255, 255}});
    ref.grazing[1 * 4 + 3] = 1;  // both have geometry: excluded
    ref.grazing[2 * 4 + 0] = 1;  // background in both: irrelevant
    const Mask test = maskFromRows(4, {{255, 0, 0, 0}, {255, 255, 255, 0}, {128, 255, 128, 255}});
    const Comparison c = ossref::compareMasks(test, ref);
    ASSERT_TRUE(c.valid) << c.error;
    EXPECT_EQ(c.geometryPixels, 8);     // 4 + 4 + 1 with geometry in both, minus 1 grazing
    EXPECT_EQ(c.wrongPixels, 2);        // (1,0) and (2,1)
    EXPECT_EQ(c.coverageMismatch, 2);   // (1,2) and (2,2)
    EXPECT_EQ(c.grazingExcluded, 1);
    EXPECT_DOUBLE_EQ(c.wrongPct, 25.0);
    EXPECT_DOUBLE_EQ(c.meanWrongDistance, 0.0);  // both wrong pixels lie on the boundary
}

TEST(ReferenceCompare, IdenticalMasksHaveNoError)
{
    const Mask ref = maskFromRows(3, {{0, 255, 128}, {255, 255, 0}});
    const Comparison c = ossref::compareMasks(ref, ref);
    ASSERT_TRUE(c.valid);
    EXPECT_EQ(c.geometryPixels, 5);
    EXPECT_EQ(c.wrongPixels, 0);
    EXPECT_EQ(c.coverageMismatch, 0);
    EXPECT_EQ(c.wrongPct, 0.0);
}

TEST(ReferenceCompare, ValuesBetweenLevelsAreClassified)
{
    const Mask ref = maskFromRows(5, {{0, 0, 255, 255, 128}});
    const Mask test = maskFromRows(5, {{63, 193, 192, 200, 64}});  // 0, 255, bg, 255, bg
    const Comparison c = ossref::compareMasks(test, ref);
    EXPECT_EQ(c.geometryPixels, 3);
    EXPECT_EQ(c.wrongPixels, 1);
    EXPECT_EQ(c.coverageMismatch, 1);
}

TEST(ReferenceCompare, MeanDistanceToTheReferenceBoundary)
{
    // Boundary: pixels 4 (lit) and 5 (dark). Wrong pixels 0 and 9 are 4 pixels away.
    const Mask ref = maskFromRows(10, {{255, 255, 255, 255, 255, 0, 0, 0, 0, 0}});
    const Mask test = maskFromRows(10, {{0, 255, 255, 255, 255, 0, 0, 0, 0, 255}});
    const Comparison c = ossref::compareMasks(test, ref);
    EXPECT_EQ(c.wrongPixels, 2);
    EXPECT_DOUBLE_EQ(c.meanWrongDistance, 4.0);

    const std::vector<float> d = ossref::boundaryDistance(maskFromRows(3, {{255, 255, 255}, {255, 255, 255}, {255, 255, 0}}));
    ASSERT_EQ(d.size(), 9u);
    // Boundary: the dark corner (2,2) and its lit neighbours (1,2) and (2,1).
    EXPECT_FLOAT_EQ(d[0], std::sqrt(5.0f));  // (0,0) -> (1,2) or (2,1)
    EXPECT_FLOAT_EQ(d[4], 1.0f);             // (1,1) -> (1,2)
    EXPECT_FLOAT_EQ(d[8], 0.0f);
    EXPECT_FLOAT_EQ(d[5], 0.0f);
}

TEST(ReferenceCompare, NoBoundaryGivesNegativeDistance)
{
    const Comparison c = ossref::compareMasks(maskFromRows(2, {{0, 0}}), maskFromRows(2, {{255, 255}}));
    EXPECT_EQ(c.wrongPixels, 2);
    EXPECT_EQ(c.meanWrongDistance, -1.0);
}

TEST(ReferenceCompare, MismatchedSizesAreReportedNotFatal)
{
    const Comparison c = ossref::compareMasks(Mask::filled(4, 3), Mask::filled(3, 4));
    EXPECT_FALSE(c.valid);
    EXPECT_FALSE(c.error.empty());
    EXPECT_EQ(c.geometryPixels, 0);
    EXPECT_FALSE(ossref::compareMasks(Mask(), Mask::filled(3, 4)).valid);
    Mask broken = Mask::filled(3, 4);
    broken.value.resize(5);
    EXPECT_FALSE(ossref::compareMasks(broken, Mask::filled(3, 4)).valid);
    EXPECT_FALSE(ossref::diffImage(Mask::filled(4, 3), Mask::filled(3, 4)).valid());
}

TEST(ReferenceCompare, DiffImageColours)
{
    // Top row: says shadow where lit (red), bottom row: says lit where dark (green), then
    // coverage (blue) and agreement (reference gray halved).
    const Mask ref = maskFromRows(2, {{255, 255}, {0, 128}});
    const Mask test = maskFromRows(2, {{0, 255}, {255, 0}});
    const osg::ref_ptr<osg::Image> img = ossref::diffImage(test, ref);
    ASSERT_TRUE(img.valid());
    ASSERT_EQ(img->getPixelFormat(), GLenum(GL_RGB));
    auto rgb = [&](int x, int glRow) {
        const unsigned char* p = img->data(x, glRow);
        return std::array<int, 3>{p[0], p[1], p[2]};
    };
    EXPECT_EQ(rgb(0, 1), (std::array<int, 3>{255, 0, 0}));   // top row is the last in memory
    EXPECT_EQ(rgb(1, 1), (std::array<int, 3>{127, 127, 127}));
    EXPECT_EQ(rgb(0, 0), (std::array<int, 3>{0, 255, 0}));
    EXPECT_EQ(rgb(1, 0), (std::array<int, 3>{0, 0, 255}));
}

// ---------------------------------------------------------------------------------------
// Images and files

/** CRC-32 of PNG chunks (ISO 3309). */
uint32_t crc32(const std::string& bytes)
{
    uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : bytes)
    {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

std::string bigEndian(uint32_t v)
{
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data)
{
    return bigEndian(uint32_t(data.size())) + type + data + bigEndian(crc32(type + data));
}

/** An 8-bit gray PNG written by hand (one stored deflate block, no filter), rows given
 *  top first as the PNG format defines them. Independent of osgDB's writer. */
std::string handMadePng(int width, const std::vector<std::vector<int>>& rows)
{
    std::string raw;
    for (const auto& row : rows)
    {
        raw += char(0);  // filter: none
        for (int x = 0; x < width; ++x) raw += char(row[x]);
    }
    uint32_t a = 1, b = 0;
    for (unsigned char c : raw) a = (a + c) % 65521, b = (b + a) % 65521;
    const uint16_t len = uint16_t(raw.size());
    std::string z = {char(0x78), char(0x01), char(0x01), char(len & 0xFF), char(len >> 8), char(~len & 0xFF),
                     char((~len >> 8) & 0xFF)};
    z += raw + bigEndian((b << 16) | a);
    const std::string header = bigEndian(uint32_t(width)) + bigEndian(uint32_t(rows.size())) + std::string{8, 0, 0, 0, 0};
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) + chunk("IDAT", z) + chunk("IEND", "");
}

TEST(ReferenceImages, ReadMaskKeepsTheTopRowOfAHandMadePng)
{
    const std::string path = tempPath("ossref_handmade.png");
    std::ofstream(path, std::ios::binary) << handMadePng(3, {{0, 0, 0}, {255, 255, 255}, {128, 128, 255}});
    Mask m;
    ASSERT_TRUE(ossref::readMask(path, m));
    ASSERT_EQ(m.width, 3);
    ASSERT_EQ(m.height, 3);
    EXPECT_EQ(m.value, (std::vector<uint8_t>{0, 0, 0, 255, 255, 255, 128, 128, 255}));
    std::remove(path.c_str());
}

TEST(ReferenceImages, WriteReadRoundTripKeepsRows)
{
    Mask m = Mask::filled(5, 4, 255);
    std::fill(m.value.begin(), m.value.begin() + 5, 0);  // top row dark
    m.value[2 * 5 + 1] = 128;
    const std::string path = tempPath("ossref_roundtrip.png");
    ASSERT_TRUE(ossref::writeMask(m, path));

    Mask back;
    ASSERT_TRUE(ossref::readMask(path, back));
    EXPECT_EQ(back.width, 5);
    EXPECT_EQ(back.height, 4);
    EXPECT_EQ(back.value, m.value);

    // osgDB hands the PNG back bottom row first: the dark top row is the last in memory.
    const osg::ref_ptr<osg::Image> img = osgDB::readRefImageFile(path);
    ASSERT_TRUE(img.valid());
    EXPECT_EQ(*img->data(0, 3), 0);
    EXPECT_EQ(*img->data(0, 0), 255);
    std::remove(path.c_str());
    EXPECT_FALSE(ossref::readMask(path, back));
}

TEST(ReferenceImages, ImageConversions)
{
    const Mask m = maskFromRows(2, {{0, 255}, {128, 0}});
    const osg::ref_ptr<osg::Image> lum = ossref::imageFromMask(m);
    ASSERT_TRUE(lum.valid());
    EXPECT_EQ(lum->getPixelFormat(), GLenum(GL_LUMINANCE));
    EXPECT_EQ(*lum->data(1, 1), 255);  // top row, right pixel
    EXPECT_EQ(ossref::maskFromImage(*lum).value, m.value);

    osg::ref_ptr<osg::Image> rgba = new osg::Image;
    rgba->allocateImage(2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    const unsigned char px[8] = {10, 200, 200, 255, 230, 0, 0, 255};
    std::copy(px, px + 8, rgba->data());
    EXPECT_EQ(ossref::maskFromImage(*rgba).value, (std::vector<uint8_t>{0, 255}));

    osg::ref_ptr<osg::Image> flt = new osg::Image;
    flt->allocateImage(3, 1, 1, GL_LUMINANCE, GL_FLOAT);
    const float fv[3] = {0.0f, 0.5f, 1.0f};
    std::copy(fv, fv + 3, reinterpret_cast<float*>(flt->data()));
    EXPECT_EQ(ossref::maskFromImage(*flt).value, (std::vector<uint8_t>{0, 128, 255}));

    osg::ref_ptr<osg::Image> depth = new osg::Image;
    depth->allocateImage(2, 2, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
    EXPECT_TRUE(ossref::maskFromImage(*depth).empty());
}

// ---------------------------------------------------------------------------------------
// Cost: printed and recorded for docs/reference.md; no bound on time (a machine's load is not
// the reference's fault), only on what was computed.

TEST(ReferenceSpeed, HundredThousandTrianglesAt1024x768)
{
    const osg::ref_ptr<osg::Node> scene = bumpyTerrain();
    const Camera c = terrainCamera();
    const auto start = std::chrono::steady_clock::now();
    const Mask m = ossref::computeReferenceMask(*scene, c, directional({1, 0.3, 0.4}));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "computeReferenceMask 1024x768, 100352 triangles: " << ms << " ms" << std::endl;
    RecordProperty("reference_ms", std::to_string(ms));
    EXPECT_GT(m.count(0), 10000);
    EXPECT_GT(m.count(255), 10000);
}

} // namespace
