/* osgsilhouetteshadow: renders a scene with osgShadowSilhouette (or without shadows),
 * offscreen or in a window, and measures it as MEASURE.md describes.
 *
 *   osgsilhouetteshadow [FILE] --mode shadowmap --map-size 2048 --offscreen \
 *       --out color.png --mask mask.png --reference ref.png --compare ref.png
 *
 * Prints frame_ms_median=..., gpu_ms_median=... and, with --compare or --reference,
 * wrong_pct=... against the exact ray-cast reference; with --visibility and
 * --reference-visibility (and --light-size S), vis_mae=... against the exact visibility of a
 * light with a size (the mode's visibility view: fractions under a soft filter; a peer's
 * shadowed over unshadowed luminance); --compare-visibility reads that exact visibility from an
 * earlier --reference-visibility run instead of casting it again.
 *
 * --animate plays the scene's osgAnimation animations at a fixed step of simulation time per
 * frame (--time-step, default 1/30 s); --camera-path FILE moves the camera along an
 * osg::AnimationPath (osgviewer's recorded paths), one --time-step per timed frame;
 * --score-every-frame scores each timed frame's mask against that frame's own reference and
 * prints frame_wrong_pct_max=... and flicker_pct=... (pixels whose mask changes from the
 * previous frame while the reference's does not) per light. Scores against a computed
 * reference also come per band of eye distance: wrong_pct_near= (0-20), wrong_pct_mid=
 * (20-200), wrong_pct_far= (beyond; scene units, docs/outdoor.md).
 *
 * --mode osgShadow:ShadowMap|osgShadow:SoftShadowMap|osgShadow:LightSpacePerspectiveShadowMapCB|
 * osgShadow:ViewDependentShadowMap|osgShadow:ParallelSplitShadowMap renders osgShadow's technique in the measurement setup of
 * MEASURE.md (harness/Peers.h); its mask (first light only) is classified from its image. */

#include "AnimatedScenes.h"
#include "Classes.h"
#include "GLErrors.h"
#include "Offscreen.h"
#include "Peers.h"
#include "RenderOptions.h"
#include "Setup.h"

#include <osgShadowSilhouette/StatsHandlerLines>

#include <osgDB/WriteFile>
#include <osgGA/StateSetManipulator>
#include <osgGA/TrackballManipulator>
#include <osgViewer/ViewerEventHandlers>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;

/** The shadow mask of light `index`, rendered by the technique's mask view. */
ossref::Mask renderMask(osshar::Renderer& renderer, SilhouetteShadowTechnique& technique, unsigned int index)
{
    const SilhouetteShadowTechnique::DebugView previous = technique.getDebugView();
    technique.setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    technique.setDebugLight(index);
    osg::ref_ptr<osg::Image> image = renderer.renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    technique.setDebugView(previous);
    return ossref::maskFromImage(*image);
}

/** The visibility of light `index`, rendered by the technique's visibility view (a grey level
 *  per pixel; the clear colour, magenta, marks the background). */
ossref::VisibilityMask renderVisibility(osshar::Renderer& renderer, SilhouetteShadowTechnique& technique,
                                        unsigned int index)
{
    const SilhouetteShadowTechnique::DebugView previous = technique.getDebugView();
    technique.setDebugView(SilhouetteShadowTechnique::DEBUG_VISIBILITY);
    technique.setDebugLight(index);
    osg::ref_ptr<osg::Image> image = renderer.renderAndCapture(osg::Vec4(1, 0, 1, 1));
    technique.setDebugView(previous);
    return ossref::visibilityFromRender(*image);
}

/** "mask%d.png" with the light index; a name without %d is used as it is for light 0 and
 *  gets "_<index>" before its extension for the others. */
std::string perLightName(const std::string& pattern, unsigned int index)
{
    if (pattern.find("%d") != std::string::npos)
    {
        char buf[1024];
        std::snprintf(buf, sizeof(buf), pattern.c_str(), int(index));
        return buf;
    }
    if (index == 0) return pattern;
    const std::size_t dot = pattern.rfind('.');
    return pattern.substr(0, dot) + "_" + std::to_string(index) + (dot == std::string::npos ? "" : pattern.substr(dot));
}

