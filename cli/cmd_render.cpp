// candela render CASE.toml --view NAME [--out DIR]: renders one [[view]] of a case into
// <out>/<name>.exr (luminance in cd/m², float), <name>.png (false colour with legend) and
// <name>_preview.png (tone mapped), and prints the view's glare ratings: UGR from the luminaires
// (CIE 117) for every view, DGP from the image (Wienold & Christoffersen 2006) for fisheye views.
// Everything is read and checked before tracing; each file is written atomically.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/view_glare.h"
#include "cli/progress.h"

#include "base/error.h"
#include "study/case_file.h"
#include "study/case_scene.h"
#include "engine/render.h"
#include "metrics/contrast.h"
#include "metrics/glare.h"
#include "reports/report_data.h"
#include "reports/tonemap.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace candela::cli {

namespace {

namespace fs = std::filesystem;

struct RenderOptions {
  std::string caseFile;
  std::string view;
  std::string outDir;   // empty: the case's [output] dir
  CaseTraceOptions trace;
  int pixelSamples = 4;
  int coarseStep = 4;
  int irradianceSamples = -1;  // < 0: automatic (64 with daylight, else 0)
  std::string scale = "log";
  double minCdM2 = -1.0, maxCdM2 = -1.0;  // < 0: automatic
  double glareThresholdCdM2 = 0.0;        // 0: 5 × the image's mean luminance
  std::vector<double> task, background;   // points (m) for contrast and CRF, seen from the view point
  bool quiet = false;
};

std::string num(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

int renderCase(const RenderOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const CaseFile c = readCaseFile(o.caseFile);
  const ViewSpec* view = nullptr;
  for (const ViewSpec& v : c.views)
    if (v.name == o.view) view = &v;
  if (!view) {
    std::string names;
    for (const ViewSpec& v : c.views) names += (names.empty() ? "" : ", ") + v.name;
    throw InputError(FileLoc{c.path.string(), 0, 0},
                     "no [[view]] named '" + o.view + "' (" + (names.empty() ? "the case has no views" : "views: " + names) + ")");
  }
  if (o.scale == "log" && o.minCdM2 == 0.0)
    throw InputError(FileLoc{c.path.string(), 0, 0}, "--min must be above 0 cd/m2 on a log scale");
  if (o.minCdM2 >= 0.0 && o.maxCdM2 > 0.0 && o.maxCdM2 <= o.minCdM2)
    throw InputError(FileLoc{c.path.string(), 0, 0}, "--max must be above --min");
  const std::unique_ptr<Scene> scene = loadCaseScene(c);

  const ResolvedTrace resolved = resolveTrace(c, o.trace, Method::kPath);
  const TraceSettings& settings = resolved.settings;
  const int threads = resolved.threads;
  const fs::path outDir = o.outDir.empty() ? c.output.dir : fs::path(o.outDir);

  RenderSettings rs;
  rs.samplesPerPixel = o.pixelSamples;
  rs.coarseStep = o.coarseStep;
  // Daylight enters rooms through windows, which a path's single sky sample rarely finds: camera
  // paths alone leave salt-and-pepper noise (docs/views.md); the stratified irradiance estimate at
  // the surfaces seen does not.
  rs.irradianceSamples = o.irradianceSamples >= 0 ? o.irradianceSamples : (scene->sky ? 64 : 0);
  const Tracer tracer(*scene);
  Image img;
  {
    ProgressBar bar("rendering " + view->name, static_cast<std::size_t>(view->resolution.x) * view->resolution.y,
                    ProgressBar::wanted(o.quiet));
    img = renderView(tracer, *view, settings, threads, rs, [&bar](std::size_t done, std::size_t) { bar.update(done); });
    bar.finish();
  }

  // Glare: UGR from the luminaires seen, DGP from a fisheye image (cli/view_glare.h).
  const Camera cam(*view);
  const ViewGlare glare = computeViewGlare(tracer, *view, settings, img, o.glareThresholdCdM2);
  const std::vector<GlareSource>& ugrSources = glare.sources;
  const double evLux = glare.verticalLux;
  const double backgroundCdM2 = glare.backgroundCdM2;
  const std::optional<ImageGlare>& dgp = glare.dgp;

  // Contrast of a task point against a background point seen from the view point, under the
  // case's lighting and under the reference uniform sphere (CRF).
  // From the command line, else from the view's `task`/`background` keys.
  std::optional<ViewContrast> contrast;
  std::optional<Vec3> task = view->taskM, background = view->backgroundM;
  if (o.task.size() == 3 && o.background.size() == 3) {
    task = Vec3(o.task[0], o.task[1], o.task[2]);
    background = Vec3(o.background[0], o.background[1], o.background[2]);
  }
  if (task && background)
    contrast = computeViewContrast(*scene, tracer, cam.position(), *task, *background, settings,
                                   o.task.size() == 3 ? FileLoc{c.path.string(), 0, 0} : view->loc);

  // Pictures.
  std::vector<Rgb> rgbCdM2(img.radiance.size());
  for (std::size_t i = 0; i < rgbCdM2.size(); ++i) rgbCdM2[i] = kLumensPerWatt * img.radiance[i];
  const bool logScale = o.scale == "log";
  const ColorScale scale = luminanceScale(img.luminance, logScale, o.minCdM2 >= 0.0 ? std::optional(o.minCdM2) : std::nullopt,
                                          o.maxCdM2 > 0.0 ? std::optional(o.maxCdM2) : std::nullopt);
  const std::string stem = safeFileName(view->name);
  ViewImagePaths paths;
  try {
    paths = writeViewImages(outDir, stem, img.width, img.height, img.luminance, rgbCdM2, img.inside, scale,
                            "candela " + std::string(CANDELA_VERSION) + ", case " + c.name + ", view " + view->name);
  } catch (const fs::filesystem_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the images: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the images: ") + e.what());
  }

  if (!o.quiet) {
    double sum = 0.0, omega = 0.0, peak = 0.0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const std::size_t i = img.index(x, y);
        const double w = cam.pixelSolidAngleSr(x, y);
        sum += img.luminance[i] * w;
        omega += w;
        peak = std::max(peak, img.luminance[i]);
      }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream s;
    s << "view " << view->name << ": " << img.width << " x " << img.height << " "
      << (view->type == ViewType::kFisheye ? "fisheye" : "perspective") << ", " << img.tracedPixels << " of "
      << img.width * img.height << " pixels traced (" << rs.samplesPerPixel << " rays each"
      << (rs.irradianceSamples > 0 ? ", irradiance from " + std::to_string(rs.irradianceSamples) + " samples at matte surfaces" : "")
      << ")\n";
    s << "luminance: mean " << num(omega > 0.0 ? sum / omega : 0.0, 1) << " cd/m2, max " << num(peak, 1) << " cd/m2\n";
    s << "vertical illuminance at the eye " << num(evLux, 1) << " lx\n";
    if (ugrSources.empty())
      s << "UGR: no luminaire with a luminous area in front of the observer\n";
    else {
      // CIE 117's formula holds for sources of 0.0003 to 0.1 sr; say so when some are outside.
      std::size_t outside = 0;
      for (const GlareSource& g : ugrSources) outside += g.solidAngleSr < 3e-4 || g.solidAngleSr > 0.1;
      s << "UGR " << num(unifiedGlareRating(backgroundCdM2, ugrSources), 1) << " (" << ugrSources.size()
        << " luminaires, background " << num(backgroundCdM2, 1) << " cd/m2";
      if (outside > 0) s << "; " << outside << " outside CIE 117's 0.0003-0.1 sr";
      s << ")\n";
    }
    if (dgp && std::min(view->fovDeg.x, view->fovDeg.y) < 180.0)
      s << "note: DGP wants the whole forward hemisphere (a 180 x 180 degree fisheye); this view sees less\n";
    if (dgp)
      s << "DGP " << num(dgp->dgp, 3) << " (Ev from the image " << num(dgp->verticalIlluminanceLux, 1) << " lx, "
        << dgp->sources.size() << " glare sources above " << num(dgp->thresholdCdM2, 0) << " cd/m2)\n";
    if (contrast)
      s << "contrast: task " << num(contrast->taskCdM2, 2) << " cd/m2, background " << num(contrast->backgroundCdM2, 2)
        << " cd/m2, C " << num(contrast->contrast, 3) << ", under the reference sphere "
        << num(contrast->referenceContrast, 3) << ", CRF " << num(contrast->crf(), 3) << "\n";
    s << "wrote " << paths.exr.string() << ", " << paths.falseColor.string() << ", " << paths.preview.string() << " in "
      << num(seconds, 1) << " s\n";
    std::cout << s.str() << std::flush;
  }
  return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "render a [[view]] of a case: luminance EXR, false colour and preview PNGs, glare");
  cmd->add_option("case", opts->caseFile, "case file (TOML, docs/case-format.md)")->required();
  cmd->add_option("--view", opts->view, "name of the [[view]] to render")->required();
  cmd->add_option("--out", opts->outDir, "results folder (default: the case's [output] dir)");
  addCaseTraceOptions(cmd, opts->trace, "hemisphere samples for the eye's illuminance");
  cmd->add_option("--pixel-samples", opts->pixelSamples, "camera rays per traced pixel (default 4)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--coarse-step", opts->coarseStep, "pixels between first-pass samples, 1 = trace every pixel (default 4)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--irradiance-samples", opts->irradianceSamples,
                  "matte surfaces seen: rho E / pi from this many hemisphere samples instead of one path per ray "
                  "(0 = off; default 64 with daylight, else 0)")
      ->check(CLI::Range(0, 65536));
  cmd->add_option("--scale", opts->scale, "false-colour scale: log | linear (default log)")
      ->check(CLI::IsMember({"log", "linear"}));
  cmd->add_option("--min", opts->minCdM2, "false-colour scale minimum, cd/m2 (default automatic)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max", opts->maxCdM2, "false-colour scale maximum, cd/m2 (default automatic)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--glare-threshold", opts->glareThresholdCdM2,
                  "DGP glare-source threshold, cd/m2 (default 5 x the image's mean luminance)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--task", opts->task, "task point X Y Z (m) for contrast and CRF, seen from the view point")
      ->expected(3);
  cmd->add_option("--background", opts->background, "background point X Y Z (m) next to the task")->expected(3);
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress bar or result lines (errors only)");
  cmd->callback([opts, &action] { action = [opts] { return renderCase(*opts); }; });
}

}  // namespace candela::cli
