// The eye pass's configuration is a pure function of the frame's plan (EyePass.h): the
// defines each mode, method and debug view sets, derived by hand from the shaders' #ifdefs,
// and applying them leaves no define of an earlier frame behind.
#include <gtest/gtest.h>

#include "osgShadowSilhouette/EyePass.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <map>
#include <set>

namespace {

using osgShadowSilhouette::SilhouetteShadowTechnique;
using osgShadowSilhouette::detail::applyEyePassDefines;
using osgShadowSilhouette::detail::eyePassDefineNames;
using osgShadowSilhouette::detail::eyePassDefines;
using osgShadowSilhouette::detail::EyePassPlan;
using Defines = std::map<std::string, std::string>;
namespace shader = osgShadowSilhouette::shader;

EyePassPlan plan(SilhouetteShadowTechnique::Mode mode)
{
    EyePassPlan p;
    p.mode = mode;
    p.slotCapacity = 12;
    p.usedSlots = 2;
    return p;
}

} // namespace

TEST(EyePass, ShadowMapSetsItsSlotsAndLightingOnly)
{
    const Defines d = eyePassDefines(plan(SilhouetteShadowTechnique::SHADOW_MAP));
    const Defines expected = {{shader::DEFINE_MAX_SHADOW_SLOTS, "12"},
                              {shader::DEFINE_NUM_SHADOW_SLOTS, "2"},
                              {shader::DEFINE_MAX_LIST_SLOTS, "1"},
                              {shader::DEFINE_PER_PIXEL_LIGHTING, ""}};
    EXPECT_EQ(d, expected);
}

TEST(EyePass, SilhouetteMapAndItsDebugViews)
{
    EyePassPlan p = plan(SilhouetteShadowTechnique::SILHOUETTE_MAP);
    p.perPixelLighting = false;
    Defines d = eyePassDefines(p);
    EXPECT_EQ(d.count(shader::DEFINE_SILHOUETTE_MAP), 1u);
    EXPECT_EQ(d.count(shader::DEFINE_PER_PIXEL_LIGHTING), 0u);
    EXPECT_EQ(d.count(shader::DEFINE_BIAS_BAND), 0u) << "HYBRID only";
    p.debugView = SilhouetteShadowTechnique::DEBUG_SILHOUETTE_PIXELS;
    d = eyePassDefines(p);
    EXPECT_EQ(d.count(shader::DEFINE_DEBUG_SILHOUETTE_PIXELS), 1u);
    EXPECT_EQ(d.count(shader::DEFINE_DEBUG_SILHOUETTE_MAP), 0u);
    // The silhouette debug views belong to SILHOUETTE_MAP: other modes ignore them.
    p.mode = SilhouetteShadowTechnique::SHADOW_MAP;
    d = eyePassDefines(p);
    EXPECT_EQ(d.count(shader::DEFINE_DEBUG_SILHOUETTE_PIXELS), 0u);
    EXPECT_EQ(d.count(shader::DEFINE_SILHOUETTE_MAP), 0u);
}

TEST(EyePass, HybridListsReadAsImagesWithBlockHeadsAndCounting)
{
    EyePassPlan p = plan(SilhouetteShadowTechnique::HYBRID);
    p.triangleLists = true;
    p.listSlots = 3;
    p.listImages = true;
    p.listBlockHeads = true;
    p.countExact = true;
    p.edgeMasks = true;
    const Defines d = eyePassDefines(p);
    EXPECT_EQ(d.at(shader::DEFINE_MAX_LIST_SLOTS), "3");
    for (const char* name : {shader::DEFINE_TRIANGLE_LISTS, shader::DEFINE_LIST_IMAGES, shader::DEFINE_LIST_BLOCK_HEADS,
                             shader::DEFINE_COUNT_EXACT, shader::DEFINE_BIAS_BAND, shader::DEFINE_HYBRID_EDGES})
        EXPECT_EQ(d.count(name), 1u) << name;
    // Block heads come only with the images; without lists none of the list defines.
    p.listImages = false;
    EXPECT_EQ(eyePassDefines(p).count(shader::DEFINE_LIST_BLOCK_HEADS), 0u);
    p.triangleLists = false;
    const Defines stencil = eyePassDefines(p);
    for (const char* name : {shader::DEFINE_TRIANGLE_LISTS, shader::DEFINE_LIST_IMAGES,
                             shader::DEFINE_LIST_BLOCK_HEADS, shader::DEFINE_COUNT_EXACT})
        EXPECT_EQ(stencil.count(name), 0u) << name;
    EXPECT_EQ(stencil.at(shader::DEFINE_MAX_LIST_SLOTS), "1");
    EXPECT_EQ(stencil.count(shader::DEFINE_BIAS_BAND), 1u) << "the stencil method's mask pass reads the band too";
}

