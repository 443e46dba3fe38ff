// Animated characters skinned in a vertex shader (osgAnimation's RigTransformHardware) keep
// their vertex arrays, primitive sets, matrices and bounds from frame to frame: only a uniform
// (the bones' matrix palette) moves them. A light pass drawn through such a caster's vertex
// stage must be drawn again when that uniform changes, not kept from an earlier frame: the
// casters' signature takes in the versions of the uniforms on the path of a caster whose
// program moves its vertices (CasterSignatureVisitor). Without that, the second pose is
// 13.54% wrong in every mode below (the first pose's shadow kept).
#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"
#include "MovedCasters.h"

#include <osg/Geode>
#include <osg/Program>

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::FixedBound;
using osstest::PLAIN_FRAGMENT;
using osstest::ShadowedRender;

namespace {

const osg::Vec3 SPHERE_DRAWN(0, 0, 30);
/** Where the uniform puts the sphere: first over one side of the view, then over the other. */
const osg::Vec3 FIRST_POSE(-1.0f, 0.0f, 3.0f), SECOND_POSE(1.0f, 0.0f, 3.0f);

const char* const MOVING_VERTEX = R"(#version 400 compatibility
uniform vec3 displacement;
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * vec4(gl_Vertex.xyz + displacement, 1.0);
    gl_FrontColor = gl_Color;
}
)";

/** A 24 x 24 ground and a sphere, moved by its vertex shader (@p onGpu: by the uniform
 *  `displacement`, from SPHERE_DRAWN to @p pose) or placed at @p pose here; a sun, and a
 *  camera looking straight down on the ground. */
osshar::PreparedScene scene(bool onGpu, const osg::Vec3& pose, osg::ref_ptr<osg::Uniform>* displacement = nullptr)
{
    osshar::PreparedScene s;
    s.content = new osg::Group;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(osshar::makeGround(0, 0, 24).get());
    osg::ref_ptr<osg::Geometry> sphere = osshar::makeSphere(onGpu ? SPHERE_DRAWN : pose, 0.8f, 48, 24);
    sphere->setName("moving sphere");
    if (onGpu)
    {
        osg::ref_ptr<osg::Program> program = new osg::Program;
        program->setName("moving");
        program->addShader(new osg::Shader(osg::Shader::VERTEX, MOVING_VERTEX));
        program->addShader(new osg::Shader(osg::Shader::FRAGMENT, PLAIN_FRAGMENT));
        program->setUserValue(SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE, true);
        osg::StateSet* ss = sphere->getOrCreateStateSet();
        ss->setAttributeAndModes(program.get());
        osg::ref_ptr<osg::Uniform> uniform = new osg::Uniform("displacement", pose - SPHERE_DRAWN);
        ss->addUniform(uniform.get());
        if (displacement) *displacement = uniform;
        osg::BoundingBox both;
        for (const osg::Vec3& p : {FIRST_POSE, SECOND_POSE}) both.expandBy(osg::BoundingSphere(p, 0.8f));
        sphere->setComputeBoundingBoxCallback(new FixedBound(both));
    }
    geode->addDrawable(sphere.get());
    s.content->addChild(geode.get());
    s.content->addChild(osshar::makeLight(osg::Vec4(0.2f, 0.1f, 1.0f, 0.0f), 0));
    s.lights = osshar::findLights(s.content.get());
    s.view.eye = osg::Vec3d(0, 0, 2.0);
    s.view.center = osg::Vec3d(0, 0, 0);
    s.view.up = osg::Vec3d(0, 1, 0);
    s.view.fovy = 100.0;
    return s;
}

struct MovedCase
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
};

class UniformMovedCaster : public ::testing::TestWithParam<MovedCase>
{
};

} // namespace

// Only the uniform changes between the two poses: the shadow follows the sphere to its
// second pose, within the mode's claim, as it stands at its first.
TEST_P(UniformMovedCaster, ShadowFollowsTheUniform)
{
    const MovedCase& c = GetParam();
    osg::ref_ptr<osg::Uniform> displacement;
    ShadowedRender r(scene(true, FIRST_POSE, &displacement), c.mode, 1024, 480, 360);
    ASSERT_TRUE(r.valid());
    r.technique->setHybridMethod(c.method);
    const std::string mode = c.mode;
    const double claim = osstest::bounds::CLAIMED.of(mode == "silhouette" ? "shadowmap" : mode);
    for (const osg::Vec3& pose : {FIRST_POSE, SECOND_POSE})
    {
        displacement->set(pose - SPHERE_DRAWN);
        const osshar::PreparedScene cpu = scene(false, pose);
        const ossref::Mask reference =
            ossref::computeReferenceMask(*cpu.content, osshar::referenceCamera(cpu.view, 480, 360),
                                         osshar::referenceLight(cpu.lights.at(0)), ~0u, ~0u);
        const ossref::Comparison cmp = ossref::compareMasks(r.mask(0, 3), reference);
        ASSERT_TRUE(cmp.valid) << cmp.error;
        std::printf("%s, pose x = %.1f: %lld wrong pixels of %lld (%.4f%%)\n", c.name, pose.x(), cmp.wrongPixels,
                    cmp.geometryPixels, cmp.wrongPct);
        EXPECT_LT(cmp.wrongPct, claim) << "pose x = " << pose.x();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Modes, UniformMovedCaster,
    ::testing::Values(MovedCase{"shadowmap", "shadowmap", SilhouetteShadowTechnique::HYBRID_AUTO},
                      MovedCase{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS},
                      MovedCase{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO}),
    [](const auto& info) { return std::string(info.param.name); });
