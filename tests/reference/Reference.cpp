// Exact reference masks by ray casting with Embree 3: scene collection, BVH building and
// the per-pixel primary and shadow rays. Mask comparison and images live in MaskTools.cpp.
#include "reference/Reference.h"

#include <embree3/rtcore.h>

#include <osg/Billboard>
#include <osg/BoundingBox>
#include <osg/Camera>
#include <osg/CullFace>
#include <osg/CullingSet>
#include <osg/FrontFace>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/Material>
#include <osg/Notify>
#include <osg/NodeVisitor>
#include <osg/Texture2D>
#include <osg/Transform>
#include <osg/TriangleFunctor>
#include <osg/TriangleIndexFunctor>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <type_traits>

namespace ossref {

namespace {

const double kInf = std::numeric_limits<double>::infinity();

bool isFinite(const osg::Vec3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

osg::Vec3d toVec3d(const osg::Vec2f& v) { return osg::Vec3d(v.x(), v.y(), 0.0); }
osg::Vec3d toVec3d(const osg::Vec2d& v) { return osg::Vec3d(v.x(), v.y(), 0.0); }
osg::Vec3d toVec3d(const osg::Vec3f& v) { return osg::Vec3d(v); }
osg::Vec3d toVec3d(const osg::Vec3d& v) { return v; }
osg::Vec3d toVec3d(const osg::Vec4f& v) { return osg::Vec3d(v.x(), v.y(), v.z()) / double(v.w()); }
osg::Vec3d toVec3d(const osg::Vec4d& v) { return osg::Vec3d(v.x(), v.y(), v.z()) / v.w(); }

template <class ArrayT>
void convertArray(const osg::Array& array, std::vector<osg::Vec3d>& out)
{
    const ArrayT& typed = static_cast<const ArrayT&>(array);
    out.reserve(typed.size());
    for (const auto& v : typed) out.push_back(toVec3d(v));
}

/** The vertex positions of `array` as doubles; false for unsupported array types. */
bool readVertices(const osg::Array* array, std::vector<osg::Vec3d>& out)
{
    if (!array) return false;
    switch (array->getType())
    {
    case osg::Array::Vec2ArrayType: convertArray<osg::Vec2Array>(*array, out); return true;
    case osg::Array::Vec2dArrayType: convertArray<osg::Vec2dArray>(*array, out); return true;
    case osg::Array::Vec3ArrayType: convertArray<osg::Vec3Array>(*array, out); return true;
    case osg::Array::Vec3dArrayType: convertArray<osg::Vec3dArray>(*array, out); return true;
    case osg::Array::Vec4ArrayType: convertArray<osg::Vec4Array>(*array, out); return true;
    case osg::Array::Vec4dArrayType: convertArray<osg::Vec4dArray>(*array, out); return true;
    default: return false;
    }
}

/** Receives triangles from the functors and forwards them to the collector. */
class TriangleCollector;

struct IndexSink
{
    TriangleCollector* collector = nullptr;
    const std::vector<osg::Vec3d>* vertices = nullptr;
    const osg::Vec2Array* texCoords = nullptr; // per vertex, or null
    void operator()(unsigned int a, unsigned int b, unsigned int c) const;
};

struct VertexSink
{
    TriangleCollector* collector = nullptr;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, bool = false) const;
};

float clamp01(float v)
{
    return std::isfinite(v) ? std::min(1.0f, std::max(0.0f, v)) : 0.0f;
}

bool alphaPasses(osg::AlphaFunc::ComparisonFunction func, float alpha, float ref)
{
    switch (func)
    {
    case osg::AlphaFunc::NEVER: return false;
    case osg::AlphaFunc::LESS: return alpha < ref;
    case osg::AlphaFunc::EQUAL: return alpha == ref;
    case osg::AlphaFunc::LEQUAL: return alpha <= ref;
    case osg::AlphaFunc::GREATER: return alpha > ref;
    case osg::AlphaFunc::NOTEQUAL: return alpha != ref;
    case osg::AlphaFunc::GEQUAL: return alpha >= ref;
    default: return true;
    }
}

/** One piece of GL state along the node path: an attribute (null for a mode) and the value
 *  it was set with (ON/OFF for a mode, with the OVERRIDE and PROTECTED bits). */
struct StateSlot
{
    const osg::StateAttribute* attribute = nullptr;
    unsigned int value = 0;
    bool set = false;

    /** osg::State::pushModeList / pushAttributeList: a value set with OVERRIDE stays in
     *  force below unless the incoming one is PROTECTED; otherwise the innermost wins. */
    void push(const osg::StateAttribute* incoming, unsigned int incomingValue)
    {
        if (set && (value & osg::StateAttribute::OVERRIDE) && !(incomingValue & osg::StateAttribute::PROTECTED)) return;
        attribute = incoming;
        value = incomingValue;
        set = true;
    }
    bool on() const { return set && (value & osg::StateAttribute::ON); }
};

/** The state that decides which fragments of a triangle the eye pass keeps: the alpha test
 *  and face culling. */
struct FragmentState
{
    StateSlot alphaTest; // GL_ALPHA_TEST
    StateSlot alphaFunc;
    StateSlot material;
    StateSlot texture;   // unit 0
    StateSlot texture2D; // GL_TEXTURE_2D on unit 0
    StateSlot cullFaceMode; // GL_CULL_FACE
    StateSlot cullFace;     // osg::CullFace
    StateSlot frontFace;    // osg::FrontFace

    void apply(const osg::StateSet& stateSet)
    {
        const osg::StateSet::ModeList& modes = stateSet.getModeList();
        const auto alphaTestMode = modes.find(GL_ALPHA_TEST);
        if (alphaTestMode != modes.end()) alphaTest.push(nullptr, alphaTestMode->second);
        const auto cullFaceModeValue = modes.find(GL_CULL_FACE);
        if (cullFaceModeValue != modes.end()) cullFaceMode.push(nullptr, cullFaceModeValue->second);
        if (const osg::StateSet::RefAttributePair* p = stateSet.getAttributePair(osg::StateAttribute::CULLFACE))
            cullFace.push(p->first.get(), p->second);
        if (const osg::StateSet::RefAttributePair* p = stateSet.getAttributePair(osg::StateAttribute::FRONTFACE))
            frontFace.push(p->first.get(), p->second);
        if (const osg::StateSet::RefAttributePair* p = stateSet.getAttributePair(osg::StateAttribute::ALPHAFUNC))
            alphaFunc.push(p->first.get(), p->second);
        if (const osg::StateSet::RefAttributePair* p = stateSet.getAttributePair(osg::StateAttribute::MATERIAL))
            material.push(p->first.get(), p->second);
        if (const osg::StateSet::RefAttributePair* p =
                stateSet.getTextureAttributePair(0, osg::StateAttribute::TEXTURE))
            texture.push(p->first.get(), p->second);
        const osg::StateSet::TextureModeList& textureModes = stateSet.getTextureModeList();
        if (!textureModes.empty())
        {
            const auto texture2DMode = textureModes[0].find(GL_TEXTURE_2D);
            if (texture2DMode != textureModes[0].end()) texture2D.push(nullptr, texture2DMode->second);
        }
    }

