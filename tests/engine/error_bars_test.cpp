// The error bars (standard errors) mean what they say: over many seeds, about 68 % of the
// estimates fall within one standard error of the exact answer (a normal estimate's share), for
// the path tracer, the irradiance cache and --target-error. With N seeds the observed share has
// a binomial standard deviation √(0.68·0.32/N) = 2.3 % at N = 400; the path tracer's lower
// bound is 4 of those below 68 % (error bars too small: the dangerous side). Stratified
// sampling has no unbiased variance estimate, so the path tracer's are upper bounds
// (engine/irradiance_estimator.cpp, stratifiedVariance); its upper bound, 90 %, says they are not grossly
// inflated (a bar 1.6× too wide covers 95 %). Estimates whose variance is unbiasedly estimated
// (the cache's records; strata refined by adaptive super-sampling, which carry the variance
// under small sky openings) are held to 68 % ± 3 binomial standard deviations both ways
// (61–75 %): a bar 20 % too wide covers 77 %, 20 % too narrow 59 %. Measured shares are printed
// and listed in docs/accuracy.md.
#include "engine/daylight.h"
#include "engine/radiance/reader.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "validation/analytic.h"
#include "tests/support/aperture_scenes.h"
#include "tests/engine/test_materials.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace candela {
namespace {

constexpr int kSeeds = 400;
constexpr double kLo = 0.68 - 4 * 0.0233, kHi = 0.90;
// Calibrated bars: 68 % ± 3 binomial standard deviations of a share over kSeeds results.
const double kBandSd = std::sqrt(0.68 * 0.32 / kSeeds);
const double kBandLo = 0.68 - 3 * kBandSd, kBandHi = 0.68 + 3 * kBandSd;

using test_support::addMaterial;

// Share of seeds whose estimate lies within one standard error of `exact`; also returns the mean
// relative error bar.
double coverage(const std::function<IrradianceEstimate(uint64_t seed)>& run, double exact, const char* what) {
  int inside = 0;
  double relErr = 0.0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const IrradianceEstimate e = run(static_cast<uint64_t>(seed) + 1);
    inside += std::abs(e.illuminanceLux() - exact) <= e.standardErrorLux();
    relErr += e.standardErrorLux() / exact;
  }
  const double share = static_cast<double>(inside) / kSeeds;
  std::printf("[ measured ] %s: %.1f %% within one error bar (mean error bar %.3g %%)\n", what, 100 * share,
              100 * relErr / kSeeds);
  return share;
}

Scene skyOverGround() {
  Scene sc;
  const uint32_t sky = addMaterial(sc, MaterialType::kGlow, 1.0);
  sc.addDistant(Vec3(0, 0, 1), 180.0, sky, "sky");
  const uint32_t grey = addMaterial(sc, MaterialType::kPlastic, 0.3);
  sc.addPolygon({{-1e4, -1e4, 0}, {1e4, -1e4, 0}, {1e4, 1e4, 0}, {-1e4, 1e4, 0}}, grey);
  return sc;
}

Scene integratingSphere(double rho) {
  Scene sc;
  sc.addSphere(Vec3(0.0), 0.02, addMaterial(sc, MaterialType::kLight, 1000.0));
  sc.addSphere(Vec3(0.0), 1.0, addMaterial(sc, MaterialType::kPlastic, rho), true);
  return sc;
}

// A sensor tilted 60° 1 m above the open ground: sky over (1 + cos β)/2 of π, ground of
// radiance ρL over the rest.
constexpr double kBeta = 60.0;
double tiltedExact() {
  const double c = std::cos(degToRad(kBeta));
  return kLumensPerWatt * kPi * (0.5 * (1 + c) + 0.3 * 0.5 * (1 - c));
}
SensorPoint tiltedSensor() {
  return {Vec3(0, 0, 1), Vec3(std::sin(degToRad(kBeta)), 0, std::cos(degToRad(kBeta)))};
}

// Facing the centre from 0.9 m: E_d + (1 − (r/d)²) ρ E_w/(1 − ρ(1 − r²)) (the black lamp takes a
// fraction r² of the light each wall point reflects: 0.16 % at ρ 0.8, a sixth of a bar there).
double sphereExact(double rho) {
  const double d = 0.9, r = 0.02;
  return kLumensPerWatt * (analytic::sphereSource(1000.0, r, d, 1.0) +
                           (1.0 - (r / d) * (r / d)) * rho * analytic::sphereSource(1000.0, r, 1.0, 1.0) /
                               (1.0 - rho * (1.0 - r * r)));
}

