#include "metrics/en12464_2.h"

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace candela {

namespace {

Verdict atLeast(double value, double required) { return value >= required ? Verdict::kPass : Verdict::kFail; }
Verdict atMost(double value, double limit) { return value <= limit ? Verdict::kPass : Verdict::kFail; }

// Fail when any checked verdict fails, pass when at least one is checked and all pass.
Verdict combine(std::initializer_list<Verdict> lines) {
  bool any = false;
  for (Verdict v : lines) {
    if (v == Verdict::kFail) return Verdict::kFail;
    any = any || v == Verdict::kPass;
  }
  return any ? Verdict::kPass : Verdict::kNotChecked;
}

}  // namespace

void judgeGrObserver(GrObserverResult& o) {
  o.grMax.reset();
  for (const GrViewResult& v : o.views)
    if (v.gr) o.grMax = std::max(o.grMax.value_or(*v.gr), *v.gr);
  if (!o.grLimit) o.verdict = Verdict::kNotChecked;
  else o.verdict = !o.grMax || *o.grMax <= *o.grLimit ? Verdict::kPass : Verdict::kFail;
}

void judgeOutdoorArea(OutdoorAreaResult& a, const std::vector<GrObserverResult>& observers) {
  a.averageVerdict = atLeast(a.averageLux, a.maintainedLux);
  a.uniformityVerdict = a.uniformityRequired ? atLeast(a.u0, *a.uniformityRequired) : Verdict::kNotChecked;
  a.grObservers.clear();
  a.grMax.reset();
  a.grVerdict = Verdict::kNotChecked;
  for (const GrObserverResult& o : observers) {
    if (o.taskArea != a.name) continue;
    a.grObservers.push_back(o.name);
    if (o.grMax) a.grMax = std::max(a.grMax.value_or(*o.grMax), *o.grMax);
    if (o.verdict == Verdict::kFail) a.grVerdict = Verdict::kFail;
    else if (o.verdict == Verdict::kPass && a.grVerdict == Verdict::kNotChecked) a.grVerdict = Verdict::kPass;
  }
  a.verdict = combine({a.averageVerdict, a.uniformityVerdict, a.grVerdict, a.raVerdict});
}

std::optional<ObtrusiveLimits> obtrusiveZoneLimits(const std::string& zone) {
  if (zone == "E1") return ObtrusiveLimits{2.0, 2500.0, 0.0};
  if (zone == "E2") return ObtrusiveLimits{5.0, 7500.0, 0.05};
  if (zone == "E3") return ObtrusiveLimits{10.0, 10000.0, 0.15};
  if (zone == "E4") return ObtrusiveLimits{25.0, 25000.0, 0.25};
  return std::nullopt;
}

void judgeObtrusiveLight(ObtrusiveLightResult& r) {
  const ObtrusiveLimits& l = r.limits;
  std::vector<Verdict> all;
  for (PropertyPointResult& p : r.points) {
    p.illuminanceVerdict = l.propertyLux ? atMost(p.illuminanceLux, *l.propertyLux) : Verdict::kNotChecked;
    p.intensityVerdict = l.intensityCd ? atMost(p.maxIntensityCd, *l.intensityCd) : Verdict::kNotChecked;
    all.push_back(p.illuminanceVerdict);
    all.push_back(p.intensityVerdict);
  }
  r.upwardVerdict = l.upwardLightRatio ? atMost(r.upwardLightRatio, *l.upwardLightRatio) : Verdict::kNotChecked;
  all.push_back(r.upwardVerdict);
  bool any = false, fail = false;
  for (Verdict v : all) any = any || v != Verdict::kNotChecked, fail = fail || v == Verdict::kFail;
  r.verdict = fail ? Verdict::kFail : any ? Verdict::kPass : Verdict::kNotChecked;
}

void judgeEn12464_2(En12464_2Result& r) {
  bool fail = false;
  for (const OutdoorAreaResult& a : r.areas) fail = fail || a.verdict == Verdict::kFail;
  for (const GrObserverResult& o : r.observers) fail = fail || o.verdict == Verdict::kFail;
  fail = fail || (r.obtrusive && r.obtrusive->verdict == Verdict::kFail);
  r.verdict = fail ? Verdict::kFail : Verdict::kPass;
}

}  // namespace candela
