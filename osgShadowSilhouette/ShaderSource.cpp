#include "ShaderSource.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/Notify>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>

#include <algorithm>
#include <cstring>
#include <sstream>

namespace osgShadowSilhouette {
namespace detail {

std::string shaderPrelude()
{
    std::ostringstream s;
    s << "// osgShadowSilhouette: ShaderConstants\n"
      << "#define OSS_MAX_SCENE_LIGHTS " << shader::MAX_SCENE_LIGHTS << "\n"
      << "#define OSS_SCREEN_VISIBILITY_UNIT " << shader::SCREEN_VISIBILITY_IMAGE_UNIT << "\n";
    // Defaults of the defines the technique sets per view (OpenGL inserts those first), for a
    // program linked outside a shadowed scene.
    const std::pair<const char*, const char*> defaults[] = {
        {shader::DEFINE_MAX_SHADOW_LIGHTS, "1"},
        {shader::DEFINE_MAX_SHADOW_SLOTS, shader::DEFINE_MAX_SHADOW_LIGHTS},
        {shader::DEFINE_NUM_SHADOW_SLOTS, shader::DEFINE_MAX_SHADOW_SLOTS},
        {shader::DEFINE_SKIPPED_SLOTS, "0"},
        {shader::DEFINE_MAX_LIST_SLOTS, shader::DEFINE_MAX_SHADOW_LIGHTS},
    };
    for (const auto& d : defaults)
        s << "#ifndef " << d.first << "\n#define " << d.first << " " << d.second << "\n#endif\n";
    // The soft filters' constants (oss_filter.frag.glsl).
    s << "#define OSS_PCSS_MAX_RADIUS_TEXELS " << shader::PCSS_MAX_RADIUS_TEXELS << "\n"
      << "#define OSS_PCSS_SEARCH_TAPS " << shader::PCSS_SEARCH_TAPS << "\n"
      << "#define OSS_PCSS_FILTER_TAPS " << shader::PCSS_FILTER_TAPS << "\n";
    // The shadow maps' sampler: raw depths in SILHOUETTE_MAP and under SHADOW_MAP's soft
    // filters, which make their own comparisons (defined where a shader imports
    // OSS_SILHOUETTE_MAP, OSS_FILTER_PCF and OSS_FILTER_PCSS).
    s << "#if defined(OSS_SILHOUETTE_MAP) || defined(OSS_FILTER_PCF) || defined(OSS_FILTER_PCSS)\n"
         "#define OSS_SHADOW_SAMPLER sampler2D\n#else\n"
         "#define OSS_SHADOW_SAMPLER sampler2DShadow\n#endif\n";
    // SILHOUETTE_MAP's second maps: neighbourhood maps, or edge distances under FILTER_SILHOUETTE.
    s << "#ifdef OSS_FILTER_SILHOUETTE\n#define OSS_SILHOUETTE_SAMPLER sampler2D\n#else\n"
         "#define OSS_SILHOUETTE_SAMPLER usampler2D\n#endif\n"
      << "#define OSS_SILDIST_NO_EDGE " << std::scientific << shader::SILDIST_NO_EDGE << std::defaultfloat << "\n"
      << "#define OSS_SILDIST_SAMPLE_REACH " << std::fixed << shader::SILDIST_SAMPLE_REACH << std::defaultfloat << "\n";
    return s.str();
}

std::string withPrelude(const std::string& source)
{
    std::size_t at = 0, line = 1;
    const std::size_t version = source.find("#version");
    if (version != std::string::npos && source.find_first_not_of(" \t\r\n", 0) == version)
    {
        const std::size_t end = source.find('\n', version);
        if (end == std::string::npos) return source + "\n" + shaderPrelude();
        at = end + 1;
        line = 1 + std::size_t(std::count(source.begin(), source.begin() + at, '\n'));
    }
    return source.substr(0, at) + shaderPrelude() + "#line " + std::to_string(line) + "\n" + source.substr(at);
}

osg::ref_ptr<osg::Shader> loadShader(osg::Shader::Type type, const std::string& name)
{
    const std::string path = osgDB::findDataFile("osgShadowSilhouette/shaders/" + name);
    if (!path.empty())
    {
        osg::ref_ptr<osg::Shader> shader = osgDB::readRefShaderFile(type, path);
        if (shader.valid())
        {
            OSG_INFO << "osgShadowSilhouette: shader " << name << " read from " << path << std::endl;
            shader->setShaderSource(withPrelude(shader->getShaderSource()));
            shader->setName(name);
            return shader;
        }
        OSG_WARN << "osgShadowSilhouette: cannot read shader file " << path << "; using the built-in " << name
                 << std::endl;
    }
    for (const EmbeddedShader* s = embeddedShaders(); s->name; ++s)
    {
        if (name == s->name)
        {
            osg::ref_ptr<osg::Shader> shader = new osg::Shader(type, withPrelude(s->source));
            shader->setName(name);
            return shader;
        }
    }
    OSG_WARN << "osgShadowSilhouette: no shader named " << name << std::endl;
    return nullptr;
}

} // namespace detail
} // namespace osgShadowSilhouette
