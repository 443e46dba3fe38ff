// The perspective-warped directional frustum (fitWarpedDirectionalFrustum()): what it covers,
// that the light's rays stay the map's depth axis, where its texels are small, and that its
// texel grid holds still while the eye moves a little.
#include <osgShadowSilhouette/LightSpace>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace osgShadowSilhouette;

namespace {

const unsigned int MAP = 2048;
const osg::BoundingBoxd GROUND(-600, -600, 0, 600, 600, 20); // receivers and casters: a 1.2 km field, 20 m high
const osg::Vec3d TOWARD_SUN = [] {
    osg::Vec3d d(1.0, -0.2, 0.21); // low, from the east
    d.normalize();
    return d;
}();

/** An eye 1.7 m above the ground at (x, y) looking along heading (degrees from +y toward +x),
 *  2.5 degrees down; fovy 50, 4:3, out to 1100 m. */
struct Eye
{
    osg::Vec3d position, direction;
    std::vector<osg::Vec3d> region;
};

Eye eyeAt(double x, double y, double headingDeg)
{
    Eye e;
    const double h = osg::DegreesToRadians(headingDeg), down = osg::DegreesToRadians(2.5);
    e.position = {x, y, 1.7};
    e.direction = {std::sin(h) * std::cos(down), std::cos(h) * std::cos(down), -std::sin(down)};
    const osg::Matrixd view = osg::Matrixd::lookAt(e.position, e.position + e.direction, {0, 0, 1});
    e.region = visibleRegion(frustumCorners(view, osg::Matrixd::perspective(50, 4.0 / 3.0, 0.5, 1100)), GROUND);
    return e;
}

LightFrustum warped(const Eye& e)
{
    return fitWarpedDirectionalFrustum(TOWARD_SUN, e.region, GROUND, MAP, e.position, e.direction);
}

osg::Vec3d texture(const LightFrustum& f, const osg::Vec3d& p)
{
    const osg::Vec4d q = osg::Vec4d(p, 1.0) * f.worldToTexture();
    EXPECT_GT(q.w(), 0.0);
    return {q.x() / q.w(), q.y() / q.w(), q.z() / q.w()};
}

/** Texels of the map per metre along the ground's x axis at p. */
double texelsPerMetre(const LightFrustum& f, const osg::Vec3d& p)
{
    const double h = 1e-3;
    const osg::Vec3d a = texture(f, p), b = texture(f, p + osg::Vec3d(h, 0, 0)), c = texture(f, p + osg::Vec3d(0, h, 0));
    return MAP * std::max(std::hypot(b.x() - a.x(), b.y() - a.y()), std::hypot(c.x() - a.x(), c.y() - a.y())) / h;
}

double fraction(double v)
{
    return v - std::floor(v);
}

/** Whether every point of @p e's region (and the top of the casters' box toward the sun
 *  above it) lies inside @p f's map and depth range. */
bool holdsRegion(const LightFrustum& f, const Eye& e)
{
    for (const osg::Vec3d& p : e.region)
    {
        const osg::Vec3d top = p + TOWARD_SUN * ((GROUND.zMax() - p.z()) / TOWARD_SUN.z());
        for (const osg::Vec3d& q : {p, top})
        {
            const osg::Vec3d t = texture(f, q);
            for (int i = 0; i < 3; ++i)
                if (!(t[i] >= 0.0 && t[i] <= 1.0)) return false;
        }
    }
    return true;
}

} // namespace

TEST(WarpedFrustum, HoldsTheRegionAndWhatCanShadowIt)
{
    const Eye e = eyeAt(10, -300, 20);
    const LightFrustum f = warped(e);
    ASSERT_TRUE(f.valid);
    ASSERT_TRUE(f.warped);
    ASSERT_FALSE(e.region.empty());
    for (const osg::Vec3d& p : e.region)
    {
        // Every point the view sees, and the top of the casters' box on the way to the sun
        // (the nearest caster that can shadow it), fall inside the map and its depth range;
        // both on one texel: the sun's rays are the map's depth axis, as in a uniform map.
        const osg::Vec3d top = p + TOWARD_SUN * ((GROUND.zMax() - p.z()) / TOWARD_SUN.z());
        const osg::Vec3d a = texture(f, p), b = texture(f, top);
        for (const osg::Vec3d& t : {a, b})
            for (int i = 0; i < 3; ++i)
            {
                EXPECT_GE(t[i], 0.0) << i;
                EXPECT_LE(t[i], 1.0) << i;
            }
        EXPECT_NEAR(a.x() * MAP, b.x() * MAP, 1e-6);
        EXPECT_NEAR(a.y() * MAP, b.y() * MAP, 1e-6);
        if (top.z() > p.z() + 1.0)
        {
            EXPECT_LT(b.z(), a.z()); // nearer the sun: a smaller depth
        }
    }
}

