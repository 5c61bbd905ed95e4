#include "cli/run_annual.h"

#include "cli/progress.h"
#include "cli/run_grids.h"
#include "base/atomic_file.h"
#include "base/error.h"
#include "study/case_scene.h"
#include "engine/daylight_coefficients.h"
#include "engine/fresnel.h"
#include "metrics/annual.h"
#include "metrics/grid_stats.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "reports/annual_results.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <thread>

namespace candela::cli {

namespace {

namespace fs = std::filesystem;

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// LM-83-12 2.2.7's closed state when nothing better is known: white blinds as a diffusing layer
// of 20 % visible transmittance. Every glass pane becomes a Lambertian transmitter of 20 % of the
// glass's own normal transmittance (no beam passes); its reflection is not modelled
// (docs/annual.md). Returns the number of materials changed.
constexpr double kBlindsTransmittance = 0.2;

int closeBlinds(Scene& scene) {
  int changed = 0;
  for (Material& m : scene.materials) {
    if (m.type != MaterialType::kGlass) continue;
    Rgb t, reflected;
    thinGlass(m.color, m.refractiveIndex, 1.0, t, reflected);  // the glass's normal transmittance
    m.type = MaterialType::kTrans;
    m.diffuseReflectance = Rgb(0.0);
    m.specularReflectance = Rgb(0.0);
    m.specularTransmittance = Rgb(0.0);
    m.diffuseTransmittance = kBlindsTransmittance * t;
    ++changed;
  }
  return changed;
}

// A year at the sensors for one state of the scene.
struct YearRun {
  AnnualIlluminance year;
  double coefficientsS = 0.0;
  uint64_t rays = 0;  // rays cast for the coefficients
};

YearRun traceYear(const Scene& scene, const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                  const AnnualSky& sky, const SunSet& sunSet, double northDeg, const TraceSettings& settings,
                  int sunSamples, bool beamSun, int threads, bool quiet, const std::string& label) {
  const auto t0 = std::chrono::steady_clock::now();
  const Tracer tracer(scene);
  const SkyPatches patches(sky.subdivision);
  DaylightCoefficients dc;
  {
    ProgressBar bar(label + "sky coefficients", positions.size(), ProgressBar::wanted(quiet));
    dc = computeDaylightCoefficients(tracer, positions, normals, patches, settings, threads,
                                     [&bar](size_t d) { bar.update(d); });
    bar.finish();
  }
  const std::vector<Vec3> suns = sunDirectionsModel(sky, northDeg);
  std::vector<float> direct(positions.size() * suns.size(), 0.0f);
  if (beamSun) direct = directSunCoefficients(tracer, positions, normals, suns, sunSamples, settings.seed, threads);
  std::vector<Vec3> setModel;
  for (const Vec3& d : sunSet.dirsTrue) setModel.push_back(trueToModel(d, northDeg));
  // The interreflected sun needs fewer paths than the sky (each carries every sun of the set).
  TraceSettings sunSettings = settings;
  sunSettings.hemisphereSamples = std::max(64, settings.hemisphereSamples / 8);
  sunSettings.firstBounceSplit = std::max(1, settings.firstBounceSplit / 4);
  std::vector<float> inter;
  {
    ProgressBar bar(label + "sun coefficients", positions.size(), ProgressBar::wanted(quiet));
    inter = indirectSunCoefficients(tracer, positions, normals, setModel, sunSettings, threads,
                                    [&bar](size_t d) { bar.update(d); });
    bar.finish();
  }
  YearRun r;
  r.coefficientsS = secondsSince(t0);
  r.rays = tracer.raysTraced();
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

}  // namespace

int runAnnualCase(const CaseFile& c, const AnnualRunOptions& o) {
  // 1. Input: weather, site, scene, grids — every error before any tracing.
  const EpwFile epw = readEpw(c.sky.weather.string());
  if (!epw.isFullYear())
    throw InputError(FileLoc{c.sky.weather.string(), epw.records.empty() ? 8 : epw.records.back().line, 0},
                     "the file ends after " + std::to_string(epw.records.size()) +
                         " hourly records; an annual study needs a full year (8760 or 8784)");
  const Site site = caseSite(c, &epw.location);
  const double north = site.trueNorthDeg();
  const AnnualSpec& a = c.annual;
  AnnualSkyOptions skyOptions;
  skyOptions.subdivision = a.skySubdivision;
  skyOptions.groundReflectance = c.sky.groundReflectance;
  std::unique_ptr<Scene> scene = loadAnnualScene(c, north);
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  for (const GridSpec& g : c.grids)
    if (g.daylightFactor)
      throw InputError(g.loc, "grid '" + g.name + "': daylight_factor needs [sky] type = \"cie-overcast\", not an annual sky");
  std::vector<Vec3> positions, normals;
  for (const PreparedGrid& g : grids)
    for (const SensorPoint& p : g.grid.points) {
      positions.push_back(p.position);
      normals.push_back(p.normal);
    }
  if (a.reportSensor)
    for (const PreparedGrid& g : grids)
      if (*a.reportSensor >= static_cast<int>(g.grid.size()))
        throw InputError(a.reportSensorLoc, "report_sensor " + std::to_string(*a.reportSensor) + " is beyond grid '" +
                                    g.spec->name + "' (" + std::to_string(g.grid.size()) + " points)");
  const ResolvedTrace resolved = resolveTrace(c, o.trace, Method::kPath);
  TraceSettings settings = resolved.settings;
  settings.method = Method::kPath;  // coefficients are path traced (Tracer::skyCoefficients)
  const int threads = resolved.threads;

  // 2. Sky vectors of the year, then coefficients.
  const auto tSky = std::chrono::steady_clock::now();
  const AnnualSky sky = makeAnnualSky(epw, site, skyOptions);
  const double skyVectorsS = secondsSince(tSky);
  scene->sky->model = yearSamplingGuide(sky);
  const SunSet sunSet = indirectSunSet(sky);
  YearRun open = traceYear(*scene, positions, normals, sky, sunSet, north, settings, a.sunSamples, true, threads,
                           o.quiet, "");
  std::optional<YearRun> closed;
  int blindMaterials = 0;
  if (a.blinds) {
    std::unique_ptr<Scene> shaded = loadAnnualScene(c, north);
    shaded->sky->model = scene->sky->model;
    blindMaterials = closeBlinds(*shaded);
    if (blindMaterials > 0)
      closed = traceYear(*shaded, positions, normals, sky, sunSet, north, settings, a.sunSamples, false, threads,
                         o.quiet, "blinds closed: ");
  }
  const double coefficientsS = open.coefficientsS + (closed ? closed->coefficientsS : 0.0);
  const double productS = open.year.productTimeS + (closed ? closed->year.productTimeS : 0.0);

  // 3. Metrics per grid.
  const int nh = open.year.hours;
  std::vector<int> hourEnding;
  std::vector<HourStamp> stamps;
  for (const AnnualHour& h : sky.hours) {
    hourEnding.push_back(h.hour);
    stamps.push_back({static_cast<uint8_t>(h.month), static_cast<uint8_t>(h.day), static_cast<uint8_t>(h.hour)});
  }
  const std::vector<char> occupied = occupiedHours(hourEnding, a.occupancyStartHour, a.occupancyEndHour);
  const int occupiedCount = countHours(occupied);
  AnnualThresholds th;
  th.daLux = a.daThresholdLux;
  th.udiLowLux = a.udiLowLux;
  th.udiHighLux = a.udiHighLux;
  th.sdaFraction = a.sdaFraction;
  th.aseLux = a.aseThresholdLux;
  th.aseHours = a.aseHours;
  th.occupancyStartHour = a.occupancyStartHour;
  th.occupancyEndHour = a.occupancyEndHour;

  ReportData data;
  data.run.caseName = c.name;
  data.run.description = c.description;
  data.run.caseFile = c.path.string();
  data.run.version = CANDELA_VERSION;
  data.run.startedAt = o.startedAt;
  data.run.seed = settings.seed;
  data.northDeg = c.site.northDeg;
  data.run.coefficientsTimeS = coefficientsS;
  data.run.productTimeS = productS;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s (%s, %.2f°, %.2f°), %zu hours", epw.location.city.c_str(),
                c.sky.weather.filename().string().c_str(), site.latitudeDeg, site.longitudeDeg, sky.hours.size());
  const unsigned usedThreads = threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());
  data.run.settings = {
      {"quality", qualityName(resolved.quality)},
      {"sky", "annual: Perez all-weather sky per hour of the weather file"},
      {"weather", buf},
      {"sky patches", a.skySubdivision == 1 ? "Tregenza, 145 + ground"
                                             : "Reinhart MF:" + std::to_string(a.skySubdivision) + ", " +
                                                   std::to_string(SkyPatches(a.skySubdivision).skyPatchCount()) + " + ground"},
      {"direct sun", "actual position every hour, " + std::to_string(a.sunSamples) + " rays over the disc"},
      {"interreflected sun", std::to_string(sunSet.dirsTrue.size()) + " sun positions (Reinhart MF:2 patches)"},
      {"hemisphere samples per point", std::to_string(settings.hemisphereSamples)},
      {"sky samples per patch", std::to_string(settings.lightSamples)},
      {"occupancy", formatFixed(a.occupancyStartHour, 2) + "–" + formatFixed(a.occupancyEndHour, 2) + " h (" +
                        std::to_string(occupiedCount) + " h a year)"},
      {"blinds (LM-83)", !a.blinds ? "not modelled"
                         : blindMaterials == 0 ? "no glass in the scene"
                                               : "closed when > 2 % of a grid's sensors get ≥ 1000 lx of direct sun: "
                                                 "glass as a 20 % diffuse transmitter"},
      {"threads", threads > 0 ? std::to_string(threads) : "all (" + std::to_string(usedThreads) + ")"},
      {"calculation points", std::to_string(positions.size())},
      {"sky vectors time", formatFixed(skyVectorsS, 2) + " s"},
      {"rays for the coefficients", formatFixed((open.rays + (closed ? closed->rays : 0)) / 1e6, 1) + " M (" +
                                        formatFixed((open.rays + (closed ? closed->rays : 0)) / 1e6 / coefficientsS, 2) +
                                        " M rays/s)"},
  };

