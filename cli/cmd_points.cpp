// candela points [SCENE.rad ...] [--points FILE] [options]: illuminance at Radiance-style sensor
// points read from a file or stdin; CSV on stdout, printed only once every point is done.
#include "cli/commands.h"

#include "engine/base/error.h"
#include "engine/case_file.h"
#include "engine/case_scene.h"
#include "engine/rad_reader.h"
#include "engine/sensor_grid.h"
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
  bool error = false;
};

int runPoints(const PointsOptions& o) {
  // The case's scene, luminaires and settings first; options given on the command line win.
  std::unique_ptr<Scene> scene;
  Quality quality = Quality::kNormal;
  int threads = 0;
  uint64_t seed = 1;
  std::optional<int> bounces, samples;
  if (!o.caseFile.empty()) {
    const CaseFile c = readCaseFile(o.caseFile);
    scene = loadCaseScene(c);
    quality = c.settings.quality;
    seed = c.settings.seed;
    threads = c.settings.threads;
    bounces = c.settings.bounces;
    samples = c.settings.samples;
  } else {
    scene = std::make_unique<Scene>();
  }
  for (const std::string& f : o.scenes) readRadianceFile(f, *scene);
  if (!o.quality.empty()) quality = parseQuality(o.quality);
  if (o.bounces >= 0) bounces = o.bounces;
  if (o.samples > 0) samples = o.samples;
  if (o.seed >= 0) seed = static_cast<uint64_t>(o.seed);
  if (o.threads >= 0) threads = o.threads;
  TraceSettings settings = settingsForQuality(quality);
  if (bounces) settings.maxBounces = *bounces;
  if (samples) settings.hemisphereSamples = *samples;
  settings.seed = seed;

  std::vector<SensorPoint> points;
  if (o.pointsFile.empty() || o.pointsFile == "-") {
    points = readPoints(std::cin, "<stdin>");
  } else {
    std::ifstream in(o.pointsFile);
    if (!in) throw InputError(FileLoc{o.pointsFile, 0, 0}, "cannot open points file");
    points = readPoints(in, o.pointsFile);
  }

  const Tracer tracer(*scene);
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
  cmd->add_option("--method", opts->method, "path (unbiased path tracer)")->check(CLI::IsMember({"path"}));
  cmd->add_flag("--error", opts->error, "add a column error_lux: one standard error of each value");
  cmd->callback([opts, &action] { action = [opts] { return runPoints(*opts); }; });
}

}  // namespace candela::cli
