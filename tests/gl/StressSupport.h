// Shared by the GL stress tests: awkward casters built in code, per-mode bounds, and the
// checks every stress case makes (no NaN or Inf in a float image, the mask against the
// exact reference).
#ifndef OSS_TESTS_STRESSSUPPORT_H
#define OSS_TESTS_STRESSSUPPORT_H

#include "GLTestSupport.h"
#include "Meshes.h"
#include "ModeBounds.h"
#include "NotifyCapture.h"

#include <osg/Geode>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osgDB/WriteFile>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

namespace osstest {

/** The modes every per-mode stress case runs in (the names of makeShadowedRoot). */
const char* const STRESS_MODES[] = {"shadowmap", "silhouette", "hybrid", "volume"};

/** The image size of the stress renders: smaller than the accuracy tests' to keep the
 *  suite fast; wrong_pct is a share of pixels and hardly depends on it. */
constexpr int STRESS_WIDTH = 640;
constexpr int STRESS_HEIGHT = 480;

/** Per-mode stress cases: the parameter is a mode name. */
class StressMode : public ::testing::TestWithParam<const char*>
{
};

/** Cases for a subset of the modes (each file instantiates the ones it uses). */
const char* const STENCIL_MODES[] = {"hybrid", "volume"};
const char* const MAP_MODES[] = {"shadowmap", "silhouette"};
const char* const DEPTH_MAP_MODES[] = {"shadowmap", "silhouette", "hybrid"};
class StencilMode : public StressMode
{
};
class MapMode : public StressMode
{
};
class DepthMapMode : public StressMode
{
};

/** The default scene (or another built-in one) in `mode`, at the stress image size. */
inline ShadowedRender stressRender(const char* mode, unsigned int mapSize = 1024, const char* scene = "default")
{
    return ShadowedRender(scene, mode, mapSize, STRESS_WIDTH, STRESS_HEIGHT);
}

/** A geometry of separate flat-shaded triangles (three corners each, no shared vertices),
 *  with one face normal per triangle ((0, 0, 1) for a degenerate one) and a white colour. */
inline osg::ref_ptr<osg::Geometry> flatTriangles(const std::vector<osg::Vec3>& corners, const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array(corners.begin(), corners.end());
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
    {
        osg::Vec3 normal = (corners[i + 1] - corners[i]) ^ (corners[i + 2] - corners[i]);
        if (!(normal.length() > 0.0f) || !std::isfinite(normal.length())) normal = osg::Vec3(0, 0, 1);
        normal.normalize();
        n->insert(n->end(), 3, normal);
    }
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(name);
    g->setVertexArray(v.get());
    g->setNormalArray(n.get(), osg::Array::BIND_PER_VERTEX);
    osg::ref_ptr<osg::Vec4Array> c = new osg::Vec4Array;
    c->push_back(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    g->setColorArray(c.get(), osg::Array::BIND_OVERALL);
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(corners.size())));
    return g;
}

/** The two triangles of the quad a b c d (counter-clockwise seen from its front). */
inline void addQuad(std::vector<osg::Vec3>& t, const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c,
                    const osg::Vec3& d)
{
    t.insert(t.end(), {a, b, c, a, c, d});
}

/** The triangles of an axis-aligned box from lo to hi, outward, counter-clockwise. `skipTop`
 *  leaves the +z face out (an open box). */
inline std::vector<osg::Vec3> boxTriangles(const osg::Vec3& lo, const osg::Vec3& hi, bool skipTop = false)
{
    const osg::Vec3 p[8] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()},
                            {lo.x(), hi.y(), lo.z()}, {lo.x(), lo.y(), hi.z()}, {hi.x(), lo.y(), hi.z()},
                            {hi.x(), hi.y(), hi.z()}, {lo.x(), hi.y(), hi.z()}};
    std::vector<osg::Vec3> t;
    addQuad(t, p[0], p[3], p[2], p[1]); // -z
    if (!skipTop) addQuad(t, p[4], p[5], p[6], p[7]); // +z
    addQuad(t, p[0], p[1], p[5], p[4]); // -y
    addQuad(t, p[2], p[3], p[7], p[6]); // +y
    addQuad(t, p[1], p[2], p[6], p[5]); // +x
    addQuad(t, p[3], p[0], p[4], p[7]); // -x
    return t;
}

/** Adds a drawable to the scene's content in a Geode of its own. */
inline osg::Geode* addToScene(ShadowedRender& r, osg::Drawable* drawable)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    r.scene.content->addChild(geode.get());
    return geode.get();
}

/** The light of the scene (light 0), its reference light refreshed from the scene. */
inline osg::Light* lightOf(ShadowedRender& r)
{
    r.scene.lights = osshar::findLights(r.scene.content.get());
    return r.scene.lights.at(0).source->getLight();
}

