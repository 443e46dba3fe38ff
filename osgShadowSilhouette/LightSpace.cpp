#include <osgShadowSilhouette/LightSpace>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace osgShadowSilhouette {

namespace {

bool finite(const osg::Vec3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

bool finite(const osg::Vec4d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()) && std::isfinite(v.w());
}

/** "x, y, z[, w]", as OSG_WARN writes numbers ("nan", "inf"). */
template<typename V>
std::string listed(const V& v)
{
    std::ostringstream text;
    for (int i = 0; i < V::num_components; ++i) text << (i ? ", " : "") << float(v[i]);
    return text.str();
}

/** Any unit vector orthogonal to d (d need not be normalized). */
osg::Vec3d orthogonal(const osg::Vec3d& d)
{
    const osg::Vec3d axis = std::fabs(d.z()) < 0.9 * d.length() ? osg::Vec3d(0, 0, 1) : osg::Vec3d(0, 1, 0);
    osg::Vec3d o = axis ^ d;
    o.normalize();
    return o;
}

struct Range
{
    double lo = std::numeric_limits<double>::max();
    double hi = -std::numeric_limits<double>::max();
    void expand(double v) { lo = std::min(lo, v); hi = std::max(hi, v); }
    bool empty() const { return lo > hi; }
};

std::array<osg::Vec3d, 8> boxCorners(const osg::BoundingBoxd& box)
{
    std::array<osg::Vec3d, 8> c;
    for (unsigned int i = 0; i < 8; ++i) c[i] = box.corner(i);
    return c;
}

using Polygon = std::vector<osg::Vec3d>;

/** Sutherland-Hodgman: the part of a convex polygon where plane.xyz . p + plane.w >= 0.
 *  New vertices made on the plane are appended to cut. */
Polygon clipPolygon(const Polygon& poly, const osg::Vec4d& plane, Polygon& cut)
{
    Polygon out;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const osg::Vec3d& a = poly[i];
        const osg::Vec3d& b = poly[(i + 1) % n];
        const double da = plane.x() * a.x() + plane.y() * a.y() + plane.z() * a.z() + plane.w();
        const double db = plane.x() * b.x() + plane.y() * b.y() + plane.z() * b.z() + plane.w();
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0))
        {
            const osg::Vec3d p = a + (b - a) * (da / (da - db));
            out.push_back(p);
            cut.push_back(p);
        }
    }
    return out;
}

/** Orders the points of a planar convex cap around their centroid. */
Polygon orderCap(Polygon cap, const osg::Vec3d& normal)
{
    if (cap.size() < 3) return Polygon();
    osg::Vec3d centre;
    for (const osg::Vec3d& p : cap) centre += p;
    centre /= static_cast<double>(cap.size());
    const osg::Vec3d u = orthogonal(normal);
    const osg::Vec3d v = normal ^ u;
    std::sort(cap.begin(), cap.end(), [&](const osg::Vec3d& a, const osg::Vec3d& b) {
        return std::atan2((a - centre) * v, (a - centre) * u) < std::atan2((b - centre) * v, (b - centre) * u);
    });
    return cap;
}

/** Clips a convex polyhedron, given as its face polygons, by a plane (keeps the positive side). */
std::vector<Polygon> clipPolyhedron(const std::vector<Polygon>& faces, const osg::Vec4d& plane)
{
    std::vector<Polygon> out;
    Polygon cut;
    for (const Polygon& f : faces)
    {
        Polygon clipped = clipPolygon(f, plane, cut);
        if (clipped.size() >= 3) out.push_back(std::move(clipped));
    }
    Polygon cap = orderCap(cut, osg::Vec3d(plane.x(), plane.y(), plane.z()));
    if (!cap.empty()) out.push_back(std::move(cap));
    return out;
}

/** The distance where 1 / (c + l d + q d^2) times the light's brightest channel falls to 1/512. */
double attenuationRange(const osg::Light& light)
{
    double brightest = 0.0;
    for (const osg::Vec4& colour : {light.getAmbient(), light.getDiffuse(), light.getSpecular()})
        for (int i = 0; i < 3; ++i) brightest = std::max(brightest, double(colour[i]));
    const double c = light.getConstantAttenuation(), l = light.getLinearAttenuation(),
                 q = light.getQuadraticAttenuation();
    if (!(std::isfinite(c) && std::isfinite(l) && std::isfinite(q)) || l < 0.0 || q < 0.0 || (l == 0.0 && q == 0.0))
        return std::numeric_limits<double>::infinity();
    const double target = 512.0 * brightest - c; // solve q d^2 + l d = target
    if (target <= 0.0) return 0.0;
    if (q == 0.0) return target / l;
    return (-l + std::sqrt(l * l + 4.0 * q * target)) / (2.0 * q);
}