  std::vector<std::vector<ReportPoint>> csvPoints(grids.size());
  size_t first = 0;
  for (size_t gi = 0; gi < grids.size(); ++gi) {
    const PreparedGrid& g = grids[gi];
    const int n = static_cast<int>(g.grid.size());
    const float* total = open.year.total.data() + first * nh;
    const float* direct = open.year.directSun.data() + first * nh;
    std::vector<char> blindsClosed;
    const float* shaded = nullptr;
    if (closed) {
      blindsClosed = blindsClosedHours(direct, n, nh, occupied, th.aseLux);
      shaded = closed->year.total.data() + first * nh;
    }
    const std::vector<SensorAnnualMetrics> m =
        sensorAnnualMetrics(total, direct, n, nh, occupied, th, shaded, closed ? &blindsClosed : nullptr);
    const GridAnnualSummary sum = summarizeAnnual(m, occupiedCount);
    AnnualGridReport ar;
    ar.sensors = m;
    ar.summary = sum;
    ar.chosenSensor = a.reportSensor ? *a.reportSensor : centralSensor(g.grid);
    for (int h = 0; h < nh; ++h) ar.chosenSensorLux.push_back(total[static_cast<size_t>(ar.chosenSensor) * nh + h]);
    ar.hours = stamps;
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
    for (const SensorPoint& s : g.grid.points) csvPoints[gi].push_back({s.position, s.normal});
    first += g.grid.size();
  }
  data.run.runTimeS = secondsSince(o.start);

