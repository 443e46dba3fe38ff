// Casters placed by their own vertex shaders (a displacement, an attribute-driven lift: what
// a skinning shader does) cast the shape the eye sees in the passes that draw the scene:
// the depth maps and HYBRID's triangle lists run the caster's vertex stage with their own
// other stages (CasterVertexStages.h). Scored against the exact reference of the same scene
// with the displacement applied on the CPU.
#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"
#include "MovedCasters.h"
#include "NotifyCapture.h"

#include <osg/Geode>
#include <osg/Program>

#include <cmath>

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::FixedBound;
using osstest::PLAIN_FRAGMENT;
using osstest::ShadowedRender;

namespace {

// Where the shaders move the casters from: far from where they cast, so that a pass that
// drew them undeformed would shadow nothing in view (the sphere lies above the camera, the
// plate under the ground, neither seen by the eye either way).
const osg::Vec3 SPHERE_DRAWN(0, 0, 30), SPHERE_CAST(-0.5f, 0.3f, 4.2f);
const float PLATE_DRAWN_Z = -5.0f;

/** The sphere's displacement: moved down by SPHERE_CAST - SPHERE_DRAWN, then bent (x grows
 *  with sin(3 y)): a shape no rigid transform gives. */
const char* const SPHERE_VERTEX = R"(#version 400 compatibility
uniform vec3 displacement;
void main()
{
    vec4 v = gl_Vertex;
    v.xyz += displacement;
    v.x += 0.5 * sin(3.0 * v.y);
    gl_Position = gl_ModelViewProjectionMatrix * v;
    gl_FrontColor = gl_Color;
}
)";

/** The plate's lift comes from a vertex attribute bound by name, as a skinning shader's
 *  bone weights are (RigTransformHardware binds boneWeight0.. from location 11). */
const char* const PLATE_VERTEX = R"(#version 400 compatibility
in vec4 lift;
void main()
{
    vec4 v = gl_Vertex;
    v.z += lift.x;
    gl_Position = gl_ModelViewProjectionMatrix * v;
    gl_FrontColor = gl_Color;
}
)";

osg::Vec3 bentSphereVertex(const osg::Vec3& drawn)
{
    osg::Vec3 v = drawn + (SPHERE_CAST - SPHERE_DRAWN);
    v.x() += 0.5f * std::sin(3.0f * v.y());
    return v;
}

/** The lift of a plate vertex at (x, y): tilted, 3 to 4 units above the ground. */
float plateLift(float x, float y)
{
    return 3.0f - PLATE_DRAWN_Z + 0.25f * x + 0.1f * y;
}

osg::BoundingBox boundOf(const osg::Vec3Array& v)
{
    osg::BoundingBox box;
    for (const osg::Vec3& p : v) box.expandBy(p);
    return box;
}

osg::ref_ptr<osg::Program> program(const char* name, const char* vertex)
{
    osg::ref_ptr<osg::Program> p = new osg::Program;
    p->setName(name);
    p->addShader(new osg::Shader(osg::Shader::VERTEX, vertex));
    p->addShader(new osg::Shader(osg::Shader::FRAGMENT, PLAIN_FRAGMENT));
    // What the CPU's geometry cannot follow: SILHOUETTE_MAP's edges and the volumes leave
    // the casters it draws out (a program that draws the vertex array where it stands says
    // nothing and keeps them).
    p->setUserValue(SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE, true);
    return p;
}

/** The bent sphere: moved by its vertex shader (@p onGpu), or its vertices moved here. */
osg::ref_ptr<osg::Geometry> sphere(bool onGpu)
{
    osg::ref_ptr<osg::Geometry> g = osshar::makeSphere(SPHERE_DRAWN, 1.0f, 48, 24);
    g->setName("bent sphere");
    if (onGpu)
    {
        osg::StateSet* ss = g->getOrCreateStateSet();
        ss->setAttributeAndModes(program("bending", SPHERE_VERTEX).get());
        ss->addUniform(new osg::Uniform("displacement", SPHERE_CAST - SPHERE_DRAWN));
        osg::ref_ptr<osg::Vec3Array> moved = new osg::Vec3Array(*static_cast<osg::Vec3Array*>(g->getVertexArray()));
        for (osg::Vec3& p : *moved) p = bentSphereVertex(p);
        g->setComputeBoundingBoxCallback(new FixedBound(boundOf(*moved)));
        return g;
    }
    auto* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    for (osg::Vec3& p : *v) p = bentSphereVertex(p);
    v->dirty();
    g->dirtyBound();
    return g;
}

/** A plate of 6 x 6 quads (GL_QUADS: the lists draw a stand-in of its triangles) over
 *  x in [0.3, 2.1], y in [-2, -0.2], lifted by the `lift` attribute (@p onGpu) or here. */
