#include "metrics/targets.h"

namespace candela {

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "pass";
    case Verdict::kFail: return "fail";
    case Verdict::kNotChecked: break;
  }
  return "n/a";
}

TargetCheck checkTargets(const GridStats& stats, const GridTargets& targets, double relativeTolerance) {
  TargetCheck c;
  const double slack = 1.0 - relativeTolerance;
  if (targets.averageLux) {
    const double t = *targets.averageLux;
    c.averageRatio = t > 0.0 ? stats.averageLux / t : 0.0;
    c.average = stats.averageLux >= t * slack ? Verdict::kPass : Verdict::kFail;
  }
  if (targets.uniformity) {
    const double t = *targets.uniformity;
    c.uniformityRatio = t > 0.0 ? stats.u0 / t : 0.0;
    c.uniformity = stats.u0 >= t * slack ? Verdict::kPass : Verdict::kFail;
  }
  if (c.average == Verdict::kFail || c.uniformity == Verdict::kFail) {
    c.overall = Verdict::kFail;
  } else if (c.average == Verdict::kPass || c.uniformity == Verdict::kPass) {
    c.overall = Verdict::kPass;
  }
  return c;
}

double immediateSurroundingLux(double taskLux) {
  // (task Ē_m at least, surrounding Ē_m), from the top row down.
  static constexpr double kRows[][2] = {{750.0, 500.0}, {500.0, 300.0}, {300.0, 200.0}, {200.0, 150.0}};
  for (const auto& row : kRows)
    if (taskLux >= row[0]) return row[1];
  return taskLux;
}

}  // namespace candela
