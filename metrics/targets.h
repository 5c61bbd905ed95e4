// Design targets of a grid and their verdicts, checked as a designer checks EN 12464-1:2021
// (Table 5.x: maintained illuminance Em and uniformity U0 per task area).
#pragma once

#include <optional>
#include <string>

#include "metrics/grid_stats.h"

namespace candela {

// Targets of one grid; an unset target is not checked.
struct GridTargets {
  std::optional<double> averageLux;  // required maintained illuminance Em in lux (Eavg >= Em)
  std::optional<double> uniformity;  // required U0 = Emin/Eavg (U0 >= target)
};

enum class Verdict { kNotChecked, kPass, kFail };

// "pass", "fail" or "n/a".
const char* verdictName(Verdict v);

// Verdicts of one grid against its targets, with the margins a designer reads.
struct TargetCheck {
  Verdict average = Verdict::kNotChecked;
  Verdict uniformity = Verdict::kNotChecked;
  Verdict overall = Verdict::kNotChecked;  // fail if any checked target fails, pass if all pass
  double averageRatio = 0.0;               // Eavg / Em (1.0 = exactly on target), 0 if unchecked
  double uniformityRatio = 0.0;            // U0 / U0,target, 0 if unchecked
};

// EN 12464-1 compares the calculated maintained values with the requirements as they are
// ("shall not be below"): a value equal to the target passes. `relativeTolerance` lets a
// caller accept e.g. the rounding of printed values (default 0: strict).
TargetCheck checkTargets(const GridStats& stats, const GridTargets& targets, double relativeTolerance = 0.0);

}  // namespace candela