    /** The CulledSide of the triangles drawn in this state (OpenGL's defaults where nothing
     *  is set: culling off, CullFace BACK, FrontFace COUNTER_CLOCKWISE). */
    uint8_t culledSide() const
    {
        if (!cullFaceMode.on()) return CULL_NONE;
        const osg::CullFace* cull = dynamic_cast<const osg::CullFace*>(cullFace.attribute);
        const osg::FrontFace* front = dynamic_cast<const osg::FrontFace*>(frontFace.attribute);
        const bool ccwIsFront = !front || front->getMode() != osg::FrontFace::CLOCKWISE;
        const osg::CullFace::Mode mode = cull ? cull->getMode() : osg::CullFace::BACK;
        if (mode == osg::CullFace::FRONT_AND_BACK) return CULL_BOTH_SIDES;
        const bool cullsFront = mode == osg::CullFace::FRONT;
        return cullsFront == ccwIsFront ? CULL_CCW_SIDE : CULL_CW_SIDE;
    }
};

/** Walks the scene, accumulating Transform matrices, the casts flag of the path and the
 *  state that makes cut-outs. */
class TriangleCollector : public osg::NodeVisitor
{
public:
    TriangleCollector(unsigned int castsMask, unsigned int traversalMask, const Camera* camera, TriangleSoup& out)
        : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _castsMask(castsMask & traversalMask), _out(out),
          _camera(camera)
    {
        setTraversalMask(traversalMask);
    }

    void apply(osg::Node& node) override { inScope(node, [&] { traverse(node); }); }
    /** A camera at the root stands for the view: its children are the scene. Nested
     *  cameras are render passes or HUDs, not world geometry. */
    void apply(osg::Camera& camera) override
    {
        if (getNodePath().size() <= 1) inScope(camera, [&] { traverse(camera); });
    }
    void apply(osg::Transform& transform) override
    {
        const osg::Matrixd saved = _matrix;
        osg::Matrix local = _matrix;
        if (transform.computeLocalToWorldMatrix(local, this)) _matrix = local;
        inScope(transform, [&] { traverse(transform); });
        _matrix = saved;
    }
    /** With a camera, the children a cull traversal of that view draws (osgUtil's
     *  CullVisitor with LOD scale 1); without one, every child in range at distance 0
     *  (OSG's own choice for visitors that are not cull visitors). */
    void apply(osg::LOD& lod) override
    {
        if (!_camera) return apply(static_cast<osg::Group&>(lod));
        const float range = lodRange(lod);
        inScope(lod, [&] {
            const unsigned int n = std::min<unsigned int>(lod.getNumChildren(), lod.getNumRanges());
            for (unsigned int i = 0; i < n; ++i)
                if (lod.getMinRange(i) <= range && range < lod.getMaxRange(i)) lod.getChild(i)->accept(*this);
        });
    }
    /** With a camera, each drawable turned toward its eye as the CullVisitor turns it. */
    void apply(osg::Billboard& billboard) override
    {
        if (!_camera) return apply(static_cast<osg::Geode&>(billboard));
        // computeMatrix() reads the eye's up direction from a model-view matrix: turn the
        // drawable in eye space, then go back to world space.
        const osg::Vec3 eyeLocal = eyeInLocal();
        const osg::Matrixd view = viewMatrix();
        const osg::Matrixd viewToWorld = osg::Matrixd::inverse(view);
        inScope(billboard, [&] {
            const osg::Matrixd saved = _matrix;
            for (unsigned int i = 0; i < billboard.getNumDrawables(); ++i)
            {
                osg::Matrix modelView = saved * view;
                billboard.computeMatrix(modelView, eyeLocal, billboard.getPosition(i));
                _matrix = modelView * viewToWorld;
                billboard.getDrawable(i)->accept(*this);
            }
            _matrix = saved;
        });
    }
    void apply(osg::Drawable& drawable) override { inScope(drawable, [&] { addDrawable(drawable); }); }
    void apply(osg::Geometry& geometry) override { inScope(geometry, [&] { addGeometry(geometry); }); }

    /** One triangle in world coordinates: kept unless non-finite or of zero area. ta, tb,
     *  tc: its texture coordinates, used when the current drawable is a cut-out. */
    void addWorldTriangle(const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c,
                          const osg::Vec2f& ta = osg::Vec2f(), const osg::Vec2f& tb = osg::Vec2f(),
                          const osg::Vec2f& tc = osg::Vec2f())
    {
        const double area2 = ((b - a) ^ (c - a)).length2();
        if (!isFinite(a) || !isFinite(b) || !isFinite(c) || !(area2 > 0.0) || !std::isfinite(area2))
        {
            ++_out.skipped;
            return;
        }
        _out.vertices.push_back(a);
        _out.vertices.push_back(b);
        _out.vertices.push_back(c);
        _out.casts.push_back(_casts ? 1 : 0);
        // As cut-outs: the per-triangle table exists from the first culled triangle on.
        if (_culled != CULL_NONE || !_out.culled.empty())
        {
            _out.culled.resize(_out.casts.size() - 1, CULL_NONE);
            _out.culled.push_back(_culled);
        }
        // The per-triangle table exists from the first cut-out on: opaque scenes carry none.
        if (_cutout >= 0 || !_out.cutout.empty())
        {
            _out.cutout.resize(_out.casts.size() - 1, -1);
            _out.cutout.push_back(_cutout);
        }
        if (_cutout >= 0)
        {
            const bool textured = _out.cutouts[size_t(_cutout)].image.valid();
            _out.texCoords.push_back(textured ? ta : osg::Vec2f());
            _out.texCoords.push_back(textured ? tb : osg::Vec2f());
            _out.texCoords.push_back(textured ? tc : osg::Vec2f());
        }
    }

    const osg::Matrixd& matrix() const { return _matrix; }

private:
    template <class F>
    void inScope(const osg::Node& node, F&& body)
    {
        const bool saved = _casts;
        const FragmentState savedState = _state;
        _casts = _casts && (node.getNodeMask() & _castsMask) != 0;
        if (const osg::StateSet* stateSet = node.getStateSet()) _state.apply(*stateSet);
        body();
        _casts = saved;
        _state = savedState;
    }

