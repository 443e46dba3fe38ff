#include "ShaderSource.h"

#include <osg/Notify>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>

#include <cstring>

namespace osgShadowSilhouette {
namespace detail {

osg::ref_ptr<osg::Shader> loadShader(osg::Shader::Type type, const std::string& name)
{
    const std::string path = osgDB::findDataFile("osgShadowSilhouette/shaders/" + name);
    if (!path.empty())
    {
        osg::ref_ptr<osg::Shader> shader = osgDB::readRefShaderFile(type, path);
        if (shader.valid())
        {
            OSG_INFO << "osgShadowSilhouette: shader " << name << " read from " << path << std::endl;
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
            osg::ref_ptr<osg::Shader> shader = new osg::Shader(type, s->source);
            shader->setName(name);
            return shader;
        }
    }
    OSG_WARN << "osgShadowSilhouette: no shader named " << name << std::endl;
    return nullptr;
}

} // namespace detail
} // namespace osgShadowSilhouette