int runWindowed(osshar::PreparedScene& scene, osg::Node* root, SilhouetteShadowTechnique* technique)
{
    osgViewer::Viewer viewer;
    viewer.setLightingMode(osg::View::NO_LIGHT);
    viewer.setSceneData(root);
    osg::ref_ptr<osgGA::TrackballManipulator> manip = new osgGA::TrackballManipulator;
    manip->setHomePosition(scene.view.eye, scene.view.center, scene.view.up);
    viewer.setCameraManipulator(manip.get());
    osg::ref_ptr<osgViewer::StatsHandler> stats = new osgViewer::StatsHandler;
    if (technique) osgShadowSilhouette::addStatsLines(viewer, *stats, *technique);
    viewer.addEventHandler(stats.get());
    viewer.addEventHandler(new osgViewer::WindowSizeHandler);
    viewer.addEventHandler(new osgGA::StateSetManipulator(viewer.getCamera()->getOrCreateStateSet()));
    return viewer.run();
}

/** The exact visibility of light @p index at --light-size: read from --compare-visibility, or
 *  computed (and written to --reference-visibility). Empty when neither is asked for. */
ossref::VisibilityMask referenceVisibility(const osshar::RenderOptions& options, const osshar::PreparedScene& scene,
                                           const ossref::Camera& camera, unsigned int index, int& status)
{
    ossref::VisibilityMask reference;
    if (!options.compareVisibility.empty() && options.referenceVisibility.empty())
    {
        if (!ossref::readVisibility(perLightName(options.compareVisibility, index), reference))
        {
            std::cerr << "cannot read " << perLightName(options.compareVisibility, index) << "\n", status = 1;
            return reference;
        }
        // An image keeps no grazing band; the hard reference's is the same (the light's centre).
        const ossref::Mask hard =
            ossref::computeReferenceMask(*scene.content, camera, osshar::referenceLight(scene.lights[index]),
                                         scene.castsMask, scene.referenceTraversalMask());
        if (hard.width == reference.width && hard.height == reference.height) reference.grazing = hard.grazing;
        return reference;
    }
    if (options.referenceVisibility.empty()) return reference;
    ossref::Light light = osshar::referenceLight(scene.lights[index]);
    light.size = options.lightSize;
    reference = ossref::computeReferenceVisibility(*scene.content, camera, light, scene.castsMask,
                                                   scene.referenceTraversalMask());
    if (!ossref::writeVisibility(reference, perLightName(options.referenceVisibility, index)))
        std::cerr << "cannot write " << perLightName(options.referenceVisibility, index) << "\n", status = 1;
    return reference;
}

/** --visibility and --reference-visibility (or --compare-visibility) of light @p index: the
 *  technique's visibility view (fractions under a soft filter), or a peer's @p peerVisibility
 *  (its shadowed over unshadowed luminance), and the exact visibility of the light at
 *  --light-size; with both, their scores (MEASURE.md, "Soft shadows"). 0, or 1 on failure. */
