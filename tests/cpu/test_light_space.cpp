// Light-space fitting: frustum corners, depth ranges, the visible region and the fitted
// light frusta, against hand-derived values.
#include <osgShadowSilhouette/LightSpace>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace osgShadowSilhouette;

namespace {

osg::BoundingBoxd boxOf(const std::vector<osg::Vec3d>& points)
{
    osg::BoundingBoxd b;
    for (const osg::Vec3d& p : points) b.expandBy(p);
    return b;
}

std::vector<osg::Vec3d> square(double half, double z)
{
    return {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
}

void expectNear(const osg::Vec3d& a, const osg::Vec3d& b, double tol = 1e-9)
{
    EXPECT_NEAR(a.x(), b.x(), tol);
    EXPECT_NEAR(a.y(), b.y(), tol);
    EXPECT_NEAR(a.z(), b.z(), tol);
}

} // namespace

TEST(FrustumCorners, OrthographicIdentityView)
{
    const auto c = frustumCorners(osg::Matrixd(), osg::Matrixd::ortho(-1, 1, -2, 2, 1, 3));
    expectNear(c[0], {-1, -2, -1});
    expectNear(c[2], {1, 2, -1});
    expectNear(c[4], {-1, -2, -3});
    expectNear(c[6], {1, 2, -3});
}

TEST(FrustumCorners, PerspectiveNinetyDegrees)
{
    // fovy 90, aspect 1: at distance d the half extent is d.
    const auto c = frustumCorners(osg::Matrixd(), osg::Matrixd::perspective(90, 1, 1, 10));
    expectNear(c[0], {-1, -1, -1}, 1e-9);
    expectNear(c[6], {10, 10, -10}, 1e-7);
}

TEST(FrustumCorners, ViewMatrixIsUndone)
{
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 5), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const auto c = frustumCorners(view, osg::Matrixd::ortho(-1, 1, -1, 1, 1, 3));
    expectNear(c[0], {-1, -1, 4});
    expectNear(c[6], {1, 1, 2});
}

TEST(WithDepthRange, PerspectiveEqualsRebuiltMatrix)
{
    const osg::Matrixd p = withDepthRange(osg::Matrixd::perspective(60, 1.5, 1, 100), 2, 50);
    const osg::Matrixd q = osg::Matrixd::perspective(60, 1.5, 2, 50);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(p(i, j), q(i, j), 1e-12) << i << "," << j;
}

TEST(WithDepthRange, OrthographicEqualsRebuiltMatrix)
{
    const osg::Matrixd p = withDepthRange(osg::Matrixd::ortho(-1, 2, -3, 4, 1, 100), -5, 7);
    const osg::Matrixd q = osg::Matrixd::ortho(-1, 2, -3, 4, -5, 7);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(p(i, j), q(i, j), 1e-12) << i << "," << j;
}

TEST(VisibleRegion, FrustumInsideBoxKeepsItsCorners)
{
    const auto c = frustumCorners(osg::Matrixd(), osg::Matrixd::ortho(-1, 1, -1, 1, 1, 3));
    const osg::BoundingBoxd b = boxOf(visibleRegion(c, osg::BoundingBoxd(-10, -10, -10, 10, 10, 10)));
    expectNear(b._min, {-1, -1, -3});
    expectNear(b._max, {1, 1, -1});
}

TEST(VisibleRegion, BoxClipsTheFrustum)
{
    const auto c = frustumCorners(osg::Matrixd(), osg::Matrixd::ortho(-1, 1, -1, 1, 1, 3));
    const osg::BoundingBoxd b = boxOf(visibleRegion(c, osg::BoundingBoxd(0, -10, -2.5, 5, 0.5, 10)));
    expectNear(b._min, {0, -1, -2.5});
    expectNear(b._max, {1, 0.5, -1});
}

TEST(VisibleRegion, DisjointBoxGivesNothing)
{
    const auto c = frustumCorners(osg::Matrixd(), osg::Matrixd::ortho(-1, 1, -1, 1, 1, 3));
    EXPECT_TRUE(visibleRegion(c, osg::BoundingBoxd(5, 5, 5, 6, 6, 6)).empty());
    EXPECT_TRUE(visibleRegion(c, osg::BoundingBoxd()).empty());
}

