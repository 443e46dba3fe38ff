// Shadow-volume orchestration: the z-pass/z-fail choice per caster and the reuse of
// volumes between frames.
#include <osgShadowSilhouette/ShadowVolumes>

#include "Meshes.h"

#include <osg/CullFace>
#include <osg/Depth>
#include <osg/FrontFace>
#include <osg/Geode>
#include <osg/MatrixTransform>

#include <gtest/gtest.h>

#include <cmath>

using namespace osgShadowSilhouette;

namespace {

const osg::BoundingSphered UNIT(osg::Vec3d(0, 0, 0), 1.0);
const osg::Vec4d OVERHEAD(0, 0, 1, 0); // directional, toward +z

struct ZFailCase
{
    const char* name;
    osg::BoundingSphered caster;
    osg::Vec4d light;
    osg::Vec3d eye;
    bool expected;
};

class ZFailChoice : public ::testing::TestWithParam<ZFailCase>
{
};

} // namespace

TEST_P(ZFailChoice, MatchesHandDerivedAnswer)
{
    const ZFailCase& c = GetParam();
    EXPECT_EQ(needsZFail(c.caster, c.light, c.eye, 0.1), c.expected) << c.name;
}

// Directional light from +z over a unit sphere: its volume lies in the cylinder of radius 1
// below it, widened by the near radius 0.1 to 1.1. Point light at (0,0,10): the cone
// tangent to the widened sphere (radius 1.1) has tan(half angle) = 1.1 / sqrt(100 - 1.21),
// so 10 units below the caster's centre its radius is 1.1 + 11 / sqrt(98.79) = 2.207.
INSTANTIATE_TEST_SUITE_P(
    Cases, ZFailChoice,
    ::testing::Values(ZFailCase{"eye in the shadow column", UNIT, OVERHEAD, {0, 0, -5}, true},
                      ZFailCase{"eye beside the column", UNIT, OVERHEAD, {1.2, 0, -5}, false},
                      ZFailCase{"eye just inside the widened column", UNIT, OVERHEAD, {1.05, 0, -50}, true},
                      ZFailCase{"eye between light and caster", UNIT, OVERHEAD, {0, 0, 5}, false},
                      ZFailCase{"eye inside the caster's bound", UNIT, OVERHEAD, {0, 0, 0.5}, true},
                      ZFailCase{"cone, inside its radius", UNIT, {0, 0, 10, 1}, {2.0, 0, -10}, true},
                      ZFailCase{"cone, outside its radius", UNIT, {0, 0, 10, 1}, {2.25, 0, -10}, false},
                      ZFailCase{"light inside the caster", UNIT, {0, 0, 0.5, 1}, {50, 50, 50}, true},
                      ZFailCase{"homogeneous light with w = 2", UNIT, {0, 0, 20, 2}, {2.0, 0, -10}, true},
                      ZFailCase{"empty bound", osg::BoundingSphered(), OVERHEAD, {0, 0, -5}, false}),
    [](const ::testing::TestParamInfo<ZFailCase>& info) {
        std::string n = info.param.name;
        for (char& ch : n)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return n;
    });

TEST(ShadowVolumeGroup, RebuildsOnlyWhatChanged)
{
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(3, 0, 0));
    osg::ref_ptr<osg::Geode> a = new osg::Geode, b = new osg::Geode;
    a->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 1), osg::Vec3(1, 1, 1)).get());
    b->addDrawable(osshar::makeSphere(osg::Vec3(0, 0, 1), 0.5f, 16, 8).get());
    moved->addChild(b.get());
    scene->addChild(a.get());
    scene->addChild(moved.get());

    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<ShadowVolumeGroup> volumes = new ShadowVolumeGroup;
    std::vector<Caster> casters = collectCasters(*scene, ~0u, *cache);
    ASSERT_EQ(casters.size(), 2u);

    EXPECT_EQ(volumes->update(casters, OVERHEAD), 2u);
    EXPECT_EQ(volumes->update(casters, OVERHEAD), 0u) << "a static frame rebuilds nothing";
    // A closed box from above: light cap (2 triangles), dark cap (10), 4 side edges x 2.
    EXPECT_GE(volumes->getTriangleCount(), 20u);

    moved->setMatrix(osg::Matrixd::translate(4, 0, 0));
    casters = collectCasters(*scene, ~0u, *cache);
    EXPECT_EQ(volumes->update(casters, OVERHEAD), 1u) << "only the moved caster";
    EXPECT_EQ(volumes->update(casters, osg::Vec4d(0.2, 0, 1, 0)), 2u) << "a new light rebuilds all";
    EXPECT_EQ(volumes->getCasterCount(), 2u);
    EXPECT_EQ(volumes->getRoot()->getNumChildren(), 2u);
}