/** Moves the whole content (lights included) under a transform and the view with it. */
inline void transformScene(ShadowedRender& r, const osg::Matrixd& m)
{
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(m);
    for (unsigned int i = 0; i < r.scene.content->getNumChildren(); ++i) moved->addChild(r.scene.content->getChild(i));
    r.scene.content->removeChildren(0, r.scene.content->getNumChildren());
    r.scene.content->addChild(moved.get());
    r.scene.lights = osshar::findLights(r.scene.content.get());
    const osg::Vec3d up = osg::Matrixd::transform3x3(r.scene.view.up, m);
    r.scene.view.eye = r.scene.view.eye * m;
    r.scene.view.center = r.scene.view.center * m;
    r.scene.view.up = up;
    r.renderer->setView(r.scene.view);
}

/** One frame of r rendered into a 32-bit float colour buffer (an FBO with depth and
 *  stencil), so that NaN and Inf written by a shader survive. Restores the window target. */
inline osg::ref_ptr<osg::Image> renderFloat(ShadowedRender& r, const osg::Vec4& clearColor)
{
    osg::Camera* camera = r.renderer->viewer().getCamera();
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(r.renderer->width(), r.renderer->height(), 1, GL_RGBA, GL_FLOAT);
    image->setInternalTextureFormat(GL_RGBA32F_ARB);
    const osg::Vec4 previous = camera->getClearColor();
    camera->setClearColor(clearColor);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->attach(osg::Camera::COLOR_BUFFER, image.get());
    camera->attach(osg::Camera::PACKED_DEPTH_STENCIL_BUFFER, GL_DEPTH24_STENCIL8_EXT);
    camera->dirtyAttachmentMap(); // attach() alone does not make the render stage set up again
    r.renderer->timeFrames(0, 1);
    camera->detach(osg::Camera::COLOR_BUFFER);
    camera->detach(osg::Camera::PACKED_DEPTH_STENCIL_BUFFER);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER);
    camera->dirtyAttachmentMap();
    camera->setClearColor(previous);
    return image;
}

/** Channel values of a GL_FLOAT image that are NaN or infinite. */
inline long long nonFiniteValues(const osg::Image& image)
{
    const float* p = reinterpret_cast<const float*>(image.data());
    const std::size_t n = std::size_t(image.s()) * image.t() * 4;
    long long bad = 0;
    for (std::size_t i = 0; i < n; ++i) bad += !std::isfinite(p[i]);
    return bad;
}

/** Asserts that neither the shaded image nor the shadow mask of r holds a NaN or an Inf,
 *  read back as floats; and that the float render is the same picture as the ordinary one
 *  (lit in one and shadowed in the other in at most 0.5% of the pixels that the reference
 *  can judge), so that
 *  the check looks at real pixels. */
inline void expectFiniteImage(ShadowedRender& r, const ossref::Mask& mask, const ossref::Mask& reference,
                              double renderDifferencePct = 0.5)
{
    osg::ref_ptr<osg::Image> shaded = renderFloat(r, osg::Vec4(0.2f, 0.2f, 0.3f, 1.0f));
    EXPECT_EQ(nonFiniteValues(*shaded), 0) << "NaN or Inf in the shaded image";
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    osg::ref_ptr<osg::Image> masked = renderFloat(r, osg::Vec4(0.5f, 0.5f, 0.5f, 1.0f));
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
    EXPECT_EQ(nonFiniteValues(*masked), 0) << "NaN or Inf in the shadow mask";
    const ossref::Mask floatMask = ossref::maskFromImage(*masked);
    long long differ = 0, judged = 0;
    for (std::size_t i = 0; i < mask.value.size() && i < floatMask.value.size(); ++i)
    {
        if (reference.isGrazing(i)) continue;
        ++judged;
        // Lit in one and shadowed in the other (a PCF value of exactly 0.25 or 0.75 may
        // round to either side of a class threshold in 8 bits).
        const int a = ossref::classify(mask.value[i]), b = ossref::classify(floatMask.value[i]);
        differ += (a == ossref::MASK_LIT && b == ossref::MASK_NO_LIGHT) || (a == ossref::MASK_NO_LIGHT && b == ossref::MASK_LIT);
    }
    EXPECT_LT(differ, 0.01 * renderDifferencePct * judged + 50) << "the float render differs from the ordinary one";
}

/** The reference mask of light `light` of r, computed with `castsMask`. Pixels whose answer
 *  changes when the light turns (or moves) by 1e-5 radians out of its place in any of four
 *  directions join the grazing band, which the comparison leaves out: a face that contains
 *  the light exactly (N.L = 0) is lit or not by rounding alone, in the reference as on the
 *  GPU. */
