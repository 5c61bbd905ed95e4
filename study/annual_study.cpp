#include "study/annual_study.h"

#include "base/error.h"
#include "metrics/grid_stats.h"
#include "metrics/window_groups.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"
#include "study/annual_glare.h"
#include "study/annual_year.h"
#include "study/blinds.h"
#include "study/case/case_scene.h"
#include "study/compliance/compliance_study.h"
#include "study/finite_results.h"
#include "study/resource_estimate.h"
#include "study/warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace candela {

using namespace annual_detail;  // the year's types (study/annual_year.h)

namespace {

// The sensor nearest the grid's centroid (the temporal map's default).
int centralSensor(const SensorGrid& g) {
  Vec3 c(0.0);
  for (const SensorPoint& p : g.points) c += p.position;
  c /= static_cast<double>(g.points.size());
  int best = 0;
  for (size_t i = 1; i < g.points.size(); ++i)
    if (glm::length(g.points[i].position - c) < glm::length(g.points[best].position - c)) best = static_cast<int>(i);
  return best;
}


AnnualInputs readAnnualInputs(const CaseFile& c) {
  AnnualInputs in;
  in.epw = readEpw(c.sky.weather.string());
  const EpwFile& epw = in.epw;
  if (!epw.isFullYear())
    throw InputError(FileLoc{c.sky.weather.string(), epw.records.empty() ? 8 : epw.records.back().line, 0},
                     "the file ends after " + std::to_string(epw.records.size()) +
                         " hourly records; an annual study needs a full year (8760 or 8784)");
  in.site = caseSite(c, &epw.location);
  in.north = in.site.trueNorthDeg();
  if (!c.surfaceGrids.empty())
    throw InputError(c.surfaceGrids.front().loc, "[[surface_grid]] applies to point-in-time runs, not an annual sky "
                                                 "(the walls' and ceiling's EN 12464-1 requirements are for electric lighting)");
  if (hasWindowStates(c)) {
    // Every group in its first state, the sun-rule groups' surfaces labelled (study/window_states.h).
    in.states = resolveWindowStates(c, epw.records.size());
    in.scene = loadStateScene(c, in.north, in.states, std::vector<int>(in.states.groups.size(), 0), &in.windows.labels);
  } else {
    in.scene = loadAnnualScene(c, in.north);
    in.windows = resolveWindowGroups(c, *in.scene);
    if (!c.windowGroups.empty() && !c.annual.blinds)
      throw InputError(c.windowGroups.front().loc, "[[window_group]] sets LM-83's operable blinds, but [annual] blinds = false");
  }
  in.grids = prepareGrids(c, gridBounds(*in.scene));
  for (const GridSpec& g : c.grids) {
    if (g.daylightFactor)
      throw InputError(g.loc, "grid '" + g.name + "': daylight_factor needs [sky] type = \"cie-overcast\", not an annual sky");
    // The daylight coefficients are those of planar illuminance on each sensor's normal.
    if (g.quantity)
      throw InputError(g.quantityLoc, "grid '" + g.name + "': 'quantity' applies to point-in-time runs, not an annual sky "
                                      "(annual metrics are of the sensors' planar illuminance)");
    if (g.modelling)
      throw InputError(g.modellingLoc, "grid '" + g.name + "': 'modelling' applies to point-in-time runs, not an annual sky");
  }
  for (const PreparedGrid& g : in.grids)
    for (const SensorPoint& p : g.grid.points) {
      in.positions.push_back(p.position);
      in.normals.push_back(p.normal);
    }
  const AnnualSpec& a = c.annual;
  if (a.reportSensor)
    for (const PreparedGrid& g : in.grids)
      if (*a.reportSensor >= static_cast<int>(g.grid.size()))
        throw InputError(a.reportSensorLoc, "report_sensor " + std::to_string(*a.reportSensor) + " is beyond grid '" +
                                    g.spec->name + "' (" + std::to_string(g.grid.size()) + " points)");
  return in;
}

// What the resource estimate counts: sensors per grid, hours, hours with direct sun.
AnnualCounts annualCounts(const AnnualInputs& in) {
  AnnualCounts a;
  for (const PreparedGrid& g : in.grids) a.gridSensors.push_back(g.grid.size());
  a.hours = in.epw.records.size();
  for (const EpwRecord& r : in.epw.records) a.sunHours += r.directNormalWhm2 > 0.0 || r.directNormalLux > 0.0;
  return a;
}

// The year's sky vectors, the sun set, and the sampling guide of the scene's sky.
AnnualTraces prepareAnnualSky(const CaseFile& c, AnnualInputs& in, const ResolvedTrace& trace) {
  AnnualSkyOptions skyOptions;
  skyOptions.subdivision = c.annual.skySubdivision;
  skyOptions.groundReflectance = c.sky.groundReflectance;
  skyOptions.threads = trace.threads;
  AnnualTraces t;
  const auto tSky = std::chrono::steady_clock::now();
  t.sky = makeAnnualSky(in.epw, in.site, skyOptions);
  t.skyVectorsS = secondsSince(tSky);
  in.scene->sky->model = yearSamplingGuide(t.sky);
  t.sunSet = indirectSunSet(t.sky);
  return t;
}

// The settings table of the report, in the order a reader scans it.
void describeAnnualSettings(ReportData& data, const CaseFile& c, const AnnualInputs& in, const AnnualTraces& t,
                            const ResolvedTrace& trace, int occupiedCount) {
  const AnnualSpec& a = c.annual;
  const TraceSettings& settings = trace.settings;
  const int threads = trace.threads;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s (%s, %.2f°, %.2f°), %zu hours", in.epw.location.city.c_str(),
                c.sky.weather.filename().string().c_str(), in.site.latitudeDeg, in.site.longitudeDeg,
                t.sky.hours.size());
  const double coefficientsS = t.coefficientsS();
  data.run.settings = {
      {"quality", qualityName(trace.quality)},
      {"sky", "annual: Perez all-weather sky per hour of the weather file"},
      {"weather", buf},
      {"sky patches", a.skySubdivision == 1 ? "Tregenza, 145 + ground"
                                             : "Reinhart MF:" + std::to_string(a.skySubdivision) + ", " +
                                                   std::to_string(SkyPatches(a.skySubdivision).skyPatchCount()) + " + ground"},
      {"direct sun", "actual position every hour, " + std::to_string(a.sunSamples) + " rays over the disc"},
      {"interreflected sun", std::to_string(t.sunSet.dirsTrue.size()) + " sun positions (Reinhart MF:2 patches)"},
      {"hemisphere samples per point", std::to_string(settings.hemisphereSamples)},
      {"sky samples per patch", std::to_string(settings.lightSamples)},
      {"occupancy", formatFixed(a.occupancyStartHour, 2) + "–" + formatFixed(a.occupancyEndHour, 2) + " h (" +
                        std::to_string(occupiedCount) + " h a year)"},
      {"blinds (LM-83)", !a.blinds ? "not modelled"
                         : !in.states.empty() ? "replaced by window states (" + std::to_string(in.states.groups.size()) +
                                                    (in.states.groups.size() == 1 ? " group" : " groups") +
                                                    ": LM-83's direct-sun rule or a schedule)"
                         : !in.windows.groups.empty()
                             ? std::to_string(in.windows.groups.size()) +
                                   " window groups closing in the fewest combination that leaves ≤ 2 % of a grid's "
                                   "sensors with ≥ 1000 lx of direct sun"
                         : t.blindMaterials == 0 ? "no glass in the scene"
                                                 : "closed when > 2 % of a grid's sensors get ≥ 1000 lx of direct sun: "
                                                   "glass as a 20 % diffuse transmitter"},
      {"threads", threads > 0 ? std::to_string(threads) : "all (" + std::to_string(threadsUsed(threads)) + ")"},
      {"calculation points", std::to_string(in.positions.size())},
      {"sky vectors time", formatFixed(t.skyVectorsS, 2) + " s"},
      {"rays for the coefficients", formatFixed(t.rays() / 1e6, 1) + " M (" +
                                        formatFixed(t.rays() / 1e6 / coefficientsS, 2) + " M rays/s)"},
  };
}

