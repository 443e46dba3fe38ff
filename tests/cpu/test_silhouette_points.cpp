// Silhouette-map rules: point picking (the four cases) and wedge reconstruction (the six
// combinations). Every expected value is derived by hand in the comment next to it; local
// coordinates are those of osgShadowSilhouette/SilhouettePoints.
#include <osgShadowSilhouette/SilhouettePoints>

#include <gtest/gtest.h>

#include <random>

using namespace osgShadowSilhouette;

namespace {

constexpr double EPS = 1e-12;

struct PickRow
{
    const char* name;
    osg::Vec2d a, b;
    bool picked;
    osg::Vec2d point;
    double t;
    PickCase pickCase;
};

void PrintTo(const PickRow& r, std::ostream* os) { *os << r.name; }

const PickCase END = PickCase::ENDPOINT;
const PickCase ONE = PickCase::ONE_INTERSECTION;
const PickCase TWO = PickCase::TWO_INTERSECTIONS;

const PickRow kPickRows[] = {
    // Case 1: endpoint inside.
    {"endpoint_a_inside", {0.3, 0.4}, {2, 3}, true, {0.3, 0.4}, 0.0, END},
    {"endpoint_b_inside", {-1, -2}, {0.7, 0.2}, true, {0.7, 0.2}, 1.0, END},
    {"both_endpoints_inside_takes_a", {0.2, 0.2}, {0.8, 0.6}, true, {0.2, 0.2}, 0.0, END},
    {"zero_length_inside", {0.3, 0.3}, {0.3, 0.3}, true, {0.3, 0.3}, 0.0, END},
    // endpoints exactly on texel corners belong to the (closed) texel
    {"endpoint_on_corner_NE", {1, 1}, {2, 3}, true, {1, 1}, 0.0, END},
    {"endpoint_on_corner_SW", {-2, -1}, {0, 0}, true, {0, 0}, 1.0, END},
    {"endpoint_on_side", {0.5, 1}, {0.5, 4}, true, {0.5, 1}, 0.0, END},
    // Case 2: one crossing. x - y = 0.8 is parallel to the diagonal (0,0)-(1,1) and meets
    // x + y = 1 at (0.9, 0.1); along a + t (0.6, 0.6): 0.6 + 0.6 t = 0.9, t = 0.5.
    {"one_crossing_near_SE", {0.6, -0.2}, {1.2, 0.4}, true, {0.9, 0.1}, 0.5, ONE},
    // x + y = 0.2 meets y = x at (0.1, 0.1); -0.2 + 0.6 t = 0.1, t = 0.5.
    {"one_crossing_near_SW", {-0.2, 0.4}, {0.4, -0.2}, true, {0.1, 0.1}, 0.5, ONE},
    // x + y = 1.9 meets y = x at (0.95, 0.95); 0.8 + 0.3 t = 0.95, t = 0.5.
    {"one_crossing_near_NE", {0.8, 1.1}, {1.1, 0.8}, true, {0.95, 0.95}, 0.5, ONE},
    // through the corner (0,0) without an endpoint: meets y = x there (t = 0.5); x + y = 0
    // is parallel to x + y = 1.
    {"through_corner_SW", {-1, 1}, {1, -1}, true, {0, 0}, 0.5, ONE},
    // through the corner (1,1): x + y = 2 meets y = x at (1,1), t = 0.5.
    {"through_corner_NE", {0, 2}, {2, 0}, true, {1, 1}, 0.5, ONE},
    // Case 3: two crossings. y = 0.25 meets y = x at x = 0.25 (t = 1.25/3) and x + y = 1 at
    // x = 0.75 (t = 1.75/3): midpoint (0.5, 0.25), t = 0.5.
    {"two_crossings_horizontal", {-1, 0.25}, {2, 0.25}, true, {0.5, 0.25}, 0.5, TWO},
    // y = 0.4 x + 0.2 meets y = x at (1/3, 1/3) and x + y = 1 at (4/7, 3/7); midpoint
    // (19/42, 16/42); x = -0.5 + 2 t gives t = 10/21.
    {"two_crossings_sloped", {-0.5, 0}, {1.5, 0.8}, true, {19.0 / 42, 16.0 / 42}, 10.0 / 21, TWO},
    // Edges on texel boundaries: y = 0 meets the diagonals at the corners (0,0) (t = 1/3) and
    // (1,0) (t = 2/3): midpoint (0.5, 0).
    {"on_bottom_boundary", {-1, 0}, {2, 0}, true, {0.5, 0}, 0.5, TWO},
    // x = 1 from y = -1 to 2: corners (1,0) at t = 1/3 and (1,1) at t = 2/3.
    {"on_right_boundary", {1, -1}, {1, 2}, true, {1, 0.5}, 0.5, TWO},
    // the same edge seen from the texel to its right, where it is x = 0: (0, 0.5), the same
    // world point as (1, 0.5) above
    {"on_left_boundary", {0, -1}, {0, 2}, true, {0, 0.5}, 0.5, TWO},
    // Edges on a diagonal: the overlap with (0,0)-(1,1) is t in [1/3, 2/3], its middle t = 0.5;
    // the other diagonal is crossed at (0.5, 0.5), t = 0.5.
    {"on_diagonal_SW_NE", {-1, -1}, {2, 2}, true, {0.5, 0.5}, 0.5, TWO},
    {"on_diagonal_NW_SE", {2, -1}, {-1, 2}, true, {0.5, 0.5}, 0.5, TWO},
    // Case 4: no crossing.
    {"outside", {1.2, -1}, {2, 0.5}, false, {}, 0, END},
    // x + y = 2.1 passes the corner (1,1) outside the texel (conservative raster fragment)
    {"passes_outside_corner", {0.9, 1.2}, {1.2, 0.9}, false, {}, 0, END},
    {"zero_length_outside", {2, 2}, {2, 2}, false, {}, 0, END},
    {"ends_before_texel", {-2, 0.5}, {-0.1, 0.5}, false, {}, 0, END},
};

class PickTest : public ::testing::TestWithParam<PickRow>
{
};

TEST_P(PickTest, MatchesHandDerivedPoint)
{
    const PickRow& r = GetParam();
    const std::optional<SilhouettePoint> p = pickSilhouettePoint(r.a, r.b);
    ASSERT_EQ(p.has_value(), r.picked);
    if (!p) return;
    EXPECT_NEAR(p->point.x(), r.point.x(), EPS);
    EXPECT_NEAR(p->point.y(), r.point.y(), EPS);
    EXPECT_NEAR(p->t, r.t, EPS);
    EXPECT_EQ(p->pickCase, r.pickCase);
}

INSTANTIATE_TEST_SUITE_P(Cases, PickTest, ::testing::ValuesIn(kPickRows),
                         [](const ::testing::TestParamInfo<PickRow>& i) { return std::string(i.param.name); });

TEST(Pick, PointLiesOnEdgeAndInTexel)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(-2.0, 3.0);
    int picked = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const osg::Vec2d a(d(rng), d(rng)), b(d(rng), d(rng));
        const std::optional<SilhouettePoint> p = pickSilhouettePoint(a, b);
        if (!p) continue;
        ++picked;
        EXPECT_GE(std::min(p->point.x(), p->point.y()), -1e-12);
        EXPECT_LE(std::max(p->point.x(), p->point.y()), 1.0 + 1e-12);
        EXPECT_NEAR((a + (b - a) * p->t - p->point).length(), 0.0, 1e-9);
        EXPECT_GE(p->t, 0.0);
        EXPECT_LE(p->t, 1.0);
    }
    EXPECT_GT(picked, 1000);
}

