// A viewer that renders offscreen (pbuffer) or in a window, times frames and reads pixels back.
#ifndef OSS_HARNESS_OFFSCREEN_H
#define OSS_HARNESS_OFFSCREEN_H

#include "Scenes.h"

#include <osg/Image>
#include <osgViewer/Viewer>

#include <functional>
#include <memory>
#include <vector>

namespace osshar {

struct FrameTiming
{
    int frames = 0;
    double cpuMsMedian = 0.0; ///< wall time of viewer.frame() with glFinish, median
    double gpuMsMedian = -1.0;///< GL_TIME_ELAPSED of the whole frame, median; -1 when unknown
};

class Renderer
{
public:
    /** A viewer of width x height with stencilBits stencil bits (default 8), single
     *  threaded, no headlight. offscreen: a pbuffer (else a window). */
    Renderer(int width, int height, bool offscreen, int stencilBits = 8);
    ~Renderer();

    /** Whether a graphics context could be created. */
    bool valid() const;

    osgViewer::Viewer& viewer() { return *_viewer; }

    void setSceneData(osg::Node* node);
    void setView(const View& view);

    /** Renders warmup frames, then frames timed frames. */
    FrameTiming timeFrames(int warmup, int frames);
    /** The same, calling beforeFrame(i) before frame i (warm-up frames first, from 0). */
    FrameTiming timeFrames(int warmup, int frames, const std::function<void(int)>& beforeFrame);
    /** The same, also calling afterFrame(i) after frame i, outside its timing. */
    FrameTiming timeFrames(int warmup, int frames, const std::function<void(int)>& beforeFrame,
                           const std::function<void(int)>& afterFrame);

    /** The frames from now on, renderAndCapture()'s included, show simulation time t (the
     *  update traversal's, which animations follow: osgViewer's frame(t)), so that a frame
     *  can be rendered again as it was; negative: the wall clock, as osgViewer's frame()
     *  (the default). */
    void setSimulationTime(double t) { _simulationTime = t; }
    double simulationTime() const { return _simulationTime; }

    /** Renders one frame with the given clear colour and returns its RGB pixels (bottom row first). */
    osg::ref_ptr<osg::Image> renderAndCapture(const osg::Vec4& clearColor = osg::Vec4(0.2f, 0.2f, 0.3f, 1.0f));

    /** Resizes the window (a pbuffer can only shrink its viewport) and the read-back to
     *  width x height; call setView() again for the new aspect ratio. */
    void resize(int width, int height);
    int width() const { return _width; }
    int height() const { return _height; }

private:
    struct DrawHooks;
    void frame();

    int _width, _height;
    double _simulationTime = -1.0;
    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<DrawHooks> _hooks;
};

} // namespace osshar

#endif
