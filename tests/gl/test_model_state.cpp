// The technique amid the state that real models bring: quads, lines and points, textures on
// several units, a program of their own, a material, blending, vertex colours, image and
// storage-buffer bindings. Every mode renders such a model with no OpenGL error, and its
// shadow matches the exact reference; the parts of a figure that touch each other (closed
// boxes sharing faces, as a robot's limbs meet its body) cast one whole shadow.
#include "GLErrors.h"
#include "GLTestSupport.h"
#include "Meshes.h"

#include <osgShadowSilhouette/TriangleListPass>

#include <osg/BindImageTexture>
#include <osg/BlendFunc>
#include <osg/BufferIndexBinding>
#include <osg/Material>
#include <osg/Program>
#include <osg/Texture2D>

#include <iostream>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

/** A box of GL_QUADS (harness makeBox's faces, each one quad): a closed mesh as exporters
 *  write them. */
osg::ref_ptr<osg::Geometry> makeQuadBox(const osg::Vec3& c, const osg::Vec3& size)
{
    osg::ref_ptr<osg::Geometry> box = osshar::makeBox(c, size);
    const auto* triangles = static_cast<const osg::DrawElementsUInt*>(box->getPrimitiveSet(0));
    osg::ref_ptr<osg::DrawElementsUShort> quads = new osg::DrawElementsUShort(GL_QUADS);
    for (std::size_t i = 0; i + 5 < triangles->size(); i += 6) // each face: (a b c) (a c d)
        for (std::size_t k : {0, 1, 2, 5}) quads->push_back(static_cast<GLushort>((*triangles)[i + k]));
    box->setPrimitiveSet(0, quads.get());
    return box;
}

osg::ref_ptr<osg::Texture2D> checkerTexture(const osg::Vec4ub& a, const osg::Vec4ub& b)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            *reinterpret_cast<osg::Vec4ub*>(image->data(x, y)) = ((x + y) % 2) ? a : b;
    return new osg::Texture2D(image.get());
}

/** Per-vertex colours and texture coordinates on units 0 and 1, as a textured model's
 *  geometry carries them (OSG draws texture coordinates on the context's
 *  GL_MAX_TEXTURE_COORDS units only, 8 here). */
void addVertexData(osg::Geometry& g)
{
    const auto* vertices = static_cast<const osg::Vec3Array*>(g.getVertexArray());
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    osg::ref_ptr<osg::Vec2Array> uv = new osg::Vec2Array;
    for (const osg::Vec3& v : *vertices)
    {
        colours->push_back(osg::Vec4(0.5f + 0.1f * v.x(), 0.6f, 0.7f, 1.0f));
        uv->push_back(osg::Vec2(v.x() + v.z(), v.y() + v.z()));
    }
    g.setColorArray(colours.get(), osg::Array::BIND_PER_VERTEX);
    for (unsigned int unit : {0u, 1u}) g.setTexCoordArray(unit, uv.get(), osg::Array::BIND_PER_VERTEX);
}

/** The state of a textured, blended model: textures on units 0, 1 and `highUnit` (one the
 *  technique's maps take by default), a material tracking the vertex colours, blending, and
 *  an image and a storage buffer bound where HYBRID's lists are read (image unit 0, buffer
 *  binding 1). */
osg::ref_ptr<osg::StateSet> modelState(unsigned int highUnit)
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setTextureAttributeAndModes(0, checkerTexture({230, 200, 160, 255}, {180, 140, 100, 255}));
    ss->setTextureAttributeAndModes(1, checkerTexture({255, 255, 255, 255}, {200, 200, 200, 255}));
    ss->setTextureAttributeAndModes(highUnit, checkerTexture({0, 0, 0, 255}, {255, 255, 255, 255}));
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setColorMode(osg::Material::AMBIENT_AND_DIFFUSE);
    ss->setAttributeAndModes(material.get());
    ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    osg::ref_ptr<osg::Texture2D> image = checkerTexture({10, 20, 30, 40}, {50, 60, 70, 80});
    ss->setAttributeAndModes(new osg::BindImageTexture(0, image.get(), osg::BindImageTexture::READ_ONLY, GL_RGBA8));
    osg::ref_ptr<osg::FloatArray> data = new osg::FloatArray(64);
    data->setBufferObject(new osg::ShaderStorageBufferObject);
    ss->setAttributeAndModes(new osg::ShaderStorageBufferBinding(1, data.get(), 0, 64 * sizeof(float)));
    return ss;
}

