/* -*-c++-*- osgShadowSilhouette - hard shadows for OpenSceneGraph
 *
 * Distributed under the terms of the OpenSceneGraph Public License (OSGPL).
 */

#include <osgShadowSilhouette/SilhouetteExtractor>

#include <algorithm>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace osgShadowSilhouette {

namespace {

/** How each face casts: +1 as it is, -1 flipped, 0 not at all. */
enum class CastMode
{
    CLOSED,          ///< lit +1, unlit 0, dark cap from the unlit faces
    LIT_FACES_ONLY,  ///< lit +1, unlit 0, dark cap from the lit faces reversed
    TWO_SIDED        ///< lit +1, unlit -1
};

CastMode castMode(bool closed, OpenCasterRule rule)
{
    if (closed) return CastMode::CLOSED;
    return rule == OpenCasterRule::TWO_SIDED ? CastMode::TWO_SIDED : CastMode::LIT_FACES_ONLY;
}

void pushEdge(SilhouetteEdges& out, std::uint32_t a, std::uint32_t b, std::uint8_t multiplicity)
{
    out.vertexIndices.push_back(a);
    out.vertexIndices.push_back(b);
    out.multiplicity.push_back(multiplicity);
}

/** Edges between a lit and an unlit face, lit face on the left. The hot loop: it reads the
 *  face pairs only and looks the vertices up for the few silhouette edges. */
void extractInteriorEdges(const MeshAdjacency& mesh, std::uint8_t multiplicity,
                          SilhouetteEdges& out)
{
    const std::uint8_t* lit = out.lit.data();
    const EdgeFaces* faces = mesh.edgeFaces.data();
    const std::size_t count = mesh.edgeFaces.size();
    for (std::size_t i = 0; i < count; ++i)
    {
        const std::uint8_t a = lit[faces[i].face0];
        if (a == lit[faces[i].face1]) continue;
        const EdgeVertices& v = mesh.edgeVertices[i];
        if (a) pushEdge(out, v.v0, v.v1, multiplicity);
        else pushEdge(out, v.v1, v.v0, multiplicity);
    }
}

void extractBoundaryEdges(const MeshAdjacency& mesh, CastMode mode, SilhouetteEdges& out)
{
    const std::uint8_t* lit = out.lit.data();
    for (const BoundaryEdge& e : mesh.boundaryEdges)
    {
        if (lit[e.face]) pushEdge(out, e.v0, e.v1, 1);
        else if (mode == CastMode::TWO_SIDED) pushEdge(out, e.v1, e.v0, 1);
    }
}

void fillEdgePositions(const MeshAdjacency& mesh, SilhouetteEdges& out)
{
    out.positions.resize(out.vertexIndices.size());
    const osg::Vec3f* p = mesh.positions.data();
    for (std::size_t i = 0; i < out.vertexIndices.size(); ++i)
        out.positions[i] = p[out.vertexIndices[i]];
}

void fillVertices(const MeshAdjacency& mesh, const osg::Vec4d& light, ShadowVolume& out)
{
    const std::size_t n = mesh.positions.size();
    out.vertices.resize(2 * n);
    osg::Vec4f* near = out.vertices.data();
    osg::Vec4f* far = near + n;
    const osg::Vec3f* p = mesh.positions.data();
    for (std::size_t i = 0; i < n; ++i) near[i].set(p[i].x(), p[i].y(), p[i].z(), 1.0f);

    const osg::Vec3f l(light.x(), light.y(), light.z());
    if (light.w() == 0.0)
    {
        std::fill(far, far + n, osg::Vec4f(-l, 0.0f));
        return;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        const osg::Vec3f d = p[i] - l;
        far[i].set(d.x(), d.y(), d.z(), 0.0f);
        if (d.x() == 0.0f && d.y() == 0.0f && d.z() == 0.0f) far[i] = near[i];
    }
}

/** Side quad of edge a -> b (casting face on its left): (b, a, a'), (b, a', b'). */
std::uint32_t* writeSides(const SilhouetteEdges& silhouette, std::uint32_t n, std::uint32_t* w)
{
    const std::uint32_t* v = silhouette.vertexIndices.data();
    for (std::size_t e = 0; e < silhouette.multiplicity.size(); ++e)
    {
        const std::uint32_t a = v[2 * e], b = v[2 * e + 1];
        for (std::uint8_t k = 0; k < silhouette.multiplicity[e]; ++k)
        {
            w[0] = b; w[1] = a; w[2] = a + n;
            w[3] = b; w[4] = a + n; w[5] = b + n;
            w += 6;
        }
    }
    return w;
}

inline void writeTriangle(std::uint32_t*& w, std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    w[0] = a; w[1] = b; w[2] = c;
    w += 3;
}

/** Writes the light cap at @p light and the dark cap at @p dark for every face, one loop
 *  per mode so that the per-face work has no mode test. */
void writeCaps(const MeshAdjacency& mesh, const std::uint8_t* lit, CastMode mode,
               std::uint32_t n, std::uint32_t* light, std::uint32_t* dark)
{
    const MeshTriangle* faces = mesh.faces.data();
    const std::size_t count = mesh.faces.size();
    if (mode == CastMode::CLOSED)
    {
        for (std::size_t f = 0; f < count; ++f)
        {
            const std::uint32_t a = faces[f].v[0], b = faces[f].v[1], c = faces[f].v[2];
            if (lit[f]) writeTriangle(light, a, b, c);
            else writeTriangle(dark, a + n, b + n, c + n);
        }
        return;
    }
    for (std::size_t f = 0; f < count; ++f)
    {
        const std::uint32_t a = faces[f].v[0], b = faces[f].v[1], c = faces[f].v[2];
        if (lit[f])
        {
            writeTriangle(light, a, b, c);
            writeTriangle(dark, a + n, c + n, b + n);
        }
        else if (mode == CastMode::TWO_SIDED)
        {
            writeTriangle(light, a, c, b);
            writeTriangle(dark, a + n, b + n, c + n);
        }
    }
}

/** Number of faces in the light cap and in the dark cap. */
void capSizes(CastMode mode, std::size_t faces, std::size_t lit, std::size_t& light, std::size_t& dark)
{
    switch (mode)
    {
        case CastMode::CLOSED:         light = lit;   dark = faces - lit; break;
        case CastMode::LIT_FACES_ONLY: light = lit;   dark = lit;         break;
        case CastMode::TWO_SIDED:      light = faces; dark = faces;       break;
    }
}

#if defined(__SSE2__)
/** Per mask of four faces (bit i: face i toward the light), their four bytes of `lit` (0 or 1,
 *  the first face in the lowest byte) as one little-endian word. */
struct LitWords
{
    std::uint32_t word[16];
    constexpr LitWords() : word()
    {
        for (unsigned mask = 0; mask < 16; ++mask)
            for (unsigned i = 0; i < 4; ++i) word[mask] |= ((mask >> i) & 1u) << (8 * i);
    }
};
constexpr LitWords kLitWords;

/** Whether each of the two faces at @p p faces the light (bit 0 the first, bit 1 the second):
 *  (x*lx + z*lz) + (y*ly + w*lw) > 0 in SSE2, the order facesLight() uses. */
inline int litPair(const double* p, __m128d lxy, __m128d lzw)
{
    // s = (x*lx + z*lz, y*ly + w*lw) for each of the two faces
    const __m128d s0 = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(p), lxy), _mm_mul_pd(_mm_loadu_pd(p + 2), lzw));
    const __m128d s1 = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(p + 4), lxy), _mm_mul_pd(_mm_loadu_pd(p + 6), lzw));
    const __m128d dots = _mm_add_pd(_mm_unpacklo_pd(s0, s1), _mm_unpackhi_pd(s0, s1));
    return _mm_movemask_pd(_mm_cmpgt_pd(dots, _mm_setzero_pd()));
}

