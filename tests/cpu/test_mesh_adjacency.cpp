// osg::Geometry -> welded OpenMesh mesh -> flat adjacency arrays.
#include "test_mesh_shapes.h"
#include "test_soups.h"

#include <osgShadowSilhouette/HalfEdgeMesh>
#include <osgShadowSilhouette/MeshAdjacency>

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

using namespace osgShadowSilhouette;
using namespace meshtest;

namespace {

const std::vector<osg::Vec3f> kCubeCorners = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
                                               { -1, -1, 1 },  { 1, -1, 1 },  { 1, 1, 1 },  { -1, 1, 1 } };
const std::vector<unsigned int> kCubeTriangles = { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 3, 0, 4, 3, 4, 7 };
const std::vector<unsigned int> kCubeQuads = { 0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                               2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7 };

osg::ref_ptr<osg::Geometry> withArrays(osg::Array* vertices, osg::PrimitiveSet* primitives)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setVertexArray(vertices);
    g->addPrimitiveSet(primitives);
    return g;
}

osg::Vec3Array* expand(const std::vector<unsigned int>& indices, float scale = 1.0f)
{
    osg::Vec3Array* v = new osg::Vec3Array;
    for (unsigned int i : indices) v->push_back(kCubeCorners[i] * scale);
    return v;
}

osg::ref_ptr<osg::Geometry> cubeSoup() { return withArrays(expand(kCubeTriangles), new osg::DrawArrays(GL_TRIANGLES, 0, 36)); }
osg::ref_ptr<osg::Geometry> cubeQuads(float scale = 1.0f) { return withArrays(expand(kCubeQuads, scale), new osg::DrawArrays(GL_QUADS, 0, 24)); }

template<class DrawElementsT>
DrawElementsT* elements(std::vector<unsigned int>::const_iterator first,
                        std::vector<unsigned int>::const_iterator last)
{
    DrawElementsT* e = new DrawElementsT(GL_TRIANGLES);
    for (; first != last; ++first) e->push_back(typename DrawElementsT::value_type(*first));
    return e;
}

template<class DrawElementsT>
osg::ref_ptr<osg::Geometry> cubeElements()
{
    return withArrays(new osg::Vec3Array(kCubeCorners.begin(), kCubeCorners.end()),
                      elements<DrawElementsT>(kCubeTriangles.begin(), kCubeTriangles.end()));
}

osg::ref_ptr<osg::Geometry> cubeArrayLengths()
{
    osg::DrawArrayLengths* lengths = new osg::DrawArrayLengths(GL_TRIANGLES, 0);
    lengths->push_back(18);
    lengths->push_back(18);
    return withArrays(expand(kCubeTriangles), lengths);
}

osg::ref_ptr<osg::Geometry> cubeTwoSets()
{
    osg::ref_ptr<osg::Geometry> g = cubeElements<osg::DrawElementsUInt>();
    g->setPrimitiveSet(0, elements<osg::DrawElementsUInt>(kCubeTriangles.begin(), kCubeTriangles.begin() + 18));
    g->addPrimitiveSet(elements<osg::DrawElementsUShort>(kCubeTriangles.begin() + 18, kCubeTriangles.end()));
    return g;
}

osg::ref_ptr<osg::Geometry> cubeWithPointsAndLines()
{
    osg::ref_ptr<osg::Geometry> g = cubeElements<osg::DrawElementsUInt>();
    g->addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, 8));
    g->addPrimitiveSet(new osg::DrawArrays(GL_LINE_LOOP, 0, 8));
    osg::DrawElementsUInt* lines = new osg::DrawElementsUInt(GL_LINES);
    for (unsigned int i : { 0, 6, 1, 7 }) lines->push_back(i);
    g->addPrimitiveSet(lines);
    return g;
}

