#include "SceneVisitors.h"

namespace osgShadowSilhouette {
namespace detail {

osg::BoundingBoxd boundsOf(osgShadow::ShadowedScene& scene, unsigned int mask, MeshCache& cache, const ViewPoint& view)
{
    FiniteBoundsVisitor cbv(cache, view);
    cbv.setTraversalMask(mask);
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) scene.getChild(i)->accept(cbv);
    const osg::BoundingBox& b = cbv.getBoundingBox();
    return b.valid() ? osg::BoundingBoxd(b._min, b._max) : osg::BoundingBoxd();
}

} // namespace detail
} // namespace osgShadowSilhouette
