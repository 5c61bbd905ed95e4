// The annual study's year as its passes share it (study/annual_study.cpp, and the window states'
// passes in study/annual_window_states.cpp): the inputs, the tracer of one state of the scene, the
// grids' years as the blocks of sensors pass, and what the passes share. Internal to those two
// files; the study's interface is study/annual_study.h.
#pragma once

#include "engine/daylight_coefficients.h"
#include "metrics/annual.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "reports/annual_results.h"
#include "study/annual_glare.h"
#include "study/annual_study.h"
#include "study/case/case_file.h"
#include "study/observer.h"
#include "study/grids/prepared_grid.h"
#include "study/run_case.h"
#include "study/run_outputs.h"
#include "study/window_groups.h"
#include "study/window_states.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace candela {

class ComplianceTallies;

namespace annual_detail {

// What a YearTracer traces and how.
struct YearJob {
  const std::vector<Vec3>* positions = nullptr;
  const std::vector<Vec3>* normals = nullptr;
  const AnnualSky* sky = nullptr;
  const SunSet* sunSet = nullptr;
  double northDeg = 0.0;
  TraceSettings settings;
  int sunSamples = 4;  // rays over the sun's disc
  int threads = 0;
  const Distribution* distribution = nullptr;  // the processes the sensors are shared between
  const SurfaceLabels* windows = nullptr;      // window groups: the direct sun split by group
  // [[compliance]]: patch luminances of the overcast sky (1 lx horizontal) whose product with
  // each sensor's sky coefficients is its daylight factor / 100 (study/compliance/compliance_study.h).
  const std::vector<float>* overcast = nullptr;
};

// One state of the scene (blinds open or closed) traced a block of sensors at a time: the
// block's coefficients, then its hourly products. Sensor indices are the study's, so every
// sensor keeps its random streams (engine/daylight_coefficients.h SensorBlock).
class YearTracer {
 public:
  YearTracer(const Scene& scene, const YearJob& job, bool beamSun)
      : start_(std::chrono::steady_clock::now()), job_(job), beamSun_(beamSun), tracer_(scene),
        patches_(job.sky->subdivision), suns_(sunDirectionsModel(*job.sky, job.northDeg)) {
    for (const Vec3& d : job.sunSet->dirsTrue) setModel_.push_back(trueToModel(d, job.northDeg));
    // The interreflected sun needs fewer paths than the sky (each carries every sun of the set).
    sunSettings_ = interreflectedSunSettings(job.settings);
    coefficientsS_ = secondsSince(start_);
  }

  // The year of sensors first .. first + count - 1. progress(done) counts 2 per sensor (its
  // sky, then its sun coefficients) from `progressBase`. With the job's window groups and a
  // beam, groupDirect gets the hourly direct sun through each group's glass.
  AnnualIlluminance block(std::size_t first, std::size_t count, std::size_t progressBase, const ObservedStep& step,
                          std::vector<std::vector<float>>* groupDirect = nullptr) {
    const auto t0 = std::chrono::steady_clock::now();
    const int threads = job_.threads;
    const SensorBlock b{std::span(*job_.positions).subspan(first, count), std::span(*job_.normals).subspan(first, count),
                        first};
    const Distribution& processes = *job_.distribution;
    const DaylightCoefficients dc = computeDaylightCoefficients(
        tracer_, b, patches_, job_.settings, threads, [&](std::size_t d) { step(progressBase + d); }, processes);
    overcast_.assign(job_.overcast ? count : 0, 0.0f);
    for (std::size_t s = 0; s < overcast_.size(); ++s)
      for (int p = 0; p < dc.patches; ++p) overcast_[s] += dc.total[s * dc.patches + p] * (*job_.overcast)[p];
    std::vector<float> direct(count * suns_.size(), 0.0f);
    if (beamSun_ && job_.windows && groupDirect) {
      std::vector<std::vector<float>> parts = directSunCoefficientsByLabel(
          tracer_, b, suns_, job_.sunSamples, job_.settings.seed, threads, *job_.windows, processes);
      direct = std::move(parts[0]);
      groupDirect->clear();
      for (std::size_t g = 1; g < parts.size(); ++g)
        groupDirect->push_back(hourlyDirectSun(parts[g], static_cast<int>(count), *job_.sky));
    } else if (beamSun_) {
      direct = directSunCoefficients(tracer_, b, suns_, job_.sunSamples, job_.settings.seed, threads, processes);
    }
    const std::vector<float> inter =
        indirectSunCoefficients(tracer_, b, setModel_, sunSettings_, threads,
                                [&](std::size_t d) { step(progressBase + count + d); }, processes);
    coefficientsS_ += secondsSince(t0);
    AnnualIlluminance year = annualIlluminance(dc, direct, inter, *job_.sunSet, *job_.sky, threads);
    productS_ += year.productTimeS;
    return year;
  }

