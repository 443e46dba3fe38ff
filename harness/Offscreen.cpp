#include "Offscreen.h"
#include "Text.h"

#include <osg/DisplaySettings>
#include <osg/GLExtensions>
#include <osg/Timer>
#include <osgViewer/GraphicsWindow>

namespace osshar {

namespace {

class NoSwap : public osg::GraphicsContext::SwapCallback
{
public:
    void swapBuffersImplementation(osg::GraphicsContext*) override {}
};

} // namespace

/** Initial and final draw callbacks: a GL_TIME_ELAPSED query around the frame, glFinish,
 *  and an optional read-back. */
struct Renderer::DrawHooks : public osg::Referenced
{
    struct Begin : public osg::Camera::DrawCallback
    {
        explicit Begin(DrawHooks* h) : hooks(h) {}
        void operator()(osg::RenderInfo& ri) const override { hooks->begin(ri); }
        DrawHooks* hooks;
    };
    struct End : public osg::Camera::DrawCallback
    {
        explicit End(DrawHooks* h) : hooks(h) {}
        void operator()(osg::RenderInfo& ri) const override { hooks->end(ri); }
        DrawHooks* hooks;
    };

    void begin(osg::RenderInfo& ri)
    {
        osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
        if (!ext || !ext->glGenQueries || !ext->glBeginQuery) return;
        if (!query) ext->glGenQueries(1, &query);
        ext->glBeginQuery(GL_TIME_ELAPSED, query);
        queryActive = true;
    }

    void end(osg::RenderInfo& ri)
    {
        osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
        if (queryActive && ext)
        {
            ext->glEndQuery(GL_TIME_ELAPSED);
            glFinish();
            GLuint64 ns = 0;
            ext->glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
            lastGpuMs = ++queriesDone > 1 ? double(ns) * 1e-6 : -1.0; // the first result is garbage
            queryActive = false;
        }
        else
            glFinish();
        if (capture)
        {
            glReadBuffer(GL_BACK);
            capture->readPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE);
        }
    }

    int width = 0, height = 0;
    GLuint query = 0;
    bool queryActive = false;
    int queriesDone = 0;
    double lastGpuMs = -1.0;
    osg::ref_ptr<osg::Image> capture;
};

Renderer::Renderer(int width, int height, bool offscreen, int stencilBits) : _width(width), _height(height)
{
    if (stencilBits > 0) osg::DisplaySettings::instance()->setMinimumNumStencilBits(stencilBits);
    _viewer = new osgViewer::Viewer;
    _viewer->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    _viewer->setLightingMode(osg::View::NO_LIGHT);
    _viewer->setKeyEventSetsDone(0);

    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->setUndefinedScreenDetailsToDefaultScreen();
    traits->x = 0, traits->y = 0, traits->width = width, traits->height = height;
    traits->windowDecoration = !offscreen;
    traits->doubleBuffer = true;
    traits->pbuffer = offscreen;
    traits->stencil = stencilBits;
    traits->depth = 24;
    traits->alpha = 8;
    traits->sharedContext = nullptr;
    osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
    if (!gc.valid()) return;
    if (offscreen) gc->setSwapCallback(new NoSwap);

    osg::Camera* camera = _viewer->getCamera();
    camera->setGraphicsContext(gc.get());
    camera->setViewport(0, 0, width, height);
    const GLenum buffer = traits->doubleBuffer ? GL_BACK : GL_FRONT;
    camera->setDrawBuffer(buffer);
    camera->setReadBuffer(buffer);

    _hooks = new DrawHooks;
    _hooks->width = width, _hooks->height = height;
    camera->setInitialDrawCallback(new DrawHooks::Begin(_hooks.get()));
    camera->setFinalDrawCallback(new DrawHooks::End(_hooks.get()));
    _viewer->realize();
}

Renderer::~Renderer() = default;

bool Renderer::valid() const
{
    return _viewer->getCamera()->getGraphicsContext() != nullptr && _viewer->isRealized();
}

void Renderer::setSceneData(osg::Node* node)
{
    _viewer->setSceneData(node);
}

void Renderer::setView(const View& view)
{
    osg::Camera* camera = _viewer->getCamera();
    camera->setViewMatrixAsLookAt(view.eye, view.center, view.up);
    camera->setProjectionMatrixAsPerspective(view.fovy, double(_width) / double(_height), 0.1, 1000.0);
}

void Renderer::resize(int width, int height)
{
    osg::GraphicsContext* gc = _viewer->getCamera()->getGraphicsContext();
    if (!gc) return;
    if (osgViewer::GraphicsWindow* window = dynamic_cast<osgViewer::GraphicsWindow*>(gc))
        window->setWindowRectangle(0, 0, width, height);
    else
        gc->resized(0, 0, width, height);
    _viewer->getCamera()->setViewport(0, 0, width, height); // resized() scales it; make it exact
    _width = width, _height = height;
    _hooks->width = width, _hooks->height = height;
}

FrameTiming Renderer::timeFrames(int warmup, int frames)
{
    return timeFrames(warmup, frames, [](int) {});
}

FrameTiming Renderer::timeFrames(int warmup, int frames, const std::function<void(int)>& beforeFrame)
{
    return timeFrames(warmup, frames, beforeFrame, [](int) {});
}

FrameTiming Renderer::timeFrames(int warmup, int frames, const std::function<void(int)>& beforeFrame,
                                 const std::function<void(int)>& afterFrame)
{
    for (int i = 0; i < warmup; ++i)
    {
        beforeFrame(i);
        frame();
        afterFrame(i);
    }
    std::vector<double> cpu, gpu;
    for (int i = 0; i < frames; ++i)
    {
        beforeFrame(warmup + i);
        const osg::Timer_t t0 = osg::Timer::instance()->tick();
        frame();
        cpu.push_back(osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick()));
        if (_hooks->lastGpuMs >= 0.0) gpu.push_back(_hooks->lastGpuMs);
        afterFrame(warmup + i);
    }
    FrameTiming t;
    t.frames = frames;
    t.cpuMsMedian = median(cpu);
    t.gpuMsMedian = median(gpu);
    return t;
}

osg::ref_ptr<osg::Image> Renderer::renderAndCapture(const osg::Vec4& clearColor)
{
    osg::Camera* camera = _viewer->getCamera();
    const osg::Vec4 previous = camera->getClearColor();
    camera->setClearColor(clearColor);
    _hooks->capture = new osg::Image;
    frame();
    osg::ref_ptr<osg::Image> image = _hooks->capture;
    _hooks->capture = nullptr;
    camera->setClearColor(previous);
    return image;
}

void Renderer::frame()
{
    _viewer->frame(_simulationTime >= 0.0 ? _simulationTime : USE_REFERENCE_TIME);
}

} // namespace osshar