// Few samples a point, so that many seeds' estimates spread enough to count their coverage.
TraceSettings coverageSettings() {
  TraceSettings s;
  s.hemisphereSamples = 64;
  s.lightSamples = 4;
  s.firstBounceSplit = 4;
  return s;
}

TEST(ErrorBars, PathTracerCoversItsShare) {
  const Scene ground = skyOverGround(), sphere = integratingSphere(0.5);
  const Tracer tg(ground), ts(sphere);
  TraceSettings s = coverageSettings();
  const SensorPoint tilted = tiltedSensor();
  const double a = coverage([&](uint64_t seed) {
    TraceSettings t = s;
    t.seed = seed;
    return estimateIrradiance(tg, tilted.position, tilted.normal, 0, t);
  }, tiltedExact(), "path, tilted sensor over open ground");
  const double b = coverage([&](uint64_t seed) {
    TraceSettings t = s;
    t.seed = seed;
    return estimateIrradiance(ts, Vec3(0.9, 0, 0), Vec3(-1, 0, 0), 0, t);
  }, sphereExact(0.5), "path, integrating sphere rho 0.5");
  EXPECT_GE(a, kLo);
  EXPECT_LE(a, kHi);
  EXPECT_GE(b, kLo);
  EXPECT_LE(b, kHi);
}

// Cylindrical, semi-cylindrical and hemispherical illuminance (engine/response.h) 1.2 m above
// the open grey ground (ρ 0.3) under the uniform glow dome: ∫ w over the upper hemisphere is
// π/2 for the cylindrical pair, over the lower the same (docs/quantities.md), the ground's
// radiance ρL; the rays of the cylindrical family go below the horizon too, into the ground's
// light. About a vertical axis the hemispherical estimate sees L alone and is exact (its warp
// draws ∝ w), so its axis is tilted by β = 60° as tiltedSensor's: (1 + cos θ')/4 over the tilted
// hemisphere is ¼ of its solid angle above and below the horizon (a lune of 2(π − β) sr
// above, 2β below) plus ¼ of the tilted plane's illuminance.
TEST(ErrorBars, QuantitiesCoverTheirShare) {
  const Scene ground = skyOverGround();
  const Tracer tg(ground);
  TraceSettings s = coverageSettings();
  const Vec3 up(0, 0, 1), p(0, 0, 1.2);
  const double L = kLumensPerWatt;
  const struct {
    Response r;
    double exact;
    const char* what;
  } cases[] = {{{Quantity::kCylindrical, up, Vec3(1, 0, 0)}, 0.5 * kPi * L * 1.3, "path, cylindrical over open ground"},
               {{Quantity::kSemiCylindrical, up, glm::normalize(Vec3(1, 1, 0))}, 0.5 * kPi * L * 1.3,
                "path, semi-cylindrical over open ground"},
               {{Quantity::kHemispherical, tiltedSensor().normal, Vec3(0, 1, 0)},
                0.25 * (L * (2.0 * (kPi - degToRad(kBeta)) + 0.3 * 2.0 * degToRad(kBeta)) + tiltedExact()),
                "path, hemispherical about a tilted axis over open ground"}};
  for (const auto& c : cases) {
    const double a = coverage([&](uint64_t seed) {
      TraceSettings t = s;
      t.seed = seed;
      return estimateIrradiance(tg, p, c.r, 0, t);
    }, c.exact, c.what);
    EXPECT_GE(a, kLo) << c.what;
    EXPECT_LE(a, kHi) << c.what;
  }
}

TEST(ErrorBars, PartlyHiddenPanelCoversItsShare) {
  // Direct light only: a 1 m light panel 2 m above the sensor, and a black sheet halfway up
  // covering x < 0: a ray to the panel point (x, y, 2) crosses z = 1 at (x/2, y/2), so exactly
  // the panel's x < 0 half is hidden, E = the x > 0 half's configuration factor (corner
  // rectangles). The ratio estimator's samples then carry V = 0 or 1 by whole strata columns.
  Scene sc;
  const uint32_t lamp = addMaterial(sc, MaterialType::kLight, 100.0), black = addMaterial(sc, MaterialType::kPlastic, 0.0);
  sc.addPolygon({{-0.5, -0.5, 2}, {-0.5, 0.5, 2}, {0.5, 0.5, 2}, {0.5, -0.5, 2}}, lamp);
  sc.addPolygon({{-5, -5, 1}, {-5, 5, 1}, {0, 5, 1}, {0, -5, 1}}, black);
  const Tracer tracer(sc);
  TraceSettings s;
  s.hemisphereSamples = 16;
  s.lightSamples = 16;
  s.maxBounces = 0;
  const double exact = kLumensPerWatt * analytic::rectangleAbove(100.0, {0.0, -0.5, 0.5, 0.5}, 2.0, 0.0, 0.0);
  const double a = coverage([&](uint64_t seed) {
    TraceSettings t = s;
    t.seed = seed;
    return estimateIrradiance(tracer, Vec3(0.0), Vec3(0, 0, 1), 0, t);
  }, exact, "direct light, half-hidden panel (16 samples)");
  EXPECT_GE(a, kLo);
  EXPECT_LE(a, kHi);
}