osg::ref_ptr<osg::Geometry> cubeDouble()
{
    osg::Vec3dArray* v = new osg::Vec3dArray;
    for (const osg::Vec3f& p : kCubeCorners) v->push_back(osg::Vec3d(p));
    return withArrays(v, elements<osg::DrawElementsUInt>(kCubeTriangles.begin(), kCubeTriangles.end()));
}

osg::ref_ptr<osg::Geometry> cubeHomogeneous()
{
    osg::Vec4Array* v = new osg::Vec4Array;
    for (const osg::Vec3f& p : kCubeCorners) v->push_back(osg::Vec4f(p * 2.0f, 2.0f));
    return withArrays(v, elements<osg::DrawElementsUInt>(kCubeTriangles.begin(), kCubeTriangles.end()));
}

osg::ref_ptr<osg::Geometry> planar(GLenum mode, const std::vector<osg::Vec3f>& p)
{
    return withArrays(new osg::Vec3Array(p.begin(), p.end()), new osg::DrawArrays(mode, 0, GLsizei(p.size())));
}

struct PrimitiveCase
{
    const char* name;
    std::function<osg::ref_ptr<osg::Geometry>()> geometry;
    std::size_t faces, vertices, interiorEdges, boundaryEdges;
    bool planarUp; // every face normal is +z
};

// A closed cube: 12 faces, 8 vertices, 18 edges. Strip/fan/polygon/quad-strip: counted by hand.
const std::vector<PrimitiveCase> kPrimitiveCases = {
    { "triangles_draw_arrays", cubeSoup, 12, 8, 18, 0, false },
    { "quads_draw_arrays", [] { return cubeQuads(); }, 12, 8, 18, 0, false },
    { "draw_elements_ubyte", cubeElements<osg::DrawElementsUByte>, 12, 8, 18, 0, false },
    { "draw_elements_ushort", cubeElements<osg::DrawElementsUShort>, 12, 8, 18, 0, false },
    { "draw_elements_uint", cubeElements<osg::DrawElementsUInt>, 12, 8, 18, 0, false },
    { "draw_array_lengths", cubeArrayLengths, 12, 8, 18, 0, false },
    { "two_primitive_sets", cubeTwoSets, 12, 8, 18, 0, false },
    { "points_and_lines_ignored", cubeWithPointsAndLines, 12, 8, 18, 0, false },
    { "vec3d_vertex_array", cubeDouble, 12, 8, 18, 0, false },
    { "vec4_vertex_array", cubeHomogeneous, 12, 8, 18, 0, false },
    // (0,0) (1,0) (0,1) (1,1): triangles 012 and 132, one shared diagonal
    { "triangle_strip", [] { return planar(GL_TRIANGLE_STRIP, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }); }, 2, 4, 1, 4, true },
    // centre + 5 rim points: 4 triangles, 3 inner spokes, 4 rim edges + 2 outer spokes
    { "triangle_fan", [] { return planar(GL_TRIANGLE_FAN, { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { -1, 1, 0 }, { -1, 0, 0 } }); }, 4, 6, 3, 6, true },
    // convex pentagon: 3 triangles, 2 diagonals, 5 sides
    { "polygon", [] { return planar(GL_POLYGON, { { 0, 0, 0 }, { 2, 0, 0 }, { 3, 1, 0 }, { 1, 2, 0 }, { -1, 1, 0 } }); }, 3, 5, 2, 5, true },
    // 2 x 1 rectangle from 6 vertices: 4 triangles, 2 diagonals + 1 rung inside, 6 outside
    { "quad_strip", [] { return planar(GL_QUAD_STRIP, { { 0, 1, 0 }, { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0 }, { 2, 1, 0 }, { 2, 0, 0 } }); }, 4, 6, 3, 6, true },
};

void PrintTo(const PrimitiveCase& c, std::ostream* os) { *os << c.name; }

class PrimitiveModes : public ::testing::TestWithParam<PrimitiveCase> {};

