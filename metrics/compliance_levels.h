// The levels of recommendation of EN 17037:2018+A1:2023 (every part grades a space or a point as
// minimum, medium or high, or not reaching the minimum), shared by the four parts
// (docs/compliance.md).
#pragma once

#include <string_view>

namespace candela {

enum class En17037Level { kNone, kMinimum, kMedium, kHigh };

// "none", "minimum", "medium", "high": the names summary.json and the report carry.
constexpr std::string_view levelName(En17037Level level) {
  switch (level) {
    case En17037Level::kMinimum: return "minimum";
    case En17037Level::kMedium: return "medium";
    case En17037Level::kHigh: return "high";
    case En17037Level::kNone: break;
  }
  return "none";
}

// A level as the report and the verdict lines word it: levelName, with "below minimum" for none.
constexpr std::string_view levelWords(En17037Level level) {
  return level == En17037Level::kNone ? "below minimum" : levelName(level);
}

// The level reached by a figure graded by three thresholds, lowest level first: `higherIsBetter`
// for hours, angles and distances (value ≥ threshold reaches it), else for DGP-like figures
// (value ≤ threshold reaches it).
constexpr En17037Level levelFromThresholds(double value, double minimum, double medium, double high,
                                           bool higherIsBetter = true) {
  auto reaches = [&](double t) { return higherIsBetter ? value >= t : value <= t; };
  if (reaches(high)) return En17037Level::kHigh;
  if (reaches(medium)) return En17037Level::kMedium;
  if (reaches(minimum)) return En17037Level::kMinimum;
  return En17037Level::kNone;
}

}  // namespace candela
