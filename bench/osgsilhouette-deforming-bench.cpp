/* osgsilhouette-deforming-bench: what a caster whose vertex array changes every frame costs the
 * technique, against the same caster held still (docs/benchmarks.md, "Deforming casters").
 *
 *   osgsilhouette-deforming-bench [--casters bunny,torus1m] [--techniques shadowmap,silhouette,...]
 *       [--size W H] [--map-size N] [--frames N] [--warmup N] [--rounds N] [--out-dir DIR] [--shader]
 *
 * Each caster stands on a ground under one directional light. In the variant "deforming" an
 * update callback moves every vertex of the caster by a small travelling wave each frame, then
 * dirty()s the vertex array and the bound, as an application or osgAnimation's
 * RigTransformSoftware does; in "still" the same callback leaves the array untouched. Per
 * frame it records the CPU time of the ShadowedScene's cull traversal (the technique's cull:
 * its light-space passes, extraction, volumes, and the eye pass's cull of the scene), the
 * time the wave itself took (in the update traversal, reported apart), and the wall time of
 * viewer.frame() with glFinish (update, cull, draw). Both variants of a (caster, technique)
 * run back to back on one technique, in alternating order from round to round, so that drift
 * of a shared machine falls on both.
 *
 * With --shader the caster's own vertex shader writes the same wave instead (its program
 * marked ShadowMovesVertices, its vertex array never changes): "deforming" advances the
 * wave's phase uniform, "still" holds it. The technique finds such a caster's silhouette
 * edges and extrudes its volumes on the GPU, so its cull delta is what that costs the CPU
 * and its frame delta what it costs the whole frame. Its rows name the caster "NAME+shader".
 *
 * Writes DIR/deforming.csv (one row per round, caster, technique and variant, medians over the
 * timed frames) and DIR/deforming.md, and prints the summary table (medians over rounds, with
 * the rounds' spread) to stdout. Progress goes to stderr. */

#include "Meshes.h"
#include "Offscreen.h"
#include "Scenes.h"
#include "Setup.h"
#include "Text.h"

#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/Program>
#include <osg/Timer>
#include <osg/TriangleFunctor>
#include <osg/Uniform>
#include <osgShadow/ShadowedScene>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osshar::fixed;
using osshar::median;
using osshar::splitList;

const char* const CSV_HEADER = "round,caster,faces,technique,map_size,width,height,variant,frames,cull_ms_median,"
                               "frame_ms_median,gpu_ms_median,wave_ms_median,mesh_builds,mesh_refreshes";

struct Options
{
    std::vector<std::string> casters{"bunny", "torus1m"};
    std::vector<std::string> techniques{"shadowmap", "silhouette", "volume", "hybrid"};
    int width = 512, height = 384;
    unsigned int mapSize = 1024;
    int frames = 20, warmup = 3, rounds = 3;
    std::string outDir = "bench-deforming";
    bool shader = false; ///< the wave in the caster's vertex shader (--shader)
};

/** The wave of --shader, in the caster's vertex stage (the contract of docs/animation.md:
 *  gl_Position from gl_ModelViewProjectionMatrix and the moved object-space position). */
const char* const WAVE_VERTEX = R"(#version 400 compatibility
uniform float bench_phase;
uniform float bench_amplitude;
uniform float bench_waveNumber;
void main()
{
    vec4 p = gl_Vertex;
    p.z += bench_amplitude * sin(bench_waveNumber * (p.x + p.y + p.z) + bench_phase);
    gl_Position = gl_ModelViewProjectionMatrix * p;
    gl_FrontColor = gl_Color;
}
)";
const char* const WAVE_FRAGMENT = R"(#version 400 compatibility
void main() { gl_FragColor = gl_Color; }
)";

/** The travelling wave of the variant "deforming": each vertex moves along z by a function of
 *  its rest position and the frame number. A function of the position, not of the index, so
 *  that vertices the mesh cache welds (the same position in several array slots, as OBJ
 *  loaders and seams give) move together and the refresh keeps the topology. Time spent
 *  writing the wave is kept apart: it is the application's work, not the technique's. */