TEST_P(PrimitiveModes, BuildsTheExpectedWeldedMesh)
{
    const PrimitiveCase& c = GetParam();
    MeshAdjacency m = adjacencyOf(*c.geometry());
    EXPECT_EQ(c.faces, m.faces.size());
    EXPECT_EQ(c.vertices, m.positions.size());
    EXPECT_EQ(c.interiorEdges, m.edgeCount());
    EXPECT_EQ(c.boundaryEdges, m.boundaryEdges.size());
    EXPECT_EQ(c.boundaryEdges == 0, m.isClosed());
    EXPECT_TRUE(m.nonManifoldFaces.empty());
    for (const osg::Vec4d& plane : m.planes)
    {
        if (c.planarUp)
        {
            EXPECT_EQ(0.0, plane.x());
            EXPECT_EQ(0.0, plane.y());
            EXPECT_GT(plane.z(), 0.0);
        }
        else // cube faces: axis-aligned, plane at distance 1
        {
            osg::Vec3d n(plane.x(), plane.y(), plane.z());
            EXPECT_NEAR(-n.length(), plane.w(), 1e-12);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Geometry, PrimitiveModes, ::testing::ValuesIn(kPrimitiveCases),
                         [](const ::testing::TestParamInfo<PrimitiveCase>& info) { return info.param.name; });

struct EulerCase
{
    const char* name;
    std::function<osg::ref_ptr<osg::Geometry>()> geometry;
    long long vertices, edges, faces, euler;
};

// sphere 16 x 8: 2 + 7*16 vertices, 2*16 + 6*16*2 faces; torus 24 x 12: 288 v, 576 f
const std::vector<EulerCase> kEulerCases = {
    { "cube", [] { return cube(); }, 8, 18, 12, 2 },
    { "tetrahedron", [] { return tetrahedron(); }, 4, 6, 4, 2 },
    { "sphere", [] { return uvSphere(16, 8); }, 114, 336, 224, 2 },
    { "torus", [] { return torus(24, 12); }, 288, 864, 576, 0 },
};

void PrintTo(const EulerCase& c, std::ostream* os) { *os << c.name; }

class Topology : public ::testing::TestWithParam<EulerCase> {};

TEST_P(Topology, ClosedWithTheExpectedEulerCharacteristic)
{
    const EulerCase& c = GetParam();
    MeshAdjacency m = adjacencyOf(*c.geometry());
    EXPECT_TRUE(m.isClosed());
    EXPECT_EQ(c.vertices, (long long)m.positions.size());
    EXPECT_EQ(c.edges, (long long)m.edgeCount());
    EXPECT_EQ(c.faces, (long long)m.faces.size());
    EXPECT_EQ(c.euler, c.vertices - c.edges + c.faces);
}

bool faceRuns(const MeshTriangle& t, std::uint32_t a, std::uint32_t b)
{
    for (int k = 0; k < 3; ++k)
        if (t.v[k] == a && t.v[(k + 1) % 3] == b) return true;
    return false;
}

TEST_P(Topology, EdgesRecordTheDirectionOfTheirFaces)
{
    MeshAdjacency m = adjacencyOf(*GetParam().geometry());
    for (std::size_t i = 0; i < m.edgeCount(); ++i)
    {
        const InteriorEdge e = m.edge(i);
        EXPECT_TRUE(faceRuns(m.faces[e.face0], e.v0, e.v1));
        EXPECT_TRUE(faceRuns(m.faces[e.face1], e.v1, e.v0));
    }
}

TEST_P(Topology, PlanesContainTheirVerticesAndMatchOpenMeshNormals)
{
    HalfEdgeMesh halfEdge;
    MeshAdjacency m;
    buildMeshAdjacency(*GetParam().geometry(), MeshBuildOptions(), m, &halfEdge);
    ASSERT_EQ(m.faces.size(), halfEdge.n_faces());
    for (std::size_t f = 0; f < m.faces.size(); ++f)
    {
        const osg::Vec4d& plane = m.planes[f];
        for (std::uint32_t v : m.faces[f].v)
            EXPECT_NEAR(0.0, plane * osg::Vec4d(osg::Vec3d(m.positions[v]), 1.0), 1e-6);
        osg::Vec3d n(plane.x(), plane.y(), plane.z());
        n.normalize();
        const auto& normal = halfEdge.normal(HalfEdgeMesh::FaceHandle(int(f)));
        EXPECT_NEAR(1.0, n * osg::Vec3d(normal[0], normal[1], normal[2]), 1e-6);
    }
}

// The planes are computed several faces at a time: each one is still, to the last bit, the
// cross product in double of its float corners and the plane's offset through its first one.
void expectExactPlanes(const MeshAdjacency& m)
{
    ASSERT_EQ(m.planes.size(), m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f)
    {
        const osg::Vec3d a(m.positions[m.faces[f].v[0]]), b(m.positions[m.faces[f].v[1]]),
            c(m.positions[m.faces[f].v[2]]);
        const osg::Vec3d n = (b - a) ^ (c - a);
        EXPECT_EQ(m.planes[f], osg::Vec4d(n, -(n * a))) << "face " << f;
    }
}

TEST_P(Topology, PlanesAreExactCrossProductsOfTheFloatPositions)
{
    expectExactPlanes(adjacencyOf(*GetParam().geometry()));
}

INSTANTIATE_TEST_SUITE_P(Closed, Topology, ::testing::ValuesIn(kEulerCases),
                         [](const ::testing::TestParamInfo<EulerCase>& info) { return info.param.name; });

TEST(Welding, DuplicatedVerticesWeldAtAnyScale)
{
    for (float scale : { 1e-4f, 1.0f, 1e5f })
    {
        MeshAdjacency m = adjacencyOf(*cubeQuads(scale));
        EXPECT_EQ(8u, m.positions.size()) << "scale " << scale;
        EXPECT_TRUE(m.isClosed()) << "scale " << scale;
    }
}

TEST(Welding, ToleranceIsRelativeToTheMeshSize)
{
    // the cube's diagonal is 2 sqrt(3) = 3.46; the default tolerance is 1e-6 of it
    osg::ref_ptr<osg::Geometry> near = cubeQuads();
    osg::ref_ptr<osg::Geometry> far = cubeQuads();
    static_cast<osg::Vec3Array*>(near->getVertexArray())->at(5) += osg::Vec3f(1e-6f, 0, 0);
    static_cast<osg::Vec3Array*>(far->getVertexArray())->at(5) += osg::Vec3f(1e-3f, 0, 0);
    MeshAdjacency welded = adjacencyOf(*near);
    MeshAdjacency cracked = adjacencyOf(*far);
    EXPECT_EQ(8u, welded.positions.size());
    EXPECT_TRUE(welded.isClosed());
    EXPECT_EQ(9u, cracked.positions.size());
    EXPECT_FALSE(cracked.isClosed());
    EXPECT_NEAR(1e-6 * 2.0 * std::sqrt(3.0), welded.report.weldDistance, 1e-9);

    MeshBuildOptions coarse;
    coarse.weldTolerance = 1e-3; // 3.5e-3 absolute: the 1e-3 crack closes
    MeshAdjacency m;
    buildMeshAdjacency(*far, coarse, m);
    EXPECT_EQ(8u, m.positions.size());
    EXPECT_TRUE(m.isClosed());
}

TEST(ZeroArea, CollapsedTrianglesAreDroppedAndCounted)
{
    std::vector<unsigned int> t = kCubeTriangles;
    t.insert(t.end(), { 0, 0, 1, 6, 6, 6 });
    MeshAdjacency m = adjacencyOf(*makeGeometry(kCubeCorners, t));
    EXPECT_EQ(2u, m.report.degenerateTriangles);
    EXPECT_EQ(12u, m.faces.size());
    EXPECT_TRUE(m.isClosed());
}

TEST(ZeroArea, CollinearTriangleIsKeptWithAZeroPlane)
{
    MeshAdjacency m = adjacencyOf(*cubeWithZeroAreaFace());
    EXPECT_EQ(14u, m.faces.size());
    EXPECT_TRUE(m.isClosed());
    std::size_t zeroPlanes = std::count(m.planes.begin(), m.planes.end(), osg::Vec4d(0, 0, 0, 0));
    EXPECT_EQ(1u, zeroPlanes);
}

class CaptureNotify : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        if (severity <= osg::WARN) text += message;
    }
    std::string text;
};

