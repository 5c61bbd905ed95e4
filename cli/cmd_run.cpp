// candela run CASE.toml [--out DIR]: the main job. Reads and checks everything first (case,
// scene files, luminaires, grids), traces every grid's points with one tracer, computes the
// metrics and target verdicts, and only then writes <grid>.csv, summary.csv, summary.json and
// report.html, each file atomically. A run that fails on bad input writes nothing.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/view_glare.h"
#include "engine/render.h"
#include "reports/png_writer.h"
#include "reports/tonemap.h"
#include "cli/progress.h"
#include "cli/run_annual.h"
#include "cli/run_grids.h"

#include "base/atomic_file.h"
#include "base/error.h"
#include "study/case_file.h"
#include "study/case_scene.h"
#include "study/sensor_grid.h"
#include "engine/sensors.h"
#include "metrics/grid_stats.h"
#include "metrics/targets.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"
#include "reports/report_data.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace candela::cli {

namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::string caseFile;
  std::string outDir;    // empty: the case's [output] dir
  CaseTraceOptions trace;
  bool quiet = false;
};

std::string fixed(double v, int decimals) { return formatFixed(v, decimals); }

// summary.json as the reports writer makes it, plus what only the run knows per grid: the
// actual spacing (m) and the number of lattice columns and rows.
std::string summaryJsonWithSpacing(const ReportData& data, const std::vector<PreparedGrid>& grids) {
  nlohmann::json j = nlohmann::json::parse(summaryJson(data));
  for (std::size_t i = 0; i < grids.size(); ++i) {
    nlohmann::json& g = j["grids"][i];
    const SensorGrid& s = grids[i].grid;
    g["file"] = grids[i].fileStem + ".csv";
    if (s.regular) {
      g["spacing_m"] = {s.spacingM.x, s.spacingM.y};
      g["columns"] = s.columns;
      g["rows"] = s.rows;
    } else {
      g["spacing_m"] = nullptr;
    }
  }
  return j.dump(2) + "\n";
}

