/* osgsilhouette-bench: frame time against error for every technique, ours and osgShadow's,
 * side by side in one run (MEASURE.md).
 *
 *   osgsilhouette-bench [--scenes default,cubes,...] [--techniques shadowmap,osgShadow:ShadowMap,...]
 *       [--sizes 256,512,1024,2048,4096] [--technique-sizes TECHNIQUE=a,b,...] [--size W H]
 *       [--frames N] [--warmup N] [--per-pixel-lighting on|off] [--user-program on|off]
 *       [--out-dir DIR] [--no-plot] [--list]
 *
 * Our modes light per vertex unless --per-pixel-lighting on (the property PerPixelLighting,
 * on by default in the technique): osgShadow's techniques light per vertex, and per-pixel
 * lighting is fragment work that is not shadow work.
 *
 * --user-program on draws the receivers with an application program given to
 * addShadowShaders() (per-pixel diffuse of every scene light times oss_shadowTerm()), as the
 * README's "Your own shaders" does: in the stencil modes this adds the screen-space
 * visibility image and its final pass. The score is the technique's mask either way.
 *
 * For each scene it builds the exact Embree reference once (one BVH, one mask per view), then
 * for each technique and map size renders offscreen, times the frames, reads the technique's
 * mask and compares it with the reference. Writes DIR/benchmark.csv (MEASURE.md's header),
 * DIR/benchmark.md (tables) and, with gnuplot, DIR/<scene>.png (frame time against wrong_pct,
 * the Pareto front drawn). Progress goes to stderr. */

#include "Classes.h"
#include "Offscreen.h"
#include "Peers.h"
#include "RenderOptions.h"
#include "Setup.h"
#include "Text.h"

#include <osg/LightSource>
#include <osg/Program>
#include <osg/Timer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osshar::splitList;

const char* const CSV_HEADER = "scene,technique,map_size,width,height,frames,frame_ms_median,gpu_ms_median,"
                               "geometry_pixels,wrong_pixels,wrong_pct,coverage_mismatch,silhouette_pixel_pct,notes";

struct Options
{
    std::vector<std::string> scenes{"default", "cubes", "tree", "bunny", "dueling", "grazing"};
    std::vector<std::string> techniques;                        ///< empty: every available one
    std::vector<unsigned int> sizes{256, 512, 1024, 2048, 4096};
    std::map<std::string, std::vector<unsigned int>> techniqueSizes; ///< --technique-sizes T=a,b
    int width = 1024, height = 768;
    int frames = 20, warmup = 3;
    std::string outDir = "bench-out";
    bool plot = true;
    bool perPixelLighting = false; ///< --per-pixel-lighting on|off: our modes' PerPixelLighting
    bool userProgram = false;      ///< --user-program on|off: receivers drawn by an application program
};

struct Row
{
    std::string scene, technique;
    unsigned int mapSize = 0;
    int width = 0, height = 0, frames = 0;
    double frameMs = 0, gpuMs = -1;
    ossref::Comparison cmp;
    double silhouettePct = -1; ///< share of geometry pixels treated as silhouette pixels; -1: does not apply
    std::string notes;
};

/** Our modes that this build implements, then the peers. */
std::vector<std::string> availableTechniques()
{
    std::vector<std::string> out;
    for (int m = SilhouetteShadowTechnique::SHADOW_MAP; m <= SilhouetteShadowTechnique::SHADOW_VOLUME; ++m)
        out.push_back(SilhouetteShadowTechnique::modeName(SilhouetteShadowTechnique::Mode(m)));
    for (const std::string& p : osshar::peerModes()) out.push_back(p);
    return out;
}

/** "ShadowMap" is accepted for "osgShadow:ShadowMap". */
std::string canonicalTechnique(const std::string& name)
{
    for (const std::string& p : osshar::peerModes())
        if (p == name || p.substr(std::string(osshar::PEER_PREFIX).size()) == name) return p;
    return name;
}

std::vector<unsigned int> parseSizes(const std::string& list)
{
    std::vector<unsigned int> out;
    for (const std::string& s : splitList(list)) out.push_back(unsigned(std::max(1, std::atoi(s.c_str()))));
    return out;
}

/** The map sizes to run a technique at: --technique-sizes, else --sizes. */
std::vector<unsigned int> sizesOf(const Options& o, const std::string& technique)
{
    auto it = o.techniqueSizes.find(technique);
    return it != o.techniqueSizes.end() ? it->second : o.sizes;
}

