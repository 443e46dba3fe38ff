// What SHADOW_MAP's soft filters take of each light (osgShadowSilhouette/SoftFilter.h): the
// light's size (the technique's, or the light's own user value) and PCSS's penumbra scale,
// against penumbrae derived by hand from similar triangles.
#include "osgShadowSilhouette/SoftFilter.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/Group>
#include <osg/LightSource>
#include <osg/ValueObject>

#include <gtest/gtest.h>

#include <cmath>

using namespace osgShadowSilhouette;
using osgShadowSilhouette::detail::lightSize;
using osgShadowSilhouette::detail::penumbraScale;

namespace {

/** Window depth [0, 1] of a light-eye point (OSG row vectors: clip = eye * projection). */
double windowDepth(const osg::Matrixd& projection, const osg::Vec3d& eye)
{
    const osg::Vec4d clip = osg::Vec4d(eye, 1.0) * projection;
    return 0.5 * clip.z() / clip.w() + 0.5;
}

TEST(PenumbraScale, DirectionalLightHandDerived)
{
    // A sun of angular radius 2 degrees; the map 10 x 5 units, depths 1 to 21 from the light.
    // A blocker edge 10 units above a receiver casts a penumbra of radius 10 tan(2 deg) there.
    LightFrustum f;
    f.valid = true;
    f.projection = osg::Matrixd::ortho(-5.0, 5.0, -2.5, 2.5, 1.0, 21.0);
    const osg::Vec2 scale = penumbraScale(f, LightDescription::DIRECTIONAL, 2.0);
    const double dz = windowDepth(f.projection, {0, 0, -15}) - windowDepth(f.projection, {0, 0, -5});
    const double radius = 10.0 * std::tan(osg::DegreesToRadians(2.0));
    EXPECT_NEAR(scale.x() * dz, radius / 10.0, 1e-6); // texture units: the map is 10 wide
    EXPECT_NEAR(scale.y() * dz, radius / 5.0, 1e-6);  // ... and 5 high
}

TEST(PenumbraScale, SphereLightHandDerived)
{
    // A sphere of radius 0.5 at the centre of a 90-degree perspective map (near 1, far 101).
    // A blocker edge at distance 2, a receiver at 10: the penumbra's radius on the receiver is
    // 0.5 (10 - 2) / 2 = 2 units, and at distance 10 the map's half width is 10 units.
    LightFrustum f;
    f.valid = true;
    f.perspective = true;
    f.projection = osg::Matrixd::perspective(90.0, 1.0, 1.0, 101.0);
    for (LightDescription::Type type : {LightDescription::POINT, LightDescription::SPOT})
    {
        const osg::Vec2 scale = penumbraScale(f, type, 0.5);
        const double dz = windowDepth(f.projection, {0, 0, -10}) - windowDepth(f.projection, {0, 0, -2});
        EXPECT_NEAR(scale.x() * dz, 2.0 / 20.0, 1e-6);
        EXPECT_NEAR(scale.y() * dz, 2.0 / 20.0, 1e-6);
    }
}

TEST(PenumbraScale, NothingToFilter)
{
    LightFrustum f;
    f.projection = osg::Matrixd::ortho(-1, 1, -1, 1, 1, 2);
    EXPECT_EQ(penumbraScale(f, LightDescription::DIRECTIONAL, 2.0), osg::Vec2()); // invalid frustum
    f.valid = true;
    EXPECT_EQ(penumbraScale(f, LightDescription::DIRECTIONAL, 0.0), osg::Vec2());
    EXPECT_GT(penumbraScale(f, LightDescription::DIRECTIONAL, 1.0).x(), 0.0f);
}

TEST(LightSize, TheLightsOwnValueWins)
{
    osg::ref_ptr<osg::Light> light = new osg::Light;
    std::string refusal;
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.25, refusal), 0.25);
    EXPECT_TRUE(refusal.empty());
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 0.5f);
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.25, refusal), 0.5);
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 3.0);
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::DIRECTIONAL, 0.25, refusal), 3.0);
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 2);
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::SPOT, 0.25, refusal), 2.0);
    EXPECT_TRUE(refusal.empty());
}

