#include "Setup.h"
#include "Peers.h"

#include <osgDB/ReadFile>
#include <osgShadow/ShadowedScene>

#include <algorithm>
#include <cmath>

namespace osshar {

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;

osg::ref_ptr<osg::Group> loadContent(const RenderOptions& o, PreparedScene& scene, std::string& error)
{
    if (o.file.empty())
    {
        Scene built = createScene(o.scene);
        if (!built.root) error = "unknown scene '" + o.scene + "'";
        scene.view = built.view;
        return built.root;
    }
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(o.file);
    if (!node)
    {
        error = "cannot read '" + o.file + "'";
        return nullptr;
    }
    osg::ref_ptr<osg::Group> group = new osg::Group;
    if (osgShadow::ShadowedScene* ss = dynamic_cast<osgShadow::ShadowedScene*>(node.get()))
    {
        scene.fileTechnique = dynamic_cast<SilhouetteShadowTechnique*>(ss->getShadowTechnique());
        for (unsigned int i = 0; i < ss->getNumChildren(); ++i) group->addChild(ss->getChild(i));
    }
    else
        group->addChild(node.get());
    scene.view = defaultView(group->getBound());
    return group;
}

void applyLights(const RenderOptions& o, PreparedScene& scene)
{
    scene.lights = findLights(scene.content.get());
    for (std::size_t i = 0; i < o.lights.size(); ++i)
    {
        const LightArg& a = o.lights[i];
        const osg::Vec4 pos(a.vector.x(), a.vector.y(), a.vector.z(), a.directional ? 0.0f : 1.0f);
        if (i < scene.lights.size())
        {
            // Given in world coordinates: undo the light source's own placement.
            const osg::Matrixd toLocal = osg::Matrixd::inverse(scene.lights[i].localToWorld);
            osg::Vec4d local = osg::Vec4d(pos) * toLocal;
            scene.lights[i].source->getLight()->setPosition(osg::Vec4(local));
        }
        else
            scene.content->addChild(makeLight(pos, static_cast<int>(i)));
    }
    if (findLights(scene.content.get()).empty())
    {
        OSG_NOTICE << "The scene has no light: adding a directional light from (0.4, -0.3, 0.87)" << std::endl;
        scene.content->addChild(makeLight(osg::Vec4(0.4f, -0.3f, 0.87f, 0.0f)));
    }
    scene.lights = findLights(scene.content.get());
    std::stable_sort(scene.lights.begin(), scene.lights.end(), [](const LightInScene& a, const LightInScene& b) {
        return a.source->getLight()->getLightNum() < b.source->getLight()->getLightNum();
    });
}

} // namespace

bool prepareScene(const RenderOptions& o, PreparedScene& scene, std::string& error)
{
    scene.content = loadContent(o, scene, error);
    if (!scene.content) return false;
    applyLights(o, scene);
    if (o.eye) scene.view.eye = *o.eye;
    if (o.center) scene.view.center = *o.center;
    if (o.up) scene.view.up = *o.up;
    if (o.fovy) scene.view.fovy = *o.fovy;
    return true;
}

bool makeShadowedRoot(const std::string& mode, unsigned int mapSize, PreparedScene& scene, osg::ref_ptr<osg::Node>& root,
                      osg::ref_ptr<SilhouetteShadowTechnique>& technique, std::string& error)
{
    if (mode == "none")
    {
        root = scene.content;
        technique = nullptr;
        return true;
    }
    if (isPeerMode(mode))
    {
        technique = nullptr;
        return makePeerRoot(mode, mapSize, scene, root, error);
    }
    SilhouetteShadowTechnique::Mode m;
    if (!SilhouetteShadowTechnique::modeFromName(mode, m))
    {
        error = "unknown mode '" + mode + "'";
        return false;
    }
    technique = scene.fileTechnique ? new SilhouetteShadowTechnique(*scene.fileTechnique)
                                    : new SilhouetteShadowTechnique;
    technique->setMode(m);
    technique->setShadowMapSize(mapSize);
    osg::ref_ptr<osgShadow::ShadowedScene> ss = new osgShadow::ShadowedScene(technique.get());
    ss->addChild(scene.content.get());
    root = ss;
    return true;
}

ossref::Camera referenceCamera(const View& view, int width, int height)
{
    ossref::Camera c;
    c.eye = view.eye, c.center = view.center, c.up = view.up;
    c.fovyDeg = view.fovy;
    c.width = width, c.height = height;
    return c;
}

ossref::Light referenceLight(const LightInScene& light)
{
    return ossref::lightFromOsg(*light.source->getLight(), light.localToWorld);
}

} // namespace osshar
