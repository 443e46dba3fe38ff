#include "SharedResources.h"

#include "DepthMapPass.h"
#include "ShaderSource.h"

#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteMapPass>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>
#include <osgShadowSilhouette/TriangleListPass>

#include <osg/ColorMask>

namespace osgShadowSilhouette {
namespace detail {

namespace {

osg::ref_ptr<osg::Program> createProgram(const char* name, const char* vertex, const char* fragment)
{
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(name);
    program->addShader(loadShader(osg::Shader::VERTEX, vertex));
    program->addShader(loadShader(osg::Shader::FRAGMENT, fragment));
    return program;
}

/** A shader of its own with @p define defined after the #version line of @p shader (not an OSG
 *  define, which a draw of the same program object with other defines may not recompile). */
osg::ref_ptr<osg::Shader> withDefine(const osg::Shader* shader, const char* define, const char* what)
{
    if (!shader) return nullptr;
    std::string source = shader->getShaderSource();
    source.insert(source.find('\n') + 1, std::string("#define ") + define + "\n");
    osg::ref_ptr<osg::Shader> own = new osg::Shader(shader->getType(), source);
    own->setName(shader->getName() + " (" + what + ")");
    return own;
}

/** The programs of the shadow geometry found on the GPU (GpuVolumes, GpuEdges), each watched
 *  by @p watchLink. */
void createGpuExtractionPrograms(SharedResources& r, const std::function<void(osg::Program*)>& watchLink)
{
    r.gpuVolumeProgram = createProgram("osgShadowSilhouette shadow volumes extruded on the GPU",
                                       shader::FILE_VOLUME_VERT, shader::FILE_VOLUME_FRAG);
    r.gpuVolumeCapProgram = createProgram("osgShadowSilhouette light caps extruded on the GPU",
                                          shader::FILE_VOLUME_VERT, shader::FILE_VOLUME_FRAG);
    const osg::ref_ptr<osg::Shader> extrusion = loadShader(osg::Shader::GEOMETRY, shader::FILE_GPU_VOLUME_GEOM);
    const osg::ref_ptr<osg::Shader> facing = loadShader(osg::Shader::GEOMETRY, shader::FILE_FACING_GEOM);
    r.gpuVolumeProgram->addShader(extrusion.get());
    r.gpuVolumeProgram->addShader(facing.get());
    r.gpuVolumeCapProgram->addShader(withDefine(extrusion.get(), shader::DEFINE_GPU_VOLUME_LIGHT_CAP, "light caps"));
    r.gpuVolumeCapProgram->addShader(facing.get());
    const osg::ref_ptr<osg::Shader> edges = withDefine(loadShader(osg::Shader::GEOMETRY, shader::FILE_SILMAP_GEOM),
                                                       shader::DEFINE_SILMAP_ADJACENCY, "triangles with adjacency");
    const char* edgeFragments[GpuEdges::MAP_COUNT] = {shader::FILE_SILMAP_FRAG, shader::FILE_SILNBR_FRAG,
                                                      shader::FILE_SILDIST_FRAG};
    for (int map = 0; map < GpuEdges::MAP_COUNT; ++map)
    {
        r.gpuEdgePrograms[map] = createProgram("osgShadowSilhouette silhouette edges found on the GPU",
                                               shader::FILE_SILMAP_VERT, edgeFragments[map]);
        r.gpuEdgePrograms[map]->addShader(edges.get());
        r.gpuEdgePrograms[map]->addShader(facing.get());
    }
    for (osg::Program* program : {r.gpuVolumeProgram.get(), r.gpuVolumeCapProgram.get()}) watchLink(program);
    for (const osg::ref_ptr<osg::Program>& program : r.gpuEdgePrograms) watchLink(program.get());
}

} // namespace

osg::ref_ptr<osg::StateSet> SharedResources::createPrepassStateSet() const
{
    const auto overrideOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setAttributeAndModes(prepassProgram.get(), overrideOn); // ftransform(), as the receivers' program
    ss->setAttribute(new osg::ColorMask(false, false, false, false), overrideOn);
    ss->addUniform(new osg::Uniform(shader::BASE_TEXTURE, 0)); // alpha-tested receivers' cut-outs
    ss->setRenderBinDetails(SilhouetteShadowTechnique::DEPTH_PREPASS_BIN, "RenderBin",
                            osg::StateSet::OVERRIDE_RENDERBIN_DETAILS);
    return ss;
}

osg::ref_ptr<SharedResources> createSharedResources(float polygonOffsetFactor, float polygonOffsetUnits,
                                                    const std::function<void(osg::Program*)>& linkShadowShaders,
                                                    const std::function<void(osg::Program*)>& watchLink)
{
    osg::ref_ptr<SharedResources> r = new SharedResources;
    r->receiverProgram =
        createProgram("osgShadowSilhouette receiver", shader::FILE_RECEIVER_VERT, shader::FILE_RECEIVER_FRAG);
    r->stencilProgram =
        createProgram("osgShadowSilhouette stencil passes", shader::FILE_RECEIVER_VERT, shader::FILE_STENCIL_FRAG);
    r->volumeProgram =
        createProgram("osgShadowSilhouette shadow volumes", shader::FILE_VOLUME_VERT, shader::FILE_VOLUME_FRAG);
    r->prepassProgram =
        createProgram("osgShadowSilhouette depth prepass", shader::FILE_DEPTH_VERT, shader::FILE_DEPTH_FRAG);
    createGpuExtractionPrograms(*r, watchLink);
    r->adjacency = new AdjacencyDrawables;
    // The lighting equation in the receivers' vertex and fragment stages, one source
    // (PerPixelLighting chooses where it runs).
    const osg::ref_ptr<osg::Shader> lighting[] = {loadShader(osg::Shader::VERTEX, shader::FILE_LIGHTING),
                                                  loadShader(osg::Shader::FRAGMENT, shader::FILE_LIGHTING),
                                                  loadShader(osg::Shader::FRAGMENT, shader::FILE_FRAGMENT_LIGHTING)};
    for (osg::Program* program : {r->receiverProgram.get(), r->stencilProgram.get()})
    {
        linkShadowShaders(program);
        for (const osg::ref_ptr<osg::Shader>& shader : lighting) program->addShader(shader.get());
    }
    // Each pass sets its mode's polygon offset factor (cullDepthMap()).
    r->depthPassStateSet = createDepthPassStateSet(polygonOffsetFactor, polygonOffsetUnits);
    r->silhouetteMapStateSet = SilhouetteMapPass::createSharedStateSet();
    r->listStateSet = TriangleListPass::createSharedStateSet();
    r->listFrontOnlyStateSet = new osg::StateSet;
    r->listFrontOnlyStateSet->addUniform(new osg::Uniform(shader::LIST_FRONT_ONLY, true));
    r->casterStages = new CasterVertexStages(watchLink);
    r->litDepthTexture = createLitTexture();
    r->litRawDepthTexture = SilhouetteMapPass::createLitDepthTexture();
    r->defaultSilhouetteTexture = SilhouetteMapPass::createDefaultTexture();
    r->defaultNeighbourhoodTexture = SilhouetteMapPass::createDefaultNeighbourhoodTexture();
    r->distanceMapStateSet = SilhouetteMapPass::createDistanceStateSet();
    r->defaultDistanceTexture = SilhouetteMapPass::createDefaultDistanceTexture();

    for (osg::Program* program : {r->volumeProgram.get(), r->prepassProgram.get()}) watchLink(program);
    for (osg::StateSet* ss :
         {r->depthPassStateSet.get(), r->listStateSet.get(), r->silhouetteMapStateSet.get(),
          r->distanceMapStateSet.get(), dynamic_cast<osg::StateSet*>(r->silhouetteMapStateSet->getUserData())})
        if (ss) watchLink(dynamic_cast<osg::Program*>(ss->getAttribute(osg::StateAttribute::PROGRAM)));
    return r;
}

} // namespace detail
} // namespace osgShadowSilhouette