int writeVisibility(const osshar::RenderOptions& options, const osshar::PreparedScene& scene,
                    const ossref::Camera& camera, const ossref::VisibilityMask& peerVisibility,
                    osshar::Renderer& renderer, SilhouetteShadowTechnique* technique, unsigned int index)
{
    int status = 0;
    ossref::VisibilityMask candidate;
    if (!options.visibility.empty() && (technique || !peerVisibility.empty()))
    {
        candidate = technique ? renderVisibility(renderer, *technique, index) : peerVisibility;
        if (!ossref::writeVisibility(candidate, perLightName(options.visibility, index)))
            std::cerr << "cannot write " << perLightName(options.visibility, index) << "\n", status = 1;
    }
    const ossref::VisibilityMask reference = referenceVisibility(options, scene, camera, index, status);
    if (candidate.empty() || reference.empty()) return status;
    const ossref::VisibilityComparison c = ossref::compareVisibility(reference, candidate);
    if (!c.valid)
    {
        std::cerr << "osgsilhouetteshadow: cannot compare visibility: " << c.error << "\n";
        return 1;
    }
    if (!options.visibilityError.empty())
    {
        // |v - v_ref| where the scores count a pixel: where the error of a penumbra lies.
        ossref::VisibilityMask error = ossref::VisibilityMask::filled(reference.width, reference.height);
        for (std::size_t k = 0; k < error.value.size(); ++k)
            if (reference.value[k] != ossref::VIS_BACKGROUND && candidate.value[k] != ossref::VIS_BACKGROUND &&
                !reference.isGrazing(k))
                error.value[k] = ossref::encodeVisibility(std::abs(ossref::decodeVisibility(candidate.value[k]) -
                                                                   ossref::decodeVisibility(reference.value[k])));
        if (!ossref::writeVisibility(error, perLightName(options.visibilityError, index)))
            std::cerr << "cannot write " << perLightName(options.visibilityError, index) << "\n", status = 1;
    }
    std::printf("light=%u light_size=%g vis_mae=%.5f vis_mae_penumbra=%.5f vis_p99_penumbra=%.5f "
                "penumbra_pixels=%lld hard_wrong_pct=%.4f\n",
                index, options.lightSize, c.visMae, c.visMaePenumbra, c.visP99Penumbra, c.penumbraPixels,
                c.hardWrongPct);
    return status;
}

/** The peer's reference: `reference` with the pixels where the peer's vertex normals and the
 *  faces disagree on facing left out (MEASURE.md); their number in `excluded`. */
ossref::Mask peerReference(const ossref::Mask& reference, const osshar::PreparedScene& scene,
                           const ossref::Camera& camera, const osshar::PeerMask& peerMask, unsigned int index,
                           long long& excluded)
{
    const ossref::Light light = osshar::referenceLight(scene.lights[index]);
    return osshar::excludeFacingDisagreement(reference, osshar::referenceFacing(*scene.content, camera, light),
                                             peerMask.vertexFacing, excluded);
}

/** The eye-distance bands of the scores (docs/outdoor.md): 0-20, 20-200 and beyond. */
const std::vector<double>& distanceBands()
{
    static const std::vector<double> edges{20.0, 200.0};
    return edges;
}

/** " wrong_pct_near=... near_pixels=... wrong_pct_mid=... ..." of a mask against a reference
 *  with distances; empty without them. */
std::string bandScores(const ossref::Mask& mask, const ossref::Mask& reference)
{
    const std::vector<ossref::BandScore> bands = ossref::compareMasksByDistance(mask, reference, distanceBands());
    std::string out;
    const char* names[] = {"near", "mid", "far"};
    for (std::size_t b = 0; b < bands.size() && b < 3; ++b)
    {
        char buf[160];
        std::snprintf(buf, sizeof(buf), " wrong_pct_%s=%.4f %s_pixels=%lld %s_wrong_pixels=%lld", names[b],
                      bands[b].wrongPct, names[b], bands[b].geometryPixels, names[b], bands[b].wrongPixels);
        out += buf;
    }
    return out;
}

/** --score-every-frame: per light, the wrong_pct of each timed frame's mask and the flicker
 *  between consecutive timed frames. */
struct FrameScores
{
    std::vector<std::vector<double>> wrongPct;         ///< [light][timed frame]
    std::vector<std::vector<double>> flickerPct;       ///< [light][timed frame after the first]
    std::vector<ossref::Mask> lastMask, lastReference; ///< [light]: the previous frame's
    int failures = 0;                                  ///< masks that could not be compared
};

/** What the per-frame scores render: the technique's masks, or a peer's (first light). */
struct FrameSubject
{
    SilhouetteShadowTechnique* technique = nullptr;
    osg::Node* peerRoot = nullptr;
    osg::ref_ptr<osg::Node> unshadowed; ///< a peer's unshadowed frame

    unsigned int lights(const osshar::PreparedScene& scene) const
    {
        return technique ? unsigned(scene.lights.size()) : std::min<unsigned>(1, unsigned(scene.lights.size()));
    }
};