class Wave : public osg::DrawableUpdateCallback
{
public:
    explicit Wave(const osg::Geometry& g)
        : _rest(new osg::Vec3Array(*static_cast<const osg::Vec3Array*>(g.getVertexArray()), osg::CopyOp::DEEP_COPY_ALL))
    {
        const osg::BoundingBox& bb = g.getBoundingBox();
        const float size = (bb.xMax() - bb.xMin()) + (bb.yMax() - bb.yMin()) + (bb.zMax() - bb.zMin());
        _amplitude = 0.005f * size; // small: the shadow's shape changes, not its place
        _waveNumber = float(2.0 * M_PI * 4.0) / size;
    }

    bool deforming = false;
    double lastMs = 0.0; ///< the last update's time writing the wave; 0 when still

    /** Moves @p g in its own vertex stage (--shader): a program marked as moving vertices,
     *  the wave's uniforms, and a bound that holds every pose. */
    void moveInShader(osg::Geometry& g)
    {
        osg::ref_ptr<osg::Program> program = new osg::Program;
        program->addShader(new osg::Shader(osg::Shader::VERTEX, WAVE_VERTEX));
        program->addShader(new osg::Shader(osg::Shader::FRAGMENT, WAVE_FRAGMENT));
        program->setUserValue(SilhouetteShadowTechnique::MOVES_VERTICES_USER_VALUE, true);
        osg::StateSet* ss = g.getOrCreateStateSet();
        ss->setAttributeAndModes(program.get(), osg::StateAttribute::ON);
        _phase = new osg::Uniform("bench_phase", 0.0f);
        ss->addUniform(_phase.get());
        ss->addUniform(new osg::Uniform("bench_amplitude", _amplitude));
        ss->addUniform(new osg::Uniform("bench_waveNumber", _waveNumber));
        osg::BoundingBox box = g.getBoundingBox();
        box.expandBy(box._min - osg::Vec3(0, 0, _amplitude));
        box.expandBy(box._max + osg::Vec3(0, 0, _amplitude));
        g.setInitialBound(box);
    }

    void update(osg::NodeVisitor* nv, osg::Drawable* drawable) override
    {
        lastMs = 0.0;
        osg::Geometry* g = drawable->asGeometry();
        if (!deforming || !g || !nv->getFrameStamp()) return;
        const osg::Timer_t t0 = osg::Timer::instance()->tick();
        const float phase = 0.4f * float(nv->getFrameStamp()->getFrameNumber() % 1000);
        if (_phase)
        {
            _phase->set(phase);
            lastMs = osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick());
            return;
        }
        osg::Vec3Array& v = *static_cast<osg::Vec3Array*>(g->getVertexArray());
        for (std::size_t i = 0; i < v.size(); ++i)
        {
            const osg::Vec3& p = (*_rest)[i];
            v[i] = p + osg::Vec3(0.0f, 0.0f, _amplitude * std::sin(_waveNumber * (p.x() + p.y() + p.z()) + phase));
        }
        v.dirty();
        g->dirtyBound();
        lastMs = osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick());
    }

private:
    osg::ref_ptr<osg::Vec3Array> _rest;
    float _amplitude = 0.0f, _waveNumber = 0.0f;
    osg::ref_ptr<osg::Uniform> _phase; ///< --shader: the wave's phase in the vertex stage
};

/** The CPU time of the last cull traversal of the node it is the cull callback of. */
class CullTimer : public osg::NodeCallback
{
public:
    double lastMs = 0.0;

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        const osg::Timer_t t0 = osg::Timer::instance()->tick();
        traverse(node, nv);
        lastMs = osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick());
    }
};

struct TriangleCounter
{
    unsigned long long count = 0;
    void operator()(const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++count; }
};

unsigned long long triangleCount(const osg::Geometry& g)
{
    osg::TriangleFunctor<TriangleCounter> counter;
    g.accept(counter);
    return counter.count;
}

/** The geometry with the most vertices below a node: the caster (the ground has four). */
class LargestGeometry : public osg::NodeVisitor
{
public:
    LargestGeometry() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    osg::Geometry* found = nullptr;

    void apply(osg::Geometry& g) override
    {
        const osg::Array* v = g.getVertexArray();
        if (v && dynamic_cast<const osg::Vec3Array*>(v) &&
            (!found || v->getNumElements() > found->getVertexArray()->getNumElements()))
            found = &g;
    }
};

struct Caster
{
    std::string name;
    osshar::PreparedScene scene;
    osg::ref_ptr<osg::Geometry> geometry;
    osg::ref_ptr<Wave> wave;
    unsigned long long faces = 0;
};

