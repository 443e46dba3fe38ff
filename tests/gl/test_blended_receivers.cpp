// Blended receivers (glass, water, a model's transparent parts: blending in the transparent
// bin, drawn after the opaque bin): every mode shadows them exactly as the reference does,
// and shades their lit pixels alike. The stencil modes count their volumes against the
// depth buffer, which holds a blended surface's depth only once that surface is drawn; their
// blended round (ShadowVolumes, StencilShadowPasses::cull()) lights such surfaces after the
// transparent bin. Without it SHADOW_VOLUME left them unlit (LWO/LWO2/transparency.lwo of the
// corpus: 41% wrong, docs/benchmarks.md).
//
// Scene: an opaque ground; a blended table top (alpha 0.5, depth writes on) with an opaque
// box above it; a blended pane standing on the ground (alpha 0.35, no depth writes); 512x384.
#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"
#include "NotifyCapture.h"

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Material>

#include <algorithm>
#include <cstdlib>
#include <iostream>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

void blend(osg::Geometry& g, const osg::Vec4& diffuse, bool depthWrites)
{
    osg::StateSet* ss = g.getOrCreateStateSet();
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setDiffuse(osg::Material::FRONT_AND_BACK, diffuse);
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.2f, 0.2f, 0.2f, diffuse.a()));
    ss->setAttributeAndModes(m.get());
    ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    ss->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    if (!depthWrites) ss->setAttribute(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
}

/** A vertical quad in the plane y = y0, x in [x0, x1], z in [0, height], facing -y. */
osg::ref_ptr<osg::Geometry> pane(float x0, float x1, float y0, float height)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(x0, y0, 0));
    v->push_back(osg::Vec3(x1, y0, 0));
    v->push_back(osg::Vec3(x1, y0, height));
    v->push_back(osg::Vec3(x0, y0, height));
    g->setVertexArray(v.get());
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    n->push_back(osg::Vec3(0, -1, 0));
    g->setNormalArray(n.get(), osg::Array::BIND_OVERALL);
    osg::ref_ptr<osg::DrawElementsUInt> t = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (unsigned int i : {0u, 1u, 2u, 0u, 2u, 3u}) t->push_back(i);
    g->addPrimitiveSet(t.get());
    return g;
}

/** The scene under a sun, and a point light too where `twoLights`. */
osshar::PreparedScene blendedScene(bool pointLight, bool twoLights)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeGround(0, 0, 16));
    osg::ref_ptr<osg::Geometry> table = osshar::makeGround(-2, 1, 4, 1.2f);
    blend(*table, osg::Vec4(0.9f, 0.6f, 0.3f, 0.5f), true);
    geode->addDrawable(table.get());
    geode->addDrawable(osshar::makeBox(osg::Vec3(-2, 1, 2.6f), osg::Vec3(1, 1, 1)));
    osg::ref_ptr<osg::Geometry> glass = pane(1.5f, 4.5f, -1, 2.5f);
    blend(*glass, osg::Vec4(0.4f, 0.7f, 0.9f, 0.35f), false);
    geode->addDrawable(glass.get());

    osshar::PreparedScene scene;
    scene.content = new osg::Group;
    scene.content->addChild(geode.get());
    if (!pointLight || twoLights) scene.content->addChild(osshar::makeLight(osg::Vec4(0.5f, -0.6f, 0.6f, 0.0f), 0));
    if (pointLight || twoLights)
        scene.content->addChild(osshar::makeLight(osg::Vec4(1.0f, -4.0f, 8.0f, 1.0f), twoLights ? 1 : 0));
    scene.lights = osshar::findLights(scene.content.get());
    scene.view = {osg::Vec3d(3, -11, 7), osg::Vec3d(-0.5, 0.5, 0.8), osg::Vec3d(0, 0, 1), 40.0};
    return scene;
}

