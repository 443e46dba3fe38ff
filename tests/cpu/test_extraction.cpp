// Silhouette extraction and shadow-volume geometry: hand-derived cases and invariants.
#include "test_mesh_shapes.h"
#include "test_soups.h"

#include <osgShadowSilhouette/SilhouetteExtractor>

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>

using namespace osgShadowSilhouette;
using namespace meshtest;

namespace {

struct ProbePoint
{
    osg::Vec3d position;
    int expectedCount; // stencil count z-fail gives there (winding number of the volume)
};

struct Case
{
    const char* name;
    std::function<osg::ref_ptr<osg::Geometry>()> shape;
    osg::Vec4d light;               // object space, w = 0 directional (toward the light) or 1
    OpenCasterRule rule;
    bool closed;
    int litFaces;                   // -1: not derived by hand
    int silhouetteEdges;            // -1: not derived by hand
    int loops;                      // -1: not derived by hand
    std::vector<ProbePoint> probes;
    bool matchesRayCast;            // false when the light lies on the surface
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const OpenCasterRule TWO = OpenCasterRule::TWO_SIDED;
const OpenCasterRule LIT = OpenCasterRule::LIT_FACES_ONLY;

auto cubeShape = [] { return cube(); };
auto tetraShape = [] { return tetrahedron(); };
auto sphereShape = [] { return uvSphere(16, 8); };
auto torusShape = [] { return torus(24, 12); };
auto planeShape = [] { return openPlane(); };
auto bookShape = [] { return nonManifoldBook(); };
auto zeroAreaShape = [] { return cubeWithZeroAreaFace(); };

// Every expected number below is derived in the comment next to it.
const std::vector<Case> kCases = {
    // top face (2 triangles) lit, its 4 edges; shadow is the column |x|,|y| < 1 below
    { "cube_directional_up", cubeShape, { 0, 0, 1, 0 }, TWO, true, 2, 4, 1,
      { { { 0, 0, -5 }, 1 }, { { 0, 0, 0 }, 1 }, { { 0, 0, 5 }, 0 }, { { 3, 0, -5 }, 0 },
        { { 0.5, 0.5, -100 }, 1 } }, true },
    // three faces lit, hexagonal silhouette
    { "cube_directional_diagonal", cubeShape, { 1, 1, 1, 0 }, TWO, true, 6, 6, 1,
      { { { -3, -3, -3 }, 1 }, { { 0, 0, 0 }, 1 }, { { 3, 3, 3 }, 0 }, { { -3, 3, 0 }, 0 } }, true },
    // light at z = 5: the shadow widens below, x = (5 - z) / 4 at the edge x = 1, z = 1
    { "cube_point_above", cubeShape, { 0, 0, 5, 1 }, TWO, true, 2, 4, 1,
      { { { 0, 0, -2 }, 1 }, { { 2.4, 0, -5 }, 1 }, { { 2.6, 0, -5 }, 0 } }, true },
    // light in the plane z = 1 of the top face: top faces away, only +x is lit
    { "cube_light_in_face_plane", cubeShape, { 3, 0, 1, 1 }, TWO, true, 2, 4, 1,
      { { { -2, 0, 0 }, 1 }, { { -2, 0, 0.99 }, 1 }, { { -2, 0, 1.5 }, 0 } }, true },
    // light at the corner (1,1,1): every face faces away (three contain the light); the
    // cube shadows the octant x, y, z < 1 seen from the corner
    { "cube_light_at_vertex", cubeShape, { 1, 1, 1, 1 }, TWO, true, 0, 0, 0,
      { { { 0, 0, 0 }, 1 }, { { -3, -3, -3 }, 1 }, { { -3, 0.5, 0.5 }, 1 }, { { 0, 2, 0 }, 0 } }, false },
    // light inside a closed caster: nothing is lit, everything is in shadow
    { "cube_light_inside", cubeShape, { 0, 0, 0.5, 1 }, TWO, true, 0, 0, 0,
      { { { 0, 0, 0 }, 1 }, { { 5, 5, 5 }, 1 }, { { 0, 0, -7 }, 1 } }, false },
    // normals are -v_i; n_i . (1,1,1) = -v_i . (1,1,1) > 0 for faces 1,2,3; silhouette is
    // the triangle v1 v2 v3 (face 0)
    { "tetrahedron_directional", tetraShape, { 1, 1, 1, 0 }, TWO, true, 3, 3, 1,
      { { { -3, -3, -3 }, 1 }, { { 3, 3, 3 }, 0 } }, true },
    // -v_i.z > 0 for faces 1, 2: silhouette v0-v2-v3-v1
    { "tetrahedron_directional_z", tetraShape, { 0, 0, 1, 0 }, TWO, true, 2, 4, 1,
      { { { 0, 0, -5 }, 1 }, { { 0, 0, 5 }, 0 } }, true },
    // 16 x 8 sphere: 224 faces, upper half lit, silhouette = the 16 equator edges
    { "sphere_directional_up", sphereShape, { 0, 0, 1, 0 }, TWO, true, 112, 16, 1,
      { { { 0, 0, -3 }, 1 }, { { 0, 0, 3 }, 0 }, { { 1.5, 0, -3 }, 0 }, { { 0.5, 0.3, -3 }, 1 } }, true },
    { "sphere_point", sphereShape, { 0, 0, 3, 1 }, TWO, true, -1, -1, 1,
      { { { 0, 0, -3 }, 1 }, { { 3, 0, 0 }, 0 } }, true },
    // 24 x 12 torus: 576 faces, upper half lit, silhouette = outer and inner equators
    { "torus_directional_up", torusShape, { 0, 0, 1, 0 }, TWO, true, 288, 48, 2,
      { { { 2, 0, -3 }, 1 }, { { 0, 0, -3 }, 0 }, { { 2, 0, 3 }, 0 }, { { 3.5, 0, -3 }, 0 } }, true },
    // a ray along +x through both sides of the ring leaves two lit faces behind: count 2
    { "torus_directional_side", torusShape, { 1, 0, 0, 0 }, TWO, true, -1, -1, -1,
      { { { -5, 0.05, 0.1 }, 2 }, { { 0, 0.05, 0.1 }, 1 }, { { 5, 0.05, 0.1 }, 0 } }, true },
    // zero-area face A,B,M faces away: silhouette A-M-B-C-D
    { "zero_area_face_up", zeroAreaShape, { 0, 0, 1, 0 }, TWO, true, 3, 5, 1,
      { { { 0, 0, -5 }, 1 }, { { 0, 0, 5 }, 0 } }, true },
    // top and front lit: A-M-B-A around the zero-area face plus B-C-D-A-E-F-B
    { "zero_area_face_front", zeroAreaShape, { 0, -1, 1, 0 }, TWO, true, 5, 9, 1,
      { { { 0.3, 3, -3.2 }, 1 }, { { 0, -3, 3 }, 0 } }, true },
    // open plane, two-sided: its 4 boundary edges, shadow below only
    { "plane_point_above", planeShape, { 0, 0, 5, 1 }, TWO, false, 2, 4, 1,
      { { { 0, 0, -1 }, 1 }, { { 0, 0, 1 }, 0 }, { { 3, 0, -1 }, 0 }, { { 0.5, 0.5, -10 }, 1 } }, true },
    { "plane_point_below_two_sided", planeShape, { 0, 0, -5, 1 }, TWO, false, 0, 4, 1,
      { { { 0, 0, 1 }, 1 }, { { 0, 0, -1 }, 0 }, { { 3, 0, 1 }, 0 } }, true },
    { "plane_point_above_lit_only", planeShape, { 0, 0, 5, 1 }, LIT, false, 2, 4, 1,
      { { { 0, 0, -1 }, 1 }, { { 0, 0, 1 }, 0 } }, true },
    { "plane_point_below_lit_only", planeShape, { 0, 0, -5, 1 }, LIT, false, 0, 0, 0,
      { { { 0, 0, 1 }, 0 }, { { 0, 0, -1 }, 0 } }, true },
    // book lit from (3,0,0.5): rhombus (4 boundary edges) and the refused fin (3) cast;
    // from (-1,0,-0.1) the segment to the light crosses the rhombus and the fin
    { "book_light_right", bookShape, { 3, 0, 0.5, 1 }, TWO, false, 3, 7, 2,
      { { { -1, 0, 0.3 }, 1 }, { { -1, 0, -0.1 }, 2 }, { { 2, 0, 0.2 }, 0 }, { { -1, 0.9, 0.3 }, 0 } }, true },
    // from the left the fin faces away: two-sided it still casts, lit-only it does not
    { "book_light_left_two_sided", bookShape, { -3, 0, 0.5, 1 }, TWO, false, 2, 7, 2,
      { { { 1, 0, 0.3 }, 1 }, { { 1, 0, -0.1 }, 2 }, { { -2, 0, 0.2 }, 0 } }, true },
    { "book_light_left_lit_only", bookShape, { -3, 0, 0.5, 1 }, LIT, false, 2, 4, 1,
      { { { 1, 0, 0.3 }, 0 }, { { 1, 0, -0.1 }, 1 }, { { -2, 0, 0.2 }, 0 } }, true },
};

class ExtractionCase : public ::testing::TestWithParam<Case>
{
protected:
    void SetUp() override
    {
        mesh = adjacencyOf(*GetParam().shape());
        SilhouetteExtractor extractor(GetParam().rule);
        extractor.extract(mesh, GetParam().light, silhouette);
        extractor.buildVolume(mesh, silhouette, volume);
    }
    MeshAdjacency mesh;
    SilhouetteEdges silhouette;
    ShadowVolume volume;
};

TEST_P(ExtractionCase, CountsMatchHandDerivation)
{
    const Case& c = GetParam();
    EXPECT_EQ(c.closed, silhouette.closedCaster);
    EXPECT_EQ(c.closed, volume.closedCaster);
    if (c.litFaces >= 0)
    {
        EXPECT_EQ(std::size_t(c.litFaces), silhouette.litFaceCount);
    }
    if (c.silhouetteEdges >= 0)
    {
        EXPECT_EQ(std::size_t(c.silhouetteEdges), silhouette.edgeCount());
    }
    if (c.loops >= 0)
    {
        EXPECT_EQ(std::size_t(c.loops), silhouetteLoops(silhouette));
    }
    EXPECT_EQ(silhouette.positions.size(), silhouette.vertexIndices.size());
}

TEST_P(ExtractionCase, ClosedCasterSilhouetteFormsClosedLoops)
{
    if (!GetParam().closed) GTEST_SKIP() << "open caster";
    EXPECT_TRUE(silhouetteHasEvenDegrees(silhouette));
    EXPECT_TRUE(silhouetteIsBalanced(silhouette));
}

TEST_P(ExtractionCase, VolumeIsWatertight)
{
    EXPECT_TRUE(volumeIsEdgeBalanced(volume));
    if (!GetParam().closed) return;
    // a closed 2-manifold, except where two silhouette loops touch at a vertex v: there the
    // extruded edge v-v' carries the side quads of both loops (four faces)
    std::set<std::pair<std::uint32_t, std::uint32_t>> expectedSeams;
    const std::uint32_t n = std::uint32_t(mesh.positions.size());
    for (std::uint32_t v : silhouetteCrossings(silhouette)) expectedSeams.insert({ v, v + n });
    EXPECT_EQ(expectedSeams, nonManifoldEdges(volume));
    if (expectedSeams.empty())
    {
        EXPECT_TRUE(pinchedVertices(volume).empty());
    }
}

TEST_P(ExtractionCase, StencilCountAtProbePoints)
{
    for (const ProbePoint& p : GetParam().probes)
    {
        double w = windingNumber(volume, p.position);
        EXPECT_NEAR(double(p.expectedCount), w, 1e-6)
            << "at (" << p.position.x() << ", " << p.position.y() << ", " << p.position.z() << ")";
    }
}

TEST_P(ExtractionCase, StencilCountEqualsCastingFacesBetweenPointAndLight)
{
    if (!GetParam().matchesRayCast) GTEST_SKIP() << "light on the surface";
    const bool allFaces = !GetParam().closed && GetParam().rule == TWO;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    for (int i = 0; i < 60; ++i)
    {
        osg::Vec3d p(coordinate(random), coordinate(random), coordinate(random));
        double w = windingNumber(volume, p);
        int expected = castingFacesBetween(mesh, silhouette.lit, GetParam().light, p, allFaces);
        EXPECT_NEAR(double(expected), w, 1e-6) << "at (" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    }
}

TEST_P(ExtractionCase, RangesPartitionTheIndices)
{
    EXPECT_EQ(0u, volume.sides.first);
    EXPECT_EQ(volume.sides.count, volume.darkCap.first);
    EXPECT_EQ(volume.darkCap.first + volume.darkCap.count, volume.lightCap.first);
    EXPECT_EQ(volume.indices.size(), std::size_t(volume.lightCap.first + volume.lightCap.count));
    std::size_t quads = 0;
    for (auto m : silhouette.multiplicity) quads += m;
    EXPECT_EQ(6 * quads, volume.sides.count);
    EXPECT_EQ(2 * mesh.positions.size(), volume.vertices.size());
}

INSTANTIATE_TEST_SUITE_P(Casters, ExtractionCase, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

std::set<std::pair<osg::Vec3f, osg::Vec3f>> directedEdges(const SilhouetteEdges& s)
{
    std::set<std::pair<osg::Vec3f, osg::Vec3f>> edges;
    for (std::size_t e = 0; e < s.edgeCount(); ++e)
        edges.insert({ s.positions[2 * e], s.positions[2 * e + 1] });
    return edges;
}

TEST(SilhouetteOrientation, LitFaceIsOnTheLeftSeenFromTheLight)
{
    // from (0,0,5) the top square is seen counter-clockwise: A(-1,-1) B(1,-1) C(1,1) D(-1,1)
    MeshAdjacency mesh = adjacencyOf(*cube());
    SilhouetteEdges s;
    SilhouetteExtractor().extract(mesh, osg::Vec4d(0, 0, 5, 1), s);
    osg::Vec3f A(-1, -1, 1), B(1, -1, 1), C(1, 1, 1), D(-1, 1, 1);
    std::set<std::pair<osg::Vec3f, osg::Vec3f>> expected = { { A, B }, { B, C }, { C, D }, { D, A } };
    EXPECT_EQ(expected, directedEdges(s));
}

TEST(SilhouetteOrientation, TwoSidedOpenCasterLitFromBehindRunsTheOtherWay)
{
    MeshAdjacency mesh = adjacencyOf(*openPlane());
    SilhouetteEdges s;
    SilhouetteExtractor(OpenCasterRule::TWO_SIDED).extract(mesh, osg::Vec4d(0, 0, -5, 1), s);
    osg::Vec3f A(-1, -1, 0), B(1, -1, 0), C(1, 1, 0), D(-1, 1, 0);
    std::set<std::pair<osg::Vec3f, osg::Vec3f>> expected = { { B, A }, { C, B }, { D, C }, { A, D } };
    EXPECT_EQ(expected, directedEdges(s));
}

TEST(ShadowVolumeGeometry, SideQuadOfFrontEdgeFacesAwayFromTheVolume)
{
    MeshAdjacency mesh = adjacencyOf(*cube());
    SilhouetteEdges s;
    ShadowVolume v;
    SilhouetteExtractor().extract(mesh, osg::Vec4d(0, 0, 5, 1), s);
    SilhouetteExtractor().buildVolume(mesh, s, v);
    // first side triangle (b, a, a'): a' = a + (a - L) stands in for the point at infinity
    bool found = false;
    for (std::uint32_t t = v.sides.first; t < v.sides.first + v.sides.count; t += 6)
    {
        osg::Vec4f b = v.vertices[v.indices[t]], a = v.vertices[v.indices[t + 1]];
        osg::Vec4f far = v.vertices[v.indices[t + 2]];
        if (a.y() != -1.0f || b.y() != -1.0f) continue;
        EXPECT_EQ(0.0f, far.w());
        osg::Vec3f a3(a.x(), a.y(), a.z()), b3(b.x(), b.y(), b.z());
        osg::Vec3f normal = (a3 - b3) ^ (a3 + osg::Vec3f(far.x(), far.y(), far.z()) - b3);
        EXPECT_LT(normal.y(), 0.0f);
        found = true;
    }
    EXPECT_TRUE(found);
}

TEST(ShadowVolumeGeometry, ExtrudedVerticesPointAwayFromTheLight)
{
    MeshAdjacency mesh = adjacencyOf(*cube());
    SilhouetteEdges s;
    ShadowVolume v;
    SilhouetteExtractor().extract(mesh, osg::Vec4d(0, 0, 5, 1), s);
    SilhouetteExtractor().buildVolume(mesh, s, v);
    const std::size_t n = mesh.positions.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const osg::Vec3f& p = mesh.positions[i];
        EXPECT_EQ(osg::Vec4f(p, 1.0f), v.vertices[i]);
        EXPECT_EQ(osg::Vec4f(p - osg::Vec3f(0, 0, 5), 0.0f), v.vertices[n + i]);
    }
    SilhouetteExtractor().extract(mesh, osg::Vec4d(0.5, 0, 1, 0), s);
    SilhouetteExtractor().buildVolume(mesh, s, v);
    EXPECT_EQ(osg::Vec4f(-0.5f, 0, -1, 0), v.vertices[n]);
    // top (2 triangles) and +x (2) lit: the silhouette runs round both, 6 edges
    EXPECT_EQ(6u * 6u, v.sides.count);
    EXPECT_EQ(4u * 3u, v.lightCap.count);
    EXPECT_EQ(8u * 3u, v.darkCap.count);
}

TEST(LightSpace, LightIsTakenIntoObjectSpace)
{
    // object point p goes to p * 2 + (10, 0, 0) in the world
    osg::Matrixd world = osg::Matrixd::scale(2, 2, 2) * osg::Matrixd::translate(10, 0, 0);
    osg::Vec4d point = lightInObjectSpace(HomogeneousLight::point({ 12, 0, 4 }), world);
    EXPECT_NEAR(1.0, point.x(), 1e-12);
    EXPECT_NEAR(0.0, point.y(), 1e-12);
    EXPECT_NEAR(2.0, point.z(), 1e-12);
    EXPECT_EQ(1.0, point.w());
    // rotating +y onto +z by 90 degrees about x: world +z is object +y
    osg::Matrixd rotation = osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS);
    osg::Vec4d dir = lightInObjectSpace(HomogeneousLight::directional({ 0, 0, 1 }), rotation);
    EXPECT_NEAR(0.0, dir.x(), 1e-12);
    EXPECT_NEAR(1.0, dir.y(), 1e-12);
    EXPECT_NEAR(0.0, dir.z(), 1e-12);
    EXPECT_EQ(0.0, dir.w());
    // homogeneous point with w = 2 is normalised
    osg::Vec4d scaled = lightInObjectSpace(HomogeneousLight{ { 4, 0, 2, 2 } }, osg::Matrixd());
    EXPECT_EQ(osg::Vec4d(2, 0, 1, 1), scaled);
}

TEST(LightSpace, WorldMatrixOverloadMatchesObjectSpaceLight)
{
    MeshAdjacency mesh = adjacencyOf(*cube());
    osg::Matrixd world = osg::Matrixd::scale(2, 2, 2) * osg::Matrixd::translate(10, 0, 0);
    SilhouetteEdges viaWorld, viaObject;
    SilhouetteExtractor().extract(mesh, HomogeneousLight::point({ 10, 0, 10 }), world, viaWorld);
    SilhouetteExtractor().extract(mesh, osg::Vec4d(0, 0, 5, 1), viaObject);
    EXPECT_EQ(viaObject.lit, viaWorld.lit);
    EXPECT_EQ(viaObject.vertexIndices, viaWorld.vertexIndices);
    EXPECT_EQ(2u, viaWorld.litFaceCount);
}

TEST(FarLight, DistantPointLightMatchesDirectionalLight)
{
    for (auto shape : { cube(), uvSphere(16, 8), torus(24, 12) })
    {
        MeshAdjacency mesh = adjacencyOf(*shape);
        SilhouetteEdges far, directional;
        osg::Vec3d toward(0.2, 0.3, 1.0);
        SilhouetteExtractor().extract(mesh, osg::Vec4d(toward * 1e7, 1.0), far);
        SilhouetteExtractor().extract(mesh, osg::Vec4d(toward, 0.0), directional);
        EXPECT_EQ(directional.lit, far.lit) << shape->getName();
        EXPECT_EQ(directional.vertexIndices, far.vertexIndices) << shape->getName();
        EXPECT_TRUE(silhouetteIsBalanced(far));
    }
}

TEST(FacingRule, LightInThePlaneFacesAway)
{
    EXPECT_FALSE(facesLight(osg::Vec4d(0, 0, 1, -1), osg::Vec4d(7, -3, 1, 1)));
    EXPECT_FALSE(facesLight(osg::Vec4d(0, 0, 1, -1), osg::Vec4d(1, 0, 0, 0)));
    EXPECT_FALSE(facesLight(osg::Vec4d(0, 0, 0, 0), osg::Vec4d(0, 0, 5, 1)));
    EXPECT_TRUE(facesLight(osg::Vec4d(0, 0, 1, -1), osg::Vec4d(0, 0, 1.0000001, 1)));
    EXPECT_TRUE(facesLight(osg::Vec4d(0, 0, 1, -1), osg::Vec4d(0, 0, 1, 0)));
}

TEST(Reuse, SteadyStateExtractionDoesNotReallocate)
{
    MeshAdjacency mesh = adjacencyOf(*torus(24, 12));
    SilhouetteExtractor extractor;
    SilhouetteEdges s;
    ShadowVolume v;
    extractor.buildVolume(mesh, HomogeneousLight::directional({ 0.3, 0.1, 1 }), osg::Matrixd(), s, v);
    const void* pointers[] = { s.lit.data(), s.vertexIndices.data(), s.positions.data(),
                               v.vertices.data(), v.indices.data() };
    extractor.buildVolume(mesh, HomogeneousLight::directional({ 0.3, 0.1, 1 }), osg::Matrixd(), s, v);
    const void* again[] = { s.lit.data(), s.vertexIndices.data(), s.positions.data(),
                            v.vertices.data(), v.indices.data() };
    for (int i = 0; i < 5; ++i) EXPECT_EQ(pointers[i], again[i]) << "buffer " << i;
}

TEST(TwoSidedRule, ClosedCasterIgnoresTheRule)
{
    MeshAdjacency mesh = adjacencyOf(*cube());
    SilhouetteEdges a, b;
    SilhouetteExtractor(OpenCasterRule::TWO_SIDED).extract(mesh, osg::Vec4d(1, 1, 1, 0), a);
    SilhouetteExtractor(OpenCasterRule::LIT_FACES_ONLY).extract(mesh, osg::Vec4d(1, 1, 1, 0), b);
    EXPECT_EQ(a.vertexIndices, b.vertexIndices);
    EXPECT_EQ(std::vector<std::uint8_t>(6, 1), a.multiplicity);
}

TEST(TwoSidedRule, FoldOfAnOpenCasterCarriesTwoSideQuads)
{
    // a roof: two triangles meeting at the ridge y = 0, z = 1 lit from +y, so one slope
    // faces the light and the other does not: the ridge is a fold of multiplicity 2
    auto roof = makeGeometry({ { -1, -1, 0 }, { 1, -1, 0 }, { 1, 0, 1 }, { -1, 0, 1 }, { -1, 1, 0 }, { 1, 1, 0 } },
                             { 0, 1, 2, 0, 2, 3, 3, 2, 5, 3, 5, 4 }, "roof");
    MeshAdjacency mesh = adjacencyOf(*roof);
    SilhouetteEdges s;
    ShadowVolume v;
    SilhouetteExtractor extractor(OpenCasterRule::TWO_SIDED);
    extractor.extract(mesh, osg::Vec4d(0, 1, 0.2, 0), s);
    extractor.buildVolume(mesh, s, v);
    EXPECT_EQ(2u, s.litFaceCount); // the +y slope
    std::size_t doubled = std::count(s.multiplicity.begin(), s.multiplicity.end(), 2);
    EXPECT_EQ(1u, doubled);
    EXPECT_TRUE(volumeIsEdgeBalanced(v));
    // below the ridge, the ray toward the light crosses only the far (+y) slope: 1; from
    // (0,-0.5,0.1) inside the roof it crosses the +y slope only: 1; far -y, low: both: 2
    EXPECT_NEAR(1.0, windingNumber(v, osg::Vec3d(0, -0.5, 0.1)), 1e-6);
    EXPECT_NEAR(2.0, windingNumber(v, osg::Vec3d(0, -3, -0.2)), 1e-6);
    EXPECT_NEAR(0.0, windingNumber(v, osg::Vec3d(0, 3, 0.8)), 1e-6);
}

/** The scanned Stanford bunny of Debian's glmark2-data, as vertices and triangles. */
bool readBunny(TriangleSoup& soup)
{
    std::ifstream in("/usr/share/glmark2/models/bunny.obj");
    std::string line, tag, corner;
    while (std::getline(in, line))
    {
        std::istringstream fields(line);
        fields >> tag;
        if (tag == "v")
        {
            osg::Vec3d p;
            fields >> p.x() >> p.y() >> p.z();
            soup.positions.push_back(p);
        }
        else if (tag == "f")
            for (int k = 0; k < 3 && fields >> corner; ++k) soup.indices.push_back(std::stoul(corner) - 1);
    }
    return !soup.indices.empty();
}

TEST(RealMesh, ScannedBunnyGivesClosedLoopsAndAWatertightVolume)
{
    TriangleSoup soup;
    if (!readBunny(soup)) GTEST_SKIP() << "glmark2-data is not installed";
    MeshAdjacency mesh;
    buildMeshAdjacency(soup, MeshBuildOptions(), "bunny", mesh);
    ASSERT_EQ(69666u, mesh.faces.size());
    ASSERT_TRUE(mesh.isClosed());
    const osg::Vec4d lights[] = { { 0.3, 0.5, 1, 0 }, { -1, 0.2, 0.1, 0 }, { 1, 2, 6, 1 }, { 0.1, -3, 0.5, 1 } };
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
    for (const osg::Vec4d& light : lights)
    {
        SilhouetteEdges s;
        ShadowVolume v;
        SilhouetteExtractor().extract(mesh, light, s);
        SilhouetteExtractor().buildVolume(mesh, s, v);
        EXPECT_GT(s.edgeCount(), 100u);
        EXPECT_TRUE(silhouetteIsBalanced(s));
        EXPECT_TRUE(silhouetteHasEvenDegrees(s));
        std::set<std::pair<std::uint32_t, std::uint32_t>> seams;
        for (std::uint32_t c : silhouetteCrossings(s)) seams.insert({ c, c + std::uint32_t(mesh.positions.size()) });
        EXPECT_EQ(seams, nonManifoldEdges(v));
        for (int i = 0; i < 10; ++i)
        {
            osg::Vec3d p(coordinate(random), coordinate(random), coordinate(random));
            EXPECT_NEAR(double(castingFacesBetween(mesh, s.lit, light, p, false)), windingNumber(v, p), 1e-6);
        }
    }
}

}

