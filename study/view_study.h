// One view of a case from start to finish, the same for `candela run` (every [[view]]) and
// `candela render` (one): the luminance image, its glare ratings, the task contrast, the
// false-colour scale and pictures, and the report's rows (docs/views.md).
#pragma once

#include "base/error.h"
#include "engine/render.h"
#include "engine/tracer.h"
#include "reports/falsecolor.h"
#include "reports/report_data.h"
#include "reports/tonemap.h"
#include "study/case/case_file.h"
#include "study/observer.h"
#include "study/resource_estimate.h"
#include "study/trace_options.h"
#include "study/view_glare.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela {

// The pipeline's knobs. The defaults are what both commands use unless told otherwise.
struct ViewOptions {
  int pixelSamples = 4;   // camera rays per traced pixel
  int coarseStep = 4;     // pixels between first-pass samples (1: every pixel)
  // Matte surfaces seen take ρE/π from a stratified irradiance estimate with this many samples
  // (0: one path per camera ray). A path per ray leaves salt-and-pepper noise at the few rays per
  // pixel a report can afford, under a sky (through windows) as under electric light (docs/views.md).
  int irradianceSamples = 64;
  int glossySamples = 8;  // paths per camera ray on a glossy (Ward) lobe seen (engine/render.h)
  bool logScale = true;
  std::optional<double> minCdM2, maxCdM2;   // false-colour range; unset: automatic
  double glareThresholdCdM2 = 0.0;          // DGP glare sources; 0: 5 × the image's mean luminance
  // Contrast points instead of the view's own `task`/`background` (both or neither), and where
  // they were given (errors point there).
  std::optional<Vec3> task, background;
  FileLoc contrastLoc;
  // The processes the pixels are shared between (base/distribution.h); null: this one.
  const Distribution* distribution = nullptr;
};

struct ViewResult {
  ViewSpec view;
  RenderSettings render;        // as traced
  Image image;
  ColorScale scale;             // of the false-colour picture
  std::string stem;             // file names: <stem>.exr, <stem>.png, <stem>_preview.png
  ViewGlare glare;
  std::optional<ViewContrast> contrast;
};

// Renders and rates one view (progress through `observer`, one item a pixel). Throws InputError
// for contrast points that cannot be rated.
ViewResult computeView(const Scene& scene, const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                       int threads, const ViewOptions& options, StudyObserver& observer);

// The view's section of the HTML report: description, pictures, metric rows.
ViewReport viewReport(const ViewResult& v);

// Writes the view's three pictures as temporaries in `dir`'s file system, put in place by the
// result's commitInto (reports/tonemap.h); `comment` goes into the EXR.
ViewImageFiles writeViewFiles(const std::filesystem::path& dir, const ViewResult& v, const std::string& comment);

// Mean luminance over the image weighted by each pixel's solid angle, and the largest, cd/m²;
// the mean's relative standard error (engine/render.h meanStandardError over the mean: Monte
// Carlo noise of the traced pixels; NaN when the image has no error estimate).
struct ViewLuminance {
  double meanCdM2 = 0.0, maxCdM2 = 0.0;
  double meanRelativeStandardError = 0.0;
};
ViewLuminance viewLuminance(const ViewResult& v);

// "± 0.52 % (standard error)" for a relative standard error of 0.0052; says it is unknown when
// it is not finite (the report's and `candela render`'s wording).
std::string relativeErrorText(double relativeStandardError);

// `candela render`: one [[view]] of a case, named `view`, through the same pipeline and settings
// as `candela run` gives it, its pictures written into `outDir` (empty: the case's [output] dir).
struct RenderRequest {
  std::string view;
  std::filesystem::path outDir;
  TraceOverrides trace;
  ViewOptions options;
  bool strict = false;  // every warning an InputError (the first one, before anything is traced)
  ResourceLimits limits;  // checked before tracing (study/resource_estimate.h)
};

struct RenderResult {
  std::string caseName;
  ViewResult view;
  ViewImagePaths paths;
  std::vector<Warning> warnings;  // study/warnings.h: no light source, luminaires, site
};

// Throws InputError for an unknown view, bad options or bad input (and, when strict, for the
// first warning), before anything is written.
RenderResult renderCaseView(const std::filesystem::path& caseFile, const RenderRequest& request,
                            StudyObserver& observer = silentObserver());

}  // namespace candela
