// An application of the installed package: the lines between "application code" mark all it
// takes to shadow a model. The rest checks the result for the test suite:
//   consumer --save <file.osgt>   writes the scene and reads it back through the installed
//                                 serializer plugin
//   consumer --render             renders a few frames and prints the technique's statistics
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/LightSource>
#include <osg/ShapeDrawable>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgShadow/ShadowedScene>
#include <osgViewer/Viewer>

#include <cstring>
#include <iostream>

using osgShadowSilhouette::SilhouetteShadowTechnique;

/** The model: a ground, a box floating above it and a directional light. */
static osg::ref_ptr<osg::Node> makeModel()
{
    osg::ref_ptr<osg::Group> model = new osg::Group;
    model->addChild(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0, 0, -0.05f), 10, 10, 0.1f)));
    model->addChild(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0, 0, 1.5f), 1.5f)));
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(0.3f, -0.4f, 0.87f, 0.0f));
    model->addChild(light);
    return model;
}

static int checkSaved(osg::Node& scene, const char* file)
{
    if (!osgDB::writeNodeFile(scene, file)) return 1;
    osg::ref_ptr<osgShadow::ShadowedScene> read = dynamic_cast<osgShadow::ShadowedScene*>(osgDB::readRefNodeFile(file).get());
    const bool ok = read && dynamic_cast<SilhouetteShadowTechnique*>(read->getShadowTechnique());
    std::cout << (ok ? "saved and read back with the technique" : "technique lost") << std::endl;
    return ok ? 0 : 1;
}

static int checkRendered(osgViewer::Viewer& viewer, osgShadow::ShadowedScene& scene)
{
    osg::DisplaySettings::instance()->setMinimumNumStencilBits(8);
    viewer.setUpViewInWindow(0, 0, 320, 240);
    viewer.realize();
    for (int i = 0; i < 5 && !viewer.done(); ++i) viewer.frame();
    const SilhouetteShadowTechnique* t = static_cast<SilhouetteShadowTechnique*>(scene.getShadowTechnique());
    const SilhouetteShadowTechnique::Statistics s = t->getStatistics();
    std::cout << "lightsShadowed=" << s.lightsShadowed << " shadowPasses=" << s.shadowPasses << std::endl;
    return s.shadowPasses > 0 ? 0 : 1;
}

int main(int argc, char** argv)
{
    if (argc < 2) return 2;
    osg::ref_ptr<osg::Node> model = makeModel();
    // --- application code ---
    osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene(new SilhouetteShadowTechnique);
    scene->addChild(model);
    osgViewer::Viewer viewer;
    viewer.setSceneData(scene);
    // --- end of application code ---
    if (scene->getNumChildren() != 1) return 1;
    if (std::strcmp(argv[1], "--save") == 0 && argc > 2) return checkSaved(*scene, argv[2]);
    if (std::strcmp(argv[1], "--render") == 0) return checkRendered(viewer, *scene);
    return 2;
}