std::string warningsWhileBuilding(const osg::Geometry& g, MeshAdjacency& m)
{
    osg::ref_ptr<CaptureNotify> capture = new CaptureNotify;
    osg::ref_ptr<osg::NotifyHandler> previous = osg::getNotifyHandler();
    osg::setNotifyHandler(capture.get());
    buildMeshAdjacency(g, MeshBuildOptions(), m);
    osg::setNotifyHandler(previous.get());
    return capture->text;
}

TEST(NonFinite, NaNVerticesAreRefusedWithAWarningNamingTheGeometry)
{
    std::vector<osg::Vec3f> p = kCubeCorners;
    p.push_back(osg::Vec3f(std::numeric_limits<float>::quiet_NaN(), 0, 0));
    p.push_back(osg::Vec3f(0, std::numeric_limits<float>::infinity(), 0));
    std::vector<unsigned int> t = kCubeTriangles;
    t.insert(t.end(), { 0, 1, 8, 8, 2, 3, 4, 9, 5 });
    MeshAdjacency m;
    std::string warning = warningsWhileBuilding(*makeGeometry(p, t, "scanned statue"), m);
    EXPECT_NE(std::string::npos, warning.find("\"scanned statue\"")) << warning;
    EXPECT_NE(std::string::npos, warning.find("NaN")) << warning;
    EXPECT_EQ(2u, m.report.nonFiniteVertices);
    EXPECT_EQ(3u, m.report.nonFiniteTriangles);
    EXPECT_EQ(12u, m.faces.size());
    EXPECT_TRUE(m.isClosed());
}

