// The "outdoor" scene: a 1.2 km height-field terrain with trees and buildings under a low
// sun, seen from eye height (docs/outdoor.md).
#include "Meshes.h"
#include "Scenes.h"

#include <osg/MatrixTransform>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace osshar {

namespace {

/** A fixed-seed 64-bit LCG (Knuth's MMIX constants): the same numbers on every platform,
 *  unlike the standard library's distributions. */
struct Lcg
{
    uint64_t state;
    double uniform() // [0, 1)
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) * (1.0 / 9007199254740992.0);
    }
    double between(double lo, double hi) { return lo + (hi - lo) * uniform(); }
};

/** Flat triangles (three corners each) as an indexed geometry with face normals, as
 *  Meshes.h's shapes are made (so that merge() takes it). */
osg::ref_ptr<osg::Geometry> flatTriangles(const std::vector<osg::Vec3>& corners, const char* name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array(corners.begin(), corners.end());
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    osg::ref_ptr<osg::DrawElementsUInt> idx = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (size_t i = 0; i + 2 < corners.size(); i += 3)
    {
        osg::Vec3 normal = (corners[i + 1] - corners[i]) ^ (corners[i + 2] - corners[i]);
        normal.normalize();
        for (size_t k = 0; k < 3; ++k) n->push_back(normal), idx->push_back(unsigned(i + k));
    }
    return triangleMesh(name, v.get(), n.get(), idx.get());
}

/** A closed cone along z: base disc of radius r at height z0, apex at z1. */
void addCone(std::vector<osg::Vec3>& t, float r, float z0, float z1, int segments)
{
    const osg::Vec3 apex(0, 0, z1), base(0, 0, z0);
    for (int i = 0; i < segments; ++i)
    {
        const double a0 = 2.0 * M_PI * i / segments, a1 = 2.0 * M_PI * (i + 1) / segments;
        const osg::Vec3 p0(r * std::cos(a0), r * std::sin(a0), z0), p1(r * std::cos(a1), r * std::sin(a1), z0);
        t.insert(t.end(), {p0, p1, apex, base, p1, p0});
    }
}

/** The trees' shared models, standing on z = 0 with their trunks reaching 0.5 below it (so
 *  that a tree on a slope has no gap under it): a broadleaf (a sphere on a trunk, 256
 *  triangles) and a conifer (five stacked cones on a trunk, 212 triangles). */
osg::ref_ptr<osg::Group> treeModel(bool conifer)
{
    osg::ref_ptr<osg::Group> tree = new osg::Group;
    tree->setName(conifer ? "conifer model" : "broadleaf model");
    const osg::Vec4 bark(0.45f, 0.33f, 0.2f, 1), leaves(0.25f, 0.5f, 0.2f, 1), needles(0.15f, 0.38f, 0.2f, 1);
    tree->addChild(coloured(makeCylinder(osg::Vec3(0, 0, -0.5f), conifer ? 0.2f : 0.25f, 4.0f, 8), bark));
    if (!conifer)
    {
        tree->addChild(coloured(makeSphere(osg::Vec3(0, 0, 5.5f), 2.5f, 14, 9), leaves));
        return tree;
    }
    std::vector<osg::Vec3> cones;
    for (int k = 0; k < 5; ++k) addCone(cones, 2.2f - 0.35f * k, 2.0f + 1.4f * k, 4.6f + 1.4f * k, 18);
    tree->addChild(coloured(flatTriangles(cones, "conifer crown"), needles));
    return tree;
}

/** A gable roof over the rectangle [-w/2, w/2] x [-d/2, d/2] at height z, its ridge along x
 *  `rise` above, overhanging by `o`; closed underneath. */
osg::ref_ptr<osg::Geometry> gableRoof(float w, float d, float z, float rise, float o)
{
    const float x = 0.5f * w + o, y = 0.5f * d + o;
    const osg::Vec3 a(-x, -y, z), b(x, -y, z), c(x, y, z), e(-x, y, z), r0(-x, 0, z + rise), r1(x, 0, z + rise);
    return flatTriangles({a, b, r1, a, r1, r0, c, e, r0, c, r0, r1, b, c, r1, e, a, r0, a, e, c, a, c, b}, "roof");
}

