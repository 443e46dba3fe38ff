// Scenes, cameras and lights that the tests of the exact reference share (test_reference.cpp,
// test_soft_reference.cpp).
//
// topCamera(): eye (0, 0, 1000) looking straight down, up +y, 300 x 300 pixels,
// tan(fovy/2) = 0.015. At z = 0 the image spans [-15, 15]^2, one pixel is 0.1 x 0.1, pixel
// (i, j) (GL window coordinates) sees the ground point (-15 + 0.1 (i + 0.5),
// -15 + 0.1 (j + 0.5)).
#ifndef OSS_TEST_REFERENCE_SCENES_H
#define OSS_TEST_REFERENCE_SCENES_H

#include "reference/Reference.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/Shape>
#include <osg/ShapeDrawable>

#include <cmath>

namespace reftest {

using ossref::Camera;
using ossref::Light;

constexpr int kSize = 300;

inline Camera topCamera()
{
    Camera c;
    c.eye = osg::Vec3d(0.0, 0.0, 1000.0);
    c.center = osg::Vec3d(0.0, 0.0, 0.0);
    c.up = osg::Vec3d(0.0, 1.0, 0.0);
    c.fovyDeg = osg::RadiansToDegrees(2.0 * std::atan(0.015));
    c.width = kSize;
    c.height = kSize;
    return c;
}

inline osg::ref_ptr<osg::Geometry> quad(double x0, double x1, double y0, double y1, double z)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(x0, y0, z));
    v->push_back(osg::Vec3(x1, y0, z));
    v->push_back(osg::Vec3(x1, y1, z));
    v->push_back(osg::Vec3(x0, y1, z));
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    return g;
}

inline osg::ref_ptr<osg::Geode> geode(osg::Drawable* d, unsigned int mask = ~0u)
{
    osg::ref_ptr<osg::Geode> g = new osg::Geode;
    g->addDrawable(d);
    g->setNodeMask(mask);
    return g;
}

enum class Occluder
{
    None,
    Quad,
    Box,
    QuadUnderTransform
};

/** Ground [-10, 10]^2 at z = 0 plus an occluder whose top is the square [-1, 1]^2 at z = 4
 *  (Box: the box [-1, 1]^2 x [3, 4]; QuadUnderTransform: the quad at z = 0 moved up by a
 *  MatrixTransform). The occluder's node mask is `occluderMask`. */
inline osg::ref_ptr<osg::Group> groundScene(Occluder occluder, unsigned int occluderMask = ~0u)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode(quad(-10, 10, -10, 10, 0).get()));
    switch (occluder)
    {
    case Occluder::None: break;
    case Occluder::Quad: root->addChild(geode(quad(-1, 1, -1, 1, 4).get(), occluderMask)); break;
    case Occluder::Box:
        root->addChild(geode(new osg::ShapeDrawable(new osg::Box(osg::Vec3(0, 0, 3.5f), 2, 2, 1)), occluderMask));
        break;
    case Occluder::QuadUnderTransform:
    {
        osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(osg::Matrixd::translate(0, 0, 4));
        t->addChild(geode(quad(-1, 1, -1, 1, 0).get()));
        t->setNodeMask(occluderMask);
        root->addChild(t.get());
        break;
    }
    }
    return root;
}

inline Light directional(const osg::Vec3d& towardLight)
{
    Light l;
    l.type = Light::DIRECTIONAL;
    l.vector = towardLight;
    return l;
}

inline Light pointLight(const osg::Vec3d& position)
{
    Light l;
    l.type = Light::POINT;
    l.vector = position;
    return l;
}

/** A 224 x 224 cell height field (100352 triangles) of bumps over [-20, 20]^2. */
inline osg::ref_ptr<osg::Node> bumpyTerrain()
{
    const int n = 224;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
        {
            const float x = -20.0f + 40.0f * i / n, y = -20.0f + 40.0f * j / n;
            v->push_back(osg::Vec3(x, y, 1.5f * std::sin(0.7f * x) * std::cos(0.5f * y)));
        }
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const unsigned a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            for (unsigned k : {a, b, d, a, d, c}) tris->push_back(k);
        }
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->addPrimitiveSet(tris.get());
    return geode(g.get());
}

/** The camera of the speed tests: 1024 x 768 looking down at the bumpy terrain. */
inline Camera terrainCamera()
{
    Camera c;
    c.eye = osg::Vec3d(0, -35, 25);
    c.center = osg::Vec3d(0, 0, 0);
    c.up = osg::Vec3d(0, 0, 1);
    c.fovyDeg = 45;
    c.width = 1024;
    c.height = 768;
    return c;
}

} // namespace reftest

#endif
