// The options of the .silhouette pseudo-loader, parsed from osgDB's option string (-O).
#ifndef OSS_PLUGINS_PSEUDOLOADEROPTIONS_H
#define OSS_PLUGINS_PSEUDOLOADEROPTIONS_H

#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <string>
#include <utility>
#include <vector>

namespace osssil {

/** One "Key=value" option the pseudo-loader knows, with its help text. */
struct OptionDescription
{
    std::string key;
    std::string help;
};

/** The options the pseudo-loader knows: one per property of the technique (the table of
 *  osgShadowSilhouette/Properties; keys are matched case-insensitively), and Report=. */
const std::vector<OptionDescription>& optionDescriptions();

/** The Key=value pairs of an option string, split at spaces; words without '=' are
 *  returned with an empty value. */
std::vector<std::pair<std::string, std::string>> splitOptions(const std::string& optionString);

/** Applies the technique's options of an option string. Unknown keys are left alone (they may
 *  belong to the loader of the model); a value that does not parse or is out of range is
 *  reported with OSG_WARN naming the option and the value. Returns the Report= file, if any. */
std::string applyOptions(const std::string& optionString, osgShadowSilhouette::SilhouetteShadowTechnique& technique);

} // namespace osssil

#endif