  // 4. Write, each file through a temporary and a rename.
  const fs::path outDir = o.outDir;
  writeRunOutputs(outDir, [&] {
    first = 0;
    for (size_t gi = 0; gi < grids.size(); ++gi) {
      const int n = static_cast<int>(grids[gi].grid.size());
      writeAnnualGridCsv(outDir, grids[gi].spec->name, csvPoints[gi], *data.grids[gi].annual);
      AnnualResults res;
      res.sensors = n;
      res.hours = stamps;
      res.lux.assign(open.year.total.begin() + first * nh, open.year.total.begin() + (first + n) * nh);
      writeAnnualResults(outDir / annualResultsFileName(grids[gi].spec->name), res);
      res.lux.assign(open.year.directSun.begin() + first * nh, open.year.directSun.begin() + (first + n) * nh);
      writeAnnualResults(outDir / annualResultsFileName(grids[gi].spec->name + "_direct_sun"), res);
      first += n;
    }
    writeSummaryCsv(outDir, data);
    writeSummaryJson(outDir, data);
    writeHtmlReport(outDir / "report.html", data);
  });

  if (!o.quiet) {
    std::ostringstream s;
    for (const GridReport& r : data.grids) {
      const GridAnnualSummary& m = r.annual->summary;
      std::snprintf(buf, sizeof buf,
                    "%-20s %6d points  DA300 %5.1f %%  cDA300 %5.1f %%  UDI_autonomous %5.1f %%  sDA300_50 %5.1f %%  "
                    "ASE1000_250 %5.1f %%\n",
                    r.name.c_str(), m.sensors, m.DA300, m.cDA300, m.UDI_autonomous, m.sDA300_50, m.ASE1000_250);
      s << buf;
    }
    s << "coefficients " << formatFixed(coefficientsS, 1) << " s, " << nh << "-hour product "
      << formatFixed(productS, 2) << " s, run time " << formatFixed(data.run.runTimeS, 1) << " s; results in "
      << outDir.string() << "\n";
    std::cout << s.str() << std::flush;
  }
  return 0;
}

}  // namespace candela::cli
