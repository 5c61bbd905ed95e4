#include "reports/falsecolor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace candela {

namespace {

// viridis sampled at 9 equally spaced points: viridisLite::viridis(9) (R package viridisLite,
// a port of matplotlib's _cm_listed.py table; CC0). Linear interpolation between the samples
// keeps within about 2/255 of the 256-entry table.
constexpr std::array<Rgb8, 9> kViridis = {{{0x44, 0x01, 0x54},
                                           {0x47, 0x2D, 0x7B},
                                           {0x3B, 0x52, 0x8B},
                                           {0x2C, 0x72, 0x8E},
                                           {0x21, 0x90, 0x8C},
                                           {0x27, 0xAD, 0x81},
                                           {0x5D, 0xC8, 0x63},
                                           {0xAA, 0xDC, 0x32},
                                           {0xFD, 0xE7, 0x25}}};

uint8_t lerp8(uint8_t a, uint8_t b, double f) {
  return static_cast<uint8_t>(std::lround(a + (static_cast<double>(b) - a) * f));
}

// The smallest "round" number (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^n) not below `raw`: a scale
// top that wastes at most 25 % of the colour range.
double niceCeil(double raw) {
  if (!(raw > 0.0)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
    if (m * decade >= raw * (1.0 - 1e-12)) return m * decade;
  return 10.0 * decade;
}

}  // namespace

Rgb8 viridis(double t) {
  if (!(t >= 0.0)) t = 0.0;  // NaN too
  t = std::min(t, 1.0);
  const double x = t * (kViridis.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kViridis.size() - 2);
  const double f = x - static_cast<double>(i);
  const Rgb8 a = kViridis[i], b = kViridis[i + 1];
  return {lerp8(a.r, b.r, f), lerp8(a.g, b.g, f), lerp8(a.b, b.b, f)};
}

double scalePosition(double value, const ColorScale& s) {
  double t;
  if (s.logarithmic) {
    const double lo = std::max(s.minValue, 1e-300), hi = std::max(s.maxValue, lo * 1.0000001);
    t = value > 0.0 ? std::log(value / lo) / std::log(hi / lo) : 0.0;
  } else {
    const double span = s.maxValue - s.minValue;
    t = span > 0.0 ? (value - s.minValue) / span : 0.0;
  }
  return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
}

Rgb8 falseColor(double value, const ColorScale& scale) { return viridis(scalePosition(value, scale)); }

ColorScale niceScale(double minValue, double maxValue, bool logarithmic) {
  ColorScale s;
  s.logarithmic = logarithmic;
  if (logarithmic) {
    const double lo = minValue > 0.0 ? minValue : std::max(maxValue * 1e-3, 1e-3);
    s.minValue = std::pow(10.0, std::floor(std::log10(lo)));
    s.maxValue = std::pow(10.0, std::ceil(std::log10(std::max(maxValue, s.minValue * 10.0))));
    return s;
  }
  s.minValue = 0.0;
  s.maxValue = niceCeil(std::max(maxValue, 1e-9));
  return s;
}

namespace {

// The 1-2-2.5-5 × 10^n step that cuts `span` into at most `count` parts.
double tickStep(double span, int count) {
  const double decade = std::pow(10.0, std::floor(std::log10(span / std::max(count, 1))));
  double step = decade;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    step = m * decade;
    if (span / step <= count * (1.0 + 1e-9)) break;
  }
  return step;
}

}  // namespace

ColorScale niceRange(double minValue, double maxValue) {
  ColorScale s;
  if (!(maxValue > minValue)) return niceScale(0.0, std::max(maxValue, 0.0));
  const double step = tickStep(maxValue - minValue, 5);
  s.minValue = std::floor(minValue / step + 1e-9) * step;
  s.maxValue = std::ceil(maxValue / step - 1e-9) * step;
  if (s.minValue < 0.0 && minValue >= 0.0) s.minValue = 0.0;
  return s;
}

std::vector<double> scaleTicks(const ColorScale& s, int approxCount) {
  std::vector<double> ticks;
  if (s.logarithmic) {
    const double lo = std::max(s.minValue, 1e-300);
    const int decades = static_cast<int>(std::ceil(std::log10(s.maxValue / lo) - 1e-9));
    const double first = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
    for (int d = 0; d <= decades; ++d)
      for (double m : decades > 3 ? std::vector<double>{1.0} : std::vector<double>{1.0, 2.0, 5.0}) {
        const double v = m * first * std::pow(10.0, d);
        if (v >= lo * (1 - 1e-9) && v <= s.maxValue * (1 + 1e-9)) ticks.push_back(v);
      }
    return ticks;
  }
  const double span = s.maxValue - s.minValue;
  if (!(span > 0.0)) return {s.minValue};
  const double step = tickStep(span, approxCount);
  for (double v = std::ceil(s.minValue / step - 1e-9) * step; v <= s.maxValue + step * 1e-9; v += step)
    ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  return ticks;
}

std::string hexColor(Rgb8 c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

Rgb8 contrastingText(Rgb8 c) {
  auto lin = [](uint8_t v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);  // sRGB EOTF (IEC 61966-2-1)
  };
  const double y = 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
  return y > 0.18 ? Rgb8{0, 0, 0} : Rgb8{255, 255, 255};
}

}  // namespace candela
