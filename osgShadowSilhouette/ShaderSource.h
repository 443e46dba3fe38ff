// Internal: the shaders embedded at build time, replaceable at run time.
#ifndef OSGSHADOWSILHOUETTE_SHADERSOURCE_H
#define OSGSHADOWSILHOUETTE_SHADERSOURCE_H

#include <osg/Shader>

#include <string>

namespace osgShadowSilhouette {
namespace detail {

struct EmbeddedShader
{
    const char* name;
    const char* source;
};

/** The table generated from the files in shaders/, ended by {nullptr, nullptr}. */
const EmbeddedShader* embeddedShaders();

/** The constants every shader shares, as GLSL defines generated from ShaderConstants
 *  (OSS_MAX_SCENE_LIGHTS, ...): loadShader() inserts them after a shader's #version line. */
std::string shaderPrelude();

/** `source` with shaderPrelude() after its #version line (at its start without one), and a
 *  #line directive that keeps the compiler's line numbers those of the file. */
std::string withPrelude(const std::string& source);

/** The shader file `name`: osgShadowSilhouette/shaders/<name> found through OSG_FILE_PATH if
 *  there is one (so shaders can be edited without rebuilding), else the embedded copy, with
 *  the prelude either way. Returns null, with a warning, when neither exists. */
osg::ref_ptr<osg::Shader> loadShader(osg::Shader::Type type, const std::string& name);

} // namespace detail
} // namespace osgShadowSilhouette

#endif
