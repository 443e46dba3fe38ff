#include "PseudoLoaderOptions.h"

#include <osgShadowSilhouette/Properties>

#include <osg/Notify>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace osssil {

using osgShadowSilhouette::SilhouetteShadowTechnique;

namespace {

const char* const WHERE = "osgShadowSilhouette pseudo-loader option";

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

/** "ShadowMapSize=<n>", "Mode=<shadowmap|silhouette|hybrid|volume>", "UseDefaultShading=<on|off>". */
std::string optionKey(const osgShadowSilhouette::PropertyInfo& p)
{
    return std::string(p.name) + "=<" + osgShadowSilhouette::propertyValueSyntax(p) + ">";
}

std::string optionHelp(const osgShadowSilhouette::PropertyInfo& p)
{
    std::string help = p.doc;
    if (p.numeric()) help += " (" + osgShadowSilhouette::describePropertyValues(p) + ")";
    if (std::string(p.name) == "Mode") help += "; overrides the mode named in the file name";
    if (std::string(p.name) == "ShadowMapSize") help += "; MapSize=<n> also works";
    return help;
}

} // namespace

const std::vector<OptionDescription>& optionDescriptions()
{
    static const std::vector<OptionDescription> options = [] {
        std::vector<OptionDescription> list;
        for (const osgShadowSilhouette::PropertyInfo& p : osgShadowSilhouette::properties())
            list.push_back({optionKey(p), optionHelp(p)});
        list.push_back({"Report=<file>", "Write the technique's statistics of every frame to <file>"});
        return list;
    }();
    return options;
}

std::vector<std::pair<std::string, std::string>> splitOptions(const std::string& optionString)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::istringstream in(optionString);
    std::string word;
    while (in >> word)
    {
        const std::string::size_type eq = word.find('=');
        if (eq == std::string::npos) pairs.emplace_back(word, std::string());
        else pairs.emplace_back(word.substr(0, eq), word.substr(eq + 1));
    }
    return pairs;
}

std::string applyOptions(const std::string& optionString, SilhouetteShadowTechnique& technique)
{
    std::string report;
    for (const auto& kv : splitOptions(optionString))
    {
        const std::string key = lower(kv.first) == "mapsize" ? "ShadowMapSize" : kv.first;
        if (lower(key) == "report")
            report = kv.second;
        else if (osgShadowSilhouette::findProperty(key))
            osgShadowSilhouette::setPropertyFromText(technique, key, kv.second, WHERE);
        else
            OSG_INFO << "osgShadowSilhouette pseudo-loader: option " << kv.first << " is not ours" << std::endl;
    }
    return report;
}

} // namespace osssil
