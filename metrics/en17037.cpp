#include "metrics/en17037.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace candela {

namespace {

// `part` of `whole` reaches `fraction` (exact for the fractions of the standard: 0.5, 0.95 of
// integer counts, where a rounding of fraction × whole must not decide).
bool reaches(double part, double whole, double fraction) { return whole > 0.0 && part >= fraction * whole - 1e-9; }

}  // namespace

std::vector<char> daylightHours(const std::vector<double>& diffuseHorizontalLux) {
  const std::size_t n = diffuseHorizontalLux.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return diffuseHorizontalLux[a] > diffuseHorizontalLux[b]; });
  std::vector<char> flags(n, 0);
  for (std::size_t k = 0; k < n / 2; ++k) flags[order[k]] = 1;
  return flags;
}

double medianDiffuseIlluminance(const std::vector<double>& diffuseHorizontalLux, const std::vector<char>& hours) {
  if (hours.size() != diffuseHorizontalLux.size()) throw std::invalid_argument("median: one flag per hour");
  std::vector<double> v;
  for (std::size_t h = 0; h < hours.size(); ++h)
    if (hours[h]) v.push_back(diffuseHorizontalLux[h]);
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

ProvisionTally::ProvisionTally(std::vector<char> daylight, std::vector<double> thresholdsLux)
    : daylight_(std::move(daylight)), thresholds_(std::move(thresholdsLux)) {
  daylightCount_ = static_cast<int>(std::count(daylight_.begin(), daylight_.end(), char{1}));
  hourCounts_.assign(daylight_.size() * thresholds_.size(), 0);
}

void ProvisionTally::add(const float* lux, int sensors, int hours) {
  if (hours != static_cast<int>(daylight_.size()) || sensors < 0 || (!lux && sensors > 0))
    throw std::invalid_argument("ProvisionTally::add: one value per sensor and hour of the year");
  const std::size_t nt = thresholds_.size();
  for (int s = 0; s < sensors; ++s) {
    std::vector<int> counts(nt, 0);
    const float* row = lux + static_cast<std::size_t>(s) * hours;
    for (int h = 0; h < hours; ++h) {
      if (!daylight_[h]) continue;
      for (std::size_t t = 0; t < nt; ++t)
        if (row[h] >= thresholds_[t]) {
          ++counts[t];
          ++hourCounts_[static_cast<std::size_t>(h) * nt + t];
        }
    }
    sensorCounts_.insert(sensorCounts_.end(), counts.begin(), counts.end());
  }
  sensors_ += sensors;
}

std::vector<double> provisionThresholds() {
  std::vector<double> t;
  for (const ProvisionLevel& l : kProvisionLevels) {
    t.push_back(l.targetLux);
    t.push_back(l.minimumTargetLux);
  }
  return t;
}

namespace {

ProvisionCriterion criterion(const ProvisionTally& tally, int t, double planeFraction) {
  ProvisionCriterion c;
  c.thresholdLux = tally.threshold(t);
  c.planeFraction = planeFraction;
  const double sensors = tally.sensors(), hours = tally.daylightHourCount();
  int passingHours = 0;
  for (int h = 0; h < static_cast<int>(tally.daylight().size()); ++h)
    if (tally.daylight()[h] && reaches(tally.sensorsAt(h, t), sensors, planeFraction)) ++passingHours;
  c.hourFirstTimeFraction = hours > 0 ? passingHours / hours : 0.0;
  c.hourFirstPass = reaches(passingHours, hours, kProvisionTimeFraction);
  int passingSensors = 0;
  for (int s = 0; s < tally.sensors(); ++s)
    if (reaches(tally.hoursAt(s, t), hours, kProvisionTimeFraction)) ++passingSensors;
  c.sensorFirstPlaneFraction = sensors > 0 ? passingSensors / sensors : 0.0;
  c.sensorFirstPass = reaches(passingSensors, sensors, planeFraction);
  return c;
}

}  // namespace

ProvisionResult evaluateProvision(const ProvisionTally& tally) {
  if (tally.thresholds() != 2 * static_cast<int>(kProvisionLevels.size()))
    throw std::invalid_argument("evaluateProvision: the tally needs provisionThresholds()");
  ProvisionResult r;
  r.sensors = tally.sensors();
  r.daylightHours = tally.daylightHourCount();
  bool hourFirst = true, sensorFirst = true;  // a level counts only when the ones below it pass
  for (std::size_t i = 0; i < kProvisionLevels.size(); ++i) {
    ProvisionLevelResult& l = r.levels[i];
    l.level = kProvisionLevels[i];
    l.target = criterion(tally, static_cast<int>(2 * i), kTargetPlaneFraction);
    l.minimumTarget = criterion(tally, static_cast<int>(2 * i + 1), kMinimumTargetPlaneFraction);
    hourFirst = hourFirst && l.target.hourFirstPass && l.minimumTarget.hourFirstPass;
    sensorFirst = sensorFirst && l.target.sensorFirstPass && l.minimumTarget.sensorFirstPass;
    if (hourFirst) r.hourFirstLevel = l.level.level;
    if (sensorFirst) r.sensorFirstLevel = l.level.level;
  }
  return r;
}

DaylightFactorResult evaluateDaylightFactor(const std::vector<double>& dfPct, double medianDiffuseLux) {
  if (!(medianDiffuseLux > 0.0)) throw std::invalid_argument("evaluateDaylightFactor: E_v,d,med must be > 0");
  DaylightFactorResult r;
  r.medianDiffuseLux = medianDiffuseLux;
  const double n = static_cast<double>(dfPct.size());
  bool below = true;
  for (std::size_t i = 0; i < kProvisionLevels.size(); ++i) {
    DaylightFactorLevelResult& l = r.levels[i];
    l.level = kProvisionLevels[i];
    l.targetPct = 100.0 * l.level.targetLux / medianDiffuseLux;
    l.minimumTargetPct = 100.0 * l.level.minimumTargetLux / medianDiffuseLux;
    const auto share = [&](double d) {
      return n > 0 ? std::count_if(dfPct.begin(), dfPct.end(), [&](double v) { return v >= d; }) / n : 0.0;
    };
    l.targetPlaneFraction = share(l.targetPct);
    l.minimumPlaneFraction = share(l.minimumTargetPct);
    l.pass = n > 0 && reaches(l.targetPlaneFraction * n, n, kTargetPlaneFraction) &&
             reaches(l.minimumPlaneFraction * n, n, kMinimumTargetPlaneFraction);
    below = below && l.pass;
    if (below) r.level = l.level.level;
  }
  return r;
}

}  // namespace candela