TEST(VisibleRegion, PerspectiveClippedByGroundSlab)
{
    // Looking straight down from z = 10 with a 90 degree frustum onto the slab z in [0, 1]:
    // at depth 9..10 the half extent is 9..10.
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 10), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const auto c = frustumCorners(view, osg::Matrixd::perspective(90, 1, 0.5, 100));
    const osg::BoundingBoxd b = boxOf(visibleRegion(c, osg::BoundingBoxd(-100, -100, 0, 100, 100, 1)));
    expectNear(b._min, {-10, -10, 0}, 1e-6);
    expectNear(b._max, {10, 10, 1}, 1e-6);
}

TEST(FitDirectional, OverheadLightCoversCasterOverRegion)
{
    // Light straight above; a caster box over part of a 2x2 ground region.
    const std::vector<osg::Vec3d> region = square(1, 0);
    const osg::BoundingBoxd casters(-0.5, -0.5, 0, 0.5, 0.5, 2);
    const LightFrustum f = fitDirectionalFrustum({0, 0, 1}, region, casters, 256);
    ASSERT_TRUE(f.valid);
    EXPECT_FALSE(f.perspective);
    const osg::Matrixd t = f.worldToTexture();
    // The caster's footprint lies inside the map, the caster's top nearer than the ground.
    for (const osg::Vec3d& p : square(0.5, 0))
    {
        const osg::Vec3d q = p * t;
        EXPECT_GE(q.x(), 0.0);
        EXPECT_LE(q.x(), 1.0);
        EXPECT_GE(q.y(), 0.0);
        EXPECT_LE(q.y(), 1.0);
    }
    const double top = (osg::Vec3d(0, 0, 2) * t).z(), ground = (osg::Vec3d(0, 0, 0) * t).z();
    EXPECT_GT(top, -1e-9);
    EXPECT_LT(top, ground);
    EXPECT_LT(ground, 1.0 + 1e-9);
    // Shrunk to the casters: the map spans about the caster's 1 unit, not the region's 2.
    const double width = ((osg::Vec3d(1, 0, 0) * t) - (osg::Vec3d(0, 0, 0) * t)).length();
    EXPECT_GT(width, 0.9);
}

TEST(FitDirectional, CastersBesideTheRegionGiveNoPass)
{
    const LightFrustum f =
        fitDirectionalFrustum({0, 0, 1}, square(1, 0), osg::BoundingBoxd(5, 5, 0, 6, 6, 1), 256);
    EXPECT_FALSE(f.valid);
}

TEST(FitDirectional, EmptyInputsGiveNoPass)
{
    EXPECT_FALSE(fitDirectionalFrustum({0, 0, 1}, {}, osg::BoundingBoxd(0, 0, 0, 1, 1, 1), 256).valid);
    EXPECT_FALSE(fitDirectionalFrustum({0, 0, 1}, square(1, 0), osg::BoundingBoxd(), 256).valid);
    EXPECT_FALSE(fitDirectionalFrustum({0, 0, 0}, square(1, 0), osg::BoundingBoxd(0, 0, 0, 1, 1, 1), 256).valid);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(fitDirectionalFrustum({nan, 0, 1}, square(1, 0), osg::BoundingBoxd(0, 0, 0, 1, 1, 1), 256).valid);
}

TEST(FitDirectional, TexelGridStaysPutWhenTheViewMoves)
{
    // A fixed world point keeps its sub-texel position when the visible region slides by a
    // fraction of a texel (the extent stays the same): shadows do not swim.
    const unsigned int n = 512;
    const osg::BoundingBoxd casters(-50, -50, 0, 50, 50, 2);
    const osg::Vec3d probe(0.123, 0.456, 0);
    double first = -1.0;
    for (double shift : {0.0, 0.0017, 0.0031})
    {
        std::vector<osg::Vec3d> region = square(4, 0);
        for (osg::Vec3d& p : region) p.x() += shift;
        const LightFrustum f = fitDirectionalFrustum({0, 0, 1}, region, casters, n);
        ASSERT_TRUE(f.valid);
        const double u = (probe * f.worldToTexture()).x() * n;
        const double frac = u - std::floor(u);
        if (first < 0.0) first = frac;
        EXPECT_NEAR(frac, first, 1e-6) << "shift " << shift;
    }
}

