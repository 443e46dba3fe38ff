// Stress, without a GL context: the mesh cache and the extractor on broken meshes, light
// frusta fitted far from the origin, at tiny and huge scales, for lights along the axes
// and inside the casters; the technique's map-size limits.
#include "NotifyCapture.h"
#include "test_mesh_shapes.h"

#include <osgShadowSilhouette/LightSpace>
#include <osgShadowSilhouette/MeshCache>
#include <osgShadowSilhouette/SilhouetteExtractor>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/io_utils>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace osgShadowSilhouette;
using meshtest::makeGeometry;

namespace {

const float NaN = std::numeric_limits<float>::quiet_NaN();
const float INF = std::numeric_limits<float>::infinity();

bool finite(const osg::Vec4f& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()) && std::isfinite(v.w());
}

bool finite(const osg::Matrixd& m)
{
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(m.ptr()[i])) return false;
    return true;
}

/** Extraction and volume of `mesh` for `light` (object space): every volume vertex finite,
 *  every index in range, and as many silhouette edges as the volume's sides carry. */
void expectSoundVolume(const MeshAdjacency& mesh, const osg::Vec4d& light)
{
    SilhouetteExtractor extractor;
    SilhouetteEdges edges;
    ShadowVolume volume;
    extractor.extract(mesh, light, edges);
    extractor.buildVolume(mesh, edges, volume);
    for (const osg::Vec4f& v : volume.vertices) ASSERT_TRUE(finite(v));
    for (std::uint32_t i : volume.indices) ASSERT_LT(i, volume.vertices.size());
    for (std::uint32_t i : edges.vertexIndices) ASSERT_LT(i, mesh.positions.size());
    EXPECT_EQ(volume.indices.size() % 3, 0u);
    EXPECT_EQ(edges.lit.size(), mesh.faces.size());
}

/** The box [lo, hi] corners as a BoundingBoxd. */
osg::BoundingBoxd box(const osg::Vec3d& lo, const osg::Vec3d& hi)
{
    return osg::BoundingBoxd(lo, hi);
}

std::vector<osg::Vec3d> corners(const osg::BoundingBoxd& b)
{
    std::vector<osg::Vec3d> c;
    for (int i = 0; i < 8; ++i) c.push_back(b.corner(i));
    return c;
}

/** Where p lands in the texture of frustum f, in texels of a map of `size`. */
osg::Vec3d texel(const LightFrustum& f, const osg::Vec3d& p, unsigned int size)
{
    const osg::Vec3d t = p * f.worldToTexture();
    return osg::Vec3d(t.x() * size, t.y() * size, t.z());
}

} // namespace

TEST(StressMesh, NaNAndInfVerticesAreRefusedWithAWarningNamingTheGeometry)
{
    osstest::NotifyCapture notes;
    osg::ref_ptr<osg::Geometry> g = meshtest::cube("poisoned cube");
    osg::Vec3Array* v = static_cast<osg::Vec3Array*>(g->getVertexArray());
    (*v)[0].x() = NaN;
    (*v)[6].z() = INF;
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<const CachedMesh> mesh = cache->get(*g);
    const MeshAdjacency& a = mesh->getAdjacency();
    EXPECT_EQ(a.report.nonFiniteVertices, 2u);
    EXPECT_GT(a.report.nonFiniteTriangles, 0u);
    for (const osg::Vec3f& p : a.positions) EXPECT_TRUE(std::isfinite(p.length()));
    EXPECT_TRUE(notes.warned("poisoned cube")) << notes.warnings();
    expectSoundVolume(a, osg::Vec4d(0.3, -0.2, 1, 0));
}

TEST(StressMesh, AllVerticesNaNGiveAnEmptyMesh)
{
    osg::ref_ptr<osg::Geometry> g = meshtest::cube("all NaN");
    for (osg::Vec3f& p : *static_cast<osg::Vec3Array*>(g->getVertexArray())) p.set(NaN, NaN, NaN);
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*g)->getAdjacency();
    EXPECT_TRUE(a.empty());
    expectSoundVolume(a, osg::Vec4d(0, 0, 1, 0));
}