/** Puts every drawable back in the opaque bin. */
struct RemoveTransparentHints : osg::NodeVisitor
{
    RemoveTransparentHints() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Node& node) override
    {
        if (node.getStateSet()) node.getStateSet()->setRenderingHint(osg::StateSet::DEFAULT_BIN);
        traverse(node);
    }
};

struct BlendedCase
{
    const char* name;
    const char* mode;
    bool point;
    bool stencil = false; ///< HYBRID by its stencil volumes
    bool gpu = false;     ///< every volume extruded on the GPU (GPU_EXTRACTION_ALL_CASTERS)
};

class BlendedReceivers : public ::testing::TestWithParam<BlendedCase>
{
};

} // namespace

TEST_P(BlendedReceivers, ShadowedAsTheReferenceShadowsThem)
{
    const BlendedCase& c = GetParam();
    ShadowedRender r(blendedScene(c.point, false), c.mode, 2048, 512, 384);
    ASSERT_TRUE(r.valid());
    if (c.stencil) r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    if (c.gpu) r.technique->setGpuExtraction(SilhouetteShadowTechnique::GPU_EXTRACTION_ALL_CASTERS);
    const ossref::Comparison score = r.scoreMask(0, 3);
    ASSERT_TRUE(score.valid) << score.error;
    std::cout << c.name << ": wrong_pct " << score.wrongPct << " (" << score.wrongPixels << " pixels of "
              << score.geometryPixels << ")\n";
    EXPECT_LT(score.coverageMismatch, 10);
    EXPECT_LT(score.wrongPct, osstest::bounds::CLAIMED.of(c.mode)) << score.wrongPixels << " wrong pixels";
    const bool stencilMode = std::string(c.mode) == "volume" || c.stencil;
    EXPECT_EQ(r.technique->getStatistics().effectiveMode, r.technique->getMode());
    EXPECT_EQ(r.technique->getStatistics().blendedRound, stencilMode) << "the blended receivers' round of their own";
}

INSTANTIATE_TEST_SUITE_P(
    Modes, BlendedReceivers,
    ::testing::Values(BlendedCase{"shadowmap_sun", "shadowmap", false},
                      BlendedCase{"silhouette_sun", "silhouette", false}, BlendedCase{"hybrid_sun", "hybrid", false},
                      BlendedCase{"hybrid_stencil_sun", "hybrid", false, true},
                      BlendedCase{"hybrid_stencil_point", "hybrid", true, true},
                      BlendedCase{"volume_sun", "volume", false}, BlendedCase{"volume_point", "volume", true},
                      // The blended round counts the volumes extruded on the GPU too.
                      BlendedCase{"volume_gpu_sun", "volume", false, false, true},
                      BlendedCase{"volume_gpu_point", "volume", true, false, true},
                      BlendedCase{"hybrid_stencil_gpu_point", "hybrid", true, true, true}),
    [](const ::testing::TestParamInfo<BlendedCase>& info) { return std::string(info.param.name); });

namespace {

struct Frame
{
    osg::ref_ptr<osg::Image> colour;
    ossref::Mask masks[2];
};

Frame renderBoth(const std::string& mode, bool stencil)
{
    ShadowedRender r(blendedScene(false, true), mode, 2048, 512, 384);
    Frame f;
    if (!r.valid()) return f;
    if (stencil) r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    r.renderer->timeFrames(0, 2);
    f.colour = r.renderer->renderAndCapture();
    f.masks[0] = r.mask(0, 1);
    f.masks[1] = r.mask(1, 1);
    return f;
}

/** Whether image pixel i (bottom row first) and its neighbours within 2 pixels are lit by
 *  both lights in f's masks (top row first). */
bool litAround(const Frame& f, int i)
{
    const int w = f.masks[0].width, h = f.masks[0].height;
    const int x = i % w, y = h - 1 - i / w;
    for (const ossref::Mask& m : f.masks)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
            {
                const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
                if (m.value[std::size_t(yy) * w + xx] != ossref::MASK_LIT) return false;
            }
    return true;
}

} // namespace

