// SHADOW_VOLUME and HYBRID's stencil method on triangle soups (tests/cpu/test_soups.h) standing
// on a ground, against the exact ray-cast reference (MEASURE.md), at 1024x768: open and
// non-manifold casters, back-to-back faces, a flipped face, a T-junction with a crack, boxes
// touching face to face, and a closed box wound inward (a room) with the camera inside it.
#include "GLTestSupport.h"
#include "Meshes.h"
#include "cpu/test_soups.h"

#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osgDB/WriteFile>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;
using namespace souptest;

namespace {

osg::ref_ptr<osg::Node> placed(const std::vector<Triangle>& soup, const char* name, float x, float y)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(soupGeometry(soup, name).get());
    osg::ref_ptr<osg::MatrixTransform> m = new osg::MatrixTransform(osg::Matrix::translate(x, y, 0));
    m->addChild(geode.get());
    return m;
}

/** Seven soups on a 3 x 3 grid, written where the renderer's options can load them. */
std::string writeSoups()
{
    osg::ref_ptr<osg::Group> g = new osg::Group;
    g->addChild(placed(threeFacesOnAnEdge(), "three faces on an edge", -5, -3));
    g->addChild(placed(backToBackQuads(), "back-to-back quads", 0, -3));
    g->addChild(placed(boxWithAFlippedFace(), "box with a flipped face", 5, -3));
    g->addChild(placed(box({-1, -1, -1}, {1, 1, 1}, 1), "open box", -5, 2));
    g->addChild(placed(tJunction(), "T-junction", 0, 2));
    g->addChild(placed(twoTouchingBoxes(), "two touching boxes", 5, 2));
    g->addChild(placed(flipped(box({-1, -1, -1}, {1, 1, 1})), "inward box", 0, 7));
    const std::string file = ::testing::TempDir() + "oss_volume_soups.osgt";
    EXPECT_TRUE(osgDB::writeNodeFile(*g, file));
    return file;
}

std::string writeRoom()
{
    osg::ref_ptr<osg::Group> g = new osg::Group;
    g->addChild(placed(roomWithABox(), "room", 0, 0));
    const std::string file = ::testing::TempDir() + "oss_volume_room.osgt";
    EXPECT_TRUE(osgDB::writeNodeFile(*g, file));
    return file;
}

/** A quad 0.008 units wide whose corners lie about 0.96 units from its frame's origin (the
 *  corners of the corpus's OBJ/regr_3429812.obj, turned z-up as OSG's OBJ reader turns them),
 *  written where the renderer can load it. */
std::string writeSmallQuadFarFromItsOrigin()
{
    const osg::Vec3f a(0.0498759f, -0.0949991f, 0.964456f), b(0.042335f, -0.0980526f, 0.96222f),
        c(0.0418548f, -0.096869f, 0.961535f), d(0.049267f, -0.0939126f, 0.963762f);
    std::vector<Triangle> quad;
    addQuad(quad, d, c, b, a);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(soupGeometry(quad, "small quad far from its origin").get());
    const std::string file = ::testing::TempDir() + "oss_volume_far_quad.osgt";
    EXPECT_TRUE(osgDB::writeNodeFile(*geode, file));
    return file;
}

osshar::RenderOptions soupOptions(const std::string& file, const osshar::LightArg& light)
{
    osshar::RenderOptions o;
    o.file = file;
    o.ground = true;
    o.lights = {light};
    return o;
}

osshar::LightArg directional(double x, double y, double z)
{
    osshar::LightArg l;
    l.vector.set(x, y, z);
    return l;
}

osshar::LightArg point(double x, double y, double z)
{
    osshar::LightArg l = directional(x, y, z);
    l.directional = false;
    return l;
}

double wrongPct(osshar::RenderOptions options, const std::string& mode, int width = 1024, int height = 768)
{
    ShadowedRender r(options, mode == "volume" ? "volume" : "hybrid", 512, width, height);
    if (!r.valid()) return 100.0;
    if (mode == "hybrid") r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    const ossref::Comparison c = ossref::compareMasks(r.mask(), r.reference());
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.coverageMismatch, 50);
    return c.wrongPct;
}

struct SoupLight
{
    const char* name;
    osshar::LightArg light;
};

class VolumeSoups : public ::testing::TestWithParam<std::tuple<SoupLight, const char*>>
{
};

} // namespace

// Measured: 0.0066% (volume) with the first light, 0.0078% with the point light: pixels
// on shadow outlines, where the reference's ray and the rasterized side quad fall on either
// side of the edge. A light lower than here (1, -0.3, 0.25) gives 0.035% of such pixels.
TEST_P(VolumeSoups, MatchTheReference)
{
    const SoupLight& l = std::get<0>(GetParam());
    const std::string mode = std::get<1>(GetParam());
    EXPECT_LT(wrongPct(soupOptions(writeSoups(), l.light), mode), 0.01) << l.name << " " << mode;
}