bool usesMapSize(const std::string& technique)
{
    return technique != "volume";
}

void usage(const char* program)
{
    std::cout << "usage: " << program
              << " [--scenes a,b] [--techniques x,y] [--sizes 256,512,...]\n"
                 "       [--technique-sizes TECHNIQUE=a,b,... (repeatable)] [--size W H] [--frames N]\n"
                 "       [--warmup N] [--per-pixel-lighting on|off] [--user-program on|off]\n"
                 "       [--out-dir DIR] [--no-plot] [--list]\n"
                 "Scenes: ";
    for (const std::string& s : osshar::sceneNames()) std::cout << s << " ";
    std::cout << "\nTechniques: ";
    for (const std::string& t : availableTechniques()) std::cout << t << " ";
    std::cout << "\n";
}

bool parseOptions(osg::ArgumentParser& a, Options& o, std::string& error)
{
    std::string list;
    if (a.read("--scenes", list)) o.scenes = splitList(list);
    if (a.read("--techniques", list))
    {
        o.techniques.clear();
        for (const std::string& t : splitList(list)) o.techniques.push_back(canonicalTechnique(t));
    }
    if (a.read("--sizes", list)) o.sizes = parseSizes(list);
    while (a.read("--technique-sizes", list))
    {
        const std::size_t eq = list.find('=');
        if (eq == std::string::npos) return error = "--technique-sizes needs TECHNIQUE=a,b,...", false;
        o.techniqueSizes[canonicalTechnique(list.substr(0, eq))] = parseSizes(list.substr(eq + 1));
    }
    a.read("--size", o.width, o.height);
    a.read("--frames", o.frames);
    a.read("--warmup", o.warmup);
    a.read("--out-dir", o.outDir);
    if (a.read("--no-plot")) o.plot = false;
    std::string lighting;
    if (a.read("--per-pixel-lighting", lighting))
    {
        if (lighting != "on" && lighting != "off") return error = "--per-pixel-lighting takes on or off", false;
        o.perPixelLighting = lighting == "on";
    }
    std::string userProgram;
    if (a.read("--user-program", userProgram))
    {
        if (userProgram != "on" && userProgram != "off") return error = "--user-program takes on or off", false;
        o.userProgram = userProgram == "on";
    }
    if (o.techniques.empty()) o.techniques = availableTechniques();
    if (o.width < 1 || o.height < 1 || o.frames < 1 || o.warmup < 0 || o.scenes.empty() || o.sizes.empty())
    {
        error = "bad --size, --frames, --warmup, --scenes or --sizes";
        return false;
    }
    return true;
}

/** Whether a technique can be run: a peer, or one of our modes that this build implements. */
bool runnable(const std::string& technique, std::string& why)
{
    if (osshar::isPeerMode(technique))
    {
        osg::ref_ptr<osgShadow::ShadowSettings> settings = new osgShadow::ShadowSettings;
        return osshar::createPeerTechnique(technique, 64, nullptr, *settings, why) != nullptr;
    }
    SilhouetteShadowTechnique::Mode m;
    if (!SilhouetteShadowTechnique::modeFromName(technique, m)) return why = "unknown technique", false;
    return true;
}

/** The reference of a scene, built once: the mask and the geometric facing of each pixel. */
struct SceneReference
{
    ossref::Mask mask, facing;
    double seconds = 0;
};

SceneReference computeReference(const osshar::PreparedScene& scene, const Options& o)
{
    const osg::Timer_t t0 = osg::Timer::instance()->tick();
    const ossref::Camera camera = osshar::referenceCamera(scene.view, o.width, o.height);
    const ossref::Light light = osshar::referenceLight(scene.lights.front());
    SceneReference r;
    {
        ossref::Tracer tracer(*scene.content);
        r.mask = tracer.render(camera, light);
    }
    {
        ossref::Tracer noCasters(*scene.content, /*castsMask*/ 0u);
        r.facing = noCasters.render(camera, light);
    }
    r.seconds = osg::Timer::instance()->delta_s(t0, osg::Timer::instance()->tick());
    return r;
}

/** Our technique's mask of the first light, through its mask view. */
ossref::Mask ourMask(osshar::Renderer& renderer, SilhouetteShadowTechnique& technique)
{
    technique.setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    technique.setDebugLight(0);
    osg::ref_ptr<osg::Image> image = renderer.renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    technique.setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
    return image ? ossref::maskFromImage(*image) : ossref::Mask{};
}