/** A building model: walls w x d, `storeys` of 3 m, standing on z = 0 and reaching 1.5 below
 *  it, window sills and lintels on the long walls, a gable roof and a chimney. */
osg::ref_ptr<osg::Group> buildingModel(float w, float d, int storeys)
{
    const float h = 3.0f * storeys;
    osg::ref_ptr<osg::Geometry> walls = makeBox(osg::Vec3(0, 0, 0.5f * h - 0.75f), osg::Vec3(w, d, h + 1.5f));
    const int windows = std::max(1, int(w / 3.0f));
    for (int s = 0; s < storeys; ++s)
        for (int i = 0; i < windows; ++i)
            for (float side : {-1.0f, 1.0f})
            {
                const float x = -0.5f * w + (i + 0.5f) * w / windows, y = side * (0.5f * d + 0.1f);
                walls = merge(*walls, *makeBox(osg::Vec3(x, y, 3.0f * s + 0.9f), osg::Vec3(1.3f, 0.2f, 0.12f)));
                walls = merge(*walls, *makeBox(osg::Vec3(x, y, 3.0f * s + 2.4f), osg::Vec3(1.3f, 0.2f, 0.2f)));
            }
    walls = merge(*walls, *makeBox(osg::Vec3(0.3f * w, 0.2f * d, h + 0.35f * d), osg::Vec3(0.8f, 0.8f, 3.0f)));
    osg::ref_ptr<osg::Group> building = new osg::Group;
    building->setName("building model");
    building->addChild(coloured(walls, osg::Vec4(0.82f, 0.76f, 0.64f, 1)));
    building->addChild(coloured(gableRoof(w, d, h, 0.35f * d, 0.4f), osg::Vec4(0.65f, 0.25f, 0.18f, 1)));
    return building;
}

} // namespace

double outdoorHeight(double x, double y)
{
    return 5.0 * std::sin(x / 110.0 + 0.3) * std::cos(y / 140.0) + 2.0 * std::sin((x + 2.0 * y) / 70.0) +
           0.8 * std::sin((2.0 * x - y) / 37.0 + 1.0);
}

namespace {

/** The terrain: OUTDOOR_SIDE square centred on the origin in cells of OUTDOOR_CELL, heights
 *  outdoorHeight(), normals of its gradient. */
osg::ref_ptr<osg::Geometry> terrain()
{
    const int n = int(OUTDOOR_SIDE / OUTDOOR_CELL);
    const double h0 = -0.5 * OUTDOOR_SIDE, eps = 0.5;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array, normals = new osg::Vec3Array;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
        {
            const double x = h0 + i * OUTDOOR_CELL, y = h0 + j * OUTDOOR_CELL;
            v->push_back(osg::Vec3(float(x), float(y), float(outdoorHeight(x, y))));
            osg::Vec3 normal(float(outdoorHeight(x - eps, y) - outdoorHeight(x + eps, y)),
                             float(outdoorHeight(x, y - eps) - outdoorHeight(x, y + eps)), float(2.0 * eps));
            normal.normalize();
            normals->push_back(normal);
        }
    osg::ref_ptr<osg::DrawElementsUInt> idx = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const unsigned a = unsigned(j * (n + 1) + i), b = a + 1, c = a + unsigned(n) + 2, d = a + unsigned(n) + 1;
            for (unsigned k : {a, b, c, a, c, d}) idx->push_back(k);
        }
    return triangleMesh("terrain", v.get(), normals.get(), idx.get());
}

/** The lowest terrain height under a footprint of half extents (hx, hy) turned by `yaw` at
 *  (x, y): its corners', edges' midpoints' and centre's. */
double lowestUnder(double x, double y, double hx, double hy, double yaw)
{
    double lowest = outdoorHeight(x, y);
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
        {
            const double u = i * hx, w = j * hy;
            lowest = std::min(lowest, outdoorHeight(x + u * std::cos(yaw) - w * std::sin(yaw),
                                                    y + u * std::sin(yaw) + w * std::cos(yaw)));
        }
    return lowest;
}

/** An instance of a shared model: turned by yaw about z, scaled by s, its origin at (x, y, z). */
osg::ref_ptr<osg::MatrixTransform> instance(osg::Node* model, const char* name, double x, double y, double z,
                                            double yaw, double s = 1.0)
{
    osg::ref_ptr<osg::MatrixTransform> t =
        new osg::MatrixTransform(osg::Matrixd::scale(s, s, s) * osg::Matrixd::rotate(yaw, osg::Vec3d(0, 0, 1)) *
                                 osg::Matrixd::translate(x, y, z));
    t->setName(name);
    t->addChild(model);
    return t;
}