TEST(StressMesh, DegenerateAndSliverTrianglesAreDroppedOrKept)
{
    // A repeated corner and three collinear corners have no area; a 1e-7 sliver has some.
    osg::ref_ptr<osg::Geometry> g = makeGeometry({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1e-7f, 5}},
                                                 {0, 0, 1, 0, 1, 2, 0, 1, 3, 0, 4, 1}, "slivers");
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*g)->getAdjacency();
    EXPECT_EQ(a.report.inputTriangles, 4u);
    EXPECT_GE(a.report.degenerateTriangles, 1u);
    EXPECT_GE(a.faces.size(), 2u);
    for (const osg::Vec4d& p : a.planes) EXPECT_TRUE(std::isfinite(p.x() + p.y() + p.z() + p.w()));
    expectSoundVolume(a, osg::Vec4d(0, 0, 1, 0));
    expectSoundVolume(a, osg::Vec4d(0.5, 3, 2, 1));
}

TEST(StressMesh, DuplicatedVerticesAreWelded)
{
    // The cube as 36 separate corners: welding must recover the closed 8-vertex cube.
    osg::ref_ptr<osg::Geometry> cube = meshtest::cube();
    const osg::Vec3Array* v = static_cast<const osg::Vec3Array*>(cube->getVertexArray());
    const osg::DrawElementsUInt* e = static_cast<const osg::DrawElementsUInt*>(cube->getPrimitiveSet(0));
    std::vector<osg::Vec3f> corners;
    std::vector<unsigned int> indices;
    for (unsigned int i : *e) corners.push_back((*v)[i]), indices.push_back(unsigned(indices.size()));
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*makeGeometry(corners, indices, "soup"))->getAdjacency();
    EXPECT_EQ(a.positions.size(), 8u);
    EXPECT_TRUE(a.isClosed());
    EXPECT_EQ(a.edgeCount(), 18u);
}

TEST(StressMesh, NonManifoldFinAndRepeatedTrianglesAreKeptAsOpenFaces)
{
    // Three triangles on the edge (0,1), and one triangle twice.
    osg::ref_ptr<osg::Geometry> g = makeGeometry({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 0}},
                                                 {0, 1, 2, 1, 0, 3, 0, 1, 4, 0, 1, 2}, "fin");
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*g)->getAdjacency();
    EXPECT_GE(a.nonManifoldFaces.size(), 1u);
    EXPECT_FALSE(a.isClosed());
    for (const osg::Vec4d& light : {osg::Vec4d(0, 0, 1, 0), osg::Vec4d(1, 0, 0, 0), osg::Vec4d(0.2, 0.3, 0.5, 1)})
    {
        expectSoundVolume(a, light);
    }
}

TEST(StressMesh, OutOfRangeIndicesAreDropped)
{
    osg::ref_ptr<osg::Geometry> g = makeGeometry({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0, 1, 7}, "bad index");
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*g)->getAdjacency();
    EXPECT_EQ(a.report.outOfRangeTriangles, 1u);
    EXPECT_EQ(a.faces.size(), 1u);
}

// A GL_TRIANGLES index list of 5 indices: one triangle, and nothing read past the list
// (osg::TriangleIndexFunctor alone reads a second triangle beyond it; found by fuzz_mesh_cache).
TEST(StressMesh, IndexListNotAMultipleOfThreeGivesWholeTrianglesOnly)
{
    const osg::ref_ptr<osg::DrawElements> lists[] = {new osg::DrawElementsUByte(GL_TRIANGLES),
                                                     new osg::DrawElementsUShort(GL_TRIANGLES),
                                                     new osg::DrawElementsUInt(GL_TRIANGLES)};
    for (const osg::ref_ptr<osg::DrawElements>& list : lists)
    {
        for (unsigned int i : {0, 1, 2, 1, 2}) list->addElement(i);
        const GLenum type = list->getDataType();
        osg::ref_ptr<osg::Geometry> g = makeGeometry({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, "five indices");
        g->setPrimitiveSetList({list.get()});
        osg::ref_ptr<MeshCache> cache = new MeshCache;
        const MeshAdjacency& a = cache->get(*g)->getAdjacency();
        EXPECT_EQ(a.report.inputTriangles, 1u) << type;
        EXPECT_EQ(a.faces.size(), 1u) << type;
    }
}

TEST(StressMesh, GeometryWithoutVerticesGivesAnEmptyMesh)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    EXPECT_TRUE(cache->get(*g)->getAdjacency().empty());
}

