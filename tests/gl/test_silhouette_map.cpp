// The silhouette-map mode on the GPU.
//  - SilhouetteMapPass renders the edges of a known caster into a small silhouette map; the
//    map is read back and compared texel by texel with pickSilhouettePoint() (the C++ twin of
//    oss_silmap.frag.glsl), including the occlusion kill against a known depth map.
//  - The whole mode is scored against the exact reference (MEASURE.md).
#include "Offscreen.h"
#include "Setup.h"

#include <osgShadowSilhouette/CasterEdges>
#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteMapPass>
#include <osgShadowSilhouette/SilhouettePoints>

#include <osg/Geode>
#include <osgDB/WriteFile>
#include <osgUtil/CullVisitor>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>

using namespace osgShadowSilhouette;

namespace {

constexpr unsigned int N = 32;          // map size
constexpr float OCCLUDER_DEPTH = 0.1f;  // depth samples with x < OCCLUDER_END lie in front
constexpr int OCCLUDER_END = 12;
constexpr double STORED_PRECISION = 0.5 / SILHOUETTE_POINT_STEPS + 1e-6; // rounding to 1/2048

/** Culls a SilhouetteMapPass the way the technique does, from inside the cull traversal. */
class PassNode : public osg::Node
{
public:
    PassNode(SilhouetteMapPass* pass, const LightFrustum& frustum, osg::Texture2D* depth,
             const std::vector<Caster>& casters, const osg::Vec4d& light)
        : _pass(pass), _frustum(frustum), _depth(depth), _casters(casters), _light(light)
    {
        setCullingActive(false);
    }
    void traverse(osg::NodeVisitor& nv) override
    {
        if (osgUtil::CullVisitor* cv = nv.asCullVisitor()) _pass->cull(*cv, _frustum, _depth.get(), _casters, _light);
    }

private:
    osg::ref_ptr<SilhouetteMapPass> _pass;
    LightFrustum _frustum;
    osg::ref_ptr<osg::Texture2D> _depth;
    std::vector<Caster> _casters;
    osg::Vec4d _light;
};

/** Depth map: samples with x < OCCLUDER_END at OCCLUDER_DEPTH, the rest at the far plane. */
osg::ref_ptr<osg::Texture2D> makeDepthMap(std::vector<float>& depths)
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(N, N, 1, GL_DEPTH_COMPONENT, GL_FLOAT);
    depths.resize(N * N);
    for (unsigned int j = 0; j < N; ++j)
        for (unsigned int i = 0; i < N; ++i) depths[j * N + i] = int(i) < OCCLUDER_END ? OCCLUDER_DEPTH : 1.0f;
    std::memcpy(image->data(), depths.data(), depths.size() * sizeof(float));
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D(image.get());
    t->setInternalFormat(GL_DEPTH_COMPONENT24);
    t->setShadowComparison(false); // the pass reads raw depths
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    t->setBorderColor(osg::Vec4d(1, 1, 1, 1));
    return t;
}

/** An open polygon (a fan of triangles) in the plane z = 0, in depth-texel units. */
osg::ref_ptr<osg::Geometry> makePolygon()
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const osg::Vec2d& p : {osg::Vec2d(3.3, 4.1), osg::Vec2d(20.7, 2.9), osg::Vec2d(27.2, 17.6),
                                osg::Vec2d(14.45, 28.3), osg::Vec2d(5.1, 19.05), osg::Vec2d(9.37, 11.21)})
        v->push_back(osg::Vec3(p.x(), p.y(), 0.0f));
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_POLYGON, 0, v->size()));
    return g;
}

/** Looks straight down -z: light view x, y = world x, y; the ortho box maps [0, N] to the map. */
LightFrustum topDownFrustum()
{
    LightFrustum f;
    f.valid = true;
    f.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 10), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    f.projection = osg::Matrixd::ortho(0, N, 0, N, 1, 20);
    return f;
}

/** The map the pass must produce, from the C++ rules: each edge in drawing order overwrites
 *  the texels where it picks a point, unless it lies behind all four depth samples. */
