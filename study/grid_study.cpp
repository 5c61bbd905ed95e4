#include "study/grid_study.h"

#include "base/atomic_file.h"
#include "base/error.h"
#include "engine/radiance/sky.h"
#include "engine/sensors.h"
#include "metrics/grid_stats.h"
#include "metrics/modelling.h"
#include "metrics/targets.h"
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"
#include "study/case/case_scene.h"
#include "study/compliance/en13201.h"
#include "study/compliance/en12464_2.h"
#include "study/compliance/en1838.h"
#include "study/finite_results.h"
#include "study/grids/grid_quantity.h"
#include "study/luminaire_schedule.h"
#include "study/grids/plan_section.h"
#include "study/grids/prepared_grid.h"
#include "study/resource_estimate.h"
#include "study/run_outputs.h"
#include "study/grids/surface_grids.h"
#include "study/task_area_report.h"
#include "study/view_glare.h"
#include "study/view_study.h"
#include "study/warnings.h"
#include "engine/irradiance_estimator.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <optional>

namespace candela {

namespace {

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

// The settings table of the report, in the order a reader scans it.
void describeSettings(ReportData& data, const CaseFile& c, const Scene& scene, const ResolvedTrace& trace,
                      std::size_t points) {
  const TraceSettings& s = trace.settings;
  data.run.settings = {
      {"quality", qualityName(trace.quality)},
      {"method", s.method == Method::kCache ? "cache (Ward's irradiance cache, path-traced closure)"
                                            : "path (Monte Carlo path tracing)"},
      {"diffuse bounces", std::to_string(s.maxBounces)},
      {"hemisphere samples per point", std::to_string(s.hemisphereSamples)},
      {"light samples per source", std::to_string(s.lightSamples)},
      {"first-bounce split", std::to_string(s.firstBounceSplit)},
      {s.gridTargetRelativeError > 0.0 ? "grid target error" : "per-point target error",
       s.gridTargetRelativeError > 0.0
           ? formatFixed(100.0 * s.gridTargetRelativeError, 3) +
                 " % of the larger of the point's value and its grid's mean (at most " +
                 std::to_string(s.maxBatches) + " batches; docs/estimator.md)"
       : s.targetRelativeError > 0.0
           ? formatFixed(100.0 * s.targetRelativeError, 3) + " % (at most " + std::to_string(s.maxBatches) +
                 " batches)"
           : "none (one batch)"},
      {"threads", trace.threads > 0 ? std::to_string(trace.threads)
                                    : "all (" + std::to_string(threadsUsed(trace.threads)) + ")"},
      {"luminaires", std::to_string(c.luminaires.size())},
      {"calculation points", std::to_string(points)},
  };
  if (scene.sky) {
    const SkyDome& sky = *scene.sky;
    char buf[160];
    // A sky from the scene's own files (gensky, gendaylit) names itself ("scene:gensky ...").
    data.run.settings.emplace_back("sky", sky.fromScene ? sky.model->name() : skyTypeName(c.sky.type));
    // An overcast or uniform sky does not depend on the sun: no sun position to state (a sky from
    // the scene's files may, as far as candela knows).
    if (sky.fromScene || c.sky.type.dependsOnSun()) {
      std::snprintf(buf, sizeof buf, "altitude %.2f deg, azimuth %.2f deg", sky.sunAltitudeDeg, sky.sunAzimuthDeg);
      data.run.settings.emplace_back("sun position", buf);
    }
    std::snprintf(buf, sizeof buf, "%.0f lx (sky %.0f lx, sun %.0f lx)", sky.outsideHorizontalLux(),
                  sky.horizontalSkyLux, sky.horizontalSunLux);
    data.run.settings.emplace_back("outside horizontal illuminance", buf);
    if (sky.fromScene) {
      std::snprintf(buf, sizeof buf, "%.1f cd/m2 (the scene's ground glow)", sky.groundLuminanceCdM2);
      data.run.settings.emplace_back("ground luminance", buf);
    } else {
      std::snprintf(buf, sizeof buf, "%.2f", c.sky.groundReflectance);
      data.run.settings.emplace_back("ground reflectance", buf);
    }
  }
  if (!c.views.empty()) data.run.settings.emplace_back("views", std::to_string(c.views.size()));
}

// A grid's values as the run keeps them: its points' illuminance and standard error (lux),
// 16 B a point; everything else of an estimate goes to the grid's CSV as it comes (below).
// A modelling grid keeps its cylindrical and horizontal values too (the grid's own when its
// quantity is one of them).
struct GridValues {
  std::vector<double> lux, errorLux;
  std::vector<double> cylindricalLux, cylindricalErrorLux, horizontalLux, horizontalErrorLux;
};

// Whether every sensor of the grid already measures q (study/grids/prepared_grid.h).
bool measures(const PreparedGrid& g, GridQuantity q) { return gridMeasures(g, q); }

// A run of consecutive points of the traced list: grid `grid`'s own points, or the sensors of
// one of its modelling quantities at its positions.
struct Segment {
  std::size_t grid = 0, count = 0;
  std::vector<double>*lux = nullptr, *errorLux = nullptr;
};

// The traced list: every grid's own points in case order (point k uses random stream k, as
// before modelling existed), then the modelling grids' cylindrical and horizontal sensors that
// their own points are not. Fills `segments` in the same order.
std::vector<SensorPoint> tracedPoints(const std::vector<PreparedGrid>& grids, std::vector<GridValues>& values,
                                      std::vector<Segment>& segments) {
  std::vector<SensorPoint> all;
  std::size_t total = 0;
  for (const PreparedGrid& g : grids)
    total += g.grid.size() * (g.spec->modelling ? 1 + !measures(g, GridQuantity::kCylindrical) +
                                                      !measures(g, GridQuantity::kHorizontal)
                                                : 1);
  all.reserve(total);  // one allocation: growing would copy every point held so far
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const PreparedGrid& g = grids[gi];
    all.insert(all.end(), g.grid.points.begin(), g.grid.points.end());
    segments.push_back({gi, g.grid.size(), &values[gi].lux, &values[gi].errorLux});
  }
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const PreparedGrid& g = grids[gi];
    if (!g.spec->modelling) continue;
    GridValues& v = values[gi];
    for (GridQuantity q : {GridQuantity::kCylindrical, GridQuantity::kHorizontal}) {
      if (measures(g, q)) continue;  // copied from the grid's own values after tracing
      for (const SensorPoint& p : g.grid.points) all.push_back(quantitySensor(q, p.position));
      const bool cyl = q == GridQuantity::kCylindrical;
      segments.push_back({gi, g.grid.size(), cyl ? &v.cylindricalLux : &v.horizontalLux,
                          cyl ? &v.cylindricalErrorLux : &v.horizontalErrorLux});
    }
  }
  return all;
}

