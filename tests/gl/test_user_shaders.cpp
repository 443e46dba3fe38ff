// An application's own program on the receivers: linked with the technique's shadow shaders
// (addShadowShaders(), README "Your own shaders") it calls oss_shadowTerm() and its picture
// shows the exact shadow in every mode. The map modes read the term in the program's own
// pass; the stencil modes (SHADOW_VOLUME, HYBRID with stencil volumes) leave each light's
// stencil answer in a screen-space visibility image and draw the receivers once more with the
// program, whose term reads it. A program that fails to link is reported as a warning that
// names it.
#include "GLErrors.h"
#include "GLTestSupport.h"
#include "NotifyCapture.h"

#include <osg/Program>
#include <osgDB/FileUtils>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

// The program's colours: red carries the mask (1 lit, 0 shadowed or facing away from GL
// light 0); green 64 and blue 192 (of 255) tell its pixels from the technique's shading
// (grey levels) and the background (grey 128).
const char* const USER_VERTEX = R"(#version 400 compatibility
out vec4 userEyePosition;
void main()
{
    userEyePosition = gl_ModelViewMatrix * gl_Vertex;
    gl_Position = ftransform();
}
)";

const char* const USER_FRAGMENT = R"(#version 400 compatibility
in vec4 userEyePosition;
float oss_shadowTerm(int light, vec4 eyePosition);
void main()
{
    vec3 p = userEyePosition.xyz;
    vec3 n = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(n, -p) < 0.0) n = -n;
    vec4 lp = gl_LightSource[0].position;
    vec3 l = normalize(lp.w == 0.0 ? lp.xyz : lp.xyz / lp.w - p);
    float term = oss_shadowTerm(0, userEyePosition);
    float lit = dot(n, l) > 1e-3 && term >= 0.5 ? 1.0 : 0.0;
    gl_FragColor = vec4(lit, 64.0 / 255.0, 192.0 / 255.0, 1.0);
}
)";

osg::ref_ptr<osg::Program> userProgram(const char* fragment = USER_FRAGMENT)
{
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("application receivers");
    program->addShader(new osg::Shader(osg::Shader::VERTEX, USER_VERTEX));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, fragment));
    return program;
}

/** The picture's pixels by who drew them: the user program's as a mask (lit or not), the
 *  background; everything else (the technique's shading, or nothing of the program) is
 *  counted in `others` and left as background in the mask. */
struct UserPicture
{
    ossref::Mask mask;
    long long userPixels = 0;
    long long others = 0;
};

UserPicture readUserPicture(const osg::Image& image)
{
    UserPicture p;
    p.mask = ossref::Mask::filled(image.s(), image.t(), ossref::MASK_BACKGROUND);
    const unsigned int bytes = image.getPixelSizeInBits() / 8;
    const auto near = [](int value, int expected) { return std::abs(value - expected) <= 2; };
    for (int r = 0; r < p.mask.height; ++r)
    {
        const unsigned char* row = image.data(0, unsigned(p.mask.height - 1 - r));
        for (int x = 0; x < p.mask.width; ++x)
        {
            const unsigned char* px = row + x * bytes;
            if (near(px[0], 128) && near(px[1], 128) && near(px[2], 128)) continue;
            if (near(px[1], 64) && near(px[2], 192) && (near(px[0], 0) || near(px[0], 255)))
            {
                ++p.userPixels;
                p.mask.value[std::size_t(r) * p.mask.width + x] = px[0] > 128 ? ossref::MASK_LIT : ossref::MASK_NO_LIGHT;
            }
            else
                ++p.others;
        }
    }
    return p;
}

/** A frame of `r` on the background grey, read as a UserPicture. */
UserPicture renderUserPicture(ShadowedRender& r)
{
    const osg::ref_ptr<osg::Image> image =
        r.renderer->renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    return readUserPicture(*image);
}

struct ModeCase
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::HybridMethod method;
    bool stencil;       ///< a stencil mode: the program draws from the screen-space visibility
    double maxWrongPct; ///< measured with this test's scene and map size, plus a margin
};

