// The scene files in data/: each is a ShadowedScene with a SilhouetteShadowTechnique of
// default properties around the built-in scene of the same name (harness/Scenes.h), as
// examples/osgsilhouette-export writes them. When a built-in scene changes, regenerate them:
//   OSG_LIBRARY_PATH=build/lib build/bin/osgsilhouette-export data default spheres poles cubes
#include "test_serializer_properties.h"

#include "Scenes.h"

#include <gtest/gtest.h>

#include <osg/Geode>
#include <osg/LightSource>
#include <osg/ValueObject>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgShadow/ShadowedScene>

#include <cstdlib>

using osstest::Technique;

namespace {

std::string dataFile(const std::string& scene)
{
    return osstest::sourceDir() + "/data/" + scene + ".osgt";
}

/** Counts what a scene holds: drawables, light sources and vertices. */
class CountVisitor : public osg::NodeVisitor
{
public:
    CountVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LightSource& ls) override
    {
        if (ls.getLight()) ++lights;
        traverse(ls);
    }
    void apply(osg::Geometry& g) override
    {
        ++drawables;
        if (g.getVertexArray()) vertices += g.getVertexArray()->getNumElements();
    }
    unsigned int drawables = 0, lights = 0, vertices = 0;
};

CountVisitor count(osg::Node& node)
{
    CountVisitor v;
    node.accept(v);
    return v;
}

} // namespace

class DataFile : public ::testing::TestWithParam<std::string>
{
};

TEST_P(DataFile, IsAShadowedSceneWithTheDefaultTechnique)
{
    ASSERT_TRUE(osgDB::fileExists(dataFile(GetParam()))) << dataFile(GetParam());
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(dataFile(GetParam()));
    osgShadow::ShadowedScene* scene = dynamic_cast<osgShadow::ShadowedScene*>(node.get());
    ASSERT_NE(scene, nullptr);
    const Technique* technique = dynamic_cast<const Technique*>(scene->getShadowTechnique());
    ASSERT_NE(technique, nullptr) << "no technique: is osgdb_serializers_osgshadowsilhouette found?";
    osg::ref_ptr<Technique> defaults = new Technique;
    for (const osstest::PropertyRow& row : osstest::propertyRows())
        EXPECT_EQ(row.get(*technique), row.get(*defaults)) << row.name;
}

TEST_P(DataFile, HoldsTheBuiltInSceneAndItsLight)
{
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(dataFile(GetParam()));
    ASSERT_NE(node, nullptr);
    const osshar::Scene builtIn = osshar::createScene(GetParam());
    ASSERT_NE(builtIn.root, nullptr);
    const CountVisitor file = count(*node), expected = count(*builtIn.root);
    EXPECT_EQ(file.drawables, expected.drawables);
    EXPECT_EQ(file.vertices, expected.vertices);
    EXPECT_EQ(file.lights, expected.lights);
    EXPECT_GE(file.lights, 1u);
    EXPECT_NEAR(node->getBound().radius(), builtIn.root->getBound().radius(), 1e-3 * builtIn.root->getBound().radius());
}

INSTANTIATE_TEST_SUITE_P(Scenes, DataFile, ::testing::Values("default", "spheres", "poles", "cubes"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// data/soft.osgt: the default scene under PCSS, its sun 2 degrees wide by its LightSource's
// own ShadowLightSize (docs/soft-shadows.md): a file keeps both.
TEST(SoftDataFile, KeepsItsFilterAndItsLightsSize)
{
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(dataFile("soft"));
    osgShadow::ShadowedScene* scene = dynamic_cast<osgShadow::ShadowedScene*>(node.get());
    ASSERT_NE(scene, nullptr);
    const Technique* technique = dynamic_cast<const Technique*>(scene->getShadowTechnique());
    ASSERT_NE(technique, nullptr);
    EXPECT_EQ(technique->getFilter(), Technique::FILTER_PCSS);
    EXPECT_EQ(technique->getLightSize(), 0.0f) << "the light's own size, not the technique's";
    struct FindSize : osg::NodeVisitor
    {
        FindSize() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::LightSource& ls) override
        {
            found = ls.getUserValue(Technique::LIGHT_SIZE_USER_VALUE, size) || found;
            traverse(ls);
        }
        double size = 0.0;
        bool found = false;
    } find;
    node->accept(find);
    EXPECT_TRUE(find.found);
    EXPECT_EQ(find.size, 2.0);
    const CountVisitor file = count(*node), expected = count(*osshar::createScene("default").root);
    EXPECT_EQ(file.drawables, expected.drawables);
}