/** A placed object's footprint, to keep others off it. */
struct Footprint
{
    double x, y, radius;
};

bool clear(const std::vector<Footprint>& taken, double x, double y, double radius)
{
    for (const Footprint& f : taken)
        if ((f.x - x) * (f.x - x) + (f.y - y) * (f.y - y) < (f.radius + radius) * (f.radius + radius)) return false;
    return true;
}

/** Where the walk starts and its heading (clockwise from +y), speed and turn. */
const osg::Vec2d WALK_START(-40.0, -420.0);
constexpr double WALK_HEADING_DEG = 10.0, WALK_SPEED = 1.5, WALK_TURN_DEG_PER_S = 2.0;
constexpr double EYE_HEIGHT = 1.7, PITCH_DEG = -2.5;

osg::Vec2d heading(double deg)
{
    const double a = osg::DegreesToRadians(deg);
    return osg::Vec2d(std::sin(a), std::cos(a));
}

/** The walk's ground point at time t: a circular arc from WALK_START. */
osg::Vec2d walkGround(double t)
{
    const double w = osg::DegreesToRadians(WALK_TURN_DEG_PER_S);
    const double a0 = osg::DegreesToRadians(WALK_HEADING_DEG), a = a0 + w * t;
    return WALK_START + osg::Vec2d(std::cos(a0) - std::cos(a), std::sin(a) - std::sin(a0)) * (WALK_SPEED / w);
}

/** The objects placed by hand within 20 m of the walk's start, and the walk's corridor kept
 *  clear of the random ones. */
void placeNearObjects(osg::Group& trees, osg::Group& buildings, osg::Node* broadleaf, osg::Node* conifer,
                      osg::Node* smallHouse, std::vector<Footprint>& taken)
{
    const osg::Vec2d d = heading(WALK_HEADING_DEG), side(d.y(), -d.x());
    for (int k = 0; k <= 8; ++k)
    {
        const osg::Vec2d p = WALK_START + d * (2.0 * k);
        taken.push_back({p.x(), p.y(), 1.5});
    }
    const struct
    {
        double ahead, right;
        osg::Node* model;
    } near[] = {{8, 6, broadleaf}, {14, -7, broadleaf}, {19, 4, conifer}};
    for (const auto& n : near)
    {
        const osg::Vec2d p = WALK_START + d * n.ahead + side * n.right;
        trees.addChild(instance(n.model, "tree", p.x(), p.y(), outdoorHeight(p.x(), p.y()), 0.0));
        taken.push_back({p.x(), p.y(), 3.0});
    }
    const osg::Vec2d h = WALK_START + d * 13.0 + side * 12.0;
    const double yaw = osg::DegreesToRadians(-WALK_HEADING_DEG);
    buildings.addChild(instance(smallHouse, "building", h.x(), h.y(), lowestUnder(h.x(), h.y(), 4.0, 3.0, yaw), yaw));
    taken.push_back({h.x(), h.y(), 6.0});
}

/** The buildings placed at random: variants of `models` (half extents in `halves`), turned
 *  at random, standing on the lowest terrain under them, 12 m off anything placed before. */
void placeBuildings(osg::Group& buildings, const std::vector<osg::ref_ptr<osg::Group>>& models,
                    const std::vector<osg::Vec2d>& halves, Lcg& rng, std::vector<Footprint>& taken)
{
    const double range = 0.5 * OUTDOOR_SIDE - 30.0;
    while (int(buildings.getNumChildren()) < OUTDOOR_BUILDINGS)
    {
        const size_t v = size_t(rng.uniform() * models.size()) % models.size();
        const double x = rng.between(-range, range), y = rng.between(-range, range);
        const double yaw = rng.between(0.0, 2.0 * M_PI), radius = halves[v].length() + 2.0;
        if (!clear(taken, x, y, radius + 12.0)) continue;
        buildings.addChild(
            instance(models[v].get(), "building", x, y, lowestUnder(x, y, halves[v].x(), halves[v].y(), yaw), yaw));
        taken.push_back({x, y, radius});
    }
}

