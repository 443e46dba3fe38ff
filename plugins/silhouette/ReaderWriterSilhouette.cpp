// The .silhouette pseudo-loader, in the spirit of OSG's .shadow:
//
//   osgviewer cow.osgt.silhouette               SilhouetteShadowTechnique, default mode
//   osgviewer cow.osgt.hybrid.silhouette        ... in mode HYBRID (also .shadowmap,
//                                               .silhouette, .volume; the enum names work too)
//   osgviewer cow.osgt.silhouette -O "ShadowMapSize=4096 DebugView=mask"
//
// It loads the model, wraps it in an osgShadow::ShadowedScene with the technique and applies
// the options (see osssil::optionDescriptions()). A model that already is a ShadowedScene
// with this technique is not wrapped again: the mode and options apply to its technique.
// A model without any osg::LightSource gets a directional light, with one notice.
#include "PseudoLoaderOptions.h"

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/LightSource>
#include <osg/NodeVisitor>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgShadow/ShadowedScene>

#include <OpenThreads/Mutex>
#include <OpenThreads/ScopedLock>

#include <atomic>
#include <fstream>

using osgShadowSilhouette::SilhouetteShadowTechnique;

namespace {

/** Where the added light comes from: above, in front and to the right of the default view. */
const osg::Vec3 ADDED_LIGHT_DIRECTION(0.4f, -0.5f, 0.77f);

class HasLightVisitor : public osg::NodeVisitor
{
public:
    HasLightVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LightSource& ls) override
    {
        if (ls.getLight()) found = true;
        else traverse(ls);
    }
    bool found = false;
};

bool hasLight(osg::Node& node)
{
    HasLightVisitor v;
    node.accept(v);
    return v.found;
}

osg::ref_ptr<osg::LightSource> createDirectionalLight()
{
    osg::Vec3 d = ADDED_LIGHT_DIRECTION;
    d.normalize();
    osg::ref_ptr<osg::Light> light = new osg::Light(0);
    light->setPosition(osg::Vec4(d, 0.0f));
    light->setAmbient(osg::Vec4(0.2f, 0.2f, 0.2f, 1.0f));
    light->setDiffuse(osg::Vec4(0.8f, 0.8f, 0.8f, 1.0f));
    light->setSpecular(osg::Vec4(0.3f, 0.3f, 0.3f, 1.0f));
    osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
    source->setName("osgShadowSilhouette added light");
    source->setLight(light.get());
    return source;
}

void noticeAddedLightOnce(const std::string& fileName)
{
    static std::atomic<bool> told(false);
    if (told.exchange(true)) return;
    osg::Vec3 d = ADDED_LIGHT_DIRECTION;
    d.normalize();
    OSG_NOTICE << "osgShadowSilhouette: " << fileName << " has no light source; added a directional light"
               << " (GL light 0) toward (" << d.x() << ", " << d.y() << ", " << d.z() << ")" << std::endl;
}

/** Cull callback of the ShadowedScene: after each cull, appends the technique's statistics to a file. */
class StatisticsReport : public osg::NodeCallback
{
public:
    StatisticsReport(SilhouetteShadowTechnique* technique, const std::string& fileName)
        : _technique(technique), _file(fileName.c_str(), std::ios::out | std::ios::trunc)
    {
        if (!_file) OSG_WARN << "osgShadowSilhouette pseudo-loader: cannot write Report=" << fileName << std::endl;
    }

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        traverse(node, nv);
        const SilhouetteShadowTechnique::Statistics s = _technique->getStatistics();
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
        _file << "frame=" << s.frameNumber << " lightsFound=" << s.lightsFound
              << " lightsShadowed=" << s.lightsShadowed << " shadowPasses=" << s.shadowPasses
              << " depthPassesReused=" << s.depthPassesReused
              << " lightsSkipped=" << s.lightsSkipped
              << " effectiveMode=" << SilhouetteShadowTechnique::modeName(s.effectiveMode) << std::endl;
    }

private:
    osg::observer_ptr<SilhouetteShadowTechnique> _technique;
    OpenThreads::Mutex _mutex;
    std::ofstream _file;
};

/** The technique of a ShadowedScene that already uses SilhouetteShadowTechnique, else null. */
SilhouetteShadowTechnique* existingTechnique(osg::Node& node)
{
    osgShadow::ShadowedScene* scene = dynamic_cast<osgShadow::ShadowedScene*>(&node);
    return scene ? dynamic_cast<SilhouetteShadowTechnique*>(scene->getShadowTechnique()) : nullptr;
}

