// Exact reference masks by ray casting with Embree 3: scene collection, BVH building and
// the per-pixel primary and shadow rays. Mask comparison and images live in MaskTools.cpp.
#include "reference/Reference.h"

#include <embree3/rtcore.h>

#include <osg/Billboard>
#include <osg/BoundingBox>
#include <osg/Camera>
#include <osg/CullingSet>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/Notify>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/TriangleFunctor>
#include <osg/TriangleIndexFunctor>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

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
    void operator()(unsigned int a, unsigned int b, unsigned int c) const;
};

struct VertexSink
{
    TriangleCollector* collector = nullptr;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, bool = false) const;
};

/** Walks the scene, accumulating Transform matrices and the casts flag of the path. */
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

    /** One triangle in world coordinates: kept unless non-finite or of zero area. */
    void addWorldTriangle(const osg::Vec3d& a, const osg::Vec3d& b, const osg::Vec3d& c)
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
    }

    const osg::Matrixd& matrix() const { return _matrix; }

private:
    template <class F>
    void inScope(const osg::Node& node, F&& body)
    {
        const bool saved = _casts;
        _casts = _casts && (node.getNodeMask() & _castsMask) != 0;
        body();
        _casts = saved;
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
        osg::TriangleIndexFunctor<IndexSink> functor;
        functor.collector = this;
        functor.vertices = &vertices;
        geometry.accept(functor);
    }

    void addDrawable(const osg::Drawable& drawable)
    {
        osg::TriangleFunctor<VertexSink> functor;
        functor.collector = this;
        drawable.accept(functor);
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
};

void IndexSink::operator()(unsigned int a, unsigned int b, unsigned int c) const
{
    const size_t n = vertices->size();
    if (a >= n || b >= n || c >= n) return;
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
    double cosCutoff = -1.0;
    osg::Vec3d direction;
    osg::Vec3d position;
    osg::Vec3d spotAxis;
};

struct PixelResult
{
    uint8_t value = MASK_BACKGROUND;
    uint8_t grazing = 0;
};

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
    RTCScene shadow = nullptr;  // == primary when every visible triangle casts
    std::vector<osg::Vec3d> normals;  // per primary triangle, unit length
    osg::Vec3d centre;
    double radius = 0.0;

    ~Impl()
    {
        if (shadow && shadow != primary) rtcReleaseScene(shadow);
        if (primary) rtcReleaseScene(primary);
        if (device) rtcReleaseDevice(device);
    }

    void build(const TriangleSoup& soup);
    RTCScene makeScene(const TriangleSoup& soup, bool castersOnly);
    std::vector<osg::Vec3d> origins;  // per primary triangle, its first vertex (recentred): a point of its plane
    double offsetScale = DEFAULT_OFFSET_SCALE;

    double epsilon(const osg::Vec3d& local) const { return offsetScale * radius + 1e-6 * local.length(); }
    PixelResult shade(const RayFrame& rays, const LightFrame& light, int x, int y) const;
    bool occluded(const osg::Vec3d& origin, const osg::Vec3d& direction, double tfar) const;
    void renderRows(const RayFrame& rays, const LightFrame& light, Mask& mask, unsigned first, unsigned step) const;
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

    primary = makeScene(soup, false);
    const bool allCast = std::all_of(soup.casts.begin(), soup.casts.end(), [](uint8_t c) { return c != 0; });
    shadow = allCast ? primary : makeScene(soup, true);

    normals.reserve(soup.size());
    origins.reserve(soup.size());
    for (size_t t = 0; t < soup.size(); ++t)
    {
        const osg::Vec3d* v = &soup.vertices[3 * t];
        osg::Vec3d n = (v[1] - v[0]) ^ (v[2] - v[0]);
        n.normalize();
        normals.push_back(n);
        origins.push_back(v[0] - centre);
    }
}

