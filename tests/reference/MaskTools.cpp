// Shadow masks: comparison against the reference (MEASURE.md), distance to the reference
// shadow boundary, conversion to and from osg::Image, PNG files and diff images; the
// images and files of visibility masks.
#include "reference/Reference.h"

#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace ossref {

namespace {

const double kFar = 1e30;  // "no boundary" in the squared distance transform

/** 1D squared Euclidean distance transform of f (Felzenszwalb & Huttenlocher 2012). */
void distanceTransform1D(const std::vector<double>& f, std::vector<double>& d)
{
    const int n = int(f.size());
    std::vector<int> v(n);
    std::vector<double> z(n + 1);
    int k = 0;
    v[0] = 0;
    z[0] = -kFar;
    z[1] = kFar;
    for (int q = 1; q < n; ++q)
    {
        double s = 0.0;
        while (true)
        {
            s = ((f[q] + double(q) * q) - (f[v[k]] + double(v[k]) * v[k])) / (2.0 * q - 2.0 * v[k]);
            if (s > z[k] || k == 0) break;
            --k;
        }
        if (s <= z[k]) s = z[k];  // only possible at k == 0
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = kFar;
    }
    d.resize(n);
    k = 0;
    for (int q = 0; q < n; ++q)
    {
        while (z[k + 1] < q) ++k;
        d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
    }
}

bool isBoundary(const std::vector<uint8_t>& c, int w, int h, int x, int y)
{
    const uint8_t v = c[size_t(y) * w + x];
    if (v == MASK_BACKGROUND) return false;
    const uint8_t other = v == MASK_LIT ? MASK_NO_LIGHT : MASK_LIT;
    return (x > 0 && c[size_t(y) * w + x - 1] == other) || (x + 1 < w && c[size_t(y) * w + x + 1] == other) ||
           (y > 0 && c[size_t(y - 1) * w + x] == other) || (y + 1 < h && c[size_t(y + 1) * w + x] == other);
}

template <class MaskT>
bool consistent(const MaskT& m)
{
    return m.width > 0 && m.height > 0 && m.value.size() == size_t(m.width) * m.height;
}

/** The mask that fromImage() makes of the image file at `path`; false (and `out`
 *  untouched) if the file is unreadable or the mask empty. */
template <class MaskT, class FromImage>
bool readImageAs(const std::string& path, MaskT& out, FromImage fromImage)
{
    osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(path);
    if (!image.valid()) return false;
    MaskT m = fromImage(*image);
    if (m.empty()) return false;
    out = std::move(m);
    return true;
}

/** First channel of the pixel at p, as 0..255. */
uint8_t firstChannel(const unsigned char* p, GLenum dataType)
{
    if (dataType == GL_UNSIGNED_BYTE) return *p;
    float f = 0.0f;
    std::memcpy(&f, p, sizeof(float));
    if (!(f > 0.0f)) return 0;
    return uint8_t(std::min(255.0f, f * 255.0f + 0.5f));
}

bool supportedFormat(GLenum format)
{
    switch (format)
    {
    case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_RED: case GL_RGB: case GL_RGBA: case GL_BGR: case GL_BGRA:
        return true;
    default:
        return false;
    }
}

/** A mask whose value at each pixel is pixel(bytes of the image's pixel), the image's
 *  rows bottom first; empty for an empty image or a format supportedFormat() refuses. */
template <class MaskT, class Pixel>
MaskT maskOfImage(const osg::Image& image, Pixel pixel)
{
    if (image.s() <= 0 || image.t() <= 0 || !image.data() || !supportedFormat(image.getPixelFormat())) return MaskT();
    MaskT m = MaskT::filled(image.s(), image.t());
    const size_t pixelBytes = image.getPixelSizeInBits() / 8;
    for (int r = 0; r < m.height; ++r)
    {
        const unsigned char* row = image.data(0, unsigned(m.height - 1 - r));
        for (int x = 0; x < m.width; ++x) m.value[size_t(r) * m.width + x] = pixel(row + size_t(x) * pixelBytes);
    }
    return m;
}

/** A one-channel image of the mask values (GL_LUMINANCE, `dataType` of the values' size),
 *  bottom row first, so that osgDB writes the file top row first. Null for an empty mask. */
template <class MaskT>
osg::ref_ptr<osg::Image> luminanceImage(const MaskT& mask, GLenum dataType, GLint internalFormat)
{
    if (!consistent(mask)) return nullptr;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(mask.width, mask.height, 1, GL_LUMINANCE, dataType, 1);
    image->setInternalTextureFormat(internalFormat);
    const size_t rowBytes = sizeof(mask.value[0]) * size_t(mask.width);
    for (int r = 0; r < mask.height; ++r)
        std::memcpy(image->data(0, unsigned(mask.height - 1 - r)), &mask.value[size_t(r) * mask.width], rowBytes);
    return image;
}

} // namespace