    /** The alpha test in force for the current drawable, as an index into _out.cutouts, or
     *  -1 when every fragment passes it (no test, or an alpha that cannot vary and passes).
     *  `textured`: the drawable has texture coordinates on unit 0. */
    int currentCutout(bool textured)
    {
        const osg::AlphaFunc* func = dynamic_cast<const osg::AlphaFunc*>(_state.alphaFunc.attribute);
        if (!_state.alphaTest.on() || !func) return -1;
        AlphaCutout cutout;
        cutout.func = func->getFunction();
        cutout.ref = clamp01(func->getReferenceValue());
        if (const osg::Material* material = dynamic_cast<const osg::Material*>(_state.material.attribute))
            cutout.alphaScale = clamp01(material->getDiffuse(osg::Material::FRONT).a());
        const osg::Texture2D* texture = dynamic_cast<const osg::Texture2D*>(_state.texture.attribute);
        const osg::Image* image = texture ? texture->getImage() : nullptr;
        if (textured && _state.texture2D.on() && image && image->data() && image->s() > 0 && image->t() > 0)
        {
            cutout.image = image;
            cutout.wrapS = texture->getWrap(osg::Texture::WRAP_S);
            cutout.wrapT = texture->getWrap(osg::Texture::WRAP_T);
            cutout.nearest = texture->getFilter(osg::Texture::MAG_FILTER) == osg::Texture::NEAREST;
        }
        if (cutout.func == osg::AlphaFunc::ALWAYS ||
            (!cutout.image && alphaPasses(cutout.func, cutout.alphaScale, cutout.ref)))
            return -1;
        const auto key = std::make_tuple(cutout.image.get(), int(cutout.wrapS), int(cutout.wrapT), cutout.nearest,
                                         int(cutout.func), cutout.ref, cutout.alphaScale);
        const auto found = _cutoutIndex.find(key);
        if (found != _cutoutIndex.end()) return found->second;
        const int index = int(_out.cutouts.size());
        _out.cutouts.push_back(cutout);
        _cutoutIndex.emplace(key, index);
        return index;
    }

    void addGeometry(const osg::Geometry& geometry)
    {
        std::vector<osg::Vec3d> vertices;
        if (!readVertices(geometry.getVertexArray(), vertices))
        {
            addDrawable(geometry);
            return;
        }
        for (osg::Vec3d& v : vertices) v = v * _matrix;
        const osg::Vec2Array* texCoords = dynamic_cast<const osg::Vec2Array*>(geometry.getTexCoordArray(0));
        if (texCoords && ((texCoords->getBinding() != osg::Array::BIND_PER_VERTEX &&
                           texCoords->getBinding() != osg::Array::BIND_UNDEFINED) ||
                          texCoords->size() < vertices.size()))
            texCoords = nullptr;
        _cutout = currentCutout(texCoords != nullptr);
        _culled = _state.culledSide();
        osg::TriangleIndexFunctor<IndexSink> functor;
        functor.collector = this;
        functor.vertices = &vertices;
        functor.texCoords = _cutout >= 0 ? texCoords : nullptr;
        geometry.accept(functor);
        _cutout = -1;
        _culled = CULL_NONE;
    }

    void addDrawable(const osg::Drawable& drawable)
    {
        _cutout = currentCutout(false);
        _culled = _state.culledSide();
        osg::TriangleFunctor<VertexSink> functor;
        functor.collector = this;
        drawable.accept(functor);
        _cutout = -1;
        _culled = CULL_NONE;
    }

    osg::Vec3d eyeInLocal() const { return _camera->eye * osg::Matrixd::inverse(_matrix); }
    osg::Matrixd viewMatrix() const { return osg::Matrixd::lookAt(_camera->eye, _camera->center, _camera->up); }

    /** What osg::LOD compares with its ranges in a cull traversal: the distance from the eye
     *  to its centre, or the pixel size of its bounding sphere on the viewport. */
    float lodRange(const osg::LOD& lod) const
    {
        if (lod.getRangeMode() == osg::LOD::DISTANCE_FROM_EYE_POINT)
            return float((osg::Vec3d(lod.getCenter()) - eyeInLocal()).length());
        const osg::Matrixd view = viewMatrix();
        const osg::Matrixd projection =
            osg::Matrixd::perspective(_camera->fovyDeg, _camera->width / double(_camera->height), 1.0, 2.0);
        osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0, 0, _camera->width, _camera->height);
        const osg::Vec4 pixelSizeVector =
            osg::CullingSet::computePixelSizeVector(*viewport, projection, _matrix * view);
        const osg::BoundingSphere& bound = lod.getBound();
        return std::fabs(bound.radius() / (bound.center() * pixelSizeVector));
    }

    unsigned int _castsMask;
    TriangleSoup& _out;
    const Camera* _camera;
    osg::Matrixd _matrix;
    bool _casts = true;
    FragmentState _state;
    int _cutout = -1;            // of the drawable being collected
    uint8_t _culled = CULL_NONE; // of the drawable being collected
    std::map<std::tuple<const osg::Image*, int, int, bool, int, float, float>, int> _cutoutIndex;
};

void IndexSink::operator()(unsigned int a, unsigned int b, unsigned int c) const
{
    const size_t n = vertices->size();
    if (a >= n || b >= n || c >= n) return;
    if (texCoords)
        collector->addWorldTriangle((*vertices)[a], (*vertices)[b], (*vertices)[c], (*texCoords)[a], (*texCoords)[b],
                                    (*texCoords)[c]);
    else
        collector->addWorldTriangle((*vertices)[a], (*vertices)[b], (*vertices)[c]);
}

void VertexSink::operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, bool) const
{
    const osg::Matrixd& m = collector->matrix();
    collector->addWorldTriangle(osg::Vec3d(a) * m, osg::Vec3d(b) * m, osg::Vec3d(c) * m);
}

/** Rays of a camera: eye-space direction per window point, taken to world space. */
struct RayFrame
{
    explicit RayFrame(const Camera& camera)
        : toWorld(osg::Matrixd::inverse(osg::Matrixd::lookAt(camera.eye, camera.center, camera.up))),
          origin(osg::Vec3d(0.0, 0.0, 0.0) * toWorld),
          tanHalf(std::tan(osg::DegreesToRadians(camera.fovyDeg) * 0.5)),
          aspect(camera.width / double(camera.height)),
          width(camera.width),
          height(camera.height)
    {
    }

    osg::Vec3d direction(double winX, double winY) const
    {
        const double ndcX = 2.0 * winX / width - 1.0;
        const double ndcY = 2.0 * winY / height - 1.0;
        osg::Vec3d d = osg::Matrixd::transform3x3(osg::Vec3d(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0), toWorld);
        d.normalize();
        return d;
    }

    osg::Matrixd toWorld;
    osg::Vec3d origin;
    double tanHalf;
    double aspect;
    int width;
    int height;
};

/** A light in the tracer's recentred frame, ready for per-point queries. */
struct LightFrame
{
    LightFrame(const Light& light, const osg::Vec3d& centre)
        : directional(light.type == Light::DIRECTIONAL), direction(light.vector), position(light.vector - centre),
          spotAxis(light.spotDirection)
    {
        valid = direction.normalize() > 0.0 && isFinite(direction);
        spot = light.type == Light::SPOT && light.spotCutoffDeg < 180.0 && spotAxis.normalize() > 0.0;
        cosCutoff = std::cos(osg::DegreesToRadians(std::max(0.0, light.spotCutoffDeg)));
        if (!directional) valid = isFinite(position);
        sized = light.size > 0.0 && std::isfinite(light.size);
        if (sized && directional) cosAngle = std::cos(osg::DegreesToRadians(std::min(180.0, light.size)));
        if (sized && !directional) radius = light.size;
    }