osg::Matrixd textureScaleBias()
{
    return osg::Matrixd::translate(1.0, 1.0, 1.0) * osg::Matrixd::scale(0.5, 0.5, 0.5);
}

} // namespace

osg::Vec4d LightDescription::homogeneous() const
{
    return type == DIRECTIONAL ? osg::Vec4d(direction, 0.0) : osg::Vec4d(position, 1.0);
}

namespace {

/** Whether a and b differ by rounding alone: by at most 1e-12 of the larger's length. */
bool roundedAlike(const osg::Vec3d& a, const osg::Vec3d& b)
{
    return (a - b).length() <= 1e-12 * std::max(a.length(), b.length());
}

} // namespace

LightDescription steadied(const LightDescription& fresh, const LightDescription& previous)
{
    if (fresh.lightNum != previous.lightNum || fresh.type != previous.type ||
        fresh.spotCutoffDeg != previous.spotCutoffDeg || !roundedAlike(fresh.direction, previous.direction) ||
        !roundedAlike(fresh.position, previous.position) || !roundedAlike(fresh.spotDirection, previous.spotDirection))
        return fresh;
    LightDescription d = fresh;
    d.direction = previous.direction;
    d.position = previous.position;
    d.spotDirection = previous.spotDirection;
    return d;
}

bool LightDescription::fromLight(const osg::Light& light, const osg::Matrixd& lightToWorld, LightDescription& out,
                                 std::string* refusal)
{
    const osg::Vec4d p(light.getPosition());
    const osg::Vec3d localAxis(light.getDirection());
    const double cutoff = light.getSpotCutoff();
    const bool cone = cutoff >= 0.0 && cutoff <= 90.0; // OpenGL's spot cone (GL_SPOT_CUTOFF)
    const auto refuse = [&](const char* field, const std::string& value, const char* why) {
        if (refusal) *refusal = std::string(field) + " (" + value + ")" + why;
        return false;
    };
    if (!finite(p)) return refuse("position", listed(p), "");
    if (cone && !finite(localAxis)) return refuse("spot direction", listed(localAxis), "");
    LightDescription d;
    d.lightNum = light.getLightNum();
    if (p.w() == 0.0)
    {
        d.type = DIRECTIONAL;
        d.direction = osg::Matrixd::transform3x3(osg::Vec3d(p.x(), p.y(), p.z()), lightToWorld);
        if (!finite(d.direction)) return refuse("position", listed(p), " placed by a non-finite transform");
        if (d.direction.length2() == 0.0) return refuse("position", listed(p), ", a direction of length 0");
        d.direction.normalize();
    }
    else
    {
        d.position = osg::Vec3d(p.x() / p.w(), p.y() / p.w(), p.z() / p.w()) * lightToWorld;
        if (!finite(d.position)) return refuse("position", listed(p), " placed by a non-finite transform");
        const osg::Vec3d axis = osg::Matrixd::transform3x3(localAxis, lightToWorld);
        if (cone && !finite(axis))
            return refuse("spot direction", listed(localAxis), " placed by a non-finite transform");
        d.type = (cone && cutoff < 90.0 && axis.length2() > 0.0) ? SPOT : POINT;
        if (d.type == SPOT)
        {
            d.spotDirection = axis;
            d.spotDirection.normalize();
            d.spotCutoffDeg = cutoff;
        }
        d.range = attenuationRange(light);
    }
    out = d;
    return true;
}

osg::Matrixd LightFrustum::worldToTexture() const
{
    return view * projection * textureScaleBias();
}

std::array<osg::Vec3d, 8> frustumCorners(const osg::Matrixd& view, const osg::Matrixd& projection)
{
    const osg::Matrixd inv = osg::Matrixd::inverse(view * projection);
    const double xs[4] = {-1, 1, 1, -1};
    const double ys[4] = {-1, -1, 1, 1};
    std::array<osg::Vec3d, 8> c;
    for (int i = 0; i < 8; ++i) c[i] = osg::Vec3d(xs[i % 4], ys[i % 4], i < 4 ? -1.0 : 1.0) * inv;
    return c;
}