/** An application's receiver program, as the README's "Your own shaders" writes one: per-pixel
 *  diffuse of each of the scene's GL lights, times its shadow term. */
osg::ref_ptr<osg::Program> userProgram(const osshar::PreparedScene& scene)
{
    std::ostringstream fragment;
    fragment << "#version 400 compatibility\n"
                "in vec4 benchEyePosition;\n"
                "in vec3 benchNormal;\n"
                "float oss_shadowTerm(int light, vec4 eyePosition);\n"
                "void main()\n"
                "{\n"
                "    vec3 p = benchEyePosition.xyz;\n"
                "    vec3 n = normalize(benchNormal);\n"
                "    if (dot(n, -p) < 0.0) n = -n;\n"
                "    vec3 colour = 0.2 * gl_Color.rgb;\n";
    for (const osshar::LightInScene& light : scene.lights)
    {
        const int num = light.source->getLight()->getLightNum();
        fragment << "    {\n"
                    "        vec4 lp = gl_LightSource["
                 << num
                 << "].position;\n"
                    "        vec3 l = normalize(lp.w == 0.0 ? lp.xyz : lp.xyz / lp.w - p);\n"
                    "        colour += max(dot(n, l), 0.0) * oss_shadowTerm("
                 << num << ", benchEyePosition) * gl_Color.rgb;\n"
                           "    }\n";
    }
    fragment << "    gl_FragColor = vec4(colour, gl_Color.a);\n"
                "}\n";
    const char* const vertex = "#version 400 compatibility\n"
                               "out vec4 benchEyePosition;\n"
                               "out vec3 benchNormal;\n"
                               "void main()\n"
                               "{\n"
                               "    benchEyePosition = gl_ModelViewMatrix * gl_Vertex;\n"
                               "    benchNormal = gl_NormalMatrix * gl_Normal;\n"
                               "    gl_FrontColor = gl_Color;\n"
                               "    gl_Position = ftransform();\n"
                               "}\n";
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("osgsilhouette-bench receivers");
    program->addShader(new osg::Shader(osg::Shader::VERTEX, vertex));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, fragment.str()));
    return program;
}

/** Renders, times and scores one technique at one map size. */
bool measure(const std::string& sceneName, const std::string& technique, unsigned int mapSize, const Options& o,
             const SceneReference& ref, osshar::Renderer& renderer, Row& row, std::string& error)
{
    osshar::RenderOptions ro;
    ro.scene = sceneName;
    osshar::PreparedScene scene;
    osg::ref_ptr<osg::Node> root;
    osg::ref_ptr<SilhouetteShadowTechnique> ours;
    if (!osshar::prepareScene(ro, scene, error) || !osshar::makeShadowedRoot(technique, mapSize, scene, root, ours, error))
        return false;
    if (ours) ours->setPerPixelLighting(o.perPixelLighting);
    osg::ref_ptr<osg::Program> program = ours && o.userProgram ? userProgram(scene) : nullptr;
    if (program)
    {
        ours->addShadowShaders(program.get());
        scene.content->getOrCreateStateSet()->setAttributeAndModes(program.get());
    }
    renderer.setSceneData(root.get());
    renderer.setView(scene.view);
    const osshar::FrameTiming timing = renderer.timeFrames(o.warmup, o.frames);
    row = Row{sceneName, technique, usesMapSize(technique) ? mapSize : 0u, o.width, o.height, timing.frames,
              timing.cpuMsMedian, timing.gpuMsMedian, {}, -1, ""};
    ossref::Mask reference = ref.mask, mask;
    if (ours)
    {
        const SilhouetteShadowTechnique::Statistics stats = ours->getStatistics();
        if (stats.volumeOverdraw() >= 0.0)
            row.notes = "volume overdraw " + osshar::fixed(stats.volumeOverdraw(), 2) + " fragments/px";
        if (stats.screenVisibility)
            row.notes += std::string(row.notes.empty() ? "" : "; ") + "application program through screen visibility";
        if (stats.blockersTested > 0)
            row.notes += "; volumes of " + std::to_string(stats.blockersSkipped) + "/" +
                         std::to_string(stats.blockersTested) + " casters skipped (hidden from the light)";
        // The mask view is the receiver program's: an application program would draw over it.
        if (program) scene.content->getOrCreateStateSet()->removeAttribute(program.get());
        mask = ourMask(renderer, *ours);
        const SilhouetteShadowTechnique::Mode mode = ours->getEffectiveMode();
        if (mode == SilhouetteShadowTechnique::SILHOUETTE_MAP || mode == SilhouetteShadowTechnique::HYBRID)
            row.silhouettePct = osshar::countClasses(*osshar::renderClasses(renderer, *ours, 0)).silhouettePercent();
    }
    else
    {
        const osshar::PeerMask peer = osshar::renderPeerMask(renderer, root.get(), osshar::makeUnshadowedRoot(scene).get());
        long long excluded = 0;
        reference = osshar::excludeFacingDisagreement(ref.mask, ref.facing, peer.vertexFacing, excluded);
        mask = peer.mask;
        row.notes = "mask by luminance; " + std::to_string(excluded) +
                    " px excluded where vertex and face normals disagree on facing";
    }
    renderer.setSceneData(nullptr);
    row.cmp = ossref::compareMasks(mask, reference);
    if (!row.cmp.valid) return error = "cannot compare masks: " + row.cmp.error, false;
    return true;
}