TEST(Pick, SegmentCrossingTheTexelIsAlwaysPicked)
{
    // Any segment that crosses the square's interior crosses one of its diagonals.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> d(-2.0, 3.0), in(0.01, 0.99);
    for (int i = 0; i < 20000; ++i)
    {
        const osg::Vec2d m(in(rng), in(rng)), dir(d(rng), d(rng));
        EXPECT_TRUE(pickSilhouettePoint(m - dir, m + dir).has_value());
    }
}

// ---------------------------------------------------------------------------------------
// Reconstruction: the six combinations of depth-test results at the four corners.

using Lit = std::array<bool, 4>; // indexed SW, SE, NE, NW

struct SampleRow
{
    osg::Vec2d p;
    int corner;    // the Corner whose wedge holds p; ANY where all four agree and it does not matter
    bool lit;      // the reconstructed (and, here, the true) result
};

struct WedgeRow
{
    const char* name;
    SilhouetteNeighbourhood points;
    Lit lit;
    std::vector<SampleRow> samples;
};

void PrintTo(const WedgeRow& r, std::ostream* os) { *os << r.name; }

SilhouetteNeighbourhood stored(osg::Vec2d c, osg::Vec2d e, osg::Vec2d n, osg::Vec2d w, osg::Vec2d s)
{
    return SilhouetteNeighbourhood::fromStored(c, e, n, w, s);
}