// A caster drawn so that what lies behind it shows through (blended in the transparent bin,
// a later or depth-sorted bin, no depth writes) is marked, from any state set on its path
// or its own; its volume then takes z-fail whatever needsZFail() says.
TEST(SeeThrough, FromTheStateOnTheCastersPath)
{
    const auto state = [] { return osg::ref_ptr<osg::StateSet>(new osg::StateSet); };
    EXPECT_FALSE(seeThrough(*state()));
    osg::ref_ptr<osg::StateSet> transparent = state(), earlyBin = state(), lateBin = state(), sorted = state();
    transparent->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    EXPECT_TRUE(seeThrough(*transparent));
    earlyBin->setRenderBinDetails(-1, "RenderBin");
    lateBin->setRenderBinDetails(3, "RenderBin");
    sorted->setRenderBinDetails(0, "DepthSortedBin");
    EXPECT_FALSE(seeThrough(*earlyBin)) << "drawn before the opaque bin: in the depth buffer";
    EXPECT_TRUE(seeThrough(*lateBin));
    EXPECT_TRUE(seeThrough(*sorted));
    osg::ref_ptr<osg::StateSet> noWrites = state(), writes = state();
    noWrites->setAttribute(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
    writes->setAttribute(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, true));
    EXPECT_TRUE(seeThrough(*noWrites));
    EXPECT_FALSE(seeThrough(*writes));

    osg::ref_ptr<osg::Group> scene = new osg::Group;
    osg::ref_ptr<osg::Group> glass = new osg::Group;
    glass->getOrCreateStateSet()->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    osg::ref_ptr<osg::Geode> pane = new osg::Geode, box = new osg::Geode;
    pane->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 1), osg::Vec3(1, 1, 1)).get());
    osg::ref_ptr<osg::Geometry> own = osshar::makeBox(osg::Vec3(3, 0, 1), osg::Vec3(1, 1, 1));
    own->getOrCreateStateSet()->setAttribute(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
    box->addDrawable(osshar::makeBox(osg::Vec3(-3, 0, 1), osg::Vec3(1, 1, 1)).get());
    box->addDrawable(own.get());
    glass->addChild(pane.get());
    scene->addChild(glass.get());
    scene->addChild(box.get());
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const std::vector<Caster> casters = collectCasters(*scene, ~0u, *cache);
    ASSERT_EQ(casters.size(), 3u);
    EXPECT_TRUE(casters[0].seeThrough) << "under a transparent group";
    EXPECT_FALSE(casters[1].seeThrough);
    EXPECT_TRUE(casters[2].seeThrough) << "its own osg::Depth writes nothing";
}