std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string csvLine(const Row& r)
{
    std::ostringstream s;
    s << r.scene << ',' << r.technique << ',' << r.mapSize << ',' << r.width << ',' << r.height << ',' << r.frames
      << ',' << osshar::fixed(r.frameMs, 3) << ',' << (r.gpuMs >= 0 ? osshar::fixed(r.gpuMs, 3) : "") << ','
      << r.cmp.geometryPixels << ',' << r.cmp.wrongPixels << ',' << osshar::fixed(r.cmp.wrongPct, 4) << ','
      << r.cmp.coverageMismatch << ',' << (r.silhouettePct >= 0 ? osshar::fixed(r.silhouettePct, 3) : "") << ','
      << csvField(r.notes);
    return s.str();
}

std::string shortName(const std::string& technique)
{
    return osshar::isPeerMode(technique) ? technique.substr(std::string(osshar::PEER_PREFIX).size()) : technique;
}

/** Rows not dominated by another row of the same scene (faster and at most as wrong, or
 *  as fast and less wrong), by increasing frame time. */
std::vector<const Row*> paretoFront(const std::vector<const Row*>& rows)
{
    std::vector<const Row*> sorted = rows;
    std::sort(sorted.begin(), sorted.end(), [](const Row* a, const Row* b) {
        return a->frameMs != b->frameMs ? a->frameMs < b->frameMs : a->cmp.wrongPct < b->cmp.wrongPct;
    });
    std::vector<const Row*> front;
    for (const Row* r : sorted)
        if (front.empty() || r->cmp.wrongPct < front.back()->cmp.wrongPct) front.push_back(r);
    return front;
}

/** A technique's best point: its lowest wrong_pct (within 10% of it plus 0.002 points, for
 *  noise), and the fastest frame time among its sizes that reach it. */
const Row* bestPoint(const std::vector<const Row*>& rows)
{
    if (rows.empty()) return nullptr;
    double lowest = rows.front()->cmp.wrongPct;
    for (const Row* r : rows) lowest = std::min(lowest, r->cmp.wrongPct);
    const Row* best = nullptr;
    for (const Row* r : rows)
        if (r->cmp.wrongPct <= lowest * 1.10 + 0.002 && (!best || r->frameMs < best->frameMs)) best = r;
    return best;
}

std::vector<const Row*> rowsOf(const std::vector<Row>& rows, const std::string& scene, const std::string& technique = "")
{
    std::vector<const Row*> out;
    for (const Row& r : rows)
        if (r.scene == scene && (technique.empty() || r.technique == technique)) out.push_back(&r);
    return out;
}

std::vector<std::string> distinct(const std::vector<Row>& rows, bool scenes)
{
    std::vector<std::string> out;
    for (const Row& r : rows)
    {
        const std::string& v = scenes ? r.scene : r.technique;
        if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    }
    return out;
}

std::string mapText(const Row& r)
{
    return r.mapSize ? std::to_string(r.mapSize) : std::string("no map");
}

std::string pointText(const Row& r)
{
    return osshar::fixed(r.cmp.wrongPct, 3) + "% @ " + osshar::fixed(r.frameMs, 1) + " ms (" + mapText(r) + ")";
}