TEST(FitPerspective, SpotLightEnclosesTheRegion)
{
    LightDescription spot;
    spot.type = LightDescription::SPOT;
    spot.position = {0, 0, 10};
    spot.spotDirection = {0, 0, -1};
    spot.spotCutoffDeg = 45;
    const LightFrustum f = fitPerspectiveFrustum(spot, square(1, 0), osg::BoundingBoxd(-1, -1, 0, 1, 1, 1));
    ASSERT_TRUE(f.valid);
    EXPECT_TRUE(f.perspective);
    const osg::Matrixd t = f.worldToTexture();
    for (const osg::Vec3d& p : square(1, 0))
    {
        const osg::Vec4d q = osg::Vec4d(p, 1.0) * t;
        EXPECT_GT(q.w(), 0.0);
        for (double v : {q.x() / q.w(), q.y() / q.w(), q.z() / q.w()})
        {
            EXPECT_GE(v, 0.0);
            EXPECT_LE(v, 1.0);
        }
    }
    // The square frustum needs tan(half angle) = 1/10 for the corners; the fit adds 1%.
    double fovy, aspect, zNear, zFar;
    ASSERT_TRUE(f.projection.getPerspective(fovy, aspect, zNear, zFar));
    EXPECT_NEAR(fovy, 2.0 * osg::RadiansToDegrees(std::atan(0.1 * 1.01)), 1e-9);
    EXPECT_NEAR(zFar, 10.0 * 1.01, 1e-9);
}

TEST(FitPerspective, ConeCapsTheFieldOfView)
{
    LightDescription spot;
    spot.type = LightDescription::SPOT;
    spot.position = {0, 0, 1};
    spot.spotDirection = {0, 0, -1};
    spot.spotCutoffDeg = 10;
    const LightFrustum f = fitPerspectiveFrustum(spot, square(100, 0), osg::BoundingBoxd(-1, -1, 0, 1, 1, 0.5));
    ASSERT_TRUE(f.valid);
    double fovy, aspect, zNear, zFar;
    ASSERT_TRUE(f.projection.getPerspective(fovy, aspect, zNear, zFar));
    EXPECT_NEAR(fovy, 20.0 * 1.02, 1e-6);
}

TEST(FitPerspective, RegionBehindTheLightGivesNoPass)
{
    LightDescription spot;
    spot.type = LightDescription::SPOT;
    spot.position = {0, 0, -5};
    spot.spotDirection = {0, 0, -1};
    spot.spotCutoffDeg = 30;
    EXPECT_FALSE(fitPerspectiveFrustum(spot, square(1, 0), osg::BoundingBoxd(-1, -1, 0, 1, 1, 1)).valid);
}

TEST(LightDescription, DirectionalRotatedByItsLightSource)
{
    osg::ref_ptr<osg::Light> lightPtr = new osg::Light(2);
    osg::Light& light = *lightPtr;
    light.setPosition(osg::Vec4(1, 0, 0, 0));
    LightDescription d;
    ASSERT_TRUE(LightDescription::fromLight(light, osg::Matrixd::rotate(osg::PI_2, osg::Vec3d(0, 0, 1)), d));
    EXPECT_EQ(d.type, LightDescription::DIRECTIONAL);
    EXPECT_EQ(d.lightNum, 2);
    expectNear(d.direction, {0, 1, 0}, 1e-12);
    EXPECT_EQ(d.homogeneous().w(), 0.0);
}