TEST(StressExtraction, LightInAFacePlaneMakesThatFaceFaceAway)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*meshtest::cube())->getAdjacency();
    // Point light in the plane x = 1 of the +x face, and a directional light along +y (in
    // the planes of the +x, -x, +z and -z faces).
    for (const osg::Vec4d& light : {osg::Vec4d(1, 0.3, 5, 1), osg::Vec4d(0, 1, 0, 0)})
    {
        SilhouetteEdges edges;
        SilhouetteExtractor().extract(a, light, edges);
        for (std::size_t f = 0; f < a.faces.size(); ++f)
        {
            const osg::Vec4d& p = a.planes[f];
            if (p.x() * light.x() + p.y() * light.y() + p.z() * light.z() + p.w() * light.w() == 0.0)
            {
                EXPECT_EQ(edges.lit[f], 0) << "face " << f;
            }
        }
        EXPECT_GT(edges.edgeCount(), 0u);
        expectSoundVolume(a, light);
    }
}

TEST(StressExtraction, PointLightInsideAClosedCasterLightsNoFace)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*meshtest::cube())->getAdjacency();
    SilhouetteEdges edges;
    SilhouetteExtractor().extract(a, osg::Vec4d(0.1, -0.2, 0.3, 1), edges);
    EXPECT_EQ(edges.litFaceCount, 0u);
    EXPECT_EQ(edges.edgeCount(), 0u);
    expectSoundVolume(a, osg::Vec4d(0.1, -0.2, 0.3, 1));
}

TEST(StressExtraction, PointLightOnAVertexKeepsTheVolumeFinite)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*meshtest::cube())->getAdjacency();
    expectSoundVolume(a, osg::Vec4d(1, 1, 1, 1));
    expectSoundVolume(a, osg::Vec4d(1 + 1e-12, 1, 1, 1));
}

TEST(StressExtraction, LightTransformedIntoAFarAwayCaster)
{
    // The caster 1e6 from the origin, scaled by 1e-4: the object-space light stays finite
    // and the silhouette of a cube lit from above-ish is one loop of 4 to 6 edges.
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const MeshAdjacency& a = cache->get(*meshtest::cube())->getAdjacency();
    const osg::Matrixd world = osg::Matrixd::scale(1e-4, 1e-4, 1e-4) * osg::Matrixd::translate(1e6, -1e6, 5e5);
    SilhouetteEdges edges;
    SilhouetteExtractor().extract(a, HomogeneousLight::point(osg::Vec3d(1e6 + 1e-3, -1e6 + 2e-3, 5e5 + 5e-3)), world,
                                  edges);
    EXPECT_TRUE(std::isfinite(edges.objectLight.length()));
    EXPECT_GE(edges.edgeCount(), 4u);
    EXPECT_LE(edges.edgeCount(), 6u);
}

TEST(StressLightSpace, DirectionalFrustumMillionUnitsFromTheOrigin)
{
    const osg::Vec3d o(1e6, -7e5, 3e5);
    const osg::BoundingBoxd receivers = box(o + osg::Vec3d(-12, -12, 0), o + osg::Vec3d(12, 12, 4));
    const LightFrustum f = fitDirectionalFrustum(osg::Vec3d(0.45, -0.35, 0.82), corners(receivers), receivers, 2048);
    ASSERT_TRUE(f.valid);
    EXPECT_TRUE(finite(f.view) && finite(f.projection));
    for (const osg::Vec3d& c : corners(receivers))
    {
        const osg::Vec3d t = c * f.worldToTexture();
        for (int i = 0; i < 3; ++i)
        {
            EXPECT_GE(t[i], -1e-9);
            EXPECT_LE(t[i], 1 + 1e-9);
        }
    }
    // The light's eye space is near the scene (its float model-view stays precise).
    EXPECT_LT((o * f.view).length(), 100.0);
}