/** "bunny": the built-in scene bunny (glmark2-data's bunny.obj, 69,666 triangles). "torus1m": a
 *  torus of 1000 x 500 quads (1,000,000 triangles) tilted 50 degrees, put on a ground as the
 *  corpus runs place models, under the built-in scenes' sun. */
bool makeCaster(const std::string& name, bool shader, Caster& c, std::string& error)
{
    osshar::Scene s;
    if (name == "bunny")
        s = osshar::createScene("bunny");
    else if (name == "torus1m")
    {
        osg::ref_ptr<osg::MatrixTransform> tilted =
            new osg::MatrixTransform(osg::Matrixd::rotate(osg::DegreesToRadians(50.0), osg::Vec3d(1, 0, 0)));
        tilted->addChild(
            osshar::coloured(osshar::makeTorus(osg::Vec3(), 1.0f, 0.35f, 1000, 500), osg::Vec4(0.8f, 0.55f, 0.35f, 1)));
        s = osshar::placeOnGround(tilted.get(), name);
        s.root->addChild(osshar::makeLight(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f)));
    }
    else
        return error = "unknown caster '" + name + "' (bunny, torus1m)", false;
    if (!s.root) return error = "cannot build caster '" + name + "'", false;
    LargestGeometry largest;
    s.root->accept(largest);
    if (!largest.found) return error = "no geometry in '" + name + "'", false;
    c.name = shader ? name + "+shader" : name;
    c.scene.content = s.root;
    c.scene.view = s.view;
    c.scene.lights = osshar::findLights(s.root.get());
    c.geometry = largest.found;
    c.faces = triangleCount(*c.geometry);
    c.wave = new Wave(*c.geometry);
    if (shader) c.wave->moveInShader(*c.geometry);
    c.geometry->setUpdateCallback(c.wave.get());
    return true;
}

struct Row
{
    int round = 0;
    std::string caster, technique, variant;
    unsigned long long faces = 0;
    int frames = 0;
    double cullMs = 0, frameMs = 0, gpuMs = -1, waveMs = 0;
    std::size_t builds = 0, refreshes = 0;
};

/** Times one variant on the root already set: per-frame cull and wave times, and the mesh
 *  cache's builds and refreshes over the timed frames. */
Row measureVariant(osshar::Renderer& renderer, Caster& c, SilhouetteShadowTechnique& technique, CullTimer& cull,
                   bool deforming, const Options& o)
{
    c.wave->deforming = deforming;
    std::vector<double> cullMs, waveMs;
    std::size_t builds = 0, refreshes = 0;
    const osgShadowSilhouette::MeshCache& cache = *technique.getMeshCache();
    const auto before = [&](int i) {
        if (i == o.warmup) builds = cache.getBuildCount(), refreshes = cache.getRefreshCount();
    };
    const auto after = [&](int i) {
        if (i < o.warmup) return;
        cullMs.push_back(cull.lastMs);
        waveMs.push_back(c.wave->lastMs);
    };
    const osshar::FrameTiming timing = renderer.timeFrames(o.warmup, o.frames, before, after);
    Row r;
    r.caster = c.name, r.technique = SilhouetteShadowTechnique::modeName(technique.getMode());
    r.variant = deforming ? "deforming" : "still";
    r.faces = c.faces, r.frames = timing.frames;
    r.cullMs = median(cullMs), r.frameMs = timing.cpuMsMedian, r.gpuMs = timing.gpuMsMedian, r.waveMs = median(waveMs);
    r.builds = cache.getBuildCount() - builds, r.refreshes = cache.getRefreshCount() - refreshes;
    return r;
}

std::string csvLine(const Row& r, const Options& o)
{
    std::ostringstream s;
    s << r.round << ',' << r.caster << ',' << r.faces << ',' << r.technique << ',' << o.mapSize << ',' << o.width << ','
      << o.height << ',' << r.variant << ',' << r.frames << ',' << fixed(r.cullMs, 3) << ',' << fixed(r.frameMs, 3)
      << ',' << fixed(r.gpuMs, 3) << ',' << fixed(r.waveMs, 3) << ',' << r.builds << ',' << r.refreshes;
    return s.str();
}

/** One (caster, technique) over the rounds: per round the still and deforming medians. */
struct Pair
{
    std::vector<const Row*> still, deforming;
};