// The grids' reports (metrics and verdicts) from the values of all points, grids in case order;
// daylight-factor grids in % of the outside horizontal illuminance.
void gridReports(ReportData& data, const std::vector<PreparedGrid>& grids, const std::vector<GridValues>& values,
                 double outsideLux) {
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const PreparedGrid& g = grids[gi];
    GridReport r;
    r.name = g.spec->name;
    r.description = gridDescription(g);
    r.planIsXY = g.spec->kind == GridKind::kPoints || inPlanCoordinates(g.spec->plane);
    if (g.spec->quantity) {
      r.quantity = gridQuantityName(*g.spec->quantity);
      r.quantityKey = gridQuantityKey(*g.spec->quantity);
    }
    if (g.spec->daylightFactor) {
      r.quantity = "Daylight factor";
      r.unit = "%";
      r.values.reserve(values[gi].lux.size());
      for (double e : values[gi].lux) r.values.push_back(100.0 * e / outsideLux);
    } else {
      r.values = values[gi].lux;
    }
    if (g.spec->modelling) r.modelling = modellingRatio(values[gi].cylindricalLux, values[gi].horizontalLux);
    r.stats = computeGridStats(r.values);
    r.targets = {g.spec->targetAverageLux, g.spec->targetUniformity};
    r.check = checkTargets(r.stats, r.targets);
    r.layout = planLayout(g);
    data.grids.push_back(std::move(r));
  }
}

