// Glare of a rendered view, shared by `candela render` and `candela run`: UGR (CIE 117) from the
// luminaires seen along the view direction against the indirect background at the eye, and DGP
// (Wienold & Christoffersen 2006) from the image when the view is a fisheye.
#pragma once

#include "study/case/case_file.h"
#include "engine/render.h"
#include "engine/tracer.h"
#include "metrics/glare.h"
#include "engine/random_streams.h"

#include <optional>

namespace candela {

// UGR (CIE 117) at a view's eye along its direction from the luminaires' luminous openings in
// front of the eye (engine/render.h seenLuminaires: L = I/A_proj, ω, occlusion through the
// scene), P the Guth position index in the view frame, Lb the indirect illuminance at the eye
// over π (its vertical illuminance estimated with random stream `stream`). No CIE 147
// small- or large-source correction (docs/views.md).
struct LuminaireGlare {
  double ugr = 0.0;                 // CIE 117 unified glare rating; 0 without luminaires in view
  std::vector<GlareSource> sources; // luminaires counted in the UGR
  double verticalLux = 0.0;         // illuminance at the eye, lux
  double backgroundCdM2 = 0.0;      // UGR background luminance
};
LuminaireGlare luminaireGlare(const Tracer& tracer, const View& view, const TraceSettings& settings,
                              uint64_t stream = 0);

// A rendered view's glare: the luminaires' UGR (LuminaireGlare: ugr, sources, verticalLux,
// backgroundCdM2) and, from a fisheye image, DGP.
struct ViewGlare : LuminaireGlare {
  std::optional<ImageGlare> dgp;    // fisheye views only
  // The image's glare sources (DGP's, fisheye views with any) pooled: their pixels' solid-angle
  // weighted mean luminance, cd/m², and its relative standard error (meanStandardError over the
  // mean; NaN when the image has no error estimate). Unset without image glare sources (UGR's
  // luminaires have closed-form luminances, no Monte Carlo error).
  std::optional<double> sourceLuminanceCdM2;
  std::optional<double> sourceLuminanceRelativeStandardError;
};

// Observers' vertical illuminances take random streams from here (sensor points use their
// index, camera rays 2^48 and up).
inline constexpr uint64_t kObserverStreamBase = streams::kObservers.first;

// An [[observer]]'s eye as a view: at its eye height, looking along its horizontal direction.
View observerView(const ObserverSpec& o);

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