AnnualThresholds thresholdsOf(const AnnualSpec& a) {
  AnnualThresholds th;
  th.daLux = a.daThresholdLux;
  th.udiLowLux = a.udiLowLux;
  th.udiHighLux = a.udiHighLux;
  th.sdaFraction = a.sdaFraction;
  th.aseLux = a.aseThresholdLux;
  th.aseHours = a.aseHours;
  th.occupancyStartHour = a.occupancyStartHour;
  th.occupancyEndHour = a.occupancyEndHour;
  return th;
}

YearHours yearHours(const AnnualSky& sky, const AnnualSpec& a) {
  YearHours y;
  for (const AnnualHour& h : sky.hours) {
    y.hourEnding.push_back(h.hour);
    y.stamps.push_back({static_cast<uint8_t>(h.month), static_cast<uint8_t>(h.day), static_cast<uint8_t>(h.hour)});
  }
  y.occupied = occupiedHours(y.hourEnding, a.occupancyStartHour, a.occupancyEndHour);
  y.occupiedCount = countHours(y.occupied);
  return y;
}

// The study's blocks: sensorsPerBlock rounded up to kAnnualProductBlock.
std::size_t blockSize(const AnnualStudyOptions& o) {
  const std::size_t m = kAnnualProductBlock;
  return std::max<std::size_t>(1, (o.sensorsPerBlock + m - 1) / m) * m;
}