TEST(LightSize, ALightSourcesValueIsFoundThroughTheScene)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::LightSource> sized = new osg::LightSource, plain = new osg::LightSource;
    sized->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 1.5);
    root->addChild(sized);
    root->addChild(plain);
    osg::ref_ptr<detail::SizedLightSources> sources = detail::findSizedLightSources(*root);
    ASSERT_EQ(sources->sources.size(), 1u);
    std::string refusal;
    EXPECT_DOUBLE_EQ(lightSize(*sized->getLight(), sources.get(), LightDescription::POINT, 0.1, refusal), 1.5);
    EXPECT_DOUBLE_EQ(lightSize(*plain->getLight(), sources.get(), LightDescription::POINT, 0.1, refusal), 0.1);
    // The light's own value before its LightSource's.
    sized->getLight()->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 0.75f);
    EXPECT_DOUBLE_EQ(lightSize(*sized->getLight(), sources.get(), LightDescription::POINT, 0.1, refusal), 0.75);
}

TEST(LightSize, UnusableSizesCastHardShadowsAndSayWhy)
{
    osg::ref_ptr<osg::Light> light = new osg::Light;
    std::string refusal;
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, -1.0);
    EXPECT_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.5, refusal), 0.0);
    EXPECT_NE(refusal.find("-1 is not a finite size"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("ShadowLightSize"), std::string::npos) << refusal;
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, std::nan(""));
    EXPECT_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.5, refusal), 0.0);
    EXPECT_NE(refusal.find("nan"), std::string::npos) << refusal;
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, std::string("large"));
    EXPECT_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.5, refusal), 0.0);
    EXPECT_NE(refusal.find("StringValueObject"), std::string::npos) << refusal;
    // A sun of 45 degrees or more is refused, one of 44 is not; a sphere of 45 units is a sphere.
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 45.0);
    EXPECT_EQ(lightSize(*light, nullptr, LightDescription::DIRECTIONAL, 0.5, refusal), 0.0);
    EXPECT_NE(refusal.find("45 degrees is no directional light's angular radius"), std::string::npos) << refusal;
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::POINT, 0.5, refusal), 45.0);
    EXPECT_TRUE(refusal.empty());
    light->setUserValue(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE, 44.0);
    EXPECT_DOUBLE_EQ(lightSize(*light, nullptr, LightDescription::DIRECTIONAL, 0.5, refusal), 44.0);
    // The technique's own value is checked the same way.
    osg::ref_ptr<osg::Light> plain = new osg::Light;
    EXPECT_EQ(lightSize(*plain, nullptr, LightDescription::DIRECTIONAL, 50.0, refusal), 0.0);
    EXPECT_NE(refusal.find("LightSize 50 degrees"), std::string::npos) << refusal;
}

TEST(FilterReach, CubeFacesReachAsFarAsTheFilterReads)
{
    using T = SilhouetteShadowTechnique;
    EXPECT_EQ(detail::filterReachTexels(T::FILTER_PCF_2X2, 3), 4.0);
    EXPECT_EQ(detail::filterReachTexels(T::FILTER_PCF, 3), 4.0);
    EXPECT_EQ(detail::filterReachTexels(T::FILTER_PCF, 16), 10.0);
    EXPECT_EQ(detail::filterReachTexels(T::FILTER_PCSS, 3), shader::PCSS_MAX_RADIUS_TEXELS + 2.0);
    EXPECT_EQ(detail::filterReachTexels(T::FILTER_SILHOUETTE, 3),
              shader::SILDIST_SAMPLE_REACH + shader::SILDIST_MAX_WIDTH + 2.0);
    // A wider margin widens each face's field of view (at 2048: 50 texels about 2.8 degrees).
    EXPECT_GT(cubeFaceFov(2048, 50.0), cubeFaceFov(2048, 4.0) + 2.0);
}

} // namespace
