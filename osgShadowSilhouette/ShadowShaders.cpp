// SilhouetteShadowTechnique: the shadow term's shaders for applications' own programs, and
// the check that reports programs failing to link.
#include <osgShadowSilhouette/SilhouetteShadowTechnique>
#include <osgShadowSilhouette/ShaderConstants>

#include "ProgramLinkCheck.h"
#include "ShaderSource.h"

#include <algorithm>

#include <OpenThreads/ScopedLock>
#include <osg/observer_ptr>
#include <osgUtil/CullVisitor>

namespace osgShadowSilhouette {

void SilhouetteShadowTechnique::createShadowShaders() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_shadowShadersMutex);
    if (_shadowFragmentShader) return;
    _shadowFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SHADOW_FRAG);
    _silhouetteFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SILHOUETTE_FRAG);
    _listTermFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_TRILIST_TERM_FRAG);
    _screenVisibilityFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SCREEN_VISIBILITY_FRAG);
    _filterFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_FILTER_FRAG);
    _silhouetteFilterFragmentShader = detail::loadShader(osg::Shader::FRAGMENT, shader::FILE_SILHOUETTE_FILTER_FRAG);
}

std::vector<osg::ref_ptr<osg::Shader>> SilhouetteShadowTechnique::getShadowShaders() const
{
    createShadowShaders();
    std::vector<osg::ref_ptr<osg::Shader>> shaders;
    for (osg::Shader* s :
         {_shadowFragmentShader.get(), _silhouetteFragmentShader.get(), _listTermFragmentShader.get(),
          _screenVisibilityFragmentShader.get(), _filterFragmentShader.get(), _silhouetteFilterFragmentShader.get()})
        if (s) shaders.push_back(s); // a shader that cannot be found has been warned about
    return shaders;
}

void SilhouetteShadowTechnique::linkShadowShaders(osg::Program* program) const
{
    if (!program) return;
    for (const osg::ref_ptr<osg::Shader>& s : getShadowShaders()) program->addShader(s.get()); // skips those it holds
    watchProgramLink(program);
}

void SilhouetteShadowTechnique::addShadowShaders(osg::Program* program) const
{
    if (!program) return;
    linkShadowShaders(program);
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_shadowShadersMutex);
    for (const osg::observer_ptr<osg::Program>& known : _applicationPrograms)
        if (known == program) return;
    _applicationPrograms.emplace_back(program);
}

bool SilhouetteShadowTechnique::hasApplicationPrograms() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_shadowShadersMutex);
    _applicationPrograms.erase(std::remove_if(_applicationPrograms.begin(), _applicationPrograms.end(),
                                              [](const osg::observer_ptr<osg::Program>& p) { return !p.valid(); }),
                               _applicationPrograms.end());
    return !_applicationPrograms.empty();
}

osg::Shader* SilhouetteShadowTechnique::getShadowFragmentShader() const
{
    createShadowShaders();
    return _shadowFragmentShader.get();
}

osg::Shader* SilhouetteShadowTechnique::getSilhouetteFragmentShader() const
{
    createShadowShaders();
    return _silhouetteFragmentShader.get();
}

osg::Shader* SilhouetteShadowTechnique::getListTermFragmentShader() const
{
    createShadowShaders();
    return _listTermFragmentShader.get();
}

void SilhouetteShadowTechnique::watchProgramLink(osg::Program* program) const
{
    if (!program) return;
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_shadowShadersMutex);
        if (!_programLinkCheck) _programLinkCheck = new detail::ProgramLinkCheck;
    }
    static_cast<detail::ProgramLinkCheck*>(_programLinkCheck.get())->watch(program);
}

void SilhouetteShadowTechnique::cullProgramLinkCheck(osgUtil::CullVisitor& cv) const
{
    osg::ref_ptr<osg::Drawable> check;
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_shadowShadersMutex);
        check = _programLinkCheck;
    }
    if (!check) return;
    cv.pushStateSet(static_cast<detail::ProgramLinkCheck*>(check.get())->getCheckStateSet());
    cv.addDrawableAndDepth(check.get(), cv.getModelViewMatrix(), 0.0f);
    cv.popStateSet();
}

} // namespace osgShadowSilhouette