// Pass 1, blinds open: every block's year goes to the grids' files, counted for the blinds rule;
// without a closed state the metrics are taken on the way.
void openPass(const AnnualPass& p, YearTracer& open, bool metricsNow, StudyObserver& observer) {
  const std::size_t sensors = p.in.positions.size(), nh = p.y.stamps.size();
  const ObservedStep step(observer, "coefficients", 2 * sensors);
  for (std::size_t b0 = 0; b0 < sensors; b0 += p.block) {
    const std::size_t n = std::min(p.block, sensors - b0);
    std::vector<std::vector<float>> groupDirect;
    const AnnualIlluminance year = open.block(b0, n, 2 * b0, step, &groupDirect);
    checkFinite(year.total, "the hourly illuminance", b0 * nh);
    if (p.compliance)
      p.compliance->addBlock(b0, n, static_cast<int>(nh), year.total.data(), open.overcast().data());
    for (GridYear& g : p.grids) {
      // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
      const auto part = overlap(g, b0, n);
      const std::size_t lo = part.first, k = part.second;
      if (k == 0) continue;
      const float* total = year.total.data() + (lo - b0) * nh;
      const float* direct = year.directSun.data() + (lo - b0) * nh;
      p.folder.guard([&] {
        g.total->append(total, static_cast<int>(k));
        g.directSun->append(direct, static_cast<int>(k));
      });
      countSunlitSensors(direct, static_cast<int>(k), static_cast<int>(nh), p.th.aseLux, g.sunlit);
      if (!groupDirect.empty()) {
        std::vector<const float*> parts;
        for (const std::vector<float>& d : groupDirect) parts.push_back(d.data() + (lo - b0) * nh);
        countSunlitByClosure(direct, parts, static_cast<int>(k), static_cast<int>(nh), p.th.aseLux, g.closureCounts);
      }
      const std::size_t chosen = g.first + static_cast<std::size_t>(g.chosenSensor);
      if (chosen >= lo && chosen < lo + k)
        g.chosenSensorLux.assign(total + (chosen - lo) * nh, total + (chosen - lo + 1) * nh);
      if (metricsNow) {
        const auto m = sensorAnnualMetrics(total, direct, static_cast<int>(k), static_cast<int>(nh), p.y.occupied, p.th);
        g.sensors.insert(g.sensors.end(), m.begin(), m.end());
      }
    }
  }
}