// The grids' CSVs written as the estimates come, a block at a time, each into an unnamed
// temporary beside the result folder (base/atomic_file.h) that goes into the folder when it is
// committed: illuminance_lux (or the quantity's column, e.g. cylindrical_illuminance_lux),
// error_lux and, for daylight-factor grids, daylight_factor_pct; modelling grids add their
// cylindrical and horizontal values and the point's ratio, written once all are traced.
class GridCsvFiles {
  // Whether the grid's first column is quantity q's (its `quantity` key says so).
  static bool measures(const PreparedGrid& g, GridQuantity q) { return g.spec->quantity && *g.spec->quantity == q; }

 public:
  GridCsvFiles(const std::filesystem::path& beside, const std::vector<PreparedGrid>& grids, double outsideLux)
      : grids_(grids), outsideLux_(outsideLux) {
    std::filesystem::create_directories(beside);
    for (const PreparedGrid& g : grids) {
      auto file = std::make_unique<AtomicFile>(beside / (g.fileStem + ".csv"));
      std::vector<std::string> columns = {g.spec->quantity ? gridQuantityColumn(*g.spec->quantity) : "illuminance_lux",
                                          "error_lux"};
      if (g.spec->daylightFactor) columns.emplace_back("daylight_factor_pct");
      if (g.spec->modelling) {
        // The pair the grid's own quantity already gives is not repeated (estimatesPerPoint).
        if (!measures(g, GridQuantity::kCylindrical))
          columns.insert(columns.end(), {"cylindrical_illuminance_lux", "cylindrical_error_lux"});
        if (!measures(g, GridQuantity::kHorizontal))
          columns.insert(columns.end(), {"horizontal_illuminance_lux", "horizontal_error_lux"});
        columns.emplace_back("modelling_ratio");
      }
      AtomicFile* f = file.get();
      writers_.push_back(std::make_unique<PointsCsvWriter>([f](std::string_view piece) { f->write(piece); }, columns));
      files_.push_back(std::move(file));
    }
  }
  // Point k of grid gi as it comes; modelling grids wait for modellingRows.
  void row(std::size_t gi, std::size_t k, double lux, double errorLux) {
    if (grids_[gi].spec->modelling) return;
    const SensorPoint& p = grids_[gi].grid.points[k];
    const double v[3] = {lux, errorLux, 100.0 * lux / outsideLux_};
    writers_[gi]->row(p.position, p.normal, v);
  }
  // Every row of the modelling grids, from their values once all are traced.
  void modellingRows(const std::vector<GridValues>& values) {
    for (std::size_t gi = 0; gi < grids_.size(); ++gi) {
      if (!grids_[gi].spec->modelling) continue;
      const GridValues& g = values[gi];
      for (std::size_t k = 0; k < g.lux.size(); ++k) {
        std::vector<double> v = {g.lux[k], g.errorLux[k]};
        if (grids_[gi].spec->daylightFactor) v.push_back(100.0 * g.lux[k] / outsideLux_);
        if (!measures(grids_[gi], GridQuantity::kCylindrical))
          v.insert(v.end(), {g.cylindricalLux[k], g.cylindricalErrorLux[k]});
        if (!measures(grids_[gi], GridQuantity::kHorizontal))
          v.insert(v.end(), {g.horizontalLux[k], g.horizontalErrorLux[k]});
        v.push_back(pointModellingRatio(g.cylindricalLux[k], g.horizontalLux[k]));
        const SensorPoint& p = grids_[gi].grid.points[k];
        writers_[gi]->row(p.position, p.normal, v.data());
      }
    }
  }
  void commitInto(const std::filesystem::path& dir) {
    for (std::size_t gi = 0; gi < files_.size(); ++gi) {
      writers_[gi]->finish();
      files_[gi]->commitAs(dir / (grids_[gi].fileStem + ".csv"));
    }
  }