TEST(LightDescription, SteadiedAgainstTheLastFrameThroughAnotherView)
{
    // The technique finds a light as its position times the model-view matrix at its
    // LightSource times the inverse of the view's: every eye gives another rounding of the
    // same world light. steadied() against the last frame's description must not tell them
    // apart (or every pass drawn for the light would be drawn again each frame the eye
    // moves), and must follow a light that moves.
    osg::ref_ptr<osg::Light> sun = new osg::Light(0);
    sun->setPosition(osg::Vec4(0.7f, -0.2f, 0.3f, 0.0f));
    osg::ref_ptr<osg::Light> lamp = new osg::Light(1);
    lamp->setPosition(osg::Vec4(120.3f, -57.1f, 9.7f, 1.0f));
    lamp->setDirection(osg::Vec3(0.1f, 0.2f, -1.0f));
    lamp->setSpotCutoff(40.0f);
    LightDescription first[2], last[2];
    ASSERT_TRUE(LightDescription::fromLight(*sun, osg::Matrixd(), first[0]));
    ASSERT_TRUE(LightDescription::fromLight(*lamp, osg::Matrixd(), first[1]));
    last[0] = first[0], last[1] = first[1];
    unsigned int roundingsDiffer = 0;
    for (int k = 0; k < 40; ++k)
    {
        // A walk that turns: 5 cm and a tenth of a degree a frame.
        const osg::Vec3d eye(-40.0 + 0.05 * k, -420.0 + 0.037 * k, 1.45 + 0.003 * k);
        const double heading = osg::DegreesToRadians(44.0 + 0.1 * k);
        const osg::Matrixd view =
            osg::Matrixd::lookAt(eye, eye + osg::Vec3d(std::cos(heading), std::sin(heading), -0.06), {0, 0, 1});
        const osg::Matrixd lightToWorld = view * osg::Matrixd::inverse(view);
        LightDescription d[2];
        ASSERT_TRUE(LightDescription::fromLight(*sun, lightToWorld, d[0]));
        ASSERT_TRUE(LightDescription::fromLight(*lamp, lightToWorld, d[1]));
        roundingsDiffer += d[0].direction != first[0].direction || d[1].position != first[1].position ? 1 : 0;
        for (int i = 0; i < 2; ++i) last[i] = steadied(d[i], last[i]);
        EXPECT_EQ(last[0].direction, first[0].direction) << k;
        EXPECT_EQ(last[1].position, first[1].position) << k;
        EXPECT_EQ(last[1].spotDirection, first[1].spotDirection) << k;
    }
    EXPECT_GT(roundingsDiffer, 10u); // the case is not vacuous: most products are not exact

    // A light that moves, however little beyond rounding, is followed.
    LightDescription moved = first[0];
    moved.direction = osg::Vec3d(0.7, -0.2, 0.3 + 1e-9);
    moved.direction.normalize();
    EXPECT_EQ(steadied(moved, first[0]).direction, moved.direction);
    moved = first[1];
    moved.position += osg::Vec3d(0.0, 0.0, 1e-6);
    EXPECT_EQ(steadied(moved, first[1]).position, moved.position);
    moved = first[1];
    moved.spotCutoffDeg = 41.0;
    EXPECT_EQ(steadied(moved, first[1]).spotCutoffDeg, 41.0);
    moved.lightNum = 3;
    EXPECT_EQ(steadied(moved, first[1]).lightNum, 3);
}

TEST(LightDescription, PositionalDividesByWAndTranslates)
{
    osg::ref_ptr<osg::Light> lightPtr = new osg::Light;
    osg::Light& light = *lightPtr;
    light.setPosition(osg::Vec4(2, 4, 6, 2));
    LightDescription d;
    ASSERT_TRUE(LightDescription::fromLight(light, osg::Matrixd::translate(10, 0, 0), d));
    EXPECT_EQ(d.type, LightDescription::POINT);
    expectNear(d.position, {11, 2, 3});
}

TEST(LightDescription, SpotCutoffBelowNinetyMakesASpot)
{
    osg::ref_ptr<osg::Light> lightPtr = new osg::Light;
    osg::Light& light = *lightPtr;
    light.setPosition(osg::Vec4(0, 0, 5, 1));
    light.setDirection(osg::Vec3(0, 0, -2));
    light.setSpotCutoff(30);
    LightDescription d;
    ASSERT_TRUE(LightDescription::fromLight(light, osg::Matrixd(), d));
    EXPECT_EQ(d.type, LightDescription::SPOT);
    expectNear(d.spotDirection, {0, 0, -1});
    EXPECT_EQ(d.spotCutoffDeg, 30);
}