TEST(StressLightSpace, DirectionalFrustumAtTinyAndHugeScales)
{
    for (double s : {1e-4, 1e4})
    {
        const osg::BoundingBoxd b = box(osg::Vec3d(-12, -12, 0) * s, osg::Vec3d(12, 12, 4) * s);
        const LightFrustum f = fitDirectionalFrustum(osg::Vec3d(0.45, -0.35, 0.82), corners(b), b, 1024);
        ASSERT_TRUE(f.valid) << s;
        EXPECT_TRUE(finite(f.worldToTexture())) << s;
        const osg::Vec3d lo = b.corner(0) * f.worldToTexture(), hi = b.corner(7) * f.worldToTexture();
        EXPECT_GT((hi - lo).length(), 0.5) << "the scene fills the map at scale " << s;
    }
}

TEST(StressLightSpace, DirectionalFrustumForLightsAlongTheAxesAndGrazing)
{
    const osg::BoundingBoxd b = box(osg::Vec3d(-12, -12, 0), osg::Vec3d(12, 12, 4));
    for (const osg::Vec3d& d : {osg::Vec3d(0, 0, 1), osg::Vec3d(1, 0, 0), osg::Vec3d(0, -1, 0), osg::Vec3d(0, 0, -1),
                                osg::Vec3d(std::cos(osg::DegreesToRadians(0.5)), 0, std::sin(osg::DegreesToRadians(0.5)))})
    {
        const LightFrustum f = fitDirectionalFrustum(d, corners(b), b, 2048);
        ASSERT_TRUE(f.valid) << d;
        EXPECT_TRUE(finite(f.view) && finite(f.projection)) << d;
    }
}

TEST(StressLightSpace, TexelGridOfAFittedFrustumIsWhereTheGLCasesExpectIt)
{
    // test_stress_scale.cpp places edges at multiples of 24 / 256 for a 257-texel map fitted
    // to a 24-unit ground lit straight down: those points fall on texel boundaries.
    const osg::BoundingBoxd b = box(osg::Vec3d(-12, -12, 0), osg::Vec3d(12, 12, 4));
    const LightFrustum f = fitDirectionalFrustum(osg::Vec3d(0, 0, 1), corners(b), b, 257);
    ASSERT_TRUE(f.valid);
    for (int k : {-54, -40, -34, -20, 0, 17})
    {
        const osg::Vec3d t = texel(f, osg::Vec3d(k * 24.0 / 256, k * 24.0 / 256, 1.0), 257);
        EXPECT_NEAR(t.x(), std::round(t.x()), 1e-6) << k;
        EXPECT_NEAR(t.y(), std::round(t.y()), 1e-6) << k;
    }
}

TEST(StressLightSpace, PerspectiveFrustumWithTheLightInsideTheCasters)
{
    const osg::BoundingBoxd receivers = box(osg::Vec3d(-12, -12, 0), osg::Vec3d(12, 12, 4));
    LightDescription light;
    light.type = LightDescription::POINT;
    light.position = osg::Vec3d(0, 0, 2); // inside the casters' box
    const LightFrustum f = fitPerspectiveFrustum(light, corners(receivers), receivers);
    ASSERT_TRUE(f.valid);
    EXPECT_TRUE(finite(f.view) && finite(f.projection));
    double l, r, b, t, n, fa;
    ASSERT_TRUE(f.projection.getFrustum(l, r, b, t, n, fa));
    EXPECT_GT(n, 0.0);
    EXPECT_GT(fa, n);
}

TEST(StressLightSpace, SpotFrustumsWithTinyAndVeryWideCones)
{
    const osg::BoundingBoxd receivers = box(osg::Vec3d(-12, -12, 0), osg::Vec3d(12, 12, 4));
    for (double cutoff : {0.01, 1.0, 89.0, 89.99})
    {
        LightDescription light;
        light.type = LightDescription::SPOT;
        light.position = osg::Vec3d(0, 0, 10);
        light.spotDirection = osg::Vec3d(0, 0, -1);
        light.spotCutoffDeg = cutoff;
        const LightFrustum f = fitPerspectiveFrustum(light, corners(receivers), receivers);
        ASSERT_TRUE(f.valid) << cutoff;
        EXPECT_TRUE(finite(f.view) && finite(f.projection)) << cutoff;
    }
}

