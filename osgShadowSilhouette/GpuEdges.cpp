#include "GpuEdges.h"

#include <osgShadowSilhouette/ShaderConstants>

namespace osgShadowSilhouette {
namespace detail {

GpuEdges::GpuEdges(const osg::ref_ptr<osg::Program> (&programs)[MAP_COUNT], CasterVertexStages* stages,
                   AdjacencyDrawables* adjacency)
    : GpuCasterDraws(stages, adjacency)
{
    for (int map = 0; map < MAP_COUNT; ++map) _programs[map] = programs[map];
}

GpuEdges::~GpuEdges() = default;

unsigned int GpuEdges::ruleOf(const Caster& caster, bool) const
{
    return caster.closed ? 0u : 1u; // the bit TWO_SIDED of oss_gpuVolumeRule
}

osg::ref_ptr<osg::StateSet> GpuEdges::createPass(Map map, osg::Uniform* light) const
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> pass = new osg::StateSet;
    pass->setAttributeAndModes(_programs[map].get(), on | osg::StateAttribute::PROTECTED);
    pass->addUniform(light, on);
    pass->addUniform(new osg::Uniform(shader::GPU_VOLUME_RULE, 0));
    return pass;
}

std::size_t GpuEdges::cull(osgUtil::CullVisitor& cv, osg::StateSet& pass, const osg::Matrixd& view,
                           const TakenCasters& taken, const CullCasters& cullCasters)
{
    if (taken.empty() || !cullCasters) return 0;
    // The view's eye still chooses the LODs, as in the depth pass (CasterCollector's choice).
    cv.pushModelViewMatrix(new osg::RefMatrix(view), osg::Transform::ABSOLUTE_RF_INHERIT_VIEWPOINT);
    cullCasters(&pass);
    cv.popModelViewMatrix();
    osgUtil::RenderBin* bin = cv.getCurrentRenderBin();
    return bin && bin->getStage() ? prepareLeaves(*bin->getStage(), pass, taken) : 0;
}

} // namespace detail
} // namespace osgShadowSilhouette
