// Built-in test scenes and the lights and cameras they come with.
#ifndef OSS_HARNESS_SCENES_H
#define OSS_HARNESS_SCENES_H

#include <osg/AnimationPath>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/LightSource>

#include <string>
#include <vector>

namespace osshar {

/** A camera as OSG's lookAt + perspective describe it. */
struct View
{
    osg::Vec3d eye, center, up{0, 0, 1};
    double fovy = 40.0;
};

/** A scene (its light sources inside) and the view it is meant to be seen from. */
struct Scene
{
    std::string name;
    osg::ref_ptr<osg::Group> root;
    View view;
};

/** Names of the built-in scenes: "default", "spheres", "poles", "cubes", "tree" (thin
 *  branches, 17k triangles), "bunny" (glmark2-data's scanned bunny on a ground plane),
 *  "dueling" (the default scene with the camera facing the light) and "grazing" (the default
 *  scene lit from 1.5 degrees above the ground, with a wall that receives the long shadows),
 *  "elephant" (libcgal-demo's elephant subdivided to 355,712 triangles on a ground plane),
 *  "ring" (a point light amid its casters: eight pillars around it), "foliage" (alpha-tested
 *  casters: a fence panel with diamond holes and crossed cards of leaves, cut out by their
 *  textures' alpha and an osg::AlphaFunc), "animated" (casters deformed every frame: a
 *  skinned osgAnimation::RigGeometry, an osgAnimation::MorphGeometry and a geometry whose
 *  vertex array an update callback edits; AnimatedScenes.h), "outdoor" (a 1.2 km terrain
 *  with trees and buildings under a low sun, seen from eye height: outdoorScene()). */
std::vector<std::string> sceneNames();

/** A built-in scene by name; root is null for an unknown name, and for "bunny" when its
 *  file is missing, and for "elephant" when elephant.off is (with a message on stderr). */
Scene createScene(const std::string& name);

/** A Geode holding `g` under an osg::Material of `colour` (ambient and diffuse; specular 0.3,
 *  shininess 32), as the built-in scenes colour their objects. */
osg::ref_ptr<osg::Geode> coloured(osg::ref_ptr<osg::Geometry> g, const osg::Vec4& colour);

/** The built-in scenes' ground colour. */
const osg::Vec4& groundColour();

/** A LightSource holding GL light `lightNum`: directional toward `towardLight` (w = 0) or at a
 *  position (w = 1), ambient 0.2, diffuse 0.8, specular 0.3. */
osg::ref_ptr<osg::LightSource> makeLight(const osg::Vec4& position, int lightNum = 0);

/** A LightSource in a scene with the matrix from its local frame to the scene's root. */
struct LightInScene
{
    osg::LightSource* source = nullptr;
    osg::Matrixd localToWorld;
};

/** Every LightSource below root that carries an osg::Light, in traversal order. */
std::vector<LightInScene> findLights(osg::Node* root);

/** The "outdoor" scene (OutdoorScene.cpp, docs/outdoor.md): a height-field terrain of
 *  OUTDOOR_SIDE x OUTDOOR_SIDE metres centred on the origin (z up, heights outdoorHeight(),
 *  triangles of OUTDOOR_CELL cells in one osg::Geometry named "terrain"), OUTDOOR_TREES
 *  trees (osg::MatrixTransforms named "tree" sharing two models, a broadleaf and a conifer,
 *  212-256 triangles) and OUTDOOR_BUILDINGS buildings ("building", four shared models of
 *  walls, window sills and lintels, a gable roof and a chimney, 128-1184 triangles), placed by a
 *  fixed-seed generator with their bases at the terrain's height; three trees and a house
 *  stand within 20 m of the view. A sun OUTDOOR_SUN_ELEVATION_DEG above the horizon from
 *  the east; the view is outdoorWalkView(0). */
Scene outdoorScene();

constexpr double OUTDOOR_SIDE = 1200.0, OUTDOOR_CELL = 5.0, OUTDOOR_SUN_ELEVATION_DEG = 12.0;
constexpr int OUTDOOR_TREES = 1500, OUTDOOR_BUILDINGS = 60;

/** The outdoor terrain's height at (x, y): a sum of sines within +-7.8 m, slopes below 10 degrees. */
double outdoorHeight(double x, double y);

/** The view of a walk through the outdoor scene at time t (s): an eye 1.7 m above the
 *  terrain walking at 1.5 m/s and turning by 2 degrees/s, looking 2.5 degrees down, fovy 50. */
View outdoorWalkView(double t);

/** That walk as an osg::AnimationPath (osgGA::AnimationPathManipulator's camera matrices,
 *  the format osgviewer records): `frames` control points `timeStep` apart from time 0
 *  (data/outdoor-walk.path is outdoorWalk(150, 1 / 30.0)). */
osg::ref_ptr<osg::AnimationPath> outdoorWalk(int frames, double timeStep);

/** A loaded model put on a ground, as the corpus runs see it: turned -30 degrees about z,
 *  scaled so that its bounding box's largest side is 6 units, its box centred on the z axis
 *  and standing on z = 0, on a 16 x 16 ground square (which casts and receives) whose top
 *  is z = 0; GL_NORMALIZE on the scaled model. No light is added. The view looks at the
 *  model from -y and above, framing it and its shadow's surroundings. */
Scene placeOnGround(osg::Node* model, const std::string& name);

/** The view osgviewer's home position would give a model: from -y and above, at a distance
 *  that frames the bounding sphere. */
View defaultView(const osg::BoundingSphere& bound);

} // namespace osshar

#endif
