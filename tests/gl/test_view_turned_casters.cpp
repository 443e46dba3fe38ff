// Casters as the view draws them: the eye pass shows LOD children chosen by the view's
// distance and billboards turned toward the eye, and the light passes must cast the shadows
// of that same geometry. OSG's cull of a light camera would choose by the light's distance
// and turn billboards toward the light; the exact reference traces what the view draws.
#include "GLTestSupport.h"
#include "Meshes.h"

#include <osg/Billboard>
#include <osg/Geode>
#include <osg/LOD>

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::ShadowedRender;

namespace {

/** A flat 2 x 3 panel of two triangles standing on its base, stored facing -y (in the x-z
 *  plane), for a billboard to turn. */
osg::ref_ptr<osg::Geometry> panel()
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec3& p : {osg::Vec3(-1, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(1, 0, 3), osg::Vec3(-1, 0, 3)})
        v->push_back(p);
    g->setVertexArray(v.get());
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array(osg::Array::BIND_OVERALL);
    n->push_back(osg::Vec3(0, -1, 0));
    g->setNormalArray(n.get());
    osg::ref_ptr<osg::DrawElementsUShort> faces = new osg::DrawElementsUShort(GL_TRIANGLES);
    for (unsigned short i : {0, 1, 2, 0, 2, 3}) faces->push_back(i);
    g->addPrimitiveSet(faces.get());
    return g;
}

/** Trees: one panel drawable at three positions of an axial billboard about z. */
osg::ref_ptr<osg::Billboard> trees()
{
    osg::ref_ptr<osg::Billboard> b = new osg::Billboard;
    b->setMode(osg::Billboard::AXIAL_ROT);
    b->setAxis(osg::Vec3(0, 0, 1));
    b->setNormal(osg::Vec3(0, -1, 0));
    osg::ref_ptr<osg::Geometry> shape = panel();
    for (const osg::Vec3& p : {osg::Vec3(-7, 1, 0), osg::Vec3(-3.5f, 4, 0), osg::Vec3(0, 2, 0)}) b->addDrawable(shape.get(), p);
    return b;
}

/** A sign turned fully toward the eye, raised above the ground. */
osg::ref_ptr<osg::Billboard> sign()
{
    osg::ref_ptr<osg::Billboard> b = new osg::Billboard;
    b->setMode(osg::Billboard::POINT_ROT_EYE);
    b->setNormal(osg::Vec3(0, -1, 0));
    b->addDrawable(panel().get(), osg::Vec3(4, 4, 1.5f));
    return b;
}

/** Two levels of a box in different places: near level (range [0, split)) at x0, far at x1. */
osg::ref_ptr<osg::LOD> levels(float split, float x0, float x1, float y)
{
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->setRangeMode(osg::LOD::DISTANCE_FROM_EYE_POINT);
    for (float x : {x0, x1})
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(osshar::makeBox(osg::Vec3(x, y, 1.0f), osg::Vec3(1.2f, 1.2f, 2.0f)).get());
        lod->addChild(geode.get(), x == x0 ? 0.0f : split, x == x0 ? split : 1e9f);
    }
    return lod;
}

osshar::PreparedScene scene()
{
    osshar::PreparedScene s;
    s.content = new osg::Group;
    osg::ref_ptr<osg::Geode> ground = new osg::Geode;
    ground->addDrawable(osshar::makeGround(0, 0, 30).get());
    s.content->addChild(ground.get());
    s.content->addChild(trees().get());
    s.content->addChild(sign().get());
    // The eye is ~20 units from both LODs, the point light ~6: the first draws its far level
    // for the view (x = -1) and its near one for the point light; the second its near level
    // for the view (x = 5.5), the far one for a distant sun camera.
    s.content->addChild(levels(12.0f, -4.0f, -1.0f, -5.0f).get());
    s.content->addChild(levels(60.0f, 5.5f, 8.0f, -6.0f).get());
    s.content->addChild(osshar::makeLight(osg::Vec4(0.7f, -0.2f, 0.5f, 0.0f), 0));
    s.content->addChild(osshar::makeLight(osg::Vec4(2.0f, -3.0f, 6.0f, 1.0f), 1));
    s.lights = osshar::findLights(s.content.get());
    s.view.eye = osg::Vec3d(0, -22, 9);
    s.view.center = osg::Vec3d(0, 0, 1);
    return s;
}

struct ModeCase
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
    double maxWrongPct; ///< per light, measured with this scene and map size, plus a margin
};

class ViewTurnedCasters : public ::testing::TestWithParam<ModeCase>
{
};

TEST_P(ViewTurnedCasters, CastTheShadowsOfWhatTheViewDraws)
{
    const ModeCase& c = GetParam();
    ShadowedRender r(scene(), c.mode, 2048, 512, 384);
    ASSERT_TRUE(r.valid());
    ASSERT_EQ(r.scene.lights.size(), 2u);
    r.technique->setHybridMethod(c.method);
    for (unsigned int light = 0; light < 2; ++light)
    {
        const ossref::Comparison cmp = ossref::compareMasks(r.mask(light, 3), r.reference(light));
        ASSERT_TRUE(cmp.valid) << cmp.error;
        std::cout << c.name << " light " << light << ": " << cmp.wrongPixels << " wrong pixels of "
                  << cmp.geometryPixels << " (" << cmp.wrongPct << "%)\n";
        EXPECT_LT(cmp.coverageMismatch, 10);
        EXPECT_LT(cmp.wrongPct, c.maxWrongPct) << "light " << light << ": " << cmp.wrongPixels << " wrong pixels of "
                                               << cmp.geometryPixels;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Modes, ViewTurnedCasters,
    ::testing::Values(ModeCase{"shadowmap", "shadowmap", SilhouetteShadowTechnique::HYBRID_AUTO, 0.1},
                      ModeCase{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO, 0.02},
                      ModeCase{"volume", "volume", SilhouetteShadowTechnique::HYBRID_AUTO, 0.02},
                      ModeCase{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 0.02},
                      ModeCase{"hybrid_stencil", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 0.02}),
    [](const ::testing::TestParamInfo<ModeCase>& info) { return std::string(info.param.name); });

} // namespace