    /** Normalised direction from p toward the light and the distance to it. */
    osg::Vec3d toLight(const osg::Vec3d& p, double& distance) const
    {
        if (directional)
        {
            distance = kInf;
            return direction;
        }
        osg::Vec3d d = position - p;
        distance = d.normalize();
        return d;
    }

    bool inCone(const osg::Vec3d& p) const
    {
        if (!spot) return true;
        osg::Vec3d fromLight = p - position;
        if (fromLight.normalize() == 0.0) return true;
        return fromLight * spotAxis >= cosCutoff;
    }

    bool directional;
    bool valid = true;
    bool spot = false;
    bool sized = false; // a sphere or a cone, not a point or a single direction
    double cosCutoff = -1.0;
    double radius = 0.0;   // POINT, SPOT: the sphere's
    double cosAngle = 1.0; // DIRECTIONAL: cosine of the cone's angular radius
    osg::Vec3d direction;
    osg::Vec3d position;
    osg::Vec3d spotAxis;
};

struct PixelResult
{
    uint8_t value = MASK_BACKGROUND;
    uint8_t grazing = 0;
    float distance = std::numeric_limits<float>::infinity(); ///< eye to the visible point
};

struct PixelVisibility
{
    uint16_t value = VIS_BACKGROUND;
    uint8_t grazing = 0;
};

/** The point a primary ray sees: p on its triangle's plane, n the unit geometric normal
 *  turned toward the camera. Both in the tracer's recentred frame. */
struct SurfacePoint
{
    osg::Vec3d p;
    osg::Vec3d n;
};

/** A unit basis (b1, b2) of the plane perpendicular to the unit vector n (Duff et al.,
 *  "Building an Orthonormal Basis, Revisited", JCGT 2017). */