std::vector<osg::Vec2d> expectedMap(const std::vector<osg::Vec3d>& world, const LightFrustum& f,
                                    const std::vector<float>& depths)
{
    std::vector<osg::Vec2d> map(N * N, osg::Vec2d(0.5, 0.5));
    auto sample = [&](int i, int j) { return (i < 0 || j < 0 || i >= int(N) || j >= int(N)) ? 1.0f : depths[j * N + i]; };
    const osg::Matrixd toTexture = f.worldToTexture();
    for (std::size_t e = 0; e + 1 < world.size(); e += 2)
    {
        const osg::Vec3d a = world[e] * toTexture, b = world[e + 1] * toTexture;
        for (unsigned int j = 0; j < N; ++j)
            for (unsigned int i = 0; i < N; ++i)
            {
                const osg::Vec2d origin(i + 0.5, j + 0.5); // texel (i, j) in depth-texel units
                const std::optional<SilhouettePoint> p =
                    pickSilhouettePoint(osg::Vec2d(a.x(), a.y()) * N - origin, osg::Vec2d(b.x(), b.y()) * N - origin);
                if (!p) continue;
                const double depth = a.z() + (b.z() - a.z()) * p->t - shader::SILMAP_DEFAULT_DEPTH_BIAS;
                bool occluded = true;
                for (int k = 0; k < 4; ++k) occluded = occluded && depth > sample(i + k % 2, j + k / 2);
                if (!occluded) map[j * N + i] = p->point;
            }
    }
    return map;
}

/** The casters of a group holding one geode with these drawables. */
std::vector<Caster> castersOf(std::initializer_list<osg::ref_ptr<osg::Geometry>> drawables, MeshCache& cache)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (const osg::ref_ptr<osg::Geometry>& g : drawables) geode->addDrawable(g.get());
    osg::ref_ptr<osg::Group> parent = new osg::Group;
    parent->addChild(geode.get());
    return collectCasters(*parent, ~0u, cache); // each Caster keeps its geometry
}

} // namespace

TEST(SilhouetteMapPass, ReadBackMatchesTheCppRules)
{
    osshar::Renderer renderer(64, 64, true);
    ASSERT_TRUE(renderer.valid()) << "GL tests need a display (run them under xvfb-run)";

    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const std::vector<Caster> casters = castersOf({makePolygon()}, *cache);
    ASSERT_EQ(casters.size(), 1u);
    EXPECT_FALSE(casters[0].closed);

    std::vector<float> depths;
    osg::ref_ptr<osg::Texture2D> depthMap = makeDepthMap(depths);
    osg::ref_ptr<SilhouetteMapPass> pass = new SilhouetteMapPass(N, *SilhouetteMapPass::createSharedStateSet(), "test");
    osg::ref_ptr<osg::Image> readBack = new osg::Image;
    readBack->allocateImage(N, N, 1, GL_RED, GL_FLOAT);
    pass->getCamera()->attach(osg::Camera::COLOR_BUFFER, readBack.get());
    const LightFrustum frustum = topDownFrustum();
    const osg::Vec4d light(0, 0, 1, 0);
    renderer.setSceneData(new PassNode(pass.get(), frustum, depthMap.get(), casters, light));
    renderer.renderAndCapture();

    // The polygon is concave at its last vertex, so the fan's last triangle (v0, v4, v5) runs
    // clockwise and faces away: the silhouette is the six boundary edges plus the fold v0-v4.
    ASSERT_EQ(pass->getEdges()->getEdgeCount(), 7u);
    const std::vector<osg::Vec2d> expected = expectedMap(pass->getEdges()->getWorldEndpoints(), frustum, depths);
    const float* texels = reinterpret_cast<const float*>(readBack->data());
    int written = 0, occluded = 0;
    for (unsigned int j = 0; j < N; ++j)
        for (unsigned int i = 0; i < N; ++i)
        {
            const osg::Vec2d& e = expected[j * N + i];
            const osg::Vec2d t = decodeSilhouettePoint(texels[j * N + i]);
            EXPECT_NEAR(t.x(), e.x(), STORED_PRECISION) << "texel " << i << ", " << j;
            EXPECT_NEAR(t.y(), e.y(), STORED_PRECISION) << "texel " << i << ", " << j;
            written += e != osg::Vec2d(0.5, 0.5);
            occluded += int(i) + 1 < OCCLUDER_END;
        }
    // The case must exercise the rules: many texels written, a region the occluder clears.
    EXPECT_GT(written, 40);
    for (unsigned int j = 0; j < N; ++j)
        for (int i = 0; i + 1 < OCCLUDER_END; ++i) EXPECT_EQ(expected[j * N + i], osg::Vec2d(0.5, 0.5));
    EXPECT_GT(occluded, 0);

    // Nothing moved: the second frame reuses the extracted edges.
    renderer.renderAndCapture();
    EXPECT_TRUE(pass->getExtractionSkipped());
    EXPECT_EQ(pass->getEdges()->getExtractionCount(), 1u);
}

namespace {

/** A triangle in z = 0 that reaches past the map's right and bottom sides, beside the polygon
 *  and clear of the occluder. */
osg::ref_ptr<osg::Geometry> makeBorderTriangle()
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(24.6f, -2.7f, 0.0f));
    v->push_back(osg::Vec3(35.3f, 6.2f, 0.0f));
    v->push_back(osg::Vec3(29.1f, 12.8f, 0.0f));
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    return g;
}

} // namespace

