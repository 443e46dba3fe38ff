/* -*-c++-*- osgShadowSilhouette - hard shadows for OpenSceneGraph
 *
 * Distributed under the terms of the OpenSceneGraph Public License (OSGPL).
 */

#ifndef OSGSHADOWSILHOUETTE_VERTEXBOUNDS_H
#define OSGSHADOWSILHOUETTE_VERTEXBOUNDS_H 1

#include <osg/Vec3f>

#include <algorithm>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace osgShadowSilhouette {
namespace detail {

/** Whether the float's exponent is all ones (Inf or NaN), read on its bits. */
inline std::uint32_t notFiniteBit(float value)
{
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return (bits & 0x7f800000u) == 0x7f800000u;
}

/** Grows [@p low, @p high] by @p points [@p first, @p end) one by one, as std::min and
 *  std::max do; returns whether one of their coordinates was not finite. */
inline std::uint32_t growBox(const osg::Vec3f* points, std::size_t first, std::size_t end, osg::Vec3f& low,
                             osg::Vec3f& high)
{
    std::uint32_t notFinite = 0;
    for (std::size_t i = first; i < end; ++i)
        for (int k = 0; k < 3; ++k)
        {
            const float v = points[i][k];
            notFinite |= notFiniteBit(v);
            low[k] = std::min(low[k], v), high[k] = std::max(high[k], v);
        }
    return notFinite;
}

#if defined(__SSE2__)
/** The minimum (@p high false) or maximum over lanes holding one coordinate: four vertices
 *  lie in three registers as (x0 y0 z0 x1) (y1 z1 x2 y2) (z2 x3 y3 z3). */
inline osg::Vec3f foldLanes(const __m128 r[3], bool high)
{
    float l[12];
    for (int k = 0; k < 3; ++k) _mm_storeu_ps(l + 4 * k, r[k]);
    osg::Vec3f out(l[0], l[1], l[2]);
    for (int i = 3; i < 12; ++i) out[i % 3] = high ? std::max(out[i % 3], l[i]) : std::min(out[i % 3], l[i]);
    return out;
}
#endif

/** The box of @p count points, and whether every coordinate is finite (false: the box is
 *  meaningless). An empty set gives the empty box (FLT_MAX, -FLT_MAX), as osg::BoundingBox.
 *  Each coordinate's extremes are those of std::min and std::max over the points, but for
 *  the sign of a zero extreme (the order and the operands' differ: four points a step in
 *  SSE2). */
inline bool finiteBox(const osg::Vec3f* points, std::size_t count, osg::Vec3f& low, osg::Vec3f& high)
{
    low.set(FLT_MAX, FLT_MAX, FLT_MAX);
    high.set(-FLT_MAX, -FLT_MAX, -FLT_MAX);
    std::size_t i = 0;
    std::uint32_t notFinite = 0;
#if defined(__SSE2__)
    static_assert(sizeof(osg::Vec3f) == 3 * sizeof(float), "packed vertices");
    if (count >= 4)
    {
        const float* p = points->ptr();
        __m128 lo[3], hi[3];
        for (int k = 0; k < 3; ++k) lo[k] = _mm_set1_ps(FLT_MAX), hi[k] = _mm_set1_ps(-FLT_MAX);
        const __m128i exponent = _mm_set1_epi32(0x7f800000);
        __m128i bad = _mm_setzero_si128();
        for (; i + 4 <= count; i += 4, p += 12)
            for (int k = 0; k < 3; ++k)
            {
                const __m128 r = _mm_loadu_ps(p + 4 * k);
                lo[k] = _mm_min_ps(lo[k], r), hi[k] = _mm_max_ps(hi[k], r);
                const __m128i e = _mm_and_si128(_mm_castps_si128(r), exponent);
                bad = _mm_or_si128(bad, _mm_cmpeq_epi32(e, exponent));
            }
        notFinite = _mm_movemask_epi8(bad) != 0;
        low = foldLanes(lo, false);
        high = foldLanes(hi, true);
    }
#endif
    notFinite |= growBox(points, i, count, low, high);
    return notFinite == 0;
}

} // namespace detail
} // namespace osgShadowSilhouette

#endif