TEST(NonFinite, UnnamedGeometryIsNamedByItsAddress)
{
    std::vector<osg::Vec3f> p = kCubeCorners;
    p[3].z() = std::numeric_limits<float>::quiet_NaN();
    osg::ref_ptr<osg::Geometry> g = makeGeometry(p, kCubeTriangles);
    MeshAdjacency m;
    std::string warning = warningsWhileBuilding(*g, m);
    std::ostringstream address;
    address << static_cast<const void*>(g.get());
    EXPECT_NE(std::string::npos, warning.find("unnamed osg::Geometry " + address.str())) << warning;
    EXPECT_EQ(1u, m.report.nonFiniteVertices);
    EXPECT_FALSE(m.isClosed()); // the faces around vertex 3 are gone
}

TEST(NonManifold, ThirdFaceOnAnEdgeIsKeptAsAnIsolatedOpenFace)
{
    MeshAdjacency m = adjacencyOf(*nonManifoldBook());
    EXPECT_EQ(1u, m.report.nonManifoldFaces);
    ASSERT_EQ(1u, m.nonManifoldFaces.size());
    EXPECT_EQ(3u, m.faces.size());
    EXPECT_FALSE(m.isClosed());
    EXPECT_EQ(1u, m.edgeCount());          // the rhombus diagonal A-B
    EXPECT_EQ(7u, m.boundaryEdges.size());  // rhombus 4 + fin 3
    // the fin has vertices of its own, at the positions of A, B and C3
    const std::uint32_t finIndex = m.nonManifoldFaces[0];
    const MeshTriangle& fin = m.faces[finIndex];
    std::set<std::pair<float, float>> yz;
    for (std::uint32_t v : fin.v)
    {
        yz.insert({ m.positions[v].y(), m.positions[v].z() });
        EXPECT_EQ(0.0f, m.positions[v].x());
        for (std::size_t f = 0; f < m.faces.size(); ++f)
        {
            if (f != finIndex)
            {
                EXPECT_EQ(std::end(m.faces[f].v), std::find(std::begin(m.faces[f].v), std::end(m.faces[f].v), v));
            }
        }
    }
    std::set<std::pair<float, float>> expected = { { -1.0f, 0.0f }, { 1.0f, 0.0f }, { 0.0f, 1.0f } };
    EXPECT_EQ(expected, yz);
}