// The neighbourhood map the eye pass reads: texel k + 1 packs the points of silhouette texel k
// and its four neighbours (default points outside the map), for k from -1 to N - 1. Read back
// and compared with packNeighbourhood() of the map the C++ rules give.
TEST(SilhouetteMapPass, NeighbourhoodMapPacksTheFivePointsOfEveryTexel)
{
    osshar::Renderer renderer(64, 64, true);
    ASSERT_TRUE(renderer.valid()) << "GL tests need a display (run them under xvfb-run)";

    osg::ref_ptr<MeshCache> cache = new MeshCache;
    const std::vector<Caster> casters = castersOf({makePolygon(), makeBorderTriangle()}, *cache);
    ASSERT_EQ(casters.size(), 2u);

    std::vector<float> depths;
    osg::ref_ptr<osg::Texture2D> depthMap = makeDepthMap(depths);
    osg::ref_ptr<SilhouetteMapPass> pass = new SilhouetteMapPass(N, *SilhouetteMapPass::createSharedStateSet(), "test");
    osg::ref_ptr<osg::Image> readBack = new osg::Image;
    readBack->allocateImage(N + 1, N + 1, 1, GL_RGBA_INTEGER_EXT, GL_UNSIGNED_INT);
    readBack->setInternalTextureFormat(GL_RGBA32UI_EXT);
    std::memset(readBack->data(), 0, readBack->getTotalSizeInBytes());
    ASSERT_EQ(pass->getNeighbourhoodTexture()->getTextureWidth(), int(N + 1));
    pass->getNeighbourhoodCamera()->attach(osg::Camera::COLOR_BUFFER, readBack.get());
    const LightFrustum frustum = topDownFrustum();
    renderer.setSceneData(new PassNode(pass.get(), frustum, depthMap.get(), casters, osg::Vec4d(0, 0, 1, 0)));
    renderer.renderAndCapture();

    const std::vector<osg::Vec2d> map = expectedMap(pass->getEdges()->getWorldEndpoints(), frustum, depths);
    auto stored = [&](int i, int j) {
        return (i < 0 || j < 0 || i >= int(N) || j >= int(N)) ? osg::Vec2d(0.5, 0.5) : map[j * N + i];
    };
    const std::uint32_t* texels = reinterpret_cast<const std::uint32_t*>(readBack->data());
    int moved = 0, border = 0;
    for (int j = -1; j < int(N); ++j)
        for (int i = -1; i < int(N); ++i)
        {
            const std::uint32_t* t = texels + 4 * ((j + 1) * (N + 1) + (i + 1));
            const SilhouetteNeighbourhood got = unpackNeighbourhood({t[0], t[1], t[2], t[3]});
            const SilhouetteNeighbourhood want = SilhouetteNeighbourhood::fromStored(
                stored(i, j), stored(i + 1, j), stored(i, j + 1), stored(i - 1, j), stored(i, j - 1));
            const std::pair<const osg::Vec2d*, const osg::Vec2d*> points[5] = {
                {&got.centre, &want.centre}, {&got.east, &want.east}, {&got.north, &want.north},
                {&got.west, &want.west}, {&got.south, &want.south}};
            for (const auto& p : points)
            {
                EXPECT_NEAR(p.first->x(), p.second->x(), STORED_PRECISION) << "texel " << i << ", " << j;
                EXPECT_NEAR(p.first->y(), p.second->y(), STORED_PRECISION) << "texel " << i << ", " << j;
            }
            const bool nonDefault = want.centre != osg::Vec2d(0.5, 0.5) || want.east != osg::Vec2d(1.5, 0.5) ||
                                    want.north != osg::Vec2d(0.5, 1.5) || want.west != osg::Vec2d(-0.5, 0.5) ||
                                    want.south != osg::Vec2d(0.5, -0.5);
            moved += nonDefault;
            border += nonDefault && (i == -1 || j == -1 || i == int(N) - 1 || j == int(N) - 1);
        }
    // The case exercises the packing: many neighbourhoods hold points, some at the map's sides
    // (the triangle crosses the right and bottom ones: texels N - 1 and -1).
    EXPECT_GT(moved, 150);
    EXPECT_GT(border, 3);
}

// ---------------------------------------------------------------------------------------
// Accuracy of the mode against the exact reference, 1024x768.

