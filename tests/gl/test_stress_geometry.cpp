// Stress: awkward caster geometry in the default scene, in every mode. Each case asserts a
// finite image and wrong_pct against the exact reference within the bound of its mode.
#include "StressSupport.h"

using namespace osstest;

// Zero-area triangles (a repeated corner, three collinear corners) and slivers (1e-5 wide,
// 5 long; an angle of 1e-4 radians) next to an ordinary box.
TEST_P(StressMode, DegenerateAndSliverTriangles)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    std::vector<osg::Vec3> t = boxTriangles(osg::Vec3(-6, -5, 0), osg::Vec3(-4.5f, -3.5f, 1.5f));
    t.insert(t.end(), {{-6, -5, 1.5f}, {-6, -5, 1.5f}, {-4.5f, -3.5f, 1.5f}});          // repeated corner
    t.insert(t.end(), {{-6, -5, 1.5f}, {-5.25f, -4.25f, 1.5f}, {-4.5f, -3.5f, 1.5f}});   // collinear
    t.insert(t.end(), {{-2, -6, 0.5f}, {3, -6, 0.5f}, {3, -6.00001f, 3.0f}});             // sliver 1e-5 wide
    t.insert(t.end(), {{-3, 6, 0.2f}, {3, 6, 2.0f}, {3, 6.0006f, 2.0f}});                // 1e-4 rad
    addToScene(r, flatTriangles(t, "slivers").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// Every triangle with its own vertices (welding must find the adjacency), and every
// triangle present twice (two faces on each edge of the same orientation: non-manifold).
TEST_P(StressMode, DuplicatedVerticesAndTriangles)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    std::vector<osg::Vec3> t = boxTriangles(osg::Vec3(-6, -5, 0.5f), osg::Vec3(-4.5f, -3.5f, 2.0f));
    const std::vector<osg::Vec3> once = t;
    t.insert(t.end(), once.begin(), once.end());
    addToScene(r, flatTriangles(t, "doubled box").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// A geometry with NaN and Inf vertices in the middle of the scene: a warning names it, it
// casts no shadow at all (the reference leaves it out of casting), and no pixel is NaN.
TEST_P(StressMode, NonFiniteGeometryIsLeftOutOfCasting)
{
    NotifyCapture notes;
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::Geometry> bad = osshar::makeBox(osg::Vec3(-5, -5, 1.5f), osg::Vec3(1.5f, 1.5f, 1.5f));
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(bad->getVertexArray());
    (*v)[0].x() = std::numeric_limits<float>::quiet_NaN();
    (*v)[5].z() = std::numeric_limits<float>::infinity();
    bad->setName("broken box");
    osg::Geode* geode = addToScene(r, bad.get());
    geode->setNodeMask(~0x100u); // the reference's casts mask below leaves it out
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()), 0, 0x100u);
    EXPECT_TRUE(notes.warned("broken box")) << notes.warnings();
}

// Open casters: a box without its top, a floating one-sided plate, a plate seen from the back.
TEST_P(StressMode, OpenCasters)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    std::vector<osg::Vec3> t = boxTriangles(osg::Vec3(-6, -5, 0.5f), osg::Vec3(-4.5f, -3.5f, 2.0f), true);
    addQuad(t, {-2, -7, 2.5f}, {0, -7, 2.5f}, {0, -5.5f, 2.5f}, {-2, -5.5f, 2.5f}); // faces the light
    addQuad(t, {5, 3, 2.0f}, {5, 5, 2.0f}, {7, 5, 2.0f}, {7, 3, 2.0f});             // faces down
    addToScene(r, flatTriangles(t, "open casters").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// Non-manifold casters: three plates sharing one edge (a fin), two boxes sharing an edge,
// two boxes touching at a corner.
TEST_P(StressMode, NonManifoldCasters)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    std::vector<osg::Vec3> t;
    const osg::Vec3 a(-2, -6, 0.5f), b(-2, -6, 2.5f);
    addQuad(t, a, {-1, -6, 0.5f}, {-1, -6, 2.5f}, b);
    addQuad(t, a, b, {-2, -5, 2.5f}, {-2, -5, 0.5f});
    addQuad(t, a, {-2.7f, -6.7f, 0.5f}, {-2.7f, -6.7f, 2.5f}, b);
    for (const auto& box : {boxTriangles({-7, -5, 0}, {-6, -4, 1}), boxTriangles({-6, -4, 0}, {-5, -3, 1}),
                            boxTriangles({5, 4, 1}, {6, 5, 2}), boxTriangles({6, 5, 2}, {7, 6, 3})})
        t.insert(t.end(), box.begin(), box.end());
    addToScene(r, flatTriangles(t, "non-manifold").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// A tilted box piercing the receiver and a box standing exactly on it.
TEST_P(StressMode, CastersTouchingAndPiercingTheReceiver)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::MatrixTransform> tilted = new osg::MatrixTransform(
        osg::Matrixd::rotate(osg::DegreesToRadians(35.0), osg::Vec3d(1, 1, 0)) * osg::Matrixd::translate(-5, -4.5, 0.3));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 0), osg::Vec3(1.2f, 1.2f, 3.0f)).get());
    tilted->addChild(geode.get());
    r.scene.content->addChild(tilted.get());
    addToScene(r, flatTriangles(boxTriangles({-1, -7, 0}, {1, -6, 1.5f}), "standing box").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// Coplanar casters: two overlapping boxes with the same top and side planes, and a plate
// lying exactly on the top face of a box.
TEST_P(StressMode, CoplanarCasters)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    std::vector<osg::Vec3> t = boxTriangles({-6, -6, 0.5f}, {-4, -4, 2});
    const std::vector<osg::Vec3> second = boxTriangles({-5, -6, 0.5f}, {-3, -4, 2});
    t.insert(t.end(), second.begin(), second.end());
    addQuad(t, {-0.5f, -3.5f, 2}, {1.5f, -3.5f, 2}, {1.5f, -1.5f, 2}, {-0.5f, -1.5f, 2}); // on the green box
    addToScene(r, flatTriangles(t, "coplanar").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// Very thin casters: a closed plate 1e-3 thick and a pole of radius 0.01.
TEST_P(StressMode, VeryThinCasters)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    addToScene(r, flatTriangles(boxTriangles({-7, -6, 2.5f}, {-4, -4, 2.501f}), "thin plate").get());
    addToScene(r, osshar::makeCylinder(osg::Vec3(-1, -6, 0), 0.01f, 4.0f, 8).get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// A plate and a box whose side faces contain the light direction exactly (light along
// (1, 0, 1), faces in planes y = const): N.L is exactly 0 on them.
TEST_P(StressMode, CasterExactlyEdgeOnToTheLight)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    lightOf(r)->setPosition(osg::Vec4(1, 0, 1, 0));
    std::vector<osg::Vec3> t;
    addQuad(t, {-6, -5, 0.5f}, {-4, -5, 2.5f}, {-4, -5, 3.5f}, {-6, -5, 1.5f}); // contains (1, 0, 1)
    addToScene(r, flatTriangles(t, "edge-on plate").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Modes, StressMode, ::testing::ValuesIn(STRESS_MODES));
