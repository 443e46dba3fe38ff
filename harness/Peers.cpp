#include "Peers.h"

#include <osg/LightModel>
#include <algorithm>
#include <osg/Material>
#include <osg/Texture2D>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#include <osgShadow/ParallelSplitShadowMap>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>
#include <osgShadow/SoftShadowMap>
#include <osgShadow/ViewDependentShadowMap>

namespace osshar {

const char* const PEER_PREFIX = "osgShadow:";

namespace {

const osg::Vec2 AMBIENT_BIAS(0.0f, 1.0f);

/** PSSM's shadow-casting polygon offset (factor, units): LiSPSM's and VDSM's own, which PSSM
 *  lacks (it has none by default and biases only by a constant depth in its shader). */
const osg::Vec2 PSSM_POLYGON_OFFSET(1.1f, 4.0f);

/** Unshadowed luminance at or below this (of 255) counts as black. */
const double BLACK_LUMINANCE = 1.0;

/** The largest map size handed to a peer. */
const unsigned int MAX_MAP_SIZE = 16384;

osg::Vec2s squareSize(unsigned int mapSize)
{
    const short n = static_cast<short>(std::min(mapSize, MAX_MAP_SIZE));
    return osg::Vec2s(n, n);
}

osg::ref_ptr<osg::Texture2D> whiteTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    unsigned char* p = image->data();
    p[0] = p[1] = p[2] = p[3] = 255;
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image.get());
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    return texture;
}

osg::ref_ptr<osg::Material> whiteMaterial()
{
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setColorMode(osg::Material::OFF);
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 1, 1, 1));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 1, 1, 1));
    m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    m->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    m->setShininess(osg::Material::FRONT_AND_BACK, 0.0f);
    return m;
}

bool isBackground(const unsigned char* rgb)
{
    return rgb[0] > 250 && rgb[1] < 5 && rgb[2] > 250;
}

osg::Light* measuredLight(const PreparedScene& scene)
{
    return scene.lights.empty() ? nullptr : scene.lights.front().source->getLight();
}

/** The world direction `light` shines in, as PSSM reads a user light's getDirection() (it
 *  shadows directional light only): a light with a position shines from there toward `target`. */
osg::Vec3 pssmDirection(const osg::Light& light, const osg::Matrixd& localToWorld, const osg::Vec3d& target)
{
    const osg::Vec4d p = osg::Vec4d(light.getPosition()) * localToWorld;
    osg::Vec3d direction =
        p.w() == 0.0 ? -osg::Vec3d(p.x(), p.y(), p.z()) : target - osg::Vec3d(p.x(), p.y(), p.z()) / p.w();
    direction.normalize();
    return osg::Vec3(direction);
}

/** PSSM's user light: a copy of `light` shining in pssmDirection(). */
osg::ref_ptr<osg::Light> pssmLight(const osg::Light& light, const osg::Matrixd& localToWorld, const osg::Vec3d& target)
{
    osg::ref_ptr<osg::Light> user = new osg::Light(light);
    user->setDirection(pssmDirection(light, localToWorld, target));
    return user;
}

/** Keeps PSSM's user light (a copy) shining as the scene's light does, every frame: a light
 *  the renderer moves (--moving-light, --rotating-light) moves PSSM's shadows too. */
class PssmLightFollower : public osg::NodeCallback
{
public:
    PssmLightFollower(const osg::Light* light, osg::Light* user, const osg::Matrixd& localToWorld,
                      const osg::Vec3d& target)
        : _light(light), _user(user), _localToWorld(localToWorld), _target(target)
    {
    }
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        osg::ref_ptr<const osg::Light> light;
        if (_light.lock(light)) _user->setDirection(pssmDirection(*light, _localToWorld, _target));
        traverse(node, nv);
    }

private:
    osg::observer_ptr<const osg::Light> _light;
    osg::ref_ptr<osg::Light> _user;
    osg::Matrixd _localToWorld;
    osg::Vec3d _target;
};

} // namespace

osg::Vec4 peerBackground()
{
    return osg::Vec4(1.0f, 0.0f, 1.0f, 1.0f);
}

std::vector<std::string> peerModes()
{
    return {"osgShadow:ShadowMap", "osgShadow:SoftShadowMap", "osgShadow:LightSpacePerspectiveShadowMapCB",
            "osgShadow:ViewDependentShadowMap", "osgShadow:ParallelSplitShadowMap"};
}

