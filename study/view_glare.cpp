#include "study/view_glare.h"

#include "engine/camera.h"
#include "metrics/contrast.h"

namespace candela {

LuminaireGlare luminaireGlare(const Tracer& tracer, const View& view, const TraceSettings& settings, uint64_t stream) {
  LuminaireGlare g;
  const EyeLight eye = eyeLight(tracer, view, settings, stream);
  for (const SeenLuminaire& s : eye.luminaires)
    if (s.transmittance > 0.0)
      g.sources.push_back({s.luminanceCdM2 * s.transmittance, s.solidAngleSr, positionIndex(s.directionView)});
  g.verticalLux = eye.verticalLux;
  g.backgroundCdM2 = eye.backgroundLuminanceCdM2();
  g.ugr = g.sources.empty() ? 0.0 : unifiedGlareRating(g.backgroundCdM2, g.sources);
  return g;
}

View observerView(const ObserverSpec& o) {
  View v;
  v.type = ViewType::kPerspective;
  v.positionM = o.eyeM();
  v.direction = Vec3(o.direction, 0.0);
  v.up = Vec3(0.0, 0.0, 1.0);
  return v;
}

ViewGlare computeViewGlare(const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                           const Image& img, double glareThresholdCdM2) {
  ViewGlare g;
  static_cast<LuminaireGlare&>(g) = luminaireGlare(tracer, view, settings);
  if (view.type == ViewType::kFisheye) {
    const PixelGeometry geo = ViewGeometry(view);  // one std::function for every call below
    GlareDetection det;
    det.thresholdCdM2 = glareThresholdCdM2;
    g.dgp = evaluateImageGlare(img.luminance, geo, img.width, img.height, det);
    // The pixels evaluateImageGlare groups into sources (metrics/glare.cpp: inside, above the
    // threshold, in front of the eye), all together.
    const double threshold = g.dgp->thresholdCdM2;
    auto sourceWeight = [&](std::size_t i) { return glareSourceSolidAngle(img.luminance, geo, i, threshold); };
    double sum = 0.0, omega = 0.0;
    for (std::size_t i = 0; i < img.luminance.size(); ++i) {
      const double w = sourceWeight(i);
      if (!(w > 0.0)) continue;
      sum += w * img.luminance[i];
      omega += w;
    }
    if (omega > 0.0) {
      g.sourceLuminanceCdM2 = sum / omega;
      g.sourceLuminanceRelativeStandardError = meanStandardError(img, sourceWeight) / *g.sourceLuminanceCdM2;
    }
  }
  return g;
}

double ViewContrast::crf() const { return contrastRenditionFactor(contrast, referenceContrast); }

ViewContrast computeViewContrast(const Scene& scene, const Tracer& tracer, const Vec3& eye, const Vec3& task,
                                 const Vec3& background, const TraceSettings& settings, const FileLoc& loc) {
  const Scene refScene =
      referenceSphereScene(scene, {shapeToward(tracer, eye, task), shapeToward(tracer, eye, background)});
  const Tracer ref(refScene);
  ViewContrast v;
  v.taskCdM2 = luminanceToward(tracer, eye, task, settings, 1);
  v.backgroundCdM2 = luminanceToward(tracer, eye, background, settings, 2);
  const double rt = luminanceToward(ref, eye, task, settings, 3);
  const double rb = luminanceToward(ref, eye, background, settings, 4);
  if (!(v.backgroundCdM2 > 0.0) || !(rb > 0.0) || rt == rb)
    throw InputError(loc, "task/background: the background is dark or task and background look alike under the "
                          "reference sphere; no contrast to rate");
  v.contrast = luminanceContrast(v.taskCdM2, v.backgroundCdM2);
  v.referenceContrast = luminanceContrast(rt, rb);
  return v;
}

}  // namespace candela
