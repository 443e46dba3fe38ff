#include "Scenes.h"
#include "AnimatedScenes.h"
#include "Meshes.h"

#include <osg/AlphaFunc>
#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/Material>
#include <osg/NodeVisitor>
#include <osg/Texture2D>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgUtil/SmoothingVisitor>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace osshar {

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

const osg::Vec4& groundColour()
{
    static const osg::Vec4 colour(0.75f, 0.75f, 0.72f, 1.0f);
    return colour;
}

namespace {

const osg::Vec4 GROUND = groundColour();

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

/** Appends `part`, transformed by m (rotation, translation, uniform scale), to `mesh`. */
void appendTransformed(osg::Geometry& mesh, const osg::Geometry& part, const osg::Matrixd& m)
{
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(mesh.getVertexArray());
    osg::Vec3Array* n = static_cast<osg::Vec3Array*>(mesh.getNormalArray());
    osg::DrawElementsUInt* idx = static_cast<osg::DrawElementsUInt*>(mesh.getPrimitiveSet(0));
    const osg::Vec3Array* pv = static_cast<const osg::Vec3Array*>(part.getVertexArray());
    const osg::Vec3Array* pn = static_cast<const osg::Vec3Array*>(part.getNormalArray());
    const unsigned int base = static_cast<unsigned int>(v->size());
    for (std::size_t i = 0; i < pv->size(); ++i)
    {
        v->push_back(osg::Vec3((*pv)[i] * m));
        osg::Vec3 nn = osg::Matrixd::transform3x3((*pn)[i], m);
        nn.normalize();
        n->push_back(nn);
    }
    for (unsigned int j = 0; j < part.getNumPrimitiveSets(); ++j)
        if (const osg::DrawElementsUInt* pi = dynamic_cast<const osg::DrawElementsUInt*>(part.getPrimitiveSet(j)))
            for (unsigned int k : *pi) idx->push_back(base + k);
}

osg::ref_ptr<osg::Geometry> emptyMesh(const char* name)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setName(name);
    g->setVertexArray(new osg::Vec3Array);
    g->setNormalArray(new osg::Vec3Array, osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES));
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    return g;
}

/** A branch of radius r and length len along +z of frame m, and its three sub-branches. */
void addBranch(osg::Geometry& mesh, const osg::Matrixd& m, float r, float len, int depth)
{
    appendTransformed(mesh, *makeCylinder(osg::Vec3(), r, len, 12), m);
    if (depth == 0) return;
    for (int i = 0; i < 3; ++i)
    {
        const double yaw = osg::DegreesToRadians(120.0 * i + 40.0 * depth);
        const osg::Matrixd child = osg::Matrixd::rotate(osg::DegreesToRadians(35.0), osg::Vec3d(1, 0, 0)) *
                                   osg::Matrixd::rotate(yaw, osg::Vec3d(0, 0, 1)) *
                                   osg::Matrixd::translate(0, 0, len * 0.97) * m;
        addBranch(mesh, child, r * 0.62f, len * 0.72f, depth - 1);
    }
}