TEST(StressLightSpace, NonFiniteOrZeroLightsAreRefused)
{
    osg::ref_ptr<osg::Light> light = new osg::Light;
    LightDescription out;
    light->setPosition(osg::Vec4(NaN, 0, 1, 0));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), out));
    light->setPosition(osg::Vec4(0, 0, 0, 0));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), out));
    light->setPosition(osg::Vec4(0, 0, INF, 1));
    EXPECT_FALSE(LightDescription::fromLight(*light, osg::Matrixd(), out));
    const osg::BoundingBoxd b = box(osg::Vec3d(-1, -1, -1), osg::Vec3d(1, 1, 1));
    EXPECT_FALSE(fitDirectionalFrustum(osg::Vec3d(NaN, 0, 1), corners(b), b, 1024).valid);
    EXPECT_FALSE(fitDirectionalFrustum(osg::Vec3d(0, 0, 0), corners(b), b, 1024).valid);
}

TEST(StressTechnique, MapSizeOutOfRangeIsRefusedWithAWarning)
{
    osstest::NotifyCapture notes;
    osg::ref_ptr<SilhouetteShadowTechnique> t = new SilhouetteShadowTechnique;
    t->setShadowMapSize(512);
    t->setShadowMapSize(1u << 20);
    EXPECT_EQ(t->getShadowMapSize(), 512u);
    EXPECT_TRUE(notes.warned("ShadowMapSize 1048576 is out of range (1 to 16384")) << notes.warnings();
    EXPECT_TRUE(notes.warned("keeping 512")) << notes.warnings();
    t->setShadowMapSize(0);
    EXPECT_EQ(t->getShadowMapSize(), 512u);
    t->setShadowMapSize(16384);
    EXPECT_EQ(t->getShadowMapSize(), 16384u);
}

// Every numeric setter refuses what its range (PropertyRanges) excludes and keeps its value.
TEST(StressTechnique, SettersKeepTheirValueOnBadInput)
{
    osstest::NotifyCapture notes;
    osg::ref_ptr<SilhouetteShadowTechnique> t = new SilhouetteShadowTechnique;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    t->setMaxShadowLights(9);
    t->setMaxShadowLights(0);
    t->setLightNum(-2);
    t->setLightNum(8);
    t->setBaseTextureUnit(0);
    t->setBaseTextureUnit(32);
    t->setDebugLight(8);
    t->setShadowRayOffset(-1e-6f);
    t->setShadowRayOffset(nan);
    t->setPolygonOffsetUnits(nan);
    t->setPolygonOffsetFactor(std::numeric_limits<float>::infinity());
    osg::ref_ptr<SilhouetteShadowTechnique> defaults = new SilhouetteShadowTechnique;
    EXPECT_EQ(t->getMaxShadowLights(), defaults->getMaxShadowLights());
    EXPECT_EQ(t->getLightNum(), defaults->getLightNum());
    EXPECT_EQ(t->getBaseTextureUnit(), defaults->getBaseTextureUnit());
    EXPECT_EQ(t->getDebugLight(), defaults->getDebugLight());
    EXPECT_EQ(t->getShadowRayOffset(), defaults->getShadowRayOffset());
    EXPECT_EQ(t->getPolygonOffsetUnits(), defaults->getPolygonOffsetUnits());
    EXPECT_EQ(t->getPolygonOffsetFactor(), defaults->getPolygonOffsetFactor());
    for (const char* part : {"MaxShadowLights 9 is out of range (1 to 8", "MaxShadowLights 0", "LightNum -2", "LightNum 8",
                             "BaseTextureUnit 0", "BaseTextureUnit 32", "DebugLight 8", "ShadowRayOffset -1e-06",
                             "ShadowRayOffset nan is not a finite number", "PolygonOffsetUnits nan",
                             "PolygonOffsetFactor inf"})
        EXPECT_TRUE(notes.warned(part)) << part << "\n" << notes.warnings();
}