TEST(WarpedFrustum, TexelsAreSmallNearTheEyeAndLargeFarAway)
{
    const Eye e = eyeAt(10, -300, 20);
    const LightFrustum f = warped(e);
    const LightFrustum uniform = fitDirectionalFrustum(TOWARD_SUN, e.region, GROUND, MAP);
    ASSERT_TRUE(f.valid && uniform.valid);
    const osg::Vec3d near = e.position + osg::Vec3d(e.direction.x(), e.direction.y(), 0) * 6.0 - osg::Vec3d(0, 0, 1.7);
    const osg::Vec3d far = e.position + osg::Vec3d(e.direction.x(), e.direction.y(), 0) * 800.0 - osg::Vec3d(0, 0, 1.7);
    const double flat = texelsPerMetre(uniform, near);
    EXPECT_NEAR(texelsPerMetre(uniform, far), flat, 1e-3 * flat);
    // 1.5 texels per metre in the uniform map; the warp puts more than 10 times as many 6 m
    // ahead of the eye, and fewer 800 m away.
    EXPECT_GT(texelsPerMetre(f, near), 10.0 * flat);
    EXPECT_LT(texelsPerMetre(f, far), flat);
}

TEST(WarpedFrustum, TexelGridHoldsStillWhileTheEyeMovesALittle)
{
    // A world point keeps its position within its texel while the eye walks 5 cm and turns
    // by a tenth of a degree (the map may slide by whole texels): the warp's axis, centre and
    // texel sizes move in steps.
    const osg::Vec3d probe(40.123, -210.456, 0.0);
    const LightFrustum f0 = warped(eyeAt(10, -300, 20));
    ASSERT_TRUE(f0.valid && f0.warped);
    const osg::Vec3d t0 = texture(f0, probe) * MAP;
    for (const Eye& e : {eyeAt(10.02, -299.95, 20), eyeAt(10, -300, 20.1), eyeAt(10.03, -299.96, 19.95)})
    {
        const LightFrustum f = warped(e);
        ASSERT_TRUE(f.valid && f.warped);
        const osg::Vec3d t = texture(f, probe) * MAP;
        EXPECT_NEAR(fraction(t.x()), fraction(t0.x()), 1e-6);
        EXPECT_NEAR(fraction(t.y()), fraction(t0.y()), 1e-6);
    }
    // A walk of 30 m moves the grid (the test above is not vacuous).
    const osg::Vec3d moved = texture(warped(eyeAt(10, -270, 20)), probe) * MAP;
    EXPECT_GT(std::hypot(fraction(moved.x()) - fraction(t0.x()), fraction(moved.y()) - fraction(t0.y())), 0.01);
}

TEST(WarpedFrustum, KeepsItsFitWhileTheEyeWalksWithinAStep)
{
    // The eye walks 5 cm a frame along its heading, turning 0.2 degrees: a frustum kept from an
    // earlier frame (keepsWarpedFit()) holds every later frame's region, at most one texel
    // step coarser, and is kept for most frames; a fresh fit takes over when it is not.
    LightFrustum kept = warped(eyeAt(10, -300, 20));
    ASSERT_TRUE(kept.valid && kept.warped);
    unsigned int keptFrames = 0;
    const unsigned int frames = 60;
    for (unsigned int i = 1; i <= frames; ++i)
    {
        const double heading = 20.0 + 0.2 * i, walked = 0.05 * i;
        const Eye e = eyeAt(10 + walked * std::sin(osg::DegreesToRadians(20.0)),
                            -300 + walked * std::cos(osg::DegreesToRadians(20.0)), heading);
        const LightFrustum fresh = warped(e);
        ASSERT_TRUE(fresh.valid && fresh.warped);
        ASSERT_TRUE(holdsRegion(fresh, e));
        if (!keepsWarpedFit(kept, fresh))
        {
            kept = fresh;
            continue;
        }
        ++keptFrames;
        EXPECT_TRUE(holdsRegion(kept, e)) << "frame " << i;
        const auto width = [](const osg::Vec2d& w) { return w.y() - w.x(); };
        EXPECT_LE(width(kept.warpFit.windowS), 1.0443 * width(fresh.warpFit.windowS)) << "frame " << i;
        EXPECT_LE(width(kept.warpFit.windowT), 1.0443 * width(fresh.warpFit.windowT)) << "frame " << i;
    }
    EXPECT_GE(keptFrames, frames / 2);

    // Not kept: after a walk of 30 m (another centre), or turned by 20 degrees (another axis).
    const LightFrustum start = warped(eyeAt(10, -300, 20));
    EXPECT_FALSE(keepsWarpedFit(start, warped(eyeAt(10, -270, 20))));
    EXPECT_FALSE(keepsWarpedFit(start, warped(eyeAt(10, -300, 40))));
    EXPECT_TRUE(keepsWarpedFit(start, start));
    EXPECT_FALSE(keepsWarpedFit(start, fitDirectionalFrustum(TOWARD_SUN, eyeAt(10, -300, 20).region, GROUND, MAP)));
}