Scene treeScene()
{
    Scene s{"tree", new osg::Group, {}};
    s.root->setName("tree: thin branches");
    s.root->addChild(coloured(makeGround(0, 0, 24), GROUND));
    // 364 branches (17k triangles), radius 0.14 at the trunk down to 0.013 at the twigs.
    osg::ref_ptr<osg::Geometry> tree = emptyMesh("tree");
    addBranch(*tree, osg::Matrixd::identity(), 0.14f, 2.5f, 5);
    s.root->addChild(coloured(tree, osg::Vec4(0.55f, 0.4f, 0.25f, 1)));
    s.root->addChild(makeLight(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f)));
    s.view = {osg::Vec3d(2, -13, 7), osg::Vec3d(-0.5, 0.5, 2.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

const char* const BUNNY_FILE = "/usr/share/glmark2/models/bunny.obj";

/** A scene of one model on a 16 x 16 ground plane: the model turned by `orientation`, then
 *  -30 degrees about z, scaled to 3.5 units high and standing on z = 0 at the origin, with
 *  the default scene's light. */
Scene modelOnGround(const char* name, const std::string& description, osg::Node* model,
                    const osg::Matrixd& orientation)
{
    osg::ref_ptr<osg::MatrixTransform> fitted = new osg::MatrixTransform;
    fitted->addChild(model);
    fitted->setMatrix(orientation * osg::Matrixd::rotate(osg::DegreesToRadians(-30.0), osg::Vec3d(0, 0, 1)));
    osg::ComputeBoundsVisitor turned;
    fitted->accept(turned);
    const osg::BoundingBox bb = turned.getBoundingBox();
    const double scale = 3.5 / (bb.zMax() - bb.zMin());
    fitted->postMult(osg::Matrixd::translate(-bb.center().x(), -bb.center().y(), -bb.zMin()) *
                     osg::Matrixd::scale(scale, scale, scale));
    Scene s{name, new osg::Group, {}};
    s.root->setName(description);
    s.root->addChild(coloured(makeGround(0, 0, 16), GROUND));
    s.root->addChild(fitted.get());
    s.root->addChild(makeLight(osg::Vec4(0.45f, -0.35f, 0.82f, 0.0f)));
    s.view = {osg::Vec3d(1.5, -10, 5.5), osg::Vec3d(0, 0.5, 1.2), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene bunnyScene()
{
    if (!osgDB::fileExists(BUNNY_FILE))
    {
        std::cerr << "scene 'bunny' needs " << BUNNY_FILE << " (Debian package glmark2-data)" << std::endl;
        return Scene{"bunny", nullptr, {}};
    }
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(BUNNY_FILE);
    if (!model)
    {
        std::cerr << "scene 'bunny': cannot read " << BUNNY_FILE << " (osgDB's obj plugin)" << std::endl;
        return Scene{"bunny", nullptr, {}};
    }
    osgUtil::SmoothingVisitor smooth; // the file has no normals
    model->accept(smooth);
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setColorMode(osg::Material::OFF);
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.85f, 0.8f, 0.7f, 1));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0.85f, 0.8f, 0.7f, 1));
    m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.3f, 0.3f, 0.3f, 1.0f));
    m->setShininess(osg::Material::FRONT_AND_BACK, 32.0f);
    model->getOrCreateStateSet()->setAttributeAndModes(m.get());
    // osgDB's obj plugin already turns the y-up file z-up.
    return modelOnGround("bunny", "bunny: scanned mesh on a ground plane", model.get(), osg::Matrixd::identity());
}

#ifndef OSS_ELEPHANT_OFF
#define OSS_ELEPHANT_OFF ""
#endif

/** libcgal-demo's elephant.off: extracted at configure time into the build tree, or found
 *  through the environment variable OSS_ELEPHANT_OFF. */
std::string elephantFile()
{
    const char* env = std::getenv("OSS_ELEPHANT_OFF");
    return env && *env ? env : OSS_ELEPHANT_OFF;
}

Scene elephantScene()
{
    std::string error;
    const std::string file = elephantFile();
    osg::ref_ptr<osg::Geometry> raw = file.empty() ? nullptr : readOff(file, error);
    if (!raw)
    {
        std::cerr << "scene 'elephant' needs elephant.off from the Debian package libcgal-demo "
                  << "(data/meshes/ in /usr/share/doc/libcgal-dev/data.tar.gz; set OSS_ELEPHANT_OFF to its path)"
                  << (error.empty() ? "" : ": " + error) << std::endl;
        return Scene{"elephant", nullptr, {}};
    }
    // 5558 triangles, split three times: 355,712 (the seed measured a 345,944-triangle mesh).
    osg::ref_ptr<osg::Geode> model = coloured(subdivideMidpoint(*raw, 3), osg::Vec4(0.7f, 0.68f, 0.65f, 1));
    // The file is y-up (the elephant raises its trunk toward +y).
    return modelOnGround("elephant", "elephant: libcgal-demo's elephant subdivided to 355,712 triangles, on a ground plane",
                         model.get(), osg::Matrixd::rotate(osg::Vec3d(0, 1, 0), osg::Vec3d(0, 0, 1)));
}