int runCase(const RunOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const std::string startedAt = localTimeNow();

  // 1. Everything that can be wrong with the input is found here, before any tracing.
  const CaseFile c = readCaseFile(o.caseFile);
  if (c.grids.empty()) throw InputError(FileLoc{c.path.string(), 0, 0}, "the case has no [[grid]] to calculate");

  const fs::path outDir = o.outDir.empty() ? c.output.dir : fs::path(o.outDir);
  if (fs::exists(outDir) && !fs::is_directory(outDir))
    throw InputError(FileLoc{outDir.string(), 0, 0}, "output path exists and is not a folder");

  if (c.sky.type == SkyType::kAnnual) {
    AnnualRunOptions ao;
    ao.outDir = outDir;
    ao.trace = o.trace;
    ao.quiet = o.quiet;
    ao.start = start;
    ao.startedAt = startedAt;
    return runAnnualCase(c, ao);
  }

  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  // Daylight factor grids need the CIE overcast sky: DF = 100 E / E_h,outside (percent).
  for (const GridSpec& spec : c.grids)
    if (spec.daylightFactor && !(scene->sky && c.sky.type == SkyType::kCieOvercast))
      throw InputError(spec.loc, "grid '" + spec.name +
                                     "': daylight_factor needs [sky] type = \"cie-overcast\" (DF is defined under it)");

  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  std::size_t totalPoints = 0;
  for (const PreparedGrid& g : grids) totalPoints += g.grid.size();

  // 2. Settings: the case's, then the command line's.
  const ResolvedTrace resolved = resolveTrace(c, o.trace, Method::kCache);
  const Quality quality = resolved.quality;
  const TraceSettings settings = resolved.settings;
  const int threads = resolved.threads;
  const unsigned usedThreads = threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());

  // Notes, after validation so that a bad case prints its one error line only.
  if (!o.quiet) {
  }

  // 3. Trace all grids as one list (grids in case order): point k of the run uses random
  // stream k, so the numbers depend on the seed only, never on threads.
  std::vector<SensorPoint> all;
  all.reserve(totalPoints);
  for (const PreparedGrid& g : grids) all.insert(all.end(), g.grid.points.begin(), g.grid.points.end());
  const Tracer tracer(*scene);
  std::vector<IrradianceEstimate> est;
  {
    ProgressBar bar("tracing", all.size(), ProgressBar::wanted(o.quiet));
    est = computeIrradiance(tracer, all, settings, threads, [&bar](std::size_t done) { bar.update(done); });
    bar.finish();
  }

  // 4. Metrics and verdicts.
  ReportData data;
  data.run.caseName = c.name;
  data.run.description = c.description;
  data.run.caseFile = c.path.string();
  data.run.version = CANDELA_VERSION;
  data.run.startedAt = startedAt;
  data.run.seed = settings.seed;
  data.northDeg = c.site.northDeg;
  data.run.settings = {
      {"quality", qualityName(quality)},
      {"method", settings.method == Method::kCache ? "cache (Ward's irradiance cache, path-traced closure)"
                                                   : "path (Monte Carlo path tracing)"},
      {"diffuse bounces", std::to_string(settings.maxBounces)},
      {"hemisphere samples per point", std::to_string(settings.hemisphereSamples)},
      {"light samples per source", std::to_string(settings.lightSamples)},
      {"first-bounce split", std::to_string(settings.firstBounceSplit)},
      {"threads", threads > 0 ? std::to_string(threads) : "all (" + std::to_string(usedThreads) + ")"},
      {"luminaires", std::to_string(c.luminaires.size())},
      {"calculation points", std::to_string(totalPoints)},
  };
  if (scene->sky) {
    const SkyDome& sky = *scene->sky;
    char buf[160];
    data.run.settings.emplace_back("sky", skyTypeName(c.sky.type, c.sky.cieType));
    std::snprintf(buf, sizeof buf, "altitude %.2f deg, azimuth %.2f deg", sky.sunAltitudeDeg, sky.sunAzimuthDeg);
    data.run.settings.emplace_back("sun position", buf);
    std::snprintf(buf, sizeof buf, "%.0f lx (sky %.0f lx, sun %.0f lx)", sky.outsideHorizontalLux(),
                  sky.horizontalSkyLux, sky.horizontalSunLux);
    data.run.settings.emplace_back("outside horizontal illuminance", buf);
    std::snprintf(buf, sizeof buf, "%.2f", c.sky.groundReflectance);
    data.run.settings.emplace_back("ground reflectance", buf);
  }
  if (!c.views.empty()) data.run.settings.emplace_back("views", std::to_string(c.views.size()));

  std::vector<std::vector<ReportPoint>> csvPoints(grids.size());
  std::vector<std::vector<double>> errors(grids.size());
  std::vector<std::vector<double>> luxValues(grids.size());
  std::size_t k = 0;
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const PreparedGrid& g = grids[gi];
    GridReport r;
    r.name = g.spec->name;
    r.description = gridDescription(g);
    const bool df = g.spec->daylightFactor;
    const double outside = scene->sky ? scene->sky->outsideHorizontalLux() : 0.0;
    for (const SensorPoint& s : g.grid.points) {
      csvPoints[gi].push_back({s.position, s.normal});
      luxValues[gi].push_back(est[k].illuminanceLux());
      errors[gi].push_back(est[k].standardErrorLux());
      r.values.push_back(df ? 100.0 * est[k].illuminanceLux() / outside : est[k].illuminanceLux());
      ++k;
    }
    if (df) {
      r.quantity = "Daylight factor";
      r.unit = "%";
    }
    r.stats = computeGridStats(r.values);
    r.targets = {g.spec->targetAverageLux, g.spec->targetUniformity};
    r.check = checkTargets(r.stats, r.targets);
    r.layout = planLayout(g);
    data.grids.push_back(std::move(r));
  }
  // 4b. Views: luminance images and visual metrics (docs/views.md), computed before anything is
  // written like the grids.
  struct RenderedView {
    std::string stem;
    Image img;
    std::vector<Rgb> rgbCdM2;
    ColorScale scale;
  };
  std::vector<RenderedView> rendered;
  for (const ViewSpec& view : c.views) {
    RenderSettings rs;
    // Matte surfaces seen take a stratified irradiance estimate (64 samples): plain camera paths
    // leave salt-and-pepper noise at the few rays per pixel a report can afford (docs/views.md).
    rs.irradianceSamples = 64;
    RenderedView rv;
    {
      ProgressBar bar("rendering " + view.name, static_cast<std::size_t>(view.resolution.x) * view.resolution.y,
                      ProgressBar::wanted(o.quiet));
      rv.img = renderView(tracer, view, settings, threads, rs, [&bar](std::size_t done, std::size_t) { bar.update(done); });
      bar.finish();
    }
    const cli::ViewGlare glare = cli::computeViewGlare(tracer, view, settings, rv.img, 0.0);
    rv.rgbCdM2.resize(rv.img.radiance.size());
    for (std::size_t i = 0; i < rv.rgbCdM2.size(); ++i) rv.rgbCdM2[i] = kLumensPerWatt * rv.img.radiance[i];
    rv.scale = luminanceScale(rv.img.luminance, true);
    rv.stem = safeFileName(view.name);
    ViewReport vr;
    vr.name = view.name;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s, %d × %d px, from (%.2f, %.2f, %.2f) m; files %s.exr, %s.png",
                  view.type == ViewType::kFisheye ? "fisheye 180°" : "perspective", rv.img.width, rv.img.height,
                  view.positionM.x, view.positionM.y, view.positionM.z, rv.stem.c_str(), rv.stem.c_str());
    vr.description = buf;
    vr.falseColorPng = encodePng(luminanceFalseColor(rv.img.width, rv.img.height, rv.img.luminance, rv.scale));
    vr.previewPng = encodePng(toneMap(rv.img.width, rv.img.height, rv.img.luminance, rv.rgbCdM2, rv.img.inside));
    vr.metrics.emplace_back("Vertical illuminance at the eye", fixed(glare.verticalLux, 1) + " lx");
    vr.metrics.emplace_back("UGR (CIE 117)", glare.sources.empty() ? "no luminaire in view"
                                                                   : fixed(glare.ugr, 1) + " (" +
                                                                         std::to_string(glare.sources.size()) +
                                                                         " luminaires)");
    if (glare.dgp) vr.metrics.emplace_back("DGP (Wienold & Christoffersen 2006)", fixed(glare.dgp->dgp, 3));
    if (view.taskM && view.backgroundM) {
      const cli::ViewContrast vc = cli::computeViewContrast(*scene, tracer, view.positionM, *view.taskM,
                                                            *view.backgroundM, settings, view.loc);
      vr.metrics.emplace_back("Task / background luminance",
                              fixed(vc.taskCdM2, 2) + " / " + fixed(vc.backgroundCdM2, 2) + " cd/m²");
      vr.metrics.emplace_back("Contrast C = (Lt − Lb)/Lb", fixed(vc.contrast, 3));
      vr.metrics.emplace_back("Contrast rendition factor CRF", fixed(vc.crf(), 3));
    }
    data.views.push_back(std::move(vr));
    rendered.push_back(std::move(rv));
  }
  data.run.runTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // 5. Write. Each file goes through a temporary and a rename.
  writeRunOutputs(outDir, [&] {
    for (std::size_t gi = 0; gi < grids.size(); ++gi)
      if (grids[gi].spec->daylightFactor)
        writeGridCsv(outDir, grids[gi].spec->name, csvPoints[gi], luxValues[gi],
                     {{"error_lux", errors[gi]}, {"daylight_factor_pct", data.grids[gi].values}});
      else
        writeGridCsv(outDir, grids[gi].spec->name, csvPoints[gi], luxValues[gi], {{"error_lux", errors[gi]}});
    for (const RenderedView& rv : rendered)
      writeViewImages(outDir, rv.stem, rv.img.width, rv.img.height, rv.img.luminance, rv.rgbCdM2, rv.img.inside,
                      rv.scale, "candela " + std::string(CANDELA_VERSION) + ", case " + c.name);
    writeSummaryCsv(outDir, data);
    writeFileAtomic(outDir / "summary.json", summaryJsonWithSpacing(data, grids));
    writeHtmlReport(outDir / "report.html", data);
  });

  if (!o.quiet) {
    std::ostringstream s;
    for (const GridReport& r : data.grids) {
      char buf[256];
      if (r.unit == "%")
        std::snprintf(buf, sizeof buf, "%-20s %6zu points  DFavg %5.2f %%  DFmin %5.2f %%  DFmedian %5.2f %%  %s\n",
                      r.name.c_str(), r.stats.count, r.stats.averageLux, r.stats.minimumLux, r.stats.medianLux,
                      verdictName(r.check.overall));
      else
        std::snprintf(buf, sizeof buf, "%-20s %6zu points  Eavg %7.1f lx  Emin %7.1f lx  U0 %.2f  %s\n",
                      r.name.c_str(), r.stats.count, r.stats.averageLux, r.stats.minimumLux, r.stats.u0,
                      verdictName(r.check.overall));
      s << buf;
    }
    s << "run time " << fixed(data.run.runTimeS, 1) << " s; results in " << outDir.string() << "\n";
    std::cout << s.str() << std::flush;
  }
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "calculate a case: grids, metrics, CSV/JSON summaries and an HTML report");
  cmd->add_option("case", opts->caseFile, "case file (TOML, docs/case-format.md)")->required();
  cmd->add_option("--out", opts->outDir, "results folder (default: the case's [output] dir)");
  addCaseTraceOptions(cmd, opts->trace, "hemisphere samples per point");
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress bar, notes or result lines (errors only)");
  cmd->callback([opts, &action] { action = [opts] { return runCase(*opts); }; });
}

}  // namespace candela::cli