/** Light `i`'s mask of the frame just rendered and its exact reference. */
void frameMasks(const osshar::PreparedScene& scene, const ossref::Camera& camera, osshar::Renderer& renderer,
                const FrameSubject& subject, unsigned int i, ossref::Mask& mask, ossref::Mask& reference)
{
    osshar::PeerMask peerMask;
    if (subject.technique)
        mask = renderMask(renderer, *subject.technique, i);
    else
        mask = (peerMask = osshar::renderPeerMask(renderer, subject.peerRoot, subject.unshadowed.get())).mask;
    reference = ossref::computeReferenceMask(*scene.content, camera, osshar::referenceLight(scene.lights[i]),
                                             scene.castsMask, scene.referenceTraversalMask());
    long long excluded = 0;
    if (!subject.technique) reference = peerReference(reference, scene, camera, peerMask, i, excluded);
}

/** Scores the frame just rendered: each light's mask, rendered again at the same simulation
 *  time, against the exact reference of the scene as that frame left it, and its flicker
 *  against the previous timed frame. */
void scoreFrame(const osshar::PreparedScene& scene, const ossref::Camera& camera, osshar::Renderer& renderer,
                const FrameSubject& subject, int frame, FrameScores& scores)
{
    const unsigned int lights = subject.lights(scene);
    scores.wrongPct.resize(lights), scores.flickerPct.resize(lights);
    scores.lastMask.resize(lights), scores.lastReference.resize(lights);
    for (unsigned int i = 0; i < lights; ++i)
    {
        ossref::Mask mask, reference;
        frameMasks(scene, camera, renderer, subject, i, mask, reference);
        const ossref::Comparison c = ossref::compareMasks(mask, reference);
        if (!c.valid)
        {
            std::cerr << "osgsilhouetteshadow: frame " << frame << ": cannot compare: " << c.error << "\n";
            ++scores.failures;
            continue;
        }
        const ossref::FlickerCount f =
            ossref::countFlicker(scores.lastMask[i], mask, scores.lastReference[i], reference);
        std::printf("frame=%d time=%.4f light=%u geometry_pixels=%lld wrong_pixels=%lld wrong_pct=%.4f%s", frame,
                    renderer.simulationTime(), i, c.geometryPixels, c.wrongPixels, c.wrongPct,
                    bandScores(mask, reference).c_str());
        if (f.valid) std::printf(" flicker_pixels=%lld flicker_pct=%.4f", f.flickerPixels, f.flickerPct);
        std::printf("\n");
        scores.wrongPct[i].push_back(c.wrongPct);
        if (f.valid) scores.flickerPct[i].push_back(f.flickerPct);
        scores.lastMask[i] = std::move(mask), scores.lastReference[i] = std::move(reference);
    }
}

double mean(const std::vector<double>& v)
{
    double sum = 0.0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
}

void printFrameScores(const FrameScores& scores)
{
    for (std::size_t i = 0; i < scores.wrongPct.size(); ++i)
    {
        const std::vector<double>& w = scores.wrongPct[i];
        if (w.empty()) continue;
        std::printf("light=%zu frames_scored=%zu frame_wrong_pct_max=%.4f frame_wrong_pct_mean=%.4f\n", i, w.size(),
                    *std::max_element(w.begin(), w.end()), mean(w));
        const std::vector<double>& f = scores.flickerPct[i];
        if (!f.empty())
            std::printf("light=%zu flicker_frames=%zu flicker_pct=%.4f flicker_pct_max=%.4f\n", i, f.size(), mean(f),
                        *std::max_element(f.begin(), f.end()));
    }
}

/** --camera-path FILE read as an osg::AnimationPath (its text format); null with a message
 *  when it cannot be read or holds no control point. */
osg::ref_ptr<osg::AnimationPath> readCameraPath(const std::string& file, std::string& error)
{
    std::ifstream in(file);
    if (!in)
    {
        error = "--camera-path: cannot read " + file;
        return nullptr;
    }
    osg::ref_ptr<osg::AnimationPath> path = new osg::AnimationPath;
    path->read(in);
    if (path->empty()) error = "--camera-path: " + file + " holds no control point (time x y z qx qy qz qw lines)";
    path->setLoopMode(osg::AnimationPath::NO_LOOPING);
    return path->empty() ? nullptr : path;
}

/** The view of a camera path `t` seconds after its first time: the control point's camera
 *  matrix (osgGA::AnimationPathManipulator's) looking along its -z with its +y up. */