  // The hourly direct sun alone (sensor-major, the year's hours) of sensors first .. first +
  // count − 1, as block's directSun: the direct-sun rule's choice among more than two window
  // states needs each state's before the states' years are folded.
  std::vector<float> directSun(std::size_t first, std::size_t count) {
    const SensorBlock b{std::span(*job_.positions).subspan(first, count), std::span(*job_.normals).subspan(first, count),
                        first};
    const std::vector<float> coefficients = directSunCoefficients(tracer_, b, suns_, job_.sunSamples, job_.settings.seed,
                                                                  job_.threads, *job_.distribution);
    return hourlyDirectSun(coefficients, static_cast<int>(count), *job_.sky);
  }

  double coefficientsS() const { return coefficientsS_; }
  double productS() const { return productS_; }
  // The last block's illuminance per lux of overcast sky outdoors (YearJob::overcast), per sensor.
  const std::vector<float>& overcast() const { return overcast_; }
  // Every process's rays (a collective call: every process asks at the same point).
  uint64_t rays() const { return job_.distribution->sum(tracer_.raysTraced()); }

 private:
  std::chrono::steady_clock::time_point start_;
  const YearJob& job_;
  bool beamSun_;
  Tracer tracer_;
  SkyPatches patches_;
  std::vector<Vec3> suns_, setModel_;
  TraceSettings sunSettings_;
  std::vector<float> overcast_;
  double coefficientsS_ = 0.0, productS_ = 0.0;
};

// The study's input, read and checked before any tracing.
struct AnnualInputs {
  EpwFile epw;
  Site site;
  double north = 0.0;
  std::unique_ptr<Scene> scene;
  std::vector<PreparedGrid> grids;
  std::vector<Vec3> positions, normals;  // every grid's sensors, grids in case order
  WindowGroups windows;                  // [[window_group]]s resolved (none: one group per grid)
  WindowStates states;                   // [[window_group]]s with states (their labels in windows.labels)
};

// The year traced: blinds open, and closed where LM-83's rule can close them. The hourly values
// themselves went to the grids' files block by block (GridYear); what stays is their times.
struct AnnualTraces {
  AnnualSky sky;
  SunSet sunSet;
  double skyVectorsS = 0.0;
  double coefficientsOpenS = 0.0, coefficientsClosedS = 0.0, productOpenS = 0.0, productClosedS = 0.0;
  uint64_t raysOpen = 0, raysClosed = 0;
  bool closed = false;     // a closed state was traced
  std::unique_ptr<Scene> shaded;  // that state's scene (one group: all the glazing), kept for glare views
  int blindMaterials = 0;  // glass materials the closed state changed
  // Window states: each grid's state of every group in every hour ([grid][group][hour]); window
  // groups of blinds: 1 where the group is closed. Kept for the glare views.
  std::vector<std::vector<std::vector<uint8_t>>> stateOf;
  double coefficientsS() const { return coefficientsOpenS + coefficientsClosedS; }
  double productS() const { return productOpenS + productClosedS; }
  uint64_t rays() const { return raysOpen + raysClosed; }
};

// The year's hours, as the metrics (hour ending) and the hourly files (stamps) label them.
struct YearHours {
  std::vector<int> hourEnding;
  std::vector<HourStamp> stamps;
  std::vector<char> occupied;
  int occupiedCount = 0;
};

// One grid's year as the blocks pass: its hourly files (open), the per-hour count of its sensors
// in direct sun (LM-83's blinds rule needs the whole grid's before the closed state is used), its
// sensors' metrics and the temporal map's sensor. Nothing of it grows with hours × sensors.
struct GridYear {
  std::size_t first = 0, count = 0;  // the grid's sensors in the study's list
  std::unique_ptr<AnnualResultsStream> total, directSun;
  std::vector<int> sunlit;           // per hour: sensors with direct sun >= the ASE threshold
  std::vector<char> blindsClosed;    // per hour, once every block has been counted
  // Window groups: per hour and set of closed groups, the sensors left sunlit; then per hour the
  // closed groups (metrics/window_groups.h).
  std::vector<int> closureCounts;
  std::vector<uint32_t> closure;
  std::vector<SensorAnnualMetrics> sensors;
  int chosenSensor = 0;
  std::vector<double> chosenSensorLux;
  // Window states: per group the state of every hour, per hour the groups off their first state;
  // per traced state (a group in a state other than its first) its year's streams (all light and
  // direct sun); the metrics of
  // the reference year (every group in its first state), then of each traced state; the switched
  // year's streams (they become the grid's hourly files).
  std::vector<std::vector<uint8_t>> stateOf;
  std::vector<uint8_t> switched;
  std::vector<std::unique_ptr<AnnualResultsStream>> stateTotal, stateDirect;
  std::vector<std::vector<SensorAnnualMetrics>> stateSensors;
  std::unique_ptr<AnnualResultsStream> switchedTotal, switchedDirect;
};

// The part of block [b0, b0 + n) that lies in grid g: its first sensor and count (0: none).
inline std::pair<std::size_t, std::size_t> overlap(const GridYear& g, std::size_t b0, std::size_t n) {
  const std::size_t lo = std::max(g.first, b0), hi = std::min(g.first + g.count, b0 + n);
  return {lo, hi > lo ? hi - lo : 0};
}

// Everything the passes share.
struct AnnualPass {
  const AnnualInputs& in;
  const YearHours& y;
  const AnnualThresholds& th;
  const RunOutputFolder& folder;
  std::size_t block = kAnnualSensorsPerBlock;
  std::vector<GridYear>& grids;
  const Distribution* processes = nullptr;  // the processes the sensors are shared between
  ComplianceTallies* compliance = nullptr;  // [[compliance]]: what the entries need of the year
};

// A grid's part of a block of sensors, [lo, lo + k) in the study's list, with the year the first
// pass wrote for it (blinds open, or the reference state) read back from the grid's files.
struct BlockPart {
  GridYear* g = nullptr;
  std::size_t lo = 0, k = 0;
  std::vector<float> total, direct;  // k × hours each: all light, direct sun
};
// The parts of block [b0, b0 + n), one per grid it reaches, in grid order.
std::vector<BlockPart> readBlockParts(const AnnualPass& p, std::size_t b0, std::size_t n);

// The open (or reference) scene's year through the open pass, its times and rays into t.
void tracedOpenPass(const AnnualInputs& in, const YearJob& job, const AnnualPass& p, bool metricsNow, AnnualTraces& t,
                    StudyObserver& observer);

// The window states' passes and results (study/annual_window_states.cpp, which says how).
void traceWindowStates(const CaseFile& c, const AnnualInputs& in, const YearJob& job, const AnnualPass& p,
                       AnnualTraces& t, StudyObserver& observer);
void windowStateResults(const WindowStates& ws, const YearHours& y, GridYear& gy, AnnualGridReport& ar);
void writeWindowStateFiles(const std::filesystem::path& outDir, const WindowStates& ws, const std::string& grid,
                           GridYear& gy);

}  // namespace annual_detail
}  // namespace candela
