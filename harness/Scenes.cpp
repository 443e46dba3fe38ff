#include "Scenes.h"
#include "Meshes.h"

#include <osg/Geode>
#include <osg/Material>
#include <osg/NodeVisitor>

#include <cmath>

namespace osshar {

namespace {

osg::ref_ptr<osg::Geode> coloured(osg::ref_ptr<osg::Geometry> g, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setColorMode(osg::Material::OFF);
    m->setAmbient(osg::Material::FRONT_AND_BACK, colour);
    m->setDiffuse(osg::Material::FRONT_AND_BACK, colour);
    m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.3f, 0.3f, 0.3f, 1.0f));
    m->setShininess(osg::Material::FRONT_AND_BACK, 32.0f);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(g.get());
    geode->getOrCreateStateSet()->setAttributeAndModes(m.get());
    return geode;
}

const osg::Vec4 GROUND(0.75f, 0.75f, 0.72f, 1.0f);

Scene defaultScene()
{
    Scene s{"default", new osg::Group, {}};
    s.root->setName("default scene");
    s.root->addChild(coloured(makeGround(0, 0, 24), GROUND));
    s.root->addChild(coloured(makeCylinder(osg::Vec3(-3.5f, 1.5f, 0), 1.0f, 4.0f, 48), osg::Vec4(0.8f, 0.3f, 0.25f, 1)));
    s.root->addChild(coloured(makeSphere(osg::Vec3(2.5f, 2.5f, 2.0f), 1.5f, 48, 24), osg::Vec4(0.3f, 0.5f, 0.85f, 1)));
    s.root->addChild(coloured(makeBox(osg::Vec3(0.5f, -2.5f, 1.0f), osg::Vec3(2, 2, 2)), osg::Vec4(0.3f, 0.75f, 0.35f, 1)));
    s.root->addChild(coloured(makeBox(osg::Vec3(4.0f, -1.5f, 0.5f), osg::Vec3(1, 3, 1)), osg::Vec4(0.85f, 0.75f, 0.3f, 1)));
    s.root->addChild(coloured(makeBox(osg::Vec3(-1.0f, 4.5f, 1.75f), osg::Vec3(0.5f, 0.5f, 3.5f)), osg::Vec4(0.6f, 0.4f, 0.8f, 1)));
    s.root->addChild(makeLight(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f)));
    s.view = {osg::Vec3d(2, -16, 10), osg::Vec3d(0, 0, 0.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene spheresScene()
{
    Scene s{"spheres", new osg::Group, {}};
    s.root->setName("curved casters");
    s.root->addChild(coloured(makeGround(0, 0, 24), GROUND));
    s.root->addChild(coloured(makeSphere(osg::Vec3(-2.5f, 0, 2.0f), 1.5f, 64, 32), osg::Vec4(0.3f, 0.5f, 0.85f, 1)));
    s.root->addChild(coloured(makeSphere(osg::Vec3(1.5f, 2.5f, 1.0f), 0.8f, 48, 24), osg::Vec4(0.8f, 0.4f, 0.3f, 1)));
    s.root->addChild(coloured(makeTorus(osg::Vec3(2.0f, -2.0f, 2.5f), 1.6f, 0.45f, 64, 24), osg::Vec4(0.4f, 0.8f, 0.4f, 1)));
    s.root->addChild(makeLight(osg::Vec4(0.3f, -0.5f, 0.81f, 0.0f)));
    s.view = {osg::Vec3d(1, -14, 9), osg::Vec3d(0, 0, 0.8), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene polesScene()
{
    Scene s{"poles", new osg::Group, {}};
    s.root->setName("thin poles");
    s.root->addChild(coloured(makeGround(0, 0, 24), GROUND));
    const osg::Vec4 wood(0.7f, 0.55f, 0.35f, 1);
    for (int i = -6; i <= 6; ++i)
        for (int j = -1; j <= 1; ++j)
            s.root->addChild(coloured(makeBox(osg::Vec3(i * 0.6f, j * 1.8f, 1.5f), osg::Vec3(0.12f, 0.12f, 3.0f)), wood));
    for (int j = -1; j <= 1; ++j)
        s.root->addChild(coloured(makeBox(osg::Vec3(0, j * 1.8f, 2.6f), osg::Vec3(8.0f, 0.08f, 0.08f)), wood));
    s.root->addChild(makeLight(osg::Vec4(0.25f, -0.6f, 0.76f, 0.0f)));
    s.view = {osg::Vec3d(3, -13, 8), osg::Vec3d(0, -1, 0.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene cubesScene()
{
    Scene s{"cubes", new osg::Group, {}};
    s.root->setName("cubes: high shadow complexity");
    s.root->addChild(coloured(makeGround(0, 0, 30), GROUND));
    // 1000 cubes (12k triangles) in a loose 10 x 10 x 10 lattice, rotated so shadows overlap.
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k)
            {
                const float jitter = 0.15f * std::sin(float(i * 7 + j * 13 + k * 3));
                const osg::Vec3 c(-4.5f + i + jitter, -4.5f + j - jitter, 1.0f + k * 0.9f + jitter);
                const osg::Vec4 col(0.4f + 0.05f * i, 0.4f + 0.05f * j, 0.4f + 0.05f * k, 1.0f);
                s.root->addChild(coloured(makeBox(c, osg::Vec3(0.45f, 0.45f, 0.45f)), col));
            }
    s.root->addChild(makeLight(osg::Vec4(0.35f, -0.25f, 0.9f, 0.0f)));
    s.view = {osg::Vec3d(6, -20, 14), osg::Vec3d(0, 0, 3), osg::Vec3d(0, 0, 1), 45.0};
    return s;
}

class FindLightsVisitor : public osg::NodeVisitor
{
public:
    FindLightsVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LightSource& ls) override
    {
        if (ls.getLight())
        {
            osg::Matrixd m = ls.getReferenceFrame() == osg::LightSource::RELATIVE_RF
                                 ? osg::computeLocalToWorld(getNodePath())
                                 : osg::Matrixd();
            found.push_back({&ls, m});
        }
        traverse(ls);
    }
    std::vector<LightInScene> found;
};

} // namespace

std::vector<std::string> sceneNames()
{
    return {"default", "spheres", "poles", "cubes"};
}

Scene createScene(const std::string& name)
{
    if (name == "default") return defaultScene();
    if (name == "spheres") return spheresScene();
    if (name == "poles") return polesScene();
    if (name == "cubes") return cubesScene();
    return Scene{name, nullptr, {}};
}

osg::ref_ptr<osg::LightSource> makeLight(const osg::Vec4& position, int lightNum)
{
    osg::ref_ptr<osg::Light> light = new osg::Light(lightNum);
    light->setPosition(position);
    light->setAmbient(osg::Vec4(0.2f, 0.2f, 0.2f, 1.0f));
    light->setDiffuse(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    light->setSpecular(osg::Vec4(0.3f, 0.3f, 0.3f, 1.0f));
    osg::ref_ptr<osg::LightSource> ls = new osg::LightSource;
    ls->setName("light " + std::to_string(lightNum));
    ls->setLight(light.get());
    return ls;
}

std::vector<LightInScene> findLights(osg::Node* root)
{
    FindLightsVisitor v;
    if (root) root->accept(v);
    return v.found;
}

View defaultView(const osg::BoundingSphere& bound)
{
    const double r = bound.valid() ? bound.radius() : 1.0;
    const osg::Vec3d c = bound.valid() ? osg::Vec3d(bound.center()) : osg::Vec3d();
    return {c + osg::Vec3d(0.0, -2.2 * r, 1.3 * r), c, osg::Vec3d(0, 0, 1), 40.0};
}

} // namespace osshar
