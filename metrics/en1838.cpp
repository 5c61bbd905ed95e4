#include "metrics/en1838.h"

#include <algorithm>
#include <limits>

namespace candela {

double En1838Stats::maxToMin() const {
  if (points == 0) return 0.0;
  return minLux > 0.0 ? maxLux / minLux : std::numeric_limits<double>::infinity();
}

En1838Stats en1838Stats(const std::vector<double>& lux) {
  En1838Stats s;
  s.points = lux.size();
  if (lux.empty()) return s;
  const auto [lo, hi] = std::minmax_element(lux.begin(), lux.end());
  s.minLux = *lo;
  s.minIndex = static_cast<std::size_t>(lo - lux.begin());
  s.maxLux = *hi;
  double sum = 0.0;
  for (double v : lux) sum += v;
  s.averageLux = sum / static_cast<double>(lux.size());
  return s;
}

namespace {
Verdict passIf(bool ok) { return ok ? Verdict::kPass : Verdict::kFail; }
}  // namespace

void judgeEscapeRoute(EscapeRouteResult& r) {
  if (r.strips.empty()) return;
  r.minCentreLineLux = std::numeric_limits<double>::infinity();
  r.maxCentreLineLux = 0.0;
  r.uniformityRatio = 0.0;
  r.centralBandMinLux = std::numeric_limits<double>::infinity();
  for (const RouteStripResult& s : r.strips) {
    r.minCentreLineLux = std::min(r.minCentreLineLux, s.centreLine.minLux);
    r.maxCentreLineLux = std::max(r.maxCentreLineLux, s.centreLine.maxLux);
    r.uniformityRatio = std::max(r.uniformityRatio, s.centreLine.maxToMin());
    r.centralBandMinLux = std::min(r.centralBandMinLux, s.band.minLux);
  }
  r.verdict = passIf(r.minCentreLineLux >= kEn1838CentreLineLux &&
                     r.centralBandMinLux >= kEn1838CentralBandShare * kEn1838CentreLineLux &&
                     r.uniformityRatio <= kEn1838MaxMinRatio);
}

void judgeOpenArea(OpenAreaResult& a) {
  a.uniformityRatio = a.stats.maxToMin();
  a.verdict = passIf(a.stats.points > 0 && a.stats.minLux >= kEn1838OpenAreaLux &&
                     a.uniformityRatio <= kEn1838MaxMinRatio);
}

void judgeHighRiskArea(HighRiskAreaResult& a) {
  a.requiredLux = std::max(kEn1838HighRiskShare * a.maintainedLux, kEn1838HighRiskMinLux);
  a.uniformity = a.stats.maxLux > 0.0 ? a.stats.minLux / a.stats.maxLux : 0.0;
  a.verdict = passIf(a.stats.points > 0 && a.stats.minLux >= a.requiredLux && a.uniformity >= kEn1838HighRiskUniformity);
}

void judgeSafetyPoint(SafetyPointResult& p) {
  p.verdict = passIf(p.verticalLux >= kEn1838SafetyPointLux && p.nearestLuminaireM <= kEn1838NearM);
}

void judgeEn1838(En1838Result& r) {
  bool any = false, fail = false;
  auto add = [&](Verdict v) {
    if (v == Verdict::kNotChecked) return;
    any = true;
    fail = fail || v == Verdict::kFail;
  };
  for (const auto& x : r.routes) add(x.verdict);
  for (const auto& x : r.openAreas) add(x.verdict);
  for (const auto& x : r.highRiskAreas) add(x.verdict);
  for (const auto& x : r.safetyPoints) add(x.verdict);
  r.verdict = !any ? Verdict::kNotChecked : fail ? Verdict::kFail : Verdict::kPass;
}

}  // namespace candela