TEST(LightDescription, NonFiniteLightIsRefused)
{
    osg::ref_ptr<osg::Light> lightPtr = new osg::Light;
    osg::Light& light = *lightPtr;
    light.setPosition(osg::Vec4(std::numeric_limits<float>::quiet_NaN(), 0, 1, 0));
    LightDescription d;
    d.lightNum = 7;
    EXPECT_FALSE(LightDescription::fromLight(light, osg::Matrixd(), d));
    EXPECT_EQ(d.lightNum, 7); // untouched
    light.setPosition(osg::Vec4(0, 0, 0, 0));
    EXPECT_FALSE(LightDescription::fromLight(light, osg::Matrixd(), d));
}

TEST(LightDescription, RefusalNamesTheValue)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    osg::ref_ptr<osg::Light> light = new osg::Light;
    LightDescription d;
    std::string why;
    light->setPosition(osg::Vec4(1, nan, 6, 1));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), d, &why));
    EXPECT_EQ(why, "position (1, nan, 6, 1)");
    light->setPosition(osg::Vec4(0, 0, 0, 0));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), d, &why));
    EXPECT_EQ(why, "position (0, 0, 0, 0), a direction of length 0");
    light->setPosition(osg::Vec4(0, 0, 5, 1));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd::scale(1, 1, std::numeric_limits<double>::infinity()), d, &why));
    EXPECT_EQ(why, "position (0, 0, 5, 1) placed by a non-finite transform");
    // A spot direction counts where OpenGL reads it: spot cutoffs 0 to 90.
    light->setDirection(osg::Vec3(0, nan, -1));
    light->setSpotCutoff(90);
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), d, &why));
    EXPECT_EQ(why, "spot direction (0, nan, -1)");
    light->setSpotCutoff(180);
    why.clear();
    ASSERT_TRUE(LightDescription::fromLight(*light, osg::Matrixd(), d, &why));
    EXPECT_EQ(d.type, LightDescription::POINT);
    EXPECT_EQ(why, "");
}

namespace {

/** A box region: the corners of [-h, h]^2 x [0, top]. */
std::vector<osg::Vec3d> boxRegion(double h, double top)
{
    std::vector<osg::Vec3d> r = square(h, 0.0);
    for (const osg::Vec3d& p : square(h, top)) r.push_back(p);
    return r;
}

LightDescription spotAt(const osg::Vec3d& position, const osg::Vec3d& axis, double cutoffDeg)
{
    LightDescription d;
    d.type = LightDescription::SPOT;
    d.position = position;
    d.spotDirection = axis;
    d.spotDirection.normalize();
    d.spotCutoffDeg = cutoffDeg;
    return d;
}

} // namespace

TEST(LightReach, DirectionalAndUnattenuatedLightsReachAnyRegion)
{
    LightDescription sun;
    EXPECT_TRUE(lightReachesRegion(sun, boxRegion(10, 2)));
    LightDescription point;
    point.type = LightDescription::POINT;
    point.position = osg::Vec3d(0, 0, 1000);
    EXPECT_TRUE(lightReachesRegion(point, boxRegion(10, 2)));
    EXPECT_FALSE(lightReachesRegion(point, {})) << "an empty region is reached by nothing";
}

TEST(LightReach, SpotAimingAwayMissesTheRegion)
{
    const std::vector<osg::Vec3d> region = boxRegion(10, 4);
    EXPECT_FALSE(lightReachesRegion(spotAt({2, -1, 8}, {0.05, 0.1, 1}, 30), region)) << "above the region, aiming up";
    EXPECT_TRUE(lightReachesRegion(spotAt({2, -1, 8}, {0, 0, -1}, 30), region)) << "aiming down at it";
    EXPECT_FALSE(lightReachesRegion(spotAt({50, 0, 5}, {1, 0, 0}, 60), region)) << "beside it, aiming away";
    EXPECT_TRUE(lightReachesRegion(spotAt({50, 0, 5}, {0, 1, 0}, 89), region)) << "a wide cone sideways grazes it";
    EXPECT_FALSE(lightReachesRegion(spotAt({0, 200, 5}, {0, 0, -1}, 20), region)) << "far away, down";
}

