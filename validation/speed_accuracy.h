// The speed–accuracy study of indirect illumination (docs/accuracy.md): a few scenes where
// interreflection dominates, each method over a range of settings, RMS and maximum relative error
// against a reference, wall time; written as CSV and a log–log SVG chart.
#pragma once

#include "engine/sensors.h"
#include "engine/tracer.h"
#include "engine/irradiance_estimator.h"

#include <string>
#include <vector>

namespace candela::validation {

// A scene in Radiance text with its sensor points and, where one exists, the closed-form
// illuminance at each (lux); otherwise the reference is a converged path-traced run.
struct IndirectScene {
  std::string name;
  std::string rad;
  std::vector<SensorPoint> points;
  std::vector<double> closedFormLux;  // empty: use referenceSettings()
  std::string reference;              // in words
};

// Integrating spheres ρ = 0.5 and 0.8, a grey sphere on a grey plane under sun and sky, a room
// lit only by an uplight, and a furnished office.
std::vector<IndirectScene> indirectScenes();

// The converged reference: the path tracer at 8192 hemisphere samples, 256 light samples,
// bounces left to Russian roulette, a seed of its own.
TraceSettings referenceSettings();

// The reference of a validation case on scene sc whose verdict allows `tolerance` (a fraction):
// referenceSettings(), each point taking further independent batches (TraceSettings::
// targetRelativeError) until its standard error is at most a tenth of the tolerance (at most
// 64 batches). A fixed sample count is not enough: near the sphere-on-plane contact 8192
// samples leave a 1.2 % standard error, so the reference alone moved a 3 % verdict by 1.4 %
// (docs/accuracy.md#near-contact-cache-bias-cause-and-fix).
std::vector<IrradianceEstimate> referenceEstimates(const IndirectScene& sc, double tolerance, int threads);

// Illuminance (lux) and standard errors of a scene's points under `s`; *seconds gets the wall
// time of the computation (cache filling included, scene building excluded), *rays the rays cast.
std::vector<IrradianceEstimate> runIndirectScene(const IndirectScene& sc, const TraceSettings& s, int threads,
                                                 double* seconds, double* rays = nullptr);

struct ChartRow {
  std::string scene, method, setting;
  int hemisphereSamples = 0;
  double accuracy = 0.0;  // cache only: Ward's a
  double seconds = 0.0;
  double rays = 0.0;      // rays cast (nearest-hit and shadow)
  double rmsRelativeError = 0.0, maxRelativeError = 0.0;
};

// Every scene × method × setting; `quick` uses fewer settings (for tests).
std::vector<ChartRow> runSpeedAccuracy(int threads, bool quick);
std::string speedAccuracyCsv(const std::vector<ChartRow>& rows);
// Log–log chart: wall time (s) against RMS relative error, one panel per scene, one line per method.
std::string speedAccuracySvg(const std::vector<ChartRow>& rows);

}  // namespace candela::validation
