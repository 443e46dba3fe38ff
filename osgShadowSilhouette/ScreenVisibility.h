// Internal: the stencil modes' screen-space visibility, so that an application's own program
// on the receivers draws in SHADOW_VOLUME and HYBRID with stencil volumes too.
//
// The stencil buffer holds one light's answer at a time and no fragment shader can read it.
// With a program given to addShadowShaders(), the stencil passes leave each light's answer
// as one bit of an R32UI image the size of the viewport (oss_screen_visibility.frag.glsl):
// the base pass clears the pixel, each light pass sets its slot's bit where the stencil test
// lets the light through, and a final pass draws the receivers again with their own programs
// (or the receiver shading), whose oss_shadowTerm() reads the bit.
#ifndef OSGSHADOWSILHOUETTE_SCREENVISIBILITY_H
#define OSGSHADOWSILHOUETTE_SCREENVISIBILITY_H

#include <osg/BindImageTexture>
#include <osg/Geode>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osg/Viewport>

namespace osgShadowSilhouette {
namespace detail {

class ScreenVisibility : public osg::Referenced
{
public:
    ScreenVisibility();

    /** Whether context @p contextID binds images and orders their writes (GL 4.2's
     *  image load/store and glMemoryBarrier). */
    static bool supported(unsigned int contextID);

    /** Sizes the image to cover @p viewport in window coordinates (gl_FragCoord). */
    void fit(const osg::Viewport& viewport);

    osg::Texture2D* getTexture() const { return _texture.get(); }
    /** The image's binding (unit SCREEN_VISIBILITY_IMAGE_UNIT, read and write). */
    osg::BindImageTexture* getBinding() const { return _binding.get(); }
    /** A node that orders the image writes drawn before it before the reads after it. */
    osg::Node* getBarrier() const { return _barrier.get(); }
    /** The final pass: OSS_SCREEN_VISIBILITY, depth GL_LEQUAL without writes, no blending and
     *  no stencil test, no program of its own (the receivers' programs draw). */
    osg::StateSet* getFinalPass() const { return _finalPass.get(); }

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state = nullptr) const;

protected:
    ~ScreenVisibility() override;

    osg::ref_ptr<osg::Texture2D> _texture;
    osg::ref_ptr<osg::BindImageTexture> _binding;
    osg::ref_ptr<osg::Geode> _barrier;
    osg::ref_ptr<osg::StateSet> _finalPass;
};

} // namespace detail
} // namespace osgShadowSilhouette

#endif