TEST(LightReach, AttenuationRangeEndsBeforeTheRegion)
{
    osg::ref_ptr<osg::Light> lightRef = new osg::Light(0);
    osg::Light& light = *lightRef;
    light.setPosition(osg::Vec4(0, 0, 60, 1));
    light.setAmbient(osg::Vec4(0.2f, 0.2f, 0.2f, 1));
    light.setDiffuse(osg::Vec4(0.8f, 0.8f, 0.8f, 1));
    light.setSpecular(osg::Vec4(0.3f, 0.3f, 0.3f, 1));
    light.setQuadraticAttenuation(0.5f);
    LightDescription d;
    ASSERT_TRUE(LightDescription::fromLight(light, osg::Matrixd(), d));
    // 1 / (1 + 0.5 d^2) * 0.8 = 1/512  ->  d = sqrt((512 * 0.8 - 1) / 0.5)
    EXPECT_NEAR(d.range, std::sqrt((512.0 * 0.8 - 1.0) / 0.5), 1e-4);
    EXPECT_FALSE(lightReachesRegion(d, boxRegion(10, 4)));
    d.position = osg::Vec3d(0, 0, 30);
    EXPECT_TRUE(lightReachesRegion(d, boxRegion(10, 4)));
    light.setQuadraticAttenuation(0.0f);
    ASSERT_TRUE(LightDescription::fromLight(light, osg::Matrixd(), d));
    EXPECT_TRUE(std::isinf(d.range));
}

TEST(CubeFaces, LightAmidTheRegionNeedsFaces)
{
    LightDescription point;
    point.type = LightDescription::POINT;
    point.position = osg::Vec3d(0, 0, 1);
    EXPECT_TRUE(needsCubeFaces(point, boxRegion(10, 4))) << "inside the region";
    point.position = osg::Vec3d(0, 0, 60);
    EXPECT_FALSE(needsCubeFaces(point, boxRegion(10, 4))) << "far above it: one frustum";
    LightDescription spot = spotAt({0, 0, 1}, {0, 0, -1}, 40);
    EXPECT_FALSE(needsCubeFaces(spot, boxRegion(10, 4))) << "spots keep their cone";
}

TEST(CubeFaces, FaceFovLeavesAMarginOfTexels)
{
    const double fov = cubeFaceFov(512, 4.0);
    EXPECT_GT(fov, 90.0);
    EXPECT_LT(fov, 92.0);
    // The 90-degree square ends 4 texels inside the map: 0.5 / tan(fov / 2) = 0.5 - 4 / 512.
    EXPECT_NEAR(0.5 / std::tan(osg::DegreesToRadians(fov / 2)), 0.5 - 4.0 / 512, 1e-12);
    EXPECT_LE(cubeFaceFov(1, 4.0), 2.0 * osg::RadiansToDegrees(std::atan(1.25)) + 1e-9) << "capped for tiny maps";
}

// canShadow(): a flat caster shadows nothing on the light's side of its plane.
TEST(CubeFaces, AFlatCasterShadowsOnlyBeyondItsPlane)
{
    LightDescription point;
    point.type = LightDescription::POINT;
    point.position = osg::Vec3d(0, 0, 8);
    CasterPart ground;
    ground.box = osg::BoundingBoxd(-20, -20, 0, 20, 20, 0);
    ground.flat = true;
    ground.planePoint = osg::Vec3d(3, 4, 0);
    ground.planeNormal = osg::Vec3d(0, 0, -1); // either orientation
    const osg::BoundingBoxd standing(-20, -20, 0, 20, 20, 3); // every receiver on or above it
    EXPECT_FALSE(canShadow(point, ground, standing));
    ground.planeNormal = osg::Vec3d(0, 0, 1);
    EXPECT_FALSE(canShadow(point, ground, standing));
    EXPECT_TRUE(canShadow(point, ground, osg::BoundingBoxd(-20, -20, -1, 20, 20, 3))) << "a receiver below it";
    point.position = osg::Vec3d(0, 0, -8);
    EXPECT_TRUE(canShadow(point, ground, standing)) << "the light below, the receivers beyond";
    point.position = osg::Vec3d(30, 0, 0);
    EXPECT_TRUE(canShadow(point, ground, standing)) << "the light in the plane: kept";
    point.position = osg::Vec3d(0, 0, 8);
    CasterPart box = ground;
    box.flat = false;
    box.box = osg::BoundingBoxd(-1, -1, 0, 1, 1, 2);
    EXPECT_TRUE(canShadow(point, box, standing));
    EXPECT_FALSE(canShadow(point, CasterPart(), standing)) << "no box: nothing";
}