/** A perspective light's near plane, at most half its far plane. A depth range much thinner
 *  than its distance (a ground seen straight down from a point light: every point at about
 *  one depth) makes the projection's depth terms, (f + n) / (f - n), large against float
 *  precision: the eye pass's depth of a receiver then misses the map's own by more than the
 *  polygon offset, and the ground shadows itself in bands (docs/robustness.md). A factor of
 *  two costs the map no precision worth having. */
double widerNear(double zNear, double zFar)
{
    return std::min(zNear, 0.5 * zFar);
}

osg::Matrixd withDepthRange(const osg::Matrixd& projection, double zNear, double zFar)
{
    osg::Matrixd p = projection;
    const bool ortho = projection(3, 3) == 1.0 && projection(2, 3) == 0.0;
    if (ortho)
    {
        p(2, 2) = -2.0 / (zFar - zNear);
        p(3, 2) = -(zFar + zNear) / (zFar - zNear);
    }
    else
    {
        p(2, 2) = -(zFar + zNear) / (zFar - zNear);
        p(3, 2) = -2.0 * zFar * zNear / (zFar - zNear);
    }
    return p;
}

std::vector<osg::Vec3d> visibleRegion(const std::array<osg::Vec3d, 8>& c, const osg::BoundingBoxd& bounds)
{
    if (!bounds.valid()) return {};
    for (const osg::Vec3d& p : c)
        if (!finite(p)) return {};
    std::vector<Polygon> faces = {
        {c[0], c[1], c[2], c[3]}, {c[4], c[5], c[6], c[7]}, {c[0], c[1], c[5], c[4]},
        {c[1], c[2], c[6], c[5]}, {c[2], c[3], c[7], c[6]}, {c[3], c[0], c[4], c[7]},
    };
    const osg::Vec4d planes[6] = {
        {1, 0, 0, -bounds.xMin()}, {-1, 0, 0, bounds.xMax()}, {0, 1, 0, -bounds.yMin()},
        {0, -1, 0, bounds.yMax()}, {0, 0, 1, -bounds.zMin()}, {0, 0, -1, bounds.zMax()},
    };
    for (const osg::Vec4d& plane : planes)
    {
        faces = clipPolyhedron(faces, plane);
        if (faces.empty()) return {};
    }
    std::vector<osg::Vec3d> points;
    for (const Polygon& f : faces) points.insert(points.end(), f.begin(), f.end());
    return points;
}

namespace {

/** The light-view ranges of the region (x, y, depth) and of the casters' box. */
struct LightRanges
{
    Range rx, ry, rDepth, cx, cy, cDepth;
    std::vector<osg::Vec3d> region; ///< the region's points in the light view
};

LightRanges lightRanges(const osg::Matrixd& view, const std::vector<osg::Vec3d>& region,
                        const osg::BoundingBoxd& casters)
{
    LightRanges r;
    for (const osg::Vec3d& p : region)
    {
        const osg::Vec3d q = p * view;
        r.region.push_back(q);
        r.rx.expand(q.x()), r.ry.expand(q.y()), r.rDepth.expand(-q.z());
    }
    for (const osg::Vec3d& p : boxCorners(casters))
    {
        const osg::Vec3d q = p * view;
        r.cx.expand(q.x()), r.cy.expand(q.y()), r.cDepth.expand(-q.z());
    }
    return r;
}

} // namespace

LightFrustum fitDirectionalFrustum(const osg::Vec3d& towardLight, const std::vector<osg::Vec3d>& region,
                                   const osg::BoundingBoxd& casters, unsigned int mapSize)
{
    LightFrustum f;
    if (region.empty() || !casters.valid() || !finite(towardLight) || towardLight.length2() == 0.0) return f;
    osg::Vec3d d = towardLight;
    d.normalize();
    // Orientation only for now; the origin is moved by whole texels once the extent is known.
    f.view = osg::Matrixd::lookAt(osg::Vec3d(), -d, orthogonal(d));

    const LightRanges r = lightRanges(f.view, region, casters);
    const Range &rDepth = r.rDepth, &cDepth = r.cDepth;
    Range x{std::max(r.rx.lo, r.cx.lo), std::min(r.rx.hi, r.cx.hi)};
    Range y{std::max(r.ry.lo, r.cy.lo), std::min(r.ry.hi, r.cy.hi)};
    if (x.empty() || y.empty() || cDepth.lo > rDepth.hi) return f;

    // Snap to whole texels of a map one texel larger than needed.
    const double n = std::max(1u, mapSize);
    const double extent = std::max(x.hi - x.lo, y.hi - y.lo);
    const double texel = std::max(extent, 1e-12 * (1.0 + std::fabs(x.lo) + std::fabs(y.lo))) / std::max(1.0, n - 1.0);

    // Move the light's origin next to the region, by whole texels: the texel grid stays where
    // it is, and the depth pass's model-view matrix (single precision on the GPU) stays small
    // for scenes far from the world's origin.
    const osg::Vec3d origin(std::round(0.5 * (x.lo + x.hi) / texel) * texel,
                            std::round(0.5 * (y.lo + y.hi) / texel) * texel,
                            -0.5 * (cDepth.lo + rDepth.hi));
    f.view = f.view * osg::Matrixd::translate(-origin);
    x.lo -= origin.x(), x.hi -= origin.x(), y.lo -= origin.y(), y.hi -= origin.y();
    x.lo = std::floor(x.lo / texel + 1e-9) * texel;
    y.lo = std::floor(y.lo / texel + 1e-9) * texel;
    x.hi = x.lo + texel * n;
    y.hi = y.lo + texel * n;

    const double zNear = cDepth.lo + origin.z();
    const double zFar = rDepth.hi + origin.z();
    const double margin = 1e-3 * (zFar - zNear) + 1e-9 * (std::fabs(zNear) + std::fabs(zFar));
    f.projection = osg::Matrixd::ortho(x.lo, x.hi, y.lo, y.hi, zNear - margin, zFar + margin);
    f.perspective = false;
    f.valid = true;
    return f;
}