/** Four faces per step (two pairs in SSE2, litPair()), their bytes written as one word. */
std::size_t classifyPlanes(const osg::Vec4d* planes, std::size_t count, const osg::Vec4d& light,
                           std::uint8_t* out)
{
    if (count == 0) return 0; // planes may be null (an empty mesh's vector)
    const double* p = planes->ptr();
    const __m128d lxy = _mm_set_pd(light.y(), light.x());
    const __m128d lzw = _mm_set_pd(light.w(), light.z());
    std::size_t litCount = 0, f = 0;
    for (; f + 4 <= count; f += 4, p += 16)
    {
        const std::uint32_t word = kLitWords.word[litPair(p, lxy, lzw) | (litPair(p + 8, lxy, lzw) << 2)];
        std::memcpy(out + f, &word, sizeof word);
        litCount += (word * 0x01010101u) >> 24; // the sum of its four bytes
    }
    for (; f < count; ++f)
    {
        out[f] = facesLight(planes[f], light);
        litCount += out[f];
    }
    return litCount;
}
#else
std::size_t classifyPlanes(const osg::Vec4d* planes, std::size_t count, const osg::Vec4d& light,
                           std::uint8_t* out)
{
    std::size_t litCount = 0;
    for (std::size_t f = 0; f < count; ++f)
    {
        out[f] = facesLight(planes[f], light);
        litCount += out[f];
    }
    return litCount;
}
#endif

}

