// What one run of the tracer samples: quality presets, the interreflection method, sample counts
// and cache settings. The single place where preset and method names are parsed and printed.
#pragma once

#include <cstdint>
#include <string>

namespace candela {

// Sample-count presets (docs/engine.md says what each stands for).
enum class Quality { kDraft, kNormal, kHigh };
const char* qualityName(Quality q);
// Parses "draft", "normal" or "high"; throws std::invalid_argument otherwise.
Quality parseQuality(const std::string& s);

struct CacheSettings {
  double accuracy = 0.1;       // Ward's a: records are used where w_i > 1/a
  int recordSamples = 1024;    // hemisphere rays per record
  int radiusSamples = 128;     // rays per record for its harmonic mean distance (phase A)
  int lightSamples = 4;        // light samples at a sensor ray's hit (direct light there is not cached)
  double minSpacingM = 0.005;  // bounds on a record's valid radius a·R_i (m)
  double maxSpacingM = 1.0;
  bool gradients = true;
  // Use a record only where a ray joins it to the point without meeting a third surface: a thin
  // wall between a lit and a dark room then stops light leaking along the floor (costs one
  // shadow ray per candidate record).
  bool visibilityCheck = true;
  // 1: records at the first diffuse hits of sensor rays, deeper bounces path traced. 2: a second
  // cache at the first diffuse hits of those records' rays (deeperLevel()), path traced beyond.
  int levels = 1;
};

// How interreflection is computed: an unbiased path tracer (the reference) or Ward's irradiance
// cache at the first diffuse bounce of sensor rays, deeper bounces path traced
// (docs/accuracy.md).
enum class Method { kCache, kPath };
// Parses "path" or "cache"; throws std::invalid_argument otherwise.
Method parseMethod(const std::string& s);

// The presets' bounce limit: a safety cap only; Russian roulette ends paths long before
// (expected length 1/(1 − albedo)).
inline constexpr int kUnlimitedBounces = 1000;

// What --target-error (and [settings] target_error) may spend: 256 batches of the point's
// settings. The presets' own target stops at kPresetMaxBatches.
inline constexpr int kExplicitTargetMaxBatches = 256;
inline constexpr int kPresetMaxBatches = 16;
// The normal and high presets' target for a study's grids (TraceSettings::gridTargetRelativeError).
inline constexpr double kPresetGridTarget = 0.005;

// Sample counts and limits of one run. Passed explicitly; no global options.
struct TraceSettings {
  int hemisphereSamples = 2048;  // cosine-weighted hemisphere rays per sensor point
  int lightSamples = 64;         // stratified samples per sampled light source per sensor point
  int maxBounces = 32;           // diffuse reflections followed (0: direct light and glow only)
  int firstBounceSplit = 16;     // continuations at the first diffuse vertex of each sensor ray
  double adaptiveFraction = 0.5; // extra hemisphere samples spent on the most varying strata
  uint64_t seed = 1;
  Method method = Method::kPath;
  CacheSettings cache;           // used by Method::kCache
  // When > 0, each sensor point takes further independent batches of samples (each as above,
  // its own random stream) until its standard error is at most this fraction of its value, or
  // maxBatches are spent. The normal and high presets set a target that the typical point meets
  // with its first batch, so that only points far noisier than the rest (near contact, in a
  // shadow lit by interreflection) take more; --target-error sets another (docs/accuracy.md).
  double targetRelativeError = 0.0;
  // The grids' target (docs/estimator.md#the-grids-error-target): when > 0 and the points come in
  // groups (computeIrradianceInBlocks' groupEnds: a study's grids), it replaces the per-point
  // target: a point takes further batches until its standard error is at most this fraction of
  // the larger of its value and its group's mean, at most maxBatches. The normal and high presets
  // set it; an explicit --target-error turns it off (study/trace_options.cpp).
  double gridTargetRelativeError = 0.0;
  int maxBatches = kExplicitTargetMaxBatches;
};

// The expected batches per point, for resource estimates: 1 without a target; with a preset's
// target the few points above it (the office demo: 1.1–1.2 batches per point on average,
// docs/accuracy.md); 4 with an explicit target, whose cost depends on the scene.
double expectedBatchesPerPoint(const TraceSettings& s);

// The sample counts a preset stands for (see docs/engine.md for why).
TraceSettings settingsForQuality(Quality q);

}  // namespace candela
