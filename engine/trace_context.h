// The state of one top-level trace — a sensor point, a cache record, a camera pixel, one call of
// rayRadiance — passed explicitly to every function below it: the tracer and settings, the
// random stream its paths draw from, the daylight-coefficient observer, the rays it cast and the
// scratch its light samples reuse. No state lives in threads (docs/architecture.md).
#pragma once

#include "base/math.h"
#include "base/rng.h"
#include "engine/materials/pattern_hook.h"
#include "engine/tracer.h"

#include <array>
#include <cstdint>
#include <vector>

namespace candela {

struct SkyTally;

// Scratch of the direct-light estimators, reused by every sample of one top-level call: sized on
// first use, so no allocation per ray once warm.
struct LightScratch {
  std::vector<Vec3> clipped;              // a polygon source clipped to the receiver's horizon
  std::vector<std::array<Vec3, 3>> tris;  // its triangulation
  std::vector<double> cumulative;         // the triangles' cumulative areas
  std::vector<double> zRatio, zRest, fyS, vyS;  // per-stratum terms of the variance
  std::vector<double> cdf;                // light selection at path vertices (light_selection.h)
  // At a cache lookup: per light, the interpolation weight of the records that left that glow
  // out (sampled from them), which the lookup's direct light then carries instead of the rule at
  // its own point (engine/integrator_path.cpp, cachedVertex); used while useGlowShare is set.
  std::vector<double> glowShare;
  bool useGlowShare = false;
  PortalView portals;                     // the portals seen from the receiver (engine/portals.h)
};

struct TraceContext {
  TraceContext(const Tracer& t, const TraceSettings& s, Rng& r, SkyTally* observer = nullptr)
      : tracer(t), settings(s), rng(r), tally(observer), smallSin2(smallEmitterSin2(s.hemisphereSamples)) {}
  // The call ends: its rays join the tracer's total (Tracer::raysTraced).
  ~TraceContext() { tracer.addRays(rays); }
  TraceContext(const TraceContext&) = delete;
  TraceContext& operator=(const TraceContext&) = delete;

  // Nearest hit along (o, d), counted.
  bool intersect(const Vec3& o, const Vec3& d, double tMin, double tMax, RayHit& h, uint32_t skip) {
    ++rays;
    return tracer.accelerator().intersect(o, d, tMin, tMax, h, skip);
  }
  // Tracer::transmittance, its rays counted here (patterned glass and trans evaluated by this
  // call's evaluator), from a point in antimatter clip state `clip` (nullptr: empty).
  Rgb transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB,
                    const ClipState* clip = nullptr) {
    uint32_t firstGlass = kNoShape;
    return tracer.transmittance(o, dir, tMax, skipA, skipB, rays, firstGlass, patternsIfAny(), clip);
  }
  // The function patterns' evaluator of this call, made on first use.
  PatternEvaluator& patterns() {
    if (!patternEval) patternEval = std::make_unique<PatternEvaluator>(tracer.scene());
    return *patternEval;
  }
  // The evaluator when the scene has function patterns, else nullptr (nothing made).
  PatternEvaluator* patternsIfAny() { return tracer.hasPatterns() ? &patterns() : nullptr; }

  const Tracer& tracer;
  const TraceSettings& settings;
  Rng& rng;          // the stream paths and light samples draw from
  SkyTally* tally;   // daylight-coefficient observer (engine/sky_tally.h), or none
  uint64_t rays = 0;  // rays cast by this call so far
  // The small-emitter bound of this call's settings (lights.h: glowSampledFrom), computed once.
  const double smallSin2;
  LightScratch light;
  std::unique_ptr<PatternEvaluator> patternEval;
};

}  // namespace candela