// Face culling lets a view ray pass a caster's culled side and end behind it, so such a
// caster is marked like a see-through one: GL_CULL_FACE, osg::CullFace and osg::FrontFace
// accumulated along the path as osg::State does, the side named by the world's winding.
// Only a closed mesh wound outward whose inside alone is culled keeps z-pass.
TEST(SeeThrough, FromFaceCulling)
{
    const auto collect = [](osg::Node& node) {
        osg::ref_ptr<osg::Group> scene = new osg::Group;
        scene->addChild(&node);
        osg::ref_ptr<MeshCache> cache = new MeshCache;
        const std::vector<Caster> casters = collectCasters(*scene, ~0u, *cache);
        EXPECT_EQ(casters.size(), 1u);
        return !casters.empty() && casters[0].seeThrough;
    };
    // A closed box (wound outward) and an open quad, each under a group that carries the state.
    const auto closedBox = [] {
        osg::ref_ptr<osg::Geode> g = new osg::Geode;
        g->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 1), osg::Vec3(1, 1, 1)).get());
        return g;
    };
    const auto openQuad = [] {
        osg::ref_ptr<osg::Geometry> q = new osg::Geometry;
        osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
        for (const osg::Vec3& p : {osg::Vec3(-1, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(1, 0, 2), osg::Vec3(-1, 0, 2)})
            v->push_back(p);
        q->setVertexArray(v.get());
        q->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_FAN, 0, 4));
        osg::ref_ptr<osg::Geode> g = new osg::Geode;
        g->addDrawable(q.get());
        return g;
    };
    struct Case
    {
        const char* name;
        bool closed;
        bool cullOn;
        int cullFace;  // -1: none set, else osg::CullFace::Mode
        int frontFace; // -1: none set, else osg::FrontFace::Mode
        bool mirrored;
        bool expected;
    };
    const int back = osg::CullFace::BACK, front = osg::CullFace::FRONT, both = osg::CullFace::FRONT_AND_BACK;
    const int cw = osg::FrontFace::CLOCKWISE, ccw = osg::FrontFace::COUNTER_CLOCKWISE;
    for (const Case& c :
         {Case{"no culling", false, false, -1, -1, false, false},
          Case{"a CullFace without GL_CULL_FACE", false, false, both, -1, false, false},
          Case{"open, BACK", false, true, -1, -1, false, true}, Case{"closed, BACK", true, true, -1, -1, false, false},
          Case{"closed, BACK, set explicitly", true, true, back, ccw, false, false},
          Case{"closed, FRONT", true, true, front, -1, false, true},
          Case{"closed, FRONT_AND_BACK", true, true, both, -1, false, true},
          Case{"closed, BACK, FrontFace CLOCKWISE", true, true, back, cw, false, true},
          Case{"closed, FRONT, FrontFace CLOCKWISE", true, true, front, cw, false, false},
          Case{"closed, BACK, mirrored", true, true, back, -1, true, true},
          Case{"closed, FRONT, mirrored", true, true, front, -1, true, false},
          Case{"closed, BACK, CLOCKWISE, mirrored", true, true, back, cw, true, false}})
    {
        SCOPED_TRACE(c.name);
        osg::ref_ptr<osg::MatrixTransform> t =
            new osg::MatrixTransform(c.mirrored ? osg::Matrixd::scale(-1, 1, 1) : osg::Matrixd::identity());
        t->addChild(c.closed ? closedBox().get() : openQuad().get());
        osg::StateSet* ss = t->getOrCreateStateSet();
        if (c.cullOn) ss->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
        if (c.cullFace >= 0) ss->setAttribute(new osg::CullFace(osg::CullFace::Mode(c.cullFace)));
        if (c.frontFace >= 0) ss->setAttribute(new osg::FrontFace(osg::FrontFace::Mode(c.frontFace)));
        EXPECT_EQ(collect(*t), c.expected);
    }
}