osg::ref_ptr<osg::Geometry> plate(bool onGpu)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName("lifted plate");
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> lift = new osg::Vec4Array(osg::Array::BIND_PER_VERTEX);
    const int n = 6;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (const auto& c : {std::make_pair(i, j), std::make_pair(i + 1, j), std::make_pair(i + 1, j + 1),
                                  std::make_pair(i, j + 1)})
            {
                const float x = 0.3f + 0.3f * c.first, y = -2.0f + 0.3f * c.second;
                v->push_back(osg::Vec3(x, y, onGpu ? PLATE_DRAWN_Z : PLATE_DRAWN_Z + plateLift(x, y)));
                lift->push_back(osg::Vec4(plateLift(x, y), 0, 0, 0));
            }
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, GLsizei(v->size())));
    if (onGpu)
    {
        const unsigned int location = 11;
        g->setVertexAttribArray(location, lift.get());
        osg::ref_ptr<osg::Program> p = program("lifting", PLATE_VERTEX);
        p->addBindAttribLocation("lift", location);
        g->getOrCreateStateSet()->setAttributeAndModes(p.get());
        osg::ref_ptr<osg::Vec3Array> moved = new osg::Vec3Array(*v);
        for (std::size_t k = 0; k < moved->size(); ++k) (*moved)[k].z() += (*lift)[k].x();
        g->setComputeBoundingBoxCallback(new FixedBound(boundOf(*moved)));
    }
    return g;
}

/** A 24 x 24 ground, the sphere and the plate, a sun and a point light, and a camera 2.5
 *  above the ground looking straight down (it sees the ground alone). */
osshar::PreparedScene scene(bool onGpu)
{
    osshar::PreparedScene s;
    s.content = new osg::Group;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeGround(0, 0, 24).get());
    geode->addDrawable(sphere(onGpu).get());
    geode->addDrawable(plate(onGpu).get());
    s.content->addChild(geode.get());
    s.content->addChild(osshar::makeLight(osg::Vec4(0.3f, 0.2f, 1.0f, 0.0f), 0));
    s.content->addChild(osshar::makeLight(osg::Vec4(0.5f, 0.8f, 9.0f, 1.0f), 1));
    s.lights = osshar::findLights(s.content.get());
    s.view.eye = osg::Vec3d(0, 0, 2.5);
    s.view.center = osg::Vec3d(0, 0, 0);
    s.view.up = osg::Vec3d(0, 1, 0);
    s.view.fovy = 90.0;
    return s;
}

/** The share (%) of the mask's geometry pixels in shadow. */
double shadowedPct(const ossref::Mask& m)
{
    long long geometry = 0, shadowed = 0;
    for (uint8_t value : m.value)
    {
        if (value == ossref::MASK_BACKGROUND) continue;
        ++geometry;
        if (value == ossref::MASK_NO_LIGHT) ++shadowed;
    }
    return geometry ? 100.0 * double(shadowed) / double(geometry) : 0.0;
}

struct StageCase
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
};

class CasterVertexStage : public ::testing::TestWithParam<StageCase>
{
};

} // namespace

// The depth maps and the triangle lists draw the casters with their own vertex stages:
// shadows of the moved and bent shapes, within each mode's claim, under either light.
TEST_P(CasterVertexStage, CastsTheShapeTheShaderGives)
{
    const StageCase& c = GetParam();
    ShadowedRender r(scene(true), c.mode, 1024, 640, 480);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(c.method);
    const osshar::PreparedScene cpu = scene(false);
    for (unsigned int light = 0; light < 2; ++light)
    {
        const ossref::Mask reference =
            ossref::computeReferenceMask(*cpu.content, osshar::referenceCamera(cpu.view, 640, 480),
                                         osshar::referenceLight(cpu.lights.at(light)), ~0u, ~0u);
        const ossref::Comparison cmp = ossref::compareMasks(r.mask(light, 3), reference);
        ASSERT_TRUE(cmp.valid) << cmp.error;
        std::printf("%s light %u: %lld wrong pixels of %lld (%.4f%%), reference %.1f%% shadowed\n", c.name, light,
                    cmp.wrongPixels, cmp.geometryPixels, cmp.wrongPct, shadowedPct(reference));
        EXPECT_GT(shadowedPct(reference), 5.0) << "the shapes' shadows must lie in view";
        EXPECT_EQ(cmp.coverageMismatch, 0);
        EXPECT_LT(cmp.wrongPct, osstest::bounds::CLAIMED.of(c.mode)) << "light " << light;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Modes, CasterVertexStage,
    ::testing::Values(StageCase{"shadowmap", "shadowmap", SilhouetteShadowTechnique::HYBRID_AUTO},
                      StageCase{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS},
                      StageCase{"hybrid_stencil", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES},
                      StageCase{"volume", "volume", SilhouetteShadowTechnique::HYBRID_AUTO},
                      StageCase{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO}),
    [](const auto& info) { return std::string(info.param.name); });

// The silhouette edges of these casters are found and their shadow volumes extruded on the GPU
// (GpuEdges.h, GpuVolumes.h), behind their own vertex stages: every mode casts them (the test
// above) and none says it leaves them out. (Measured before the GPU's edges: SILHOUETTE_MAP
// gave them the depth map's edges, 0.0599% and 0.1035% wrong, and named them; before the
// GPU's volumes SHADOW_VOLUME shadowed nothing of theirs, 18.2% and 48.9% of the view wrong.)
TEST(CasterVertexStageWarnings, NoModeLeavesTheCastersOut)
{
    for (const char* mode : {"volume", "hybrid", "silhouette"})
    {
        osstest::NotifyCapture capture;
        ShadowedRender r(scene(true), mode, 1024, 320, 240);
        ASSERT_TRUE(r.valid());
        r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
        r.mask(0, 3);
        r.mask(1, 2);
        EXPECT_EQ(capture.count("bent sphere"), 0) << mode << ": " << capture.warnings();
        EXPECT_EQ(capture.count("lifted plate"), 0) << mode << ": " << capture.warnings();
    }
}