/** Splits "cow.osgt.hybrid" into the model file name and the mode it names, if any. */
bool splitModeExtension(const std::string& name, std::string& modelFile, SilhouetteShadowTechnique::Mode& mode)
{
    if (SilhouetteShadowTechnique::modeFromName(osgDB::getFileExtension(name), mode))
    {
        modelFile = osgDB::getNameLessExtension(name);
        return true;
    }
    modelFile = name;
    return false;
}

/** For "cow.osgt.fancy" where no file of that name exists but "cow.osgt" does: a message
 *  naming the unknown mode and the valid ones; else empty. */
std::string unknownMode(const std::string& modelFile)
{
    const std::string word = osgDB::getFileExtension(modelFile);
    const std::string stripped = osgDB::getNameLessExtension(modelFile);
    if (word.empty() || osgDB::getFileExtension(stripped).empty() || !osgDB::findDataFile(modelFile).empty() ||
        osgDB::findDataFile(stripped).empty())
        return "";
    std::string modes;
    for (int m = SilhouetteShadowTechnique::SHADOW_MAP; m <= SilhouetteShadowTechnique::SHADOW_VOLUME; ++m)
        modes += std::string(modes.empty() ? "" : ", ") +
                 SilhouetteShadowTechnique::modeName(SilhouetteShadowTechnique::Mode(m));
    return "osgShadowSilhouette pseudo-loader: unknown mode \"" + word + "\" in \"" + modelFile +
           ".silhouette\"; the modes are " + modes + " (model." + osgDB::getFileExtension(stripped) +
           ".<mode>.silhouette)";
}

} // namespace

class ReaderWriterSilhouette : public osgDB::ReaderWriter
{
public:
    ReaderWriterSilhouette()
    {
        supportsExtension("silhouette", "osgShadowSilhouette pseudo-loader: model.<ext>[.<mode>].silhouette");
        for (const osssil::OptionDescription& o : osssil::optionDescriptions()) supportsOption(o.key, o.help);
    }

    const char* className() const override { return "osgShadowSilhouette pseudo-loader"; }

    ReadResult readObject(const std::string& fileName, const Options* options) const override
    {
        return readNode(fileName, options);
    }

    ReadResult readNode(const std::string& fileName, const Options* options) const override
    {
        if (!acceptsExtension(osgDB::getLowerCaseFileExtension(fileName))) return ReadResult::FILE_NOT_HANDLED;

        std::string modelFile;
        SilhouetteShadowTechnique::Mode mode = SilhouetteShadowTechnique::SHADOW_MAP;
        const bool modeNamed = splitModeExtension(osgDB::getNameLessExtension(fileName), modelFile, mode);
        if (modelFile.empty()) return ReadResult::FILE_NOT_HANDLED;

        if (!modeNamed)
            if (const std::string unknown = unknownMode(modelFile); !unknown.empty())
            {
                OSG_WARN << unknown << std::endl;
                return ReadResult(unknown);
            }
        osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(modelFile, options);
        if (!model)
        {
            OSG_WARN << "osgShadowSilhouette pseudo-loader: cannot load \"" << modelFile << "\"" << std::endl;
            return ReadResult::FILE_NOT_HANDLED;
        }
        osg::ref_ptr<osgShadow::ShadowedScene> scene = shadowedScene(model.get(), modelFile);
        SilhouetteShadowTechnique* technique = existingTechnique(*scene);
        if (modeNamed) technique->setMode(mode);
        const std::string report = options ? osssil::applyOptions(options->getOptionString(), *technique) : "";
        if (!report.empty()) scene->addCullCallback(new StatisticsReport(technique, report));
        return scene.get();
    }

private:
    /** The model itself when it already is a ShadowedScene with our technique, else a new one around it. */
    static osg::ref_ptr<osgShadow::ShadowedScene> shadowedScene(osg::Node* model, const std::string& modelFile)
    {
        if (existingTechnique(*model)) return static_cast<osgShadow::ShadowedScene*>(model);
        osg::ref_ptr<osgShadow::ShadowedScene> scene = new osgShadow::ShadowedScene(new SilhouetteShadowTechnique);
        scene->setName(osgDB::getSimpleFileName(modelFile));
        scene->addChild(model);
        if (!hasLight(*model))
        {
            scene->addChild(createDirectionalLight().get());
            noticeAddedLightOnce(modelFile);
        }
        return scene;
    }
};

REGISTER_OSGPLUGIN(silhouette, ReaderWriterSilhouette)
