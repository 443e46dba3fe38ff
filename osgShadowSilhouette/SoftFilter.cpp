#include "SoftFilter.h"

#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/NodeVisitor>
#include <osg/ValueObject>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace osgShadowSilhouette {
namespace detail {

namespace {

class FindSizedSources : public osg::NodeVisitor
{
public:
    FindSizedSources() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LightSource& source) override
    {
        if (source.getLight() && source.getUserDataContainer() &&
            source.getUserDataContainer()->getUserObject(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE))
            found->sources.emplace_back(source.getLight(), &source);
        traverse(source);
    }
    osg::ref_ptr<SizedLightSources> found = new SizedLightSources;
};

/** The user value named LIGHT_SIZE_USER_VALUE on @p object, as a double: false where there is
 *  none; @p text names what is there when it is no number. */
bool userSize(const osg::Object& object, double& value, std::string& text)
{
    const osg::UserDataContainer* udc = object.getUserDataContainer();
    const osg::Object* user = udc ? udc->getUserObject(SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE) : nullptr;
    if (!user) return false;
    if (const auto* d = dynamic_cast<const osg::DoubleValueObject*>(user))
        value = d->getValue();
    else if (const auto* f = dynamic_cast<const osg::FloatValueObject*>(user))
        value = f->getValue();
    else if (const auto* i = dynamic_cast<const osg::IntValueObject*>(user))
        value = i->getValue();
    else if (const auto* u = dynamic_cast<const osg::UIntValueObject*>(user))
        value = u->getValue();
    else
    {
        value = std::nan("");
        text = std::string("a ") + user->className();
        return true;
    }
    std::ostringstream s;
    s << value;
    text = s.str();
    return true;
}

} // namespace

osg::ref_ptr<SizedLightSources> findSizedLightSources(osg::Node& node)
{
    FindSizedSources find;
    node.accept(find);
    return find.found;
}

double lightSize(const osg::Light& light, const SizedLightSources* sources, LightDescription::Type type,
                 double techniqueSize, std::string& refusal)
{
    refusal.clear();
    double size = techniqueSize;
    std::string text, origin = "LightSize";
    if (userSize(light, size, text))
        origin = std::string("its osg::Light's user value ") + SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE;
    else if (sources)
    {
        for (const auto& s : sources->sources)
        {
            osg::ref_ptr<const osg::LightSource> source;
            if (s.first.get() != &light || !s.second.lock(source)) continue;
            if (userSize(*source, size, text))
                origin =
                    std::string("its LightSource's user value ") + SilhouetteShadowTechnique::LIGHT_SIZE_USER_VALUE;
            break;
        }
    }
    if (text.empty())
    {
        std::ostringstream s;
        s << size;
        text = s.str();
    }
    const bool directional = type == LightDescription::DIRECTIONAL;
    if (!std::isfinite(size) || size < 0.0)
        refusal = origin + " " + text + " is not a finite size of at least 0";
    else if (directional && size >= MAX_DIRECTIONAL_SIZE_DEG)
        refusal = origin + " " + text + " degrees is no directional light's angular radius (below 45)";
    if (!refusal.empty()) return 0.0;
    return size;
}

osg::Vec2 penumbraScale(const LightFrustum& frustum, LightDescription::Type type, double size)
{
    if (!frustum.valid || !(size > 0.0)) return osg::Vec2();
    const osg::Matrixd& p = frustum.projection;
    double perDepth = 0.0; // world size scale: tan(theta) / P22 or R / P32 (with the sign)
    if (type == LightDescription::DIRECTIONAL && !frustum.perspective)
        perDepth = p(2, 2) != 0.0 ? -std::tan(osg::DegreesToRadians(size)) / p(2, 2) : 0.0;
    else if (frustum.perspective)
        perDepth = p(3, 2) != 0.0 ? -size / p(3, 2) : 0.0;
    const osg::Vec2 scale(float(std::abs(p(0, 0) * perDepth)), float(std::abs(p(1, 1) * perDepth)));
    return std::isfinite(scale.x()) && std::isfinite(scale.y()) ? scale : osg::Vec2();
}

double filterReachTexels(SilhouetteShadowTechnique::Filter filter, unsigned int window)
{
    switch (filter)
    {
    case SilhouetteShadowTechnique::FILTER_PCF: return std::max(4.0, 0.5 * window + 2.0);
    case SilhouetteShadowTechnique::FILTER_PCSS: return double(shader::PCSS_MAX_RADIUS_TEXELS) + 2.0;
    // SILHOUETTE_MAP's: its samples lie up to SILDIST_SAMPLE_REACH from the point, and their
    // edges up to the distance band's width beyond them.
    case SilhouetteShadowTechnique::FILTER_SILHOUETTE:
        return double(shader::SILDIST_SAMPLE_REACH) + double(shader::SILDIST_MAX_WIDTH) + 2.0;
    case SilhouetteShadowTechnique::FILTER_PCF_2X2: break;
    }
    return 4.0;
}

} // namespace detail
} // namespace osgShadowSilhouette