osshar::View viewOnPath(const osg::AnimationPath& path, double t, double fovy)
{
    osg::AnimationPath::ControlPoint cp;
    path.getInterpolatedControlPoint(path.getFirstTime() + t, cp);
    osg::Matrixd m;
    cp.getMatrix(m);
    const osg::Vec3d eye = m.getTrans();
    return {eye, eye + osg::Matrixd::transform3x3(osg::Vec3d(0, 0, -1), m),
            osg::Matrixd::transform3x3(osg::Vec3d(0, 1, 0), m), fovy};
}

} // namespace

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    osshar::GLErrorCounter& glErrors = osshar::installGLErrorCounter();
    if (arguments.read("-h") || arguments.read("--help"))
    {
        std::cout << osshar::renderOptionsUsage(arguments.getApplicationName());
        return 0;
    }
    if (arguments.read("--list-modes"))
    {
        for (int m = SilhouetteShadowTechnique::SHADOW_MAP; m <= SilhouetteShadowTechnique::SHADOW_VOLUME; ++m)
            std::cout << SilhouetteShadowTechnique::modeName(SilhouetteShadowTechnique::Mode(m)) << "\n";
        return 0;
    }
    osshar::RenderOptions options;
    std::string error;
    osshar::PreparedScene scene;
    osg::ref_ptr<osg::Node> root;
    osg::ref_ptr<SilhouetteShadowTechnique> technique;
    osg::ref_ptr<osg::AnimationPath> cameraPath;
    if (!osshar::parseRenderOptions(arguments, options, error) || !osshar::prepareScene(options, scene, error) ||
        !osshar::makeShadowedRoot(options.mode, options.mapSize, scene, root, technique, error) ||
        (!options.cameraPath.empty() && !(cameraPath = readCameraPath(options.cameraPath, error))))
    {
        std::cerr << "osgsilhouetteshadow: " << error << "\n" << osshar::renderOptionsUsage(arguments.getApplicationName());
        return 1;
    }
    if (technique)
    {
        SilhouetteShadowTechnique::Tuning tuning = technique->getTuning();
        tuning.skipEmptyFaces = options.skipEmptyFaces;
        technique->setTuning(tuning);
        osshar::applyProperties(options, *technique);
    }
    osg::DisplaySettings::instance()->setMinimumNumStencilBits(8);
    const bool batch = options.offscreen || !options.out.empty() || !options.mask.empty() ||
                       !options.reference.empty() || !options.classes.empty() || !options.visibility.empty() ||
                       !options.referenceVisibility.empty() || !options.compareVisibility.empty();
    if (!batch) return runWindowed(scene, root.get(), technique.get());

    osshar::Renderer renderer(options.width, options.height, options.offscreen);
    if (!renderer.valid())
    {
        std::cerr << "osgsilhouetteshadow: cannot create a graphics context (is DISPLAY set? try xvfb-run)\n";
        return 1;
    }
    if (options.checkGLErrors)
        if (osg::GraphicsContext* gc = renderer.viewer().getCamera()->getGraphicsContext())
            gc->getState()->setCheckForGLErrors(osg::State::ONCE_PER_ATTRIBUTE);
    renderer.setSceneData(root.get());
    renderer.setView(scene.view);
    // --moving-light: light 0 turns by +-0.1 degree about the vertical every frame, so that
    // no light-space pass can be reused (the cost of a frame in which the light moves);
    // --rotating-light DEG: it turns on by DEG degrees every frame (a slow sun, for flicker).
    osg::Light* moving = options.movingLight && !scene.lights.empty() ? scene.lights[0].source->getLight() : nullptr;
    const osg::Vec4 rest = moving ? moving->getPosition() : osg::Vec4();
    if (options.animate)
    {
        unsigned int others = 0;
        std::printf("animations_playing=%u\n", osshar::playAnimations(root.get(), &others));
        if (others)
            std::cerr << "osgsilhouetteshadow: --animate plays BasicAnimationManagers only; " << others
                      << " other animation managers left as they are\n";
    }
    ossref::Camera refCamera = osshar::referenceCamera(scene.view, options.width, options.height);
    const bool peer = osshar::isPeerMode(options.mode);
    FrameScores frameScores;
    const FrameSubject subject{technique.get(), root.get(), peer ? osshar::makeUnshadowedRoot(scene) : nullptr};
    const auto beforeFrame = [&](int frame) {
        if (options.animate) renderer.setSimulationTime(frame * options.timeStep);
        if (cameraPath)
        {
            scene.view =
                viewOnPath(*cameraPath, std::max(0, frame - options.warmup) * options.timeStep, scene.view.fovy);
            renderer.setView(scene.view);
            refCamera = osshar::referenceCamera(scene.view, options.width, options.height);
        }
        if (!moving) return;
        const double angle = osg::DegreesToRadians(options.lightTurnDeg != 0.0 ? frame * options.lightTurnDeg
                                                                               : (frame % 2 ? 0.1 : -0.1));
        moving->setPosition(rest * osg::Matrix::rotate(angle, osg::Vec3(0.0f, 0.0f, 1.0f)));
    };
    const auto afterFrame = [&](int frame) {
        if (options.scoreEveryFrame && (technique || peer) && frame >= options.warmup)
            scoreFrame(scene, refCamera, renderer, subject, frame, frameScores);
    };
    const osshar::FrameTiming timing = renderer.timeFrames(options.warmup, options.frames, beforeFrame, afterFrame);
    int status = frameScores.failures ? 1 : 0;
    printFrameScores(frameScores);
    std::printf("frame_ms_median=%.3f\n", timing.cpuMsMedian);
    if (timing.gpuMsMedian >= 0.0) std::printf("gpu_ms_median=%.3f\n", timing.gpuMsMedian);
    if (technique)
    {
        const SilhouetteShadowTechnique::Statistics s = technique->getStatistics();
        std::printf("lights_found=%u lights_shadowed=%u shadow_passes=%u silhouette_edges=%u zfail_casters=%u "
                    "zpass_casters=%u volumes_rebuilt=%u extractions_skipped=%u\n",
                    s.lightsFound, s.lightsShadowed, s.shadowPasses, s.silhouetteEdges, s.zfailCasters, s.zpassCasters,
                    s.volumesRebuilt, s.extractionsSkipped);
        std::printf("viewport_pixels=%u silhouette_pixels=%lld volume_fragments=%lld volume_overdraw=%.3f "
                    "blockers_tested=%u blockers_skipped=%u triangle_lists=%d list_images=%d\n",
                    s.viewportPixels, s.silhouettePixels, s.volumeFragments, s.volumeOverdraw(), s.blockersTested,
                    s.blockersSkipped, s.triangleLists ? 1 : 0, s.listImages ? 1 : 0);
        std::printf("depth_passes_reused=%u silhouette_passes_reused=%u lights_skipped=%u volumes_culled=%u "
                    "depth_prepass=%d list_block_heads=%d slots_skipped=%u blended_round=%d\n",
                    s.depthPassesReused, s.silhouettePassesReused, s.lightsSkipped, s.volumesCulled,
                    s.depthPrepass ? 1 : 0, s.listBlockHeads ? 1 : 0, s.slotsSkipped, s.blendedRound ? 1 : 0);
        // HYBRID's penumbra pixels and rays are counted only while the technique records
        // statistics (a counter in its eye pass): a few frames after the timed ones, so that
        // the counter does not run in them.
        long long penumbraPixels = s.penumbraPixels, shadowRays = s.shadowRays, agreed = s.penumbraAgreed;
        if (technique->getMode() == SilhouetteShadowTechnique::HYBRID)
        {
            osg::ref_ptr<osg::Stats> stats = new osg::Stats("osgsilhouetteshadow");
            technique->setStats(stats.get());
            renderer.timeFrames(0, 3); // the counts come back a frame or two late
            const SilhouetteShadowTechnique::Statistics counted = technique->getStatistics();
            technique->setStats(nullptr);
            penumbraPixels = counted.penumbraPixels, shadowRays = counted.shadowRays, agreed = counted.penumbraAgreed;
        }
        std::printf("penumbra_pixels_cast=%lld penumbra_agreed=%lld shadow_rays=%lld\n", penumbraPixels, agreed,
                    shadowRays);
    }

    if (!options.classes.empty() && technique)
    {
        // DEBUG_CLASSES of each light: the pixels each mode treats as silhouette pixels.
        for (unsigned int i = 0; i < scene.lights.size(); ++i)
        {
            osg::ref_ptr<osg::Image> image = osshar::renderClasses(renderer, *technique, i);
            const osshar::ClassCounts c = osshar::countClasses(*image);
            std::printf("light=%u silhouette_pixel_pct=%.4f silhouette_pixels=%lld geometry_pixels=%lld\n", i,
                        c.silhouettePercent(), c.silhouette(), c.geometry);
            if (!osgDB::writeImageFile(*image, perLightName(options.classes, i)))
                std::cerr << "cannot write " << perLightName(options.classes, i) << "\n", status = 1;
        }
    }
    if (!options.out.empty())
    {
        osg::ref_ptr<osg::Image> color = renderer.renderAndCapture();
        if (!osgDB::writeImageFile(*color, options.out)) std::cerr << "cannot write " << options.out << "\n";
    }
    const unsigned int maskLights = peer ? std::min<unsigned int>(1, scene.lights.size()) : scene.lights.size();
    for (unsigned int i = 0; i < maskLights; ++i)
    {
        ossref::Mask mask, reference;
        osshar::PeerMask peerMask;
        // A mask is rendered for --mask, --compare and --diff, and for --reference to score
        // it; --mode none with --reference alone writes the reference only.
        const bool maskWanted =
            !options.mask.empty() || !options.compare.empty() || !options.diff.empty() || !options.visibility.empty();
        if (maskWanted || (!options.reference.empty() && (peer || technique)))
        {
            if (peer)
            {
                peerMask = osshar::renderPeerMask(renderer, root.get(), osshar::makeUnshadowedRoot(scene).get());
                mask = peerMask.mask;
            }
            else if (!technique)
            {
                std::cerr << "osgsilhouetteshadow: --mask needs one of this project's modes\n";
                return 1;
            }
            else
                mask = renderMask(renderer, *technique, i);
            if (!options.mask.empty() && !ossref::writeMask(mask, perLightName(options.mask, i)))
                std::cerr << "cannot write " << perLightName(options.mask, i) << "\n", status = 1;
        }
        if (writeVisibility(options, scene, refCamera, peerMask.visibility, renderer, peer ? nullptr : technique.get(),
                            i) != 0)
            status = 1;
        if (!options.reference.empty() || (!options.compare.empty() && !ossref::readMask(perLightName(options.compare, i), reference)))
        {
            reference = ossref::computeReferenceMask(
                *scene.content, refCamera, osshar::referenceLight(scene.lights[i]), scene.castsMask,
                scene.referenceTraversalMask(),
                options.referenceOffset >= 0.0 ? options.referenceOffset : ossref::DEFAULT_OFFSET_SCALE);
            if (!options.reference.empty()) ossref::writeMask(reference, perLightName(options.reference, i));
        }
        if (mask.empty() || reference.empty()) continue;
        if (peer)
        {
            long long excluded = 0;
            reference = peerReference(reference, scene, refCamera, peerMask, i, excluded);
            std::printf("facing_excluded_pixels=%lld\n", excluded);
        }
        const ossref::Comparison c = ossref::compareMasks(mask, reference);
        if (!c.valid)
        {
            std::cerr << "osgsilhouetteshadow: cannot compare: " << c.error << "\n";
            status = 1;
            continue;
        }
        std::printf("light=%u geometry_pixels=%lld wrong_pixels=%lld wrong_pct=%.4f coverage_mismatch=%lld\n", i,
                    c.geometryPixels, c.wrongPixels, c.wrongPct, c.coverageMismatch);
        const std::string bands = bandScores(mask, reference);
        if (!bands.empty()) std::printf("light=%u%s\n", i, bands.c_str());
        if (!options.diff.empty()) osgDB::writeImageFile(*ossref::diffImage(mask, reference), perLightName(options.diff, i));
    }
    // Every frame rendered above, the masks' and images' included.
    std::printf("gl_errors=%lld\n", glErrors.count());
    return status;
}
