// Scores beside wrong_pct (docs/outdoor.md): wrong_pct per band of eye distance of the
// reference's visible point, and flicker_pct between consecutive frames.
//
// The bands are checked on the scene of test_reference_scenes.h's top camera seen from
// nearer: eye (0, 0, 10) looking straight down, tan(fovy/2) = 1.5, 300 x 300 pixels of
// 0.1 x 0.1 at z = 0; pixel (i, j) (GL window coordinates) looks at the ground point
// (-15 + 0.1 (i + 0.5), -15 + 0.1 (j + 0.5)). The occluder quad [-1, 1]^2 at z = 4 is 6 from
// the eye and covers the pixels whose centres lie within 10 / 6 of the axis: 34 x 34 = 1156
// of them, the same that it hides of the ground [-10, 10]^2 (40000 pixels). A ground point
// at radius r from the axis lies sqrt(100 + r^2) from the eye: 13 is reached at r^2 = 69,
// between pixel centres (their r^2 are multiples of 0.0025 * 8 plus 0.005: 68.985, 69.005).
#include "reference/Reference.h"
#include "test_reference_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace {

using ossref::BandScore;
using ossref::FlickerCount;
using ossref::Mask;
using namespace reftest;

/** The ground pixels (pixel centres in [-10, 10]^2, outside the quad's 34 x 34) whose
 *  centre lies within radius^2 < r2 of the axis. */
long long groundCentresWithin(double r2)
{
    long long n = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
        {
            const double x = -15.0 + 0.1 * (i + 0.5), y = -15.0 + 0.1 * (j + 0.5);
            const bool ground = std::fabs(x) < 10.0 && std::fabs(y) < 10.0;
            const bool underQuad = std::fabs(x) < 10.0 / 6.0 && std::fabs(y) < 10.0 / 6.0;
            if (ground && !underQuad && x * x + y * y < r2) ++n;
        }
    return n;
}

Camera nearCamera()
{
    Camera c = topCamera();
    c.eye = osg::Vec3d(0.0, 0.0, 10.0);
    c.fovyDeg = osg::RadiansToDegrees(2.0 * std::atan(1.5));
    return c;
}

Mask nearReference()
{
    return ossref::computeReferenceMask(*groundScene(Occluder::Quad), nearCamera(), directional({0, 0, 1}));
}

/** Index of GL pixel (x, y) in a mask's rows (top first). */
size_t at(int x, int y)
{
    return size_t(kSize - 1 - y) * kSize + size_t(x);
}

TEST(DistanceBands, ReferenceDistancesAreTheEyeToTheVisiblePoint)
{
    const Mask ref = nearReference();
    ASSERT_EQ(ref.distance.size(), ref.value.size());
    // Pixel (150, 150) sees the quad at (0.05, 0.05) * 6 / 10, pixel (0, 150) background,
    // pixel (50, 150) the ground at (-9.95, 0.05).
    EXPECT_NEAR(ref.distance[at(150, 150)], std::sqrt(36.0 + 2 * 0.03 * 0.03), 1e-5);
    EXPECT_TRUE(std::isinf(ref.distance[at(0, 150)]));
    EXPECT_NEAR(ref.distance[at(50, 150)], std::sqrt(100.0 + 9.95 * 9.95 + 0.05 * 0.05), 1e-5);
}