// OVERRIDE on a parent beats the drawable's value unless that is PROTECTED, for the mode
// and for both attributes.
TEST(SeeThrough, FaceCullingOverrideAndProtected)
{
    osg::ref_ptr<osg::Group> scene = new osg::Group, parent = new osg::Group;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> box = osshar::makeBox(osg::Vec3(0, 0, 1), osg::Vec3(1, 1, 1));
    geode->addDrawable(box.get());
    parent->addChild(geode.get());
    scene->addChild(parent.get());
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const auto marked = [&] {
        const std::vector<Caster> casters = collectCasters(*scene, ~0u, *cache);
        return casters.size() == 1 && casters[0].seeThrough;
    };
    osg::StateSet* child = box->getOrCreateStateSet();
    osg::StateSet* above = parent->getOrCreateStateSet();
    child->setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT));
    EXPECT_TRUE(marked()) << "the drawable culls the outside of a closed box";
    above->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    EXPECT_FALSE(marked()) << "the parent's OFF | OVERRIDE";
    child->setMode(GL_CULL_FACE, osg::StateAttribute::ON | osg::StateAttribute::PROTECTED);
    EXPECT_TRUE(marked()) << "the drawable's ON | PROTECTED";

    above->setAttribute(new osg::CullFace(osg::CullFace::BACK), osg::StateAttribute::OVERRIDE);
    EXPECT_FALSE(marked()) << "the parent's CullFace BACK | OVERRIDE";
    child->setAttribute(new osg::CullFace(osg::CullFace::FRONT), osg::StateAttribute::PROTECTED);
    EXPECT_TRUE(marked()) << "the drawable's CullFace FRONT | PROTECTED";

    child->setAttribute(new osg::CullFace(osg::CullFace::BACK));
    above->removeAttribute(osg::StateAttribute::CULLFACE);
    EXPECT_FALSE(marked());
    above->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE), osg::StateAttribute::OVERRIDE);
    child->setAttribute(new osg::FrontFace(osg::FrontFace::COUNTER_CLOCKWISE));
    EXPECT_TRUE(marked()) << "the parent's FrontFace CLOCKWISE | OVERRIDE";
    child->setAttribute(new osg::FrontFace(osg::FrontFace::COUNTER_CLOCKWISE), osg::StateAttribute::PROTECTED);
    EXPECT_FALSE(marked()) << "the drawable's FrontFace COUNTER_CLOCKWISE | PROTECTED";
}

// The windings the eye pass culls, as GL names them from CullFace and FrontFace (the
// rasterizer applies a mirroring matrix to the volumes as to the caster, so it is not in
// them): ShadowVolumeGroup draws the light caps of such a caster apart.
TEST(SeeThrough, CulledWindings)
{
    struct Case
    {
        bool cullOn;
        int cullFace;  // -1: none set
        int frontFace; // -1: none set
        bool mirrored;
        unsigned char expected;
    };
    const unsigned char ccw = Caster::CULLS_CCW, cw = Caster::CULLS_CW;
    for (const Case& c : {Case{false, osg::CullFace::FRONT, -1, false, 0}, Case{true, -1, -1, false, cw},
                          Case{true, osg::CullFace::FRONT, -1, false, ccw},
                          Case{true, osg::CullFace::FRONT_AND_BACK, -1, false, (unsigned char)(ccw | cw)},
                          Case{true, osg::CullFace::BACK, osg::FrontFace::CLOCKWISE, false, ccw},
                          Case{true, osg::CullFace::FRONT, osg::FrontFace::CLOCKWISE, false, cw},
                          Case{true, osg::CullFace::BACK, -1, true, cw}})
    {
        osg::ref_ptr<osg::Group> scene = new osg::Group;
        osg::ref_ptr<osg::MatrixTransform> t =
            new osg::MatrixTransform(c.mirrored ? osg::Matrixd::scale(-1, 1, 1) : osg::Matrixd::identity());
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(osshar::makeBox(osg::Vec3(0, 0, 1), osg::Vec3(1, 1, 1)).get());
        t->addChild(geode.get());
        scene->addChild(t.get());
        osg::StateSet* ss = t->getOrCreateStateSet();
        if (c.cullOn) ss->setMode(GL_CULL_FACE, osg::StateAttribute::ON);
        if (c.cullFace >= 0) ss->setAttribute(new osg::CullFace(osg::CullFace::Mode(c.cullFace)));
        if (c.frontFace >= 0) ss->setAttribute(new osg::FrontFace(osg::FrontFace::Mode(c.frontFace)));
        osg::ref_ptr<MeshCache> cache = new MeshCache;
        const std::vector<Caster> casters = collectCasters(*scene, ~0u, *cache);
        ASSERT_EQ(casters.size(), 1u);
        EXPECT_EQ(int(casters[0].culledWindings), int(c.expected))
            << "cull " << c.cullOn << " " << c.cullFace << " front " << c.frontFace << " mirrored " << c.mirrored;
    }
}
