#include "engine/trace_settings.h"

#include <stdexcept>

namespace candela {

const char* qualityName(Quality q) {
  switch (q) {
    case Quality::kDraft: return "draft";
    case Quality::kNormal: return "normal";
    case Quality::kHigh: return "high";
  }
  return "?";
}

Quality parseQuality(const std::string& s) {
  if (s == "draft") return Quality::kDraft;
  if (s == "normal") return Quality::kNormal;
  if (s == "high") return Quality::kHigh;
  throw std::invalid_argument("quality must be draft, normal or high, not '" + s + "'");
}

Method parseMethod(const std::string& s) {
  if (s == "path") return Method::kPath;
  if (s == "cache") return Method::kCache;
  throw std::invalid_argument("method must be path or cache, not '" + s + "'");
}

TraceSettings settingsForQuality(Quality q) {
  // Presets leave the number of bounces to Russian roulette by albedo (unbiased: a path ends
  // with probability 1 − albedo at each vertex), so closed bright rooms converge to the whole
  // series (E_d/(1 − ρ)); a cap of 32 would drop 0.9³³ = 3 % of a ρ = 0.9 box. --bounces N
  // still truncates on request.
  TraceSettings s;
  switch (q) {
    // Cache settings (a, record samples) from the speed–accuracy study (docs/accuracy.md).
    case Quality::kDraft:
      s.hemisphereSamples = 256;
      s.lightSamples = 16;
      s.maxBounces = kUnlimitedBounces;
      s.cache.accuracy = 0.3;
      s.cache.recordSamples = 64;
      break;
    case Quality::kNormal:
      s.hemisphereSamples = 2048;
      s.lightSamples = 64;
      s.maxBounces = kUnlimitedBounces;
      s.cache.accuracy = 0.2;
      s.cache.recordSamples = 256;
      // The office demo's median point has a standard error of 0.18 % at these counts; points
      // above 0.25 % take more batches, at most kPresetMaxBatches (docs/accuracy.md). A study's
      // grids take the grids' target instead (docs/estimator.md#the-grids-error-target).
      s.targetRelativeError = 0.0025;
      s.gridTargetRelativeError = kPresetGridTarget;
      s.maxBatches = kPresetMaxBatches;
      break;
    case Quality::kHigh:
      s.hemisphereSamples = 8192;
      s.lightSamples = 256;
      s.maxBounces = kUnlimitedBounces;
      s.cache.accuracy = 0.1;
      s.cache.recordSamples = 1024;
      // The same ceiling on any point's error as normal: high's four times the samples lower the
      // typical point's error (0.09 % on the office demo), the target only the outliers'.
      s.targetRelativeError = 0.0025;
      s.gridTargetRelativeError = kPresetGridTarget;
      s.maxBatches = kPresetMaxBatches;
      break;
  }
  return s;
}

double expectedBatchesPerPoint(const TraceSettings& s) {
  if (s.targetRelativeError <= 0.0) return 1.0;
  return s.maxBatches <= kPresetMaxBatches ? 1.25 : 4.0;
}

}  // namespace candela
