// The rendered check of imageless annual glare (docs/annual-glare.md): at chosen hours of the
// year, the hour's Perez sky and sun as a point-in-time sky, a 180° fisheye of the view rendered
// with the view machinery (engine/render.h), and its DGP from the image (metrics/glare.h
// evaluateImageGlare), beside the imageless DGP and Ev of the same hour. The image sees what the
// imageless method leaves out — sunlit surfaces, reflections in glass, a closed blind's glow —
// and the evalglare way of grouping the source pixels.
#pragma once

#include "engine/render.h"
#include "engine/scene.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "study/annual_glare.h"

#include <vector>

namespace candela {

// The point-in-time scene of hour `hour` of `sky` (built from `epw`): a copy of `geometry` (its
// own sky dropped) under the record's Perez sky with the sun at the hour's middle (the sky
// vectors' position), as a point-in-time Perez run builds it (engine/daylight.h addDaylight).
// Throws InputError when the hour has no daylight.
struct HourSceneInput {
  const Scene* geometry = nullptr;
  const EpwFile* epw = nullptr;
  const AnnualSky* sky = nullptr;
  double northDeg = 0.0;
  double groundReflectance = 0.2;
};
Scene hourScene(const HourSceneInput& in, int hour);

struct RenderedGlareOptions {
  int resolutionPx = 256;  // square 180° × 180° equiangular fisheye
  // Every pixel traced (the sun is smaller than a pixel: a coarse lattice could step over it),
  // 4 stratified rays a pixel, matte surfaces as ρE/π from 64 hemisphere samples (views' default).
  RenderSettings render = [] {
    RenderSettings r;
    r.coarseStep = 1;
    r.samplesPerPixel = 4;
    r.irradianceSamples = 64;
    return r;
  }();
  // Random stream of the sensor estimate of Ev at the eye (apart from the pixels' and the grids').
  uint64_t evStream = kAnnualGlareStreamBase - 1;
};

struct RenderedGlare {
  ImageGlare image;           // evaluateImageGlare: pixels above the threshold grouped (evalglare)
  double dgpPerPixel = 0.0;   // every pixel above the threshold its own source (as the imageless tally)
  // Ev at the eye from the sensor estimator (the sun and sky sampled explicitly, estimateIrradiance),
  // and the image's DGP with it in place of the image's Ev (evalglare's -i): a sun smaller than a
  // pixel makes the image's own Ev noisy (docs/annual-glare.md).
  double sensorEvLux = 0.0, sensorEvStandardErrorLux = 0.0;
  double dgpSensorEv = 0.0;
  double seconds = 0.0;
};
// The view rendered through `tracer` (any scene state) and rated with `threshold` (a fixed
// luminance, or its factor × the image's mean luminance).
RenderedGlare renderedGlare(const Tracer& tracer, const GlareView& view, const TraceSettings& settings, int threads,
                            const GlareSourceThreshold& threshold, const RenderedGlareOptions& options = {});

struct GlareHourCheck {
  int hour = 0;  // index into the sky's hours
  double imagelessDgp = 0.0, imagelessEvLux = 0.0;
  double renderedDgp = 0.0, renderedDgpPerPixel = 0.0, renderedEvLux = 0.0;
  double renderedSensorEvLux = 0.0, renderedDgpSensorEv = 0.0;  // RenderedGlare's sensorEvLux, dgpSensorEv
  int renderedSources = 0;
  double renderS = 0.0;
  double dgpDifference() const { return renderedDgp - imagelessDgp; }
  double evRelativeDifference() const { return imagelessEvLux > 0.0 ? renderedEvLux / imagelessEvLux - 1.0 : 0.0; }
};
// Each chosen hour's scene traced and rendered in turn, beside the view's imageless year.
std::vector<GlareHourCheck> checkChosenHours(const HourSceneInput& in, const GlareView& view,
                                             const ViewAnnualGlare& imageless, const std::vector<int>& hours,
                                             const TraceSettings& settings, int threads,
                                             const ImagelessGlareOptions& imagelessOptions,
                                             const RenderedGlareOptions& options = {});

}  // namespace candela