bool isPeerMode(const std::string& mode)
{
    return mode.rfind(PEER_PREFIX, 0) == 0;
}

osg::ref_ptr<osgShadow::ShadowTechnique> createPeerTechnique(const std::string& mode, unsigned int mapSize, osg::Light* light,
                                                             osgShadow::ShadowSettings& settings, std::string& error)
{
    const std::string name = isPeerMode(mode) ? mode.substr(std::string(PEER_PREFIX).size()) : mode;
    settings.setTextureSize(squareSize(mapSize));
    if (light) settings.setLightNum(light->getLightNum());
    if (name == "ShadowMap" || name == "SoftShadowMap")
    {
        osg::ref_ptr<osgShadow::ShadowMap> sm =
            name == "ShadowMap" ? new osgShadow::ShadowMap : new osgShadow::SoftShadowMap;
        sm->setTextureSize(squareSize(mapSize));
        sm->setAmbientBias(AMBIENT_BIAS);
        if (light) sm->setLight(light);
        return sm;
    }
    if (name == "LightSpacePerspectiveShadowMapCB")
    {
        osg::ref_ptr<osgShadow::LightSpacePerspectiveShadowMapCB> lispsm = new osgShadow::LightSpacePerspectiveShadowMapCB;
        lispsm->setTextureSize(squareSize(mapSize));
        if (light) lispsm->setLight(light);
        return lispsm;
    }
    if (name == "ViewDependentShadowMap") return new osgShadow::ViewDependentShadowMap;
    if (name == "ParallelSplitShadowMap")
    {
        osg::ref_ptr<osgShadow::ParallelSplitShadowMap> pssm = new osgShadow::ParallelSplitShadowMap;
        pssm->setTextureResolution(std::min(mapSize, MAX_MAP_SIZE));
        // Its default (0.1, 0.3) shades a shadow at 77% of the unshadowed frame: classified lit.
        pssm->setAmbientBias(AMBIENT_BIAS);
        pssm->setPolygonOffset(PSSM_POLYGON_OFFSET);
        if (light) pssm->setUserLight(pssmLight(*light, osg::Matrixd::identity(), osg::Vec3d()).get());
        return pssm;
    }
    error = "unknown osgShadow technique '" + mode +
            "' (known: ShadowMap, SoftShadowMap, LightSpacePerspectiveShadowMapCB, ViewDependentShadowMap, "
            "ParallelSplitShadowMap)";
    return nullptr;
}

void applyMeasurementLight(PreparedScene& scene)
{
    osg::Light* light = measuredLight(scene);
    if (!light) return;
    light->setAmbient(osg::Vec4(0, 0, 0, 1));
    light->setDiffuse(osg::Vec4(1, 1, 1, 1));
    light->setSpecular(osg::Vec4(0, 0, 0, 1));
}

osg::ref_ptr<osg::StateSet> measurementStateSet(const PreparedScene& scene)
{
    const osg::StateAttribute::GLModeValue on = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE;
    const osg::StateAttribute::GLModeValue off = osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE;
    osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
    ss->setAttributeAndModes(whiteMaterial().get(), on);
    osg::ref_ptr<osg::LightModel> lm = new osg::LightModel;
    lm->setAmbientIntensity(osg::Vec4(0, 0, 0, 1));
    ss->setAttributeAndModes(lm.get(), on);
    // Texture unit 0: white for the shaders that sample it, off for the fixed function.
    ss->setTextureAttribute(0, whiteTexture().get(), osg::StateAttribute::OVERRIDE);
    ss->setTextureMode(0, GL_TEXTURE_2D, off);
    ss->setMode(GL_LIGHTING, on);
    const osg::Light* light = measuredLight(scene);
    for (int i = 0; i < 8; ++i)
        ss->setMode(GL_LIGHT0 + i, light && light->getLightNum() == i ? on : off);
    return ss;
}

