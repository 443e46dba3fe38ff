// The renderer command line of MEASURE.md, shared by the renderer, the benchmark and tests.
#ifndef OSS_HARNESS_RENDEROPTIONS_H
#define OSS_HARNESS_RENDEROPTIONS_H

#include "Scenes.h"

#include <osg/ArgumentParser>

#include <optional>
#include <string>
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
    unsigned int maxShadowLights = 0; ///< --max-shadow-lights N: the technique's light budget (0: its default)
    int frames = 20;                  ///< --frames N: timed frames
    int warmup = 3;                   ///< --warmup N
    std::string out, mask;            ///< --out color.png, --mask mask.png (per light: %d, or _<i> before the extension)
    bool offscreen = false;           ///< --offscreen
    bool checkGLErrors = false;       ///< --check-gl-errors: OSG checks for GL errors after every attribute (slow)
    std::string compare;              ///< --compare ref.png: compare --mask against this reference mask
    std::string reference;            ///< --reference ref.png: write the exact Embree reference mask
    std::string diff;                 ///< --diff diff.png: red/green diff against the reference
    double referenceOffset = -1.0;    ///< --reference-offset S: the reference's offset scale (negative: ossref's default)
    bool blockerCulling = true;       ///< --blocker-culling on|off (HYBRID)
    bool hybridEdgeMask = true;       ///< --hybrid-edges on|off (HYBRID with triangle lists)
    bool perPixelLighting = true;     ///< --per-pixel-lighting on|off (the property PerPixelLighting)
    bool skipEmptyFaces = true;       ///< --skip-empty-faces on|off (SilhouetteShadowTechnique::Tuning)
    std::string hybridMethod = "auto"; ///< --hybrid-method auto|stencil|lists
    std::string depthPrepass = "auto"; ///< --depth-prepass auto|on|off
    float shadowRayOffset = -1.0f;     ///< --shadow-ray-offset F (negative: the technique's default)
    float polygonOffsetFactor = -1.0f; ///< --polygon-offset FACTOR UNITS of the depth pass (negative: the technique's default)
    float polygonOffsetUnits = -1.0f;
    bool movingLight = false;         ///< --moving-light: light 0 turns by +-0.1 degree every frame (no map is reused)
    std::string classes;              ///< --classes classes.png: DebugView DEBUG_CLASSES per light, with silhouette_pixel_pct
    std::string stats;                ///< --stats: print the technique's statistics
};

/** Reads the options from arguments (removing them). Returns false with a message in error
 *  on a malformed value. The first non-option argument is taken as the file. */
bool parseRenderOptions(osg::ArgumentParser& arguments, RenderOptions& options, std::string& error);

/** The usage text of those options. */
std::string renderOptionsUsage(const std::string& program);

} // namespace osshar

#endif
