// Shadow geometry found on the GPU (GpuExtraction): the silhouette edges of the silhouette-map
// passes (GpuEdges.h: SILHOUETTE_MAP's maps, FILTER_SILHOUETTE's distance maps, HYBRID's edge
// masks) and the shadow volumes (GpuVolumes.h), on a scene built for what the corpus does not
// hold: a closed caster under a mirroring transform (the facing rule's MIRRORED bit), an open
// curled sheet (TWO_SIDED), and a caster behind the eye whose shadow falls in view (the casters
// are culled without the view frustum), and an LOD whose child the eye chooses (the lights
// stand beyond its switch distance: culled from the light's viewpoint, the GPU's edges would
// be the far child's while the depth map holds the near one). Every caster's on the GPU (GPU_EXTRACTION_ALL_CASTERS)
// against the exact reference and against the CPU's of the same technique, pixel for pixel,
// a sun and a point light. (tests/gl/test_caster_vertex_stage.cpp and
// test_animated_casters.cpp: casters moved by their own vertex stages; tests/corpus: real
// models.)
#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"

#include <osg/Geode>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/Texture2D>

#include <algorithm>

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::ShadowedRender;

namespace {

constexpr int W = 480, H = 360;

/** An open sheet curled three quarters round the y axis (angles from 90 to 360 degrees, the
 *  top right quarter missing): its lower faces turn away from the lights, and part of its
 *  shadow is cast by them alone, so only the TWO_SIDED rule casts all of it. */
osg::ref_ptr<osg::Geometry> curl()
{
    constexpr int ALONG = 24, ACROSS = 6;
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (int j = 0; j <= ACROSS; ++j)
        for (int i = 0; i <= ALONG; ++i)
        {
            const double t = osg::PI_2 + 1.5 * osg::PI * i / ALONG;
            v->push_back(
                osg::Vec3(1.5f + 0.5f * float(std::cos(t)), -1.8f + 0.2f * j, 1.6f + 0.5f * float(std::sin(t))));
        }
    osg::ref_ptr<osg::DrawElementsUInt> e = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (unsigned int j = 0; j < ACROSS; ++j)
        for (unsigned int i = 0; i < ALONG; ++i)
        {
            const unsigned int a = j * (ALONG + 1) + i, b = a + 1, c = a + ALONG + 2, d = a + ALONG + 1;
            for (unsigned int k : {a, c, b, a, d, c}) e->push_back(k); // outward: the upper arc faces up
        }
    g->setVertexArray(v.get());
    g->addPrimitiveSet(e.get());
    g->setName("curl");
    return g;
}

osshar::PreparedScene scene()
{
    osshar::PreparedScene s;
    s.content = new osg::Group;
    osg::ref_ptr<osg::Geode> ground = new osg::Geode;
    ground->addDrawable(osshar::makeGround(0, 0, 24).get());
    // Textured on unit 0, where the edge maps read their own map: the edges' draws must not take it.
    osg::ref_ptr<osg::Geometry> sphere = osshar::makeSphere(osg::Vec3(-1.4f, 1.0f, 1.0f), 0.6f, 24, 16);
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    std::fill(image->data(), image->data() + image->getTotalSizeInBytes(), 200);
    sphere->getOrCreateStateSet()->setTextureAttributeAndModes(0, new osg::Texture2D(image.get()));
    ground->addDrawable(sphere.get());
    ground->addDrawable(curl().get());
    // Behind the eye (z = 6), its shadow in view.
    ground->addDrawable(osshar::makeBox(osg::Vec3(-0.6f, -0.5f, 8.0f), osg::Vec3(0.8f, 0.6f, 0.5f)).get());
    s.content->addChild(ground.get());
    // The near child within 7 of the eye (5.6 away), the far one beyond (the point light is 11.6 away).
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
    lod->setCenter(osg::Vec3(-1.5f, -1.2f, 0.7f));
    osg::ref_ptr<osg::Geode> nearChild = new osg::Geode, farChild = new osg::Geode;
    nearChild->addDrawable(osshar::makeCylinder(osg::Vec3(-1.5f, -1.2f, 0.3f), 0.35f, 0.8f, 20).get());
    farChild->addDrawable(osshar::makeBox(osg::Vec3(-1.2f, -1.4f, 0.9f), osg::Vec3(1.0f, 0.4f, 1.2f)).get());
    lod->addChild(nearChild.get(), 0.0f, 7.0f);
    lod->addChild(farChild.get(), 7.0f, 1e6f);
    s.content->addChild(lod.get());
    // A torus mirrored in x: its faces wind clockwise in the eye's frame.
    osg::ref_ptr<osg::MatrixTransform> mirror =
        new osg::MatrixTransform(osg::Matrix::scale(-1, 1, 1) * osg::Matrix::translate(0.4f, 1.2f, 1.2f));
    osg::ref_ptr<osg::Geode> torus = new osg::Geode;
    torus->addDrawable(osshar::makeTorus(osg::Vec3(), 0.6f, 0.2f, 32, 16).get());
    mirror->addChild(torus.get());
    s.content->addChild(mirror.get());
    s.content->addChild(osshar::makeLight(osg::Vec4(0.1f, 0.12f, 1.0f, 0.0f), 0));
    s.content->addChild(osshar::makeLight(osg::Vec4(0.4f, 0.3f, 12.0f, 1.0f), 1));
    s.lights = osshar::findLights(s.content.get());
    s.view.eye = osg::Vec3d(0, 0, 6);
    s.view.center = osg::Vec3d(0, 0, 0);
    s.view.up = osg::Vec3d(0, 1, 0);
    s.view.fovy = 70.0;
    return s;
}

struct Case
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
    /** Mask pixels where the GPU's geometry and the CPU's may disagree, per light. */
    long long differ;
    /** The edges' cases at a size whose texels are larger than the pixels: the silhouette
     *  maps and edge masks decide there. */
    unsigned int mapSize = 1024;
    SilhouetteShadowTechnique::Filter filter = SilhouetteShadowTechnique::FILTER_PCF_2X2;
};

