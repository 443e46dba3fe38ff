// Stress: viewer configurations. Two views, multi-threaded viewers, window resizes, a
// context destroyed and re-created, a map size beyond the GL limit. Every case asserts a
// finite image and, where a reference applies, wrong_pct within the bound of its mode.
#include "StressSupport.h"

#include <osg/ContextData>
#include <osg/BufferObject>
#include <osg/GLObjects>
#include <osg/Texture>
#include <osgViewer/CompositeViewer>

using namespace osstest;

namespace {

class NoSwap : public osg::GraphicsContext::SwapCallback
{
public:
    void swapBuffersImplementation(osg::GraphicsContext*) override {}
};

/** Reads the camera's viewport (GL_UNSIGNED_BYTE RGB) after it has drawn. */
struct ReadViewport : public osg::Camera::DrawCallback
{
    void operator()(osg::RenderInfo& ri) const override
    {
        const osg::Viewport* vp = ri.getCurrentCamera()->getViewport();
        glReadBuffer(GL_BACK);
        image->readPixels(int(vp->x()), int(vp->y()), int(vp->width()), int(vp->height()), GL_RGB, GL_UNSIGNED_BYTE);
    }
    osg::ref_ptr<osg::Image> image = new osg::Image;
};

/** Two views of one shadowed scene side by side in one pbuffer, in a CompositeViewer. */
struct TwoViews
{
    static constexpr int W = 320, H = 480;
    osshar::PreparedScene scene;
    osg::ref_ptr<SilhouetteShadowTechnique> technique;
    osg::ref_ptr<osg::Node> root;
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    osshar::View views[2];
    osg::ref_ptr<ReadViewport> reads[2] = {new ReadViewport, new ReadViewport};

    explicit TwoViews(const char* mode)
    {
        osshar::RenderOptions options;
        std::string error;
        if (!osshar::prepareScene(options, scene, error) ||
            !osshar::makeShadowedRoot(mode, 1024, scene, root, technique, error))
            ADD_FAILURE() << error;
        osg::DisplaySettings::instance()->setMinimumNumStencilBits(8);
        osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
        traits->readDISPLAY();
        traits->setUndefinedScreenDetailsToDefaultScreen();
        traits->width = 2 * W, traits->height = H;
        traits->pbuffer = true, traits->doubleBuffer = true;
        traits->stencil = 8, traits->depth = 24, traits->alpha = 8;
        osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
        if (!gc) return;
        gc->setSwapCallback(new NoSwap);
        views[0] = scene.view;
        views[1] = {osg::Vec3d(-14, -6, 9), osg::Vec3d(0, 0, 0.5), osg::Vec3d(0, 0, 1), 45.0};
        for (int i = 0; i < 2; ++i)
        {
            osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
            view->setLightingMode(osg::View::NO_LIGHT);
            osg::Camera* camera = view->getCamera();
            camera->setGraphicsContext(gc.get());
            camera->setViewport(i * W, 0, W, H);
            camera->setDrawBuffer(GL_BACK);
            camera->setReadBuffer(GL_BACK);
            camera->setViewMatrixAsLookAt(views[i].eye, views[i].center, views[i].up);
            camera->setProjectionMatrixAsPerspective(views[i].fovy, double(W) / H, 0.1, 1000.0);
            camera->setClearColor(osg::Vec4(0.5f, 0.5f, 0.5f, 1.0f));
            camera->setFinalDrawCallback(reads[i].get());
            view->setSceneData(root.get());
            viewer->addView(view.get());
        }
        viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
        viewer->realize();
    }
    bool valid() const { return technique && viewer->isRealized(); }

    /** wrong_pct of view i's mask (rendered in the frame before) against its reference. */
    double wrongPct(int i) const
    {
        const ossref::Comparison c = ossref::compareMasks(
            ossref::maskFromImage(*reads[i]->image),
            ossref::computeReferenceMask(*scene.content, osshar::referenceCamera(views[i], W, H),
                                         osshar::referenceLight(scene.lights.at(0))));
        EXPECT_TRUE(c.valid) << c.error;
        EXPECT_GT(c.geometryPixels, 10000) << "view " << i;
        EXPECT_LT(c.coverageMismatch, 0.002 * W * H + 20) << "view " << i;
        return c.wrongPct;
    }
};

void expectTwoViewsAccurate(const char* mode, osgViewer::ViewerBase::ThreadingModel threading)
{
    TwoViews two(mode);
    ASSERT_TRUE(two.valid());
    two.viewer->setThreadingModel(threading);
    for (int frame = 0; frame < 10; ++frame) two.viewer->frame();
    two.viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded); // waits for the draw threads
    two.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    two.viewer->frame();
    for (int i = 0; i < 2; ++i) EXPECT_LT(two.wrongPct(i), bounds::CLAIMED.of(mode)) << mode << ", view " << i;
}

} // namespace

// Two views (two CullVisitors, so two sets of per-view state) of one scene in one context.
TEST_P(StressMode, TwoViewsOfOneScene)
{
    expectTwoViewsAccurate(GetParam(), osgViewer::ViewerBase::SingleThreaded);
}

// The same two views drawn by DrawThreadPerContext: cull of frame n+1 overlaps the draw of n.
TEST_P(StressMode, TwoViewsDrawThreadPerContext)
{
    expectTwoViewsAccurate(GetParam(), osgViewer::ViewerBase::DrawThreadPerContext);
}

