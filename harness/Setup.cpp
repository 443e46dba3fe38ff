#include "Setup.h"
#include "Peers.h"

#include <osg/Texture>
#include <osgDB/FileNameUtils>
#include <osgDB/ReadFile>
#include <osgShadow/ShadowedScene>

#include <algorithm>
#include <cmath>

namespace osshar {

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;

/** Keeps every texture's image after OpenGL has it (a file may ask for UnRefImageDataAfterApply,
 *  as OpenSceneGraph's lz.osgt does): the exact reference samples the images of alpha-tested
 *  casters on the CPU, after the frames are drawn. */
class KeepTextureImagesVisitor : public osg::NodeVisitor
{
public:
    KeepTextureImagesVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Node& node) override
    {
        keep(node.getStateSet());
        traverse(node);
    }
    void apply(osg::Drawable& drawable) override { keep(drawable.getStateSet()); }

private:
    static void keep(osg::StateSet* ss)
    {
        if (!ss) return;
        for (unsigned int unit = 0; unit < ss->getTextureAttributeList().size(); ++unit)
            if (auto* texture = dynamic_cast<osg::Texture*>(ss->getTextureAttribute(unit, osg::StateAttribute::TEXTURE)))
                texture->setUnRefImageDataAfterApply(false);
    }
};

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
    KeepTextureImagesVisitor keepImages;
    node->accept(keepImages);
    osg::ref_ptr<osg::Group> group = new osg::Group;
    if (osgShadow::ShadowedScene* ss = dynamic_cast<osgShadow::ShadowedScene*>(node.get()))
    {
        scene.fileTechnique = dynamic_cast<SilhouetteShadowTechnique*>(ss->getShadowTechnique());
        scene.castsMask = ss->getCastsShadowTraversalMask();
        scene.receivesMask = ss->getReceivesShadowTraversalMask();
        for (unsigned int i = 0; i < ss->getNumChildren(); ++i) group->addChild(ss->getChild(i));
    }
    else
        group->addChild(node.get());
    if (o.ground)
    {
        Scene placed = placeOnGround(group.get(), osgDB::getSimpleFileName(o.file));
        scene.view = placed.view;
        return placed.root;
    }
    scene.view = defaultView(group->getBound());
    return group;
}

/** Sets light's position and spot cone from a, given in world coordinates, for a light
 *  source placed by localToWorld. */
void placeLight(osg::Light& light, const LightArg& a, const osg::Matrixd& localToWorld)
{
    const osg::Matrixd toLocal = osg::Matrixd::inverse(localToWorld);
    const osg::Vec4d pos(a.vector, a.directional ? 0.0 : 1.0);
    light.setPosition(osg::Vec4(pos * toLocal));
    light.setSpotCutoff(a.spot() ? float(a.spotCutoff) : 180.0f);
    if (a.spot())
    {
        osg::Vec3d axis = osg::Matrixd::transform3x3(a.spotDirection, toLocal);
        axis.normalize();
        light.setDirection(osg::Vec3(axis));
    }
}

/** A GL light number above those of every light of the scene: a loaded model's lights may
 *  hold any numbers (the AC plugin's first light is GL_LIGHT1), and two lights of one number
 *  are one light to OpenGL. */
int freeLightNum(osg::Node* content)
{
    int num = 0;
    for (const LightInScene& l : findLights(content))
        num = std::max(num, l.source->getLight()->getLightNum() + 1);
    return num;
}

void applyLights(const RenderOptions& o, PreparedScene& scene)
{
    scene.lights = findLights(scene.content.get());
    for (std::size_t i = 0; i < o.lights.size(); ++i)
    {
        if (i < scene.lights.size())
            placeLight(*scene.lights[i].source->getLight(), o.lights[i], scene.lights[i].localToWorld);
        else
        {
            osg::ref_ptr<osg::LightSource> source =
                makeLight(osg::Vec4(0, 0, 1, 0), freeLightNum(scene.content.get()));
            placeLight(*source->getLight(), o.lights[i], osg::Matrixd::identity());
            scene.content->addChild(source.get());
        }
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
    ss->setCastsShadowTraversalMask(scene.castsMask);
    ss->setReceivesShadowTraversalMask(scene.receivesMask);
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