/** The default scene's light source (its last child). */
osg::Light* lightOf(Scene& s)
{
    return static_cast<osg::LightSource*>(s.root->getChild(s.root->getNumChildren() - 1))->getLight();
}

/** A direction toward the light at azimuth (0.79, -0.61) (the default scene's) and `elevationDeg`. */
osg::Vec4 defaultAzimuthLight(double elevationDeg)
{
    const double e = osg::DegreesToRadians(elevationDeg);
    osg::Vec3d h(0.45, -0.35, 0.0);
    h.normalize();
    return osg::Vec4(float(h.x() * std::cos(e)), float(h.y() * std::cos(e)), float(std::sin(e)), 0.0f);
}

Scene duelingScene()
{
    // "Dueling frusta": the camera looks toward the light (30 degrees up, from the default
    // scene's azimuth), so light and view frusta face each other.
    Scene s = defaultScene();
    s.name = "dueling";
    s.root->setName("default scene, camera facing the light");
    lightOf(s)->setPosition(defaultAzimuthLight(30.0));
    s.view = {osg::Vec3d(-12.5, 10.0, 6.5), osg::Vec3d(0.5, -0.5, 0.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene grazingScene()
{
    // The light 1.5 degrees above the ground: the ground itself is in the grazing band, the
    // long shadows fall on the objects and on a wall at x = -8 facing the light.
    Scene s = defaultScene();
    s.name = "grazing";
    s.root->setName("default scene, light 1.5 degrees above the ground");
    s.root->insertChild(1, coloured(makeBox(osg::Vec3(-8.0f, 2.0f, 2.0f), osg::Vec3(0.3f, 14.0f, 4.0f)),
                                    osg::Vec4(0.7f, 0.7f, 0.75f, 1)));
    lightOf(s)->setPosition(defaultAzimuthLight(1.5));
    s.view = {osg::Vec3d(3, -16, 10), osg::Vec3d(-2, 1, 0.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

Scene ringScene()
{
    // A point light amid its casters: eight pillars on a circle around it and a low wall
    // piece inside, so shadows fall in every direction; one perspective map cannot hold them.
    Scene s{"ring", new osg::Group, {}};
    s.root->setName("ring: a point light inside a ring of pillars");
    s.root->addChild(coloured(makeGround(0, 0, 20), GROUND));
    for (int i = 0; i < 8; ++i)
    {
        const double a = osg::DegreesToRadians(45.0 * i + 10.0);
        const osg::Vec3 c(float(3.2 * std::cos(a)), float(3.2 * std::sin(a)), 1.25f);
        s.root->addChild(coloured(makeBox(c, osg::Vec3(0.6f, 0.6f, 2.5f)), osg::Vec4(0.75f, 0.45f, 0.3f, 1)));
    }
    s.root->addChild(coloured(makeBox(osg::Vec3(-1.2f, 0.8f, 0.3f), osg::Vec3(1.2f, 0.3f, 0.6f)), osg::Vec4(0.3f, 0.6f, 0.8f, 1)));
    s.root->addChild(coloured(makeSphere(osg::Vec3(0.9f, -0.9f, 0.4f), 0.4f, 32, 16), osg::Vec4(0.4f, 0.75f, 0.35f, 1)));
    s.root->addChild(makeLight(osg::Vec4(0.0f, 0.0f, 1.6f, 1.0f)));
    s.view = {osg::Vec3d(4, -12, 11), osg::Vec3d(0, 0, 0.5), osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

/** An RGBA texture of `size` x `size` texels whose alpha is 255 where `opaque(s, t)` holds at
 *  the texel's centre (s, t in [0, 1]) and 0 elsewhere; linear filtering on level 0 only
 *  (no mipmaps: every view then samples the same alpha, as the reference does). */
template <class F>
osg::ref_ptr<osg::Texture2D> cutoutTexture(int size, const osg::Vec3& rgb, F opaque)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(size, size, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int t = 0; t < size; ++t)
        for (int s = 0; s < size; ++s)
        {
            unsigned char* p = image->data(s, t);
            const bool on = opaque((s + 0.5) / size, (t + 0.5) / size);
            p[0] = static_cast<unsigned char>(255 * rgb.x());
            p[1] = static_cast<unsigned char>(255 * rgb.y());
            p[2] = static_cast<unsigned char>(255 * rgb.z());
            p[3] = on ? 255 : 0;
        }
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    return texture;
}

/** A vertical card from `a` to `b` (bottom edge), `height` tall, texture coordinates 0..1. */
osg::ref_ptr<osg::Geometry> makeCard(const osg::Vec3& a, const osg::Vec3& b, float height)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    const osg::Vec3 up(0, 0, height);
    v->push_back(a);
    v->push_back(b);
    v->push_back(b + up);
    v->push_back(a + up);
    osg::Vec3 n = (b - a) ^ up;
    n.normalize();
    osg::ref_ptr<osg::Vec3Array> normals = new osg::Vec3Array(1, &n);
    osg::ref_ptr<osg::Vec2Array> tc = new osg::Vec2Array;
    tc->push_back(osg::Vec2(0, 0));
    tc->push_back(osg::Vec2(1, 0));
    tc->push_back(osg::Vec2(1, 1));
    tc->push_back(osg::Vec2(0, 1));
    g->setVertexArray(v.get());
    g->setNormalArray(normals.get(), osg::Array::BIND_OVERALL);
    g->setTexCoordArray(0, tc.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    return g;
}

/** Alpha-tested casters: a fence panel with diamond holes and crossed cards of leaves, each a
 *  quad whose shape is cut out of it by its texture's alpha and an osg::AlphaFunc
 *  (GREATER 0.5), over a ground. */
Scene foliageScene()
{
    Scene s{"foliage", new osg::Group, {}};
    s.root->setName("foliage: alpha-tested fence and leaf cards");
    s.root->addChild(coloured(makeGround(0, 0, 20), GROUND));
    osg::ref_ptr<osg::Group> cutouts = new osg::Group;
    cutouts->setName("alpha-tested casters");
    osg::StateSet* ss = cutouts->getOrCreateStateSet();
    ss->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    s.root->addChild(cutouts.get());

    // The fence: bars along the diagonals of a 6 x 3 lattice (holes are diamonds).
    osg::ref_ptr<osg::Geode> fence = coloured(makeCard(osg::Vec3(-4.5f, 1.5f, 0), osg::Vec3(1.5f, 1.5f, 0), 3.0f),
                                              osg::Vec4(0.8f, 0.8f, 0.8f, 1));
    fence->getDrawable(0)->setName("fence");
    fence->getOrCreateStateSet()->setTextureAttributeAndModes(
        0, cutoutTexture(128, osg::Vec3(0.55f, 0.4f, 0.25f), [](double u, double v) {
            const double a = std::fabs(std::fmod(6.0 * u + 3.0 * v, 1.0) - 0.5);
            const double b = std::fabs(std::fmod(6.0 * u - 3.0 * v + 3.0, 1.0) - 0.5);
            return a > 0.38 || b > 0.38 || v < 0.04 || v > 0.96;
        }));
    cutouts->addChild(fence.get());

    // Two crossed cards of round leaves on a stem.
    osg::ref_ptr<osg::Texture2D> leaves = cutoutTexture(128, osg::Vec3(0.3f, 0.6f, 0.25f), [](double u, double v) {
        if (std::fabs(u - 0.5) < 0.02) return true; // the stem
        for (int i = 0; i < 7; ++i)
        {
            const double cu = 0.5 + (i % 2 ? 0.22 : -0.22) * (1.0 - 0.1 * i), cv = 0.15 + 0.12 * i;
            const double r = 0.13 - 0.01 * i;
            if ((u - cu) * (u - cu) + (v - cv) * (v - cv) < r * r) return true;
        }
        return false;
    });
    for (int k = 0; k < 2; ++k)
    {
        const double a = osg::DegreesToRadians(30.0 + 90.0 * k);
        const osg::Vec3 d(float(1.5 * std::cos(a)), float(1.5 * std::sin(a)), 0);
        const osg::Vec3 c(3.0f, -1.0f, 0);
        osg::ref_ptr<osg::Geode> card = coloured(makeCard(c - d, c + d, 3.5f), osg::Vec4(0.8f, 0.8f, 0.8f, 1));
        card->getDrawable(0)->setName(k == 0 ? "leaves 1" : "leaves 2");
        card->getOrCreateStateSet()->setTextureAttributeAndModes(0, leaves.get());
        cutouts->addChild(card.get());
    }
    ss->setMode(GL_ALPHA_TEST, osg::StateAttribute::ON);

    // An opaque box for comparison.
    s.root->addChild(coloured(makeBox(osg::Vec3(-2.0f, -3.0f, 0.75f), osg::Vec3(1.5f, 1.5f, 1.5f)),
                              osg::Vec4(0.3f, 0.5f, 0.85f, 1)));
    s.root->addChild(makeLight(osg::Vec4(0.3f, -0.55f, 0.78f, 0.0f)));
    s.view = {osg::Vec3d(1, -15, 9), osg::Vec3d(0, -0.5, 1.0), osg::Vec3d(0, 0, 1), 40.0};
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
    return {"default", "spheres",  "poles", "cubes",   "tree",     "bunny",  "dueling",
            "grazing", "elephant", "ring",  "foliage", "animated", "outdoor"};
}

Scene createScene(const std::string& name)
{
    if (name == "default") return defaultScene();
    if (name == "spheres") return spheresScene();
    if (name == "poles") return polesScene();
    if (name == "cubes") return cubesScene();
    if (name == "tree") return treeScene();
    if (name == "bunny") return bunnyScene();
    if (name == "dueling") return duelingScene();
    if (name == "grazing") return grazingScene();
    if (name == "elephant") return elephantScene();
    if (name == "ring") return ringScene();
    if (name == "foliage") return foliageScene();
    if (name == "animated") return animatedScene();
    if (name == "outdoor") return outdoorScene();
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

Scene placeOnGround(osg::Node* model, const std::string& name)
{
    osg::ref_ptr<osg::MatrixTransform> fitted = new osg::MatrixTransform;
    fitted->addChild(model);
    fitted->setMatrix(osg::Matrixd::rotate(osg::DegreesToRadians(-30.0), osg::Vec3d(0, 0, 1)));
    osg::ComputeBoundsVisitor turned;
    fitted->accept(turned);
    const osg::BoundingBox bb = turned.getBoundingBox();
    const double side = bb.valid() ? std::max({bb.xMax() - bb.xMin(), bb.yMax() - bb.yMin(), bb.zMax() - bb.zMin()}) : 0.0;
    const double scale = side > 0.0 && std::isfinite(side) ? 6.0 / side : 1.0;
    if (bb.valid())
        fitted->postMult(osg::Matrixd::translate(-bb.center().x(), -bb.center().y(), -bb.zMin()) *
                         osg::Matrixd::scale(scale, scale, scale));
    fitted->getOrCreateStateSet()->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
    const double height = bb.valid() ? (bb.zMax() - bb.zMin()) * scale : 1.0;
    Scene s{name, new osg::Group, {}};
    s.root->setName(name + " on a ground");
    s.root->addChild(coloured(makeGround(0, 0, 16), GROUND));
    s.root->addChild(fitted.get());
    const osg::Vec3d center(0.0, 0.0, 0.4 * height);
    s.view = {center + osg::Vec3d(1.0, -6.5, 2.5 + 0.6 * height), center, osg::Vec3d(0, 0, 1), 40.0};
    return s;
}

View defaultView(const osg::BoundingSphere& bound)
{
    const double r = bound.valid() ? bound.radius() : 1.0;
    const osg::Vec3d c = bound.valid() ? osg::Vec3d(bound.center()) : osg::Vec3d();
    return {c + osg::Vec3d(0.0, -2.2 * r, 1.3 * r), c, osg::Vec3d(0, 0, 1), 40.0};
}

} // namespace osshar