namespace {

constexpr double WARP_TURN_STEPS = 32.0;      // the warp's axis turns in steps of 1/32 turn
constexpr double WARP_MIN_SIN_GAMMA = 0.17;   // ~10 degrees between the view and the light
constexpr double WARP_MIN_NEAR_SHARE = 1e-3;  // z_n is at least this share of z_f (cascadeSplits() too)
constexpr double WARP_MAX_NEAR_RATIO = 100.0; // n beyond this many region lengths: uniform
constexpr double WARP_CENTRE_STEPS = 8.0;     // the centre moves on a grid of n / 8

/** v rounded up to the next of the steps 2^(k/16). */
double stepUp(double v)
{
    return std::exp2(std::ceil(16.0 * std::log2(v)) / 16.0);
}

/** The range of n texels, of a size in steps of 2^(1/16), on that size's grid, that holds r,
 *  as near centred on it as the grid allows: the spare texels lie on both sides, where a
 *  later frame's need can slide into them (keepsWarpedFit()). */
Range snapToTexels(Range r, double n)
{
    const double texel =
        stepUp(std::max((r.hi - r.lo) / std::max(1.0, n - 1.0), 1e-12 * (std::fabs(r.lo) + std::fabs(r.hi)) + 1e-300));
    // lo on the grid within [r.hi - n texel, r.lo] (at least a texel wide), nearest the centred start.
    const double first = std::ceil((r.hi - n * texel) / texel), last = std::floor(r.lo / texel);
    const double centred = std::round((0.5 * (r.lo + r.hi) - 0.5 * n * texel) / texel);
    r.lo = std::max(first, std::min(last, centred)) * texel;
    r.hi = r.lo + texel * n;
    return r;
}

/** The warp's light view (rotation only): looking along -d, its y axis the view direction's
 *  part across d turned to a multiple of 1/32 turn of a fixed frame. False (no warp) when the
 *  view looks within ~10 degrees of d or away from it. */
bool warpRotation(const osg::Vec3d& d, osg::Vec3d view, osg::Matrixd& rotation, double& sinGamma)
{
    if (view.normalize() == 0.0) return false;
    const osg::Vec3d across = view - d * (view * d);
    sinGamma = across.length();
    if (!(sinGamma >= WARP_MIN_SIN_GAMMA)) return false;
    const osg::Vec3d a = orthogonal(d), b = d ^ a;
    const double step = 2.0 * osg::PI / WARP_TURN_STEPS;
    const double phi = std::round(std::atan2(across * b, across * a) / step) * step;
    rotation = osg::Matrixd::lookAt(osg::Vec3d(), -d, a * std::cos(phi) + b * std::sin(phi));
    return true;
}

/** Wimmer's n_opt for the region seen from eye along view, in steps of 2^(1/4); 0 if the
 *  region does not lie ahead of the eye. */
double warpDistance(const std::vector<osg::Vec3d>& region, const osg::Vec3d& eye, osg::Vec3d view, double sinGamma,
                    double nearFloor)
{
    view.normalize();
    Range z;
    for (const osg::Vec3d& p : region) z.expand((p - eye) * view);
    if (!(z.hi > 0.0)) return 0.0;
    const double zn = std::max({z.lo, WARP_MIN_NEAR_SHARE * z.hi, nearFloor});
    const double n = (zn + std::sqrt(zn * z.hi)) / sinGamma;
    return std::exp2(std::round(4.0 * std::log2(n)) / 4.0);
}

/** The points (light view) of the part of the hull of `points` with y in [y.lo, y.hi]: those
 *  inside, and where the segments between two of them cross y = y.lo or y = y.hi (every edge
 *  of the hull is such a segment, and every such crossing lies in the hull). */
std::vector<osg::Vec3d> slabPoints(const std::vector<osg::Vec3d>& points, const Range& y)
{
    std::vector<osg::Vec3d> inside;
    for (const osg::Vec3d& p : points)
        if (p.y() >= y.lo && p.y() <= y.hi) inside.push_back(p);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
            for (double plane : {y.lo, y.hi})
            {
                const osg::Vec3d &a = points[i], &b = points[j];
                if ((a.y() - plane) * (b.y() - plane) < 0.0)
                    inside.push_back(a + (b - a) * ((plane - a.y()) / (b.y() - a.y())));
            }
    return inside;
}

/** The warp's projection in the light view whose origin is the centre (y: the axis, depth
 *  -z): x / y over s, 1 / y over t and the depth over y over e, each mapped onto [-1, 1]. */
osg::Matrixd warpProjection(const Range& s, const Range& t, const Range& e)
{
    const double sc = 0.5 * (s.lo + s.hi), sh = 0.5 * (s.hi - s.lo);
    const double tc = 0.5 * (t.lo + t.hi), th = 0.5 * (t.hi - t.lo);
    const double ec = 0.5 * (e.lo + e.hi), eh = 0.5 * (e.hi - e.lo);
    osg::Matrixd p(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0); // row-vector: clip = q * p
    p(0, 0) = 1.0 / sh, p(1, 0) = -sc / sh;                         // x: (x - sc y) / sh
    p(1, 1) = tc / th, p(3, 1) = -1.0 / th;                         // y: (tc y - 1) / th
    p(2, 2) = -1.0 / eh, p(1, 2) = -ec / eh;                        // z: (-z - ec y) / eh
    p(1, 3) = 1.0;                                                  // w: y
    return p;
}

/** The range of x / y over the box [x] x [y] (y > 0). */
Range ratioRange(const Range& x, const Range& y)
{
    Range s;
    for (double a : {x.lo, x.hi})
        for (double b : {y.lo, y.hi}) s.expand(a / b);
    return s;
}

} // namespace