// Pass 2, blinds closed: with every grid's hours of closed blinds known, each block's closed year
// beside its open one, read back from the grid's files, gives the metrics.
void closedPass(const AnnualPass& p, YearTracer& closed, StudyObserver& observer) {
  const std::size_t sensors = p.in.positions.size(), nh = p.y.stamps.size();
  for (GridYear& g : p.grids)
    g.blindsClosed = blindsClosedFromCounts(g.sunlit, static_cast<int>(g.count), p.y.occupied);
  const ObservedStep step(observer, "blinds closed: coefficients", 2 * sensors);
  for (std::size_t b0 = 0; b0 < sensors; b0 += p.block) {
    const std::size_t n = std::min(p.block, sensors - b0);
    AnnualIlluminance year = closed.block(b0, n, 2 * b0, step);
    std::vector<float>().swap(year.directSun);  // no beam through closed blinds: zeros
    checkFinite(year.total, "the hourly illuminance with blinds closed", b0 * nh);
    for (BlockPart& part : readBlockParts(p, b0, n)) {
      GridYear& g = *part.g;
      const auto m = sensorAnnualMetrics(part.total.data(), part.direct.data(), static_cast<int>(part.k),
                                         static_cast<int>(nh), p.y.occupied, p.th,
                                         year.total.data() + (part.lo - b0) * nh, &g.blindsClosed);
      g.sensors.insert(g.sensors.end(), m.begin(), m.end());
    }
  }
}

// A closed group's tracer and its index among the window groups.
struct ClosedGroup {
  int group = 0;
  std::unique_ptr<YearTracer> tracer;
};

// Pass 2 with window groups: each block's open year read back, every traced group's closed year
// folded in (foldClosedGroup), the metrics of the result.
void groupsPass(const AnnualPass& p, std::vector<ClosedGroup>& closed, StudyObserver& observer) {
  const std::size_t sensors = p.in.positions.size(), nh = p.y.stamps.size(), nq = closed.size();
  const ObservedStep step(observer, "blinds closed per window group: coefficients", 2 * sensors * nq);
  for (std::size_t b0 = 0; b0 < sensors; b0 += p.block) {
    const std::size_t n = std::min(p.block, sensors - b0);
    std::vector<BlockPart> parts = readBlockParts(p, b0, n);
    std::vector<std::vector<float>> combined;
    for (const BlockPart& part : parts) combined.push_back(part.total);
    for (std::size_t q = 0; q < nq; ++q) {
      const AnnualIlluminance year = closed[q].tracer->block(b0, n, 2 * (b0 * nq + q * n), step);
      checkFinite(year.total, "the hourly illuminance with blinds closed", b0 * nh);
      for (std::size_t i = 0; i < parts.size(); ++i)
        foldClosedGroup(year.total.data() + (parts[i].lo - b0) * nh, parts[i].total.data(), parts[i].g->closure,
                        closed[q].group, parts[i].k, combined[i].data());
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const BlockPart& part = parts[i];
      const auto m = sensorAnnualMetrics(combined[i].data(), part.direct.data(), static_cast<int>(part.k),
                                         static_cast<int>(nh), p.y.occupied, p.th);
      part.g->sensors.insert(part.g->sensors.end(), m.begin(), m.end());
    }
  }
}

// The grids' files opened beside the run's folder (unnamed temporaries until the end), their
// report sensors chosen.
std::vector<GridYear> openGridYears(const AnnualInputs& in, const AnnualSpec& a, const YearHours& y,
                                    const RunOutputFolder& folder) {
  std::vector<GridYear> grids;
  std::size_t first = 0;
  for (const PreparedGrid& g : in.grids) {
    GridYear gy;
    gy.first = first;
    gy.count = g.grid.size();
    gy.sunlit.assign(y.stamps.size(), 0);
    if (in.windows.labels.count > 0)
      gy.closureCounts.assign(y.stamps.size() << in.windows.labels.count, 0);
    gy.chosenSensor = a.reportSensor ? *a.reportSensor : centralSensor(g.grid);
    gy.sensors.reserve(gy.count);
    const int n = static_cast<int>(gy.count);
    folder.guard([&] {
      const std::filesystem::path& dir = folder.beside();
      gy.total = std::make_unique<AnnualResultsStream>(dir / annualResultsFileName(g.spec->name), n, y.stamps);
      gy.directSun =
          std::make_unique<AnnualResultsStream>(dir / annualResultsFileName(g.spec->name + "_direct_sun"), n, y.stamps);
    });
    first += gy.count;
    grids.push_back(std::move(gy));
  }
  return grids;
}