 private:
  const std::vector<PreparedGrid>& grids_;
  double outsideLux_;
  std::vector<std::unique_ptr<AtomicFile>> files_;
  std::vector<std::unique_ptr<PointsCsvWriter>> writers_;
};

}  // namespace

// From this many luminaires on, placing them costs seconds, so their memory is checked first.
constexpr std::size_t kLuminairesCheckedFirst = 10000;

RunResult runGridStudy(const CaseFile& asRead, const RunContext& run, StudyObserver& observer) {
  // 1. Everything that can be wrong with the input is found here, before any tracing. Large
  // luminaire arrays are checked before they are placed (placing 10⁶ takes about a minute); the
  // whole case's estimate follows once the scene is loaded.
  if (asRead.luminaires.size() >= kLuminairesCheckedFirst) {
    ResourceEstimate luminaires;
    addLuminaires(luminaires, asRead);
    checkResources(luminaires, run.request.limits, FileLoc{asRead.path.string(), 0, 0});
  }
  const std::unique_ptr<Scene> scene = loadCaseScene(asRead);
  // The walls' and ceilings' grids lie on the scene's surfaces: from here on they are grids of
  // the case like any other.
  const CaseFile c = withSurfaceGrids(asRead, *scene);
  // Daylight factor grids need the CIE overcast sky: DF = 100 E / E_h,outside (percent). The
  // case's, or the scene's own from `gensky -c` (skybright.cal's sky type 2).
  const auto* sceneSky = scene->sky && scene->sky->fromScene ? dynamic_cast<const RadianceSky*>(scene->sky->model.get())
                                                              : nullptr;
  const bool overcast = scene->sky && (sceneSky ? sceneSky->function().skyType() == 2
                                                : c.sky.type.kind == SkyKind::kCieOvercast);
  for (const GridSpec& spec : c.grids)
    if (spec.daylightFactor && !overcast)
      throw InputError(spec.loc, "grid '" + spec.name +
                                     "': daylight_factor needs [sky] type = \"cie-overcast\" (DF is defined under it), "
                                     "or a scene sky from gensky -c");
  const ResolvedTrace trace = resolveTrace(&c.settings, run.request.trace, Method::kCache);
  // The memory check comes before the grids are generated: a grid too large is refused without
  // being made.
  const std::vector<std::size_t> pointCounts = gridPointCounts(c);
  checkResources(estimateGridStudy(c, pointCounts, *scene, trace.settings, trace.threads), run.request.limits,
                 FileLoc{c.path.string(), 0, 0});
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  const ReferenceGrid reference = referenceGrid(c, grids);  // W/m²/100 lx over its Ē

  // 2. All grids as one list (grids in case order, then the modelling grids' other sensors):
  // point k of the run uses random stream k, so the numbers depend on the seed only, never on
  // threads.
  std::vector<GridValues> values(grids.size());
  std::vector<Segment> segments;
  std::vector<SensorPoint> all = tracedPoints(grids, values, segments);
  std::size_t gridPoints = 0;
  for (const PreparedGrid& g : grids) gridPoints += g.grid.size();
  const Tracer tracer(*scene);
  // The time estimate, with the share of the points' hemisphere rays that meet the scene (an open
  // site's leave it: study/resource_estimate.h).
  observer.estimated(estimateGridStudy(c, pointCounts, *scene, trace.settings, trace.threads,
                                       hemispherePilot(tracer, all, &trace.settings, trace.threads)));
  // Warnings on the input, before tracing: a strict run stops here.
  Warnings warnings = pointInTimeWarnings(c, tracer, grids);
  if (std::optional<Warning> w = noEmergencyLuminaireWarning(c)) warnings.push_back(*w);
  const std::vector<SensorSet> sets = sensorSets(grids);
  throwIfStrict(warnings, run.request.strict);
  // The points are estimated a block at a time (engine/sensors.h): each block's values are kept
  // (16 B a point) and its CSV rows written at once, so the estimates of a 10⁶-point grid are
  // never all in memory.
  const double outsideLux = scene->sky ? scene->sky->outsideHorizontalLux() : 0.0;
  const Distribution& processes = run.request.processes();
  const std::filesystem::path beside =
      std::filesystem::absolute(run.outDir).parent_path();  // the result folder's file system
  std::optional<GridCsvFiles> csvFiles;
  if (processes.writesOutputs()) {
    try {
      csvFiles.emplace(beside, grids, outsideLux);
    } catch (const std::exception& e) {
      throw InputError(FileLoc{run.outDir.string(), 0, 0}, std::string("cannot write the results: ") + e.what());
    }
  }
  for (const Segment& seg : segments) {
    seg.lux->reserve(seg.count);
    seg.errorLux->reserve(seg.count);
  }
  std::size_t withoutCache = 0;
  // Each segment (a grid's points, a modelling grid's other sensors) is a group of the grids'
  // target: its mean sets its points' goal.
  std::vector<std::size_t> groupEnds;
  for (const Segment& seg : segments) groupEnds.push_back((groupEnds.empty() ? 0 : groupEnds.back()) + seg.count);
  {
    const ObservedStep step(observer, "tracing", all.size());
    std::size_t si = 0;  // the segment of the block's next point
    computeIrradianceInBlocks(
        tracer, all, trace.settings, trace.threads, [&step](std::size_t done) { step(done); }, processes,
        [&](std::size_t first, const IrradianceEstimate* est, std::size_t n) {
          checkFinite(est, n, "the grids' illuminance", first);
          for (std::size_t j = 0; j < n; ++j) {
            while (segments[si].lux->size() == segments[si].count) ++si;
            const Segment& seg = segments[si];
            const double lux = est[j].illuminanceLux(), err = est[j].standardErrorLux();
            if (csvFiles && si < grids.size()) csvFiles->row(seg.grid, seg.lux->size(), lux, err);
            seg.lux->push_back(lux);
            seg.errorLux->push_back(err);
            withoutCache += est[j].withoutCache;
          }
        },
        kSensorBlockPoints, groupEnds);
  }
  // A modelling grid whose own sensors are cylindrical or horizontal takes its values for them.
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    if (!grids[gi].spec->modelling) continue;
    GridValues& v = values[gi];
    if (measures(grids[gi], GridQuantity::kCylindrical)) v.cylindricalLux = v.lux, v.cylindricalErrorLux = v.errorLux;
    if (measures(grids[gi], GridQuantity::kHorizontal)) v.horizontalLux = v.lux, v.horizontalErrorLux = v.errorLux;
  }
  if (csvFiles) csvFiles->modellingRows(values);
  std::vector<SensorPoint>().swap(all);  // not needed again: the report's memory takes its place

  // Warnings on the results, before anything is written.
  // A shard's points of other shards read 0 ± 0 here: their darkness is the merge's to judge.
  const bool allPoints = !run.request.processes().partial();
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    checkErrorBars(tracer, sets[gi], values[gi].lux.data(), values[gi].errorLux.data(), warnings);
    if (allPoints) checkDarkSensors(sets[gi], values[gi].lux.data(), values[gi].errorLux.data(), warnings);
  }
  // A shard holds only its share of the points: merge checks the warnings on all of them.
  throwIfStrict(warnings, run.request.strict && !run.request.processes().partial());

  // 3. Metrics, verdicts and views, all before anything is written.
  RunResult result;
  result.outDir = run.outDir;
  ReportData& data = result.data;
  data = reportDataFor(c, run, trace.settings.seed);
  describeSettings(data, c, *scene, trace, gridPoints);
  data.run.functionFiles = scene->functionFiles;
  data.run.settings.emplace_back("ranks", run.request.processes().describe());
  if (trace.settings.method == Method::kCache &&
      (trace.settings.targetRelativeError > 0.0 || trace.settings.gridTargetRelativeError > 0.0))
    data.run.settings.emplace_back("points estimated without the cache (docs/accuracy.md)",
                                   std::to_string(withoutCache));
  data.warnings = warnings;
  gridReports(data, grids, values, outsideLux);
  InstallationReport& installation = data.installation.emplace();
  installation.luminaires = luminaireSchedule(c, *scene);
  installation.surfaces = surfaceMaterials(*scene);
  installation.energy = energyReport(c, installation.luminaires, scene->bounds(), reference, data.grids);
  values.clear();
  values.shrink_to_fit();
  // Each view's pictures are written as soon as it is rendered, as unnamed temporaries beside the
  // result folder (base/atomic_file.h: a killed run leaves nothing), so that one image at a time
  // is in memory; they go into the result folder with everything else when it is committed.
  const std::string comment = "candela " + std::string(CANDELA_VERSION) + ", case " + c.name;
  std::vector<ViewImageFiles> pictures;
  for (const ViewSpec& view : c.views) {
    ViewOptions options;
    options.distribution = &processes;
    const ViewResult v = computeView(*scene, tracer, view, trace.settings, trace.threads, options, observer);
    checkFinite(v.image.luminance, "view '" + view.name + "'");
    data.views.push_back(viewReport(v));
    if (processes.writesOutputs()) {
      try {
        pictures.push_back(writeViewFiles(beside, v, comment));
      } catch (const std::exception& e) {
        throw InputError(FileLoc{run.outDir.string(), 0, 0}, std::string("cannot write the results: ") + e.what());
      }
    }
  }
  // Glare at the observers: one vertical illuminance estimate each (its own random stream).
  for (std::size_t k = 0; k < c.observers.size(); ++k) {
    const ObserverSpec& o = c.observers[k];
    const LuminaireGlare g = luminaireGlare(tracer, observerView(o), trace.settings, kObserverStreamBase + k);
    ObserverReport r;
    r.name = o.name;
    r.eyeM = o.eyeM();
    r.direction = o.direction;
    if (!g.sources.empty()) r.ugr = g.ugr;
    r.ugrLimit = o.ugrLimit;
    r.luminairesInView = g.sources.size();
    r.verticalLux = g.verticalLux;
    r.backgroundCdM2 = g.backgroundCdM2;
    data.observers.push_back(std::move(r));
  }
  addTaskAreaReports(c, data);
  addSurfaceGridReports(c, data);
  addEn1838Compliance(c, trace, data);  // EN 1838: its own scene of the emergency luminaires
  addEn13201Compliance(c, data);        // EN 13201: the roads, direct light of every luminaire
  addEn12464_2Compliance(c, tracer, data);  // EN 12464-2: the areas' grids above and GR at its observers
  // The plans show where the luminaires and observers are (up to 2000 luminaires: more symbols
  // than that make no readable plan, and a 10⁶-fitting array would hold them all again).
  constexpr std::size_t kMaxLuminaireMarkers = 2000;
  if (c.luminaires.size() <= kMaxLuminaireMarkers)
    for (const LuminairePlacement& l : c.luminaires)
      data.planMarkers.push_back({PlanMarker::Kind::kLuminaire, Vec2(l.positionM.x, l.positionM.y), Vec2(0.0), l.name});
  for (const ObserverSpec& o : c.observers)
    data.planMarkers.push_back({PlanMarker::Kind::kObserver, o.positionM, o.direction, o.name});
  // The scene cut at each horizontal grid's plan height: walls, windows and furniture on the plans.
  addPlanSections(data, *scene, grids);
  data.run.runTimeS = secondsSince(run.start);

  // 4. Write: the folder is committed as a whole.
  commitRun(c, run, [&](const std::filesystem::path& dir) {
    if (csvFiles) csvFiles->commitInto(dir);
    for (ViewImageFiles& p : pictures) p.commitInto(dir);
    writeSummaryCsv(dir, data);
    for (const ComplianceReport& r : data.compliance)
      if (r.section) r.section->writeFiles(dir);
    writeFileAtomic(dir / "summary.json", summaryJsonWithSpacing(data, grids));
    writeHtmlReport(dir / "report.html", data);
  });
  return result;
}

}  // namespace candela
