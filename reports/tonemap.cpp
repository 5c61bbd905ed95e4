#include "reports/tonemap.h"

#include "reports/exr_writer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela {

namespace {

// sRGB encoding of a linear value in [0, 1] (IEC 61966-2-1).
uint8_t srgb8(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<uint8_t>(std::lround(255.0 * e));
}

}  // namespace

RowPicture toneMapRows(int width, int height, const std::vector<float>& lum, const std::vector<glm::vec3>& rgb,
                       const std::vector<uint8_t>& mask, double key) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (width <= 0 || height <= 0 || lum.size() != n || (!rgb.empty() && rgb.size() != n) ||
      (!mask.empty() && mask.size() != n))
    throw std::invalid_argument("toneMap: need width × height values");
  auto in = [&mask](std::size_t i) { return mask.empty() || mask[i] != 0; };
  // Log-average luminance (eq. 1); δ avoids log 0 on black pixels.
  constexpr double kDelta = 1e-4;
  double logSum = 0.0, maxL = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in(i)) continue;
    const double l = std::max<double>(lum[i], 0.0);
    logSum += std::log(kDelta + l);
    maxL = std::max(maxL, l);
    ++count;
  }
  if (count == 0 || !(maxL > 0.0))
    return RowPicture{width, height, [width](int, uint8_t* out) { std::fill_n(out, 3 * width, uint8_t{0}); }};
  const double avg = std::exp(logSum / count);
  const double scale = key / avg;
  // Lwhite: the largest scaled luminance, but at least 1, so that a low-contrast picture keeps
  // its key instead of burning out to white (eq. 4 maps Lwhite itself to 1).
  const double white = std::max(scale * maxL, 1.0);
  return RowPicture{width, height, [&lum, &rgb, in, width, scale, white](int y, uint8_t* out) {
                      for (int x = 0; x < width; ++x) {
                        const std::size_t i = static_cast<std::size_t>(y) * width + x;
                        uint8_t* p = out + 3 * x;
                        if (!in(i)) {
                          p[0] = p[1] = p[2] = 0;
                          continue;
                        }
                        const double l = std::max<double>(lum[i], 0.0);
                        const double ls = scale * l;
                        const double ld = ls * (1.0 + ls / (white * white)) / (1.0 + ls);
                        Rgb c(ld);
                        if (!rgb.empty() && l > 0.0) {
                          // RGB relative to its photopic value, times the displayed luminance.
                          const Rgb ci(rgb[i]);
                          const double pv = photopic(ci);
                          c = pv > 0.0 ? ci * (ld / pv) : Rgb(ld);
                        }
                        p[0] = srgb8(c.x);
                        p[1] = srgb8(c.y);
                        p[2] = srgb8(c.z);
                      }
                    }};
}

Image8 toneMap(int width, int height, const std::vector<float>& lum, const std::vector<glm::vec3>& rgb,
               const std::vector<uint8_t>& mask, double key) {
  return imageOf(toneMapRows(width, height, lum, rgb, mask, key));
}

ColorScale luminanceScale(const std::vector<float>& lum, bool logarithmic, std::optional<double> minCdM2,
                          std::optional<double> maxCdM2) {
  double hi = 0.0, loPos = 1e300;
  for (const double l : lum) {
    if (!std::isfinite(l)) continue;
    hi = std::max(hi, l);
    if (l > 0.0) loPos = std::min(loPos, l);
  }
  if (maxCdM2) hi = *maxCdM2;
  ColorScale s;
  if (logarithmic) {
    const double top = hi > 0.0 ? hi : 1.0;
    const double lo = minCdM2 ? *minCdM2 : std::max(loPos < 1e300 ? loPos : top * 1e-4, top * 1e-4);
    if (minCdM2 && maxCdM2) return ColorScale{*minCdM2, *maxCdM2, true};
    s = niceScale(lo, top, true);
    if (minCdM2) s.minValue = *minCdM2;
    if (maxCdM2) s.maxValue = *maxCdM2;
    return s;
  }
  if (minCdM2 && maxCdM2) return ColorScale{*minCdM2, *maxCdM2, false};
  s = niceScale(0.0, hi, false);
  if (minCdM2) s.minValue = *minCdM2;
  if (maxCdM2) s.maxValue = *maxCdM2;
  return s;
}

Image8 luminanceFalseColor(int width, int height, const std::vector<float>& lum, const ColorScale& scale) {
  return falseColorImage(lum, width, height, scale, "cd/m2");
}

ViewImagePaths viewImagePaths(const std::filesystem::path& dir, const std::string& stem) {
  return ViewImagePaths{dir / (stem + ".exr"), dir / (stem + ".png"), dir / (stem + "_preview.png")};
}

ViewImagePaths ViewImageFiles::commitInto(const std::filesystem::path& dir) {
  const ViewImagePaths p = viewImagePaths(dir, stem);
  exr->commitAs(p.exr);
  falseColor->commitAs(p.falseColor);
  preview->commitAs(p.preview);
  return p;
}

ViewImageFiles writeViewImageFiles(const std::filesystem::path& dir, const std::string& stem, int width, int height,
                                   const std::vector<float>& lum, const std::vector<glm::vec3>& rgb, double rgbScale,
                                   const std::vector<uint8_t>& mask, const ColorScale& scale,
                                   const std::string& comment) {
  std::filesystem::create_directories(dir);
  const ViewImagePaths p = viewImagePaths(dir, stem);
  ViewImageFiles f;
  f.stem = stem;
  f.exr = std::make_unique<AtomicFile>(p.exr);
  writeLuminanceExr(*f.exr, p.exr.string(), width, height, lum, rgb, rgbScale, comment);
  f.falseColor = std::make_unique<AtomicFile>(p.falseColor);
  writePng(*f.falseColor, falseColorRows(lum, width, height, scale, "cd/m2"));
  f.preview = std::make_unique<AtomicFile>(p.preview);
  writePng(*f.preview, toneMapRows(width, height, lum, rgb, mask));
  return f;
}

ViewImagePaths writeViewImages(const std::filesystem::path& dir, const std::string& stem, int width, int height,
                               const std::vector<float>& lum, const std::vector<glm::vec3>& rgb, double rgbScale,
                               const std::vector<uint8_t>& mask, const ColorScale& scale, const std::string& comment) {
  return writeViewImageFiles(dir, stem, width, height, lum, rgb, rgbScale, mask, scale, comment).commitInto(dir);
}

}  // namespace candela