TEST(EyePass, CubeFacesAndSkippedSlots)
{
    EyePassPlan p = plan(SilhouetteShadowTechnique::SHADOW_MAP);
    p.cubeFaces = true;
    p.skippedSlots = (1u << 3) | (1u << 5);
    const Defines d = eyePassDefines(p);
    EXPECT_EQ(d.count(shader::DEFINE_CUBE_FACES), 1u);
    EXPECT_EQ(d.at(shader::DEFINE_SKIPPED_SLOTS), "40");
    p.skippedSlots = 0;
    EXPECT_EQ(eyePassDefines(p).count(shader::DEFINE_SKIPPED_SLOTS), 0u) << "no slot left out: no define";
}

TEST(EyePass, EveryDefineAPlanSetsIsOwned)
{
    std::set<std::string> owned(eyePassDefineNames().begin(), eyePassDefineNames().end());
    EXPECT_EQ(owned.size(), eyePassDefineNames().size()) << "a name listed twice";
    EyePassPlan p = plan(SilhouetteShadowTechnique::HYBRID);
    p.triangleLists = p.listImages = p.listBlockHeads = p.countExact = p.edgeMasks = p.cubeFaces = true;
    p.skippedSlots = 1;
    for (SilhouetteShadowTechnique::DebugView view :
         {SilhouetteShadowTechnique::DEBUG_NONE, SilhouetteShadowTechnique::DEBUG_SHADOW_MASK,
          SilhouetteShadowTechnique::DEBUG_CLASSES, SilhouetteShadowTechnique::DEBUG_SILHOUETTE_PIXELS,
          SilhouetteShadowTechnique::DEBUG_SILHOUETTE_MAP, SilhouetteShadowTechnique::DEBUG_VISIBILITY})
        for (SilhouetteShadowTechnique::Mode mode :
             {SilhouetteShadowTechnique::SHADOW_MAP, SilhouetteShadowTechnique::SILHOUETTE_MAP,
              SilhouetteShadowTechnique::HYBRID, SilhouetteShadowTechnique::SHADOW_VOLUME})
            for (SilhouetteShadowTechnique::Filter filter :
                 {SilhouetteShadowTechnique::FILTER_PCF_2X2, SilhouetteShadowTechnique::FILTER_PCF,
                  SilhouetteShadowTechnique::FILTER_PCSS, SilhouetteShadowTechnique::FILTER_SILHOUETTE})
            {
                p.mode = mode;
                p.debugView = view;
                p.filter = filter;
                for (const auto& define : eyePassDefines(p)) EXPECT_EQ(owned.count(define.first), 1u) << define.first;
            }
}

// SHADOW_MAP's soft filters: one define each (the window's N as FILTER_PCF's value), none in
// the other modes, whose eye passes keep their own hard answer.
TEST(EyePass, SoftFiltersInShadowMapOnly)
{
    using T = SilhouetteShadowTechnique;
    struct Case
    {
        T::Mode mode;
        T::Filter filter;
        const char* pcf; ///< FILTER_PCF's value, "" where it is absent
        bool pcss;
    };
    const Case cases[] = {
        {T::SHADOW_MAP, T::FILTER_PCF, "5", false},    {T::SHADOW_MAP, T::FILTER_PCSS, "", true},
        {T::SHADOW_MAP, T::FILTER_PCF_2X2, "", false}, {T::SILHOUETTE_MAP, T::FILTER_PCSS, "", false},
        {T::HYBRID, T::FILTER_PCF, "", false},         {T::SHADOW_VOLUME, T::FILTER_PCSS, "", false},
    };
    for (const Case& c : cases)
    {
        EyePassPlan p = plan(c.mode);
        p.filter = c.filter;
        p.filterWindow = 5;
        const Defines d = eyePassDefines(p);
        const auto pcf = d.find(shader::DEFINE_FILTER_PCF);
        EXPECT_EQ(pcf == d.end() ? std::string() : pcf->second, c.pcf) << T::modeName(c.mode) << " " << c.filter;
        EXPECT_EQ(d.count(shader::DEFINE_FILTER_PCSS), c.pcss ? 1u : 0u) << T::modeName(c.mode) << " " << c.filter;
        EXPECT_EQ(d.count(shader::DEFINE_FILTER_SILHOUETTE), 0u) << T::modeName(c.mode) << " " << c.filter;
    }
}