const osg::Vec2d DEF(0.5, 0.5); // cleared texel
constexpr int ANY = -1;

const WedgeRow kWedgeRows[] = {
    // 1 of 6: all four shadowed - a non-silhouette sample, whatever the points say.
    {"1_all_shadowed", stored({0.2, 0.9}, DEF, {0.1, 0.1}, DEF, DEF), {false, false, false, false},
     {{{0.5, 0.5}, ANY, false}, {{0.1, 0.1}, ANY, false}}},
    // 2 of 6: one lit corner (NE). Silhouette x + y = 1.6, lit above. It meets y = x in this
    // texel at (0.8, 0.8). In the north texel (y' = y - 1) it is x + y' = 0.6, picked at
    // (0.3, 0.3); the east texel likewise at (0.3, 0.3). West (x' + y = 2.6) and south do not
    // meet it and keep their centres.
    {"2_one_lit", stored({0.8, 0.8}, {0.3, 0.3}, {0.3, 0.3}, DEF, DEF), {false, false, true, false},
     {{{0.9, 0.9}, CORNER_NE, true},      // 1.8 > 1.6: on the segment centre -> NE
      {{0.95, 0.7}, CORNER_NE, true},     // 1.65: right of the spoke to the east point
      {{1.0, 0.65}, CORNER_NE, true},     // 1.65, on the texel's right side
      {{0.75, 0.8}, CORNER_NW, false},    // 1.55: just below the line, NW quadrant
      {{0.7, 0.88}, CORNER_NW, false},    // 1.58
      {{0.2, 0.2}, CORNER_SW, false},
      {{0.85, 0.7}, CORNER_SE, false}}},  // 1.55
    // 3 of 6: two adjacent lit corners (NE, NW). Silhouette y = 0.6, lit above; the centre
    // texel picks (0.5, 0.6) (midpoint of (0.6, 0.6) and (0.4, 0.6)), east and west the same
    // in their frames; north and south are not crossed.
    {"3_two_adjacent_lit", stored({0.5, 0.6}, {0.5, 0.6}, DEF, {0.5, 0.6}, DEF), {false, false, true, true},
     {{{0.7, 0.65}, CORNER_NE, true},
      {{0.7, 0.55}, CORNER_SE, false},
      {{0.2, 0.61}, CORNER_NW, true},
      {{0.2, 0.59}, CORNER_SW, false},
      {{0.5, 0.99}, CORNER_NE, true}}},
    // 4 of 6: two diagonal lit corners (NE, SW): two shadows meet at the centre, boundaries
    // x = 0.5 and y = 0.5. Every crossed texel picks its centre (the two crossings of
    // x = 0.5 with the diagonals are both (0.5, 0.5)).
    {"4_two_diagonal_lit", stored(DEF, DEF, DEF, DEF, DEF), {true, false, true, false},
     {{{0.7, 0.7}, CORNER_NE, true},
      {{0.3, 0.7}, CORNER_NW, false},
      {{0.3, 0.3}, CORNER_SW, true},
      {{0.7, 0.3}, CORNER_SE, false}}},
    // 5 of 6: three lit corners, SW shadowed. Silhouette x + y = 0.4, shadow below: the
    // centre picks (0.2, 0.2); the west texel (x' = x + 1) sees x' + y = 1.4 and picks
    // (0.7, 0.7), the south texel likewise; east and north are not crossed.
    {"5_three_lit", stored({0.2, 0.2}, DEF, DEF, {0.7, 0.7}, {0.7, 0.7}), {false, true, true, true},
     {{{0.1, 0.1}, CORNER_SW, false},
      {{0.25, 0.1}, CORNER_SW, false},   // 0.35
      {{0.3, 0.2}, CORNER_SE, true},     // 0.5
      {{0.1, 0.35}, CORNER_NW, true},    // 0.45
      {{0.9, 0.9}, CORNER_NE, true}}},
    // 6 of 6: all four lit.
    {"6_all_lit", stored({0.2, 0.9}, DEF, {0.1, 0.1}, DEF, DEF), {true, true, true, true},
     {{{0.5, 0.5}, ANY, true}, {{0.9, 0.1}, ANY, true}}},
};