LightFrustum fitWarpedDirectionalFrustum(const osg::Vec3d& towardLight, const std::vector<osg::Vec3d>& region,
                                         const osg::BoundingBoxd& casters, unsigned int mapSize, const osg::Vec3d& eye,
                                         const osg::Vec3d& viewDirection, double nearFloor)
{
    osg::Matrixd rotation;
    double sinGamma = 0.0;
    osg::Vec3d d = towardLight;
    if (region.empty() || !casters.valid() || !finite(d) || d.normalize() == 0.0 || !finite(eye) ||
        !finite(viewDirection) || !warpRotation(d, viewDirection, rotation, sinGamma))
        return fitDirectionalFrustum(towardLight, region, casters, mapSize);
    const double n = warpDistance(region, eye, viewDirection, sinGamma, nearFloor);
    const LightRanges r = lightRanges(rotation, region, casters);
    const Range y{std::max(r.ry.lo, r.cy.lo), std::min(r.ry.hi, r.cy.hi)};
    if (!(n > 0.0) || !std::isfinite(n) || y.empty() || n > WARP_MAX_NEAR_RATIO * (y.hi - y.lo))
        return fitDirectionalFrustum(towardLight, region, casters, mapSize);

    // The centre, on a grid of n / 8: laterally at the eye, n or a little more behind the region.
    const double step = n / WARP_CENTRE_STEPS;
    const osg::Vec3d eyeInLight = eye * rotation;
    // The depth's origin at the eye's own (on a grid of 1/64 of the depth range): the map's
    // depth (d - d_origin) / u changes across the light by (d - d_origin) / u^2 per unit of u,
    // which the lookups' bias (the gradient's length) pays for; near the eye, where u is
    // small, the receivers' d is close to the eye's.
    const double eyeDepth = -eyeInLight.z();
    const double depthStep = stepUp(std::max(r.rDepth.hi - r.cDepth.lo, 1e-9 * (1.0 + std::fabs(eyeDepth)))) / 64.0;
    const osg::Vec3d centre(std::round(eyeInLight.x() / step) * step, std::floor((y.lo - n) / step) * step,
                            -std::round(eyeDepth / depthStep) * depthStep);
    const Range u{y.lo - centre.y(), y.hi - centre.y()};

    Range s; // x / u over the region's part within the casters' extent along the axis ...
    for (const osg::Vec3d& p : slabPoints(r.region, y)) s.expand((p.x() - centre.x()) / (p.y() - centre.y()));
    const Range cs = ratioRange({r.cx.lo - centre.x(), r.cx.hi - centre.x()}, u); // ... and the casters'
    s = {std::max(s.lo, cs.lo), std::min(s.hi, cs.hi)};
    LightFrustum f;
    if (s.empty() || r.cDepth.lo > r.rDepth.hi) return f;
    const double texels = std::max(1u, mapSize);
    const Range needT{1.0 / u.hi, 1.0 / u.lo};
    const Range windowS = snapToTexels(s, texels), windowT = snapToTexels(needT, texels);

    // The depth over u: from the casters nearest the light to the farthest receiver (out to
    // the depth grid), anywhere along the axis the map covers.
    const double zNear = std::floor((r.cDepth.lo + centre.z()) / depthStep) * depthStep;
    const double zFar = std::ceil((r.rDepth.hi + centre.z()) / depthStep) * depthStep;
    const double margin = 1e-3 * (zFar - zNear) + 1e-9 * (std::fabs(zNear) + std::fabs(zFar));
    const Range e = ratioRange({zNear - margin, zFar + margin}, {1.0 / windowT.hi, 1.0 / windowT.lo});
    f.view = rotation * osg::Matrixd::translate(-centre);
    f.projection = warpProjection(windowS, windowT, e);
    f.warpFit = {{s.lo, s.hi}, {needT.lo, needT.hi}, {zNear, zFar}, {windowS.lo, windowS.hi}, {windowT.lo, windowT.hi}};
    f.warped = true;
    f.valid = true;
    return f;
}

