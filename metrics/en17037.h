// EN 17037:2018+A1:2023 part 1, daylight provision (docs/compliance.md): the illuminance method
// over a year of hourly illuminance, in either order of aggregation, and the daylight-factor
// method with its targets derived for the site. Pure functions over numbers; the study feeds them.
#pragma once

#include "metrics/compliance_levels.h"

#include <array>
#include <vector>

namespace candela {

// EN 17037 Table A.1 (daylight openings in vertical and inclined surfaces): a level needs the
// target illuminance E_T over F_plane = 50 % of the reference plane and the minimum target
// illuminance E_TM over 95 % of it, each for F_time = 50 % of the daylight hours.
struct ProvisionLevel {
  En17037Level level;
  double targetLux;         // E_T
  double minimumTargetLux;  // E_TM
};
inline constexpr std::array<ProvisionLevel, 3> kProvisionLevels{{
    {En17037Level::kMinimum, 300.0, 100.0},
    {En17037Level::kMedium, 500.0, 300.0},
    {En17037Level::kHigh, 750.0, 500.0},
}};
inline constexpr double kTargetPlaneFraction = 0.5;
inline constexpr double kMinimumTargetPlaneFraction = 0.95;
inline constexpr double kProvisionTimeFraction = 0.5;

// The daylight hours of a year: the half of its hours (4380 of 8760) with the most diffuse
// horizontal illuminance outdoors, as EN 17037 A.3 takes E_v,d,med over them (ClimateStudio's
// "4380 hours with the most diffuse horizontal illuminance"; the Active House guide's "median of
// the 4380 highest hourly values"). Ties go to the earlier hour. One 0/1 flag per hour.
std::vector<char> daylightHours(const std::vector<double>& diffuseHorizontalLux);

// E_v,d,med: the median of the diffuse horizontal illuminance over the flagged hours, lux (the
// mean of the two middle values for an even count; 0 without hours).
double medianDiffuseIlluminance(const std::vector<double>& diffuseHorizontalLux, const std::vector<char>& hours);

// Counts over a year of hourly illuminance arriving a block of sensors at a time: for every
// daylight hour and threshold, the sensors at or above it; for every sensor and threshold, its
// daylight hours at or above it. Nothing grows with sensors × hours.
class ProvisionTally {
 public:
  // `thresholdsLux`: the levels' E_T and E_TM, in kProvisionLevels order (provisionThresholds()).
  ProvisionTally(std::vector<char> daylight, std::vector<double> thresholdsLux);
  // lux[s * hours + h] for `sensors` sensors; hours must be daylight.size().
  void add(const float* lux, int sensors, int hours);

  int sensors() const { return sensors_; }
  int daylightHourCount() const { return daylightCount_; }
  int thresholds() const { return static_cast<int>(thresholds_.size()); }
  double threshold(int t) const { return thresholds_[t]; }
  // Sensors at or above threshold t in daylight hour h (0 for other hours).
  int sensorsAt(int hour, int t) const { return hourCounts_[static_cast<std::size_t>(hour) * thresholds_.size() + t]; }
  // Daylight hours in which sensor s reached threshold t.
  int hoursAt(int sensor, int t) const { return sensorCounts_[static_cast<std::size_t>(sensor) * thresholds_.size() + t]; }
  const std::vector<char>& daylight() const { return daylight_; }

 private:
  std::vector<char> daylight_;
  int daylightCount_ = 0;
  std::vector<double> thresholds_;
  std::vector<int> hourCounts_, sensorCounts_;
  int sensors_ = 0;
};

// E_T then E_TM of each level, minimum to high: the tally's thresholds.
std::vector<double> provisionThresholds();

// One criterion ("E over F_plane of the plane for F_time of the daylight hours") judged both ways.
struct ProvisionCriterion {
  double thresholdLux = 0.0;
  double planeFraction = 0.0;   // F_plane required
  // Hour first: the share of daylight hours in which at least planeFraction of the sensors reach
  // the threshold; passes at ≥ F_time.
  double hourFirstTimeFraction = 0.0;
  bool hourFirstPass = false;
  // Sensor first: the share of sensors that reach the threshold in at least F_time of the
  // daylight hours; passes at ≥ planeFraction.
  double sensorFirstPlaneFraction = 0.0;
  bool sensorFirstPass = false;
};

struct ProvisionLevelResult {
  ProvisionLevel level;
  ProvisionCriterion target, minimumTarget;
};

struct ProvisionResult {
  int sensors = 0, daylightHours = 0;
  std::array<ProvisionLevelResult, 3> levels;
  En17037Level hourFirstLevel = En17037Level::kNone, sensorFirstLevel = En17037Level::kNone;
};

ProvisionResult evaluateProvision(const ProvisionTally& tally);

// The daylight-factor method (EN 17037 A.3): D_T = E_T / E_v,d,med and D_TM = E_TM / E_v,d,med,
// in %; a level needs D ≥ D_T over 50 % of the sensors and D ≥ D_TM over 95 % of them.
struct DaylightFactorLevelResult {
  ProvisionLevel level;
  double targetPct = 0.0, minimumTargetPct = 0.0;             // D_T, D_TM
  double targetPlaneFraction = 0.0, minimumPlaneFraction = 0.0;  // shares of sensors reaching them
  bool pass = false;
};
struct DaylightFactorResult {
  double medianDiffuseLux = 0.0;  // E_v,d,med
  std::array<DaylightFactorLevelResult, 3> levels;
  En17037Level level = En17037Level::kNone;
};
// dfPct: each sensor's daylight factor in %. medianDiffuseLux must be > 0.
DaylightFactorResult evaluateDaylightFactor(const std::vector<double>& dfPct, double medianDiffuseLux);

}  // namespace candela