RTCScene Tracer::Impl::makeScene(const TriangleSoup& soup, bool castersOnly)
{
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    size_t count = 0;
    for (uint8_t c : soup.casts) count += (!castersOnly || c) ? 1 : 0;
    if (count > 0)
    {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), 3 * count));
        unsigned* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(unsigned), count));
        size_t k = 0;
        for (size_t t = 0; t < soup.size(); ++t)
        {
            if (castersOnly && !soup.casts[t]) continue;
            for (int i = 0; i < 3; ++i)
            {
                const osg::Vec3d v = soup.vertices[3 * t + i] - centre;
                vb[9 * k + 3 * i + 0] = float(v.x());
                vb[9 * k + 3 * i + 1] = float(v.y());
                vb[9 * k + 3 * i + 2] = float(v.z());
                ib[3 * k + i] = unsigned(3 * k + i);
            }
            ++k;
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(scene);
    return scene;
}

bool Tracer::Impl::occluded(const osg::Vec3d& origin, const osg::Vec3d& direction, double tfar) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
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
    rtcOccluded1(shadow, &context, &ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

PixelResult Tracer::Impl::shade(const RayFrame& rays, const LightFrame& light, int x, int y) const
{
    PixelResult result;
    const osg::Vec3d dir = rays.direction(x + 0.5, y + 0.5);
    const osg::Vec3d org = rays.origin - centre;
    if (!isFinite(dir) || !isFinite(org)) return result;

    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = float(org.x());
    rh.ray.org_y = float(org.y());
    rh.ray.org_z = float(org.z());
    rh.ray.dir_x = float(dir.x());
    rh.ray.dir_y = float(dir.y());
    rh.ray.dir_z = float(dir.z());
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(primary, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.primID >= normals.size()) return result;

    // Embree's hit distance is a float, good to a few units in the last place of the
    // distance from the camera: the hit is moved onto the plane of its triangle in double
    // precision, so that the shadow ray's offset below need not cover the camera distance.
    osg::Vec3d n = normals[rh.hit.primID];
    double t = double(rh.ray.tfar);
    const double nd = n * dir;
    if (std::fabs(nd) > 1e-12)
    {
        const double exact = ((origins[rh.hit.primID] - org) * n) / nd;
        if (std::isfinite(exact) && exact > 0.0) t = exact;
    }
    const osg::Vec3d p = org + dir * t;
    if (n * dir > 0.0) n = -n;
    result.value = MASK_NO_LIGHT;
    if (!light.valid) return result;

    double distance = 0.0;
    const osg::Vec3d l = light.toLight(p, distance);
    const double ndotl = n * l;
    result.grazing = (ndotl > 0.0 && ndotl < GRAZING_NDOTL) ? 1 : 0;
    if (!(ndotl > 0.0) || !light.inCone(p)) return result;

    const double eps = epsilon(p);
    const osg::Vec3d start = p + n * eps;
    double tfar = kInf;
    const osg::Vec3d toward = light.directional ? l : light.toLight(start, tfar);
    tfar -= eps;
    if (tfar <= 0.0 || !occluded(start, toward, tfar)) result.value = MASK_LIT;
    return result;
}

void Tracer::Impl::renderRows(const RayFrame& rays, const LightFrame& light, Mask& mask, unsigned first,
                              unsigned step) const
{
    for (int y = int(first); y < mask.height; y += int(step))
    {
        const size_t row = size_t(mask.height - 1 - y) * mask.width;
        for (int x = 0; x < mask.width; ++x)
        {
            const PixelResult r = shade(rays, light, x, y);
            mask.value[row + x] = r.value;
            mask.grazing[row + x] = r.grazing;
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

Mask Tracer::render(const Camera& camera, const Light& light, unsigned int threads) const
{
    if (camera.width <= 0 || camera.height <= 0) return Mask();
    Mask mask = Mask::filled(camera.width, camera.height, MASK_BACKGROUND);
    const RayFrame rays(camera);
    const LightFrame lightFrame(light, _impl->centre);

    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(camera.height));
    std::vector<std::thread> workers;
    for (unsigned t = 1; t < threads; ++t)
        workers.emplace_back([&, t] { _impl->renderRows(rays, lightFrame, mask, t, threads); });
    _impl->renderRows(rays, lightFrame, mask, 0, threads);
    for (std::thread& w : workers) w.join();
    return mask;
}

Mask computeReferenceMask(const osg::Node& scene, const Camera& camera, const Light& light, unsigned int castsMask,
                          unsigned int traversalMask, double offsetScale)
{
    Tracer tracer(collectTriangles(scene, &camera, castsMask, traversalMask));
    tracer.setOffsetScale(offsetScale);
    return tracer.render(camera, light);
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