long long Mask::count(uint8_t v) const { return std::count(value.begin(), value.end(), v); }

uint8_t classify(uint8_t v)
{
    if (v < 64) return MASK_NO_LIGHT;
    if (v > 192) return MASK_LIT;
    return MASK_BACKGROUND;
}

std::vector<float> boundaryDistance(const Mask& mask)
{
    const int w = mask.width, h = mask.height;
    if (!consistent(mask)) return {};
    std::vector<uint8_t> c(mask.value.size());
    std::transform(mask.value.begin(), mask.value.end(), c.begin(), classify);

    std::vector<double> grid(c.size()), f, d;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) grid[size_t(y) * w + x] = isBoundary(c, w, h, x, y) ? 0.0 : kFar;
    f.resize(h);
    for (int x = 0; x < w; ++x)  // columns
    {
        for (int y = 0; y < h; ++y) f[y] = grid[size_t(y) * w + x];
        distanceTransform1D(f, d);
        for (int y = 0; y < h; ++y) grid[size_t(y) * w + x] = d[y];
    }
    f.resize(w);
    std::vector<float> out(c.size());
    for (int y = 0; y < h; ++y)  // rows
    {
        std::copy(grid.begin() + size_t(y) * w, grid.begin() + size_t(y + 1) * w, f.begin());
        distanceTransform1D(f, d);
        for (int x = 0; x < w; ++x)
            out[size_t(y) * w + x] = d[x] >= 0.5 * kFar ? std::numeric_limits<float>::infinity() : float(std::sqrt(d[x]));
    }
    return out;
}

Comparison compareMasks(const Mask& test, const Mask& reference)
{
    Comparison r;
    if (!consistent(test) || !consistent(reference))
    {
        r.error = "empty or inconsistent mask";
        return r;
    }
    if (test.width != reference.width || test.height != reference.height)
    {
        r.error = "size mismatch: " + std::to_string(test.width) + "x" + std::to_string(test.height) + " vs reference " +
                  std::to_string(reference.width) + "x" + std::to_string(reference.height);
        return r;
    }
    r.valid = true;
    std::vector<size_t> wrong;
    for (size_t i = 0; i < test.value.size(); ++i)
    {
        const uint8_t t = classify(test.value[i]), ref = classify(reference.value[i]);
        if ((t == MASK_BACKGROUND) != (ref == MASK_BACKGROUND)) ++r.coverageMismatch;
        if (t == MASK_BACKGROUND || ref == MASK_BACKGROUND) continue;
        if (reference.isGrazing(i))
        {
            ++r.grazingExcluded;
            continue;
        }
        ++r.geometryPixels;
        if (t != ref) wrong.push_back(i);
    }
    r.wrongPixels = (long long)wrong.size();
    r.wrongPct = r.geometryPixels > 0 ? 100.0 * r.wrongPixels / r.geometryPixels : 0.0;
    if (wrong.empty()) return r;

    const std::vector<float> distance = boundaryDistance(reference);
    double sum = 0.0;
    for (size_t i : wrong) sum += distance[i];
    r.meanWrongDistance = std::isfinite(sum) ? sum / wrong.size() : -1.0;
    return r;
}

namespace {

/** Whether pixel i counts in a score (Comparison::geometryPixels): test and reference values
 *  `t` and `ref` (classified) both have geometry, the reference outside its grazing band. */
bool judged(uint8_t t, uint8_t ref, const Mask& reference, size_t i)
{
    return t != MASK_BACKGROUND && ref != MASK_BACKGROUND && !reference.isGrazing(i);
}

bool sameSize(const Mask& a, const Mask& b)
{
    return consistent(a) && consistent(b) && a.width == b.width && a.height == b.height;
}

double percent(long long part, long long whole)
{
    return whole > 0 ? 100.0 * part / whole : 0.0;
}

} // namespace

std::vector<BandScore> compareMasksByDistance(const Mask& test, const Mask& reference, const std::vector<double>& edges)
{
    if (!sameSize(test, reference) || reference.distance.size() != reference.value.size()) return {};
    std::vector<BandScore> bands(edges.size() + 1);
    for (size_t b = 0; b < bands.size(); ++b)
    {
        bands[b].from = b == 0 ? 0.0 : edges[b - 1];
        bands[b].to = b < edges.size() ? edges[b] : std::numeric_limits<double>::infinity();
    }
    for (size_t i = 0; i < test.value.size(); ++i)
    {
        const uint8_t t = classify(test.value[i]), ref = classify(reference.value[i]);
        if (!judged(t, ref, reference, i)) continue;
        const double d = reference.distance[i];
        const size_t b = size_t(std::upper_bound(edges.begin(), edges.end(), d) - edges.begin());
        ++bands[b].geometryPixels;
        if (t != ref) ++bands[b].wrongPixels;
    }
    for (BandScore& band : bands) band.wrongPct = percent(band.wrongPixels, band.geometryPixels);
    return bands;
}