// The stencil modes add each light in a pass of its own, after the blended surface's base
// pass has blended its ambient over what lies behind; the map modes shade it once and blend
// the whole. Both give alpha times the clamped shading: a light pass adds alpha times its
// light (GL_SRC_ALPHA, GL_ONE), no more than the base pass and the slots before it left
// below 1. The table is bright enough that the two lights saturate its red channel.
TEST(BlendedReceivers, LitPixelsAgreeWithTheMapModes)
{
    const Frame lists = renderBoth("hybrid", false);
    ASSERT_TRUE(lists.colour.valid());
    for (const auto& [mode, stencil] : {std::pair<const char*, bool>{"volume", false}, {"hybrid", true}})
    {
        const Frame other = renderBoth(mode, stencil);
        ASSERT_TRUE(other.colour.valid());
        const int n = lists.colour->s() * lists.colour->t();
        // Judged by the lists' masks alone: the other's are under test too.
        const osstest::ColourComparison lit =
            osstest::compareColours(*lists.colour, *other.colour, [&](int i) { return litAround(lists, i); });
        const long long compared = lit.compared, differing = lit.differing;
        const int worst = lit.worst;
        std::cout << mode << (stencil ? " (stencil)" : "") << ": " << compared << " pixels compared, " << differing
                  << " differ, largest difference " << worst << "\n";
        EXPECT_GT(compared, n / 4);
        // The masks say where the nearest surface is lit, not the ground seen through the
        // glass: along the pane's foot, where its shadow on the ground begins, a pixel may
        // show the ground behind on the other side of that edge (measured: 29 and 31 pixels of 116726).
        EXPECT_LT(differing, compared / 1000) << mode << ": lit pixels shaded differently from HYBRID's triangle lists "
                                              << "(largest difference " << worst << " of 255)";
    }
}

// With a program given to addShadowShaders(), the stencil modes draw the receivers from a
// screen-space visibility, which has no blended round yet: they say so once, and only when
// the view has blended receivers.
TEST(BlendedReceivers, ScreenVisibilityWarnsOnce)
{
    for (bool blended : {true, false})
    {
        osstest::NotifyCapture capture;
        osshar::PreparedScene scene = blendedScene(false, false);
        RemoveTransparentHints opaque;
        if (!blended) scene.content->accept(opaque); // every drawable in the opaque bin
        ShadowedRender r(std::move(scene), "volume", 1024, 320, 240);
        ASSERT_TRUE(r.valid());
        osg::ref_ptr<osg::Program> program = new osg::Program;
        program->setName("application receivers");
        program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 400 compatibility\n"
                                                                "out vec4 eyePosition;\n"
                                                                "void main() { eyePosition = gl_ModelViewMatrix * "
                                                                "gl_Vertex; gl_Position = ftransform(); }\n"));
        program->addShader(new osg::Shader(osg::Shader::FRAGMENT,
                                           "#version 400 compatibility\n"
                                           "in vec4 eyePosition;\n"
                                           "float oss_shadowTerm(int light, vec4 eyePosition);\n"
                                           "void main() { gl_FragColor = vec4(vec3(oss_shadowTerm(0, eyePosition)), "
                                           "gl_FrontMaterial.diffuse.a); }\n"));
        r.technique->addShadowShaders(program.get());
        r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
        r.renderer->timeFrames(0, 3);
        if (osstest::contextGLVersion(r) < 4.3f) GTEST_SKIP() << "screen-space visibility needs OpenGL 4.3";
        EXPECT_TRUE(r.technique->getStatistics().screenVisibility);
        EXPECT_FALSE(r.technique->getStatistics().blendedRound);
        EXPECT_EQ(capture.count("no blended round yet"), blended ? 1 : 0) << capture.warnings();
    }
}
