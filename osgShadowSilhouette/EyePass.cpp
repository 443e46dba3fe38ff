#include "EyePass.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <algorithm>

namespace osgShadowSilhouette {
namespace detail {

std::map<std::string, std::string> eyePassDefines(const EyePassPlan& plan)
{
    using Technique = SilhouetteShadowTechnique;
    std::map<std::string, std::string> d;
    const auto flag = [&d](const char* name, bool on) {
        if (on) d[name] = "";
    };
    const bool silhouette = plan.mode == Technique::SILHOUETTE_MAP;
    const bool hybrid = plan.mode == Technique::HYBRID;
    const bool lists = hybrid && plan.triangleLists;
    d[shader::DEFINE_MAX_SHADOW_SLOTS] = std::to_string(plan.slotCapacity);
    d[shader::DEFINE_NUM_SHADOW_SLOTS] = std::to_string(plan.usedSlots);
    d[shader::DEFINE_MAX_LIST_SLOTS] = std::to_string(lists ? std::max(1u, plan.listSlots) : 1u);
    if (plan.skippedSlots != 0) d[shader::DEFINE_SKIPPED_SLOTS] = std::to_string(plan.skippedSlots);
    flag(shader::DEFINE_CUBE_FACES, plan.cubeFaces);
    flag(shader::DEFINE_PER_PIXEL_LIGHTING, plan.perPixelLighting);
    const bool visibility = plan.debugView == Technique::DEBUG_VISIBILITY;
    flag(shader::DEFINE_DEBUG_MASK, plan.debugView == Technique::DEBUG_SHADOW_MASK || visibility);
    flag(shader::DEFINE_DEBUG_VISIBILITY, visibility);
    const bool shadowMap = plan.mode == Technique::SHADOW_MAP;
    if (shadowMap && plan.filter == Technique::FILTER_PCF)
        d[shader::DEFINE_FILTER_PCF] = std::to_string(std::max(1u, plan.filterWindow));
    flag(shader::DEFINE_FILTER_PCSS, shadowMap && plan.filter == Technique::FILTER_PCSS);
    flag(shader::DEFINE_DEBUG_CLASSES, plan.debugView == Technique::DEBUG_CLASSES);
    flag(shader::DEFINE_SILHOUETTE_MAP, silhouette);
    // FILTER_SILHOUETTE reads edge distances instead of the silhouette points the overlays show.
    const bool distances = silhouette && plan.filter == Technique::FILTER_SILHOUETTE;
    flag(shader::DEFINE_FILTER_SILHOUETTE, distances);
    const bool points = silhouette && !distances;
    flag(shader::DEFINE_DEBUG_SILHOUETTE_PIXELS, points && plan.debugView == Technique::DEBUG_SILHOUETTE_PIXELS);
    // DEBUG_SILHOUETTE_MAP: the silhouette points, or under FILTER_SILHOUETTE the edge distances.
    flag(shader::DEFINE_DEBUG_SILHOUETTE_MAP, silhouette && plan.debugView == Technique::DEBUG_SILHOUETTE_MAP);
    flag(shader::DEFINE_TRIANGLE_LISTS, lists);
    flag(shader::DEFINE_LIST_IMAGES, lists && plan.listImages);
    flag(shader::DEFINE_LIST_BLOCK_HEADS, lists && plan.listImages && plan.listBlockHeads);
    flag(shader::DEFINE_COUNT_EXACT, lists && plan.countExact);
    flag(shader::DEFINE_LIST_SOFT, lists && plan.listSoft);
    flag(shader::DEFINE_BIAS_BAND, hybrid);
    flag(shader::DEFINE_HYBRID_EDGES, hybrid && plan.edgeMasks);
    return d;
}

const std::vector<std::string>& eyePassDefineNames()
{
    static const std::vector<std::string> names = {
        shader::DEFINE_MAX_SHADOW_SLOTS,     shader::DEFINE_NUM_SHADOW_SLOTS,
        shader::DEFINE_MAX_LIST_SLOTS,       shader::DEFINE_SKIPPED_SLOTS,
        shader::DEFINE_CUBE_FACES,           shader::DEFINE_PER_PIXEL_LIGHTING,
        shader::DEFINE_DEBUG_MASK,           shader::DEFINE_DEBUG_CLASSES,
        shader::DEFINE_SILHOUETTE_MAP,       shader::DEFINE_DEBUG_SILHOUETTE_PIXELS,
        shader::DEFINE_DEBUG_SILHOUETTE_MAP, shader::DEFINE_TRIANGLE_LISTS,
        shader::DEFINE_LIST_IMAGES,          shader::DEFINE_LIST_BLOCK_HEADS,
        shader::DEFINE_COUNT_EXACT,          shader::DEFINE_BIAS_BAND,
        shader::DEFINE_HYBRID_EDGES,         shader::DEFINE_DEBUG_VISIBILITY,
        shader::DEFINE_FILTER_PCF,           shader::DEFINE_FILTER_PCSS,
        shader::DEFINE_FILTER_SILHOUETTE,    shader::DEFINE_LIST_SOFT,
    };
    return names;
}

void applyEyePassDefines(osg::StateSet& ss, const std::map<std::string, std::string>& defines)
{
    for (const std::string& name : eyePassDefineNames())
    {
        const auto found = defines.find(name);
        if (found == defines.end())
            ss.removeDefine(name);
        else
            ss.setDefine(name, found->second);
    }
}

} // namespace detail
} // namespace osgShadowSilhouette