// ----- triangle soups ------------------------------------------------------------------------
// Whatever the soup, the count z-fail takes at a point (the winding number of the volume) is
// never negative and is zero exactly where no face of the soup lies between the point and
// the light, so that counts of several casters add up without cancelling. Where the soup
// casts with the two-sided rule the count is the number of faces crossed.

namespace {

struct SoupCase
{
    const char* name;
    std::function<std::vector<souptest::Triangle>()> soup;
    bool classic; // cast with the classic rule (closed and wound outward)
};

void PrintTo(const SoupCase& c, std::ostream* os) { *os << c.name; }

const std::vector<osg::Vec4d> kSoupLights = {
    {0.3, 0.2, 1, 0}, {1, -0.5, 0.3, 0}, {-0.2, 0.1, -1, 0}, {0.5, 0.4, 4, 1}, {0.1, 0.2, 0.3, 1}};

class SoupCount : public ::testing::TestWithParam<SoupCase>
{
};

} // namespace

TEST_P(SoupCount, IsZeroExactlyWhereNoFaceIsBetweenPointAndLight)
{
    const MeshAdjacency mesh = adjacencyOf(*souptest::soupGeometry(GetParam().soup(), GetParam().name));
    EXPECT_EQ(GetParam().classic, mesh.isClosedOutward());
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
    for (const osg::Vec4d& light : kSoupLights)
    {
        SilhouetteExtractor extractor;
        SilhouetteEdges silhouette;
        ShadowVolume volume;
        extractor.extract(mesh, light, silhouette);
        extractor.buildVolume(mesh, silhouette, volume);
        EXPECT_TRUE(volumeIsEdgeBalanced(volume));
        for (int i = 0; i < 80; ++i)
        {
            const osg::Vec3d p(coordinate(random), coordinate(random), coordinate(random));
            const double count = windingNumber(volume, p);
            const int crossed = castingFacesBetween(mesh, silhouette.lit, light, p, true);
            const std::string where = "light (" + std::to_string(light.x()) + ", " + std::to_string(light.y()) + ", " +
                                      std::to_string(light.z()) + ", " + std::to_string(light.w()) + ") at (" +
                                      std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
                                      std::to_string(p.z()) + ")";
            EXPECT_GT(count, -1e-6) << where;
            EXPECT_EQ(crossed > 0, count > 0.5) << where << ": count " << count << ", faces crossed " << crossed;
            if (!GetParam().classic) { EXPECT_NEAR(double(crossed), count, 1e-6) << where; }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Soups, SoupCount,
    ::testing::Values(SoupCase{"three_faces_on_an_edge", souptest::threeFacesOnAnEdge, false},
                      SoupCase{"back_to_back_quads", souptest::backToBackQuads, false},
                      SoupCase{"box_with_a_flipped_face", souptest::boxWithAFlippedFace, false},
                      SoupCase{"open_box", [] { return souptest::box({-1, -1, -1}, {1, 1, 1}, 1); }, false},
                      SoupCase{"t_junction", souptest::tJunction, false},
                      SoupCase{"two_touching_boxes", souptest::twoTouchingBoxes, false},
                      SoupCase{"inward_box", [] { return souptest::flipped(souptest::box({-1, -1, -1}, {1, 1, 1})); }, false},
                      SoupCase{"room_with_a_box", souptest::roomWithABox, false}),
    [](const ::testing::TestParamInfo<SoupCase>& info) { return std::string(info.param.name); });
