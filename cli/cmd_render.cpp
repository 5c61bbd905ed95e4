// candela render CASE.toml --view NAME [--out DIR]: one [[view]] of a case through the view
// pipeline `candela run` uses (study/view_study.h): <out>/<name>.exr (luminance in cd/m², float),
// <name>.png (false colour with legend) and <name>_preview.png (tone mapped). This file parses
// the options and prints the view's luminance, glare ratings (UGR, CIE 117; DGP for fisheye
// views, Wienold & Christoffersen 2006) and contrast.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/processes.h"
#include "cli/progress.h"
#include "cli/resource_options.h"

#include "base/error.h"
#include "metrics/glare.h"
#include "study/run_case.h"
#include "study/view_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace candela::cli {

namespace {

struct RenderOptions {
  std::string caseFile;
  std::string view;
  std::string outDir;   // empty: the case's [output] dir
  CaseTraceOptions trace;
  // The view pipeline's defaults (study/view_study.h), which `candela run` uses: one estimator.
  int pixelSamples = ViewOptions{}.pixelSamples;
  int coarseStep = ViewOptions{}.coarseStep;
  int irradianceSamples = ViewOptions{}.irradianceSamples;
  int glossySamples = ViewOptions{}.glossySamples;
  std::string scale = "log";
  double minCdM2 = -1.0, maxCdM2 = -1.0;  // < 0: automatic
  double glareThresholdCdM2 = 0.0;        // 0: 5 × the image's mean luminance
  std::vector<double> task, background;   // points (m) for contrast and CRF, seen from the view point
  ResourceOptions resources;
  bool quiet = false;
  bool strict = false;
};

std::string num(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// A relative standard error as the report gives it, in ASCII as the other lines.
std::string asciiError(double relativeStandardError) {
  if (!std::isfinite(relativeStandardError)) return "(standard error unknown)";
  return "+/- " + num(100.0 * relativeStandardError, 2) + " % (standard error)";
}

RenderRequest requestOf(const RenderOptions& o) {
  RenderRequest r;
  r.view = o.view;
  r.outDir = o.outDir;
  r.trace = o.trace.overrides();
  r.strict = o.strict;
  ViewOptions& v = r.options;
  v.pixelSamples = o.pixelSamples;
  v.coarseStep = o.coarseStep;
  v.irradianceSamples = o.irradianceSamples;
  v.glossySamples = o.glossySamples;
  v.logScale = o.scale == "log";
  if (o.minCdM2 >= 0.0) v.minCdM2 = o.minCdM2;
  if (o.maxCdM2 > 0.0) v.maxCdM2 = o.maxCdM2;
  v.glareThresholdCdM2 = o.glareThresholdCdM2;
  if (o.task.size() == 3 && o.background.size() == 3) {
    v.task = Vec3(o.task[0], o.task[1], o.task[2]);
    v.background = Vec3(o.background[0], o.background[1], o.background[2]);
    v.contrastLoc = FileLoc{o.caseFile, 0, 0};
  }
  return r;
}

void printGlare(std::ostringstream& s, const ViewResult& r) {
  const ViewGlare& g = r.glare;
  if (g.sources.empty()) {
    s << "UGR: no luminaire with a luminous area in front of the observer\n";
  } else {
    // CIE 117's formula holds for sources of 0.0003 to 0.1 sr; say so when some are outside.
    std::size_t outside = 0;
    for (const GlareSource& src : g.sources) outside += src.solidAngleSr < 3e-4 || src.solidAngleSr > 0.1;
    s << "UGR " << num(g.ugr, 1) << " (" << g.sources.size() << " luminaires, background " << num(g.backgroundCdM2, 1)
      << " cd/m2";
    if (outside > 0) s << "; " << outside << " outside CIE 117's 0.0003-0.1 sr";
    s << ")\n";
  }
  if (g.dgp && std::min(r.view.fovDeg.x, r.view.fovDeg.y) < 180.0)
    s << "note: DGP wants the whole forward hemisphere (a 180 x 180 degree fisheye); this view sees less\n";
  if (g.dgp)
    s << "DGP " << num(g.dgp->dgp, 3) << " (Ev from the image " << num(g.dgp->verticalIlluminanceLux, 1) << " lx, "
      << g.dgp->sources.size() << " glare sources above " << num(g.dgp->thresholdCdM2, 0) << " cd/m2)\n";
  if (g.sourceLuminanceCdM2)
    s << "glare sources' luminance " << num(*g.sourceLuminanceCdM2, 0) << " cd/m2 "
      << asciiError(*g.sourceLuminanceRelativeStandardError) << "\n";
}

int renderCommand(const RenderOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  RenderRequest request = requestOf(o);
  request.limits = o.resources.limits();
  request.options.distribution = &processes();
  ProgressObserver progress(o.quiet || !printsResults(), request.limits.maxMemoryBytes);
  const RenderResult r = renderCaseView(o.caseFile, request, progress);
  if (!printsResults()) return 0;  // rank 0 writes and prints
  printWarnings(r.warnings);
  if (o.quiet) return 0;
  const ViewResult& v = r.view;
  const Image& img = v.image;
  const ViewLuminance lum = viewLuminance(v);
  std::ostringstream s;
  s << "view " << v.view.name << ": " << img.width << " x " << img.height << " "
    << (v.view.type == ViewType::kFisheye ? "fisheye" : "perspective") << ", " << img.tracedPixels << " of "
    << img.width * img.height << " pixels traced (" << v.render.samplesPerPixel << " rays each"
    << (v.render.irradianceSamples > 0
            ? ", irradiance from " + std::to_string(v.render.irradianceSamples) +
                  " samples at diffuse surfaces seen, directly or through glass"
            : "")
    << ")\n";
  s << "luminance: mean " << num(lum.meanCdM2, 1) << " cd/m2 " << asciiError(lum.meanRelativeStandardError)
    << ", max " << num(lum.maxCdM2, 1) << " cd/m2\n";
  s << "vertical illuminance at the eye " << num(v.glare.verticalLux, 1) << " lx\n";
  printGlare(s, v);
  if (v.contrast)
    s << "contrast: task " << num(v.contrast->taskCdM2, 2) << " cd/m2, background " << num(v.contrast->backgroundCdM2, 2)
      << " cd/m2, C " << num(v.contrast->contrast, 3) << ", under the reference sphere "
      << num(v.contrast->referenceContrast, 3) << ", CRF " << num(v.contrast->crf(), 3) << "\n";
  s << "wrote " << r.paths.exr.string() << ", " << r.paths.falseColor.string() << ", " << r.paths.preview.string()
    << " in " << num(secondsSince(start), 1) << " s\n";
  std::cout << s.str() << std::flush;
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
                  "diffuse surfaces seen (directly, through or in glass): rho E / pi from this many hemisphere "
                  "samples (0 = plain paths, one per camera ray; default 64, as candela run)")
      ->check(CLI::Range(0, 65536));
  cmd->add_option("--glossy-samples", opts->glossySamples,
                  "glossy surfaces seen: paths per camera ray on their specular lobe (default 8, as candela run)")
      ->check(CLI::Range(1, 4096));
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
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress bar or result lines (errors and warnings only)");
  addStrictOption(cmd, opts->strict);
  addResourceOptions(cmd, opts->resources);
  cmd->callback([opts, &action] { action = [opts] { return renderCommand(*opts); }; });
}

}  // namespace candela::cli