/** A program of the model's own, as a shader-based exporter gives one. */
osg::ref_ptr<osg::Program> modelProgram()
{
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 120\n"
                                                            "varying vec4 colour;\n"
                                                            "void main() { colour = gl_Color; gl_Position = ftransform(); }\n"));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, "#version 120\n"
                                                              "varying vec4 colour;\n"
                                                              "void main() { gl_FragColor = colour; }\n"));
    return program;
}

/** Lines and points among the model's drawables (an outline, markers), around c. */
osg::ref_ptr<osg::Geometry> linesAndPoints(const osg::Vec3& c)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec3& d : {osg::Vec3(-0.8f, -0.3f, -0.3f), osg::Vec3(0.8f, -0.3f, -0.3f), osg::Vec3(0.8f, -0.3f, 0.3f),
                               osg::Vec3(-0.8f, -0.3f, 0.3f)})
        v->push_back(c + d);
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_LINE_LOOP, 0, 4));
    g->addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, 4));
    return g;
}

/** A figure of closed boxes that touch: a body, two arms against its sides, two legs under
 *  it and a head on top, sharing whole faces or parts of them (GL_QUADS, or triangles where
 *  `quads` is false). */
osg::ref_ptr<osg::Geode> figure(bool quads)
{
    const auto box = [quads](const osg::Vec3& c, const osg::Vec3& size) {
        return quads ? makeQuadBox(c, size) : osshar::makeBox(c, size);
    };
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(box(osg::Vec3(0, 0, 1.5f), osg::Vec3(2, 1, 1)));           // body, z 1..2
    geode->addDrawable(box(osg::Vec3(-1.25f, 0, 1.5f), osg::Vec3(0.5f, 0.5f, 1))); // arms against x = -1, 1
    geode->addDrawable(box(osg::Vec3(1.25f, 0, 1.5f), osg::Vec3(0.5f, 0.5f, 1)));
    geode->addDrawable(box(osg::Vec3(-0.5f, 0, 0.5f), osg::Vec3(0.8f, 0.8f, 1)));  // legs under z = 1
    geode->addDrawable(box(osg::Vec3(0.5f, 0, 0.5f), osg::Vec3(0.8f, 0.8f, 1)));
    geode->addDrawable(box(osg::Vec3(0, 0, 2.25f), osg::Vec3(1, 0.8f, 0.5f)));      // head on z = 2
    return geode;
}

/** The figure with the state of a real model: vertex data and modelState() on every part,
 *  lines and points, and a part drawn by the model's own program (the last two inside the
 *  body, where neither the camera nor the light sees them: the reference has no lines, and
 *  the model's own program does not shade with the technique). */
osg::ref_ptr<osg::Node> stateRichModel(unsigned int highUnit)
{
    osg::ref_ptr<osg::Geode> geode = figure(true);
    for (unsigned int i = 0; i < geode->getNumDrawables(); ++i) addVertexData(*geode->getDrawable(i)->asGeometry());
    geode->setStateSet(modelState(highUnit).get());
    geode->addDrawable(linesAndPoints(osg::Vec3(0, 0, 1.5f)));
    osg::ref_ptr<osg::Geometry> inner = osshar::makeBox(osg::Vec3(0, 0, 1.5f), osg::Vec3(1, 0.5f, 0.5f));
    inner->getOrCreateStateSet()->setAttributeAndModes(modelProgram().get());
    geode->addDrawable(inner.get());
    return geode;
}

/** `model` on the 16 x 16 ground of the renderer's --ground, lit from (0.5, -0.6, 0.6). */
osshar::PreparedScene onGround(osg::Node* model)
{
    osshar::Scene placed = osshar::placeOnGround(model, "model");
    osshar::PreparedScene scene;
    scene.content = placed.root;
    scene.view = placed.view;
    scene.content->addChild(osshar::makeLight(osg::Vec4(0.5f, -0.6f, 0.6f, 0.0f)));
    scene.lights = osshar::findLights(scene.content.get());
    return scene;
}

struct ModeCase
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
    double maxWrongPct; ///< measured with this test's scene and map size, plus a margin
};

class ModelState : public ::testing::TestWithParam<ModeCase>
{
};

