#include "study/annual_glare_check.h"

#include "base/error.h"
#include "engine/daylight.h"
#include "engine/tracer.h"
#include "engine/irradiance_estimator.h"

#include <chrono>
#include <cstdio>

namespace candela {

Scene hourScene(const HourSceneInput& in, int hour) {
  if (!in.geometry || !in.epw || !in.sky) throw std::invalid_argument("hourScene: geometry, weather and sky needed");
  const AnnualHour& h = in.sky->hours.at(static_cast<size_t>(hour));
  const EpwRecord& rec = in.epw->records.at(static_cast<size_t>(hour));
  const FileLoc loc{"", rec.line, 0};
  if (!(h.diffuseHorizontalLux > 0.0) && !(h.directNormalLux > 0.0))
    throw InputError(loc, "annual glare check: the chosen hour has no daylight");
  Scene scene = *in.geometry;
  scene.sky.reset();
  DaylightSpec d;
  d.skyType = {SkyKind::kPerez};
  d.skyLoc = loc;
  // The sky vectors' sun (SPA at the middle of the hour-ending record) given directly; the time
  // only sets the day of the year.
  d.sunAltitudeDeg = h.sunAltitudeDeg;
  d.sunAzimuthDeg = h.sunAzimuthDeg;
  char time[40];
  std::snprintf(time, sizeof time, "%04d-%02d-%02dT%02d:30", rec.year, rec.month, rec.day, rec.hour - 1);
  d.time = time;
  d.northDeg = in.northDeg;
  d.directNormalWm2 = std::max(0.0, rec.directNormalWhm2);
  d.diffuseHorizontalWm2 = std::max(0.0, rec.diffuseHorizontalWhm2);
  d.groundReflectance = in.groundReflectance;
  addDaylight(scene, d);
  return scene;
}

RenderedGlare renderedGlare(const Tracer& tracer, const GlareView& view, const TraceSettings& settings, int threads,
                            const GlareSourceThreshold& threshold, const RenderedGlareOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const ViewFrame frame = viewFrame(view.direction);
  View v;
  v.type = ViewType::kFisheye;
  v.positionM = view.eyeM;
  v.direction = frame.forward;
  v.up = frame.up;
  v.fovDeg = {180.0, 180.0};
  v.resolution = {options.resolutionPx, options.resolutionPx};
  const Image img = renderView(tracer, v, settings, threads, options.render);
  const ViewGeometry geo(v);
  GlareDetection det;
  det.thresholdCdM2 = threshold.fixedCdM2;
  det.averageFactor = threshold.factorOfMean;
  RenderedGlare out;
  out.image = evaluateImageGlare(img.luminance, geo, img.width, img.height, det);
  // The same pixels, each its own source.
  std::vector<GlareSource> pixels;
  Vec3 dir;
  double omega = 0.0;
  for (std::size_t i = 0; i < img.luminance.size(); ++i) {
    if (!(glareSourceSolidAngle(img.luminance, geo, i, out.image.thresholdCdM2) > 0.0)) continue;
    geo(i, dir, omega);
    pixels.push_back({img.luminance[i], omega, positionIndex(dir)});
  }
  out.dgpPerPixel = daylightGlareProbability(out.image.verticalIlluminanceLux, pixels, det.lowLightCorrection);
  const IrradianceEstimate e = estimateIrradiance(tracer, view.eyeM, frame.forward, options.evStream, settings);
  out.sensorEvLux = e.illuminanceLux();
  out.sensorEvStandardErrorLux = e.standardErrorLux();
  out.dgpSensorEv = daylightGlareProbability(out.sensorEvLux, out.image.sources, det.lowLightCorrection);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::vector<GlareHourCheck> checkChosenHours(const HourSceneInput& in, const GlareView& view,
                                             const ViewAnnualGlare& imageless, const std::vector<int>& hours,
                                             const TraceSettings& settings, int threads,
                                             const ImagelessGlareOptions& imagelessOptions,
                                             const RenderedGlareOptions& options) {
  std::vector<GlareHourCheck> out;
  for (int h : hours) {
    const Scene scene = hourScene(in, h);
    const Tracer tracer(scene);
    const RenderedGlare r = renderedGlare(tracer, view, settings, threads, imagelessOptions.threshold, options);
    GlareHourCheck c;
    c.hour = h;
    c.imagelessDgp = imageless.dgp.at(static_cast<size_t>(h));
    c.imagelessEvLux = imageless.verticalLux.at(static_cast<size_t>(h));
    c.renderedDgp = imagelessOptions.lowLightCorrection ? r.image.dgp : r.image.dgpUncorrected;
    c.renderedDgpPerPixel = r.dgpPerPixel;
    c.renderedEvLux = r.image.verticalIlluminanceLux;
    c.renderedSensorEvLux = r.sensorEvLux;
    c.renderedDgpSensorEv = r.dgpSensorEv;
    c.renderedSources = static_cast<int>(r.image.sources.size());
    c.renderS = r.seconds;
    out.push_back(c);
  }
  return out;
}

}  // namespace candela
