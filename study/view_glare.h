// Glare of a rendered view, shared by `candela render` and `candela run`: UGR (CIE 117) from the
// luminaires seen along the view direction against the indirect background at the eye, and DGP
// (Wienold & Christoffersen 2006) from the image when the view is a fisheye.
#pragma once

#include "study/case_file.h"
#include "engine/render.h"
#include "engine/tracer.h"
#include "metrics/glare.h"

#include <optional>

namespace candela {

struct ViewGlare {
  double ugr = 0.0;                 // CIE 117 unified glare rating
  std::vector<GlareSource> sources; // luminaires counted in the UGR
  double verticalLux = 0.0;         // illuminance at the eye, lux
  double backgroundCdM2 = 0.0;      // UGR background luminance
  std::optional<ImageGlare> dgp;    // fisheye views only
  // The image's glare sources (DGP's, fisheye views with any) pooled: their pixels' solid-angle
  // weighted mean luminance, cd/m², and its relative standard error (meanStandardError over the
  // mean; NaN when the image has no error estimate). Unset without image glare sources (UGR's
  // luminaires have closed-form luminances, no Monte Carlo error).
  std::optional<double> sourceLuminanceCdM2;
  std::optional<double> sourceLuminanceRelativeStandardError;
};

ViewGlare computeViewGlare(const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                           const Image& img, double glareThresholdCdM2);

// Luminance contrast of a task point against a background point seen from `eye`, under the
// scene's lighting and under the reference uniform sphere (CRF = C / C_ref).
struct ViewContrast {
  double taskCdM2 = 0.0, backgroundCdM2 = 0.0;
  double contrast = 0.0;           // C = (Lt − Lb) / Lb
  double referenceContrast = 0.0;  // C_ref under the uniform sphere
  double crf() const;
};

// Throws InputError at `loc` when the background is dark or task and background look alike under
// the reference sphere (no contrast to rate).
ViewContrast computeViewContrast(const Scene& scene, const Tracer& tracer, const Vec3& eye, const Vec3& task,
                                 const Vec3& background, const TraceSettings& settings, const FileLoc& loc);

}  // namespace candela