namespace {

struct ModeScore
{
    double wrongPct = -1.0;
    unsigned int silhouetteEdges = 0;
    double silhouettePixelPct = -1.0; ///< SILHOUETTE_MAP: share of geometry pixels shaded by reconstruction
};

/** Pixels whose RGB differs between two captures of the same size. */
long long differingPixels(const osg::Image& a, const osg::Image& b)
{
    long long n = 0;
    for (int i = 0; i < a.s() * a.t(); ++i) n += std::memcmp(a.data() + 3 * i, b.data() + 3 * i, 3) != 0;
    return n;
}

ModeScore scoreMode(const std::string& sceneName, const std::string& mode, unsigned int mapSize)
{
    osshar::RenderOptions options;
    options.scene = sceneName;
    osshar::PreparedScene scene;
    osg::ref_ptr<osg::Node> root;
    osg::ref_ptr<SilhouetteShadowTechnique> technique;
    std::string error;
    ModeScore score;
    if (!osshar::prepareScene(options, scene, error) ||
        !osshar::makeShadowedRoot(mode, mapSize, scene, root, technique, error))
    {
        ADD_FAILURE() << error;
        return score;
    }
    osshar::Renderer renderer(1024, 768, true);
    if (!renderer.valid())
    {
        ADD_FAILURE() << "GL tests need a display (run them under xvfb-run)";
        return score;
    }
    renderer.setSceneData(root.get());
    renderer.setView(scene.view);
    technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    renderer.timeFrames(1, 1);
    const ossref::Mask mask = ossref::maskFromImage(*renderer.renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1)));
    const ossref::Mask reference = ossref::computeReferenceMask(
        *scene.content, osshar::referenceCamera(scene.view, 1024, 768), osshar::referenceLight(scene.lights.front()));
    const ossref::Comparison c = ossref::compareMasks(mask, reference);
    EXPECT_TRUE(c.valid) << c.error;
    EXPECT_LT(c.coverageMismatch, 50);
    EXPECT_EQ(technique->getStatistics().effectiveMode, technique->getMode());
    score.wrongPct = c.wrongPct;
    score.silhouetteEdges = technique->getStatistics().silhouetteEdges;
    if (technique->getMode() == SilhouetteShadowTechnique::SILHOUETTE_MAP)
    {
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_NONE);
        osg::ref_ptr<osg::Image> plain = renderer.renderAndCapture();
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SILHOUETTE_PIXELS);
        osg::ref_ptr<osg::Image> tinted = renderer.renderAndCapture();
        score.silhouettePixelPct = 100.0 * differingPixels(*plain, *tinted) / double(c.geometryPixels);
        technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SILHOUETTE_MAP);
        osg::ref_ptr<osg::Image> projected = renderer.renderAndCapture();
        if (const char* dir = std::getenv("OSS_BINARY_DIR")) // the debug views, for inspection
        {
            const std::string stem = std::string(dir) + "/silhouette_" + sceneName + "_" + std::to_string(mapSize);
            osgDB::writeImageFile(*tinted, stem + "_pixels.png");
            osgDB::writeImageFile(*projected, stem + "_map.png");
        }
        EXPECT_GT(differingPixels(*plain, *projected), 0);
        std::cout << sceneName << " " << mode << " " << mapSize << ": wrong_pct " << c.wrongPct
                  << " silhouette_pixel_pct " << score.silhouettePixelPct << "\n";
    }
    return score;
}

} // namespace

// Measured (docs/benchmarks.md, "Silhouette map"): default scene at 512, shadowmap about
// 0.075% wrong, silhouette about 0.003%. Bounds leave room for rasterizer differences.
TEST(SilhouetteMapAccuracy, DefaultSceneAt512IsFourTimesBetterThanTheShadowMap)
{
    const ModeScore shadowMap = scoreMode("default", "shadowmap", 512);
    const ModeScore silhouette = scoreMode("default", "silhouette", 512);
    ASSERT_GT(shadowMap.wrongPct, 0.0);
    ASSERT_GE(silhouette.wrongPct, 0.0);
    EXPECT_GT(silhouette.silhouetteEdges, 100u);
    EXPECT_LT(silhouette.wrongPct, 0.02);
    EXPECT_LT(4.0 * silhouette.wrongPct, shadowMap.wrongPct);
    // The reconstruction runs at few pixels (the paper reports about 1%); the tint must show them.
    EXPECT_GT(silhouette.silhouettePixelPct, 0.05);
    EXPECT_LT(silhouette.silhouettePixelPct, 6.0); // measured about 3% at 512
}

// Curved casters (spheres, a torus): the reconstruction follows their outlines.
TEST(SilhouetteMapAccuracy, CurvedCastersAt1024)
{
    const ModeScore shadowMap = scoreMode("spheres", "shadowmap", 1024);
    const ModeScore silhouette = scoreMode("spheres", "silhouette", 1024);
    ASSERT_GT(shadowMap.wrongPct, 0.0);
    ASSERT_GE(silhouette.wrongPct, 0.0);
    EXPECT_LT(silhouette.wrongPct, 0.02);
    EXPECT_LT(2.0 * silhouette.wrongPct, shadowMap.wrongPct);
}