double medianOf(const std::vector<const Row*>& rows, double Row::*field)
{
    std::vector<double> v;
    for (const Row* r : rows) v.push_back(r->*field);
    return median(v);
}

/** Per round, deforming - still of a field; the median over rounds and its range. */
void deltas(const Pair& p, double Row::*field, double& mid, double& lo, double& hi)
{
    std::vector<double> d;
    for (std::size_t k = 0; k < p.still.size() && k < p.deforming.size(); ++k)
        d.push_back(p.deforming[k]->*field - p.still[k]->*field);
    mid = median(d);
    lo = d.empty() ? 0.0 : *std::min_element(d.begin(), d.end());
    hi = d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
}

/** The summary: per caster and technique, medians over rounds of the per-round medians; the
 *  deltas with their range over rounds (how noisy the machine was). */
std::string summaryTable(const std::vector<Row>& rows, const Options& o)
{
    std::vector<std::pair<std::string, std::string>> keys;
    std::map<std::pair<std::string, std::string>, Pair> pairs;
    for (const Row& r : rows)
    {
        const auto key = std::make_pair(r.caster, r.technique);
        if (!pairs.count(key)) keys.push_back(key);
        (r.variant == "still" ? pairs[key].still : pairs[key].deforming).push_back(&r);
    }
    std::ostringstream md;
    md << "| caster | faces | technique | cull ms still | cull ms deforming | cull delta ms (range over rounds) | "
          "cull delta ns/face | frame ms still | frame ms deforming | frame delta ms (range) | GPU delta ms | "
          "wave ms | refreshes/frame |\n"
          "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& key : keys)
    {
        const Pair& p = pairs[key];
        if (p.still.empty() || p.deforming.empty()) continue;
        const unsigned long long faces = p.still.front()->faces;
        double cd, cl, ch, fd, fl, fh, gd, gl, gh;
        deltas(p, &Row::cullMs, cd, cl, ch);
        deltas(p, &Row::frameMs, fd, fl, fh);
        deltas(p, &Row::gpuMs, gd, gl, gh);
        std::size_t refreshes = 0;
        for (const Row* r : p.deforming) refreshes += r->refreshes;
        md << "| " << key.first << " | " << faces << " | " << key.second << " | "
           << fixed(medianOf(p.still, &Row::cullMs), 2) << " | " << fixed(medianOf(p.deforming, &Row::cullMs), 2)
           << " | " << fixed(cd, 2) << " (" << fixed(cl, 2) << " .. " << fixed(ch, 2) << ") | "
           << fixed(cd * 1e6 / double(faces), 1) << " | " << fixed(medianOf(p.still, &Row::frameMs), 1) << " | "
           << fixed(medianOf(p.deforming, &Row::frameMs), 1) << " | " << fixed(fd, 1) << " (" << fixed(fl, 1) << " .. "
           << fixed(fh, 1) << ") | " << fixed(gd, 1) << " | " << fixed(medianOf(p.deforming, &Row::waveMs), 2) << " | "
           << fixed(double(refreshes) / double(p.deforming.size() * std::size_t(o.frames)), 2) << " |\n";
    }
    return md.str();
}

void usage(const char* program)
{
    std::cout << "usage: " << program
              << " [--casters bunny,torus1m] [--techniques shadowmap,silhouette,volume,hybrid]\n"
                 "       [--size W H] [--map-size N] [--frames N] [--warmup N] [--rounds N] [--out-dir DIR] "
                 "[--shader]\n";
}

