#include "cli/view_glare.h"

#include "engine/camera.h"

namespace candela::cli {

ViewGlare computeViewGlare(const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                           const Image& img, double glareThresholdCdM2) {
  ViewGlare g;
  const EyeLight eye = eyeLight(tracer, view, settings);
  for (const SeenLuminaire& s : eye.luminaires)
    if (s.transmittance > 0.0)
      g.sources.push_back({s.luminanceCdM2 * s.transmittance, s.solidAngleSr, positionIndex(s.directionView)});
  g.verticalLux = eye.verticalLux;
  g.backgroundCdM2 = eye.backgroundLuminanceCdM2();
  g.ugr = g.sources.empty() ? 0.0 : unifiedGlareRating(g.backgroundCdM2, g.sources);
  if (view.type == ViewType::kFisheye) {
    const ViewGeometry geo = viewGeometry(view);
    GlareDetection det;
    det.thresholdCdM2 = glareThresholdCdM2;
    g.dgp = evaluateImageGlare(img.luminance, geo.directionView, geo.solidAngleSr, img.width, img.height, det);
  }
  return g;
}

}  // namespace candela::cli
