// Stress: scenes far from the origin, very small and very large, a depth range of 1e8, and
// shadow edges placed exactly on the texel grid of the shadow map, in every mode.
#include "StressSupport.h"

using namespace osstest;

namespace {

/** Texel of the 257-texel map fitted to the default scene's 24-unit ground seen whole with
 *  the light straight down: fitDirectionalFrustum() makes texels extent / (size - 1) wide on
 *  a grid through the light-space origin (test_stress_cpu.cpp checks this). */
constexpr unsigned int GRID_MAP_SIZE = 257;
constexpr float TEXEL = 24.0f / 256.0f;

/** The default scene, light straight down, seen from high above so that the whole ground
 *  is in view (the light frustum is then fitted to the ground exactly). */
ShadowedRender gridRender(const char* mode)
{
    ShadowedRender r = stressRender(mode, GRID_MAP_SIZE);
    if (!r.valid()) return r;
    lightOf(r)->setPosition(osg::Vec4(0, 0, 1, 0));
    r.scene.view = {osg::Vec3d(0.3, -6, 40), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1), 40.0};
    r.renderer->setView(r.scene.view);
    return r;
}

} // namespace

void sceneMillionUnitsFromTheOrigin(const char* mode, bool stencilVolumes = false)
{
    ShadowedRender r = stressRender(mode, 2048);
    ASSERT_TRUE(r.valid());
    if (stencilVolumes) r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    transformScene(r, osg::Matrixd::translate(1e6, -7e5, 3e5));
    // The reference's BVH holds floats 1e6 from the origin (1/16 unit apart): its own edges
    // move by that much, about 0.15 pixel here; the claims hold all the same.
    expectWithinBound(r, bounds::CLAIMED.of(mode));
}

TEST_P(MapMode, SceneMillionUnitsFromTheOrigin)
{
    sceneMillionUnitsFromTheOrigin(GetParam());
}

// The stencil passes' state-change drawables (stencil clear, GPU counters) once had a unit
// box around the world origin: 1e6 away, it pushed the view's computed far plane out and
// its near plane (far x NearFarRatio) past the whole scene, so nothing was drawn.
TEST_P(StencilMode, SceneMillionUnitsFromTheOrigin)
{
    sceneMillionUnitsFromTheOrigin(GetParam());
}

TEST(StressScale, SceneMillionUnitsFromTheOriginHybridWithStencilVolumes)
{
    sceneMillionUnitsFromTheOrigin("hybrid", true);
}

TEST_P(StressMode, SceneScaledDownBy1e4)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    transformScene(r, osg::Matrixd::scale(1e-4, 1e-4, 1e-4));
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

TEST_P(StressMode, SceneScaledUpBy1e4)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    transformScene(r, osg::Matrixd::scale(1e4, 1e4, 1e4));
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// Near plane 1e-2 and far plane 1e6, fixed (OSG's near/far computation off): the eye's
// 24-bit depth buffer has little precision left at the scene.
TEST_P(StressMode, NearOneHundredthFarOneMillion)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    osg::Camera* camera = r.renderer->viewer().getCamera();
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setProjectionMatrixAsPerspective(r.scene.view.fovy, double(STRESS_WIDTH) / STRESS_HEIGHT, 1e-2, 1e6);
    expectWithinBound(r, bounds::DEEP_DEPTH_RANGE.of(GetParam()));
}

// A box whose edges lie exactly on texel boundaries of the shadow map.
TEST_P(StressMode, SilhouetteEdgesOnTexelBoundaries)
{
    ShadowedRender r = gridRender(GetParam());
    ASSERT_TRUE(r.valid());
    const std::vector<osg::Vec3> t =
        boxTriangles(osg::Vec3(-40 * TEXEL, -54 * TEXEL, 1.0f), osg::Vec3(-20 * TEXEL, -34 * TEXEL, 2.0f));
    addToScene(r, flatTriangles(t, "grid box").get());
    // Depth-map answers exactly on texel boundaries may flip from one frame to the next, so
    // the float frame is allowed to differ from the ordinary one in more pixels.
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()), 0, ~0u, 6.0);
}

// A prism whose cross-section is a square turned 45 degrees with its corners on texel
// corners: its silhouette edges run exactly along texel diagonals.
TEST_P(StressMode, SilhouetteEdgesOnTexelDiagonals)
{
    ShadowedRender r = gridRender(GetParam());
    ASSERT_TRUE(r.valid());
    const osg::Vec3 c(-30 * TEXEL, -44 * TEXEL, 0.0f);
    const float a = 12 * TEXEL, lo = 1.0f, hi = 2.0f;
    const osg::Vec3 ring[4] = {c + osg::Vec3(a, 0, 0), c + osg::Vec3(0, a, 0), c + osg::Vec3(-a, 0, 0),
                               c + osg::Vec3(0, -a, 0)};
    std::vector<osg::Vec3> t;
    for (int i = 0; i < 4; ++i)
    {
        const osg::Vec3 p = ring[i], q = ring[(i + 1) % 4];
        addQuad(t, p + osg::Vec3(0, 0, lo), q + osg::Vec3(0, 0, lo), q + osg::Vec3(0, 0, hi), p + osg::Vec3(0, 0, hi));
    }
    addQuad(t, ring[0] + osg::Vec3(0, 0, hi), ring[1] + osg::Vec3(0, 0, hi), ring[2] + osg::Vec3(0, 0, hi),
            ring[3] + osg::Vec3(0, 0, hi));
    addQuad(t, ring[3] + osg::Vec3(0, 0, lo), ring[2] + osg::Vec3(0, 0, lo), ring[1] + osg::Vec3(0, 0, lo),
            ring[0] + osg::Vec3(0, 0, lo));
    addToScene(r, flatTriangles(t, "diagonal prism").get());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()), 0, ~0u, 6.0);
}

INSTANTIATE_TEST_SUITE_P(Modes, StressMode, ::testing::ValuesIn(STRESS_MODES));
INSTANTIATE_TEST_SUITE_P(Modes, StencilMode, ::testing::ValuesIn(STENCIL_MODES));
INSTANTIATE_TEST_SUITE_P(Modes, MapMode, ::testing::ValuesIn(MAP_MODES));