TEST(DistanceBands, PixelsFallIntoTheBandOfTheirReferencePoint)
{
    const Mask ref = nearReference();
    // The test mask: the reference with the quad's 1156 pixels and three ground pixels
    // turned over: (80, 150) at (-6.95, 0.05), r^2 = 48.3 (middle band), (10, 10) at
    // (-13.95, -13.95) (background: not counted) and (55, 55) at (-9.45, -9.45), r^2 = 178.6
    // (far band).
    Mask test = ref;
    for (size_t i = 0; i < test.value.size(); ++i)
        if (ref.distance[i] < 8.0) test.value[i] = 255 - test.value[i];
    for (const auto& [x, y] : {std::pair{80, 150}, std::pair{10, 10}, std::pair{55, 55}})
    {
        uint8_t& v = test.value[at(x, y)];
        if (v != ossref::MASK_BACKGROUND) v = 255 - v;
    }
    const std::vector<BandScore> bands = ossref::compareMasksByDistance(test, ref, {8.0, 13.0});
    ASSERT_EQ(bands.size(), 3u);
    EXPECT_EQ(bands[0].geometryPixels, 1156);
    EXPECT_EQ(bands[0].wrongPixels, 1156);
    EXPECT_DOUBLE_EQ(bands[0].wrongPct, 100.0);
    const long long middle = groundCentresWithin(69.0);
    EXPECT_EQ(bands[1].geometryPixels, middle);
    EXPECT_EQ(bands[1].wrongPixels, 1);
    EXPECT_EQ(bands[2].geometryPixels, 40000 - 1156 - middle);
    EXPECT_EQ(bands[2].wrongPixels, 1);
    EXPECT_EQ(bands[2].to, std::numeric_limits<double>::infinity());
    // The bands add up to the whole comparison.
    const ossref::Comparison c = ossref::compareMasks(test, ref);
    EXPECT_EQ(bands[0].geometryPixels + bands[1].geometryPixels + bands[2].geometryPixels, c.geometryPixels);
    EXPECT_EQ(bands[0].wrongPixels + bands[1].wrongPixels + bands[2].wrongPixels, c.wrongPixels);
}

TEST(DistanceBands, MasksWithoutDistancesHaveNoBands)
{
    const Mask a = Mask::filled(4, 4, ossref::MASK_LIT);
    EXPECT_TRUE(ossref::compareMasksByDistance(a, a, {20.0, 200.0}).empty());
    Mask b = a;
    b.distance.assign(16, 1.0f);
    EXPECT_TRUE(ossref::compareMasksByDistance(Mask::filled(3, 4, ossref::MASK_LIT), b, {20.0}).empty());
    EXPECT_EQ(ossref::compareMasksByDistance(a, b, {20.0, 200.0}).size(), 3u);
}

/** A 1-row mask of the given values (0, 255, 128), grazing where `g` is 'g'. */
Mask row(const std::vector<int>& values, const char* g = "")
{
    Mask m = Mask::filled(int(values.size()), 1);
    for (size_t i = 0; i < values.size(); ++i) m.value[i] = uint8_t(values[i]);
    for (size_t i = 0; g[i]; ++i) m.grazing[i] = g[i] == 'g';
    return m;
}

TEST(Flicker, CountsChangesTheReferenceDoesNotMake)
{
    // Pixel: 0 flickers (mask 255 -> 0, reference lit in both); 1 follows the reference
    // (both 255 -> 0); 2 lags behind it (reference 0 -> 255, mask stays 0); 3 steady;
    // 4 newly covered (mask and reference background before); 5 flickers (0 -> 255);
    // 6 background now; 7 flickers but lies in this frame's grazing band.
    const Mask prevRef = row({255, 255, 0, 0, 128, 0, 255, 255});
    const Mask ref = row({255, 0, 255, 0, 255, 0, 128, 255}, ".......g");
    const Mask prevTest = row({255, 255, 0, 0, 128, 0, 255, 255});
    const Mask test = row({0, 0, 0, 0, 255, 255, 128, 0});
    const FlickerCount f = ossref::countFlicker(prevTest, test, prevRef, ref);
    ASSERT_TRUE(f.valid);
    EXPECT_EQ(f.geometryPixels, 6); // pixels 0-5
    EXPECT_EQ(f.flickerPixels, 2);  // pixels 0 and 5
    EXPECT_DOUBLE_EQ(f.flickerPct, 100.0 * 2 / 6);
}

TEST(Flicker, IdenticalFramesDoNotFlickerAndSizesMustAgree)
{
    const Mask m = row({0, 255, 0, 255});
    const FlickerCount same = ossref::countFlicker(m, m, m, m);
    ASSERT_TRUE(same.valid);
    EXPECT_EQ(same.flickerPixels, 0);
    EXPECT_EQ(same.geometryPixels, 4);
    EXPECT_FALSE(ossref::countFlicker(row({0, 255}), m, m, m).valid);
    EXPECT_FALSE(ossref::countFlicker(m, m, Mask(), m).valid);
}

} // namespace