// With window groups: the open year with the direct sun split by group, each grid's closures,
// then one closed scene per group closed in some hour (only that group's glass closed).
void traceWindowGroups(const CaseFile& c, const AnnualInputs& in, const YearJob& job, const AnnualPass& p,
                       AnnualTraces& t, StudyObserver& observer) {
  tracedOpenPass(in, job, p, false, t, observer);
  const int groups = in.windows.labels.count;
  uint32_t used = 0;
  for (GridYear& g : p.grids) {
    g.closure = blindsClosureFromCounts(g.closureCounts, groups, static_cast<int>(g.count), p.y.occupied);
    std::vector<int>().swap(g.closureCounts);
    for (uint32_t m : g.closure) used |= m;
  }
  std::vector<std::unique_ptr<Scene>> scenes;
  std::vector<ClosedGroup> closed;
  for (int q = 0; q < groups; ++q) {
    if (!((used >> q) & 1u)) continue;  // never closed: its closed year is never used
    scenes.push_back(loadAnnualScene(c, in.north));
    scenes.back()->sky->model = in.scene->sky->model;
    t.blindMaterials += closeWindowGroup(*scenes.back(), in.windows, q);
    // With a beam: the sun through the other groups' open glass still shines in (the closed
    // glass stops the beams through it, the same rays otherwise).
    closed.push_back({q, std::make_unique<YearTracer>(*scenes.back(), job, true)});
  }
  t.closed = !closed.empty();
  groupsPass(p, closed, observer);
  // The [[compliance]] glare views follow the groups' blinds: each grid's closed groups per hour
  // (a group "closed" is in its second state, study/compliance/compliance_study.cpp).
  for (const GridYear& g : p.grids) {
    std::vector<std::vector<uint8_t>> byGroup(static_cast<std::size_t>(groups), std::vector<uint8_t>(g.closure.size(), 0));
    for (std::size_t h = 0; h < g.closure.size(); ++h)
      for (int q = 0; q < groups; ++q) byGroup[static_cast<std::size_t>(q)][h] = static_cast<uint8_t>((g.closure[h] >> q) & 1u);
    t.stateOf.push_back(std::move(byGroup));
  }
  for (const ClosedGroup& q : closed) {
    t.coefficientsClosedS += q.tracer->coefficientsS();
    t.productClosedS += q.tracer->productS();
    t.raysClosed += q.tracer->rays();
  }
}

// The year's trace settings: the case's and the command line's, except that at the normal
// preset the coefficients' hemisphere takes kAnnualNormalHemisphereSamples rays unless the case
// or the command line gives a count. The annual metrics sum each sensor's coefficients over 3650
// occupied hours, where the hemisphere's noise averages out: on the annual office demo 1024 rays
// give DA300, sDA300/50 and ASE1000/250 within 0.3 points of the converged figures at half the
// cost of 2048; 512 rays put sDA 1.8 points low (docs/performance.md#annual-daylight).
constexpr int kAnnualNormalHemisphereSamples = 1024;

ResolvedTrace annualTrace(const CaseFile& c, const TraceOverrides& o) {
  ResolvedTrace r = resolveTrace(&c.settings, o, Method::kPath);
  if (r.quality == Quality::kNormal && !o.samples && !c.settings.samples)
    r.settings.hemisphereSamples = kAnnualNormalHemisphereSamples;
  return r;
}

