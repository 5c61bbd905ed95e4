// Direct light at path vertices (not at sensors): each of the k samples first chooses ONE light
// with probability p_l = 0.9 · w_l / Σw + 0.1 / n (w_l a cheap estimate of its unoccluded
// irradiance, mixed with a uniform floor so that every light that can contribute has p_l > 0),
// then one point of it; the estimate f V / p_l is unbiased and costs one shadow ray per sample
// whatever the number of lights. Sensors keep the per-light ratio estimator (integrator_direct.cpp), which
// is exact for wholly visible sources.
#pragma once

#include "engine/accelerator.h"
#include "engine/lights.h"
#include "engine/sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace candela {

// A cheap estimate (W/m²) of the unoccluded irradiance from `light` at p (normal n): the source
// reduced to a point at its centre (the disk and cap formulas for spheres and the sun), clamped
// near the source. Zero only where the light certainly cannot reach: behind a one-sided source.
double lightImportance(const Light& light, const Scene& scene, const Vec3& p, const Vec3& n);

// lightImportance of a luminaire, inline for the selection's loop (one square root and two
// divisions): its largest intensity over the C planes at p's angle from the nadir (the tabulated
// band's, LuminaireSource::peakByCosGamma; the exact intensity towards p without a table), times
// the cosine at the receiver plus 0.05, over the distance squared (at least a quarter of the
// opening's size squared).
inline double luminaireImportance(const LuminaireSource& lum, const Vec3& p, const Vec3& n) {
  const Vec3 e = p - lum.position;
  const double r2 = glm::dot(e, e);
  double cosI = 1.0, cosG = 1.0, inv = 0.0;
  if (r2 > 0.0) {
    inv = 1.0 / std::sqrt(r2);
    cosI = std::max(0.0, -glm::dot(n, e) * inv);
    cosG = -glm::dot(e, lum.axisZ) * inv;
  }
  double peak;
  if (lum.peakTabulated) {
    const int bin = std::clamp(static_cast<int>((cosG + 1.0) * 0.5 * LuminaireSource::kCosBins), 0,
                               LuminaireSource::kCosBins - 1);
    peak = lum.peakByCosGamma[static_cast<size_t>(bin)];
  } else {
    peak = lum.intensityCd(r2 > 0.0 ? e * inv : -lum.axisZ);
  }
  const double size = lum.sizeM();
  return peak * (cosI + 0.05) / (kLumensPerWatt * std::max(r2, 0.25 * size * size + 1e-6));
}

// `visibility(p, sample, tMax, lightShape)` returns the RGB transmittance of the shadow ray of a
// LightSample (and any weight the receiver gives its direction: integrator_direct.h); `cdf` is
// the caller's scratch (TraceContext), reused from call to call. A glow counts with the share
// glowShare[l] of its light when given (a cache lookup: LightScratch::glowShare), else fully
// where glowSampledFrom(smallSin2) samples it from p and not at all elsewhere.
// `patterns` evaluates the lights' function patterns (sampleLight; nullptr when the scene has none).
// 11 parameters: the scene and point, the sample count and stream, the scratch, the patterns'
// evaluator, the visibility test and the glows' rule are separate inputs of one estimate.
template <class Visibility>
Rgb sampleLightsByImportance(const std::vector<Light>& lights, const Scene& scene, const Vec3& p, const Vec3& n,
                             int k, Rng& rng, std::vector<double>& cdf, PatternEvaluator* patterns,
                             const Visibility& visibility,
                             double smallSin2 = 0.0, const double* glowShare = nullptr) {
  const size_t count = lights.size();
  if (count == 0) return Rgb(0.0);
  auto share = [&](size_t l) {
    if (!lights[l].glow) return 1.0;
    if (glowShare) return glowShare[l];
    return glowSampledFrom(lights[l], p, smallSin2) ? 1.0 : 0.0;
  };
  cdf.resize(count);
  double total = 0.0;
  for (size_t l = 0; l < count; ++l) {
    const double s = share(l);
    if (!(s > 0.0)) {
      cdf[l] = 0.0;
      continue;
    }
    const Light& light = lights[l];
    total += cdf[l] = s * (light.kind == Light::Kind::kLuminaire ? luminaireImportance(scene.luminaires[light.luminaire], p, n)
                                                                  : lightImportance(light, scene, p, n));
  }
  if (total <= 0.0) return Rgb(0.0);
  double acc = 0.0;
  const double floor = 0.1 / static_cast<double>(count), scale = 0.9 / total;
  for (size_t l = 0; l < count; ++l) {
    const double w = cdf[l];
    acc += w > 0.0 ? w * scale + floor : 0.0;
    cdf[l] = acc;
  }
  if (acc <= 0.0) return Rgb(0.0);
  const Strata2D strata(k);
  Rgb sum(0.0);
  for (int i = 0; i < k; ++i) {
    const Vec2 u = strata.sample(i, rng);
    // Choose the light with u.x, reusing its position inside the chosen interval for sampling.
    const double target = u.x * acc;
    size_t l = std::lower_bound(cdf.begin(), cdf.end(), target) - cdf.begin();
    l = std::min(l, count - 1);
    const double lo = l == 0 ? 0.0 : cdf[l - 1];
    const double pl = (cdf[l] - lo) / acc;
    if (pl <= 0.0) continue;
    const double v1 = std::clamp((target - lo) / (cdf[l] - lo), 0.0, 1.0 - 1e-12);
    LightSample ls;
    if (!sampleLight(lights[l], scene, p, v1, u.y, ls, patterns)) continue;
    const double cosI = glm::dot(n, ls.dir);
    if (cosI <= 0.0) continue;
    const uint32_t lightShape = lights[l].ownShape;
    const double tMax = std::isinf(ls.distance) ? std::numeric_limits<double>::infinity()
                                                : ls.distance * (1.0 - 1e-9);
    sum += ls.weight * ls.pattern * (cosI * share(l) / pl) * visibility(p, ls, tMax, lightShape);
  }
  return sum / static_cast<double>(k);
}

}  // namespace candela