class GpuExtraction : public ::testing::TestWithParam<Case>
{
};

} // namespace

TEST_P(GpuExtraction, MatchesTheReferenceAndTheCpu)
{
    const Case& c = GetParam();
    ShadowedRender r(scene(), c.mode, c.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(c.method);
    r.technique->setFilter(c.filter);
    const ossref::Mask cpu[2] = {r.mask(0, 3), r.mask(1, 2)};
    r.technique->setGpuExtraction(SilhouetteShadowTechnique::GPU_EXTRACTION_ALL_CASTERS);
    const ossref::Mask gpu[2] = {r.mask(0, 3), r.mask(1, 2)};
    for (unsigned int light = 0; light < 2; ++light)
    {
        const ossref::Mask reference = r.reference(light);
        const ossref::Comparison onGpu = ossref::compareMasks(gpu[light], reference);
        const ossref::Comparison onCpu = ossref::compareMasks(cpu[light], reference);
        ASSERT_TRUE(onGpu.valid && onCpu.valid) << onGpu.error << onCpu.error;
        long long differ = 0, shadowed = 0;
        for (std::size_t p = 0; p < gpu[light].value.size(); ++p)
        {
            differ += gpu[light].value[p] != cpu[light].value[p];
            shadowed += reference.value[p] == ossref::MASK_NO_LIGHT;
        }
        std::printf("%s light %u: GPU %lld wrong pixels (%.4f%%), CPU %lld (%.4f%%), %lld differ; %lld shadowed\n",
                    c.name, light, onGpu.wrongPixels, onGpu.wrongPct, onCpu.wrongPixels, onCpu.wrongPct, differ,
                    shadowed);
        EXPECT_GT(shadowed, W * H / 50) << "the casters' shadows must lie in view";
        EXPECT_EQ(onGpu.coverageMismatch, 0);
        EXPECT_LE(onGpu.wrongPct, osstest::bounds::CLAIMED.of(c.mode)) << "light " << light;
        EXPECT_LE(differ, c.differ) << "light " << light
                                    << ": mask pixels where the GPU's geometry and the CPU's disagree";
    }
}

INSTANTIATE_TEST_SUITE_P(
    Modes, GpuExtraction,
    ::testing::Values(Case{"volume", "volume", SilhouetteShadowTechnique::HYBRID_AUTO, 12},
                      Case{"hybrid_stencil", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 12},
                      Case{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 12, 256},
                      Case{"hybrid_stencil_256", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 12, 256},
                      Case{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO, 12, 256},
                      Case{"silhouette_filter", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO, 12, 256,
                           SilhouetteShadowTechnique::FILTER_SILHOUETTE}),
    [](const auto& info) { return std::string(info.param.name); });
