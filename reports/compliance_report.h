// What a [[compliance]] entry found, as summary.json (compliance.<name>) and the report's
// compliance section carry it (docs/compliance.md lists every key).
#pragma once

#include "base/math.h"
#include "metrics/compliance_levels.h"
#include "metrics/en17037.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace candela {

struct SunlightReportPoint {
  Vec3 position{0.0};
  double hours = 0.0;
  std::vector<std::pair<double, double>> intervals;  // sunlit stretches, local standard hours
  En17037Level level = En17037Level::kNone;
};

struct ViewOutReportPoint {
  Vec3 eye{0.0};
  double sightAngleDeg = 0.0, totalSightAngleDeg = 0.0;  // largest contiguous, all windows
  double outsideDistanceM = 0.0, medianOutsideDistanceM = 0.0;  // +inf: nothing met outside
  std::string layers;  // "sky+landscape+ground", "none", ...
  En17037Level sightLevel = En17037Level::kNone, distanceLevel = En17037Level::kNone,
               layersLevel = En17037Level::kNone, level = En17037Level::kNone;
};

// Annual glare at one view (imageless DGP over the occupied hours).
struct GlareViewReport {
  Vec3 position{0.0}, direction{0.0, 1.0, 0.0};
  double azimuthDeg = 0.0;  // the direction's true azimuth, clockwise from true north
  double shareAbove035 = 0.0, shareAbove040 = 0.0, shareAbove045 = 0.0;  // of occupied hours
  double glareAutonomy = 0.0;  // share of occupied hours with DGP < 0.40
  En17037Level level = En17037Level::kNone;
  // The shading the view saw: "open" (none modelled, or window groups: see docs/compliance.md),
  // "lm83" (the LM-83 blinds of `blindsSpace`, closed in blindsClosedHours occupied hours) or
  // "window_states" (the window groups' states as `blindsSpace` chooses them, some group off its
  // first state in blindsClosedHours occupied hours; blindsNote says why not, when the views
  // stayed in the first states).
  std::string blinds = "open";
  std::string blindsSpace;
  int blindsClosedHours = 0;
  std::string blindsNote;
  // The rendered check of chosen hours: imageless and rendered DGP side by side.
  struct Check {
    std::string time;
    bool blindsClosed = false;
    double imagelessDgp = 0.0, renderedDgp = 0.0;
    double imagelessEvLux = 0.0, renderedEvLux = 0.0;
  };
  std::vector<Check> checks;
};

struct ProvisionSpaceReport {
  std::string space;
  ProvisionResult illuminance;
  std::optional<DaylightFactorResult> daylightFactor;
  double meanDaylightFactorPct = 0.0;
};

struct En17037Report {
  // Part 1, daylight provision.
  bool sensorFirst = false;  // the order the level is graded by (the other is reported beside)
  int daylightHours = 0;
  double medianDiffuseLux = 0.0;  // E_v,d,med
  std::vector<ProvisionSpaceReport> spaces;
  En17037Level provisionLevel = En17037Level::kNone;       // lowest space, chosen order
  En17037Level provisionLevelOther = En17037Level::kNone;  // lowest space, the other order
  En17037Level daylightFactorLevel = En17037Level::kNone;  // lowest space, DF method
  // Part 3, exposure to sunlight.
  std::string sunlightDate;
  double sunlightMinAltitudeDeg = 0.0;
  bool sunlightMinAltitudeDefault = true;
  double sunAboveMinHours = 0.0;
  std::vector<SunlightReportPoint> sunlight;
  // Part 2, view out.
  std::vector<ViewOutReportPoint> viewOut;
  // Part 4, protection from glare.
  double glareExceedance = 0.05;
  std::vector<GlareViewReport> glare;
};

struct LeedSpaceReport {
  std::string space;
  double areaM2 = 0.0;
  double sdaPct = 0.0, asePct = 0.0;    // option 1
  double inRangePct = 0.0;              // option 2: share of the area between 300 and 3000 lx, all times
  std::vector<double> inRangeByTimePct;  // option 2: per simulated time
  bool aseAbove10 = false;
  // Option 2: the standard errors of those shares from each sensor's Monte Carlo error
  // (metrics/leed.h inRangeShare); the space's over the times, independent: √Σ SE_t² / T.
  double inRangeStandardErrorPct = 0.0;
  std::vector<double> inRangeByTimeStandardErrorPct;
  // Option 2: the space's mean illuminance per time, lx, and its standard error √Σσ² / n.
  std::vector<double> meanLuxByTime, meanLuxByTimeStandardError;
};

struct LeedReport {
  std::vector<LeedSpaceReport> spaces;
  double averagePct = 0.0;  // area-weighted sDA (option 1) or share in range (option 2)
  double averageStandardErrorPct = 0.0;  // option 2: √Σ (A_k/A)² SE_k²
  int points = 0;
  bool eachSpaceAbove55 = false;
  bool aseExceeds10Percent = false;      // option 1: any space with ASE > 10 %
  std::vector<std::string> times;        // option 2: the simulated times
  // Option 2: each time's sky (study/compliance/compliance_leed.h equinoxWindowLight).
  struct Sky {
    double diffuseHorizontalLux = 0.0, directNormalLux = 0.0;
    int days = 0;
  };
  std::vector<Sky> skyByTime;
};

// A standard's own part of its entry, written by the standard's unit (reports/en1838_report.h):
// the shared writers call it without knowing the standard, so a new standard adds a file, not a
// branch in each writer.
class StandardSection {
 public:
  virtual ~StandardSection() = default;
  virtual std::string title() const = 0;                 // the report section's heading
  virtual void addJson(nlohmann::json& entry) const = 0;  // its keys in compliance.<name>
  // Keys of summary.json's top level that the standard's issue names there (EN 13201's `roads`);
  // none by default.
  virtual void addTopLevelJson(nlohmann::json& /*summary*/) const {}
  // Files of its own in the result folder `dir` (EN 1838's per-point CSV); none by default.
  virtual void writeFiles(const std::filesystem::path& /*dir*/) const {}
  virtual std::string html() const = 0;                   // its part of the section, after the verdict lines
};

struct ComplianceReport {
  std::string name;      // the key under `compliance`
  std::string standard;  // "en17037", "leed-v4.1-option1", "leed-v4.1-option2"
  std::string verdict;   // "pass" / "fail"
  std::vector<std::string> verdictLines;  // what decided it, one line each
  std::optional<En17037Report> en17037;
  std::optional<LeedReport> leed;
  std::shared_ptr<const StandardSection> section;  // standards written by their own unit
  std::vector<std::pair<std::string, double>> timesS;  // wall time of each part, s (summary.json time_s)
};

// The entry as summary.json carries it.
nlohmann::json complianceJson(const ComplianceReport& r);

}  // namespace candela
