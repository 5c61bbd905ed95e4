#include "study/annual_study.h"

#include "base/error.h"
#include "engine/daylight_coefficients.h"
#include "metrics/annual.h"
#include "metrics/grid_stats.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "reports/annual_results.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"
#include "study/blinds.h"
#include "study/case_scene.h"
#include "study/finite_results.h"
#include "study/prepared_grid.h"
#include "study/resource_estimate.h"
#include "study/run_outputs.h"
#include "study/warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace candela {

namespace {

namespace fs = std::filesystem;

// A year at the sensors for one state of the scene.
struct YearRun {
  AnnualIlluminance year;
  double coefficientsS = 0.0;
  uint64_t rays = 0;  // rays cast for the coefficients
};

// What traceYear traces and how.
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
};

YearRun traceYear(const Scene& scene, const YearJob& job, bool beamSun, const std::string& label,
                  StudyObserver& observer) {
  const std::vector<Vec3>& positions = *job.positions;
  const std::vector<Vec3>& normals = *job.normals;
  const AnnualSky& sky = *job.sky;
  const SunSet& sunSet = *job.sunSet;
  const double northDeg = job.northDeg;
  const TraceSettings& settings = job.settings;
  const int threads = job.threads;
  const Distribution& processes = *job.distribution;
  const auto t0 = std::chrono::steady_clock::now();
  const Tracer tracer(scene);
  const SkyPatches patches(sky.subdivision);
  DaylightCoefficients dc;
  {
    const ObservedStep step(observer, label + "sky coefficients", positions.size());
    dc = computeDaylightCoefficients(tracer, positions, normals, patches, settings, threads,
                                     [&step](size_t d) { step(d); }, processes);
  }
  const std::vector<Vec3> suns = sunDirectionsModel(sky, northDeg);
  std::vector<float> direct(positions.size() * suns.size(), 0.0f);
  if (beamSun)
    direct = directSunCoefficients(tracer, positions, normals, suns, job.sunSamples, settings.seed, threads, processes);
  std::vector<Vec3> setModel;
  for (const Vec3& d : sunSet.dirsTrue) setModel.push_back(trueToModel(d, northDeg));
  // The interreflected sun needs fewer paths than the sky (each carries every sun of the set).
  TraceSettings sunSettings = settings;
  sunSettings.hemisphereSamples = std::max(64, settings.hemisphereSamples / 8);
  sunSettings.firstBounceSplit = std::max(1, settings.firstBounceSplit / 4);
  std::vector<float> inter;
  {
    const ObservedStep step(observer, label + "sun coefficients", positions.size());
    inter = indirectSunCoefficients(tracer, positions, normals, setModel, sunSettings, threads,
                                    [&step](size_t d) { step(d); }, processes);
  }
  YearRun r;
  r.coefficientsS = secondsSince(t0);
  r.rays = processes.sum(tracer.raysTraced());  // every rank's
  r.year = annualIlluminance(dc, direct, inter, sunSet, sky, threads);
  return r;
}

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


// The study's input, read and checked before any tracing.
struct AnnualInputs {
  EpwFile epw;
  Site site;
  double north = 0.0;
  std::unique_ptr<Scene> scene;
  std::vector<PreparedGrid> grids;
  std::vector<Vec3> positions, normals;  // every grid's sensors, grids in case order
};

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
  in.scene = loadAnnualScene(c, in.north);
  in.grids = prepareGrids(c, gridBounds(*in.scene));
  for (const GridSpec& g : c.grids)
    if (g.daylightFactor)
      throw InputError(g.loc, "grid '" + g.name + "': daylight_factor needs [sky] type = \"cie-overcast\", not an annual sky");
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

// The year traced: blinds open, and closed where LM-83's rule can close them.
struct AnnualTraces {
  AnnualSky sky;
  SunSet sunSet;
  double skyVectorsS = 0.0;
  YearRun open;
  std::optional<YearRun> closed;
  int blindMaterials = 0;  // glass materials the closed state changed
  double coefficientsS() const { return open.coefficientsS + (closed ? closed->coefficientsS : 0.0); }
  double productS() const { return open.year.productTimeS + (closed ? closed->year.productTimeS : 0.0); }
  uint64_t rays() const { return open.rays + (closed ? closed->rays : 0); }
};