osg::Vec4d lightInObjectSpace(const HomogeneousLight& light, const osg::Matrixd& world)
{
    osg::Vec4d l = light.position * osg::Matrixd::inverse(world);
    if (l.w() != 0.0) return osg::Vec4d(l.x() / l.w(), l.y() / l.w(), l.z() / l.w(), 1.0);
    return l;
}

std::size_t SilhouetteExtractor::classifyFaces(const MeshAdjacency& mesh,
                                               const osg::Vec4d& objectLight,
                                               std::vector<std::uint8_t>& lit)
{
    const std::size_t count = mesh.planes.size();
    lit.resize(count);
    return classifyPlanes(mesh.planes.data(), count, objectLight, lit.data());
}

void SilhouetteExtractor::extract(const MeshAdjacency& mesh, const osg::Vec4d& objectLight,
                                  SilhouetteEdges& out) const
{
    out.objectLight = objectLight;
    out.closedCaster = mesh.isClosedOutward();
    out.rule = _openCasterRule;
    out.vertexIndices.clear();
    out.multiplicity.clear();
    out.litFaceCount = classifyFaces(mesh, objectLight, out.lit);

    const CastMode mode = castMode(out.closedCaster, _openCasterRule);
    extractInteriorEdges(mesh, mode == CastMode::TWO_SIDED ? 2 : 1, out);
    extractBoundaryEdges(mesh, mode, out);
    fillEdgePositions(mesh, out);
}

void SilhouetteExtractor::extract(const MeshAdjacency& mesh, const HomogeneousLight& light,
                                  const osg::Matrixd& world, SilhouetteEdges& out) const
{
    extract(mesh, lightInObjectSpace(light, world), out);
}

void SilhouetteExtractor::buildVolume(const MeshAdjacency& mesh, const SilhouetteEdges& silhouette,
                                      ShadowVolume& out) const
{
    const CastMode mode = castMode(silhouette.closedCaster, silhouette.rule);
    out.closedCaster = silhouette.closedCaster;
    fillVertices(mesh, silhouette.objectLight, out);

    std::size_t quads = 0;
    for (std::uint8_t m : silhouette.multiplicity) quads += m;
    std::size_t lightFaces = 0, darkFaces = 0;
    capSizes(mode, mesh.faces.size(), silhouette.litFaceCount, lightFaces, darkFaces);

    // Sides, dark cap, light cap: z-fail's sides and dark cap are one range.
    out.sides = IndexRange{ 0, std::uint32_t(6 * quads) };
    out.darkCap = IndexRange{out.sides.count, std::uint32_t(3 * darkFaces)};
    out.lightCap = IndexRange{out.darkCap.first + out.darkCap.count, std::uint32_t(3 * lightFaces)};
    out.indices.resize(out.lightCap.first + out.lightCap.count);

    const std::uint32_t n = std::uint32_t(mesh.positions.size());
    std::uint32_t* base = out.indices.data();
    writeSides(silhouette, n, base);
    writeCaps(mesh, silhouette.lit.data(), mode, n, base + out.lightCap.first,
              base + out.darkCap.first);
}

void SilhouetteExtractor::buildVolume(const MeshAdjacency& mesh, const HomogeneousLight& light,
                                      const osg::Matrixd& world, SilhouetteEdges& silhouette,
                                      ShadowVolume& out) const
{
    extract(mesh, light, world, silhouette);
    buildVolume(mesh, silhouette, out);
}

}
