// False-colour scales: value → colour for plans, images and legends.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace candela {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

// A value range mapped onto the colour map; values outside are clamped to the ends.
struct ColorScale {
  double minValue = 0.0;
  double maxValue = 1.0;
  bool logarithmic = false;  // log scales need minValue > 0
};

// Matplotlib's perceptually uniform "viridis" map (van der Walt & Smith 2015), t in [0, 1]
// (clamped): dark violet → blue → green → yellow.
Rgb8 viridis(double t);

// Position of `value` on the scale, in [0, 1].
double scalePosition(double value, const ColorScale& scale);

Rgb8 falseColor(double value, const ColorScale& scale);

// A scale spanning [0, max] rounded up to a round number (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^n)
// for linear scales,
// or whole decades for log scales; what a designer expects on a legend.
ColorScale niceScale(double minValue, double maxValue, bool logarithmic = false);

// A linear scale from a round number at or below `minValue` to one at or above `maxValue`, on the
// step of scaleTicks(…, 6): uses the whole colour range for the values a plan shows (as AGi32's
// and DIALux's automatic ranges do), with legend ends a reader can quote.
ColorScale niceRange(double minValue, double maxValue);

// Legend tick values: multiples of a 1-2-5 step covering the scale (about `approxCount`), or
// 1-2-5 per decade on log scales.
std::vector<double> scaleTicks(const ColorScale& scale, int approxCount = 6);

// "#rrggbb"
std::string hexColor(Rgb8 c);

// Black or white, whichever reads better on `background` (relative luminance, ITU-R BT.709).
Rgb8 contrastingText(Rgb8 background);

}  // namespace candela
