// The [[compliance]] entries of an annual case (docs/compliance.md): what they need of the
// hourly results is gathered while the annual study streams its blocks of sensors
// (ComplianceTallies), the geometric parts (sunlight, view out) are traced after it, and each
// entry becomes a ComplianceReport for summary.json and the report.
#pragma once

#include "engine/tracer.h"
#include "metrics/en17037.h"
#include "photometry/annual_sky.h"
#include "photometry/site.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/observer.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace candela {

// A grid of the study: its sensors first .. first + count - 1 in the study's list, and the floor
// area each sensor stands for (m²; spacing² for plane grids, LEED's area weighting).
struct ComplianceGrid {
  std::string name;
  std::size_t first = 0, count = 0;
  double sensorAreaM2 = 1.0;
};

class ComplianceTallies {
 public:
  ComplianceTallies(const CaseFile& c, std::vector<ComplianceGrid> grids, const AnnualSky& sky);

  // Whether any entry needs the hourly illuminance (EN 17037 part 1): then every block goes to
  // addBlock, with each sensor's illuminance under the overcast sky of overcastPatches().
  bool needsHours() const { return !tallies_.empty(); }
  // CIE overcast sky of 1 lx horizontal (and its ground, ρ_g of the case) per patch: the sky
  // coefficients times it give each sensor's daylight factor / 100.
  const std::vector<float>& overcastPatches() const { return overcast_; }
  // Sensors first .. first + count - 1: total[s * hours + h] lux (blinds open: EN 17037 judges
  // the daylight provision without movable shading), overcastLux[s] per lux outdoors.
  void addBlock(std::size_t first, std::size_t count, int hours, const float* total, const float* overcastLux);

  const std::vector<ComplianceGrid>& grids() const { return grids_; }
  int gridIndex(const std::string& name) const;  // -1: none
  const ProvisionTally& tally(int grid) const { return tallies_[static_cast<std::size_t>(grid)]; }
  const std::vector<double>& daylightFactorPct(int grid) const { return df_[static_cast<std::size_t>(grid)]; }
  int daylightHours() const { return daylightCount_; }
  double medianDiffuseLux() const { return medianDiffuseLux_; }

 private:
  std::vector<ComplianceGrid> grids_;
  std::vector<ProvisionTally> tallies_;  // one per grid (empty without EN 17037 entries)
  std::vector<std::vector<double>> df_;
  std::vector<float> overcast_;
  int daylightCount_ = 0;
  double medianDiffuseLux_ = 0.0;
};

struct AnnualGlareJob;

// The most combinations of window states a glare view is traced in (each is its own scene).
inline constexpr std::size_t kMaxGlareStateScenes = 64;

struct ComplianceInputs {
  const CaseFile* caseFile = nullptr;
  const Scene* scene = nullptr;       // blinds open
  Site site;
  const EpwFile* epw = nullptr;
  const AnnualSky* sky = nullptr;
  const AnnualGlareJob* glareJob = nullptr;  // the year's suns and the case's trace settings
  // Point-in-time tracing (LEED option 2): the case's settings with a grid's default method
  // (Ward's irradiance cache unless the case or the command line says path).
  TraceSettings pointSettings;
  const std::vector<char>* occupied = nullptr;  // per hour of the year
  int weatherYear = 2026;             // the weather file's first year: the default dates' year
  const ComplianceTallies* tallies = nullptr;
  const std::vector<GridReport>* annualGrids = nullptr;  // the study's grid reports, in grid order
  const std::vector<Vec3>* positions = nullptr;  // the study's sensors (grids in case order)
  const std::vector<Vec3>* normals = nullptr;
  // LM-83 blinds for the glare views, when the study traced them for all its glazing at once (no
  // [[window_group]]): the blinds-closed scene and each grid's hours of closed blinds (grid order).
  const Scene* closedScene = nullptr;
  const std::vector<std::vector<char>>* blindsClosed = nullptr;
  // What closes them, as the views report it: "lm83" (the blinds, of all the glazing or of
  // window groups) or "window_states".
  std::string blindsLabel = "lm83";
  // Window states or window groups of blinds for the glare views (docs/annual.md): each grid's
  // state of every group in every hour ([grid][group][hour], grid order; for blinds 1 = closed),
  // and the scene of one choice (a state per group). The views follow the entry's first space:
  // each combination its occupied hours use is traced (at most kMaxGlareStateScenes, beyond
  // which the views stay in the first states and say so).
  const std::vector<std::vector<std::vector<uint8_t>>>* windowStates = nullptr;
  std::function<std::unique_ptr<Scene>(const std::vector<int>&)> stateScene;
  int threads = 0;
  StudyObserver* observer = nullptr;  // one step per entry, its parts as the items
};

// Every entry of the case, in case order. Throws InputError (at the entry's keys) for inputs only
// the scene can judge.
std::vector<ComplianceReport> evaluateCompliance(const ComplianceInputs& in);

// The grid indices an entry judges (its `spaces`, else every grid).
std::vector<int> complianceSpaces(const ComplianceSpec& s, const ComplianceTallies& t);

}  // namespace candela
