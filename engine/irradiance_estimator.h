// The sensor estimator: irradiance at one point from the sampled sources (engine/integrator_direct.h)
// and the paper's stratified cosine-weighted hemisphere (eq. 3) with path-traced interreflection
// (engine/integrator_path.h), adaptive super-sampling of the strata whose neighbours disagree,
// and the variance of the estimate from its own samples (derivations: docs/estimator.md).
#pragma once

#include "engine/irradiance_cache.h"
#include "engine/response.h"
#include "engine/tracer.h"
#include "engine/random_streams.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace candela {

struct SkyTally;

// Irradiance estimate at a point: RGB irradiance in W/m² and the variance of its photopic value
// (from the estimator's own sample variance; stratification makes it an upper bound).
struct IrradianceEstimate {
  Rgb irradiance{0.0};
  double variancePhotopic = 0.0;
  // The part of variancePhotopic due to the irradiance cache's records (cache method): the
  // cache is frozen, so every batch of a point shares it and more batches do not reduce it.
  double varianceRecordsPhotopic = 0.0;
  bool withoutCache = false;  // cache method: the point was estimated by the path method instead
  double illuminanceLux() const { return illuminanceFromIrradiance(irradiance); }
  double standardErrorLux() const;
};

// The stream of a point's hemisphere directions under the cache method, apart from its other
// samples, so that phase A (cacheQueries) traces exactly the directions evaluation will.
inline constexpr uint64_t kDirectionStream = streams::kDirections.first;

// The hemisphere's M × N strata for s.hemisphereSamples rays (N ≈ πM).
inline int hemisphereThetaStrata(const TraceSettings& s) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(s.hemisphereSamples / kPi))));
}
inline int hemispherePhiStrata(const TraceSettings& s) {
  return std::max(1, s.hemisphereSamples / hemisphereThetaStrata(s));
}
// The strata of a response's rays (engine/response.h). The cylindrical family spans θ in
// [0, π] with its density sin²θ/(π/2) largest at the horizon, where a stratum is π/(2M) high
// and 2π/N wide: N ≈ 4M makes them square, and an even M puts the horizon (sky against ground)
// on a stratum boundary. Planar and hemispherical take the hemisphere's.
inline int hemisphereThetaStrata(const TraceSettings& s, const Response& r) {
  if (r.kind != Quantity::kCylindrical && r.kind != Quantity::kSemiCylindrical) return hemisphereThetaStrata(s);
  return std::max(2, 2 * static_cast<int>(std::lround(0.25 * std::sqrt(static_cast<double>(s.hemisphereSamples)))));
}
inline int hemispherePhiStrata(const TraceSettings& s, const Response& r) {
  return std::max(1, s.hemisphereSamples / hemisphereThetaStrata(s, r));
}

// What an estimate reads and reports besides its point: the frozen irradiance cache
// (Method::kCache; the indirect irradiance at the hemisphere rays' first diffuse hits), and the
// daylight-coefficient observer (engine/sky_tally.h). Either may be null.
struct EstimatorInputs {
  const IrradianceCache* cache = nullptr;
  SkyTally* tally = nullptr;
};

// Irradiance on the side of unit normal n at p (W/m², and its variance) in the tracer's scene.
// `pointIndex` selects the random stream, so the result depends only on (seed, pointIndex), never
// on threads. With in.cache (Method::kCache) the indirect irradiance at the first diffuse hits
// of the hemisphere rays is taken from that frozen cache, a hit no record covers path traced.
IrradianceEstimate estimateIrradiance(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex,
                                      const TraceSettings& s, const EstimatorInputs& in = {});
// The quantity of `response` at p (engine/response.h: cylindrical, semi-cylindrical,
// hemispherical or planar illuminance), in the same units: the sources' light weighted by w(ω),
// the M × N strata drawn with density w/W (docs/quantities.md); planar: the call above.
IrradianceEstimate estimateIrradiance(const Tracer& tracer, const Vec3& p, const Response& response,
                                      uint64_t pointIndex, const TraceSettings& s, const EstimatorInputs& in = {});

// Variance of E = π/(MN) Σ y over M × N strata (y photopic radiance, cell j·N + k) from second
// differences along φ (n ≥ 3) or collapsed pairs; cells refined by adaptive super-sampling
// (ownBetween not NaN) take their own estimate ownBetween + ownWithin instead; recordShare (cache
// method): the records' expected share of each unrefined cell's squared second difference, taken
// off. Derivation: docs/estimator.md#stratified-variance.
double stratifiedVariance(const std::vector<double>& y, int m, int n, const std::vector<double>* ownBetween = nullptr,
                          const std::vector<double>* ownWithin = nullptr,
                          const std::vector<double>* recordShare = nullptr);

}  // namespace candela