// One view, CullThreadPerCameraDrawThreadPerContext, switching mode every frame; then each
// mode's accuracy once the viewer is single-threaded again. The masks are read from the
// window first and the float FBO render (renderFloat()) comes last: after cull threads, a
// master camera switched to an FBO and back no longer draws into the window
// (docs/robustness.md), which would hand every later mode the picture drawn before.
TEST(StressConfig, CullAndDrawThreadsWhileSwitchingModes)
{
    ShadowedRender r = stressRender("shadowmap");
    ASSERT_TRUE(r.valid());
    r.renderer->viewer().setThreadingModel(osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext);
    for (int frame = 0; frame < 16; ++frame)
    {
        r.technique->setMode(SilhouetteShadowTechnique::Mode(frame % 4));
        r.renderer->viewer().frame();
    }
    r.renderer->viewer().setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    ossref::Mask mask, reference;
    for (const char* mode : STRESS_MODES)
    {
        SilhouetteShadowTechnique::Mode m;
        ASSERT_TRUE(SilhouetteShadowTechnique::modeFromName(mode, m));
        r.technique->setMode(m);
        mask = r.mask();
        reference = stressReference(r, 0, ~0u);
        expectMaskWithinBound(r, mask, reference, bounds::CLAIMED.of(mode));
        EXPECT_EQ(r.technique->getStatistics().effectiveMode, m);
    }
    expectFiniteImage(r, mask, reference); // the last mode's
}

// The context resized between frames, as osgViewer does on a window's resize event (a
// pbuffer whose viewport changes width): the passes follow the viewport and the new aspect
// ratio. The masks after a resize are rendered into an FBO of the new size: the pbuffer's
// back buffer, read back after GraphicsContext::resized(), does not hold the picture the
// camera draws under Mesa and Xvfb (docs/robustness.md), while an FBO does.
TEST_P(StressMode, WindowResize)
{
    ShadowedRender r("default", GetParam(), 1024, 900, 600);
    ASSERT_TRUE(r.valid());
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
    for (const auto& size : {std::make_pair(700, 600), std::make_pair(420, 600), std::make_pair(900, 600)})
    {
        r.renderer->resize(size.first, size.second);
        r.renderer->setView(r.scene.view);
        expectFloatMaskWithinBound(r, bounds::CLAIMED.of(GetParam()));
        EXPECT_EQ(r.mask().width, size.first);
    }
    expectWithinBound(r, bounds::CLAIMED.of(GetParam())); // back at 900: the window read-back agrees again
}

// The context is destroyed and a new one renders the same scene graph: releaseGLObjects()
// frees every texture and buffer object the technique made in the old context (the stencil
// modes' volumes among them), and the new one renders as accurately as the first.
TEST_P(StressMode, ContextDestroyedAndRecreated)
{
    ShadowedRender r = stressRender(GetParam());
    ASSERT_TRUE(r.valid());
    for (int round = 0; round < 3; ++round)
    {
        expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
        osg::GraphicsContext* gc = r.renderer->viewer().getCamera()->getGraphicsContext();
        osg::State* state = gc->getState();
        const unsigned int contextID = state->getContextID();
        const osg::TextureObjectManager* textures = osg::get<osg::TextureObjectManager>(contextID);
        const osg::GLBufferObjectManager* buffers = osg::get<osg::GLBufferObjectManager>(contextID);
        EXPECT_GT(textures->getNumberActiveTextureObjects(), 0u);
        EXPECT_GT(buffers->getNumberActiveGLBufferObjects(), 0u);
        gc->makeCurrent();
        r.root->releaseGLObjects(state);
        osg::flushAllDeletedGLObjects(contextID);
        gc->releaseContext();
        EXPECT_EQ(textures->getNumberActiveTextureObjects(), 0u) << "round " << round << ": textures left behind";
        EXPECT_EQ(buffers->getNumberActiveGLBufferObjects(), 0u) << "round " << round << ": buffers left behind";
        r.renderer.reset(new osshar::Renderer(STRESS_WIDTH, STRESS_HEIGHT, true));
        ASSERT_TRUE(r.renderer->valid());
        r.renderer->setSceneData(r.root.get());
        r.renderer->setView(r.scene.view);
    }
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
}

// A map size beyond the context's GL_MAX_TEXTURE_SIZE (lowered here to 1024, as a small
// GPU would report it) is clamped to it at draw time, with a warning naming the limit.
TEST_P(StressMode, MapSizeAboveTheGLLimitIsClampedWithAWarning)
{
    NotifyCapture notes;
    ShadowedRender r = stressRender(GetParam(), 4096);
    ASSERT_TRUE(r.valid());
    r.renderer->timeFrames(0, 1); // the context's GLExtensions exist once it has drawn
    osg::GraphicsContext* gc = r.renderer->viewer().getCamera()->getGraphicsContext();
    osg::GLExtensions* ext = osg::GLExtensions::Get(gc->getState()->getContextID(), false);
    ASSERT_TRUE(ext);
    ext->maxTextureSize = 1024;
    expectWithinBound(r, bounds::CLAIMED.of(GetParam()));
    EXPECT_TRUE(notes.warned("GL_MAX_TEXTURE_SIZE")) << notes.warnings();
    EXPECT_EQ(r.technique->getShadowMapSize(), 1024u);
}

INSTANTIATE_TEST_SUITE_P(Modes, StressMode, ::testing::ValuesIn(STRESS_MODES));