bool keepsWarpedFit(const LightFrustum& previous, const LightFrustum& fresh)
{
    if (!previous.valid || !fresh.valid || !previous.warped || !fresh.warped || previous.view != fresh.view)
        return false;
    const LightFrustum::WarpFit &p = previous.warpFit, &q = fresh.warpFit;
    const auto holds = [](const osg::Vec2d& window, const osg::Vec2d& need) {
        return window.x() <= need.x() && need.y() <= window.y();
    };
    // Texel sizes are steps of 2^(1/16): one step is a ratio of 1.044; two, 1.091.
    const auto coarserByAStepAtMost = [](const osg::Vec2d& kept, const osg::Vec2d& fitted) {
        return (kept.y() - kept.x()) <= 1.06 * (fitted.y() - fitted.x());
    };
    return holds(p.windowS, q.needS) && holds(p.windowT, q.needT) && holds(p.needZ, q.needZ) &&
           coarserByAStepAtMost(p.windowS, q.windowS) && coarserByAStepAtMost(p.windowT, q.windowT);
}

std::vector<double> cascadeSplits(double zNear, double zFar, unsigned int count, double lambda)
{
    count = std::max(1u, count);
    const double zn = std::max(zNear, WARP_MIN_NEAR_SHARE * zFar);
    std::vector<double> splits(count + 1);
    for (unsigned int i = 0; i <= count; ++i)
    {
        const double share = double(i) / count;
        splits[i] = lambda * zn * std::pow(zFar / zn, share) + (1.0 - lambda) * (zn + (zFar - zn) * share);
    }
    splits.front() = zNear;
    splits.back() = zFar;
    return splits;
}

bool needsCubeFaces(const LightDescription& light, const std::vector<osg::Vec3d>& region, double maxFovDeg)
{
    if (light.type != LightDescription::POINT || region.empty()) return false;
    osg::Vec3d axis;
    for (const osg::Vec3d& p : region) axis += p;
    axis = axis / static_cast<double>(region.size()) - light.position;
    if (axis.normalize() == 0.0) return true; // the light amid the region
    const double cosMax = std::cos(osg::DegreesToRadians(0.5 * maxFovDeg));
    for (const osg::Vec3d& p : region)
    {
        osg::Vec3d d = p - light.position;
        if (d.normalize() > 0.0 && d * axis < cosMax) return true;
    }
    return false;
}