class WedgeTest : public ::testing::TestWithParam<WedgeRow>
{
};

TEST_P(WedgeTest, MatchesHandDerivedResult)
{
    const WedgeRow& r = GetParam();
    for (const SampleRow& s : r.samples)
    {
        SCOPED_TRACE(::testing::Message() << "sample (" << s.p.x() << ", " << s.p.y() << ")");
        if (s.corner != ANY)
        {
            EXPECT_EQ(int(wedgeCorner(r.points, s.p)), s.corner);
        }
        EXPECT_EQ(silhouetteMapLit(r.points, r.lit, s.p), s.lit);
    }
}

INSTANTIATE_TEST_SUITE_P(SixCombinations, WedgeTest, ::testing::ValuesIn(kWedgeRows),
                         [](const ::testing::TestParamInfo<WedgeRow>& i) { return std::string(i.param.name); });

TEST(Wedge, DefaultPointsGiveTheNearestDepthSample)
{
    const SilhouetteNeighbourhood n;
    EXPECT_EQ(wedgeCorner(n, {0.6, 0.9}), CORNER_NE);
    EXPECT_EQ(wedgeCorner(n, {0.4, 0.9}), CORNER_NW);
    EXPECT_EQ(wedgeCorner(n, {0.1, 0.2}), CORNER_SW);
    EXPECT_EQ(wedgeCorner(n, {0.9, 0.1}), CORNER_SE);
}

TEST(Wedge, TwoEdgesInOneTexelLoseOne)
{
    // The limitation the paper names: a shadow band 0.7 < x + y < 1.3 (a thin pole) with both
    // of its edges in one texel. Only the edge drawn last is kept: x + y = 1.3 at (0.65, 0.65).
    // East (x' + y = 0.3) -> (0.15, 0.15), north likewise; west sees x + y = 0.7 as
    // x' + y = 1.7 -> (0.85, 0.85), south likewise. SW and NE are lit, NW and SE in shadow.
    const SilhouetteNeighbourhood n = stored({0.65, 0.65}, {0.15, 0.15}, {0.15, 0.15}, {0.85, 0.85}, {0.85, 0.85});
    const Lit lit = {true, false, true, false};
    EXPECT_TRUE(silhouetteMapLit(n, lit, {0.9, 0.9}));  // 1.8: lit, right
    EXPECT_FALSE(silhouetteMapLit(n, lit, {0.3, 0.85})); // 1.15: in the band, right (NW wedge)
    // 1.1 lies in the band but in the SW wedge: the lost edge x + y = 0.7 would have
    // separated it from the SW sample. Reconstructed lit, truly shadowed.
    EXPECT_EQ(wedgeCorner(n, {0.5, 0.6}), CORNER_SW);
    EXPECT_TRUE(silhouetteMapLit(n, lit, {0.5, 0.6}));
}

// For a single straight silhouette every texel it crosses stores a point on it and every
// other texel keeps its centre, which lies on the side of its own corners: the
// reconstruction is then exact everywhere in the texel.
TEST(Wedge, StraightSilhouetteIsReconstructedExactly)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * osg::PI), offset(-0.6, 0.6), in(0.0, 1.0);
    int silhouetteSamples = 0;
    for (int line = 0; line < 2000; ++line)
    {
        const double phi = angle(rng);
        const osg::Vec2d normal(std::cos(phi), std::sin(phi));
        const double d = normal * osg::Vec2d(0.5, 0.5) + offset(rng); // lit where normal . x > d
        const osg::Vec2d dir(-normal.y(), normal.x()), base = normal * d;
        auto storedIn = [&](osg::Vec2d origin) { // the point texel `origin` stores, in its frame
            const std::optional<SilhouettePoint> p =
                pickSilhouettePoint(base - dir * 50.0 - origin, base + dir * 50.0 - origin);
            return p ? p->point : DEF;
        };
        const SilhouetteNeighbourhood n = stored(storedIn({0, 0}), storedIn({1, 0}), storedIn({0, 1}),
                                                 storedIn({-1, 0}), storedIn({0, -1}));
        Lit lit;
        for (int k = 0; k < 4; ++k) lit[k] = normal * cornerPosition(Corner(k)) > d;
        for (int s = 0; s < 50; ++s)
        {
            const osg::Vec2d p(in(rng), in(rng));
            const double side = normal * p - d;
            if (std::abs(side) < 1e-9) continue;
            silhouetteSamples += (lit[0] + lit[1] + lit[2] + lit[3]) % 4 != 0;
            ASSERT_EQ(silhouetteMapLit(n, lit, p), side > 0.0)
                << "line " << line << " normal (" << normal.x() << ", " << normal.y() << ") d " << d << " p ("
                << p.x() << ", " << p.y() << ")";
        }
    }
    EXPECT_GT(silhouetteSamples, 20000);
}

} // namespace

