// The adjacency the GPU's volumes are extruded from (GpuVolumes.h): per welded face, its
// corners in the vertex array's indices and, between them, the corner across each edge, or
// the face's own third corner where the edge has no single face across. Counted by hand on
// small meshes.
#include "test_mesh_shapes.h"

#include "osgShadowSilhouette/GpuVolumes.h"

#include <osgShadowSilhouette/MeshCache>

#include <gtest/gtest.h>

using namespace osgShadowSilhouette;
using namespace meshtest;
using osgShadowSilhouette::detail::AdjacencyDrawables;

namespace {

/** The six indices of face @p f. */
std::vector<unsigned int> faceOf(const osg::DrawElementsUInt& indices, std::size_t f)
{
    return std::vector<unsigned int>(indices.begin() + 6 * f, indices.begin() + 6 * f + 6);
}

osg::ref_ptr<osg::DrawElementsUInt> adjacencyOf(const osg::Geometry& g, osg::ref_ptr<const CachedMesh>& mesh)
{
    static osg::ref_ptr<MeshCache> cache = new MeshCache;
    mesh = cache->get(g);
    EXPECT_TRUE(mesh && mesh->getWelding());
    return AdjacencyDrawables::adjacencyIndices(mesh->getAdjacency(), *mesh->getWelding());
}

// Two triangles of a square sharing the diagonal 0-2: across it each names the other's
// third corner; across its borders, its own.
TEST(GpuVolumeAdjacency, ASharedEdgeNamesTheOtherFacesCornerAndABorderItsOwn)
{
    osg::ref_ptr<osg::Geometry> g = makeGeometry({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3});
    osg::ref_ptr<const CachedMesh> mesh;
    osg::ref_ptr<osg::DrawElementsUInt> indices = adjacencyOf(*g, mesh);
    ASSERT_EQ(indices->getMode(), GLenum(GL_TRIANGLES_ADJACENCY));
    ASSERT_EQ(indices->size(), 12u);
    // Each face starts where the mesh starts it: find the corner sequence by rotation.
    std::multiset<std::vector<unsigned int>> faces;
    for (std::size_t f = 0; f < 2; ++f)
    {
        std::vector<unsigned int> face = faceOf(*indices, f);
        while (face[0] != 0) std::rotate(face.begin(), face.begin() + 2, face.end());
        faces.insert(face);
    }
    // face 0 1 2: edge 0-1 border (own third corner 2), 1-2 border (0), 2-0 shared (3)
    // face 0 2 3: edge 0-2 shared (1), 2-3 border (0), 3-0 border (2)
    const std::multiset<std::vector<unsigned int>> expected = {{0, 2, 1, 0, 2, 3}, {0, 1, 2, 0, 3, 2}};
    EXPECT_EQ(faces, expected);
}

// Corners welded from several vertices of the array (a cube with a normal per face: 24
// vertices) name the first of their weld group, and a closed mesh has no border: every
// corner across an edge is off the face.
TEST(GpuVolumeAdjacency, WeldedCornersNameTheFirstVertexOfTheirGroup)
{
    osg::ref_ptr<osg::Geometry> welded = cube();
    const auto* v = static_cast<const osg::Vec3Array*>(welded->getVertexArray());
    const auto* e = static_cast<const osg::DrawElementsUInt*>(welded->getPrimitiveSet(0));
    std::vector<osg::Vec3f> split;
    std::vector<unsigned int> triangles;
    for (unsigned int i : *e) // a vertex per corner: 36 vertices, 8 positions
    {
        triangles.push_back(unsigned(split.size()));
        split.push_back((*v)[i]);
    }
    osg::ref_ptr<osg::Geometry> g = makeGeometry(split, triangles);
    osg::ref_ptr<const CachedMesh> mesh;
    osg::ref_ptr<osg::DrawElementsUInt> indices = adjacencyOf(*g, mesh);
    ASSERT_EQ(indices->size(), 6u * 12u);
    std::map<osg::Vec3f, unsigned int> first; // each position's first vertex in the array
    for (unsigned int i = 0; i < split.size(); ++i) first.emplace(split[i], i);
    for (std::size_t f = 0; f < 12; ++f)
    {
        const std::vector<unsigned int> face = faceOf(*indices, f);
        for (int k = 0; k < 6; ++k)
        {
            ASSERT_LT(face[k], split.size());
            EXPECT_EQ(face[k], first[split[face[k]]]) << "face " << f << " corner " << k;
        }
        for (int k = 0; k < 3; ++k)
        {
            const unsigned int across = face[2 * k + 1], own = face[(2 * k + 4) % 6];
            EXPECT_NE(across, own) << "face " << f << ": a closed cube has no border";
            EXPECT_NE(across, face[2 * k]);
            EXPECT_NE(across, face[(2 * k + 2) % 6]);
        }
    }
}

// Three faces on one edge: OpenMesh keeps two of them joined and the third isolated (its own
// copies of its corners, mapped back to the array's vertices). The isolated face's edges are
// all borders; the two joined faces name each other across the edge.
TEST(GpuVolumeAdjacency, AnEdgeOfThreeFacesIsOpenForTheFaceMadeIsolated)
{
    osg::ref_ptr<osg::Geometry> g = nonManifoldBook();
    osg::ref_ptr<const CachedMesh> mesh;
    osg::ref_ptr<osg::DrawElementsUInt> indices = adjacencyOf(*g, mesh);
    ASSERT_EQ(mesh->getAdjacency().nonManifoldFaces.size(), 1u);
    ASSERT_EQ(indices->size(), 6u * 3u);
    const std::size_t isolated = mesh->getAdjacency().nonManifoldFaces[0];
    const std::size_t vertices = g->getVertexArray()->getNumElements();
    unsigned int openEdges = 0;
    for (std::size_t f = 0; f < 3; ++f)
    {
        const std::vector<unsigned int> face = faceOf(*indices, f);
        for (int k = 0; k < 6; ++k) EXPECT_LT(face[k], vertices) << "an index of the array, not of a copy";
        for (int k = 0; k < 3; ++k)
        {
            const bool open = face[2 * k + 1] == face[(2 * k + 4) % 6];
            openEdges += open;
            if (f == isolated) EXPECT_TRUE(open) << "edge " << k << " of the isolated face";
        }
    }
    EXPECT_EQ(openEdges, 3u + 2u * 2u); // the isolated face's 3, and the joined faces' two borders each
}

// The stand-in draws the source's own arrays, and stays while its arrays and its mesh's
// topology do; a new topology makes a new one.
TEST(GpuVolumeAdjacency, TheStandInSharesTheArraysAndFollowsTheTopology)
{
    osg::ref_ptr<MeshCache> cache = new MeshCache;
    osg::ref_ptr<osg::Geometry> g = cube();
    g->setNormalArray(new osg::Vec3Array(8), osg::Array::BIND_PER_VERTEX);
    Caster caster;
    caster.geometry = g;
    caster.mesh = cache->get(*g);
    osg::ref_ptr<AdjacencyDrawables> drawables = new AdjacencyDrawables;
    osg::Geometry* standIn = drawables->get(caster);
    ASSERT_NE(standIn, nullptr);
    EXPECT_EQ(standIn->getVertexArray(), g->getVertexArray());
    EXPECT_EQ(standIn->getNormalArray(), g->getNormalArray());
    ASSERT_EQ(standIn->getNumPrimitiveSets(), 1u);
    EXPECT_EQ(standIn->getPrimitiveSet(0)->getMode(), GLenum(GL_TRIANGLES_ADJACENCY));
    EXPECT_EQ(standIn->getPrimitiveSet(0)->getNumIndices(), 6u * 12u);
    // Positions alone change: a refresh of the same topology keeps the stand-in.
    static_cast<osg::Vec3Array*>(g->getVertexArray())->at(0) += osg::Vec3f(0.1f, 0, 0);
    g->getVertexArray()->dirty();
    caster.mesh = cache->get(*g);
    EXPECT_EQ(drawables->get(caster), standIn);
    // Two faces fewer: another topology.
    auto* elements = static_cast<osg::DrawElementsUInt*>(g->getPrimitiveSet(0));
    elements->resize(elements->size() - 6);
    elements->dirty();
    caster.mesh = cache->get(*g);
    osg::Geometry* rebuilt = drawables->get(caster);
    ASSERT_NE(rebuilt, nullptr);
    EXPECT_EQ(rebuilt->getPrimitiveSet(0)->getNumIndices(), 6u * 10u);
    EXPECT_EQ(drawables->size(), 1u);
}

} // namespace
