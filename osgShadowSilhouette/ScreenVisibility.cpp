#include "ScreenVisibility.h"
#include "GLConstants.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/Depth>
#include <osg/GLExtensions>
#include <osg/State>

namespace osgShadowSilhouette {
namespace detail {

namespace {

/** glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT): image writes of the draws before it
 *  are visible to the image reads and atomics of the draws after it. */
class ImageBarrierDrawable : public osg::Drawable
{
public:
    ImageBarrierDrawable() { setUseDisplayList(false); }
    ImageBarrierDrawable(const ImageBarrierDrawable& d, const osg::CopyOp& op) : osg::Drawable(d, op) {}
    META_Object(osgShadowSilhouette, ImageBarrierDrawable);
    void drawImplementation(osg::RenderInfo& renderInfo) const override
    {
        const osg::GLExtensions* ext = renderInfo.getState()->get<osg::GLExtensions>();
        if (ext && ext->glMemoryBarrier) ext->glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    // No bounds: an ordering point, not geometry (it must not move the view's near plane).
    osg::BoundingBox computeBoundingBox() const override { return osg::BoundingBox(); }
};

} // namespace

ScreenVisibility::ScreenVisibility()
{
    _texture = new osg::Texture2D;
    _texture->setName("osgShadowSilhouette screen visibility");
    _texture->setInternalFormat(GL_R32UI);
    _texture->setSourceFormat(GL_RED_INTEGER);
    _texture->setSourceType(GL_UNSIGNED_INT);
    _texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    _texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    _texture->setResizeNonPowerOfTwoHint(false);
    _texture->setTextureSize(1, 1);
    _binding = new osg::BindImageTexture(shader::SCREEN_VISIBILITY_IMAGE_UNIT, _texture.get(),
                                         osg::BindImageTexture::READ_WRITE, GL_R32UI);

    _barrier = new osg::Geode;
    _barrier->setName("osgShadowSilhouette screen visibility barrier");
    osg::ref_ptr<ImageBarrierDrawable> barrier = new ImageBarrierDrawable;
    barrier->setCullingActive(false);
    _barrier->addDrawable(barrier.get());
    _barrier->setCullingActive(false);

    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    const auto off = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE;
    _finalPass = new osg::StateSet;
    _finalPass->setDefine(shader::DEFINE_SCREEN_VISIBILITY);
    // The receivers' own vertex stages meet the base pass's depths: ftransform() there.
    _finalPass->setAttribute(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false), on);
    _finalPass->setMode(GL_BLEND, off);
    _finalPass->setMode(GL_STENCIL_TEST, off);
}

ScreenVisibility::~ScreenVisibility() = default;

bool ScreenVisibility::supported(unsigned int contextID)
{
    const osg::GLExtensions* ext = osg::GLExtensions::Get(contextID, false);
    return ext && ext->glVersion >= 4.3f && ext->isBindImageTextureSupported() && ext->glMemoryBarrier; // GLSL 4.30
}

void ScreenVisibility::fit(const osg::Viewport& viewport)
{
    const int width = std::max(1, int(viewport.x() + viewport.width()));
    const int height = std::max(1, int(viewport.y() + viewport.height()));
    if (_texture->getTextureWidth() == width && _texture->getTextureHeight() == height) return;
    _texture->setTextureSize(width, height);
    _texture->dirtyTextureObject();
}

void ScreenVisibility::resizeGLObjectBuffers(unsigned int maxSize)
{
    _texture->resizeGLObjectBuffers(maxSize);
    _binding->resizeGLObjectBuffers(maxSize);
    _barrier->resizeGLObjectBuffers(maxSize);
    _finalPass->resizeGLObjectBuffers(maxSize);
}

void ScreenVisibility::releaseGLObjects(osg::State* state) const
{
    _texture->releaseGLObjects(state);
    _binding->releaseGLObjects(state);
    _barrier->releaseGLObjects(state);
    _finalPass->releaseGLObjects(state);
}

} // namespace detail
} // namespace osgShadowSilhouette
