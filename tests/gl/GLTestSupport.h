// Shared by the GL tests: render a built-in scene with the technique, read its shadow mask
// back, and score it against the exact reference.
#ifndef OSS_TESTS_GLTESTSUPPORT_H
#define OSS_TESTS_GLTESTSUPPORT_H

#include "Offscreen.h"
#include "Setup.h"
#include "reference/Reference.h"

#include <osg/GLExtensions>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osgShadow/ShadowedScene>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace osstest {

using osgShadowSilhouette::SilhouetteShadowTechnique;

/** A built-in scene under a ShadowedScene with the technique, rendered offscreen. */
struct ShadowedRender
{
    osshar::PreparedScene scene;
    osg::ref_ptr<SilhouetteShadowTechnique> technique;
    osg::ref_ptr<osg::Node> root;
    std::unique_ptr<osshar::Renderer> renderer;

    ShadowedRender(const std::string& sceneName, const std::string& mode, unsigned int mapSize, int width = 1024,
                   int height = 768)
        : ShadowedRender(optionsFor(sceneName), mode, mapSize, width, height)
    {
    }

    /** The scene, lights and view of a renderer command line (RenderOptions). */
    ShadowedRender(const osshar::RenderOptions& options, const std::string& mode, unsigned int mapSize, int width,
                   int height)
    {
        std::string error;
        if (!osshar::prepareScene(options, scene, error))
            ADD_FAILURE() << error;
        else
            start(mode, mapSize, width, height);
    }

    /** A scene built in the test (its content, lights and view), as prepareScene() gives one. */
    ShadowedRender(osshar::PreparedScene prepared, const std::string& mode, unsigned int mapSize, int width, int height)
        : scene(std::move(prepared))
    {
        start(mode, mapSize, width, height);
    }

    void start(const std::string& mode, unsigned int mapSize, int width, int height)
    {
        std::string error;
        if (!osshar::makeShadowedRoot(mode, mapSize, scene, root, technique, error)) ADD_FAILURE() << error;
        renderer.reset(new osshar::Renderer(width, height, true));
        if (!renderer->valid())
        {
            ADD_FAILURE() << "no graphics context: GL tests need a display (run them under xvfb-run)";
            return;
        }
        renderer->setSceneData(root.get());
        renderer->setView(scene.view);
    }

    static osshar::RenderOptions optionsFor(const std::string& sceneName)
    {
        osshar::RenderOptions options;
        options.scene = sceneName;
        return options;
    }

    bool valid() const { return renderer && renderer->valid() && technique; }

    /** The technique's shadow mask of light `index` (DEBUG_SHADOW_MASK), after `frames` frames. */
    ossref::Mask mask(unsigned int index = 0, int frames = 2)
    {
        renderer->timeFrames(0, frames);
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
        technique->setDebugLight(index);
        osg::ref_ptr<osg::Image> image = renderer->renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
        return ossref::maskFromImage(*image);
    }

    /** The technique's visibility of light `index` (DEBUG_VISIBILITY: the shadow term before
     *  the mask's threshold), after `frames` frames. */
    ossref::VisibilityMask visibility(unsigned int index = 0, int frames = 2)
    {
        renderer->timeFrames(0, frames);
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_VISIBILITY);
        technique->setDebugLight(index);
        osg::ref_ptr<osg::Image> image = renderer->renderAndCapture(osg::Vec4(1, 0, 1, 1));
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
        return ossref::visibilityFromRender(*image);
    }

    /** The exact visibility of light `index` at size `size` (MEASURE.md, "Soft shadows"). */
    ossref::VisibilityMask referenceVisibility(unsigned int index, double size) const
    {
        ossref::Light light = osshar::referenceLight(scene.lights.at(index));
        light.size = size;
        return ossref::computeReferenceVisibility(
            *scene.content, osshar::referenceCamera(scene.view, renderer->width(), renderer->height()), light, ~0u,
            ~0u);
    }

    /** The technique's mask of light `index` after `frames` frames, scored against the
     *  exact reference. */
    ossref::Comparison scoreMask(unsigned int index = 0, int frames = 2)
    {
        const ossref::Mask m = mask(index, frames);
        return ossref::compareMasks(m, reference(index));
    }

    /** The exact reference mask of light `index` for the same view (its shadow rays offset
     *  by `offsetScale` of the scene's radius: ossref::computeReferenceMask). */
    ossref::Mask reference(unsigned int index = 0, double offsetScale = ossref::DEFAULT_OFFSET_SCALE) const
    {
        return ossref::computeReferenceMask(*scene.content,
                                            osshar::referenceCamera(scene.view, renderer->width(), renderer->height()),
                                            osshar::referenceLight(scene.lights.at(index)), ~0u, ~0u, offsetScale);
    }
};

/** One integer limit of r's context (0 where the query fails): what the context offers is
 *  asked of it, not assumed from this machine's. */
inline GLint contextLimit(ShadowedRender& r, GLenum name)
{
    osg::GraphicsContext* gc = r.renderer->viewer().getCamera()->getGraphicsContext();
    GLint value = 0;
    gc->makeCurrent();
    glGetIntegerv(name, &value);
    if (glGetError() != GL_NO_ERROR) value = 0;
    gc->releaseContext();
    return value;
}

/** The OpenGL version of r's context as OSG reads it (0 before the context has drawn). */
inline float contextGLVersion(ShadowedRender& r)
{
    const osg::State* state = r.renderer->viewer().getCamera()->getGraphicsContext()->getState();
    const osg::GLExtensions* ext = state ? osg::GLExtensions::Get(state->getContextID(), false) : nullptr;
    return ext ? ext->glVersion : 0.0f;
}

/** Two RGB colour images of one size compared at the pixels @p judged (pixel index, bottom
 *  row first) accepts: how many were compared, how many differ by more than 2 of 255 in some
 *  channel, and the largest difference. */
struct ColourComparison
{
    long long compared = 0, differing = 0;
    int worst = 0;
};

template<class Judged>
ColourComparison compareColours(const osg::Image& a, const osg::Image& b, const Judged& judged)
{
    ColourComparison result;
    const int n = a.s() * a.t();
    for (int i = 0; i < n; ++i)
    {
        if (!judged(i)) continue;
        ++result.compared;
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.data()[3 * i + c]) - int(b.data()[3 * i + c])));
        result.worst = std::max(result.worst, d);
        result.differing += d > 2;
    }
    return result;
}

/** A GL version for a message: "4.1", not the float's 4.0999999. */
inline std::string glVersionText(float version)
{
    char text[16];
    std::snprintf(text, sizeof(text), "%.1f", double(version));
    return text;
}

} // namespace osstest

#endif
