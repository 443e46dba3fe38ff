// Which lights get a shadow, in which slots, with which frusta (LightPlanning.h): cases
// derived by hand from the properties (LightNum, MaxShadowLights, the mode's slots) and the
// lights' reach, with the warnings each case raises.
#include <gtest/gtest.h>

#include "osgShadowSilhouette/LightPlanning.h"

#include <limits>
#include <map>

namespace {

namespace oss = osgShadowSilhouette;
using oss::LightDescription;
using oss::detail::FoundLight;
using oss::detail::FrameContext;
using oss::detail::SlotBudget;
using oss::detail::SlotPlan;

/** A 10 x 10 ground at z = 0 with a 2 x 2 x 2 box on it, the whole of it visible. */
FrameContext groundWithBox()
{
    FrameContext frame;
    frame.receivers = osg::BoundingBoxd(-5, -5, 0, 5, 5, 2);
    frame.casters = osg::BoundingBoxd(-1, -1, 0, 1, 1, 2);
    for (unsigned int i = 0; i < 8; ++i) frame.region.push_back(frame.receivers.corner(i));
    return frame;
}

/** The same, with casters all over the ground (a field of boxes): around a point light among
 *  them, every direction but straight up has something to shadow. */
FrameContext fieldOfBoxes()
{
    FrameContext frame = groundWithBox();
    frame.casters = frame.receivers;
    return frame;
}

/** A 200 x 200 ground, 5 high, casters all over it, seen from 1.7 above it at its south edge
 *  looking north: 0.5 to 150 deep, fovy 50, 4:3. */
FrameContext viewAcrossAField()
{
    FrameContext frame;
    frame.receivers = osg::BoundingBoxd(-100, -100, 0, 100, 100, 5);
    frame.casters = frame.receivers;
    frame.view.valid = true;
    frame.view.view = osg::Matrixd::lookAt(osg::Vec3d(0, -95, 1.7), osg::Vec3d(0, 0, 1.7), osg::Vec3d(0, 0, 1));
    frame.view.projection = osg::Matrixd::perspective(50, 4.0 / 3.0, 0.5, 150);
    frame.region = oss::visibleRegion(oss::frustumCorners(frame.view.view, frame.view.projection), frame.receivers);
    return frame;
}

FoundLight directional(int num, const osg::Vec3d& towardLight)
{
    FoundLight l;
    l.description.type = LightDescription::DIRECTIONAL;
    l.description.lightNum = num;
    l.description.direction = towardLight / towardLight.length();
    return l;
}

FoundLight point(int num, const osg::Vec3d& position)
{
    FoundLight l;
    l.description.type = LightDescription::POINT;
    l.description.lightNum = num;
    l.description.position = position;
    return l;
}

FoundLight spot(int num, const osg::Vec3d& position, const osg::Vec3d& axis, double cutoffDeg)
{
    FoundLight l = point(num, position);
    l.description.type = LightDescription::SPOT;
    l.description.spotDirection = axis / axis.length();
    l.description.spotCutoffDeg = cutoffDeg;
    return l;
}

/** Plans the slots, counting the warnings raised by key. */
struct Planned
{
    SlotPlan plan;
    unsigned int skipped = 0;
    std::map<int, int> warnings;
    int warned(int key) const
    {
        const auto it = warnings.find(key);
        return it == warnings.end() ? 0 : it->second;
    }
};

Planned plan(const FrameContext& frame, const std::vector<FoundLight>& lights, const SlotBudget& budget)
{
    Planned p;
    p.plan = oss::detail::planSlots(
        frame, lights, budget, [&](int key, const std::string&) { ++p.warnings[key]; }, p.skipped);
    return p;
}

} // namespace

TEST(LightPlanning, TheFirstMaxShadowLightsCastTheRestWarnOnce)
{
    SlotBudget budget;
    budget.maxShadowLights = 2;
    const Planned p = plan(groundWithBox(),
                           {directional(0, {0, 0, 1}), directional(1, {1, 0, 1}), directional(2, {0, 1, 1})}, budget);
    EXPECT_EQ(p.plan.slots, (std::vector<int>{0, 1, -1}));
    EXPECT_EQ(p.plan.slotsInUse, 2u);
    EXPECT_EQ(p.warned(oss::detail::WARN_OVER_BUDGET), 1);
    EXPECT_EQ(p.skipped, 0u);
    ASSERT_EQ(p.plan.frusta[0].size(), 1u);
    EXPECT_TRUE(p.plan.frusta[0][0].valid);
    EXPECT_FALSE(p.plan.frusta[0][0].perspective);
    EXPECT_TRUE(p.plan.frusta[2].empty()); // unshadowed: no frustum
}

TEST(LightPlanning, LightNumCastsAloneInTheFirstSlot)
{
    SlotBudget budget;
    budget.lightNum = 2;
    const Planned p = plan(groundWithBox(),
                           {directional(0, {0, 0, 1}), directional(1, {1, 0, 1}), directional(2, {0, 1, 1})}, budget);
    EXPECT_EQ(p.plan.slots, (std::vector<int>{-1, -1, 0}));
    EXPECT_EQ(p.plan.slotsInUse, 1u);
    EXPECT_TRUE(p.warnings.empty());
}