AnnualTraces traceAnnual(const CaseFile& c, AnnualInputs& in, const ResolvedTrace& trace, const Distribution& processes,
                         StudyObserver& observer) {
  const AnnualSpec& a = c.annual;
  AnnualSkyOptions skyOptions;
  skyOptions.subdivision = a.skySubdivision;
  skyOptions.groundReflectance = c.sky.groundReflectance;
  skyOptions.threads = trace.threads;
  TraceSettings settings = trace.settings;
  settings.method = Method::kPath;  // coefficients are path traced (Tracer::skyCoefficients)

  AnnualTraces t;
  const auto tSky = std::chrono::steady_clock::now();
  t.sky = makeAnnualSky(in.epw, in.site, skyOptions);
  t.skyVectorsS = secondsSince(tSky);
  in.scene->sky->model = yearSamplingGuide(t.sky);
  t.sunSet = indirectSunSet(t.sky);
  const YearJob job{&in.positions, &in.normals, &t.sky,         &t.sunSet,     in.north,
                    settings,       a.sunSamples, trace.threads, &processes};
  t.open = traceYear(*in.scene, job, true, "", observer);
  if (a.blinds) {
    std::unique_ptr<Scene> shaded = loadAnnualScene(c, in.north);
    shaded->sky->model = in.scene->sky->model;
    t.blindMaterials = closeBlinds(*shaded);
    if (t.blindMaterials > 0) t.closed = traceYear(*shaded, job, false, "blinds closed: ", observer);
  }
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

// The year's hours, as the metrics (hour ending) and the hourly files (stamps) label them.
struct YearHours {
  std::vector<int> hourEnding;
  std::vector<HourStamp> stamps;
  std::vector<char> occupied;
  int occupiedCount = 0;
};

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

// Each grid's annual metrics (LM-83's blinds rule applied per grid) and report.
void annualGridReports(ReportData& data, const CaseFile& c, const AnnualInputs& in, const AnnualTraces& t,
                       const YearHours& y) {
  const AnnualSpec& a = c.annual;
  const AnnualThresholds th = thresholdsOf(a);
  const int nh = t.open.year.hours;
  size_t first = 0;
  for (const PreparedGrid& g : in.grids) {
    const int n = static_cast<int>(g.grid.size());
    const float* total = t.open.year.total.data() + first * nh;
    const float* direct = t.open.year.directSun.data() + first * nh;
    std::vector<char> blindsClosed;
    const float* shaded = nullptr;
    if (t.closed) {
      blindsClosed = blindsClosedHours(direct, n, nh, y.occupied, th.aseLux);
      shaded = t.closed->year.total.data() + first * nh;
    }
    AnnualGridReport ar;
    ar.sensors = sensorAnnualMetrics(total, direct, n, nh, y.occupied, th, shaded, t.closed ? &blindsClosed : nullptr);
    ar.summary = summarizeAnnual(ar.sensors, y.occupiedCount);
    ar.chosenSensor = a.reportSensor ? *a.reportSensor : centralSensor(g.grid);
    for (int h = 0; h < nh; ++h) ar.chosenSensorLux.push_back(total[static_cast<size_t>(ar.chosenSensor) * nh + h]);
    ar.hours = y.stamps;
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
    first += g.grid.size();
  }
}

// Per grid: the annual CSV and the hourly files (all light, and direct sun alone).
void writeAnnualGrids(const std::filesystem::path& outDir, const ReportData& data, const AnnualInputs& in,
                      const AnnualTraces& t, const YearHours& y) {
  const int nh = t.open.year.hours;
  size_t first = 0;
  for (size_t gi = 0; gi < in.grids.size(); ++gi) {
    const PreparedGrid& g = in.grids[gi];
    const int n = static_cast<int>(g.grid.size());
    std::vector<ReportPoint> points;
    for (const SensorPoint& s : g.grid.points) points.push_back({s.position, s.normal});
    writeAnnualGridCsv(outDir, g.spec->name, points, *data.grids[gi].annual);
    AnnualResults res;
    res.sensors = n;
    res.hours = y.stamps;
    res.lux.assign(t.open.year.total.begin() + first * nh, t.open.year.total.begin() + (first + n) * nh);
    writeAnnualResults(outDir / annualResultsFileName(g.spec->name), res);
    res.lux.assign(t.open.year.directSun.begin() + first * nh, t.open.year.directSun.begin() + (first + n) * nh);
    writeAnnualResults(outDir / annualResultsFileName(g.spec->name + "_direct_sun"), res);
    first += n;
  }
}

}  // namespace

RunResult runAnnualStudy(const CaseFile& c, const RunContext& run, StudyObserver& observer) {
  // 1. Input: weather, site, scene, grids — every error before any tracing.
  AnnualInputs in = readAnnualInputs(c);
  const ResolvedTrace trace = resolveTrace(&c.settings, run.request.trace, Method::kPath);
  Warnings warnings = annualInputWarnings(c, in.epw.location, *in.scene, in.grids);
  checkWeatherGaps(in.epw, c.sky.weather.string(), warnings);
  throwIfStrict(warnings, run.request.strict);
  const ResourceEstimate needs = estimateAnnualStudy(c, *in.scene, annualCounts(in), trace.settings, trace.threads);
  checkResources(needs, run.request.limits, FileLoc{c.path.string(), 0, 0});
  observer.estimated(needs);
  // 2. Sky vectors of the year, then coefficients.
  const AnnualTraces t = traceAnnual(c, in, trace, run.request.processes(), observer);
  checkFinite(t.open.year.total, "the hourly illuminance");
  if (t.closed) checkFinite(t.closed->year.total, "the hourly illuminance with blinds closed");
  // 3. Metrics per grid.
  const YearHours y = yearHours(t.sky, c.annual);
  RunResult result;
  result.outDir = run.outDir;
  result.annual = true;
  result.hours = t.open.year.hours;
  result.coefficientsS = t.coefficientsS();
  result.productS = t.productS();
  ReportData& data = result.data;
  data = reportDataFor(c, run, trace.settings.seed);
  data.run.coefficientsTimeS = result.coefficientsS;
  data.run.productTimeS = result.productS;
  describeAnnualSettings(data, c, in, t, trace, y.occupiedCount);
  data.run.settings.emplace_back("ranks", run.request.processes().describe());
  data.warnings = warnings;
  annualGridReports(data, c, in, t, y);
  data.run.runTimeS = secondsSince(run.start);
  // 4. Write: the folder is committed as a whole.
  commitRun(c, run, [&](const std::filesystem::path& dir) {
    writeAnnualGrids(dir, data, in, t, y);
    writeSummaryCsv(dir, data);
    writeSummaryJson(dir, data);
    writeHtmlReport(dir / "report.html", data);
  });
  return result;
}

}  // namespace candela