bool parseOptions(osg::ArgumentParser& a, Options& o, std::string& error)
{
    std::string list;
    if (a.read("--casters", list)) o.casters = splitList(list);
    if (a.read("--techniques", list)) o.techniques = splitList(list);
    a.read("--size", o.width, o.height);
    a.read("--map-size", o.mapSize);
    a.read("--frames", o.frames);
    a.read("--warmup", o.warmup);
    a.read("--rounds", o.rounds);
    a.read("--out-dir", o.outDir);
    if (a.read("--shader")) o.shader = true;
    if (o.width < 1 || o.height < 1 || o.frames < 1 || o.warmup < 1 || o.rounds < 1 || o.casters.empty() ||
        o.techniques.empty())
        return error = "bad --size, --frames, --warmup (at least 1), --rounds, --casters or --techniques", false;
    for (const std::string& t : o.techniques)
    {
        SilhouetteShadowTechnique::Mode m;
        if (!SilhouetteShadowTechnique::modeFromName(t, m)) return error = "unknown technique '" + t + "'", false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    if (arguments.read("-h") || arguments.read("--help")) return usage(argv[0]), 0;
    Options o;
    std::string error;
    if (!parseOptions(arguments, o, error))
    {
        std::cerr << "osgsilhouette-deforming-bench: " << error << "\n";
        usage(argv[0]);
        return 1;
    }
    std::vector<Caster> casters(o.casters.size());
    for (std::size_t i = 0; i < casters.size(); ++i)
        if (!makeCaster(o.casters[i], o.shader, casters[i], error))
        {
            std::cerr << "osgsilhouette-deforming-bench: " << error << "\n";
            return 1;
        }
    if (std::system(("mkdir -p '" + o.outDir + "'").c_str()) != 0) return 1;
    std::ofstream csv(o.outDir + "/deforming.csv");
    csv << CSV_HEADER << "\n";
    // One viewer for the whole run, never destroyed (as osgsilhouette-bench: OSG 3.6.5 can
    // deadlock destroying a viewer whose CullVisitors an osg::Identifier observes).
    osshar::Renderer* renderer = new osshar::Renderer(o.width, o.height, true);
    if (!renderer->valid())
    {
        std::cerr << "osgsilhouette-deforming-bench: cannot create a graphics context (is DISPLAY set? try xvfb-run)\n";
        return 1;
    }
    std::vector<Row> rows;
    rows.reserve(std::size_t(o.rounds) * casters.size() * o.techniques.size() * 2);
    const osg::Timer_t start = osg::Timer::instance()->tick();
    for (int round = 1; round <= o.rounds; ++round)
        for (Caster& c : casters)
            for (const std::string& t : o.techniques)
            {
                // A new technique each round: its mesh cache is built in the warm-up of the
                // first variant, and both variants then run on the same cache.
                osg::ref_ptr<osg::Node> root;
                osg::ref_ptr<SilhouetteShadowTechnique> technique;
                if (!osshar::makeShadowedRoot(t, o.mapSize, c.scene, root, technique, error))
                {
                    std::cerr << "osgsilhouette-deforming-bench: " << error << "\n";
                    return 1;
                }
                technique->setPerPixelLighting(false); // as osgsilhouette-bench: fragment work, not shadow work
                osg::ref_ptr<CullTimer> cull = new CullTimer;
                root->setCullCallback(cull.get());
                renderer->setSceneData(root.get());
                renderer->setView(c.scene.view);
                // Still first in odd rounds, deforming first in even ones.
                for (int k = 0; k < 2; ++k)
                {
                    const bool deforming = (k == 1) == (round % 2 == 1);
                    Row r = measureVariant(*renderer, c, *technique, *cull, deforming, o);
                    r.round = round;
                    rows.push_back(r);
                    csv << csvLine(r, o) << "\n" << std::flush;
                    std::fprintf(stderr,
                                 "round %d %-8s %-10s %-9s cull %8.2f ms  frame %8.2f ms  wave %6.2f ms  builds %zu "
                                 "refreshes %zu  elapsed %.0f s\n",
                                 round, r.caster.c_str(), r.technique.c_str(), r.variant.c_str(), r.cullMs, r.frameMs,
                                 r.waveMs, r.builds, r.refreshes,
                                 osg::Timer::instance()->delta_s(start, osg::Timer::instance()->tick()));
                }
                c.wave->deforming = false;
                renderer->setSceneData(nullptr);
            }
    const std::string table = summaryTable(rows, o);
    std::ofstream(o.outDir + "/deforming.md")
        << "# Deforming casters against still ones\n\n"
        << o.width << "x" << o.height << ", map " << o.mapSize << ", " << o.rounds
        << " rounds; per round the median of " << o.frames << " frames after " << o.warmup
        << " warm-up frames per variant; below, medians over the rounds. cull: CPU time of the ShadowedScene's cull "
           "traversal; frame: wall time of viewer.frame() with glFinish, the wave's own time included; wave: the "
           "update callback writing the wave (application work); GPU: GL_TIME_ELAPSED of the frame.\n\n"
        << table;
    std::cout << table;
    return 0;
}
