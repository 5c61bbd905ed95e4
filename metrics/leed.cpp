#include "metrics/leed.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace candela {

namespace {

// LEED v4.1 EQ credit Daylight, option 1, Table 1 (USGBC credit language, e.g. as published at
// leeduser.buildinggreen.com/credit/Data-Centers-NC-v4.1/EQc7 and .../Healthcare-v4.1/EQc7).
constexpr double kOnePointSda = 40.0, kTwoPointsSda = 55.0, kThreePointsSda = 75.0;
constexpr double kEachSpaceSda = 55.0;
// "For any regularly occupied spaces with ASE1000,250 greater than 10%, identify how the space is
// designed to address glare."
constexpr double kAseGlarePercent = 10.0;

void checkSpace(const LeedSpace& s) {
  if (!(s.floorAreaM2 > 0.0) || !std::isfinite(s.floorAreaM2))
    throw std::invalid_argument("LEED space '" + s.name + "': the floor area must be > 0 m²");
  for (double p : {s.sdaPercent, s.asePercent})
    if (!(p >= 0.0 && p <= 100.0)) throw std::invalid_argument("LEED space '" + s.name + "': sDA and ASE are 0..100 %");
}

std::string verdictOf(const LeedOption1Result& r, LeedProjectType type) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "LEED v4.1 EQ Daylight option 1%s: %d point%s (average sDA300/50%% %.1f %%)",
                type == LeedProjectType::kHealthcare ? " (healthcare)" : "", r.points, r.points == 1 ? "" : "s",
                r.averageSdaPercent);
  std::string v = buf;
  if (r.exemplaryPerformance) v += "; exemplary performance";
  if (!r.glareToAddress.empty()) {
    v += "; ASE1000,250 above 10 % in";
    for (std::size_t i = 0; i < r.glareToAddress.size(); ++i) v += (i ? ", " : " ") + r.glareToAddress[i];
    v += ": identify how the space is designed to address glare";
  }
  return v;
}

}  // namespace

LeedOption1Result leedV41Option1(const std::vector<LeedSpace>& spaces, LeedProjectType type) {
  if (spaces.empty()) throw std::invalid_argument("LEED option 1 needs at least one regularly occupied space");
  LeedOption1Result r;
  double weighted = 0.0;
  r.eachSpaceAtLeast55 = true;
  for (const LeedSpace& s : spaces) {
    checkSpace(s);
    LeedSpaceResult q{s.name, s.floorAreaM2, s.sdaPercent, s.asePercent, s.asePercent > kAseGlarePercent,
                      s.sdaPercent >= kEachSpaceSda};
    r.totalFloorAreaM2 += s.floorAreaM2;
    weighted += s.floorAreaM2 * s.sdaPercent;
    r.eachSpaceAtLeast55 = r.eachSpaceAtLeast55 && q.sdaAtLeast55;
    if (q.aseAbove10) r.glareToAddress.push_back(s.name);
    r.spaces.push_back(std::move(q));
  }
  r.averageSdaPercent = weighted / r.totalFloorAreaM2;
  const double a = r.averageSdaPercent;
  const bool healthcare = type == LeedProjectType::kHealthcare;
  r.averagePoints = a >= kTwoPointsSda ? 2 : a >= kOnePointSda ? 1 : 0;
  if (a >= kThreePointsSda) {
    if (healthcare) r.exemplaryPerformance = true;
    else r.averagePoints = 3;
  }
  r.points = r.averagePoints;
  // Every space at >= 55 % puts the average at >= 55 % too, so the credit's "if only 1 or 2
  // points" and "if 2 points" wordings agree: the line adds a point to 2, or is exemplary.
  if (r.eachSpaceAtLeast55) {
    if (!healthcare && r.averagePoints == 2) r.points = 3;
    else r.exemplaryPerformance = true;
  }
  r.verdict = verdictOf(r, type);
  return r;
}

double gridFloorAreaM2(int sensors, double cellAreaM2) {
  if (sensors < 0 || !(cellAreaM2 >= 0.0)) throw std::invalid_argument("gridFloorAreaM2: negative sensors or cell area");
  return sensors * cellAreaM2;
}

InRangeShare inRangeShare(const std::vector<double>& lux, const std::vector<double>& sigmaLux, double loLux,
                          double hiLux) {
  if (lux.size() != sigmaLux.size()) throw std::invalid_argument("inRangeShare: one standard error per value");
  if (!(loLux <= hiLux)) throw std::invalid_argument("inRangeShare: lo > hi");
  InRangeShare r;
  if (lux.empty()) return r;
  const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  int count = 0;
  double variance = 0.0;
  for (std::size_t i = 0; i < lux.size(); ++i) {
    const double e = lux[i], s = sigmaLux[i];
    if (!(s >= 0.0)) throw std::invalid_argument("inRangeShare: negative standard error");
    count += e >= loLux && e <= hiLux;
    if (s > 0.0) {
      const double p = phi((hiLux - e) / s) - phi((loLux - e) / s);
      variance += p * (1.0 - p);
    }
  }
  const double n = static_cast<double>(lux.size());
  r.sharePct = 100.0 * count / n;
  r.standardErrorPct = 100.0 * std::sqrt(variance) / n;
  return r;
}

}  // namespace candela