inline ossref::Mask stressReference(ShadowedRender& r, unsigned int light, unsigned int castsMask)
{
    const ossref::Tracer tracer(*r.scene.content, castsMask);
    const ossref::Camera camera = osshar::referenceCamera(r.scene.view, r.renderer->width(), r.renderer->height());
    const ossref::Light base = osshar::referenceLight(r.scene.lights.at(light));
    ossref::Mask reference = tracer.render(camera, base);
    const osg::BoundingSphere bound = r.scene.content->getBound();
    osg::Vec3d axis = base.type == ossref::Light::DIRECTIONAL ? base.vector : base.vector - osg::Vec3d(bound.center());
    const double length = axis.length() > 0.0 ? axis.length() : 1.0;
    axis /= length;
    osg::Vec3d u = axis ^ (std::fabs(axis.z()) < 0.9 ? osg::Vec3d(0, 0, 1) : osg::Vec3d(1, 0, 0));
    u.normalize();
    const osg::Vec3d v = axis ^ u;
    for (const osg::Vec3d& step : {u, -u, v, -v})
    {
        ossref::Light nudged = base;
        nudged.vector += step * (1e-5 * length);
        const ossref::Mask other = tracer.render(camera, nudged);
        for (std::size_t i = 0; i < reference.value.size(); ++i)
            if (other.value[i] != reference.value[i]) reference.grazing[i] = 1;
    }
    return reference;
}

/** wrong_pct of `mask` (light `light` of r) against the reference computed with
 *  `castsMask`, asserted below `bound`, with the geometry in view and the coverage checked. */
inline ossref::Comparison expectMaskWithinBound(ShadowedRender& r, const ossref::Mask& mask,
                                                const ossref::Mask& reference, double bound)
{
    const ossref::Comparison c = ossref::compareMasks(mask, reference);
    // OSS_STRESS_DIFF=<prefix>: the error image (ossref::diffImage) as <prefix>_<mode>_<width>.png.
    if (const char* prefix = std::getenv("OSS_STRESS_DIFF"))
        osgDB::writeImageFile(*ossref::diffImage(mask, reference),
                              std::string(prefix) + "_" + SilhouetteShadowTechnique::modeName(r.technique->getMode()) +
                                  "_" + std::to_string(mask.width) + ".png");
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_GT(c.geometryPixels, 1000) << "too little of the scene is in view to judge";
    EXPECT_LT(c.coverageMismatch, 0.002 * r.renderer->width() * r.renderer->height() + 20)
        << "the mask and the reference disagree on where geometry is";
    EXPECT_LT(c.wrongPct, bound) << SilhouetteShadowTechnique::modeName(r.technique->getMode()) << ": "
                                 << c.wrongPixels << " wrong pixels of " << c.geometryPixels;
    ::testing::Test::RecordProperty("wrong_pct", std::to_string(c.wrongPct));
    std::printf("wrong_pct %s %.4f (%lld of %lld, %lld left out)\n",
                SilhouetteShadowTechnique::modeName(r.technique->getMode()), c.wrongPct, c.wrongPixels,
                c.geometryPixels, c.grazingExcluded);
    return c;
}

/** The checks of a stress case with a reference: a finite image, and the mask of light
 *  `light` within `bound` % of the reference computed with `castsMask`; the float render
 *  may differ from the ordinary one in renderDifferencePct % of the pixels. */
inline ossref::Comparison expectWithinBound(ShadowedRender& r, double bound, unsigned int light = 0,
                                            unsigned int castsMask = ~0u, double renderDifferencePct = 0.5)
{
    const ossref::Mask mask = r.mask(light);
    const ossref::Mask reference = stressReference(r, light, castsMask);
    const ossref::Comparison c = expectMaskWithinBound(r, mask, reference, bound);
    expectFiniteImage(r, mask, reference, renderDifferencePct);
    return c;
}

/** As expectWithinBound(), but the mask (light 0) is rendered into a float FBO of the
 *  renderer's size (renderFloat()) instead of being read back from the window. */
inline ossref::Comparison expectFloatMaskWithinBound(ShadowedRender& r, double bound)
{
    r.renderer->timeFrames(0, 2);
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    r.technique->setDebugLight(0);
    osg::ref_ptr<osg::Image> masked = renderFloat(r, osg::Vec4(0.5f, 0.5f, 0.5f, 1.0f));
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
    EXPECT_EQ(nonFiniteValues(*masked), 0) << "NaN or Inf in the shadow mask";
    osg::ref_ptr<osg::Image> shaded = renderFloat(r, osg::Vec4(0.2f, 0.2f, 0.3f, 1.0f));
    EXPECT_EQ(nonFiniteValues(*shaded), 0) << "NaN or Inf in the shaded image";
    return expectMaskWithinBound(r, ossref::maskFromImage(*masked), stressReference(r, 0, ~0u), bound);
}

} // namespace osstest

#endif