/** The trees placed at random, broadleaves and conifers, scaled by 0.75 to 1.3, off the
 *  buildings and each other (2 m times their scale around each), their trunks' axis
 *  standing at the terrain's height. */
void placeTrees(osg::Group& trees, osg::Node* broadleaf, osg::Node* conifer, Lcg& rng, std::vector<Footprint>& taken)
{
    const double range = 0.5 * OUTDOOR_SIDE - 10.0;
    while (int(trees.getNumChildren()) < OUTDOOR_TREES)
    {
        const double x = rng.between(-range, range), y = rng.between(-range, range);
        const double s = rng.between(0.75, 1.3), yaw = rng.between(0.0, 2.0 * M_PI);
        osg::Node* model = rng.uniform() < 0.4 ? conifer : broadleaf;
        if (!clear(taken, x, y, 2.0 * s)) continue;
        trees.addChild(instance(model, "tree", x, y, outdoorHeight(x, y), yaw, s));
        taken.push_back({x, y, 2.0 * s});
    }
}

} // namespace

View outdoorWalkView(double t)
{
    const osg::Vec2d g = walkGround(t);
    const osg::Vec2d d = heading(WALK_HEADING_DEG + WALK_TURN_DEG_PER_S * t);
    const osg::Vec3d eye(g.x(), g.y(), outdoorHeight(g.x(), g.y()) + EYE_HEIGHT);
    const double pitch = osg::DegreesToRadians(PITCH_DEG);
    const osg::Vec3d look(d.x() * std::cos(pitch), d.y() * std::cos(pitch), std::sin(pitch));
    return {eye, eye + look * 100.0, osg::Vec3d(0, 0, 1), 50.0};
}

osg::ref_ptr<osg::AnimationPath> outdoorWalk(int frames, double timeStep)
{
    osg::ref_ptr<osg::AnimationPath> path = new osg::AnimationPath;
    path->setLoopMode(osg::AnimationPath::NO_LOOPING);
    for (int i = 0; i < frames; ++i)
    {
        const View v = outdoorWalkView(i * timeStep);
        const osg::Matrixd camera = osg::Matrixd::inverse(osg::Matrixd::lookAt(v.eye, v.center, v.up));
        path->insert(i * timeStep, osg::AnimationPath::ControlPoint(camera.getTrans(), camera.getRotate()));
    }
    return path;
}

Scene outdoorScene()
{
    Scene s{"outdoor", new osg::Group, {}};
    s.root->setName("outdoor: 1.2 km terrain, trees and buildings, low sun");
    s.root->addChild(coloured(terrain(), osg::Vec4(0.5f, 0.62f, 0.35f, 1)));
    osg::ref_ptr<osg::Group> trees = new osg::Group, buildings = new osg::Group;
    trees->setName("trees");
    buildings->setName("buildings");
    trees->getOrCreateStateSet()->setMode(GL_RESCALE_NORMAL, osg::StateAttribute::ON); // scaled instances
    const osg::ref_ptr<osg::Group> broadleaf = treeModel(false), conifer = treeModel(true);
    const std::vector<osg::ref_ptr<osg::Group>> houses = {buildingModel(8, 6, 1), buildingModel(10, 7, 2),
                                                          buildingModel(14, 9, 3), buildingModel(20, 12, 4)};
    const std::vector<osg::Vec2d> halves = {{4, 3}, {5, 3.5}, {7, 4.5}, {10, 6}};
    std::vector<Footprint> taken;
    Lcg rng{20261207};
    placeNearObjects(*trees, *buildings, broadleaf.get(), conifer.get(), houses[0].get(), taken);
    placeBuildings(*buildings, houses, halves, rng, taken);
    placeTrees(*trees, broadleaf.get(), conifer.get(), rng, taken);
    s.root->addChild(trees.get());
    s.root->addChild(buildings.get());
    const double e = osg::DegreesToRadians(OUTDOOR_SUN_ELEVATION_DEG);
    osg::Vec3d toward(0.98, -0.2, 0.0);
    toward.normalize();
    s.root->addChild(makeLight(osg::Vec4(osg::Vec3(toward * std::cos(e) + osg::Vec3d(0, 0, std::sin(e))), 0.0f)));
    s.view = outdoorWalkView(0.0);
    return s;
}

} // namespace osshar
