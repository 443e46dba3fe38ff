// The side of a surface that the camera sees decides whether it is lit (MEASURE.md), never
// the winding of its triangles: the same scene with every triangle wound the other way
// gives the same shadow mask in every mode, for every light type, and both match the exact
// reference.
#include "GLTestSupport.h"

#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>

#include <algorithm>

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

struct TriangleIndices
{
    std::vector<GLuint>* out = nullptr;
    void operator()(unsigned int a, unsigned int b, unsigned int c) const
    {
        out->insert(out->end(), {a, c, b}); // a, c, b: the other winding
    }
};

/** Rewinds every triangle of every geometry below the node (one GL_TRIANGLES DrawElements
 *  per geometry); positions, normals and colours stay as they are, so the fixed-function
 *  shading, which follows the normals, does not change. */
class ReverseWinding : public osg::NodeVisitor
{
public:
    ReverseWinding() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Geometry& geometry) override
    {
        osg::TriangleIndexFunctor<TriangleIndices> collect;
        osg::ref_ptr<osg::DrawElementsUInt> reversed = new osg::DrawElementsUInt(GL_TRIANGLES);
        std::vector<GLuint> indices;
        collect.out = &indices;
        geometry.accept(collect);
        reversed->assign(indices.begin(), indices.end());
        geometry.removePrimitiveSet(0, geometry.getNumPrimitiveSets());
        geometry.addPrimitiveSet(reversed.get());
        geometry.dirtyGLObjects();
        geometry.dirtyBound();
        ++rewound;
    }

    int rewound = 0;
};

struct WindingCase
{
    const char* name;
    const char* mode;
    unsigned int mapSize;
    const char* method;    ///< HYBRID's method: "lists" or "stencil" ("" for other modes)
    const char* light;     ///< "sun", "point" or "spot"
    double boundPct;       ///< each mask against the exact reference
};

osshar::RenderOptions optionsFor(const WindingCase& c)
{
    osshar::RenderOptions o;
    o.scene = "default";
    osshar::LightArg light;
    if (std::string(c.light) == "sun")
        light.vector = osg::Vec3d(0.45, -0.35, 0.82);
    else
    {
        light.directional = false;
        light.vector = osg::Vec3d(-1.0, -5.0, 7.0);
        if (std::string(c.light) == "spot")
        {
            light.spotDirection = osg::Vec3d(0.2, 0.7, -1.0);
            light.spotCutoff = 50.0;
        }
    }
    o.lights.push_back(light);
    return o;
}

ossref::Mask renderCase(const WindingCase& c, bool rewind, ossref::Comparison& score, ossref::Mask& reference)
{
    ShadowedRender r(optionsFor(c), c.mode, c.mapSize, 512, 384);
    if (!r.valid()) return {};
    if (std::string(c.method) == "stencil") r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_STENCIL_VOLUMES);
    if (std::string(c.method) == "lists") r.technique->setHybridMethod(SilhouetteShadowTechnique::HYBRID_TRIANGLE_LISTS);
    if (rewind)
    {
        ReverseWinding reverse;
        r.scene.content->accept(reverse);
        EXPECT_GT(reverse.rewound, 5);
    }
    const ossref::Mask mask = r.mask();
    reference = r.reference();
    score = ossref::compareMasks(mask, reference);
    EXPECT_TRUE(score.valid) << score.error;
    return mask;
}

class Winding : public ::testing::TestWithParam<WindingCase>
{
};

} // namespace

TEST_P(Winding, DoesNotChangeTheMask)
{
    const WindingCase& c = GetParam();
    ossref::Comparison asModelled, rewound;
    ossref::Mask reference;
    const ossref::Mask a = renderCase(c, false, asModelled, reference);
    const ossref::Mask b = renderCase(c, true, rewound, reference);
    ASSERT_FALSE(a.empty());
    ASSERT_EQ(a.value.size(), b.value.size());
    long long differing = 0, shadowed = 0;
    // Over the pixels the wrong_pct counts: where the exact reference sees geometry (a pixel
    // on an outline that the rasterizer covers and the primary ray misses is no answer).
    ASSERT_EQ(reference.value.size(), a.value.size());
    for (std::size_t i = 0; i < a.value.size(); ++i)
    {
        if (reference.value[i] == ossref::MASK_BACKGROUND) continue;
        differing += a.value[i] != b.value[i];
        shadowed += a.value[i] == 0;
    }
    EXPECT_GT(shadowed, 1000) << "the view must hold shadows for the comparison to mean anything";
    EXPECT_EQ(differing, 0) << c.name << ": pixels whose answer follows the winding";
    EXPECT_LT(asModelled.wrongPct, c.boundPct) << c.name << " as modelled: " << asModelled.wrongPixels << " wrong";
    EXPECT_LT(rewound.wrongPct, c.boundPct) << c.name << " rewound: " << rewound.wrongPixels << " wrong";
    EXPECT_EQ(rewound.coverageMismatch, asModelled.coverageMismatch);
}

INSTANTIATE_TEST_SUITE_P(
    Modes, Winding,
    ::testing::Values(WindingCase{"shadowmap_sun", "shadowmap", 2048, "", "sun", 0.1},
                      WindingCase{"silhouette_sun", "silhouette", 1024, "", "sun", 0.1},
                      WindingCase{"hybrid_lists_sun", "hybrid", 512, "lists", "sun", 0.02},
                      WindingCase{"hybrid_stencil_sun", "hybrid", 512, "stencil", "sun", 0.02},
                      WindingCase{"volume_sun", "volume", 1024, "", "sun", 0.02},
                      WindingCase{"shadowmap_point", "shadowmap", 2048, "", "point", 0.2},
                      WindingCase{"silhouette_point", "silhouette", 1024, "", "point", 0.2},
                      WindingCase{"hybrid_lists_point", "hybrid", 512, "lists", "point", 0.02},
                      WindingCase{"volume_point", "volume", 1024, "", "point", 0.02},
                      WindingCase{"hybrid_lists_spot", "hybrid", 512, "lists", "spot", 0.02},
                      WindingCase{"volume_spot", "volume", 1024, "", "spot", 0.02}),
    [](const ::testing::TestParamInfo<WindingCase>& info) { return std::string(info.param.name); });