// Both states of the year, block by block, into the grids' files and metrics.
void traceAnnual(const CaseFile& c, const AnnualInputs& in, const ResolvedTrace& trace, const AnnualPass& p,
                 AnnualTraces& t, StudyObserver& observer) {
  const AnnualSpec& a = c.annual;
  TraceSettings settings = trace.settings;
  settings.method = Method::kPath;  // coefficients are path traced (skyCoefficients)
  YearJob job{&in.positions, &in.normals, &t.sky,         &t.sunSet,      in.north,
              settings,       a.sunSamples, trace.threads, p.processes};
  if (p.compliance && p.compliance->needsHours()) job.overcast = &p.compliance->overcastPatches();
  if (!in.states.empty()) {
    if (in.windows.labels.count > 0) job.windows = &in.windows.labels;
    traceWindowStates(c, in, job, p, t, observer);
    return;
  }
  if (in.windows.labels.count > 0) {
    job.windows = &in.windows.labels;
    traceWindowGroups(c, in, job, p, t, observer);
    return;
  }
  std::unique_ptr<Scene>& shaded = t.shaded;
  if (a.blinds) {
    shaded = loadAnnualScene(c, in.north);
    shaded->sky->model = in.scene->sky->model;
    t.blindMaterials = closeBlinds(*shaded);
  }
  t.closed = t.blindMaterials > 0;
  tracedOpenPass(in, job, p, !t.closed, t, observer);
  if (t.closed) {
    YearTracer closed(*shaded, job, false);
    closedPass(p, closed, observer);
    t.coefficientsClosedS = closed.coefficientsS();
    t.productClosedS = closed.productS();
    t.raysClosed = closed.rays();
  }
}

// Each grid's report from its metrics (LM-83's blinds rule applied per grid).
void annualGridReports(ReportData& data, const AnnualInputs& in, const AnnualThresholds& th, const YearHours& y,
                       std::vector<GridYear>& grids) {
  for (std::size_t gi = 0; gi < in.grids.size(); ++gi) {
    const PreparedGrid& g = in.grids[gi];
    GridYear& gy = grids[gi];
    AnnualGridReport ar;
    ar.sensors = std::move(gy.sensors);
    ar.summary = summarizeAnnual(ar.sensors, y.occupiedCount);
    ar.chosenSensor = gy.chosenSensor;
    ar.chosenSensorLux = std::move(gy.chosenSensorLux);
    ar.hours = y.stamps;
    for (std::size_t q = 0; q < in.windows.groups.size(); ++q)
      ar.windowGroups.push_back({in.windows.groups[q].name, in.windows.groups[q].surfaces,
                                 closedHoursOfGroup(gy.closure, static_cast<int>(q))});
    windowStateResults(in.states, y, gy, ar);
    GridReport r;
    r.name = g.spec->name;
    r.description = gridDescription(g) + "; temporal map of sensor " + std::to_string(ar.chosenSensor);
    r.quantity = "Daylight autonomy DA" + formatFixed(th.daLux, 0);
    r.unit = "%";
    r.values = annualColumn(ar, &SensorAnnualMetrics::da);
    r.stats = computeGridStats(r.values);
    r.layout = planLayout(g);
    r.annual = std::move(ar);
    data.grids.push_back(std::move(r));
  }
}

// Per grid: the annual CSV; the hourly files (all light, and direct sun alone), complete, move in.
void writeAnnualGrids(const std::filesystem::path& outDir, const ReportData& data, const AnnualInputs& in,
                      std::vector<GridYear>& grids) {
  for (std::size_t gi = 0; gi < in.grids.size(); ++gi) {
    const PreparedGrid& g = in.grids[gi];
    std::vector<ReportPoint> points;
    for (const SensorPoint& s : g.grid.points) points.push_back({s.position, s.normal});
    writeAnnualGridCsv(outDir, g.spec->name, points, *data.grids[gi].annual);
    if (!in.states.empty()) {
      writeWindowStateFiles(outDir, in.states, g.spec->name, grids[gi]);
      continue;
    }
    grids[gi].total->commitAs(outDir / annualResultsFileName(g.spec->name));
    grids[gi].directSun->commitAs(outDir / annualResultsFileName(g.spec->name + "_direct_sun"));
  }
}