bool makePeerRoot(const std::string& mode, unsigned int mapSize, PreparedScene& scene, osg::ref_ptr<osg::Node>& root,
                  std::string& error)
{
    applyMeasurementLight(scene);
    osg::ref_ptr<osgShadow::ShadowedScene> ss = new osgShadow::ShadowedScene;
    osg::ref_ptr<osgShadow::ShadowTechnique> technique =
        createPeerTechnique(mode, mapSize, measuredLight(scene), *ss->getShadowSettings(), error);
    if (!technique) return false;
    // PSSM takes its user light's direction as given in world coordinates.
    auto* pssm = dynamic_cast<osgShadow::ParallelSplitShadowMap*>(technique.get());
    if (pssm && !scene.lights.empty())
    {
        const osg::Vec3d target = scene.content->getBound().center();
        const osg::Matrixd& localToWorld = scene.lights.front().localToWorld;
        const osg::ref_ptr<osg::Light> user = pssmLight(*measuredLight(scene), localToWorld, target);
        pssm->setUserLight(user.get());
        ss->addUpdateCallback(new PssmLightFollower(measuredLight(scene), user.get(), localToWorld, target));
    }
    ss->setShadowTechnique(technique.get());
    ss->addChild(scene.content.get());
    ss->setStateSet(measurementStateSet(scene).get());
    root = ss;
    return true;
}

osg::ref_ptr<osg::Node> makeUnshadowedRoot(const PreparedScene& scene)
{
    osg::ref_ptr<osg::Group> group = new osg::Group;
    group->addChild(scene.content.get());
    group->setStateSet(measurementStateSet(scene).get());
    return group;
}

double luminance(const unsigned char* rgb)
{
    return 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2];
}

PeerMask classifyPeerFrames(const osg::Image& shadowed, const osg::Image& unshadowed)
{
    const int w = shadowed.s(), h = shadowed.t();
    PeerMask out;
    if (w != unshadowed.s() || h != unshadowed.t() || shadowed.getPixelFormat() != GL_RGB ||
        unshadowed.getPixelFormat() != GL_RGB)
        return out;
    out.mask = ossref::Mask::filled(w, h);
    out.vertexFacing = ossref::Mask::filled(w, h);
    out.visibility = ossref::VisibilityMask::filled(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
        {
            const unsigned char* s = shadowed.data(x, y);
            const unsigned char* u = unshadowed.data(x, y);
            const std::size_t i = std::size_t(h - 1 - y) * w + x; // row 0 = top
            const double lu = luminance(u);
            const bool black = lu <= BLACK_LUMINANCE;
            if (!isBackground(u)) out.vertexFacing.value[i] = black ? ossref::MASK_NO_LIGHT : ossref::MASK_LIT;
            if (isBackground(s)) continue;
            const bool dark = black || luminance(s) <= 0.5 * lu;
            out.mask.value[i] = dark ? ossref::MASK_NO_LIGHT : ossref::MASK_LIT;
            out.visibility.value[i] = ossref::encodeVisibility(black ? 0.0 : std::min(1.0, luminance(s) / lu));
        }
    return out;
}

PeerMask renderPeerMask(Renderer& renderer, osg::Node* peerRoot, osg::Node* unshadowed)
{
    renderer.setSceneData(peerRoot);
    renderer.viewer().frame(); // the technique is initialised in an update traversal
    osg::ref_ptr<osg::Image> shadowed = renderer.renderAndCapture(peerBackground());
    renderer.setSceneData(unshadowed);
    osg::ref_ptr<osg::Image> plain = renderer.renderAndCapture(peerBackground());
    renderer.setSceneData(peerRoot);
    if (!shadowed || !plain) return PeerMask{};
    return classifyPeerFrames(*shadowed, *plain);
}

ossref::Mask referenceFacing(const osg::Node& content, const ossref::Camera& camera, const ossref::Light& light)
{
    return ossref::computeReferenceMask(content, camera, light, /*castsMask*/ 0u);
}

ossref::Mask excludeFacingDisagreement(const ossref::Mask& reference, const ossref::Mask& faceFacing,
                                       const ossref::Mask& vertexFacing, long long& excluded)
{
    ossref::Mask out = reference;
    excluded = 0;
    const std::size_t n = out.value.size();
    if (faceFacing.value.size() != n || vertexFacing.value.size() != n) return out;
    out.grazing.resize(n, 0);
    for (std::size_t i = 0; i < n; ++i)
    {
        const uint8_t f = faceFacing.value[i], v = vertexFacing.value[i];
        if (out.grazing[i] || out.value[i] == ossref::MASK_BACKGROUND || f == ossref::MASK_BACKGROUND ||
            v == ossref::MASK_BACKGROUND || f == v)
            continue;
        out.grazing[i] = 1;
        ++excluded;
    }
    return out;
}

} // namespace osshar