double cubeFaceFov(unsigned int mapSize, double marginTexels)
{
    const double size = std::max(1u, mapSize);
    const double inner = std::max(0.8, 1.0 - 2.0 * marginTexels / size); // at most ~12.7 degrees wider
    return osg::RadiansToDegrees(2.0 * std::atan(1.0 / inner));
}

bool canShadow(const LightDescription& light, const CasterPart& part, const osg::BoundingBoxd& receivers)
{
    if (!part.box.valid()) return false;
    if (!part.flat || !receivers.valid() || light.type == LightDescription::DIRECTIONAL) return true;
    const double lightSide = (light.position - part.planePoint) * part.planeNormal;
    const double tolerance = 1e-6 * (receivers._max - receivers._min).length(); // float bounds
    if (std::abs(lightSide) <= tolerance) return true; // the light in the plane: keep it, conservatively
    for (const osg::Vec3d& corner : boxCorners(receivers))
        if (((corner - part.planePoint) * part.planeNormal) * (lightSide > 0.0 ? 1.0 : -1.0) < -tolerance)
            return true; // a receiver corner beyond the plane
    return false;
}

std::vector<LightFrustum> fitCubeFaces(const LightDescription& light, const std::vector<osg::Vec3d>& region,
                                       const osg::BoundingBoxd& casters, unsigned int mapSize,
                                       const std::vector<osg::BoundingBoxd>* parts, double marginTexels)
{
    std::vector<LightFrustum> faces;
    if (region.empty() || !casters.valid() || !finite(light.position)) return faces;
    static const osg::Vec3d axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const osg::Vec3d ups[6] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};
    const double fov = cubeFaceFov(mapSize, marginTexels);
    const double tanHalf = std::tan(osg::DegreesToRadians(0.5 * fov));
    const std::array<osg::Vec3d, 8> casterCorners = boxCorners(casters);
    // Every caster point inside a face's pyramid is at least this deep along its axis: the
    // depth precision of a face depends on it (0 when the light is among the casters).
    const osg::Vec3d nearestCaster(std::clamp(light.position.x(), casters.xMin(), casters.xMax()),
                                   std::clamp(light.position.y(), casters.yMin(), casters.yMax()),
                                   std::clamp(light.position.z(), casters.zMin(), casters.zMax()));
    const double casterDistance = (nearestCaster - light.position).length() / std::sqrt(1.0 + 2.0 * tanHalf * tanHalf);
    for (int face = 0; face < 6; ++face)
    {
        LightFrustum f;
        f.view = osg::Matrixd::lookAt(light.position, light.position + axes[face], ups[face]);
        // Outside the pyramid when every point is beyond one of its planes (in eye space,
        // looking down -z: depth = -z, inside |x|, |y| <= depth * tanHalf, depth > 0).
        const auto outside = [&](const auto& points) {
            bool beyond[5] = {true, true, true, true, true};
            for (const osg::Vec3d& p : points)
            {
                const osg::Vec3d q = p * f.view;
                const double depth = -q.z();
                beyond[0] = beyond[0] && depth <= 0.0;
                beyond[1] = beyond[1] && q.x() > depth * tanHalf;
                beyond[2] = beyond[2] && -q.x() > depth * tanHalf;
                beyond[3] = beyond[3] && q.y() > depth * tanHalf;
                beyond[4] = beyond[4] && -q.y() > depth * tanHalf;
            }
            return beyond[0] || beyond[1] || beyond[2] || beyond[3] || beyond[4];
        };
        if (outside(region) || outside(casterCorners)) continue;
        if (parts && std::all_of(parts->begin(), parts->end(),
                                 [&](const osg::BoundingBoxd& part) { return outside(boxCorners(part)); }))
            continue; // the casters' box meets the face, no caster does
        Range depth, casterDepth;
        for (const osg::Vec3d& p : region) depth.expand(-(p * f.view).z());
        for (const osg::Vec3d& p : casterCorners) casterDepth.expand(-(p * f.view).z());
        if (depth.hi <= 0.0) continue;
        const double zFar = depth.hi * 1.01;
        const double zNear = std::max({casterDepth.lo * 0.99, casterDistance * 0.99, zFar * 1e-3});
        if (zNear >= zFar) continue;
        f.projection = osg::Matrixd::perspective(fov, 1.0, widerNear(zNear, zFar), zFar);
        f.perspective = true;
        f.faceCore = 0.5 / tanHalf;
        f.valid = true;
        faces.push_back(f);
    }
    return faces;
}

