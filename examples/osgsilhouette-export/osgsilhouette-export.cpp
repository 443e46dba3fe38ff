// Writes built-in scenes (harness/Scenes.h) as scene files: an osgShadow::ShadowedScene with
// a SilhouetteShadowTechnique (default properties) around the scene and its light sources.
// This is how data/*.osgt are made:
//
//   OSG_LIBRARY_PATH=build/lib build/bin/osgsilhouette-export data            (every scene)
//   OSG_LIBRARY_PATH=build/lib build/bin/osgsilhouette-export data poles cubes
//
// --walk FILE writes the walk through the "outdoor" scene as a camera path instead
// (osg::AnimationPath's text format, as osgviewer records it): data/outdoor-walk.path is
//
//   build/bin/osgsilhouette-export --walk data/outdoor-walk.path
//
// The file format follows the extension given with --ext (default osgt). Text files are
// written with one space of indentation per level instead of OSG's two and no trailing
// spaces (a third smaller; OSG reads them the same): the 1000 boxes of "cubes" stay under 3 MB.
#include "Scenes.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/ArgumentParser>
#include <osg/MatrixTransform>
#include <osgDB/FileUtils>
#include <osgDB/WriteFile>
#include <osgShadow/ShadowedScene>

#include <fstream>
#include <iostream>
#include <sstream>

namespace {

/** The scene turned so that osgviewer's home view (from -y, level, z up) sees it as the
 *  scene's own view does: a plain viewer then opens with the shadows in sight, not edge-on
 *  to the ground. A rigid transform: sizes, the light's placement and the shading stay. */
osg::ref_ptr<osg::MatrixTransform> homeViewTransform(const osshar::View& view, osg::Node* scene)
{
    // lookAt takes the view to eye space (looking along -z, y up); the quarter turn about x
    // takes -z to +y and y to +z.
    osg::ref_ptr<osg::MatrixTransform> turned = new osg::MatrixTransform(
        osg::Matrixd::lookAt(view.eye, view.center, view.up) * osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS));
    turned->setName("turned toward osgviewer's home view");
    turned->addChild(scene);
    return turned;
}

osg::ref_ptr<osg::Node> shadowedScene(const osshar::Scene& scene)
{
    osg::ref_ptr<osgShadow::ShadowedScene> root =
        new osgShadow::ShadowedScene(new osgShadowSilhouette::SilhouetteShadowTechnique);
    root->setName(scene.name);
    root->addChild(homeViewTransform(scene.view, scene.root.get()).get());
    return root;
}

/** Halves the leading spaces of each line and drops trailing spaces. */
std::string compactIndentation(std::istream& in)
{
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line))
    {
        const std::string::size_type first = line.find_first_not_of(' ');
        const std::string::size_type last = line.find_last_not_of(' ');
        if (first == std::string::npos) out << '\n';
        else out << std::string(first / 2, ' ') << line.substr(first, last - first + 1) << '\n';
    }
    return out.str();
}

bool compactTextFile(const std::string& file)
{
    std::ifstream in(file);
    const std::string text = compactIndentation(in);
    in.close();
    std::ofstream out(file, std::ios::trunc);
    out << text;
    return bool(out);
}

bool exportScene(const std::string& name, const std::string& dir, const std::string& ext)
{
    const osshar::Scene scene = osshar::createScene(name);
    if (!scene.root)
    {
        std::cerr << "osgsilhouette-export: unknown scene '" << name << "'" << std::endl;
        return false;
    }
    const std::string file = dir + "/" + name + "." + ext;
    if (!osgDB::writeNodeFile(*shadowedScene(scene), file))
    {
        std::cerr << "osgsilhouette-export: cannot write " << file << std::endl;
        return false;
    }
    if (ext == "osgt" && !compactTextFile(file))
    {
        std::cerr << "osgsilhouette-export: cannot rewrite " << file << std::endl;
        return false;
    }
    std::cout << file << std::endl;
    return true;
}

/** The outdoor walk (osshar::outdoorWalk) of 150 frames at 30 per second, written to `file`. */
int writeWalk(const std::string& file)
{
    std::ofstream out(file);
    out.precision(9);
    osshar::outdoorWalk(150, 1.0 / 30.0)->write(out);
    if (out) return 0;
    std::cerr << "osgsilhouette-export: cannot write " << file << std::endl;
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    osg::ArgumentParser args(&argc, argv);
    args.getApplicationUsage()->setCommandLineUsage(args.getApplicationName() +
                                                    " [--ext osgt] <directory> [scene...] | --walk FILE");
    std::string ext = "osgt", walk;
    args.read("--ext", ext);
    if (args.read("--walk", walk)) return writeWalk(walk);
    if (argc < 2 || args.read("--help") || args.read("-h"))
    {
        args.getApplicationUsage()->write(std::cout);
        return argc < 2 ? 1 : 0;
    }
    const std::string dir = argv[1];
    std::vector<std::string> names(argv + 2, argv + argc);
    if (names.empty()) names = osshar::sceneNames();
    if (!osgDB::makeDirectory(dir)) return 1;
    bool ok = true;
    for (const std::string& name : names) ok = exportScene(name, dir, ext) && ok;
    return ok ? 0 : 1;
}
