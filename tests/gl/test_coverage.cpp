// The reference sees what a view draws: LOD children chosen by the camera's distance and by
// their size on screen, the active children of a switch, billboards turned toward the eye.
// A mismatch in coverage (geometry in one mask and background in the other) would count as
// error of the technique anywhere else.
#include "GLTestSupport.h"
#include "Meshes.h"

#include <osg/Billboard>
#include <osg/LOD>
#include <osg/Switch>

using osstest::ShadowedRender;

namespace {

// Everything stands beyond the ground's far edge (y = 12) and floats from z = 1 to 3, so the
// view sees it against the background, where coverage shows.
constexpr float kY = 14.0f;

osg::ref_ptr<osg::Geode> boxAt(float x)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeBox(osg::Vec3(x, kY, 2.0f), osg::Vec3(1.5f, 1.5f, 2.0f)).get());
    return geode;
}

/** Two levels in different places, so that the wrong choice shows as coverage: the near
 *  level (range [0, split)) at x0, the far one at x1. */
osg::ref_ptr<osg::LOD> twoLevels(osg::LOD::RangeMode mode, float split, float x0, float x1)
{
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->setRangeMode(mode);
    lod->addChild(boxAt(x0), 0.0f, split);
    lod->addChild(boxAt(x1), split, 1e9f);
    return lod;
}

/** A square stored edge-on to the view (in the y-z plane, facing +x), which a billboard
 *  turns toward the eye. */
osg::ref_ptr<osg::Billboard> billboardAt(const osg::Vec3& position)
{
    osg::ref_ptr<osg::Geometry> square = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> corners = new osg::Vec3Array;
    for (const osg::Vec3& corner : {osg::Vec3(0, -1, 0), osg::Vec3(0, 1, 0), osg::Vec3(0, 1, 2), osg::Vec3(0, -1, 2)})
        corners->push_back(corner);
    square->setVertexArray(corners.get());
    square->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    osg::ref_ptr<osg::Billboard> billboard = new osg::Billboard;
    billboard->setMode(osg::Billboard::POINT_ROT_EYE);
    billboard->setNormal(osg::Vec3(1, 0, 0));
    billboard->addDrawable(square.get(), position);
    return billboard;
}

TEST(ReferenceCoverage, LodSwitchAndBillboardAsTheViewDrawsThem)
{
    ShadowedRender r("default", "shadowmap", 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    // The default scene alone: a pixel centre on the ground's far edge, which rasterization
    // and the ray cast settle differently, may already count. The nodes below add none.
    const long long before = ossref::compareMasks(r.mask(0), r.reference(0)).coverageMismatch;
    EXPECT_LE(before, 1);
    // The eye of the default scene is ~32 units from the first LOD: its far level (x = -6.5)
    // is drawn. The second spans ~80 pixels: its level for less than 1000 (x = 4) is drawn.
    r.scene.content->addChild(twoLevels(osg::LOD::DISTANCE_FROM_EYE_POINT, 10.0f, -9.0f, -6.5f).get());
    r.scene.content->addChild(twoLevels(osg::LOD::PIXEL_SIZE_ON_SCREEN, 1000.0f, 4.0f, 6.5f).get());
    osg::ref_ptr<osg::Switch> choice = new osg::Switch;
    choice->addChild(boxAt(-4.0f).get(), false);
    choice->addChild(boxAt(-2.0f).get(), true);
    r.scene.content->addChild(choice.get());
    r.scene.content->addChild(billboardAt(osg::Vec3(1.0f, kY, 1.0f)).get());
    const ossref::Mask mask = r.mask(0);

    const ossref::Comparison seen = ossref::compareMasks(mask, r.reference(0));
    ASSERT_TRUE(seen.valid) << seen.error;
    EXPECT_EQ(seen.coverageMismatch, before);
    // The same scene collected without the camera: the other LOD levels, the upright square.
    const ossref::Tracer blind(ossref::collectTriangles(*r.scene.content));
    const ossref::Mask blindReference =
        blind.render(osshar::referenceCamera(r.scene.view, r.renderer->width(), r.renderer->height()),
                     osshar::referenceLight(r.scene.lights.at(0)));
    EXPECT_GT(ossref::compareMasks(mask, blindReference).coverageMismatch, 1000)
        << "the scene does not tell a camera-aware reference from a blind one";
}

} // namespace