// The cache method's settings of the integrating-sphere tests: 4 light samples, the given
// hemisphere samples, accuracy a and record rays.
TraceSettings sphereCacheSettings(int samples, double a, int recordSamples) {
  TraceSettings s;
  s.hemisphereSamples = samples;
  s.lightSamples = 4;
  s.method = Method::kCache;
  s.cache.accuracy = a;
  s.cache.recordSamples = recordSamples;
  return s;
}

TEST(ErrorBars, IrradianceCacheCoversItsShare) {
  // The cache's error bar is the law of total variance: the hemisphere's strata with the records
  // held fixed, plus the records' own noise through (E, G_r, G_t) and their covariance.
  for (double rho : {0.5, 0.8}) {
    const Scene sphere = integratingSphere(rho);
    const Tracer ts(sphere);
    const TraceSettings s = sphereCacheSettings(128, 0.3, 64);
    const std::vector<SensorPoint> pts = {{Vec3(0.9, 0, 0), Vec3(-1, 0, 0)}};
    const std::string what = "cache, integrating sphere rho " + std::to_string(rho).substr(0, 3);
    const double a = coverage([&](uint64_t seed) {
      TraceSettings t = s;
      t.seed = seed;
      return computeIrradiance(ts, pts, t, 1)[0];
    }, sphereExact(rho), what.c_str());
    EXPECT_GE(a, kBandLo) << rho;
    EXPECT_LE(a, kBandHi) << rho;
  }
}

TEST(ErrorBars, IrradianceCacheCoversItsShareAtNormalLikeSettings) {
  // Larger records and more hemisphere samples (normal's a and record rays): adaptive
  // super-sampling then refines 64 strata, whose sub-samples may miss the cache (the first
  // samples never do: phase A placed the records at their hits). Before the refined strata were
  // chosen without the records' values and estimated from their own samples this way
  // (engine/tracer.cpp), 59.2 % of 400 seeds fell within one bar (variance ratio 0.79).
  const Scene sphere = integratingSphere(0.5);
  const Tracer ts(sphere);
  const TraceSettings s = sphereCacheSettings(512, 0.2, 256);
  const std::vector<SensorPoint> pts = {{Vec3(0.9, 0, 0), Vec3(-1, 0, 0)}};
  const double a = coverage([&](uint64_t seed) {
    TraceSettings t = s;
    t.seed = seed;
    return computeIrradiance(ts, pts, t, 1)[0];
  }, sphereExact(0.5), "cache, integrating sphere rho 0.5, 512 samples, a 0.2, 256-ray records");
  EXPECT_GE(a, kBandLo);
  EXPECT_LE(a, kBandHi);
}

// coverage() of one point with a target error, with the largest relative error bar seen and
// how many seeds the cache method left to the path method.
struct TargetRun {
  double share = 0.0, worst = 0.0;
  int withoutCache = 0;
};
TargetRun coverageWithTarget(const Tracer& tracer, const SensorPoint& p, const TraceSettings& s, double exact,
                             const char* what) {
  TargetRun r;
  r.share = coverage([&](uint64_t seed) {
    TraceSettings t = s;
    t.seed = seed;
    const IrradianceEstimate e = computeIrradiance(tracer, {p}, t, 1)[0];
    r.worst = std::max(r.worst, e.standardErrorLux() / e.illuminanceLux());
    r.withoutCache += e.withoutCache;
    return e;
  }, exact, what);
  return r;
}

TEST(ErrorBars, TargetErrorReachesItsTargetAndCoversItsShare) {
  const Scene ground = skyOverGround();
  const Tracer tg(ground);
  TraceSettings s = coverageSettings();
  s.targetRelativeError = 0.01;
  const TargetRun r = coverageWithTarget(tg, tiltedSensor(), s, tiltedExact(), "path with --target-error 1 %, tilted sensor");
  const double worst = r.worst, a = r.share;
  EXPECT_LE(worst, 0.01);
  EXPECT_GE(a, kLo);
  EXPECT_LE(a, kHi);
}

