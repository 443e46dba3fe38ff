// The renderer command line of MEASURE.md, shared by the renderer, the benchmark and tests.
#ifndef OSS_HARNESS_RENDEROPTIONS_H
#define OSS_HARNESS_RENDEROPTIONS_H

#include "Scenes.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/ArgumentParser>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace osshar {

/** A light given on the command line: --light-dir X Y Z (toward the light) or --light-pos X Y Z,
 *  the latter made a spot light by a following --spot-dir X Y Z and/or --spot-cutoff DEG. */
struct LightArg
{
    bool directional = true;
    osg::Vec3d vector;
    osg::Vec3d spotDirection{0.0, 0.0, -1.0}; ///< --spot-dir (OpenGL's default axis)
    double spotCutoff = 180.0;                ///< --spot-cutoff: half angle in degrees; 180: a point light

    bool spot() const { return !directional && spotCutoff <= 90.0; }

    /** --light-dir: a directional light toward `towardLight`. */
    static LightArg toward(const osg::Vec3d& towardLight)
    {
        LightArg light;
        light.vector = towardLight;
        return light;
    }
    /** --light-pos: a point light at `position`. */
    static LightArg at(const osg::Vec3d& position)
    {
        LightArg light;
        light.directional = false;
        light.vector = position;
        return light;
    }
};

struct RenderOptions
{
    std::string file;                 ///< model file; empty: the built-in scene `scene`
    std::string scene = "default";    ///< --scene NAME (built-in scenes)
    bool ground = false;              ///< --ground: put FILE on a ground, scaled and framed (placeOnGround())
    std::string mode = "shadowmap";   ///< --mode: shadowmap|silhouette|hybrid|volume|none|osgShadow:<Technique>
    unsigned int mapSize = 2048;      ///< --map-size N
    int width = 1024, height = 768;   ///< --size W H
    std::optional<osg::Vec3d> eye, center, up;
    std::optional<double> fovy;
    std::vector<LightArg> lights;     ///< --light-dir / --light-pos [--spot-dir] [--spot-cutoff] (repeatable)
    int frames = 20;                  ///< --frames N: timed frames
    int warmup = 3;                   ///< --warmup N
    std::string out, mask;            ///< --out color.png, --mask mask.png (per light: %d, or _<i> before the extension)
    bool offscreen = false;           ///< --offscreen
    bool checkGLErrors = false;       ///< --check-gl-errors: OSG checks for GL errors after every attribute (slow)
    std::string compare;              ///< --compare ref.png: compare --mask against this reference mask
    std::string reference;            ///< --reference ref.png: write the exact Embree reference mask
    std::string diff;                 ///< --diff diff.png: red/green diff against the reference
    double referenceOffset = -1.0; ///< --reference-offset S: the reference's offset scale (negative: ossref's default)
    bool skipEmptyFaces = true;       ///< --skip-empty-faces on|off (SilhouetteShadowTechnique::Tuning)
    /** --light-size S: every light's size (MEASURE.md, "Soft shadows"), for the technique's
     *  soft filters (its LightSize, also in properties) and the exact visibility reference:
     *  the radius of point and spot lights in scene units, the angular radius of directional
     *  lights in degrees; 0: a point or a single direction. */
    double lightSize = 0.0;
    std::string visibility;          ///< --visibility vis.png: the frame's visibility mask (16-bit)
    std::string referenceVisibility; ///< --reference-visibility ref.png: the exact visibility mask
    /** --compare-visibility ref.png: score --visibility against this exact visibility mask
     *  (written earlier by --reference-visibility at the same view and --light-size) instead
     *  of computing it again. */
    std::string compareVisibility;
    /** --visibility-error err.png: |v - v_ref| of --visibility against the exact visibility,
     *  as a visibility mask (16-bit), at the scored pixels (geometry in both, outside the
     *  reference's grazing band); no geometry elsewhere. */
    std::string visibilityError;
    /** The technique's properties set on the command line, in order, each checked against the
     *  table of properties (osgShadowSilhouette/Properties): --property NAME=VALUE, and the
     *  shorthands of propertyOptions() (--max-shadow-lights N, --hybrid-method lists, ...). */
    std::vector<std::pair<std::string, double>> properties;
    bool movingLight = false;         ///< --moving-light: light 0 turns by +-0.1 degree every frame (no map is reused)
    double lightTurnDeg = 0.0;        ///< --rotating-light DEG: light 0 turns on by DEG degrees every frame
    /** --animate: plays every animation of the scene's osgAnimation::BasicAnimationManagers,
     *  looping (playAnimations()), and renders frame k (warm-up frames first, from 0) at
     *  simulation time k * timeStep; the frames after them (masks, images) show the last. */
    bool animate = false;
    double timeStep = 1.0 / 30.0; ///< --time-step S: seconds of simulation time per frame (--animate, --camera-path)
    /** --score-every-frame: after each timed frame, each light's mask of that frame (rendered
     *  again at its simulation time) scored against its own exact reference. */
    bool scoreEveryFrame = false;
    /** --camera-path FILE: an osg::AnimationPath in its text format (as osgviewer records
     *  with 'z') that moves the camera: timed frame k shows the path at its first time plus
     *  k * timeStep (warm-up frames its first point, frames past its end its last); the
     *  masks and images after the timed frames show the last timed frame's view. The view
     *  keeps the scene's (or --fovy's) field of view. */
    std::string cameraPath;
    std::string classes;              ///< --classes classes.png: DebugView DEBUG_CLASSES per light, with silhouette_pixel_pct
    std::string stats;                ///< --stats: print the technique's statistics
};

/** The options that set one property of the technique: {"--hybrid-method", "HybridMethod"}, ... */
const std::vector<std::pair<std::string, std::string>>& propertyOptions();

/** The value given for property @p name (the last one), if any. */
std::optional<double> propertyValue(const RenderOptions& options, const std::string& name);

/** Sets the properties of options.properties on @p technique. */
void applyProperties(const RenderOptions& options, osgShadowSilhouette::SilhouetteShadowTechnique& technique);

/** Reads the options from arguments (removing them). Returns false with a message in error
 *  on a malformed value. The first non-option argument is taken as the file. */
bool parseRenderOptions(osg::ArgumentParser& arguments, RenderOptions& options, std::string& error);

/** The usage text of those options. */
std::string renderOptionsUsage(const std::string& program);

} // namespace osshar

#endif