// The study's grids as the compliance entries see them: their sensors and cell areas.
std::vector<ComplianceGrid> complianceGrids(const AnnualInputs& in) {
  std::vector<ComplianceGrid> out;
  std::size_t first = 0;
  for (const PreparedGrid& g : in.grids) {
    out.push_back({g.spec->name, first, g.grid.size(), g.grid.regular ? g.grid.cellAreaM2() : 1.0});
    first += g.grid.size();
  }
  return out;
}

std::vector<ComplianceReport> evaluateComplianceOf(const CaseFile& c, const AnnualInputs& in, const AnnualTraces& t,
                                                   const ResolvedTrace& trace, const TraceSettings& pointSettings,
                                                   const YearHours& y,
                                                   const ComplianceTallies& tallies, const ReportData& data,
                                                   const std::vector<GridYear>& grids, StudyObserver& observer) {
  TraceSettings settings = trace.settings;
  settings.method = Method::kPath;
  const AnnualGlareJob glareJob{&t.sky, &t.sunSet, in.north, settings, c.annual.sunSamples, trace.threads};
  ComplianceInputs ci;
  ci.caseFile = &c;
  ci.scene = in.scene.get();
  ci.site = in.site;
  ci.epw = &in.epw;
  ci.sky = &t.sky;
  ci.glareJob = &glareJob;
  ci.pointSettings = pointSettings;
  ci.occupied = &y.occupied;
  ci.weatherYear = in.epw.records.empty() ? 2026 : in.epw.records.front().year;
  ci.tallies = &tallies;
  ci.annualGrids = &data.grids;
  ci.positions = &in.positions;
  ci.normals = &in.normals;
  ci.threads = trace.threads;
  ci.observer = &observer;
  // The glare views' blinds: the closed scene of LM-83's blinds and each grid's closed hours.
  std::vector<std::vector<char>> closedHours;
  if (t.closed && t.shaded) {
    for (const GridYear& g : grids) closedHours.push_back(g.blindsClosed);
    ci.closedScene = t.shaded.get();
    ci.blindsClosed = &closedHours;
  }
  // Window states: the views see each combination of states their space's hours use; window
  // groups of blinds: each combination of closed groups.
  if (!in.states.empty()) {
    ci.windowStates = &t.stateOf;
    ci.blindsLabel = "window_states";
    ci.stateScene = [&c, &in](const std::vector<int>& choice) {
      std::unique_ptr<Scene> scene = loadStateScene(c, in.north, in.states, choice);
      scene->sky->model = in.scene->sky->model;
      return scene;
    };
  } else if (in.windows.labels.count > 0 && !t.stateOf.empty()) {
    ci.windowStates = &t.stateOf;
    ci.blindsLabel = "lm83";
    ci.stateScene = [&c, &in](const std::vector<int>& closedGroups) {
      std::unique_ptr<Scene> scene = loadAnnualScene(c, in.north);
      scene->sky->model = in.scene->sky->model;
      for (std::size_t q = 0; q < closedGroups.size(); ++q)
        if (closedGroups[q] != 0) closeWindowGroup(*scene, in.windows, static_cast<int>(q));
      return scene;
    };
  }
  return evaluateCompliance(ci);
}

}  // namespace

std::vector<BlockPart> annual_detail::readBlockParts(const AnnualPass& p, std::size_t b0, std::size_t n) {
  const std::size_t nh = p.y.stamps.size();
  std::vector<BlockPart> parts;
  for (GridYear& g : p.grids) {
    const auto [lo, k] = overlap(g, b0, n);
    if (k == 0) continue;
    BlockPart part{&g, lo, k, std::vector<float>(k * nh), std::vector<float>(k * nh)};
    const int from = static_cast<int>(lo - g.first), count = static_cast<int>(k);
    p.folder.guard([&] {
      g.total->read(from, count, part.total.data());
      g.directSun->read(from, count, part.direct.data());
    });
    parts.push_back(std::move(part));
  }
  return parts;
}

