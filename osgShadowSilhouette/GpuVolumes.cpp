#include "GpuVolumes.h"

#include "RenderLeaves.h"

#include <osgShadowSilhouette/ShaderConstants>

#include <osg/FrontFace>
#include <osg/PolygonOffset>

namespace osgShadowSilhouette {
namespace detail {

GpuVolumes::GpuVolumes(osg::Program* sides, osg::Program* cap, CasterVertexStages* stages,
                       AdjacencyDrawables* adjacency)
    : GpuCasterDraws(stages, adjacency), _sidesProgram(sides), _capProgram(cap)
{
}

GpuVolumes::~GpuVolumes() = default;

unsigned int GpuVolumes::ruleOf(const Caster& caster, bool mirrored) const
{
    // The bits of oss_gpuVolumeRule (oss_gpuvolume.geom.glsl).
    static_assert(Caster::CULLS_CCW == 1 && Caster::CULLS_CW == 2, "the rule's bits 4 and 8");
    const bool twoSided = !caster.closed;
    return (twoSided ? 1u : 0u) | (!twoSided && mirrored ? 2u : 0u) | (unsigned(caster.culledWindings) << 2);
}

GpuVolumes::Light GpuVolumes::createLight(const osg::StateSet& volumeState, const osg::StateSet& zfailStencil,
                                          const osg::StateSet& lightCapOffset) const
{
    const auto on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    const auto protectedOn = on | osg::StateAttribute::PROTECTED;
    Light light;
    light.position = new osg::Uniform(shader::GPU_VOLUME_LIGHT, osg::Vec4f());
    light.sides = new osg::StateSet(volumeState, osg::CopyOp::SHALLOW_COPY);
    // The casters' own render bins do not take their volumes elsewhere.
    light.sides->setRenderBinDetails(volumeState.getBinNumber(), volumeState.getBinName(),
                                     osg::StateSet::OVERRIDE_RENDERBIN_DETAILS);
    light.sides->setAttributeAndModes(_sidesProgram.get(), protectedOn);
    for (const auto& attribute : zfailStencil.getAttributeList())
        light.sides->setAttributeAndModes(attribute.second.first.get(), on);
    light.sides->setAttribute(new osg::FrontFace(osg::FrontFace::COUNTER_CLOCKWISE), protectedOn);
    light.sides->addUniform(light.position.get(), on);
    light.sides->addUniform(new osg::Uniform(shader::GPU_VOLUME_RULE, 0)); // the classic rule (ruleOf())
    light.cap = new osg::StateSet(*light.sides, osg::CopyOp::SHALLOW_COPY);
    for (const auto& attribute : lightCapOffset.getAttributeList())
        light.cap->setAttributeAndModes(attribute.second.first.get(), protectedOn);
    light.cap->setAttributeAndModes(_capProgram.get(), protectedOn);
    return light;
}

std::size_t GpuVolumes::cull(osgUtil::CullVisitor& cv, Light& passes, const osg::Vec4d& light,
                             const std::vector<Caster>& casters, const CullCasters& cullCasters)
{
    const std::unordered_map<const osg::Drawable*, const Caster*> extruded = takenByDrawable(casters);
    if (extruded.empty()) return 0;
    osg::Vec4d eye = light * *cv.getModelViewMatrix();
    if (eye.w() != 0.0) eye /= eye.w();
    passes.position->set(osg::Vec4f(eye));
    std::size_t culled = 0;
    for (osg::StateSet* pass : {passes.sides.get(), passes.cap.get()})
    {
        cullCasters(pass);
        osgUtil::RenderBin* bin = cv.getCurrentRenderBin();
        if (bin && bin->getStage()) culled = prepareLeaves(*bin->getStage(), *pass, extruded);
    }
    return culled;
}

} // namespace detail
} // namespace osgShadowSilhouette
