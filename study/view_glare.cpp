#include "study/view_glare.h"

#include "engine/camera.h"
#include "metrics/contrast.h"

namespace candela {

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
    // The pixels evaluateImageGlare groups into sources (metrics/glare.cpp: inside, above the
    // threshold, in front of the eye), all together.
    std::vector<double> w(img.luminance.size(), 0.0);
    double sum = 0.0, omega = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i)
      if (geo.solidAngleSr[i] > 0.0 && img.luminance[i] > g.dgp->thresholdCdM2 && geo.directionView[i].z > 0.0) {
        w[i] = geo.solidAngleSr[i];
        sum += w[i] * img.luminance[i];
        omega += w[i];
      }
    if (omega > 0.0) {
      g.sourceLuminanceCdM2 = sum / omega;
      g.sourceLuminanceRelativeStandardError = meanStandardError(img, w) / *g.sourceLuminanceCdM2;
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