// A point light 8 above a ground (casting, flat) with a box under it: the casters' box
// (ground and box) meets the four side faces and -z, the box alone only -z.
TEST(CubeFaces, FacesMeetingNoCasterPartAreLeftOut)
{
    LightDescription point;
    point.type = LightDescription::POINT;
    point.position = osg::Vec3d(0, 0, 8);
    const osg::BoundingBoxd casters(-20, -20, 0, 20, 20, 2);
    const std::vector<osg::Vec3d> region = boxRegion(20, 0.1);
    EXPECT_EQ(fitCubeFaces(point, region, casters, 512).size(), 5u) << "+-x, +-y and -z";
    const std::vector<osg::BoundingBoxd> box = {osg::BoundingBoxd(-1, -1, 0, 1, 1, 2)};
    const std::vector<LightFrustum> faces = fitCubeFaces(point, region, casters, 512, &box);
    ASSERT_EQ(faces.size(), 1u);
    const osg::Vec3d down = osg::Vec3d(0, 0, -1) * osg::Matrixd::inverse(faces[0].view) - point.position;
    EXPECT_NEAR(down.z(), -1.0, 1e-9) << "the face looking down";
    // Boxes in two side faces: those two.
    const std::vector<osg::BoundingBoxd> sides = {osg::BoundingBoxd(15, -1, 0, 16, 1, 2),
                                                  osg::BoundingBoxd(-1, -16, 0, 1, -15, 2)};
    EXPECT_EQ(fitCubeFaces(point, region, casters, 512, &sides).size(), 2u);
    const std::vector<osg::BoundingBoxd> none;
    EXPECT_TRUE(fitCubeFaces(point, region, casters, 512, &none).empty());
}

TEST(CubeFaces, LightInsideARingKeepsTheFacesThatSeeCastersOverTheRegion)
{
    LightDescription point;
    point.type = LightDescription::POINT;
    point.position = osg::Vec3d(0, 0, 1);
    // The ring's box reaches z = 2; the region is the ground slab around the light.
    const osg::BoundingBoxd ring(-4, -4, 0, 4, 4, 2);
    const std::vector<LightFrustum> faces = fitCubeFaces(point, boxRegion(10, 0.1), ring, 512);
    ASSERT_EQ(faces.size(), 5u) << "+x, -x, +y, -y and -z; +z sees neither region nor casters above the light";
    for (const LightFrustum& f : faces)
    {
        EXPECT_TRUE(f.valid && f.perspective);
        EXPECT_NEAR(f.faceCore, 0.5 - 4.0 / 512, 1e-9);
        // The light's own position maps to the face's eye origin.
        expectNear(point.position * f.view, osg::Vec3d(), 1e-9);
    }
    // Every direction from the light lands in the own square of exactly one face (or on a
    // border between two), inside that face's map.
    for (const osg::Vec3d& d : {osg::Vec3d(1, 0.3, -0.2), osg::Vec3d(-0.2, -1, -0.9), osg::Vec3d(0.1, 0.2, -1)})
    {
        int owners = 0;
        for (const LightFrustum& f : faces)
        {
            const osg::Vec3d t = (point.position + d) * f.worldToTexture();
            const osg::Vec4d h = osg::Vec4d(point.position + d, 1.0) * f.view * f.projection;
            if (h.w() > 0 && std::fabs(t.x() - 0.5) <= f.faceCore && std::fabs(t.y() - 0.5) <= f.faceCore) ++owners;
        }
        EXPECT_EQ(owners, 1) << d.x() << " " << d.y() << " " << d.z();
    }
}
