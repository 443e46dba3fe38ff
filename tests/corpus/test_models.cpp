// Real-world models (Debian's assimp-testmodels, read by OSG's own plugins) on a ground, as
// scripts/corpus.sh renders them: a directional and a point light at once, every mode, each
// light's mask against the exact reference; and the soft filters (PCSS, FILTER_SILHOUETTE)
// under the directional light with a size, against its exact visibility. The subset is small and diverse: open meshes,
// non-manifold and inconsistently wound ones, textured ones, models of many parts. Measured
// errors that miss a mode's bound today are listed in kKnownFailures with the defect.
#include "GLErrors.h"
#include "gl/StressSupport.h"

#include <osgDB/FileUtils>

#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osstest::ShadowedRender;

namespace {

constexpr int W = 512, H = 384;
const char* const kCorpusDir = "/usr/share/assimp/models";

struct Model
{
    const char* name; ///< the test's name
    const char* path; ///< relative to kCorpusDir
    const char* why;  ///< what it brings to the subset
};

const Model kModels[] = {
    {"SpiderObj", "OBJ/spider.obj", "textured, 18 parts, 72 open edges"},
    {"SpiderStl", "STL/Spider_ascii.stl", "the same spider unindexed: 10 flipped edges (inconsistent winding)"},
    {"Teapots", "Collada/teapots.DAE", "8 parts, 163 open and 59 non-manifold edges, back faces culled"},
    {"MaxExport", "STL/3DSMaxExport.STL", "24 closed parts, 16 non-manifold edges"},
    {"Wuson", "OBJ/WusonOBJ.obj", "51 parts, 412 open edges, 4 flipped edges"},
    {"Duck", "Collada/duck.dae", "textured, closed, one part"},
    {"Test3ds", "3DS/test1.3ds", "textured, 9 parts under transforms"},
    {"SphereWithHole", "STL/sphereWithHole.stl", "a closed sphere with a hole (9 open edges)"},
    {"Regression3429812", "OBJ/regr_3429812.obj", "4 triangles: a non-manifold edge, every edge flipped"},
    {"Hierarchy", "LWO/LWO2/hierarchy.lwo", "4 parts in a hierarchy of layers"},
    {"Transparency", "LWO/LWO2/transparency.lwo", "2 blended parts (the transparent bin)"},
    {"ConcavePolygon", "Collada/ConcavePolygon.dae",
     "one concave polygon: a fan whose triangles overlap with opposite windings, back faces culled"},
};

struct Mode
{
    const char* name;
    unsigned int mapSize;
    double boundPct; ///< wrong_pct bound of every light
};

// The map modes' bounds: the largest error measured over the subset outside the known
// failures (shadowmap 0.228%, silhouette 0.067%) with a margin of a third or so.
const Mode kModes[] = {
    {"shadowmap", 2048, 0.3},
    {"silhouette", 2048, 0.1},
    {"hybrid", 1024, 0.01},
    {"volume", 2048, 0.01},
};

/** Cases whose wrong_pct misses their mode's bound today (512 x 384, measured on llvmpipe):
 *  model/mode/light -> the measured error and the defect behind it. */
const std::map<std::string, std::string> kKnownFailures = {};

/** Models whose mask and reference disagree on coverage in a few pixels, in every mode and
 *  for both lights: the measured count (asserted as a ceiling) and where they are. */
const std::map<std::string, std::pair<long long, std::string>> kKnownCoverage = {
    {"MaxExport", {2, "two pixel centres on the silhouette of the raised arm"}},
    {"Test3ds", {1, "one pixel centre on the ground's far edge"}},
};

/** Models whose shaded image holds NaN or Inf in every mode: the defect. */
const std::map<std::string, std::string> kKnownNonFinite = {
};

std::string caseKey(const std::string& model, const std::string& mode, unsigned int light)
{
    return model + "/" + mode + "/" + (light == 0 ? "directional" : "point");
}

osshar::RenderOptions corpusOptions(const Model& model)
{
    osshar::RenderOptions o;
    o.file = std::string(kCorpusDir) + "/" + model.path;
    o.ground = true;
    osshar::LightArg directional, point;
    directional.vector = osg::Vec3d(0.5, -0.6, 0.6);
    point.directional = false;
    point.vector = osg::Vec3d(-3.0, -4.0, 9.0);
    o.lights = {directional, point};
    return o;
}

/** The reference masks of a model's two lights, ray cast once for all modes. */
const ossref::Mask& reference(const Model& model, ShadowedRender& r, unsigned int light)
{
    static std::map<std::string, ossref::Mask> cache;
    const std::string key = std::string(model.path) + "#" + std::to_string(light);
    auto found = cache.find(key);
    if (found == cache.end()) found = cache.emplace(key, r.reference(light)).first;
    return found->second;
}

/** Why a model cannot be tested (its file is missing), or empty. */
std::string missingModel(const Model& model)
{
    const std::string path = std::string(kCorpusDir) + "/" + model.path;
    return osgDB::fileExists(path) ? std::string()
                                   : path + " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh)";
}

/** The GL error counter, at 0. */
osshar::GLErrorCounter& resetGLErrors()
{
    osshar::GLErrorCounter& glErrors = osshar::installGLErrorCounter();
    glErrors.reset();
    return glErrors;
}

void PrintTo(const Model& model, std::ostream* os) { *os << model.path; }
void PrintTo(const Mode& mode, std::ostream* os) { *os << mode.name << " " << mode.mapSize; }

using Case = std::tuple<Model, Mode>;

class CorpusModel : public testing::TestWithParam<Case>
{
};

TEST_P(CorpusModel, MatchesTheReference)
{
    const Model& model = std::get<0>(GetParam());
    const Mode& mode = std::get<1>(GetParam());
    const std::string missing = missingModel(model);
    if (!missing.empty()) GTEST_SKIP() << missing;
    osshar::GLErrorCounter& glErrors = resetGLErrors();
    ShadowedRender r(corpusOptions(model), mode.name, mode.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    ASSERT_GE(r.scene.lights.size(), 2u);
    const ossref::Mask masks[2] = {r.mask(0), r.mask(1)};
    std::string known;
    for (unsigned int light = 0; light < 2; ++light)
    {
        SCOPED_TRACE(caseKey(model.name, mode.name, light));
        const ossref::Mask& mask = masks[light];
        const ossref::Mask& ref = reference(model, r, light);
        const ossref::Comparison c = ossref::compareMasks(mask, ref);
        ASSERT_TRUE(c.valid) << c.error;
        EXPECT_GT(c.geometryPixels, W * H / 4) << "the model and its ground should fill the view";
        const auto coverage = kKnownCoverage.find(model.name);
        if (coverage == kKnownCoverage.end())
            EXPECT_EQ(c.coverageMismatch, 0) << "the mask and the reference disagree on where geometry is";
        else
            EXPECT_LE(c.coverageMismatch, coverage->second.first) << coverage->second.second;
        std::printf("corpus %s wrong_pct=%.4f coverage_mismatch=%lld\n", caseKey(model.name, mode.name, light).c_str(),
                    c.wrongPct, c.coverageMismatch);
        const auto failure = kKnownFailures.find(caseKey(model.name, mode.name, light));
        if (failure != kKnownFailures.end())
            known += "; " + failure->first + ": " + failure->second + " (measured now " + std::to_string(c.wrongPct) + "%)";
        else
            EXPECT_LE(c.wrongPct, mode.boundPct) << "wrong pixels in % of " << c.geometryPixels;
    }
    // After the masks: the float frames leave the camera drawing into a new target.
    const auto nonFinite = kKnownNonFinite.find(model.name);
    r.technique->setDebugLight(0);
    if (nonFinite == kKnownNonFinite.end())
        osstest::expectFiniteImage(r, masks[0], reference(model, r, 0));
    else
        known += std::string("; ") + model.name + ": " + nonFinite->second;
    EXPECT_EQ(glErrors.count(), 0) << "OpenGL errors while rendering";
    if (!known.empty()) GTEST_SKIP() << "known failure" << known.substr(1);
}

std::string caseName(const testing::TestParamInfo<Case>& info)
{
    return std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param).name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusModel, testing::Combine(testing::ValuesIn(kModels), testing::ValuesIn(kModes)),
                         caseName);

// The shadow geometry found on the GPU (GpuExtraction GPU_EXTRACTION_ALL_CASTERS: every
// caster's, from its welded faces drawn with adjacency): SILHOUETTE_MAP's silhouette edges
// (GpuEdges.h), HYBRID's edge masks and SHADOW_VOLUME's volumes (GpuVolumes.h), against the
// CPU's on the same models, in one technique: the masks agree pixel for pixel but for a few
// outline pixels, and both meet the mode's bound where the CPU's does.
class GpuExtractionOnCorpus : public testing::TestWithParam<std::tuple<Model, Mode>>
{
};

/** Cases (model/mode) where the GPU's geometry misses the mode's bound or differs from the
 *  CPU's in more than kGpuCpuDiffer pixels: the measured numbers and why. */
const std::map<std::string, std::string> kKnownGpuDifferences = {
    {"SpiderStl/silhouette",
     "0.0689% against the CPU's 0.0613% under the sun, 86 pixels differing (4 under the point light), both "
     "within SILHOUETTE_MAP's bound: a dense caster whose edges cross texels by the several, where the last edge "
     "drawn keeps its point and the GPU draws them in another order than the CPU; not proven to be all of it"},
};

/** Pixels of a light's mask where the GPU's and the CPU's geometry may disagree: volumes and
 *  HYBRID's edge masks (measured up to 1; 16 on Teapots under the point light while the GPU's
 *  caps seen from a culled side lay two depth steps back instead of four), and
 *  SILHOUETTE_MAP's maps, whose texels keep the point of the last edge drawn across them, in
 *  another order on the GPU (measured up to 27: SpiderObj, point light). */
constexpr long long kGpuCpuDiffer = 20, kGpuCpuDifferSilhouette = 30;

TEST_P(GpuExtractionOnCorpus, MatchesTheCpuAndTheReference)
{
    const Model& model = std::get<0>(GetParam());
    const Mode& mode = std::get<1>(GetParam());
    const std::string missing = missingModel(model);
    if (!missing.empty()) GTEST_SKIP() << missing;
    osshar::GLErrorCounter& glErrors = resetGLErrors();
    ShadowedRender r(corpusOptions(model), mode.name, mode.mapSize, W, H);
    ASSERT_TRUE(r.valid());
    ASSERT_GE(r.scene.lights.size(), 2u);
    const ossref::Mask cpu[2] = {r.mask(0), r.mask(1)};
    r.technique->setGpuExtraction(SilhouetteShadowTechnique::GPU_EXTRACTION_ALL_CASTERS);
    const ossref::Mask gpu[2] = {r.mask(0), r.mask(1)};
    const auto known = kKnownGpuDifferences.find(std::string(model.name) + "/" + mode.name);
    for (unsigned int light = 0; light < 2; ++light)
    {
        SCOPED_TRACE(caseKey(model.name, std::string(mode.name) + "_gpu", light));
        ASSERT_EQ(gpu[light].value.size(), cpu[light].value.size());
        long long differ = 0;
        for (std::size_t p = 0; p < gpu[light].value.size(); ++p) differ += gpu[light].value[p] != cpu[light].value[p];
        const ossref::Comparison c = ossref::compareMasks(gpu[light], reference(model, r, light));
        const ossref::Comparison onCpu = ossref::compareMasks(cpu[light], reference(model, r, light));
        ASSERT_TRUE(c.valid && onCpu.valid) << c.error << onCpu.error;
        std::printf("corpus %s gpu wrong_pct=%.4f cpu wrong_pct=%.4f differing=%lld\n",
                    caseKey(model.name, mode.name, light).c_str(), c.wrongPct, onCpu.wrongPct, differ);
        if (known != kKnownGpuDifferences.end()) continue;
        EXPECT_LE(differ, std::string(mode.name) == "silhouette" ? kGpuCpuDifferSilhouette : kGpuCpuDiffer)
            << "mask pixels where the GPU's geometry and the CPU's disagree";
        // Where the CPU's geometry meets the bound, so does the GPU's.
        if (onCpu.wrongPct <= mode.boundPct)
        {
            EXPECT_LE(c.wrongPct, mode.boundPct) << "wrong pixels in % of " << c.geometryPixels;
        }
    }
    EXPECT_EQ(glErrors.count(), 0) << "OpenGL errors while rendering";
    if (known != kKnownGpuDifferences.end()) GTEST_SKIP() << "known difference: " << known->second;
}

INSTANTIATE_TEST_SUITE_P(Corpus, GpuExtractionOnCorpus,
                         testing::Combine(testing::ValuesIn(kModels), testing::ValuesIn(kModes + 1, std::end(kModes))),
                         caseName);

// The soft filters on the same models: the directional light alone, of angular radius 2
// degrees, each filter's visibility against the exact visibility (MEASURE.md, "Soft
// shadows"), beside its mode's hard answer.
struct SoftFilter
{
    const char* name;
    const char* mode;
    SilhouetteShadowTechnique::Filter filter;
    double penumbraBound; ///< vis_mae_penumbra bound of every model
};

constexpr double kSoftSize = 2.0; // degrees

// The bounds: the largest vis_mae_penumbra measured over the subset with a margin of a fifth
// or so (PCSS 0.077 on Teapots; FILTER_SILHOUETTE 0.060 on Hierarchy, 0.015-0.060 elsewhere,
// where one sample across the nearest edge measured up to 0.120 and failed four models).
// Each filter also stays below half of its mode's hard answer (0.20-0.28).
const SoftFilter kSoftFilters[] = {
    {"pcss", "shadowmap", SilhouetteShadowTechnique::FILTER_PCSS, 0.09},
    {"silhouette", "silhouette", SilhouetteShadowTechnique::FILTER_SILHOUETTE, 0.075},
};

/** The exact visibility of a model's directional light at kSoftSize, ray cast once. */
const ossref::VisibilityMask& referenceVisibility(const Model& model, ShadowedRender& r)
{
    static std::map<std::string, ossref::VisibilityMask> cache;
    auto found = cache.find(model.path);
    if (found == cache.end()) found = cache.emplace(model.path, r.referenceVisibility(0, kSoftSize)).first;
    return found->second;
}

void PrintTo(const SoftFilter& filter, std::ostream* os)
{
    *os << filter.name;
}

using SoftCase = std::tuple<Model, SoftFilter>;

class CorpusSoftModel : public testing::TestWithParam<SoftCase>
{
};

TEST_P(CorpusSoftModel, FollowsTheExactPenumbra)
{
    const Model& model = std::get<0>(GetParam());
    const SoftFilter& filter = std::get<1>(GetParam());
    const std::string missing = missingModel(model);
    if (!missing.empty()) GTEST_SKIP() << missing;
    osshar::GLErrorCounter& glErrors = resetGLErrors();
    osshar::RenderOptions options = corpusOptions(model);
    options.lights.resize(1); // the directional light
    ShadowedRender r(options, filter.mode, 2048, W, H);
    ASSERT_TRUE(r.valid());
    const ossref::VisibilityMask& reference = referenceVisibility(model, r);
    r.technique->setLightSize(float(kSoftSize));
    const ossref::VisibilityComparison hard = ossref::compareVisibility(reference, r.visibility());
    r.technique->setFilter(filter.filter);
    const ossref::VisibilityComparison soft = ossref::compareVisibility(reference, r.visibility());
    ASSERT_TRUE(hard.valid && soft.valid) << hard.error << soft.error;
    std::printf("corpus soft %s/%s penumbra_pixels=%lld vis_mae_penumbra hard=%.4f filtered=%.4f vis_mae=%.5f "
                "hard_wrong_pct=%.4f\n",
                model.name, filter.name, soft.penumbraPixels, hard.visMaePenumbra, soft.visMaePenumbra, soft.visMae,
                soft.hardWrongPct);
    EXPECT_GT(soft.penumbraPixels, 200) << "the light's size should make penumbrae to score";
    EXPECT_LE(soft.visMaePenumbra, filter.penumbraBound);
    EXPECT_LT(soft.visMaePenumbra, 0.5 * hard.visMaePenumbra);
    r.technique->setDebugLight(0);
    osstest::expectFiniteImage(r, r.mask(0), r.reference(0));
    EXPECT_EQ(glErrors.count(), 0) << "OpenGL errors while rendering";
}

std::string softCaseName(const testing::TestParamInfo<SoftCase>& info)
{
    return std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param).name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusSoftModel,
                         testing::Combine(testing::ValuesIn(kModels), testing::ValuesIn(kSoftFilters)), softCaseName);

} // namespace
