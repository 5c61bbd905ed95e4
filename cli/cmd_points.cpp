// candela points [SCENE.rad ...] [--points FILE] [options]: illuminance at Radiance-style sensor
// points read from a file or stdin; CSV on stdout, printed only once every point is done.
#include "cli/commands.h"

#include "base/error.h"
#include "study/case_file.h"
#include "study/case_scene.h"
#include "engine/daylight.h"
#include "photometry/site.h"
#include "engine/rad_reader.h"
#include "study/sensor_grid.h"
#include "engine/sensors.h"

#include <cstdio>
#include <fstream>
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
  std::string quality;  // empty: the case's, else normal
  int bounces = -1;
  int samples = -1;
  int64_t seed = -1;
  int threads = -1;
  std::string method = "path";
  std::string accelerator = "embree";
  bool error = false;
  double targetErrorPct = 0.0;
  // Daylight (issue "Daylight"): used when --sky is given; else the case's [sky] applies.
  std::string sky;
  std::optional<double> sunAltitude, sunAzimuth, timezone, elevation, north;
  std::string lat, lon, time;
  bool noSun = false;
  std::optional<double> dhiLux, dniLux, dniWm2, dhiWm2, groundReflectance;
};

DaylightSpec daylightFromOptions(const PointsOptions& o, DaylightSpec d) {
  const FileLoc cli{"command line", 0, 0};
  d.skyType = o.sky;
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
  // The case's scene, luminaires and settings first; options given on the command line win.
  std::unique_ptr<Scene> scene;
  Quality quality = Quality::kNormal;
  int threads = 0;
  uint64_t seed = 1;
  std::optional<int> bounces, samples;
  DaylightSpec daylight;
  if (!o.caseFile.empty()) {
    const CaseFile c = readCaseFile(o.caseFile);
    scene = loadCaseScene(c, o.sky.empty());
    if (!o.sky.empty()) daylight = daylightFromCase(c);
    quality = c.settings.quality;
    seed = c.settings.seed;
    threads = c.settings.threads;
    bounces = c.settings.bounces;
    samples = c.settings.samples;
  } else {
    scene = std::make_unique<Scene>();
  }
  for (const std::string& f : o.scenes) readRadianceFile(f, *scene);
  if (!o.sky.empty()) addDaylight(*scene, daylightFromOptions(o, daylight));
  if (!o.quality.empty()) quality = parseQuality(o.quality);
  if (o.bounces >= 0) bounces = o.bounces;
  if (o.samples > 0) samples = o.samples;
  if (o.seed >= 0) seed = static_cast<uint64_t>(o.seed);
  if (o.threads >= 0) threads = o.threads;
  TraceSettings settings = settingsForQuality(quality);
  if (bounces) settings.maxBounces = *bounces;
  if (samples) settings.hemisphereSamples = *samples;
  settings.seed = seed;
  settings.method = parseMethod(o.method);
  settings.targetRelativeError = o.targetErrorPct / 100.0;

  std::vector<SensorPoint> points;
  if (o.pointsFile.empty() || o.pointsFile == "-") {
    points = readPoints(std::cin, "<stdin>");
  } else {
    std::ifstream in(o.pointsFile);
    if (!in) throw InputError(FileLoc{o.pointsFile, 0, 0}, "cannot open points file");
    points = readPoints(in, o.pointsFile);
  }

  const Tracer tracer(*scene, parseAccelerator(o.accelerator));
  const std::vector<IrradianceEstimate> est = computeIrradiance(tracer, points, settings, threads);

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
  cmd->add_option("scenes", opts->scenes, "Radiance scene files, read in order")->check(CLI::ExistingFile);
  cmd->add_option("--case", opts->caseFile, "case file: its scenes, luminaires and settings apply")
      ->check(CLI::ExistingFile);
  cmd->add_option("--points", opts->pointsFile, "sensor points file (default: stdin)");
  cmd->add_option("--quality", opts->quality, "draft | normal | high (default: the case's, else normal: accurate)")
      ->check(CLI::IsMember({"draft", "normal", "high"}));
  cmd->add_option("--bounces", opts->bounces, "diffuse interreflections followed (default by quality)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--samples", opts->samples, "hemisphere samples per point (default by quality)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", opts->seed, "random seed (same seed, same numbers; default 1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", opts->threads, "threads, 0 = all cores")->check(CLI::NonNegativeNumber);
  cmd->add_option("--method", opts->method, "path (unbiased path tracer) | cache (Ward's irradiance cache)")
      ->check(CLI::IsMember({"path", "cache"}));
  cmd->add_option("--accelerator", opts->accelerator, "embree (default) | octree (the paper's)")
      ->check(CLI::IsMember({"embree", "octree"}));
  cmd->add_flag("--error", opts->error, "add a column error_lux: one standard error of each value");
  cmd->add_option("--target-error", opts->targetErrorPct,
                  "sample each point until its standard error is below PCT percent of its value")
      ->check(CLI::Range(0.01, 100.0));
  // Daylight.
  cmd->add_option("--sky", opts->sky, "uniform | cie-overcast | cie-clear | cie:1..15 | perez | none")
      ->group("Daylight");
  cmd->add_option("--sun-altitude", opts->sunAltitude, "sun altitude, deg")->group("Daylight");
  cmd->add_option("--sun-azimuth", opts->sunAzimuth, "sun azimuth, deg clockwise from north")->group("Daylight");
  cmd->add_option("--lat", opts->lat, "site latitude, deg north (or DMS: 37d52'N)")->group("Daylight");
  cmd->add_option("--lon", opts->lon, "site longitude, deg east (or DMS: 122d16'W)")->group("Daylight");
  cmd->add_option("--time", opts->time, "local standard time, ISO 8601 (sun from the NREL SPA)")->group("Daylight");
  cmd->add_option("--timezone", opts->timezone, "hours from UTC of local standard time")->group("Daylight");
  cmd->add_option("--elevation", opts->elevation, "site elevation, m")->group("Daylight");
  cmd->add_option("--north", opts->north, "true north, deg clockwise from model +Y")->group("Daylight");
  cmd->add_flag("--no-sun", opts->noSun, "sky only, no sun")->group("Daylight");
  cmd->add_option("--diffuse-horizontal-illuminance", opts->dhiLux,
                  "the sky's illuminance on an open horizontal plane, lux (default 10000)")
      ->check(CLI::NonNegativeNumber)->group("Daylight");
  cmd->add_option("--direct-normal-illuminance", opts->dniLux, "the sun's direct normal illuminance, lux")
      ->check(CLI::NonNegativeNumber)->group("Daylight");
  cmd->add_option("--direct-normal-irradiance", opts->dniWm2, "direct normal irradiance, W/m2 (perez)")
      ->check(CLI::NonNegativeNumber)->group("Daylight");
  cmd->add_option("--diffuse-horizontal-irradiance", opts->dhiWm2, "diffuse horizontal irradiance, W/m2 (perez)")
      ->check(CLI::NonNegativeNumber)->group("Daylight");
  cmd->add_option("--ground-reflectance", opts->groundReflectance, "ground reflectance (default 0.2)")
      ->check(CLI::Range(0.0, 1.0))->group("Daylight");
  cmd->callback([opts, &action] { action = [opts] { return runPoints(*opts); }; });
}

}  // namespace candela::cli
