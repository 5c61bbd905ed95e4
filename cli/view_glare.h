// Glare of a rendered view, shared by `candela render` and `candela run`: UGR (CIE 117) from the
// luminaires seen along the view direction against the indirect background at the eye, and DGP
// (Wienold & Christoffersen 2006) from the image when the view is a fisheye.
#pragma once

#include "engine/case_file.h"
#include "engine/render.h"
#include "engine/tracer.h"
#include "metrics/glare.h"

#include <optional>

namespace candela::cli {

struct ViewGlare {
  double ugr = 0.0;                 // CIE 117 unified glare rating
  std::vector<GlareSource> sources; // luminaires counted in the UGR
  double verticalLux = 0.0;         // illuminance at the eye, lux
  double backgroundCdM2 = 0.0;      // UGR background luminance
  std::optional<ImageGlare> dgp;    // fisheye views only
};

ViewGlare computeViewGlare(const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                           const Image& img, double glareThresholdCdM2);

}  // namespace candela::cli
