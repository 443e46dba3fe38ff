// Settings that point at nothing say so: LightNum naming no light of the view, DebugLight
// past the view's lights. The warning names the setting and what the view has.
#include "GLTestSupport.h"
#include "NotifyCapture.h"

using osstest::ShadowedRender;
using osstest::SilhouetteShadowTechnique;

namespace {

/** Lights shadowed in the default scene (one light, GL light 0) with LightNum `lightNum`. */
unsigned int shadowedWithLightNum(int lightNum)
{
    ShadowedRender r("default", "shadowmap", 512, 256, 192);
    EXPECT_TRUE(r.valid());
    if (!r.valid()) return 0;
    r.technique->setLightNum(lightNum);
    r.renderer->timeFrames(0, 2);
    return r.technique->getStatistics().lightsShadowed;
}

} // namespace

TEST(SettingWarnings, LightNumNamingNoLight)
{
    osstest::NotifyCapture capture;
    EXPECT_EQ(shadowedWithLightNum(3), 0u);
    EXPECT_TRUE(capture.warned("LightNum 3 names no light (the view's GL lights are 0)")) << capture.warnings();
}

TEST(SettingWarnings, AnExistingLightNumIsQuiet)
{
    osstest::NotifyCapture capture;
    EXPECT_EQ(shadowedWithLightNum(0), 1u);
    EXPECT_FALSE(capture.warned("LightNum")) << capture.warnings();
}

TEST(SettingWarnings, DebugLightPastTheLights)
{
    osstest::NotifyCapture capture;
    ShadowedRender r("default", "hybrid", 512, 256, 192);
    ASSERT_TRUE(r.valid());
    r.technique->setDebugView(SilhouetteShadowTechnique::DEBUG_SHADOW_MASK);
    r.technique->setDebugLight(7);
    r.renderer->timeFrames(0, 2);
    EXPECT_TRUE(capture.warned("DebugLight 7 is not a light of the view (1 found")) << capture.warnings();
}