// A target below what the frozen cache's records allow: the batches of a point share the records,
// so averaging them leaves the records' share as it is (before the fix its variance was divided
// by the batches too, and the bars of such points were too small: the validation suite's cache
// near contact read 4–6 of them off). The point's records' share (64-ray records) is above half
// the target's variance, so the point is estimated again by the path method, whose bars cover.
TEST(ErrorBars, TargetErrorUnderTheCacheCoversItsShare) {
  const Scene sphere = integratingSphere(0.5);
  const Tracer ts(sphere);
  TraceSettings s = sphereCacheSettings(128, 0.3, 64);
  s.firstBounceSplit = 4;
  s.targetRelativeError = 0.002;
  const TargetRun r = coverageWithTarget(ts, {Vec3(0.9, 0, 0), Vec3(-1, 0, 0)}, s, sphereExact(0.5),
                                         "cache with a 0.2 % target, integrating sphere rho 0.5");
  const double worst = r.worst, a = r.share;
  const int withoutCache = r.withoutCache;
  std::printf("[ measured ] %d of %d seeds estimated without the cache\n", withoutCache, kSeeds);
  EXPECT_EQ(withoutCache, kSeeds);
  EXPECT_LE(worst, 0.002);
  EXPECT_GE(a, kLo);
  EXPECT_LE(a, kHi);
}

// An infinite black roof 3 m up with a 1 m × 1.5 m opening over [−0.5, 0.5] × [−0.75, 0.75]
// (validation case roof-opening-uniform-sky) under a uniform sky of 10000 lux, or (window) a
// 2 m × 1 m window (z 1–2 m) in an infinite black wall x = 0 with a black ceiling at its head
// under the CIE overcast sky (side-window-overcast-sky). Every hemisphere ray that sees the sky
// carries L or 0, so the variance sits in the few strata cut by the aperture's edge, which are
// the ones adaptive super-sampling refines.
Scene apertureScene(const char* rad, const char* sky) {
  Scene scene;
  readRadianceText(rad, "<aperture>", scene);
  DaylightSpec d;
  d.skyType = parseSkyType(sky).value();
  d.sunAltitudeDeg = 35.0;
  d.sunAzimuthDeg = 200.0;
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = 0.0;
  addDaylight(scene, d);
  return scene;
}
using test_support::kRoofOpening;
using test_support::kSideWindow;

TEST(ErrorBars, SmallSkyOpeningsCoverTheirShareAtNormalQuality) {
  // Normal quality's settings (2048 hemisphere samples, 64 sky samples, adaptive fraction 0.5).
  // Under the roof opening nearly all the variance is in refined strata, whose bars come from
  // their own samples (an unbiased estimate): held to 68 % ± 3 binomial σ both ways (61–75 %).
  // Before, their second differences of means divided by the count covered 41 % at (0, 0).
  // Through the side window the sky samples and unrefined strata matter too (upper bounds):
  // the path tracer's band (59–90 %).
  const Scene roof = apertureScene(kRoofOpening, "uniform"), window = apertureScene(kSideWindow, "cie-overcast");
  const Tracer tr(roof), tw(window);
  const TraceSettings s = settingsForQuality(Quality::kNormal);
  auto at = [&](const Tracer& t, const Vec3& p) {
    return [&t, p, &s](uint64_t seed) {
      TraceSettings u = s;
      u.seed = seed;
      return estimateIrradiance(t, p, Vec3(0, 0, 1), 0, u);
    };
  };
  const double L = 10000.0 / kPi;  // a uniform sky of 10000 lux on the open horizontal plane
  for (auto [x, y] : {std::pair{0.0, 0.0}, {0.5, 0.75}, {2.0, 1.0}}) {
    const std::string what = "normal, under the roof opening at (" + std::to_string(x).substr(0, 3) + ", " +
                             std::to_string(y).substr(0, 4) + ")";
    const double exact = analytic::rectangleAbove(L, {-0.5, -0.75, 0.5, 0.75}, 3.0, x, y);
    const double a = coverage(at(tr, Vec3(x, y, 0)), exact, what.c_str());
    EXPECT_GE(a, kBandLo) << what;
    EXPECT_LE(a, kBandHi) << what;
  }
  for (double x : {1.0, 4.0}) {
    const double p[3] = {x, 0.3, 0.8}, up[3] = {0, 0, 1}, c[3] = {0, -1, 1}, u[3] = {0, 2, 0}, v[3] = {0, 0, 1};
    const std::string what = "normal, side window, " + std::to_string(x).substr(0, 3) + " m in";
    const double a = coverage(at(tw, Vec3(x, 0.3, 0.8)), analytic::overcastAperture(p, up, c, u, v, 10000.0, 1500),
                              what.c_str());
    EXPECT_GE(a, kLo) << what;
    EXPECT_LE(a, kHi) << what;
  }
}

}  // namespace
}  // namespace candela