// FILTER_SILHOUETTE: its define in SILHOUETTE_MAP only, which then reads distances (and its
// DEBUG_SILHOUETTE_MAP overlay shows them, not silhouette points); the other modes keep their
// answer.
TEST(EyePass, SilhouetteFilterInSilhouetteMapOnly)
{
    using T = SilhouetteShadowTechnique;
    for (T::Mode mode : {T::SHADOW_MAP, T::SILHOUETTE_MAP, T::HYBRID, T::SHADOW_VOLUME})
    {
        EyePassPlan p = plan(mode);
        p.filter = T::FILTER_SILHOUETTE;
        p.debugView = T::DEBUG_SILHOUETTE_MAP;
        const Defines d = eyePassDefines(p);
        const bool silhouette = mode == T::SILHOUETTE_MAP;
        EXPECT_EQ(d.count(shader::DEFINE_FILTER_SILHOUETTE), silhouette ? 1u : 0u) << T::modeName(mode);
        EXPECT_EQ(d.count(shader::DEFINE_SILHOUETTE_MAP), silhouette ? 1u : 0u) << T::modeName(mode);
        EXPECT_EQ(d.count(shader::DEFINE_DEBUG_SILHOUETTE_MAP), silhouette ? 1u : 0u) << T::modeName(mode);
        EXPECT_EQ(d.count(shader::DEFINE_FILTER_PCF) + d.count(shader::DEFINE_FILTER_PCSS), 0u) << T::modeName(mode);
    }
    EyePassPlan p = plan(T::SILHOUETTE_MAP);
    p.debugView = T::DEBUG_SILHOUETTE_MAP;
    EXPECT_EQ(eyePassDefines(p).count(shader::DEFINE_DEBUG_SILHOUETTE_MAP), 1u) << "without the filter";
}

// The visibility view is the mask's pass without its threshold.
TEST(EyePass, VisibilityViewIsTheMaskUnthresholded)
{
    for (const bool visibility : {true, false})
    {
        EyePassPlan p = plan(SilhouetteShadowTechnique::SHADOW_MAP);
        p.debugView =
            visibility ? SilhouetteShadowTechnique::DEBUG_VISIBILITY : SilhouetteShadowTechnique::DEBUG_SHADOW_MASK;
        const Defines d = eyePassDefines(p);
        EXPECT_EQ(d.count(shader::DEFINE_DEBUG_MASK) + d.count(shader::DEFINE_DEBUG_VISIBILITY), visibility ? 2u : 1u);
    }
}

// Applying a frame's defines removes what an earlier frame set and keeps what is not the
// eye pass's (the light budget, an application's own define).
TEST(EyePass, ApplyingReplacesTheEarlierFrameAndKeepsOtherDefines)
{
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setDefine(shader::DEFINE_MAX_SHADOW_LIGHTS, "4");
    ss->setDefine("APP_OWN_DEFINE", "7");
    EyePassPlan hybrid = plan(SilhouetteShadowTechnique::HYBRID);
    hybrid.triangleLists = hybrid.listImages = true;
    hybrid.cubeFaces = true;
    applyEyePassDefines(*ss, eyePassDefines(hybrid));
    EXPECT_NE(ss->getDefinePair(shader::DEFINE_TRIANGLE_LISTS), nullptr);
    EXPECT_NE(ss->getDefinePair(shader::DEFINE_CUBE_FACES), nullptr);
    EyePassPlan map = plan(SilhouetteShadowTechnique::SHADOW_MAP);
    map.usedSlots = 1;
    applyEyePassDefines(*ss, eyePassDefines(map));
    for (const char* gone : {shader::DEFINE_TRIANGLE_LISTS, shader::DEFINE_LIST_IMAGES, shader::DEFINE_CUBE_FACES,
                             shader::DEFINE_BIAS_BAND})
        EXPECT_EQ(ss->getDefinePair(gone), nullptr) << gone << " stayed from the earlier frame";
    ASSERT_NE(ss->getDefinePair(shader::DEFINE_NUM_SHADOW_SLOTS), nullptr);
    EXPECT_EQ(ss->getDefinePair(shader::DEFINE_NUM_SHADOW_SLOTS)->first, "1");
    ASSERT_NE(ss->getDefinePair(shader::DEFINE_MAX_SHADOW_LIGHTS), nullptr);
    EXPECT_EQ(ss->getDefinePair(shader::DEFINE_MAX_SHADOW_LIGHTS)->first, "4");
    ASSERT_NE(ss->getDefinePair("APP_OWN_DEFINE"), nullptr);
    EXPECT_EQ(ss->getDefinePair("APP_OWN_DEFINE")->first, "7");
}
