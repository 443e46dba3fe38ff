#include <osgShadowSilhouette/ViewPoint>

#include <osg/CullingSet>
#include <osg/Viewport>
#include <osgUtil/CullVisitor>

#include <cmath>

namespace osgShadowSilhouette {

ViewPoint ViewPoint::fromCullVisitor(osgUtil::CullVisitor& cv)
{
    ViewPoint vp;
    const osg::RefMatrix* modelView = cv.getModelViewMatrix();
    const osg::RefMatrix* projection = cv.getProjectionMatrix();
    const osg::Viewport* viewport = cv.getViewport();
    if (!modelView || !projection || !viewport) return vp;
    vp.valid = true;
    vp.view = *modelView;
    vp.projection = *projection;
    vp.width = viewport->width();
    vp.height = viewport->height();
    vp.lodScale = cv.getLODScale();
    return vp;
}

float ViewPoint::lodRange(const osg::LOD& lod, const osg::Matrixd& world) const
{
    const osg::Matrixd modelView = world * view;
    if (lod.getRangeMode() == osg::LOD::DISTANCE_FROM_EYE_POINT)
    {
        // osg::NodeVisitor::getDistanceToViewPoint(centre, true) of a cull traversal.
        const osg::Vec3d eyeLocal = osg::Matrixd::inverse(modelView).getTrans();
        return float((osg::Vec3d(lod.getCenter()) - eyeLocal).length() * lodScale);
    }
    // osg::CullStack::clampedPixelSize(bound) / LOD scale.
    osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0.0, 0.0, width, height);
    const osg::Vec4 pixelSizeVector = osg::CullingSet::computePixelSizeVector(*viewport, projection, modelView);
    const osg::BoundingSphere& bound = lod.getBound();
    const float pixels = std::fabs(bound.radius() / (bound.center() * pixelSizeVector));
    return lodScale > 0.0f ? pixels / lodScale : pixels;
}

bool ViewPoint::isActive(const osg::LOD& lod, unsigned int child, const osg::Matrixd& world) const
{
    if (child >= lod.getNumChildren()) return false;
    if (child >= lod.getNumRanges()) return false; // osg::LOD::traverse draws only children with a range
    const float range = valid ? lodRange(lod, world) : 0.0f;
    return lod.getMinRange(child) <= range && range < lod.getMaxRange(child);
}

osg::Matrixd ViewPoint::billboardMatrix(const osg::Billboard& billboard, unsigned int index,
                                        const osg::Matrixd& world) const
{
    const osg::Vec3& position = billboard.getPosition(index);
    if (!valid) return osg::Matrixd::translate(position) * world;
    // Billboard::computeMatrix() reads the eye's up direction from a model-view matrix:
    // turn the drawable in eye space, as osgUtil::CullVisitor does, then leave the view.
    osg::Matrix modelView = world * view;
    const osg::Vec3 eyeLocal = osg::Matrixd::inverse(modelView).getTrans();
    billboard.computeMatrix(modelView, eyeLocal, position);
    return modelView * osg::Matrixd::inverse(view);
}

} // namespace osgShadowSilhouette
