// Visibility masks (MEASURE.md, "Soft shadows"): the 16-bit encoding, the scores against
// the reference, thresholds to and from hard masks. Images and files: MaskTools.cpp.
#include "reference/Reference.h"

#include <algorithm>
#include <cmath>

namespace ossref {

namespace {

bool consistent(const VisibilityMask& m)
{
    return m.width > 0 && m.height > 0 && m.value.size() == size_t(m.width) * m.height;
}

/** The k-th smallest of `values` with k = ceil(fraction * n) (nearest rank); 0 if empty. */
double nearestRank(std::vector<double> values, double fraction)
{
    if (values.empty()) return 0.0;
    const size_t k = size_t(std::ceil(fraction * double(values.size())));
    const size_t index = std::min(values.size(), std::max<size_t>(k, 1)) - 1;
    std::nth_element(values.begin(), values.begin() + index, values.end());
    return values[index];
}

bool inPenumbra(double v)
{
    return v > PENUMBRA_LOW && v < PENUMBRA_HIGH;
}

/** Which pixels count and how far apart the two masks are there (no hard scores). */
void scoreVisibility(const VisibilityMask& reference, const VisibilityMask& candidate, VisibilityComparison& r)
{
    double sum = 0.0;
    double penumbraSum = 0.0;
    std::vector<double> penumbraErrors;
    for (size_t i = 0; i < reference.value.size(); ++i)
    {
        const bool refBackground = reference.value[i] == VIS_BACKGROUND;
        const bool background = candidate.value[i] == VIS_BACKGROUND;
        if (refBackground != background) ++r.coverageMismatch;
        if (refBackground || background) continue;
        if (reference.isGrazing(i))
        {
            ++r.grazingExcluded;
            continue;
        }
        ++r.geometryPixels;
        const double vRef = decodeVisibility(reference.value[i]);
        const double error = std::fabs(decodeVisibility(candidate.value[i]) - vRef);
        sum += error;
        if (!inPenumbra(vRef)) continue;
        penumbraSum += error;
        penumbraErrors.push_back(error);
    }
    r.penumbraPixels = (long long)penumbraErrors.size();
    r.visMae = r.geometryPixels > 0 ? sum / double(r.geometryPixels) : 0.0;
    r.visMaePenumbra = r.penumbraPixels > 0 ? penumbraSum / double(r.penumbraPixels) : 0.0;
    r.visP99Penumbra = nearestRank(std::move(penumbraErrors), 0.99);
}

} // namespace

uint16_t encodeVisibility(double v)
{
    const double clamped = v > 0.0 ? std::min(1.0, v) : 0.0;
    return uint16_t(std::lround(clamped * VIS_FULL));
}

VisibilityComparison compareVisibility(const VisibilityMask& reference, const VisibilityMask& candidate)
{
    VisibilityComparison r;
    // The thresholded masks' comparison checks that both are consistent and of one size.
    const Comparison hard = compareMasks(thresholdVisibility(candidate), thresholdVisibility(reference));
    r.error = hard.error;
    if (!hard.valid) return r;
    r.valid = true;
    r.hardWrongPixels = hard.wrongPixels;
    r.hardWrongPct = hard.wrongPct;
    scoreVisibility(reference, candidate, r);
    return r;
}

Mask thresholdVisibility(const VisibilityMask& mask)
{
    if (!consistent(mask)) return Mask();
    Mask m = Mask::filled(mask.width, mask.height, MASK_BACKGROUND);
    for (size_t i = 0; i < m.value.size() && i < mask.value.size(); ++i)
    {
        const uint16_t v = mask.value[i];
        if (v != VIS_BACKGROUND) m.value[i] = decodeVisibility(v) > 0.5 ? MASK_LIT : MASK_NO_LIGHT;
        m.grazing[i] = mask.isGrazing(i) ? 1 : 0;
    }
    return m;
}

VisibilityMask visibilityFromMask(const Mask& mask)
{
    VisibilityMask m = VisibilityMask::filled(mask.width, mask.height, VIS_BACKGROUND);
    for (size_t i = 0; i < m.value.size() && i < mask.value.size(); ++i)
    {
        const uint8_t c = classify(mask.value[i]);
        if (c != MASK_BACKGROUND) m.value[i] = c == MASK_LIT ? VIS_FULL : VIS_NONE;
        m.grazing[i] = mask.isGrazing(i) ? 1 : 0;
    }
    return m;
}

} // namespace ossref