TEST(LightPlanning, ASpotLightPointingAwayIsSkippedAndTakesNoSlot)
{
    // The spot light above the scene looks straight up, its 30 degree cone away from every
    // receiver: it is skipped, and the next light takes slot 0.
    const Planned p =
        plan(groundWithBox(), {spot(0, {0, 0, 10}, {0, 0, 1}, 30.0), directional(1, {0, 0, 1})}, SlotBudget());
    EXPECT_EQ(p.plan.slots, (std::vector<int>{-1, 0}));
    EXPECT_EQ(p.skipped, 1u);
    // Pointing down at the scene, it casts: a perspective map in slot 0.
    const Planned down = plan(groundWithBox(), {spot(0, {0, 0, 10}, {0, 0, -1}, 30.0)}, SlotBudget());
    EXPECT_EQ(down.plan.slots, (std::vector<int>{0}));
    EXPECT_EQ(down.skipped, 0u);
    ASSERT_EQ(down.plan.frusta[0].size(), 1u);
    EXPECT_TRUE(down.plan.frusta[0][0].perspective);
}

TEST(LightPlanning, APointLightAmongItsCastersTakesCubeFacesAfterTheLightsSlots)
{
    // A point light among the boxes, 1 above the ground, sees receivers and casters in every
    // direction: cube faces. Its first face keeps its own slot 0, the directional light takes
    // slot 1, and the further faces take the slots from 2 on.
    SlotBudget budget;
    budget.slotLimit = 12;
    const Planned p = plan(fieldOfBoxes(), {point(0, {0, 0, 1}), directional(1, {0, 0, 1})}, budget);
    EXPECT_EQ(p.plan.slots, (std::vector<int>{0, 1}));
    const std::size_t faces = p.plan.frusta[0].size();
    ASSERT_GE(faces, 2u);
    ASSERT_LE(faces, 6u);
    for (const oss::LightFrustum& f : p.plan.frusta[0]) EXPECT_GT(f.faceCore, 0.0);
    EXPECT_EQ(p.plan.firstFaceSlot[0], 2u);
    EXPECT_EQ(p.plan.slotsInUse, 2u + (faces - 1));
    EXPECT_TRUE(p.warnings.empty());
}

TEST(LightPlanning, CubeFacesThatDoNotFitGiveOnePerspectiveMapAndAWarning)
{
    SlotBudget budget;
    budget.slotLimit = 2; // a light's own slot and one more: not enough for its faces
    const Planned p = plan(fieldOfBoxes(), {point(0, {0, 0, 1})}, budget);
    ASSERT_EQ(p.plan.frusta[0].size(), 1u);
    EXPECT_EQ(p.plan.frusta[0][0].faceCore, 0.0);
    EXPECT_TRUE(p.plan.frusta[0][0].perspective);
    EXPECT_EQ(p.plan.slotsInUse, 1u);
    EXPECT_EQ(p.warned(oss::detail::WARN_FACE_SLOTS), 1);
}

TEST(LightPlanning, WithoutCubeFacesAPointLightHasOneFrustum)
{
    SlotBudget budget;
    budget.slotLimit = 12;
    budget.cubeFaces = false; // SHADOW_VOLUME: the volumes need no map
    const Planned p = plan(fieldOfBoxes(), {point(0, {0, 0, 1})}, budget);
    EXPECT_EQ(p.plan.frusta[0].size(), 1u);
    EXPECT_EQ(p.plan.slotsInUse, 1u);
}

TEST(LightPlanning, APointLightOverAGroundAloneHasNothingToShadow)
{
    // The only caster is the ground itself, and every receiver stands on or above it: the
    // light is lit unshadowed (one invalid frustum), in its slot.
    FrameContext frame = groundWithBox();
    oss::CasterPart ground;
    ground.box = osg::BoundingBoxd(-5, -5, 0, 5, 5, 0);
    ground.flat = true;
    ground.planePoint = osg::Vec3d(0, 0, 0);
    ground.planeNormal = osg::Vec3d(0, 0, 1);
    frame.casterParts = {ground};
    SlotBudget budget;
    budget.slotLimit = 12;
    const Planned p = plan(frame, {point(0, {2, 0, 1})}, budget);
    ASSERT_EQ(p.plan.frusta[0].size(), 1u);
    EXPECT_FALSE(p.plan.frusta[0][0].valid);
    EXPECT_EQ(p.plan.slots, (std::vector<int>{0}));
}