// Storage: one float per texel, each coordinate to 1/2048 of a texel.
TEST(Storage, EncodingRoundTrips)
{
    EXPECT_EQ(decodeSilhouettePoint(defaultSilhouetteValue()), osg::Vec2d(0.5, 0.5));
    EXPECT_EQ(decodeSilhouettePoint(encodeSilhouettePoint({0, 0})), osg::Vec2d(0, 0));
    EXPECT_EQ(decodeSilhouettePoint(encodeSilhouettePoint({1, 1})), osg::Vec2d(1, 1));
    EXPECT_EQ(decodeSilhouettePoint(encodeSilhouettePoint({1, 0})), osg::Vec2d(1, 0));
    EXPECT_EQ(decodeSilhouettePoint(encodeSilhouettePoint({2, -1})), osg::Vec2d(1, 0)); // clamped
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> in(0.0, 1.0);
    for (int i = 0; i < 10000; ++i)
    {
        const osg::Vec2d p(in(rng), in(rng));
        const osg::Vec2d q = decodeSilhouettePoint(encodeSilhouettePoint(p));
        EXPECT_LE(std::abs(q.x() - p.x()), 0.5 / SILHOUETTE_POINT_STEPS + 1e-12);
        EXPECT_LE(std::abs(q.y() - p.y()), 0.5 / SILHOUETTE_POINT_STEPS + 1e-12);
    }
}

// ---------------------------------------------------------------------------------------
// wedgeCorner() tests four rays where the paper tests eight triangles; within the texel the
// two agree wherever every point lies in its own texel (which storage guarantees).

namespace {

/** The paper's form: the first corner, in the order NE, NW, SW, SE, one of whose two wedges
 *  (closed triangles of nonzero area) holds p; -1 when none does. */
int paperWedgeCorner(const SilhouetteNeighbourhood& n, const osg::Vec2d& p)
{
    const osg::Vec2d* from[4] = {&n.east, &n.north, &n.west, &n.south};
    const osg::Vec2d* to[4] = {&n.north, &n.west, &n.south, &n.east};
    const Corner corner[4] = {CORNER_NE, CORNER_NW, CORNER_SW, CORNER_SE};
    for (int k = 0; k < 4; ++k)
    {
        const osg::Vec2d c = cornerPosition(corner[k]);
        if (insideTriangle(p, n.centre, *from[k], c) || insideTriangle(p, n.centre, c, *to[k])) return corner[k];
    }
    return -1;
}

/** Five stored points drawn from a grid of `steps` per texel (0 and 1 included, so points
 *  on texel sides and corners come up often), or uniformly when steps is 0. */
SilhouetteNeighbourhood randomNeighbourhood(std::mt19937& rng, int steps)
{
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::uniform_int_distribution<int> grid(0, std::max(steps, 1));
    auto coordinate = [&] { return steps > 0 ? double(grid(rng)) / steps : uniform(rng); };
    auto point = [&] { return osg::Vec2d(coordinate(), coordinate()); };
    const osg::Vec2d c = point(), e = point(), n = point(), w = point(), s = point();
    return SilhouetteNeighbourhood::fromStored(c, e, n, w, s);
}

} // namespace

TEST(Wedge, FourRaysAgreeWithTheEightWedgesOfThePaper)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> in(0.0, 1.0);
    int tested = 0, reflex = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        const SilhouetteNeighbourhood n = randomNeighbourhood(rng, 0);
        reflex += silhouette::cross(n.east - n.centre, n.north - n.centre) < 0.0 ||
                  silhouette::cross(n.north - n.centre, n.west - n.centre) < 0.0 ||
                  silhouette::cross(n.west - n.centre, n.south - n.centre) < 0.0 ||
                  silhouette::cross(n.south - n.centre, n.east - n.centre) < 0.0;
        for (int k = 0; k < 8; ++k)
        {
            const osg::Vec2d p(in(rng), in(rng));
            const int paper = paperWedgeCorner(n, p);
            ASSERT_NE(paper, -1) << "the eight wedges cover the texel";
            ASSERT_EQ(int(wedgeCorner(n, p)), paper) << "trial " << trial;
            ++tested;
        }
    }
    EXPECT_EQ(tested, 160000);
    EXPECT_GT(reflex, 100); // quadrants wider than half a turn are exercised
}

