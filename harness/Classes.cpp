#include "Classes.h"

#include <cstdlib>

namespace osshar {

ClassCounts countClasses(const osg::Image& image)
{
    ClassCounts c;
    const unsigned int channels = osg::Image::computeNumComponents(image.getPixelFormat());
    if (image.getDataType() != GL_UNSIGNED_BYTE || channels < 3) return c;
    const auto near = [](int v, int target) { return std::abs(v - target) <= 24; };
    for (int y = 0; y < image.t(); ++y)
    {
        const unsigned char* p = image.data(0, y);
        for (int x = 0; x < image.s(); ++x, p += channels)
        {
            const int r = p[0], g = p[1], b = p[2];
            if (near(r, 128) && near(g, 128) && near(b, 128)) continue; // background
            ++c.geometry;
            if (near(r, 0) && near(g, 255) && near(b, 0)) ++c.silhouetteLit;
            else if (near(r, 0) && near(g, 0) && near(b, 0)) ++c.silhouetteShadow;
            else if (near(r, 255) && near(g, 0) && near(b, 0)) ++c.mapLit;
            else if (near(r, 0) && near(g, 0) && near(b, 255)) ++c.mapShadow;
            else ++c.other;
        }
    }
    return c;
}

osg::ref_ptr<osg::Image> renderClasses(Renderer& renderer, osgShadowSilhouette::SilhouetteShadowTechnique& technique,
                                       unsigned int light)
{
    using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;
    const Technique::DebugView view = technique.getDebugView();
    const unsigned int debugLight = technique.getDebugLight();
    technique.setDebugView(Technique::DEBUG_CLASSES);
    technique.setDebugLight(light);
    osg::ref_ptr<osg::Image> image = renderer.renderAndCapture(osg::Vec4(128 / 255.0f, 128 / 255.0f, 128 / 255.0f, 1));
    technique.setDebugView(view);
    technique.setDebugLight(debugLight);
    return image;
}

} // namespace osshar
