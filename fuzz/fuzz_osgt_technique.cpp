// libFuzzer target: the .osgt reader on SilhouetteShadowTechnique's serialized properties.
//
// An input that starts with "#Ascii" is read as a whole .osgt file; any other input is the
// body of a SilhouetteShadowTechnique block inside a ShadowedScene, so that most mutations
// reach the technique's wrapper (plugins/serializers). Whatever is read is written back as
// .osgt and read again, and the technique's getters must hold values its setters allow.
#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Notify>
#include <osgDB/ReaderWriter>
#include <osgDB/Registry>
#include <osgShadow/ShadowedScene>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

osgDB::ReaderWriter* osgt = nullptr;
osg::ref_ptr<osgDB::Options> options;

osg::ref_ptr<osg::Node> readOsgt(const std::string& text)
{
    std::istringstream in(text);
    osgDB::ReaderWriter::ReadResult result = osgt->readNode(in, options.get());
    return result.getNode();
}

void check(const osg::Node* node)
{
    const osgShadow::ShadowedScene* scene = dynamic_cast<const osgShadow::ShadowedScene*>(node);
    if (!scene) return;
    const auto* t = dynamic_cast<const osgShadowSilhouette::SilhouetteShadowTechnique*>(scene->getShadowTechnique());
    if (!t) return;
    // The setters' guarantees: every property holds one of its row's values (Properties).
    for (const osgShadowSilhouette::PropertyInfo& p : osgShadowSilhouette::properties())
        if (!osgShadowSilhouette::isPropertyValue(p, p.get(*t))) std::abort();
}

/** Whether the text gives a group more children than it could hold ("Children N" with N
 *  negative, or larger than the text). OSG 3.6.5's ascii reader then loops once per announced
 *  child, each failing to read, for hours ("Children 11111111111 {", read as a huge unsigned
 *  int, with or without its bracket): a hang of OSG's own reader, not of the technique's
 *  wrapper, so the target skips such inputs. */
bool hasImpossibleCount(const std::string& text)
{
    const std::string key = "Children";
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + key.size()))
    {
        std::size_t i = at + key.size();
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i < text.size() && (text[i] == '-' || text[i] == '+')) return true;
        const std::size_t start = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        if (i - start > 9 || (i > start && std::stoul(text.substr(start, i - start)) > text.size())) return true;
    }
    return false;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    osg::setNotifyLevel(osg::FATAL); // bad input is reported through osg::notify: keep quiet
    osgDB::Registry* registry = osgDB::Registry::instance();
    registry->getLibraryFilePathList().push_front(OSS_FUZZ_PLUGIN_DIR);
    osgt = registry->getReaderWriterForExtension("osgt");
    registry->loadLibrary(registry->createLibraryNameForExtension("serializers_osgshadowsilhouette"));
    if (!osgt) std::abort();
    options = new osgDB::Options;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::string text = input;
    if (input.compare(0, 6, "#Ascii") != 0)
        text = "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\n"
               "osgShadow::ShadowedScene {\n UniqueID 1\n ShadowTechnique TRUE {\n"
               "  osgShadowSilhouette::SilhouetteShadowTechnique {\n   UniqueID 2\n" +
               input + "\n  }\n }\n}\n";
    if (hasImpossibleCount(text)) return 0;
    osg::ref_ptr<osg::Node> node = readOsgt(text);
    if (!node) return 0;
    check(node.get());
    std::ostringstream out;
    if (osgt->writeNode(*node, out, options.get()).success()) check(readOsgt(out.str()).get());
    return 0;
}