TEST(Wedge, FourRaysAgreeOnGridPointsWhereTheWedgesDecide)
{
    // Points on texel sides and corners make wedges of zero area, which the paper's form
    // skips; wherever one of its wedges holds p, the rays give the same corner.
    std::mt19937 rng(12);
    std::uniform_int_distribution<int> grid(0, 8);
    int decided = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        const SilhouetteNeighbourhood n = randomNeighbourhood(rng, 4);
        const osg::Vec2d p(grid(rng) / 8.0, grid(rng) / 8.0);
        const int paper = paperWedgeCorner(n, p);
        if (paper < 0) continue;
        ++decided;
        // Ties: a point on a ray shared by two quadrants goes to the first in NE, NW, SW, SE
        // order in both forms, unless the paper's first quadrant there has zero area.
        const Corner rays = wedgeCorner(n, p);
        if (int(rays) != paper)
        {
            const osg::Vec2d q = p - n.centre;
            const osg::Vec2d ray[4] = {n.east - n.centre, n.north - n.centre, n.west - n.centre, n.south - n.centre};
            bool onRay = false;
            for (const osg::Vec2d& r : ray) onRay = onRay || silhouette::cross(r, q) == 0.0;
            EXPECT_TRUE(onRay) << "trial " << trial << ": rays " << rays << ", wedges " << paper;
        }
    }
    EXPECT_GT(decided, 19000);
}

TEST(Neighbourhood, PackingKeepsAllFivePoints)
{
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> step(0, 2048);
    for (int trial = 0; trial < 2000; ++trial)
    {
        osg::Vec2d points[5];
        float stored[5];
        for (int k = 0; k < 5; ++k)
        {
            points[k] = osg::Vec2d(step(rng), step(rng)) / SILHOUETTE_POINT_STEPS;
            stored[k] = encodeSilhouettePoint(points[k]);
        }
        const SilhouetteNeighbourhood n =
            unpackNeighbourhood(packNeighbourhood(stored[0], stored[1], stored[2], stored[3], stored[4]));
        const SilhouetteNeighbourhood expected =
            SilhouetteNeighbourhood::fromStored(points[0], points[1], points[2], points[3], points[4]);
        ASSERT_EQ(n.centre, expected.centre);
        ASSERT_EQ(n.east, expected.east);
        ASSERT_EQ(n.north, expected.north);
        ASSERT_EQ(n.west, expected.west);
        ASSERT_EQ(n.south, expected.south);
    }
    // The extremes: every coordinate 0, every coordinate 1 (2048, the largest 12-bit value used).
    for (double v : {0.0, 1.0})
    {
        const float s = encodeSilhouettePoint(osg::Vec2d(v, v));
        const SilhouetteNeighbourhood n = unpackNeighbourhood(packNeighbourhood(s, s, s, s, s));
        EXPECT_EQ(n.south, osg::Vec2d(v, v - 1.0));
        EXPECT_EQ(n.west, osg::Vec2d(v - 1.0, v));
    }
}

TEST(Neighbourhood, ClearedTexelHoldsFiveDefaultPoints)
{
    const SilhouetteNeighbourhood n = unpackNeighbourhood(defaultNeighbourhood());
    const SilhouetteNeighbourhood d;
    EXPECT_EQ(n.centre, d.centre);
    EXPECT_EQ(n.east, d.east);
    EXPECT_EQ(n.north, d.north);
    EXPECT_EQ(n.west, d.west);
    EXPECT_EQ(n.south, d.south);
    // The layout, worked by hand: the default value is 1024 * 4096 + 1024 = 0x400400.
    const std::array<std::uint32_t, 4> v = defaultNeighbourhood();
    EXPECT_EQ(v[0], 0x00400400u); // centre | south bits 0-7 (0x00) << 24
    EXPECT_EQ(v[1], 0x04400400u); // east | south bits 8-15 (0x04) << 24
    EXPECT_EQ(v[2], 0x40400400u); // north | south bits 16-23 (0x40) << 24
    EXPECT_EQ(v[3], 0x00400400u); // west
}