INSTANTIATE_TEST_SUITE_P(Lights, VolumeSoups,
                         ::testing::Combine(::testing::Values(SoupLight{"directional", directional(0.5, -0.6, 0.6)},
                                                              SoupLight{"point", point(3, -3, 5)}),
                                            ::testing::Values("volume", "hybrid")),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param);
                         });

// Inside a closed box wound inward every surface is shadowed from a light outside it. The
// classic rule (light-facing faces cast) left all of it lit: 100% wrong pixels.
TEST(VolumeSoups, InsideARoomWoundInward)
{
    osshar::RenderOptions o = soupOptions(writeRoom(), directional(0.3, -0.2, 1));
    o.eye = osg::Vec3d(1, -1, 3);
    o.center = osg::Vec3d(-1, 1, 1);
    EXPECT_LT(wrongPct(o, "volume"), 0.01);
    EXPECT_LT(wrongPct(o, "hybrid"), 0.01);
}

// A caster under a mirroring transform: its volume, drawn with the caster's matrix, is
// turned inside out in the window, and its counts were negative: -1 cancelled another
// caster's +1 where their shadows overlap, and that ground showed lit. A mirrored open quad
// under a box, and a mirrored closed box under an open quad, lit from above.
TEST(VolumeSoups, MirroredCastersCountAsTheOthers)
{
    const auto geodeOf = [](osg::Geometry* g) {
        osg::ref_ptr<osg::Geode> node = new osg::Geode;
        node->addDrawable(g);
        return node;
    };
    const auto mirrored = [](osg::Node* node, float cx) {
        osg::ref_ptr<osg::MatrixTransform> m = new osg::MatrixTransform(
            osg::Matrixd::translate(-cx, 0, 0) * osg::Matrixd::scale(-1, 1, 1) * osg::Matrixd::translate(cx, 0, 0));
        m->addChild(node);
        return m;
    };
    osshar::PreparedScene s;
    s.content = new osg::Group;
    s.content->addChild(geodeOf(osshar::makeGround(0, 0, 24).get()));
    const std::vector<Triangle> quad = {{{-2, -2, 2}, {2, -2, 2}, {2, 2, 2}}, {{-2, -2, 2}, {2, 2, 2}, {-2, 2, 2}}};
    s.content->addChild(mirrored(geodeOf(soupGeometry(quad, "quad").get()).get(), 0));
    s.content->addChild(geodeOf(osshar::makeBox(osg::Vec3(0.5f, 0.5f, 4), osg::Vec3(1, 1, 1)).get()));
    s.content->addChild(mirrored(geodeOf(osshar::makeBox(osg::Vec3(5, 0, 1), osg::Vec3(2, 2, 2)).get()).get(), 5));
    osg::ref_ptr<osg::MatrixTransform> above = new osg::MatrixTransform(osg::Matrixd::translate(5.5f, 0.5f, 2));
    above->addChild(geodeOf(soupGeometry(quad, "quad above the box").get()).get());
    s.content->addChild(above.get());
    s.content->addChild(osshar::makeLight(osg::Vec4(0.1f, 0.2f, 1.0f, 0.0f), 0));
    s.lights = osshar::findLights(s.content.get());
    s.view.eye = osg::Vec3d(2, -12, 12);
    s.view.center = osg::Vec3d(2, 0, 0);
    for (const char* mode : {"volume", "hybrid"})
    {
        ShadowedRender r(s, mode, 512, 1024, 768);
        ASSERT_TRUE(r.valid());
        if (std::string(mode) == "hybrid")
            r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
        const ossref::Comparison c = ossref::compareMasks(r.mask(), r.reference());
        ASSERT_TRUE(c.valid) << c.error;
        std::cout << mode << ": " << c.wrongPixels << " wrong pixels of " << c.geometryPixels << " (" << c.wrongPct
                  << "%)\n";
        EXPECT_LT(c.wrongPct, 0.01) << mode;
    }
}

// A caster whose vertices lie far from its frame's origin for its size, scaled up by its
// transform (the renderer's --ground scales the 0.008-unit quad to 6 units): drawn in that
// frame, its volume took the float rounding of model-view-projection terms about 750 times
// its size into the depths of its side quads, and the shadow's outline on the ground moved
// by a fifth of a pixel (0.0325% and 0.0899% wrong pixels, sun and point light, 512x384).
// With the sides drawn about the caster's centre 0.0051% and 0.0147%: the rest of the
// point light's was the sides' polygon offset of one depth unit, which moved the outline
// too. Without it 0.0057% and 0.0077%.
TEST(VolumeSoups, SmallCasterFarFromItsOrigin)
{
    const std::string file = writeSmallQuadFarFromItsOrigin();
    const double sun = wrongPct(soupOptions(file, directional(0.5, -0.6, 0.6)), "volume", 512, 384);
    const double lamp = wrongPct(soupOptions(file, point(-3, -4, 9)), "volume", 512, 384);
    std::cout << "wrong pixels: " << sun << "% (sun), " << lamp << "% (point light)\n";
    EXPECT_LT(sun, 0.01);
    EXPECT_LT(lamp, 0.01);
}