TEST(BadInput, OutOfRangeIndicesAndMissingVerticesAreHarmless)
{
    std::vector<unsigned int> t = kCubeTriangles;
    t.insert(t.end(), { 0, 1, 99 });
    MeshAdjacency m = adjacencyOf(*makeGeometry(kCubeCorners, t));
    EXPECT_EQ(1u, m.report.outOfRangeTriangles);
    EXPECT_EQ(12u, m.faces.size());

    osg::ref_ptr<osg::Geometry> empty = new osg::Geometry;
    empty->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    MeshAdjacency none = adjacencyOf(*empty);
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(none.isClosed());
}

// Planes and the parts' volumes are computed several faces at a time along runs of faces of
// one part: runs starting and ending anywhere give the face-by-face results.
TEST(MeshAdjacency, PlanesAndPartsOfRunsAtAnyOffset)
{
    using namespace souptest;
    const std::vector<Triangle> a = box({-2, -2, -2}, {-1, -1, -1});
    const std::vector<Triangle> b = flipped(box({1, 1, 1}, {2, 2, 2}));
    std::vector<Triangle> soup(a.begin() + 2, a.end()); // runs of 10, 12 and 2 faces
    soup.insert(soup.end(), b.begin(), b.end());
    soup.insert(soup.end(), a.begin(), a.begin() + 2);
    const MeshAdjacency m = adjacencyOf(*soupGeometry(soup, "runs"));
    EXPECT_TRUE(m.isClosed());
    EXPECT_EQ(1u, m.inwardParts);
    expectExactPlanes(m);
    const MeshAdjacency open = adjacencyOf(*soupGeometry(box({-1, -1, -1}, {1, 1, 1}, 1), "open"));
    EXPECT_EQ(10u, open.faces.size());
    expectExactPlanes(open);
}

// A closed part wound inward (a room seen from within) must not cast with the classic rule.
TEST(MeshAdjacency, CountsClosedPartsWoundInward)
{
    using namespace souptest;
    MeshAdjacency outward = adjacencyOf(*soupGeometry(box({-1, -1, -1}, {1, 1, 1}), "box"));
    EXPECT_TRUE(outward.isClosed());
    EXPECT_EQ(0u, outward.inwardParts);
    EXPECT_TRUE(outward.isClosedOutward());

    MeshAdjacency room = adjacencyOf(*soupGeometry(flipped(box({-1, -1, -1}, {1, 1, 1})), "room"));
    EXPECT_TRUE(room.isClosed());
    EXPECT_EQ(1u, room.inwardParts);
    EXPECT_FALSE(room.isClosedOutward());

    // an outward box inside the room, apart from its walls: two parts, one inward
    MeshAdjacency both = adjacencyOf(*soupGeometry(
        joined(flipped(box({-2, -2, -2}, {2, 2, 2})), box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f})), "both"));
    EXPECT_TRUE(both.isClosed());
    EXPECT_EQ(1u, both.inwardParts);

    MeshAdjacency open = adjacencyOf(*soupGeometry(flipped(box({-1, -1, -1}, {1, 1, 1}, 1)), "open"));
    EXPECT_FALSE(open.isClosed());
    EXPECT_EQ(0u, open.inwardParts); // counted only for closed meshes
}

}