TEST(WarpedFrustum, LookingAlongTheLightKeepsTheUniformMap)
{
    // Looking toward the sun (within 10 degrees of its direction) a warp gains nothing.
    Eye e = eyeAt(0, 0, 0);
    e.direction = -TOWARD_SUN;
    const osg::Matrixd view = osg::Matrixd::lookAt(e.position, e.position + e.direction, {0, 0, 1});
    e.region = visibleRegion(frustumCorners(view, osg::Matrixd::perspective(50, 4.0 / 3.0, 0.5, 1100)), GROUND);
    const LightFrustum f = warped(e);
    const LightFrustum uniform = fitDirectionalFrustum(TOWARD_SUN, e.region, GROUND, MAP);
    ASSERT_TRUE(f.valid);
    EXPECT_FALSE(f.warped);
    EXPECT_EQ(f.projection, uniform.projection);
    EXPECT_EQ(f.view, uniform.view);
}

TEST(WarpedFrustum, NonFiniteEyeKeepsTheUniformMap)
{
    Eye e = eyeAt(10, -300, 20);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int which = 0; which < 2; ++which)
    {
        const osg::Vec3d position = which == 0 ? osg::Vec3d(nan, 0, 1) : e.position;
        const osg::Vec3d direction = which == 1 ? osg::Vec3d(0, nan, 0) : e.direction;
        const LightFrustum f = fitWarpedDirectionalFrustum(TOWARD_SUN, e.region, GROUND, MAP, position, direction);
        ASSERT_TRUE(f.valid);
        EXPECT_FALSE(f.warped);
        EXPECT_FALSE(f.projection.isNaN());
    }
}

TEST(CascadeSplits, MixTheLogarithmicAndTheUniformSplits)
{
    // [1, 1000] in three: logarithmic 1, 10, 100, 1000; uniform 1, 334, 667, 1000.
    const std::vector<double> log = cascadeSplits(1.0, 1000.0, 3, 1.0);
    const std::vector<double> uniform = cascadeSplits(1.0, 1000.0, 3, 0.0);
    const std::vector<double> mixed = cascadeSplits(1.0, 1000.0, 3, 0.9);
    ASSERT_EQ(log.size(), 4u);
    for (int i = 0; i < 4; ++i)
    {
        EXPECT_NEAR(log[i], std::pow(10.0, i), 1e-9);
        EXPECT_NEAR(uniform[i], 1.0 + 333.0 * i, 1e-9);
        EXPECT_NEAR(mixed[i], 0.9 * log[i] + 0.1 * uniform[i], 1e-9);
    }
    // A near plane millimetres away counts as zFar / 1000 inside; the ends stay.
    const std::vector<double> eyeHeight = cascadeSplits(1e-4, 1000.0, 3, 1.0);
    EXPECT_EQ(eyeHeight.front(), 1e-4);
    EXPECT_NEAR(eyeHeight[1], 10.0, 1e-9);
    EXPECT_NEAR(eyeHeight[2], 100.0, 1e-9);
    EXPECT_EQ(eyeHeight.back(), 1000.0);
    EXPECT_EQ(cascadeSplits(2.0, 8.0, 1), (std::vector<double>{2.0, 8.0}));
}