class UserShaders : public ::testing::TestWithParam<ModeCase>
{
};

/** The default scene with the program on everything it draws, added to the program before
 *  the first frame. */
TEST_P(UserShaders, ProgramLinksAndShowsTheExactShadow)
{
    const ModeCase& c = GetParam();
    osstest::NotifyCapture notices;
    osshar::GLErrorCounter& errors = osshar::installGLErrorCounter();
    ShadowedRender r("default", c.mode, 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    ASSERT_EQ(r.scene.lights.size(), 1u);
    r.technique->setHybridMethod(c.method);
    osg::ref_ptr<osg::Program> program = userProgram();
    r.technique->addShadowShaders(program.get());
    r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
    errors.reset();
    r.renderer->timeFrames(0, 3);
    const UserPicture picture = renderUserPicture(r);
    EXPECT_EQ(errors.count(), 0) << "OpenGL errors while the program drew in " << c.name;
    EXPECT_EQ(r.technique->getStatistics().triangleLists, c.method == SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    EXPECT_FALSE(notices.warned("failed to link")) << notices.warnings();
    EXPECT_EQ(r.technique->getStatistics().screenVisibility, c.stencil);
    const ossref::Mask reference = r.reference();
    // Every pixel of the scene drawn by the program.
    EXPECT_GT(picture.userPixels, 50000);
    EXPECT_EQ(picture.others, 0) << "pixels not drawn by the program";
    const ossref::Comparison cmp = ossref::compareMasks(picture.mask, reference);
    ASSERT_TRUE(cmp.valid) << cmp.error;
    std::cout << c.name << ": " << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels << "\n";
    EXPECT_LT(cmp.coverageMismatch, 10);
    EXPECT_LT(cmp.wrongPct, c.maxWrongPct) << cmp.wrongPixels << " wrong pixels of " << cmp.geometryPixels;
    // The technique's own mask (DebugView) is the same answer.
    const ossref::Comparison own = ossref::compareMasks(r.mask(0, 1), reference);
    ASSERT_TRUE(own.valid) << own.error;
    EXPECT_LT(own.wrongPct, c.maxWrongPct) << own.wrongPixels << " wrong pixels of the technique's mask";
}

INSTANTIATE_TEST_SUITE_P(
    Modes, UserShaders,
    // Measured at 512 x 384 with a map of 1024: 56 wrong pixels of 149259 (0.038%: the shadow
    // map's edge aliasing), 2, 1, 1 and 1.
    ::testing::Values(ModeCase{"shadowmap", "shadowmap", SilhouetteShadowTechnique::HYBRID_AUTO, false, 0.06},
                      ModeCase{"silhouette", "silhouette", SilhouetteShadowTechnique::HYBRID_AUTO, false, 0.01},
                      ModeCase{"volume", "volume", SilhouetteShadowTechnique::HYBRID_AUTO, true, 0.01},
                      ModeCase{"hybrid_lists", "hybrid", SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, false, 0.01},
                      ModeCase{"hybrid_stencil", "hybrid", SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, true,
                               0.01}),
    [](const ::testing::TestParamInfo<ModeCase>& info) { return std::string(info.param.name); });

// One program, given the shaders once in SHADOW_MAP, stays linked and right when the mode
// changes to those whose terms it calls through the other shaders, and to the stencil modes.
TEST(UserShaderModes, ProgramStaysValidWhenTheModeChanges)
{
    osstest::NotifyCapture notices;
    ShadowedRender r("default", "shadowmap", 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::Program> program = userProgram();
    r.technique->addShadowShaders(program.get());
    r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
    const ossref::Mask reference = r.reference();
    // The bounds of ProgramLinksAndShowsTheExactShadow's cases.
    struct Step
    {
        SilhouetteShadowTechnique::Mode mode;
        SilhouetteShadowTechnique::HybridMethod method;
        double maxWrongPct;
    };
    const Step steps[] = {{SilhouetteShadowTechnique::SHADOW_MAP, SilhouetteShadowTechnique::HYBRID_AUTO, 0.06},
                          {SilhouetteShadowTechnique::SILHOUETTE_MAP, SilhouetteShadowTechnique::HYBRID_AUTO, 0.01},
                          {SilhouetteShadowTechnique::HYBRID, SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS, 0.01},
                          {SilhouetteShadowTechnique::SHADOW_VOLUME, SilhouetteShadowTechnique::HYBRID_AUTO, 0.01},
                          {SilhouetteShadowTechnique::HYBRID, SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES, 0.01},
                          {SilhouetteShadowTechnique::SHADOW_MAP, SilhouetteShadowTechnique::HYBRID_AUTO, 0.06}};
    for (const Step& step : steps)
    {
        r.technique->setMode(step.mode);
        r.technique->setHybridMethod(step.method);
        r.renderer->timeFrames(0, 3);
        EXPECT_EQ(r.technique->getStatistics().effectiveMode, step.mode);
        const UserPicture picture = renderUserPicture(r);
        EXPECT_GT(picture.userPixels, 50000) << "mode " << step.mode;
        EXPECT_EQ(picture.others, 0) << "mode " << step.mode;
        const ossref::Comparison cmp = ossref::compareMasks(picture.mask, reference);
        ASSERT_TRUE(cmp.valid) << cmp.error;
        EXPECT_LT(cmp.wrongPct, step.maxWrongPct) << "mode " << step.mode << ": " << cmp.wrongPixels << " wrong pixels";
    }
    EXPECT_FALSE(notices.warned("failed to link")) << notices.warnings();
}

/** USER_FRAGMENT for GL light `light` instead of light 0. */
std::string userFragmentFor(int light)
{
    std::string source = USER_FRAGMENT;
    for (const std::string& call : {std::string("oss_shadowTerm(0,"), std::string("gl_LightSource[0]")})
    {
        const std::size_t at = source.find(call);
        source.replace(at, call.size(), call.substr(0, call.size() - 2) + std::to_string(light) + call.back());
    }
    return source;
}

// Two lights (a directional one and a point light with its cube faces), each with its own
// bit of the stencil modes' visibility: the program's mask of either light is the exact one.
TEST(UserShaderModes, StencilModesKeepEachLightsAnswer)
{
    osshar::RenderOptions options;
    options.scene = "default";
    options.lights = {osshar::LightArg::toward(osg::Vec3d(0.45, -0.35, 0.82)),
                      osshar::LightArg::at(osg::Vec3d(-6.0, -2.6, 10.0))};
    for (const char* mode : {"volume", "hybrid"})
    {
        ShadowedRender r(options, mode, 1024, 512, 384);
        ASSERT_TRUE(r.valid());
        ASSERT_EQ(r.scene.lights.size(), 2u);
        r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
        for (int light = 0; light < 2; ++light)
        {
            osg::ref_ptr<osg::Program> program = userProgram(userFragmentFor(light).c_str());
            r.technique->addShadowShaders(program.get());
            r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
            r.renderer->timeFrames(0, 3);
            EXPECT_TRUE(r.technique->getStatistics().screenVisibility) << mode;
            EXPECT_EQ(r.technique->getStatistics().lightsShadowed, 2u) << mode;
            const UserPicture picture = renderUserPicture(r);
            EXPECT_GT(picture.userPixels, 50000) << mode << " light " << light;
            const ossref::Comparison cmp = ossref::compareMasks(picture.mask, r.reference(light));
            ASSERT_TRUE(cmp.valid) << cmp.error;
            std::cout << mode << " light " << light << ": " << cmp.wrongPixels << " wrong pixels of "
                      << cmp.geometryPixels << "\n";
            EXPECT_LT(cmp.wrongPct, 0.01) << mode << " light " << light << ": " << cmp.wrongPixels << " wrong pixels";
        }
    }
}

// The stencil modes draw from the visibility only while a program given to
// addShadowShaders() lives: without one, the technique's additive passes draw as before.
TEST(UserShaderModes, StencilPassesReturnWhenTheProgramIsGone)
{
    ShadowedRender r("default", "volume", 1024, 512, 384);
    ASSERT_TRUE(r.valid());
    {
        osg::ref_ptr<osg::Program> program = userProgram();
        r.technique->addShadowShaders(program.get());
        r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
        r.renderer->timeFrames(0, 2);
        EXPECT_TRUE(r.technique->getStatistics().screenVisibility);
        r.scene.content->getOrCreateStateSet()->removeAttribute(program.get());
    }
    r.renderer->timeFrames(0, 2);
    EXPECT_FALSE(r.technique->getStatistics().screenVisibility);
    const UserPicture picture = renderUserPicture(r);
    EXPECT_EQ(picture.userPixels, 0);
    const ossref::Comparison cmp = ossref::compareMasks(r.mask(0, 1), r.reference());
    ASSERT_TRUE(cmp.valid) << cmp.error;
    EXPECT_LT(cmp.wrongPct, 0.01) << cmp.wrongPixels << " wrong pixels";
}

// A fragment stage that calls a function no shader defines: it compiles, and fails to link.
const char* const BROKEN_FRAGMENT = R"(#version 400 compatibility
in vec4 userEyePosition;
float oss_shadowTerm(int light, vec4 eyePosition);
float userUndefinedTerm(vec4 eyePosition);
void main()
{
    gl_FragColor = vec4(oss_shadowTerm(0, userEyePosition) * userUndefinedTerm(userEyePosition));
}
)";

std::size_t occurrences(const std::string& text, const std::string& part)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// The program given to addShadowShaders() that fails to link is named in one warning, with
// the GL log (which names what is missing), however many frames draw it.
TEST(UserShaderLink, FailureOfTheProgramIsReportedOnce)
{
    osstest::NotifyCapture notices;
    ShadowedRender r("default", "shadowmap", 256, 256, 192);
    ASSERT_TRUE(r.valid());
    osg::ref_ptr<osg::Program> program = userProgram(BROKEN_FRAGMENT);
    r.technique->addShadowShaders(program.get());
    r.scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
    r.renderer->timeFrames(0, 4);
    const std::string warnings = notices.warnings();
    EXPECT_EQ(occurrences(warnings, "program \"application receivers\" failed to link"), 1u) << warnings;
    EXPECT_EQ(occurrences(warnings, "failed to link"), 1u) << warnings;
    EXPECT_NE(warnings.find("userUndefinedTerm"), std::string::npos) << warnings;
}

// A program of the technique's own that fails to link (here its receiver shading, from a
// broken replacement of oss_receiver.frag.glsl found through the data file path) is named
// in a warning too.
TEST(UserShaderLink, FailureOfTheTechniquesProgramIsReported)
{
    const std::string dir = ::testing::TempDir() + "oss_user_shaders";
    osgDB::makeDirectory(dir + "/osgShadowSilhouette/shaders");
    const std::string file = dir + "/osgShadowSilhouette/shaders/oss_receiver.frag.glsl";
    {
        std::ofstream out(file);
        out << BROKEN_FRAGMENT;
    }
    osgDB::FilePathList saved = osgDB::getDataFilePathList();
    osgDB::getDataFilePathList().push_front(dir);
    osstest::NotifyCapture notices;
    {
        ShadowedRender r("default", "shadowmap", 256, 256, 192);
        EXPECT_TRUE(r.valid());
        if (r.valid()) r.renderer->timeFrames(0, 3);
    }
    osgDB::setDataFilePathList(saved);
    std::remove(file.c_str());
    const std::string warnings = notices.warnings();
    EXPECT_EQ(occurrences(warnings, "program \"osgShadowSilhouette receiver\" failed to link"), 1u) << warnings;
    EXPECT_EQ(occurrences(warnings, "failed to link"), 1u) << warnings;
}

} // namespace