/** Per scene, each of our modes against the peers: a peer row that is at least as accurate as
 *  our mode's best point and faster, and a peer whose lowest error is below our mode's. */
void writeLosses(std::ostream& md, const std::vector<Row>& rows)
{
    int lines = 0;
    for (const std::string& scene : distinct(rows, true))
        for (const std::string& ours : distinct(rows, false))
        {
            if (osshar::isPeerMode(ours)) continue;
            const Row* b = bestPoint(rowsOf(rows, scene, ours));
            if (!b) continue;
            for (const std::string& peer : distinct(rows, false))
            {
                if (!osshar::isPeerMode(peer)) continue;
                const std::vector<const Row*> pr = rowsOf(rows, scene, peer);
                const Row* faster = nullptr;
                for (const Row* r : pr)
                    if (r->cmp.wrongPct <= b->cmp.wrongPct && r->frameMs < b->frameMs && (!faster || r->frameMs < faster->frameMs))
                        faster = r;
                const Row* pb = bestPoint(pr);
                if (faster)
                    md << "- " << scene << ": **" << ours << "** (" << pointText(*b) << ") is beaten by "
                       << shortName(peer) << " at " << pointText(*faster) << ": as accurate and "
                       << osshar::fixed(b->frameMs / faster->frameMs, 2) << "x faster.\n",
                        ++lines;
                else if (pb && pb->cmp.wrongPct * 1.10 + 0.002 < b->cmp.wrongPct)
                    md << "- " << scene << ": **" << ours << "** (" << pointText(*b) << ") never gets as accurate as "
                       << shortName(peer) << " (" << pointText(*pb) << ").\n", ++lines;
            }
        }
    if (!lines) md << "- None in this run: no peer row is at least as accurate as one of our modes' best points and faster.\n";
}

/** The headline: per scene and technique, the lowest error and the best time reaching it. */
void writeHeadline(std::ostream& md, const std::vector<Row>& rows)
{
    const std::vector<std::string> techniques = distinct(rows, false);
    md << "| scene |";
    for (const std::string& t : techniques) md << ' ' << shortName(t) << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < techniques.size(); ++i) md << "---|";
    md << "\n";
    for (const std::string& scene : distinct(rows, true))
    {
        md << "| " << scene << " |";
        for (const std::string& t : techniques)
        {
            const Row* b = bestPoint(rowsOf(rows, scene, t));
            if (!b)
                md << " - |";
            else
                md << ' ' << pointText(*b) << " |";
        }
        md << "\n";
    }
}

void writeSceneTable(std::ostream& md, const std::vector<Row>& rows, const std::string& scene)
{
    const std::vector<const Row*> sceneRows = rowsOf(rows, scene);
    const std::vector<const Row*> front = paretoFront(sceneRows);
    md << "| technique | map | frame ms | GPU ms | wrong % | wrong px | coverage mismatch | silhouette px % | Pareto |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
    for (const Row* r : sceneRows)
    {
        const bool onFront = std::find(front.begin(), front.end(), r) != front.end();
        md << "| " << r->technique << " | " << mapText(*r) << " | " << osshar::fixed(r->frameMs, 2) << " | "
           << (r->gpuMs >= 0 ? osshar::fixed(r->gpuMs, 2) : "-") << " | " << osshar::fixed(r->cmp.wrongPct, 3) << " | "
           << r->cmp.wrongPixels << " | " << r->cmp.coverageMismatch << " | "
           << (r->silhouettePct >= 0 ? osshar::fixed(r->silhouettePct, 2) : "-") << " | " << (onFront ? "yes" : "")
           << " |\n";
    }
}

void writeMarkdown(const std::string& path, const std::vector<Row>& rows, const Options& o,
                   const std::map<std::string, std::string>& sceneNotes)
{
    std::ofstream md(path);
    md << "# Frame time against error\n\n"
       << o.width << "x" << o.height << ", median of " << o.frames << " frames after " << o.warmup
       << " warm-up frames; wrong_pct against the exact Embree reference (MEASURE.md).\n\n"
       << (o.userProgram ? "Our modes draw the receivers with an application program given to addShadowShaders() "
                           "(--user-program on).\n\n"
                         : "")
       << "## Best point of each technique\n\n"
          "Lowest wrong_pct over the map sizes (within 10% of it plus 0.002 points, for noise) and the fastest "
          "frame time among the sizes that reach it, with that map size (volume uses no map).\n\n";
    writeHeadline(md, rows);
    md << "\n## Where a peer beats our modes\n\n"
          "Each of our modes' best point against every row of every peer on the same scene.\n\n";
    writeLosses(md, rows);
    for (const std::string& scene : distinct(rows, true))
    {
        md << "\n## " << scene << "\n\n";
        auto note = sceneNotes.find(scene);
        if (note != sceneNotes.end()) md << note->second << "\n\n";
        md << "![" << scene << "](" << scene << ".png)\n\n";
        writeSceneTable(md, rows, scene);
    }
}