// The open (or reference) scene's year through openPass, its times and rays into t.
void annual_detail::tracedOpenPass(const AnnualInputs& in, const YearJob& job, const AnnualPass& p, bool metricsNow,
                                   AnnualTraces& t, StudyObserver& observer) {
  YearTracer open(*in.scene, job, true);
  openPass(p, open, metricsNow, observer);
  t.coefficientsOpenS = open.coefficientsS();
  t.productOpenS = open.productS();
  t.raysOpen = open.rays();
}

RunResult runAnnualStudy(const CaseFile& c, const RunContext& run, StudyObserver& observer,
                         const AnnualStudyOptions& options) {
  // 1. Input: weather, site, scene, grids — every error before any tracing.
  AnnualInputs in = readAnnualInputs(c);
  const ResolvedTrace trace = annualTrace(c, run.request.trace);
  Warnings warnings = annualInputWarnings(c, in.epw.location, *in.scene, in.grids);
  checkWeatherGaps(in.epw, c.sky.weather.string(), warnings);
  throwIfStrict(warnings, run.request.strict);
  // The point-in-time settings of the [[compliance]] entries (LEED option 2's clear-sky traces).
  const TraceSettings pointSettings = resolveTrace(&c.settings, run.request.trace, Method::kCache).settings;
  const ResourceEstimate needs = estimateAnnualStudy(c, *in.scene, annualCounts(in), trace.settings, trace.threads,
                                                     blockSize(options), &pointSettings);
  checkResources(needs, run.request.limits, FileLoc{c.path.string(), 0, 0});
  observer.estimated(needs);
  // 2. Sky vectors of the year, then coefficients and hours block by block: the hourly files
  // stream into unnamed temporaries, moved into the run's folder at the end.
  AnnualTraces t = prepareAnnualSky(c, in, trace);
  const YearHours y = yearHours(t.sky, c.annual);
  const AnnualThresholds th = thresholdsOf(c.annual);
  // Only the process that writes the result folder streams the hourly files (rank 0, a merge);
  // the others' folder writes nothing, and their metrics, which no output uses, are not complete.
  const Distribution& processes = run.request.processes();
  RunOutputFolder folder(run.outDir, processes.writesOutputs());
  std::vector<GridYear> grids = openGridYears(in, c.annual, y, folder);
  ComplianceTallies compliance(c, complianceGrids(in), t.sky);
  AnnualPass pass{in, y, th, folder, blockSize(options), grids, &processes};
  if (!c.compliance.empty()) pass.compliance = &compliance;
  traceAnnual(c, in, trace, pass, t, observer);
  // 3. Metrics per grid.
  RunResult result;
  result.outDir = run.outDir;
  result.annual = true;
  result.hours = static_cast<int>(y.stamps.size());
  result.coefficientsS = t.coefficientsS();
  result.productS = t.productS();
  ReportData& data = result.data;
  data = reportDataFor(c, run, trace.settings.seed);
  data.run.coefficientsTimeS = result.coefficientsS;
  data.run.productTimeS = result.productS;
  describeAnnualSettings(data, c, in, t, trace, y.occupiedCount);
  data.run.functionFiles = in.scene->functionFiles;
  data.run.settings.emplace_back("ranks", run.request.processes().describe());
  data.warnings = warnings;
  annualGridReports(data, in, th, y, grids);
  // The [[compliance]] entries, by the process that writes the results (a shard's part has none:
  // its merge evaluates them).
  if (!c.compliance.empty() && processes.writesOutputs() && !processes.partial()) {
    data.compliance = evaluateComplianceOf(c, in, t, trace, pointSettings, y, compliance, data, grids, observer);
  }
  data.run.runTimeS = secondsSince(run.start);
  // 4. Write the rest; the folder is committed as a whole (a shard writes its part instead).
  if (processes.partial()) {
    commitRun(c, run, {});
    return result;
  }
  processes.finish();
  folder.write([&](const std::filesystem::path& dir) {
    writeAnnualGrids(dir, data, in, grids);
    writeSummaryCsv(dir, data);
    writeSummaryJson(dir, data);
    writeHtmlReport(dir / "report.html", data);
  });
  folder.commit();
  return result;
}

}  // namespace candela