bool lightReachesRegion(const LightDescription& light, const std::vector<osg::Vec3d>& region)
{
    if (region.empty()) return false;
    if (light.type == LightDescription::DIRECTIONAL) return true;
    osg::BoundingBoxd box;
    for (const osg::Vec3d& p : region) box.expandBy(p);
    const osg::Vec3d nearest(std::clamp(light.position.x(), box.xMin(), box.xMax()),
                             std::clamp(light.position.y(), box.yMin(), box.yMax()),
                             std::clamp(light.position.z(), box.zMin(), box.zMax()));
    if ((nearest - light.position).length() > light.range) return false;
    if (light.type != LightDescription::SPOT) return true;
    // The cone lies on the positive side of every plane through its apex whose normal is
    // within 90 degrees - cutoff of its axis: such a plane with every region point on its
    // negative side separates the hull from the cone. Candidates: the axis itself, and the
    // axis tilted away from the region's centre as far as the cone allows.
    const osg::Vec3d& axis = light.spotDirection;
    const double tilt = osg::PI_2 - osg::DegreesToRadians(std::min(light.spotCutoffDeg, 90.0));
    osg::Vec3d side = box.center() - light.position;
    side -= axis * (side * axis);
    std::vector<osg::Vec3d> normals = {axis};
    if (side.normalize() > 0.0) normals.push_back(axis * std::cos(tilt) - side * std::sin(tilt));
    for (const osg::Vec3d& n : normals)
    {
        const bool separated = std::all_of(region.begin(), region.end(),
                                           [&](const osg::Vec3d& p) { return (p - light.position) * n < 0.0; });
        if (separated) return false;
    }
    // The sphere around the region's box: outside when the angle from the axis to its centre
    // exceeds the cutoff by more than its angular radius.
    const osg::Vec3d toCentre = box.center() - light.position;
    const double distance = toCentre.length();
    const double radius = box.radius();
    if (distance <= radius) return true;
    const double axisAngle = std::acos(std::clamp(toCentre * axis / distance, -1.0, 1.0));
    return axisAngle - std::asin(radius / distance) <= osg::DegreesToRadians(light.spotCutoffDeg);
}

LightFrustum fitPerspectiveFrustum(const LightDescription& light, const std::vector<osg::Vec3d>& region,
                                   const osg::BoundingBoxd& casters, double maxFovDeg)
{
    LightFrustum f;
    if (region.empty() || !casters.valid() || !finite(light.position)) return f;
    osg::Vec3d axis = light.spotDirection;
    if (light.type != LightDescription::SPOT)
    {
        osg::Vec3d centre;
        for (const osg::Vec3d& p : region) centre += p;
        axis = centre / static_cast<double>(region.size()) - light.position;
        // A light exactly at the region's centre still needs an axis: toward the casters'
        // centre, else straight down.
        if (finite(axis) && axis.length2() == 0.0) axis = casters.center() - light.position;
        if (finite(axis) && axis.length2() == 0.0) axis = osg::Vec3d(0.0, 0.0, -1.0);
    }
    if (!finite(axis) || axis.length2() == 0.0) return f;
    axis.normalize();
    f.view = osg::Matrixd::lookAt(light.position, light.position + axis, orthogonal(axis));

    double maxHalf = osg::DegreesToRadians(maxFovDeg * 0.5);
    if (light.type == LightDescription::SPOT) maxHalf = std::min(maxHalf, osg::DegreesToRadians(light.spotCutoffDeg) * 1.02);
    const double maxTan = std::tan(maxHalf);

    double tanHalf = 0.0;
    Range depth;
    for (const osg::Vec3d& p : region)
    {
        const osg::Vec3d q = p * f.view;
        const double z = -q.z();
        depth.expand(z);
        tanHalf = z > 0.0 ? std::max(tanHalf, std::max(std::fabs(q.x()), std::fabs(q.y())) / z) : maxTan;
    }
    if (depth.hi <= 0.0) return f;
    tanHalf = std::min(tanHalf * 1.01, maxTan);

    Range casterDepth;
    for (const osg::Vec3d& p : boxCorners(casters)) casterDepth.expand(-(p * f.view).z());
    const double zFar = depth.hi * 1.01;
    const double zNear = std::max(std::min(casterDepth.lo, depth.lo) * 0.99, zFar * 1e-4);
    if (casterDepth.hi <= 0.0 || zNear >= zFar) return f;

    f.projection = osg::Matrixd::perspective(osg::RadiansToDegrees(2.0 * std::atan(tanHalf)), 1.0,
                                             widerNear(zNear, zFar), zFar);
    f.perspective = true;
    f.valid = true;
    return f;
}

} // namespace osgShadowSilhouette
