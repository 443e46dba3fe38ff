/* osgsilhouette-corpus-probe: loads one model with OSG's own plugins and describes what the
 * shadow techniques will meet in it, as one line of key=value pairs:
 *
 *   status=ok triangles=.. parts=.. open_edges=.. nonmanifold_edges=.. flipped_edges=..
 *   geometries=.. textured=0|1 lights=.. lods=.. switches=.. billboards=..
 *
 * The triangles are the exact reference's (ossref::collectTriangles: world space, the active
 * children, degenerate ones dropped), welded by identical position over the whole model.
 * An edge is open when one triangle uses it, non-manifold when three or more do, flipped
 * when its two triangles run along it in the same direction (inconsistent winding). Parts
 * are the groups of triangles connected through shared vertices.
 *
 * Exit status: 0 loaded with triangles; 2 no plugin reads the extension; 3 the plugin read
 * nothing; 4 loaded but holds no triangle. scripts/corpus.sh runs it in a subprocess with a
 * time limit, so a plugin that crashes or hangs is reported, not fatal.
 */

#include "reference/Reference.h"

#include <osg/Billboard>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/LightSource>
#include <osg/NodeVisitor>
#include <osg/Switch>
#include <osgDB/FileNameUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <array>
#include <cstdio>
#include <map>
#include <numeric>
#include <vector>

namespace {

/** Counts the node kinds that decide what a renderer draws, and textured state. */
class Census : public osg::NodeVisitor
{
public:
    Census() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Node& node) override { look(node); }
    void apply(osg::LOD& node) override { ++lods, look(node); }
    void apply(osg::Switch& node) override { ++switches, look(node); }
    void apply(osg::Billboard& node) override { ++billboards, look(node); }
    void apply(osg::LightSource& node) override { ++lights, look(node); }
    void apply(osg::Geometry& node) override { ++geometries, look(node); }

    int geometries = 0, lights = 0, lods = 0, switches = 0, billboards = 0;
    bool textured = false;

private:
    void look(osg::Node& node)
    {
        if (const osg::StateSet* ss = node.getStateSet())
            for (unsigned int u = 0; u < ss->getTextureAttributeList().size(); ++u)
                textured = textured || ss->getTextureAttribute(u, osg::StateAttribute::TEXTURE);
        traverse(node);
    }
};

struct Topology
{
    long long triangles = 0, parts = 0, openEdges = 0, nonManifoldEdges = 0, flippedEdges = 0;
};

/** Vertex ids of the soup's corners, equal for identical positions. */
std::vector<unsigned int> weld(const ossref::TriangleSoup& soup, unsigned int& vertexCount)
{
    std::map<std::array<double, 3>, unsigned int> ids;
    std::vector<unsigned int> corner(soup.vertices.size());
    for (std::size_t i = 0; i < soup.vertices.size(); ++i)
    {
        const osg::Vec3d& p = soup.vertices[i];
        corner[i] = ids.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, unsigned(ids.size())).first->second;
    }
    vertexCount = unsigned(ids.size());
    return corner;
}

unsigned int findRoot(std::vector<unsigned int>& parent, unsigned int v)
{
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

Topology topology(const ossref::TriangleSoup& soup)
{
    Topology t;
    unsigned int vertexCount = 0;
    const std::vector<unsigned int> corner = weld(soup, vertexCount);
    std::vector<unsigned int> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0u);
    // Per undirected edge: how many triangles use it, and how many run along it low -> high.
    std::map<std::pair<unsigned int, unsigned int>, std::pair<int, int>> edges;
    for (std::size_t f = 0; f < soup.size(); ++f)
        for (int k = 0; k < 3; ++k)
        {
            const unsigned int a = corner[3 * f + k], b = corner[3 * f + (k + 1) % 3];
            parent[findRoot(parent, a)] = findRoot(parent, b);
            auto& use = edges[{std::min(a, b), std::max(a, b)}];
            ++use.first;
            use.second += a < b ? 1 : 0;
        }
    t.triangles = (long long)soup.size();
    for (const auto& e : edges)
    {
        t.openEdges += e.second.first == 1;
        t.nonManifoldEdges += e.second.first > 2;
        t.flippedEdges += e.second.first == 2 && e.second.second != 1;
    }
    std::vector<char> isRoot(vertexCount, 0);
    for (unsigned int c : corner) isRoot[findRoot(parent, c)] = 1;
    t.parts = std::count(isRoot.begin(), isRoot.end(), 1);
    return t;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: %s MODEL\n", argv[0]);
        return 1;
    }
    const std::string file = argv[1];
    const std::string ext = osgDB::getLowerCaseFileExtension(file);
    if (!osgDB::Registry::instance()->getReaderWriterForExtension(ext))
    {
        std::printf("status=no_plugin reason=\"no OSG plugin reads .%s\"\n", ext.c_str());
        return 2;
    }
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(file);
    if (!model)
    {
        std::printf("status=load_failed reason=\"the .%s plugin read nothing\"\n", ext.c_str());
        return 3;
    }
    Census census;
    model->accept(census);
    const Topology t = topology(ossref::collectTriangles(*model));
    std::printf("status=%s triangles=%lld parts=%lld open_edges=%lld nonmanifold_edges=%lld flipped_edges=%lld "
                "geometries=%d textured=%d lights=%d lods=%d switches=%d billboards=%d\n",
                t.triangles > 0 ? "ok" : "no_triangles", t.triangles, t.parts, t.openEdges, t.nonManifoldEdges,
                t.flippedEdges, census.geometries, census.textured ? 1 : 0, census.lights, census.lods,
                census.switches, census.billboards);
    return t.triangles > 0 ? 0 : 4;
}
