// candela points [SCENE.rad ...] [--points FILE] [options]: illuminance at Radiance-style sensor
// points read from a file or stdin (study/points_study.h traces them); CSV on stdout, printed only
// once every point is done.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/processes.h"
#include "cli/progress.h"
#include "cli/resource_options.h"

#include "base/error.h"
#include "base/input_file.h"
#include "engine/daylight.h"
#include "photometry/site.h"
#include "photometry/sky_type.h"
#include "study/points_study.h"
#include "study/grids/sensor_grid.h"
#include "engine/irradiance_estimator.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace candela::cli {

namespace {

struct PointsOptions {
  std::vector<std::string> scenes;
  std::string caseFile;
  std::string pointsFile;
  std::vector<std::string> portalFiles;
  CaseTraceOptions trace;
  ResourceOptions resources;
  bool quiet = false;
  std::string accelerator = "embree";
  bool error = false;
  bool strict = false;
  // Daylight: used when --sky is given; else the case's [sky] applies.
  std::string sky;
  std::optional<double> sunAltitude, sunAzimuth, timezone, elevation, north;
  std::string lat, lon, time;
  bool noSun = false;
  std::optional<double> dhiLux, dniLux, dniWm2, dhiWm2, groundReflectance;
};

DaylightSpec daylightFromOptions(const PointsOptions& o, DaylightSpec d) {
  const FileLoc cli{"command line", 0, 0};
  std::string why;
  const std::optional<SkyType> type = parseSkyType(o.sky, &why);
  if (!type) throw InputError(cli, why);
  if (type->kind == SkyKind::kAnnual)
    throw InputError(cli, "an annual sky is a whole year: `candela run` computes it from a case");
  d.skyType = *type;
  d.skyLoc = cli;
  d.timeLoc = cli;
  if (o.sunAltitude) d.sunAltitudeDeg = o.sunAltitude;
  if (o.sunAzimuth) d.sunAzimuthDeg = o.sunAzimuth;
  if (!o.lat.empty()) d.latitudeDeg = parseLatitudeDeg(o.lat, cli);
  if (!o.lon.empty()) d.longitudeDeg = parseLongitudeDeg(o.lon, cli);
  if (!o.time.empty()) d.time = o.time;
  if (o.timezone) d.timezoneHours = *o.timezone;
  if (o.elevation) d.elevationM = *o.elevation;
  if (o.north) d.northDeg = *o.north;
  if (o.noSun) d.sun = false;
  if (o.dhiLux) d.diffuseHorizontalLux = o.dhiLux;
  if (o.dniLux) d.directNormalLux = o.dniLux;
  if (o.dniWm2) d.directNormalWm2 = o.dniWm2;
  if (o.dhiWm2) d.diffuseHorizontalWm2 = o.dhiWm2;
  if (o.groundReflectance) d.groundReflectance = *o.groundReflectance;
  return d;
}

int runPoints(const PointsOptions& o) {
  PointsJob job;
  job.caseFile = o.caseFile;
  job.scenes.assign(o.scenes.begin(), o.scenes.end());
  job.portalFiles.assign(o.portalFiles.begin(), o.portalFiles.end());
  if (!o.sky.empty()) job.sky = [&o](DaylightSpec caseDaylight) { return daylightFromOptions(o, caseDaylight); };
  job.trace = o.trace.overrides();
  job.accelerator = parseAccelerator(o.accelerator);
  job.strict = o.strict;
  job.limits = o.resources.limits();
  job.pointsName = o.pointsFile.empty() || o.pointsFile == "-" ? "<stdin>" : o.pointsFile;
  job.distribution = &processes();
  const PointsScene scene = loadPointsScene(job);

  std::vector<SensorPoint> points;
  std::vector<int> lines;
  const bool stdinPoints = o.pointsFile.empty() || o.pointsFile == "-";
  const std::string source = stdinPoints ? "<stdin>" : o.pointsFile;
  if (stdinPoints && processes().ranks() > 1) {
    // mpirun gives standard input to rank 0 alone: it reads the points and sends them on.
    std::string text;
    bool bad = false;
    if (processes().rank() == 0) {
      std::ostringstream all;
      all << std::cin.rdbuf();
      bad = std::cin.bad();
      text = bad ? std::string("\x01") : all.str();
    }
    processes().broadcast(text);
    if (text == "\x01") throw InputError(FileLoc{source, 0, 0}, "cannot read the sensor points");
    std::istringstream in(text);
    points = readPoints(in, source, &lines);
  } else if (stdinPoints) {
    points = readPoints(std::cin, source, &lines);
    if (std::cin.bad()) throw InputError(FileLoc{source, 0, 0}, "cannot read the sensor points");
  } else {
    std::istringstream in(readInputFile(o.pointsFile, "points file"));
    points = readPoints(in, source, &lines);
  }
  std::vector<FileLoc> locs;
  for (const int line : lines) locs.push_back(FileLoc{source, line, 0});
  ProgressObserver progress(o.quiet || !printsResults(), job.limits.maxMemoryBytes);
  const PointsResult result = computePoints(scene, job.accelerator, points, progress, locs);
  const std::vector<IrradianceEstimate>& est = result.estimates;
  if (!printsResults()) return 0;  // rank 0 prints the CSV
  printWarnings(result.warnings);

  std::ostringstream csv;
  csv << "x,y,z,dx,dy,dz,illuminance_lux" << (o.error ? ",error_lux" : "") << "\n";
  char buf[256];
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i].position;
    const Vec3& n = points[i].normal;
    std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.7g", p.x, p.y, p.z, n.x, n.y, n.z,
                  est[i].illuminanceLux());
    csv << buf;
    if (o.error) {
      std::snprintf(buf, sizeof buf, ",%.3g", est[i].standardErrorLux());
      csv << buf;
    }
    csv << "\n";
  }
  std::cout << csv.str() << std::flush;
  return 0;
}

}  // namespace

void addPointsCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<PointsOptions>();
  CLI::App* cmd = app.add_subcommand("points", "illuminance (lux) at sensor points 'x y z dx dy dz'; CSV on stdout");
  cmd->add_option("scenes", opts->scenes,
                  "scene files: Radiance, read in order, then Wavefront OBJ (.obj), whose faces take the modifiers "
                  "they name")
      ->check(CLI::ExistingFile);
  cmd->add_option("--case", opts->caseFile, "case file: its scenes, luminaires and settings apply")
      ->check(CLI::ExistingFile);
  cmd->add_option("--points", opts->pointsFile, "sensor points file (default: stdin)");
  cmd->add_option("--portal", opts->portalFiles,
                  "file of openings without glazing that guide sky sampling (repeatable): one planar polygon "
                  "per line, 'x1 y1 z1 x2 y2 z2 x3 y3 z3 ...' in m, '#' comments; glazing is found by itself "
                  "(docs/daylight.md#portals)")
      ->group("Daylight");
  addCaseTraceOptions(cmd, opts->trace, "hemisphere samples per point", "path");
  cmd->add_option("--accelerator", opts->accelerator, "embree (default) | octree (the paper's)")
      ->check(parsedBy(parseAccelerator, "ACCELERATOR"));
  addStrictOption(cmd, opts->strict);
  addResourceOptions(cmd, opts->resources);
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress or estimate on stderr (errors and warnings only)");
  cmd->add_flag("--error", opts->error, "add a column error_lux: one standard error of each value");
  // Daylight.
  cmd->add_option("--sky", opts->sky, "uniform | cie-overcast | cie-clear | cie:1..15 | perez | none")
      ->group("Daylight");
  cmd->add_option("--sun-altitude", opts->sunAltitude, "sun altitude, deg")
      ->check(CLI::Range(-90.0, 90.0))->group("Daylight");
  cmd->add_option("--sun-azimuth", opts->sunAzimuth, "sun azimuth, deg clockwise from north")
      ->check(CLI::Range(-360.0, 360.0))->group("Daylight");
  cmd->add_option("--lat", opts->lat, "site latitude, deg north (or DMS: 37d52'N)")->group("Daylight");
  cmd->add_option("--lon", opts->lon, "site longitude, deg east (or DMS: 122d16'W)")->group("Daylight");
  cmd->add_option("--time", opts->time, "local standard time, ISO 8601 (sun from the NREL SPA)")->group("Daylight");
  cmd->add_option("--timezone", opts->timezone, "hours from UTC of local standard time")
      ->check(CLI::Range(-18.0, 18.0))->group("Daylight");
  cmd->add_option("--elevation", opts->elevation, "site elevation, m")->check(CLI::Range(-500.0, 12000.0))->group("Daylight");
  cmd->add_option("--north", opts->north, "true north, deg clockwise from model +Y")
      ->check(CLI::Range(-360.0, 360.0))->group("Daylight");
  cmd->add_flag("--no-sun", opts->noSun, "sky only, no sun")->group("Daylight");
  // Illuminances and irradiances: finite, and far above any sky's (the sun's direct normal
  // illuminance stays below 1.3e5 lx) so that no valid input is refused.
  cmd->add_option("--diffuse-horizontal-illuminance", opts->dhiLux,
                  "the sky's illuminance on an open horizontal plane, lux (default 10000)")
      ->check(CLI::Range(0.0, 1.0e7))->group("Daylight");
  cmd->add_option("--direct-normal-illuminance", opts->dniLux, "the sun's direct normal illuminance, lux")
      ->check(CLI::Range(0.0, 1.0e7))->group("Daylight");
  cmd->add_option("--direct-normal-irradiance", opts->dniWm2, "direct normal irradiance, W/m2 (perez)")
      ->check(CLI::Range(0.0, 1.0e7))->group("Daylight");
  cmd->add_option("--diffuse-horizontal-irradiance", opts->dhiWm2, "diffuse horizontal irradiance, W/m2 (perez)")
      ->check(CLI::Range(0.0, 1.0e7))->group("Daylight");
  cmd->add_option("--ground-reflectance", opts->groundReflectance, "ground reflectance (default 0.2)")
      ->check(CLI::Range(0.0, 1.0))->group("Daylight");
  cmd->callback([opts, &action] { action = [opts] { return runPoints(*opts); }; });
}

}  // namespace candela::cli