/** A gnuplot script: one line per technique through its map sizes (log-log), the Pareto
 *  front as a thick gray staircase. */
std::string gnuplotScript(const std::vector<Row>& rows, const std::string& scene, const std::string& png)
{
    std::ostringstream gp;
    const std::vector<const Row*> sceneRows = rowsOf(rows, scene);
    const auto x = [](const Row* r) { return std::max(r->cmp.wrongPct, 1e-3); };
    gp << "set terminal pngcairo size 900,600 noenhanced font ',10'\nset output '" << png << "'\n"
       << "set title '" << scene << ": frame time against error (" << sceneRows.front()->width << "x"
       << sceneRows.front()->height << ")'\n"
       << "set logscale xy\nset xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'\n"
       << "set ylabel 'frame time, ms (median, log)'\nset grid\nset key outside right top\n";
    gp << "$front << EOD\n";
    for (const Row* r : paretoFront(sceneRows)) gp << x(r) << ' ' << r->frameMs << "\n";
    gp << "EOD\n";
    const std::vector<std::string> techniques = distinct(rows, false);
    std::vector<std::string> plots{"$front using 1:2 with steps lw 6 lc rgb '#c8c8c8' title 'Pareto front'"};
    for (std::size_t i = 0; i < techniques.size(); ++i)
    {
        std::vector<const Row*> tr = rowsOf(rows, scene, techniques[i]);
        if (tr.empty()) continue;
        gp << "$t" << i << " << EOD\n";
        for (const Row* r : tr) gp << x(r) << ' ' << r->frameMs << ' ' << (r->mapSize ? mapText(*r) : "\"\"") << "\n";
        gp << "EOD\n";
        const std::string pt = osshar::isPeerMode(techniques[i]) ? "6" : "7";
        plots.push_back("$t" + std::to_string(i) + " using 1:2 with linespoints pt " + pt + " ps 1.3 lw 2 title '" +
                        shortName(techniques[i]) + "'");
        plots.push_back("$t" + std::to_string(i) + " using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle");
    }
    gp << "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i) gp << (i ? ", \\\n     " : "") << plots[i];
    gp << "\n";
    return gp.str();
}

bool havePlotter()
{
    return std::system("gnuplot --version > /dev/null 2>&1") == 0;
}

void writePlots(const std::vector<Row>& rows, const Options& o)
{
    if (!o.plot) return;
    if (!havePlotter())
    {
        std::cerr << "osgsilhouette-bench: gnuplot not found (Debian: gnuplot-nox): no plots, CSV and markdown written\n";
        return;
    }
    for (const std::string& scene : distinct(rows, true))
    {
        const std::string gpPath = o.outDir + "/" + scene + ".gp";
        std::ofstream(gpPath) << gnuplotScript(rows, scene, o.outDir + "/" + scene + ".png");
        if (std::system(("gnuplot '" + gpPath + "'").c_str()) != 0)
            std::cerr << "osgsilhouette-bench: gnuplot failed on " << gpPath << "\n";
    }
}

std::string clock(double seconds)
{
    const int s = int(seconds + 0.5);
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%dm%02ds", s / 60, s % 60);
    return buf;
}

struct Progress
{
    int done = 0, total = 0;
    osg::Timer_t start = osg::Timer::instance()->tick();

    double elapsed() const { return osg::Timer::instance()->delta_s(start, osg::Timer::instance()->tick()); }

    void report(const Row& r)
    {
        ++done;
        const double e = elapsed();
        std::fprintf(stderr, "[%3d/%d] %-8s %-42s %5u  %8.2f ms  wrong %7.3f%%   elapsed %s, left ~%s\n", done, total,
                     r.scene.c_str(), r.technique.c_str(), r.mapSize, r.frameMs, r.cmp.wrongPct, clock(e).c_str(),
                     clock(e / done * (total - done)).c_str());
    }
};