TEST(LightPlanning, MissingLightNumAndDebugLightWarnNamingTheLights)
{
    std::map<int, std::string> said;
    const auto warn = [&](int key, const std::string& message) { said[key] = message; };
    oss::detail::warnAboutMissingLights({directional(0, {0, 0, 1}), directional(3, {0, 0, 1})}, 2, true, 5, warn);
    ASSERT_EQ(said.size(), 2u);
    EXPECT_NE(said[oss::detail::WARN_LIGHT_NUM].find("LightNum 2 names no light (the view's GL lights are 0, 3)"),
              std::string::npos)
        << said[oss::detail::WARN_LIGHT_NUM];
    EXPECT_NE(said[oss::detail::WARN_DEBUG_LIGHT].find("DebugLight 5 is not a light of the view (2 found"),
              std::string::npos)
        << said[oss::detail::WARN_DEBUG_LIGHT];
    said.clear();
    oss::detail::warnAboutMissingLights({directional(0, {0, 0, 1})}, 0, false, 5, warn); // no debug view
    EXPECT_TRUE(said.empty());
}

TEST(LightPlanning, ADirectionalLightTakesOneSlotPerCascade)
{
    // Three cascades of the first light: its own slot 0, the second light slot 1, the further
    // cascades slots 2 and 3. Their view depths follow cascadeSplits() over the region's depth
    // range and cover [0, inf) without a gap; each holds its part of the region, with
    // smaller texels than the next.
    SlotBudget budget;
    budget.slotLimit = 12;
    budget.cascades = 3;
    const FrameContext frame = viewAcrossAField();
    const Planned p = plan(frame, {directional(0, {1, 0.2, 0.5}), directional(1, {0, -1, 1})}, budget);
    EXPECT_EQ(p.plan.slots, (std::vector<int>{0, 1}));
    ASSERT_EQ(p.plan.frusta[0].size(), 3u);
    ASSERT_EQ(p.plan.frusta[1].size(), 3u);
    EXPECT_EQ(p.plan.firstFaceSlot[0], 2u);
    EXPECT_EQ(p.plan.firstFaceSlot[1], 4u);
    EXPECT_EQ(p.plan.slotsInUse, 6u);
    EXPECT_TRUE(p.warnings.empty());
    double lo = 1e300, hi = 0.0;
    for (const osg::Vec3d& q : frame.region)
        lo = std::min(lo, -(q * frame.view.view).z()), hi = std::max(hi, -(q * frame.view.view).z());
    const std::vector<double> splits = oss::cascadeSplits(lo, hi, 3);
    const std::vector<oss::LightFrustum>& c = p.plan.frusta[0];
    EXPECT_EQ(c[0].viewDepthFrom, 0.0);
    EXPECT_EQ(c[2].viewDepthTo, std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < 3; ++k)
    {
        EXPECT_TRUE(c[k].valid && c[k].partial());
        EXPECT_EQ(c[k].viewDepthFrom, k > 0 ? splits[k] : 0.0);
        EXPECT_EQ(c[k].viewDepthTo, k < 2 ? splits[k + 1] : std::numeric_limits<double>::infinity());
        const osg::Matrixd slice = oss::withDepthRange(frame.view.projection, splits[k], splits[k + 1]);
        for (const osg::Vec3d& q : oss::visibleRegion(oss::frustumCorners(frame.view.view, slice), frame.receivers))
        {
            const osg::Vec3d t = q * c[k].worldToTexture();
            for (int i = 0; i < 3; ++i) EXPECT_TRUE(t[i] >= 0.0 && t[i] <= 1.0) << "cascade " << k << " axis " << i;
        }
        if (k < 2)
        {
            EXPECT_GT(c[k].projection(0, 0), c[k + 1].projection(0, 0)); // smaller texels
        }
    }
}

TEST(LightPlanning, CascadesThatDoNotFitGiveOneMapAndAWarning)
{
    SlotBudget budget;
    budget.slotLimit = 2;
    budget.cascades = 3;
    const Planned p = plan(viewAcrossAField(), {directional(0, {1, 0.2, 0.5})}, budget);
    ASSERT_EQ(p.plan.frusta[0].size(), 1u);
    EXPECT_FALSE(p.plan.frusta[0][0].partial());
    EXPECT_EQ(p.plan.slotsInUse, 1u);
    EXPECT_EQ(p.warned(oss::detail::WARN_CASCADE_SLOTS), 1);
}

TEST(LightPlanning, CascadesAreDirectionalLightsOnly)
{
    // A spot light keeps its one perspective map; a frame without a view (no depths to split)
    // gives the directional light one map.
    SlotBudget budget;
    budget.slotLimit = 12;
    budget.cascades = 4;
    FrameContext frame = viewAcrossAField();
    const Planned spotLit = plan(frame, {spot(0, {0, 0, 30}, {0, 0, -1}, 60.0)}, budget);
    ASSERT_EQ(spotLit.plan.frusta[0].size(), 1u);
    EXPECT_TRUE(spotLit.plan.frusta[0][0].perspective);
    frame.view.valid = false;
    const Planned viewless = plan(frame, {directional(0, {1, 0.2, 0.5})}, budget);
    ASSERT_EQ(viewless.plan.frusta[0].size(), 1u);
    EXPECT_FALSE(viewless.plan.frusta[0][0].partial());
}