TEST_P(ModelState, NoGLErrorAndTheExactShadow)
{
    const ModeCase& c = GetParam();
    osshar::GLErrorCounter& errors = osshar::installGLErrorCounter();
    const unsigned int mapUnit = osg::ref_ptr<SilhouetteShadowTechnique>(new SilhouetteShadowTechnique)->getBaseTextureUnit();
    ShadowedRender r(onGround(stateRichModel(mapUnit).get()), c.mode, 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(c.method);
    errors.reset();
    const ossref::Mask mask = r.mask(0, 4);
    EXPECT_EQ(errors.count(), 0) << "OpenGL errors while " << c.name << " rendered the model";
    const ossref::Comparison cmp = ossref::compareMasks(mask, r.reference());
    ASSERT_TRUE(cmp.valid) << cmp.error;
    std::cout << c.name << ": " << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels << "\n";
    EXPECT_LT(cmp.coverageMismatch, 10);
    EXPECT_LT(cmp.wrongPct, c.maxWrongPct) << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels;
}

INSTANTIATE_TEST_SUITE_P(
    Modes, ModelState,
    ::testing::Values(ModeCase{"shadowmap", "shadowmap", SilhouetteShadowTechnique::HYBRID_AUTO, 0.15},
                      ModeCase{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO, 0.02},
                      // 365 wrong pixels (0.21%): the volumes' caps split the quads along
                      // the other diagonal than the rasterizer, and a lit face of an arm
                      // shadows itself in stripes (docs/shadow-volumes.md, "Quads").
                      ModeCase{"volume", "volume", SilhouetteShadowTechnique::HYBRID_AUTO, 0.25},
                      ModeCase{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 0.01},
                      ModeCase{"hybrid_stencil", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 0.01}),
    [](const ::testing::TestParamInfo<ModeCase>& info) { return std::string(info.param.name); });

// The exact test must not leak where a ray caster does not: a shadow ray from the ground
// that leaves the figure through the seam between two touching parts meets the face of one
// of them. A map of 256 makes most of the figure's shadow silhouette pixels.
class TouchingParts : public ::testing::TestWithParam<bool>
{
};

TEST_P(TouchingParts, CastOneWholeShadow)
{
    osshar::GLErrorCounter& errors = osshar::installGLErrorCounter();
    ShadowedRender r(onGround(figure(GetParam()).get()), "hybrid", 256, 512, 384);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    errors.reset();
    const ossref::Mask mask = r.mask(0, 4);
    EXPECT_EQ(errors.count(), 0);
    EXPECT_TRUE(r.technique->getStatistics().triangleLists);
    const ossref::Comparison cmp = ossref::compareMasks(mask, r.reference());
    ASSERT_TRUE(cmp.valid) << cmp.error;
    std::cout << (GetParam() ? "quads" : "triangles") << ": " << cmp.wrongPixels << " wrong pixels of "
              << cmp.geometryPixels << "\n";
    EXPECT_LT(cmp.wrongPct, 0.01) << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels;
}

INSTANTIATE_TEST_SUITE_P(Figures, TouchingParts, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return std::string(info.param ? "Quads" : "Triangles");
                         });

// The stand-ins: a geometry of triangles is drawn as it is, one of quads as its triangles on
// the same vertex array (rebuilt when its primitives change), lines and points not at all.
TEST(ListedDrawables, DrawTrianglesOnly)
{
    osg::ref_ptr<osgShadowSilhouette::ListedDrawables> listed = new osgShadowSilhouette::ListedDrawables;
    osg::ref_ptr<osg::Geometry> triangles = osshar::makeBox(osg::Vec3(), osg::Vec3(1, 1, 1));
    EXPECT_EQ(listed->get(*triangles), triangles.get());

    osg::ref_ptr<osg::Geometry> quads = makeQuadBox(osg::Vec3(), osg::Vec3(1, 1, 1));
    quads->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, 2));
    osg::Geometry* standIn = listed->get(*quads)->asGeometry();
    ASSERT_NE(standIn, nullptr);
    EXPECT_NE(standIn, quads.get());
    EXPECT_EQ(standIn->getVertexArray(), quads->getVertexArray());
    ASSERT_EQ(standIn->getNumPrimitiveSets(), 1u);
    const osg::PrimitiveSet& faces = *standIn->getPrimitiveSet(0);
    EXPECT_EQ(faces.getMode(), GLenum(GL_TRIANGLES));
    ASSERT_EQ(faces.getNumIndices(), 36u); // 6 quads, 12 triangles
    const auto* source = static_cast<const osg::DrawElementsUShort*>(quads->getPrimitiveSet(0));
    EXPECT_EQ(faces.index(3), (*source)[0]); // the second triangle of the first quad: a c d
    EXPECT_EQ(faces.index(4), (*source)[2]);
    EXPECT_EQ(faces.index(5), (*source)[3]);
    EXPECT_EQ(listed->get(*quads), standIn);

    quads->getPrimitiveSet(0)->dirty();
    EXPECT_NE(listed->get(*quads), standIn) << "a changed primitive set makes a new stand-in";

    osg::ref_ptr<osg::Geometry> lines = linesAndPoints(osg::Vec3());
    EXPECT_EQ(listed->get(*lines), nullptr);
}

} // namespace