void basisAround(const osg::Vec3d& n, osg::Vec3d& b1, osg::Vec3d& b2)
{
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double b = n.x() * n.y() * a;
    b1 = osg::Vec3d(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    b2 = osg::Vec3d(b, sign + n.y() * n.y() * a, -n.y());
}

/** A light with a size as one visible point p sees it (computeReferenceVisibility): a
 *  disk around the light's position perpendicular to the direction from p, or the cone
 *  of directions around the light's direction. Maps a point of the unit square to a
 *  shadow ray, keeping areas. */
struct LightSampler
{
    LightSampler(const LightFrame& light, const osg::Vec3d& p) : light(light)
    {
        axis = light.directional ? light.direction : light.position - p;
        axis.normalize();
        basisAround(axis, b1, b2);
    }

    /** The unit direction from `start` toward sample s of the light, and the distance to
     *  that point of the light (infinite for a directional light). */
    osg::Vec3d toward(const osg::Vec3d& start, const osg::Vec2d& s, double& distance) const
    {
        const double azimuth = 2.0 * osg::PI * s.y();
        const osg::Vec3d across = b1 * std::cos(azimuth) + b2 * std::sin(azimuth);
        if (light.directional)
        {
            const double cosA = 1.0 - s.x() * (1.0 - light.cosAngle);
            distance = kInf;
            return axis * cosA + across * std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
        }
        osg::Vec3d d = light.position + across * (light.radius * std::sqrt(s.x())) - start;
        distance = d.normalize();
        return d;
    }

    const LightFrame& light;
    osg::Vec3d axis, b1, b2;
};

/** SplitMix64 (Steele, Lea and Flood, 2014): a stream of 64-bit numbers from a seed. */
struct SplitMix64
{
    uint64_t state;

    uint64_t next()
    {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /** Uniform in [0, 1): the top 53 bits. */
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
};

/** The fixed seed of every sample pattern of the reference. */
const uint64_t kSampleSeed = 0x05F7AD0E5EEDull;

/** The key of a pixel's sample pattern; `stream` tells the light's samples from the
 *  pixel's. */
uint64_t pixelKey(int x, int y, unsigned stream)
{
    return (uint64_t(stream) << 62) ^ (uint64_t(uint32_t(y)) << 31) ^ uint64_t(uint32_t(x));
}

/** An Embree ray from origin along direction, tnear 0. */
RTCRay makeRay(const osg::Vec3d& origin, const osg::Vec3d& direction, double tfar)
{
    RTCRay ray;
    ray.org_x = float(origin.x());
    ray.org_y = float(origin.y());
    ray.org_z = float(origin.z());
    ray.dir_x = float(direction.x());
    ray.dir_y = float(direction.y());
    ray.dir_z = float(direction.z());
    ray.tnear = 0.0f;
    ray.tfar = float(tfar);
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

/** Calls rows(first, step) for first = 0 .. n - 1 on n threads (`threads`, 0 = all cores,
 *  at most `height`): each call renders the rows first, first + step, ... */
template <class Rows>
void splitRows(int height, unsigned threads, Rows&& rows)
{
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(height));
    std::vector<std::thread> workers;
    for (unsigned t = 1; t < threads; ++t) workers.emplace_back([&, t] { rows(t, threads); });
    rows(0, threads);
    for (std::thread& w : workers) w.join();
}

/** GL's wrap of an integer texel coordinate (OpenGL 4.6, 8.14.2): REPEAT, MIRRORED_REPEAT,
 *  anything else clamps to the edge. */
int wrapTexel(double i, int size, osg::Texture::WrapMode mode)
{
    // Far outside the texture only the coordinate modulo 2 size matters; an int must hold it.
    const double limit = 1e9;
    const long long k = std::isfinite(i) ? (long long)std::max(-limit, std::min(limit, i)) : 0;
    switch (mode)
    {
    case osg::Texture::REPEAT:
    {
        const long long r = k % size;
        return int(r < 0 ? r + size : r);
    }
    case osg::Texture::MIRROR:
    {
        long long m = k % (2 * size);
        if (m < 0) m += 2 * size;
        m -= size;
        return int((size - 1) - (m >= 0 ? m : -(1 + m)));
    }
    default: return int(std::max(0LL, std::min<long long>(size - 1, k)));
    }
}

/** An AlphaCutout ready for sampling: the image's level-0 alphas as floats, read once. */
struct PreparedCutout
{
    PreparedCutout(const AlphaCutout& cutout, std::shared_ptr<const std::vector<float>> texels)
        : alpha(std::move(texels)), width(cutout.image ? cutout.image->s() : 0),
          height(cutout.image ? cutout.image->t() : 0), wrapS(cutout.wrapS), wrapT(cutout.wrapT),
          nearest(cutout.nearest), func(cutout.func), ref(cutout.ref), scale(cutout.alphaScale)
    {
    }

    float texel(int i, int j) const { return (*alpha)[size_t(j) * size_t(width) + size_t(i)]; }

    /** The fragment alpha at texture coordinate tc: GL's level-0 sampling (texel centres at
     *  (i + 0.5) / size), times the material's alpha. */
    float alphaAt(const osg::Vec2f& tc) const
    {
        if (!alpha) return scale;
        const double u = double(tc.x()) * width;
        const double v = double(tc.y()) * height;
        if (nearest)
            return scale * texel(wrapTexel(std::floor(u), width, wrapS), wrapTexel(std::floor(v), height, wrapT));
        const double i0 = std::floor(u - 0.5);
        const double j0 = std::floor(v - 0.5);
        const double a = u - 0.5 - i0;
        const double b = v - 0.5 - j0;
        const int is[2] = {wrapTexel(i0, width, wrapS), wrapTexel(i0 + 1.0, width, wrapS)};
        const int js[2] = {wrapTexel(j0, height, wrapT), wrapTexel(j0 + 1.0, height, wrapT)};
        const double sampled = (1.0 - a) * (1.0 - b) * texel(is[0], js[0]) + a * (1.0 - b) * texel(is[1], js[0]) +
                               (1.0 - a) * b * texel(is[0], js[1]) + a * b * texel(is[1], js[1]);
        return scale * float(sampled);
    }

    bool keeps(const osg::Vec2f& tc) const { return alphaPasses(func, alphaAt(tc), ref); }

    std::shared_ptr<const std::vector<float>> alpha; // null: untextured
    int width;
    int height;
    osg::Texture::WrapMode wrapS;
    osg::Texture::WrapMode wrapT;
    bool nearest;
    osg::AlphaFunc::ComparisonFunction func;
    float ref;
    float scale;
};

/** The level-0 alphas of an image, row 0 first (t = 0), through osg::Image::getColor. */
std::shared_ptr<const std::vector<float>> imageAlphas(const osg::Image& image)
{
    auto texels = std::make_shared<std::vector<float>>();
    texels->reserve(size_t(image.s()) * size_t(image.t()));
    for (int j = 0; j < image.t(); ++j)
        for (int i = 0; i < image.s(); ++i) texels->push_back(clamp01(image.getColor(unsigned(i), unsigned(j)).a()));
    return texels;
}

/** A cut-out triangle as its Embree filter sees it. */
struct CutoutTriangle
{
    osg::Vec2f texCoords[3];
    unsigned int cutout; // index into CutoutGeometry::cutouts
};

/** The user data of an Embree geometry whose hits are filtered, indexed by primID: the
 *  alpha tests of cut-out triangles, and in the primary scene the culled sides. */
struct FilteredGeometry
{
    const std::vector<PreparedCutout>* cutouts = nullptr; // null: no cut-outs
    std::vector<CutoutTriangle> triangles;                // per primID, with cut-outs
    std::vector<uint8_t> culled;                          // per primID CulledSide; empty: none
    const osg::Vec3d* normals = nullptr;                  // per primID, with culled: unit winding normal
};

/** Whether the alpha test keeps the fragment of hit i. */
bool keepsFragment(const FilteredGeometry& geometry, const RTCFilterFunctionNArguments* args, unsigned int i)
{
    const unsigned int prim = RTCHitN_primID(args->hit, args->N, i);
    if (!geometry.cutouts || prim >= geometry.triangles.size()) return true;
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    const CutoutTriangle& t = geometry.triangles[prim];
    const osg::Vec2f tc = t.texCoords[0] * (1.0f - u - v) + t.texCoords[1] * u + t.texCoords[2] * v;
    return (*geometry.cutouts)[t.cutout].keeps(tc);
}

/** Whether hit i is on a side of its triangle that the eye pass draws: the ray sees the CCW
 *  side when it runs against the winding's normal. */
bool drawnSide(const FilteredGeometry& geometry, const RTCFilterFunctionNArguments* args, unsigned int i)
{
    const unsigned int prim = RTCHitN_primID(args->hit, args->N, i);
    if (prim >= geometry.culled.size() || geometry.culled[prim] == CULL_NONE) return true;
    RTCRayN* ray = args->ray;
    const osg::Vec3d dir(RTCRayN_dir_x(ray, args->N, i), RTCRayN_dir_y(ray, args->N, i),
                         RTCRayN_dir_z(ray, args->N, i));
    const uint8_t seen = dir * geometry.normals[prim] < 0.0 ? CULL_CCW_SIDE : CULL_CW_SIDE;
    return (geometry.culled[prim] & seen) == 0;
}

/** Occlusion filter of the cut-out geometries (shadow rays, two-sided): rejects the hits
 *  whose fragment the alpha test discards. Reads only; safe from several threads. */
void cutoutFilter(const RTCFilterFunctionNArguments* args)
{
    const FilteredGeometry& geometry = *static_cast<const FilteredGeometry*>(args->geometryUserPtr);
    for (unsigned int i = 0; i < args->N; ++i)
        if (args->valid[i] != 0 && !keepsFragment(geometry, args, i)) args->valid[i] = 0;
}

/** Intersection filter of the primary scene's geometries (the camera's rays): rejects the
 *  hits on a culled side and those whose fragment the alpha test discards. Reads only. */
void primaryFilter(const RTCFilterFunctionNArguments* args)
{
    const FilteredGeometry& geometry = *static_cast<const FilteredGeometry*>(args->geometryUserPtr);
    for (unsigned int i = 0; i < args->N; ++i)
        if (args->valid[i] != 0 && !(drawnSide(geometry, args, i) && keepsFragment(geometry, args, i)))
            args->valid[i] = 0;
}

/** Embree geometry IDs of a scene: opaque triangles, then cut-outs. */
const unsigned int OPAQUE_GEOMETRY = 0;
const unsigned int CUTOUT_GEOMETRY = 1;

void reportEmbreeError(void*, RTCError code, const char* message)
{
    OSG_WARN << "ossref: Embree error " << int(code) << ": " << (message ? message : "") << std::endl;
}

} // namespace

TriangleSoup collectTriangles(const osg::Node& scene, unsigned int castsMask, unsigned int traversalMask)
{
    return collectTriangles(scene, nullptr, castsMask, traversalMask);
}

TriangleSoup collectTriangles(const osg::Node& scene, const Camera* camera, unsigned int castsMask,
                              unsigned int traversalMask)
{
    TriangleSoup soup;
    TriangleCollector collector(castsMask, traversalMask, camera, soup);
    // The visitor only reads the graph; accept() is not const in OSG.
    const_cast<osg::Node&>(scene).accept(collector);
    return soup;
}

struct Tracer::Impl
{
    RTCDevice device = nullptr;
    RTCScene primary = nullptr;
    RTCScene shadow = nullptr; // == primary when every triangle casts and is in the primary
    // Per primary triangle (those not culled on both sides), opaque ones first and then
    // cut-outs (the order of the primary scene's geometries): (geomID, primID) is triangle
    // primID + firstPrim[geomID].
    std::vector<osg::Vec3d> normals; // unit length
    unsigned int firstPrim[2] = {0, 0};
    osg::Vec3d centre;
    double radius = 0.0;
    std::vector<PreparedCutout> cutouts; // TriangleSoup::cutouts
    FilteredGeometry primaryGeometries[2]; // by geomID
    FilteredGeometry shadowGeometries[2];

    ~Impl()
    {
        if (shadow && shadow != primary) rtcReleaseScene(shadow);
        if (primary) rtcReleaseScene(primary);
        if (device) rtcReleaseDevice(device);
    }

    void build(const TriangleSoup& soup);
    RTCScene makeScene(const TriangleSoup& soup, bool primaryScene, FilteredGeometry* filtered);
    template <class Keep>
    void attachTriangles(RTCScene scene, const TriangleSoup& soup, unsigned int geomID, Keep&& keep, bool primaryScene,
                         FilteredGeometry& filtered);
    std::vector<osg::Vec3d> origins;  // per primary triangle, its first vertex (recentred): a point of its plane
    double offsetScale = DEFAULT_OFFSET_SCALE;

    double epsilon(const osg::Vec3d& local) const { return offsetScale * radius + 1e-6 * local.length(); }
    bool visiblePoint(const RayFrame& rays, double winX, double winY, SurfacePoint& surface) const;
    bool facesLight(const LightFrame& light, const SurfacePoint& surface, uint8_t& grazing) const;
    PixelResult shade(const RayFrame& rays, const LightFrame& light, double winX, double winY) const;
    bool occluded(const osg::Vec3d& origin, const osg::Vec3d& direction, double tfar) const;
    void renderRows(const RayFrame& rays, const LightFrame& light, Mask& mask, unsigned first, unsigned step) const;

    /** Scratch space of one thread's visibility rows. */
    struct ShadowBatch
    {
        std::vector<osg::Vec2d> samples;
        std::vector<RTCRay> rays;
    };
    double lightVisibility(const LightFrame& light, const SurfacePoint& surface, uint64_t key,
                           ShadowBatch& batch) const;
    PixelVisibility softShade(const RayFrame& rays, const LightFrame& light, int x, int y, ShadowBatch& batch) const;
    PixelVisibility coverage(const RayFrame& rays, const LightFrame& light, int x, int y, ShadowBatch& batch) const;
    void renderRows(const RayFrame& rays, const LightFrame& light, VisibilityMask& mask, unsigned first,
                    unsigned step) const;
    template <class MaskT>
    MaskT renderMask(const Camera& camera, const Light& light, unsigned threads) const;
};

void Tracer::Impl::build(const TriangleSoup& soup)
{
    osg::BoundingBoxd box;
    for (const osg::Vec3d& v : soup.vertices) box.expandBy(v);
    if (box.valid())
    {
        centre = box.center();
        radius = box.radius();
    }
    device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("ossref: cannot create an Embree device");
    rtcSetDeviceErrorFunction(device, reportEmbreeError, nullptr);
    if ((!soup.cutouts.empty() || !soup.culled.empty()) &&
        !rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
        throw std::runtime_error(
            "ossref: Embree was built without filter functions, needed by alpha-tested and culled triangles");

    // Images shared by several cut-outs are read once.
    std::map<const osg::Image*, std::shared_ptr<const std::vector<float>>> alphas;
    cutouts.reserve(soup.cutouts.size());
    for (const AlphaCutout& c : soup.cutouts)
    {
        std::shared_ptr<const std::vector<float>> texels;
        if (c.image.valid())
        {
            auto& cached = alphas[c.image.get()];
            if (!cached) cached = imageAlphas(*c.image);
            texels = cached;
        }
        cutouts.emplace_back(c, texels);
    }

    // The normals first: the primary scene's filters read them.
    normals.reserve(soup.size());
    origins.reserve(soup.size());
    for (const bool cut : {false, true})
    {
        firstPrim[cut ? CUTOUT_GEOMETRY : OPAQUE_GEOMETRY] = unsigned(normals.size());
        for (size_t t = 0; t < soup.size(); ++t)
        {
            if ((soup.cutoutOf(t) >= 0) != cut || soup.culledOf(t) == CULL_BOTH_SIDES) continue;
            const osg::Vec3d* v = &soup.vertices[3 * t];
            osg::Vec3d n = (v[1] - v[0]) ^ (v[2] - v[0]);
            n.normalize();
            normals.push_back(n);
            origins.push_back(v[0] - centre);
        }
        if (soup.cutout.empty()) break; // no cut-outs
    }

    primary = makeScene(soup, true, primaryGeometries);
    const bool allCast = std::all_of(soup.casts.begin(), soup.casts.end(), [](uint8_t c) { return c != 0; });
    const bool allInPrimary =
        std::none_of(soup.culled.begin(), soup.culled.end(), [](uint8_t c) { return c == CULL_BOTH_SIDES; });
    shadow = allCast && allInPrimary ? primary : makeScene(soup, false, shadowGeometries);
}

/** Attaches, as geometry `geomID`, the soup's triangles for which keep(t) holds, in soup
 *  order. The geometry filters its hits through `filtered` when they are cut-outs
 *  (CUTOUT_GEOMETRY) or, in the primary scene, when some of them are culled. */
template <class Keep>
void Tracer::Impl::attachTriangles(RTCScene scene, const TriangleSoup& soup, unsigned int geomID, Keep&& keep,
                                   bool primaryScene, FilteredGeometry& filtered)
{
    size_t count = 0;
    bool anyCulled = false;
    for (size_t t = 0; t < soup.size(); ++t)
        if (keep(t))
        {
            ++count;
            anyCulled = anyCulled || soup.culledOf(t) != CULL_NONE;
        }
    if (count == 0) return;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
    unsigned* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    const bool cut = geomID == CUTOUT_GEOMETRY;
    const bool cull = primaryScene && anyCulled; // shadow rays see both sides
    if (cut)
    {
        filtered.cutouts = &cutouts;
        filtered.triangles.reserve(count);
    }
    if (cull)
    {
        filtered.culled.reserve(count);
        filtered.normals = normals.data() + firstPrim[geomID];
    }
    size_t k = 0;
    size_t cutoutOrdinal = 0; // of triangle t among the soup's cut-outs: its texCoords
    for (size_t t = 0; t < soup.size(); ++t)
    {
        const int cutout = soup.cutoutOf(t);
        const size_t ordinal = cutout >= 0 ? cutoutOrdinal++ : 0;
        if (!keep(t)) continue;
        for (int i = 0; i < 3; ++i)
        {
            const osg::Vec3d v = soup.vertices[3 * t + i] - centre;
            vb[9 * k + 3 * i + 0] = float(v.x());
            vb[9 * k + 3 * i + 1] = float(v.y());
            vb[9 * k + 3 * i + 2] = float(v.z());
            ib[3 * k + i] = unsigned(3 * k + i);
        }
        if (cut)
        {
            CutoutTriangle triangle;
            for (int i = 0; i < 3; ++i)
                triangle.texCoords[i] =
                    3 * ordinal + i < soup.texCoords.size() ? soup.texCoords[3 * ordinal + i] : osg::Vec2f();
            triangle.cutout = unsigned(cutout);
            filtered.triangles.push_back(triangle);
        }
        if (cull) filtered.culled.push_back(soup.culledOf(t));
        ++k;
    }
    if (cut || cull) rtcSetGeometryUserData(geometry, &filtered);
    if (primaryScene && (cut || cull)) rtcSetGeometryIntersectFilterFunction(geometry, primaryFilter);
    if (cut) rtcSetGeometryOccludedFilterFunction(geometry, cutoutFilter);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, geomID);
    rtcReleaseGeometry(geometry);
}

/** The primary scene (`primaryScene`: the triangles a camera can see, those culled on both
 *  sides left out) or the casters-only shadow scene. */
RTCScene Tracer::Impl::makeScene(const TriangleSoup& soup, bool primaryScene, FilteredGeometry* filtered)
{
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    const auto inScene = [&](size_t t) {
        return primaryScene ? soup.culledOf(t) != CULL_BOTH_SIDES : soup.casts[t] != 0;
    };
    attachTriangles(
        scene, soup, OPAQUE_GEOMETRY, [&](size_t t) { return inScene(t) && soup.cutoutOf(t) < 0; }, primaryScene,
        filtered[OPAQUE_GEOMETRY]);
    if (!soup.cutout.empty())
        attachTriangles(
            scene, soup, CUTOUT_GEOMETRY, [&](size_t t) { return inScene(t) && soup.cutoutOf(t) >= 0; }, primaryScene,
            filtered[CUTOUT_GEOMETRY]);
    rtcCommitScene(scene);
    return scene;
}

bool Tracer::Impl::occluded(const osg::Vec3d& origin, const osg::Vec3d& direction, double tfar) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = makeRay(origin, direction, tfar);
    rtcOccluded1(shadow, &context, &ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

bool Tracer::Impl::visiblePoint(const RayFrame& rays, double winX, double winY, SurfacePoint& surface) const
{
    const osg::Vec3d dir = rays.direction(winX, winY);
    const osg::Vec3d org = rays.origin - centre;
    if (!isFinite(dir) || !isFinite(org)) return false;

    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = makeRay(org, dir, kInf);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(primary, &context, &rh);
    if (rh.hit.geomID != OPAQUE_GEOMETRY && rh.hit.geomID != CUTOUT_GEOMETRY) return false;
    const size_t triangle = size_t(rh.hit.primID) + firstPrim[rh.hit.geomID];
    if (triangle >= normals.size()) return false;

    // Embree's hit distance is a float, good to a few units in the last place of the
    // distance from the camera: the hit is moved onto the plane of its triangle in double
    // precision, so that the shadow ray's offset below need not cover the camera distance.
    osg::Vec3d n = normals[triangle];
    double t = double(rh.ray.tfar);
    const double nd = n * dir;
    if (std::fabs(nd) > 1e-12)
    {
        const double exact = ((origins[triangle] - org) * n) / nd;
        if (std::isfinite(exact) && exact > 0.0) t = exact;
    }
    surface.p = org + dir * t;
    surface.n = n * dir > 0.0 ? -n : n;
    return true;
}

/** Whether the seen side of the surface faces the light's centre (N.L > 0) and, for a
 *  spot, the point lies in its cone; `grazing` is set for the band 0 < N.L < 0.05. */
bool Tracer::Impl::facesLight(const LightFrame& light, const SurfacePoint& surface, uint8_t& grazing) const
{
    if (!light.valid) return false;
    double distance = 0.0;
    const double ndotl = surface.n * light.toLight(surface.p, distance);
    grazing = (ndotl > 0.0 && ndotl < GRAZING_NDOTL) ? 1 : 0;
    return ndotl > 0.0 && light.inCone(surface.p);
}

PixelResult Tracer::Impl::shade(const RayFrame& rays, const LightFrame& light, double winX, double winY) const
{
    PixelResult result;
    SurfacePoint surface;
    if (!visiblePoint(rays, winX, winY, surface)) return result;
    result.value = MASK_NO_LIGHT;
    result.distance = float((surface.p - (rays.origin - centre)).length());
    if (!facesLight(light, surface, result.grazing)) return result;

    const double eps = epsilon(surface.p);
    const osg::Vec3d start = surface.p + surface.n * eps;
    double tfar = kInf;
    const osg::Vec3d toward = light.toLight(start, tfar);
    tfar -= eps;
    if (tfar <= 0.0 || !occluded(start, toward, tfar)) result.value = MASK_LIT;
    return result;
}

/** The fraction of the light's LIGHT_STRATA^2 shadow rays from `surface` that reach it. */
double Tracer::Impl::lightVisibility(const LightFrame& light, const SurfacePoint& surface, uint64_t key,
                                     ShadowBatch& batch) const
{
    stratifiedSamples(LIGHT_STRATA, key, batch.samples);
    const LightSampler sampler(light, surface.p);
    const double eps = epsilon(surface.p);
    const osg::Vec3d start = surface.p + surface.n * eps;
    size_t reached = 0;
    batch.rays.clear();
    for (const osg::Vec2d& s : batch.samples)
    {
        double distance = kInf;
        const osg::Vec3d toward = sampler.toward(start, s, distance);
        if (!(toward * surface.n > 0.0)) continue; // below the seen side's horizon
        if (distance - eps <= 0.0)
            ++reached;
        else
            batch.rays.push_back(makeRay(start, toward, distance - eps));
    }
    if (!batch.rays.empty())
    {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        rtcOccluded1M(shadow, &context, batch.rays.data(), unsigned(batch.rays.size()), sizeof(RTCRay));
        for (const RTCRay& ray : batch.rays) reached += ray.tfar == -std::numeric_limits<float>::infinity() ? 0 : 1;
    }
    return double(reached) / double(batch.samples.size());
}

PixelVisibility Tracer::Impl::softShade(const RayFrame& rays, const LightFrame& light, int x, int y,
                                        ShadowBatch& batch) const
{
    PixelVisibility result;
    SurfacePoint surface;
    if (!visiblePoint(rays, x + 0.5, y + 0.5, surface)) return result;
    result.value = VIS_NONE;
    if (!facesLight(light, surface, result.grazing)) return result;
    result.value = encodeVisibility(lightVisibility(light, surface, pixelKey(x, y, 0), batch));
    return result;
}

/** A light of size 0: the lit fraction of the pixel's sub-pixel rays that hit geometry. */
PixelVisibility Tracer::Impl::coverage(const RayFrame& rays, const LightFrame& light, int x, int y,
                                       ShadowBatch& batch) const
{
    PixelVisibility result;
    const PixelResult centre = shade(rays, light, x + 0.5, y + 0.5);
    if (centre.value == MASK_BACKGROUND) return result;
    result.grazing = centre.grazing;
    stratifiedSamples(PIXEL_STRATA, pixelKey(x, y, 1), batch.samples);
    int hits = 0;
    int lit = 0;
    for (const osg::Vec2d& s : batch.samples)
    {
        const PixelResult r = shade(rays, light, x + s.x(), y + s.y());
        hits += r.value != MASK_BACKGROUND ? 1 : 0;
        lit += r.value == MASK_LIT ? 1 : 0;
    }
    const double v = hits > 0 ? double(lit) / hits : (centre.value == MASK_LIT ? 1.0 : 0.0);
    result.value = encodeVisibility(v);
    return result;
}

void Tracer::Impl::renderRows(const RayFrame& rays, const LightFrame& light, VisibilityMask& mask, unsigned first,
                              unsigned step) const
{
    ShadowBatch batch;
    batch.rays.reserve(size_t(LIGHT_STRATA) * LIGHT_STRATA);
    for (int y = int(first); y < mask.height; y += int(step))
    {
        const size_t row = size_t(mask.height - 1 - y) * mask.width;
        for (int x = 0; x < mask.width; ++x)
        {
            const PixelVisibility r =
                light.sized ? softShade(rays, light, x, y, batch) : coverage(rays, light, x, y, batch);
            mask.value[row + x] = r.value;
            mask.grazing[row + x] = r.grazing;
        }
    }
}

void Tracer::Impl::renderRows(const RayFrame& rays, const LightFrame& light, Mask& mask, unsigned first,
                              unsigned step) const
{
    for (int y = int(first); y < mask.height; y += int(step))
    {
        const size_t row = size_t(mask.height - 1 - y) * mask.width;
        for (int x = 0; x < mask.width; ++x)
        {
            const PixelResult r = shade(rays, light, x + 0.5, y + 0.5);
            mask.value[row + x] = r.value;
            mask.grazing[row + x] = r.grazing;
            mask.distance[row + x] = r.distance;
        }
    }
}

Tracer::Tracer(const TriangleSoup& triangles) : _impl(new Impl)
{
    _impl->build(triangles);
}

Tracer::Tracer(const osg::Node& scene, unsigned int castsMask, unsigned int traversalMask)
    : Tracer(collectTriangles(scene, castsMask, traversalMask))
{
}

Tracer::~Tracer() = default;

size_t Tracer::triangleCount() const { return _impl->normals.size(); }

double Tracer::epsilonAt(const osg::Vec3d& p) const { return _impl->epsilon(p - _impl->centre); }

void Tracer::setOffsetScale(double scale) { _impl->offsetScale = scale; }

double Tracer::getOffsetScale() const { return _impl->offsetScale; }

/** A mask of the camera's size, background where renderRows() leaves it, its rows split
 *  over `threads` threads (0 = all cores). */
template <class MaskT>
MaskT Tracer::Impl::renderMask(const Camera& camera, const Light& light, unsigned threads) const
{
    if (camera.width <= 0 || camera.height <= 0) return MaskT();
    MaskT mask = MaskT::filled(camera.width, camera.height);
    if constexpr (std::is_same_v<MaskT, Mask>)
        mask.distance.assign(mask.value.size(), std::numeric_limits<float>::infinity());
    const RayFrame rays(camera);
    const LightFrame lightFrame(light, centre);
    splitRows(camera.height, threads,
              [&](unsigned first, unsigned step) { renderRows(rays, lightFrame, mask, first, step); });
    return mask;
}

Mask Tracer::render(const Camera& camera, const Light& light, unsigned int threads) const
{
    return _impl->renderMask<Mask>(camera, light, threads);
}

VisibilityMask Tracer::renderVisibility(const Camera& camera, const Light& light, unsigned int threads) const
{
    return _impl->renderMask<VisibilityMask>(camera, light, threads);
}

Mask computeReferenceMask(const osg::Node& scene, const Camera& camera, const Light& light, unsigned int castsMask,
                          unsigned int traversalMask, double offsetScale)
{
    Tracer tracer(collectTriangles(scene, &camera, castsMask, traversalMask));
    tracer.setOffsetScale(offsetScale);
    return tracer.render(camera, light);
}

VisibilityMask computeReferenceVisibility(const osg::Node& scene, const Camera& camera, const Light& light,
                                          unsigned int castsMask, unsigned int traversalMask)
{
    const Tracer tracer(collectTriangles(scene, &camera, castsMask, traversalMask));
    return tracer.renderVisibility(camera, light);
}

void stratifiedSamples(int n, uint64_t key, std::vector<osg::Vec2d>& out)
{
    n = std::max(0, n);
    SplitMix64 random{kSampleSeed ^ (key * 0xD1B54A32D192ED03ull)};
    out.resize(size_t(n) * size_t(n));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
            const double u = (i + random.uniform()) / n;
            out[size_t(i) * n + j] = osg::Vec2d(u, (j + random.uniform()) / n);
        }
}

bool cameraFromOsg(const osg::Camera& camera, Camera& out)
{
    const osg::Viewport* viewport = camera.getViewport();
    double left, right, bottom, top, zNear, zFar;
    if (!viewport || viewport->width() <= 0 || viewport->height() <= 0 ||
        !camera.getProjectionMatrixAsFrustum(left, right, bottom, top, zNear, zFar))
        return false;
    const double tolerance = 1e-6;
    const double aspect = viewport->width() / viewport->height();
    if (std::fabs(left + right) > tolerance * right || std::fabs(bottom + top) > tolerance * top ||
        std::fabs(right / top - aspect) > tolerance * aspect)
        return false;
    Camera result;
    camera.getViewMatrixAsLookAt(result.eye, result.center, result.up, 1.0);
    result.fovyDeg = osg::RadiansToDegrees(2.0 * std::atan(top / zNear));
    result.width = int(viewport->width());
    result.height = int(viewport->height());
    out = result;
    return true;
}

void primaryRay(const Camera& camera, double winX, double winY, osg::Vec3d& origin, osg::Vec3d& direction)
{
    const RayFrame rays(camera);
    origin = rays.origin;
    direction = rays.direction(winX, winY);
}

Light lightFromOsg(const osg::Light& light, const osg::Matrixd& world)
{
    const osg::Vec4d p = osg::Vec4d(light.getPosition()) * world;
    Light result;
    if (p.w() == 0.0)
    {
        result.type = Light::DIRECTIONAL;
        result.vector = osg::Vec3d(p.x(), p.y(), p.z());
        result.vector.normalize();
        return result;
    }
    result.vector = osg::Vec3d(p.x(), p.y(), p.z()) / p.w();
    result.spotDirection = osg::Matrixd::transform3x3(osg::Vec3d(light.getDirection()), world);
    result.spotDirection.normalize();
    result.spotCutoffDeg = light.getSpotCutoff();
    result.type = result.spotCutoffDeg < 180.0 ? Light::SPOT : Light::POINT;
    return result;
}

Light lightFromLightSource(const osg::LightSource& source)
{
    const osg::Light* light = dynamic_cast<const osg::Light*>(source.getLight());
    if (!light) return Light();
    osg::Matrixd world;
    if (source.getReferenceFrame() == osg::LightSource::RELATIVE_RF)
    {
        const osg::MatrixList matrices = source.getWorldMatrices();
        if (!matrices.empty()) world = matrices.front();
    }
    return lightFromOsg(*light, world);
}

} // namespace ossref