int runsPerScene(const Options& o)
{
    int n = 0;
    for (const std::string& t : o.techniques) n += usesMapSize(t) ? int(sizesOf(o, t).size()) : 1;
    return n;
}

/** All techniques and sizes of one scene; false when the scene cannot be built. */
bool benchScene(const std::string& sceneName, const Options& o, osshar::Renderer& renderer, Progress& progress,
                std::vector<Row>& rows, std::string& note, std::ofstream& csv)
{
    osshar::RenderOptions ro;
    ro.scene = sceneName;
    osshar::PreparedScene scene;
    std::string error;
    if (!osshar::prepareScene(ro, scene, error))
    {
        std::cerr << "osgsilhouette-bench: skipping scene " << sceneName << ": " << error << "\n";
        progress.total -= runsPerScene(o);
        return false;
    }
    const SceneReference ref = computeReference(scene, o);
    const ossref::TriangleSoup soup = ossref::collectTriangles(*scene.content);
    note = std::to_string(soup.size()) + " triangles; reference (two BVHs, two masks) in " +
           osshar::fixed(ref.seconds, 2) + " s.";
    std::fprintf(stderr, "scene %s: %zu triangles, reference in %.2f s\n", sceneName.c_str(), soup.size(), ref.seconds);
    for (const std::string& technique : o.techniques)
    {
        const std::vector<unsigned int> sizes = sizesOf(o, technique);
        for (std::size_t k = 0; k < sizes.size(); ++k)
        {
            if (!usesMapSize(technique) && k > 0) break;
            Row row;
            if (!measure(sceneName, technique, sizes[k], o, ref, renderer, row, error))
            {
                std::cerr << "osgsilhouette-bench: " << sceneName << " " << technique << ": " << error << "\n";
                --progress.total;
                continue;
            }
            rows.push_back(row);
            csv << csvLine(row) << "\n" << std::flush;
            progress.report(row);
        }
    }
    return true;
}

void dropUnrunnable(Options& o)
{
    std::vector<std::string> kept;
    for (const std::string& t : o.techniques)
    {
        std::string why;
        if (runnable(t, why))
            kept.push_back(t);
        else
            std::cerr << "osgsilhouette-bench: skipping technique " << t << ": " << why << "\n";
    }
    o.techniques = kept;
}

} // namespace

int main(int argc, char** argv)
{
    osg::ArgumentParser arguments(&argc, argv);
    if (arguments.read("-h") || arguments.read("--help"))
    {
        usage(argv[0]);
        return 0;
    }
    Options o;
    std::string error;
    if (!parseOptions(arguments, o, error))
    {
        std::cerr << "osgsilhouette-bench: " << error << "\n";
        usage(argv[0]);
        return 1;
    }
    if (arguments.read("--list"))
    {
        usage(argv[0]);
        return 0;
    }
    dropUnrunnable(o);
    if (std::system(("mkdir -p '" + o.outDir + "'").c_str()) != 0) return 1;
    std::ofstream csv(o.outDir + "/benchmark.csv");
    csv << CSV_HEADER << "\n";
    std::vector<Row> rows;
    std::map<std::string, std::string> notes;
    // One viewer for the whole run, never destroyed: in OSG 3.6.5 destroying a viewer whose
    // CullVisitors an osg::Identifier observes (LiSPSM keys its data by them) can deadlock in
    // Identifier::objectDeleted. The process exit reclaims it.
    osshar::Renderer* renderer = new osshar::Renderer(o.width, o.height, true);
    if (!renderer->valid())
    {
        std::cerr << "osgsilhouette-bench: cannot create a graphics context (is DISPLAY set? try xvfb-run)\n";
        return 1;
    }
    Progress progress;
    progress.total = runsPerScene(o) * int(o.scenes.size());
    for (const std::string& scene : o.scenes) benchScene(scene, o, *renderer, progress, rows, notes[scene], csv);
    if (rows.empty())
    {
        std::cerr << "osgsilhouette-bench: nothing measured\n";
        return 1;
    }
    writeMarkdown(o.outDir + "/benchmark.md", rows, o, notes);
    writePlots(rows, o);
    std::fprintf(stderr, "done: %zu rows in %s -> %s/benchmark.csv, benchmark.md, <scene>.png\n", rows.size(),
                 clock(progress.elapsed()).c_str(), o.outDir.c_str());
    return 0;
}