FlickerCount countFlicker(const Mask& previousTest, const Mask& test, const Mask& previousReference,
                          const Mask& reference)
{
    FlickerCount r;
    if (!sameSize(test, reference) || !sameSize(test, previousTest) || !sameSize(test, previousReference)) return r;
    r.valid = true;
    for (size_t i = 0; i < test.value.size(); ++i)
    {
        const uint8_t t = classify(test.value[i]), ref = classify(reference.value[i]);
        if (!judged(t, ref, reference, i)) continue;
        ++r.geometryPixels;
        const uint8_t t0 = classify(previousTest.value[i]), ref0 = classify(previousReference.value[i]);
        if (t0 != MASK_BACKGROUND && ref0 == ref && t0 != t) ++r.flickerPixels;
    }
    r.flickerPct = percent(r.flickerPixels, r.geometryPixels);
    return r;
}

Mask maskFromImage(const osg::Image& image)
{
    const GLenum type = image.getDataType();
    if (type != GL_UNSIGNED_BYTE && type != GL_FLOAT) return Mask();
    return maskOfImage<Mask>(image, [type](const unsigned char* p) { return classify(firstChannel(p, type)); });
}

osg::ref_ptr<osg::Image> imageFromMask(const Mask& mask)
{
    return luminanceImage(mask, GL_UNSIGNED_BYTE, GL_LUMINANCE);
}

bool writeMask(const Mask& mask, const std::string& path)
{
    osg::ref_ptr<osg::Image> image = imageFromMask(mask);
    return image.valid() && osgDB::writeImageFile(*image, path);
}

bool readMask(const std::string& path, Mask& mask)
{
    return readImageAs(path, mask, maskFromImage);
}

osg::ref_ptr<osg::Image> imageFromVisibility(const VisibilityMask& mask)
{
    return luminanceImage(mask, GL_UNSIGNED_SHORT, GL_LUMINANCE16);
}

VisibilityMask visibilityFromImage(const osg::Image& image)
{
    if (image.getDataType() != GL_UNSIGNED_SHORT) return visibilityFromMask(maskFromImage(image));
    return maskOfImage<VisibilityMask>(image, [](const unsigned char* p) {
        uint16_t v = 0;
        std::memcpy(&v, p, sizeof(v));
        return v;
    });
}

VisibilityMask visibilityFromRender(const osg::Image& image)
{
    const GLenum format = image.getPixelFormat();
    if (image.getDataType() != GL_UNSIGNED_BYTE || (format != GL_RGB && format != GL_RGBA)) return VisibilityMask();
    return maskOfImage<VisibilityMask>(
        image, [](const unsigned char* p) { return p[0] != p[1] ? VIS_BACKGROUND : encodeVisibility(p[0] / 255.0); });
}

bool writeVisibility(const VisibilityMask& mask, const std::string& path)
{
    osg::ref_ptr<osg::Image> image = imageFromVisibility(mask);
    return image.valid() && osgDB::writeImageFile(*image, path);
}

bool readVisibility(const std::string& path, VisibilityMask& mask)
{
    return readImageAs(path, mask, visibilityFromImage);
}

osg::ref_ptr<osg::Image> diffImage(const Mask& test, const Mask& reference)
{
    if (!consistent(test) || !consistent(reference) || test.width != reference.width || test.height != reference.height)
        return nullptr;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(test.width, test.height, 1, GL_RGB, GL_UNSIGNED_BYTE, 1);
    for (int r = 0; r < test.height; ++r)
    {
        unsigned char* out = image->data(0, unsigned(test.height - 1 - r));
        for (int x = 0; x < test.width; ++x, out += 3)
        {
            const size_t i = size_t(r) * test.width + x;
            const uint8_t t = classify(test.value[i]), ref = classify(reference.value[i]);
            const uint8_t gray = uint8_t(reference.value[i] / 2);
            out[0] = out[1] = out[2] = gray;
            if (t == MASK_NO_LIGHT && ref == MASK_LIT) out[0] = 255, out[1] = out[2] = 0;
            else if (t == MASK_LIT && ref == MASK_NO_LIGHT) out[1] = 255, out[0] = out[2] = 0;
            else if ((t == MASK_BACKGROUND) != (ref == MASK_BACKGROUND)) out[2] = 255, out[0] = out[1] = 0;
        }
    }
    return image;
}

} // namespace ossref
