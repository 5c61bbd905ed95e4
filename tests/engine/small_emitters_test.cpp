// Small emitters (issue 16, item 4): glows sampled explicitly where Radiance's radius argument
// or the small-emitter rule says so, never counted twice, and never `0 ± 0` when in view.
#include "engine/lights.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "engine/trace_settings.h"
#include "test_materials.h"
#include "engine/integrator_path.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace candela {
namespace {

using test_support::addMaterial;

uint32_t addGlow(Scene& sc, double radiance, double radiusM) {
  Material m;
  m.type = MaterialType::kGlow;
  m.name = "glow";
  m.color = Rgb(radiance);
  m.glowRadiusM = radiusM;
  return sc.addMaterial(m);
}

// The bulb of the issue: a glow sphere of r = 2.5 cm, L = 60 W/sr/m², 2 m above a sensor facing
// it. The cap formula E = π L sin²α cos θ with sin α = r/d (the sphere wholly above the horizon)
// gives 179 · π · 60 · (0.0125)² = 5.27 lx.
constexpr double kBulbR = 0.025, kBulbD = 2.0, kBulbL = 60.0;
double bulbLux() { return kLumensPerWatt * kPi * kBulbL * (kBulbR / kBulbD) * (kBulbR / kBulbD); }

Scene bulbScene(double radiusM) {
  Scene sc;
  sc.addSphere(Vec3(0, 0, kBulbD), kBulbR, addGlow(sc, kBulbL, radiusM));
  return sc;
}

IrradianceEstimate estimate(const Scene& sc, const SensorPoint& p, const TraceSettings& s) {
  const Tracer tracer(sc);
  return computeIrradiance(tracer, {p}, s, 1)[0];
}

void report(const char* what, const IrradianceEstimate& e, double want) {
  std::printf("[ measured ] %s: %.6g ± %.2g lx, closed form %.6g lx\n", what, e.illuminanceLux(),
              e.standardErrorLux(), want);
}

const Quality kQualities[] = {Quality::kDraft, Quality::kNormal, Quality::kHigh};

TEST(SmallEmitters, GlowBulbOfRadiusZeroIsFoundAtEveryQuality) {
  // Radius 0 (never a source in Radiance) but small from the sensor at every preset: sampled,
  // so the estimate is the closed form (wholly visible: the ratio estimator is exact, and its
  // error bar is rightly 0); the hemisphere rays that meet it leave it out.
  const Scene sc = bulbScene(0.0);
  const double want = bulbLux();
  for (Quality q : kQualities) {
    for (Method m : {Method::kPath, Method::kCache}) {
      TraceSettings s = settingsForQuality(q);
      s.method = m;
      const IrradianceEstimate e = estimate(sc, {Vec3(0.0), Vec3(0, 0, 1)}, s);
      report(qualityName(q), e, want);
      EXPECT_NEAR(e.illuminanceLux(), want, 1e-9 * want) << qualityName(q);
    }
  }
}

TEST(SmallEmitters, HalfHiddenBulbHasAnHonestErrorBar) {
  // A black screen at z = 1 over x < 0: its edge and the sensor span the plane x = 0, which holds
  // the bulb's axis and the sensor's normal, so by symmetry exactly half the bulb's light
  // arrives. The visibility is sampled: the error bar is not 0, and covers the error.
  Scene sc = bulbScene(0.0);
  sc.addPolygon({{-5, -5, 1}, {0, -5, 1}, {0, 5, 1}, {-5, 5, 1}}, addMaterial(sc, MaterialType::kPlastic, 0.0));
  const double want = 0.5 * bulbLux();
  for (Quality q : kQualities) {
    TraceSettings s = settingsForQuality(q);
    s.method = Method::kPath;
    double sum = 0.0;
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      s.seed = seed;
      const IrradianceEstimate e = estimate(sc, {Vec3(0.0), Vec3(0, 0, 1)}, s);
      report(qualityName(q), e, want);
      EXPECT_GT(e.standardErrorLux(), 0.0) << qualityName(q);
      EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux()) << qualityName(q) << " seed " << seed;
      sum += e.illuminanceLux();
    }
    EXPECT_GT(sum, 0.0);
  }
}

TEST(SmallEmitters, SamplingRuleFollowsRadiusAndSolidAngle) {
  // The rule's boundaries against their own definitions: the small-emitter bound is a cap of
  // solid angle 2π/N (1 − cos α = 1/N), the radius rule reaches radius + r from the centre.
  Scene sc;
  sc.addSphere(Vec3(0.0), 0.1, addGlow(sc, 1.0, 0.0));
  sc.addSphere(Vec3(10, 0, 0), 0.1, addGlow(sc, 1.0, 1.0));
  sc.addSphere(Vec3(20, 0, 0), 0.1, addGlow(sc, 1.0, -1.0));
  const std::vector<Light> lights = collectLights(sc);
  ASSERT_EQ(lights.size(), 2u);  // the negative radius is no source
  const int n = 256;
  const double sin2 = smallEmitterSin2(n);
  const double cosA = 1.0 - 1.0 / n, dSmall = 0.1 / std::sqrt(1.0 - cosA * cosA);
  EXPECT_NEAR(kTwoPi * (1.0 - cosA), kTwoPi / n, 1e-15);
  EXPECT_FALSE(glowSampledFrom(lights[0], Vec3(0.999 * dSmall, 0, 0), sin2));
  EXPECT_TRUE(glowSampledFrom(lights[0], Vec3(0, 1.001 * dSmall, 0), sin2));
  EXPECT_FALSE(glowSampledFrom(lights[0], Vec3(0, 0, 0.05), sin2));  // inside the sphere
  // Radius 1 m: sampled up to 1.1 m from the centre, then not, until it becomes small.
  EXPECT_TRUE(glowSampledFrom(lights[1], Vec3(10, 1.09, 0), sin2));
  EXPECT_FALSE(glowSampledFrom(lights[1], Vec3(10, 1.11, 0), sin2));
  EXPECT_FALSE(glowSampledFrom(lights[1], Vec3(10, 0.999 * dSmall, 0), sin2));
  EXPECT_TRUE(glowSampledFrom(lights[1], Vec3(10, 1.001 * dSmall, 0), sin2));
  // Without the small-emitter rule (bound 0) only the radius counts.
  EXPECT_FALSE(glowSampledFrom(lights[0], Vec3(100, 0, 0), 0.0));
}

// A glow disk of radius R facing down at height h over a sensor facing up: on the axis
// E = π L R²/(h² + R²) (the disk's configuration factor).
double diskLux(double L, double R, double h) { return kLumensPerWatt * kPi * L * R * R / (h * h + R * R); }

TEST(SmallEmitters, LargeGlowSampledOrNotHasTheSameExpectation) {
  // R = 1 m at 1.3 m: far too large to be small. Radius 0: found by hemisphere rays only; radius
  // 10 m: sampled (exact), hemisphere rays leave it out. Both the closed form. (At 1 m its edge,
  // sin²θ = 1/2, would fall on a boundary of the θ strata and make the hemisphere exact too.)
  const double want = diskLux(1.0, 1.0, 1.3);
  for (double radius : {0.0, 10.0}) {
    Scene sc;
    sc.addRing({0, 0, 1.3}, {0, 0, -1}, 0.0, 1.0, addGlow(sc, 1.0, radius));
    TraceSettings s = settingsForQuality(Quality::kNormal);
    s.method = Method::kPath;
    const IrradianceEstimate e = estimate(sc, {Vec3(0.0), Vec3(0, 0, 1)}, s);
    report(radius > 0 ? "large glow, sampled" : "large glow, hemisphere", e, want);
    if (radius > 0) {
      EXPECT_NEAR(e.illuminanceLux(), want, 1e-9 * want);
    } else {
      EXPECT_GT(e.standardErrorLux(), 0.0);
      EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
    }
  }
}

TEST(SmallEmitters, GlowBeyondItsRadiusIsLeftToTheHemisphere) {
  // R = 1 m at 3 m with radius 0.5 m: 2 m from its bound, not small (sin²α = 1/9): not sampled,
  // and the hemisphere still sees all of it. Radius 2.5 m: sampled. Both the closed form.
  const double want = diskLux(1.0, 1.0, 3.0);
  for (double radius : {0.5, 2.5}) {
    Scene sc;
    sc.addRing({0, 0, 3}, {0, 0, -1}, 0.0, 1.0, addGlow(sc, 1.0, radius));
    TraceSettings s = settingsForQuality(Quality::kNormal);
    s.method = Method::kPath;
    const Tracer tracer(sc);
    ASSERT_EQ(tracer.sources().lights.size(), 1u);
    EXPECT_EQ(glowSampledFrom(tracer.sources().lights[0], Vec3(0.0), smallEmitterSin2(s.hemisphereSamples)),
              radius > 1.0);
    const IrradianceEstimate e = computeIrradiance(tracer, {{Vec3(0.0), Vec3(0, 0, 1)}}, s, 1)[0];
    report(radius > 1.0 ? "within radius" : "beyond radius", e, want);
    if (radius > 1.0) {
      EXPECT_NEAR(e.illuminanceLux(), want, 1e-9 * want);
    } else {
      EXPECT_GT(e.standardErrorLux(), 0.0);
      EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
    }
  }
}

// Sensors over a grey floor (ρ 0.5) lit by a glow: facing down (reflected light only), sideways
// and up. Where the rule changes between the sensor and the floor points its rays meet, each
// side must still count every glow exactly once.
std::vector<SensorPoint> floorSensors() {
  return {{Vec3(0, 0, 0.3), Vec3(0, 0, -1)},
          {Vec3(1.5, 0, 0.3), Vec3(0, 0, -1)},
          {Vec3(2.5, 0, 1.0), glm::normalize(Vec3(-1, 0, -1))},
          {Vec3(0.6, 0.2, 0.2), Vec3(0, 0, 1)}};
}

void expectAgree(const IrradianceEstimate& a, const IrradianceEstimate& b, const char* what, size_t i) {
  const double tol = 4.0 * std::hypot(a.standardErrorLux(), b.standardErrorLux());
  std::printf("[ measured ] %s, sensor %zu: %.5g ± %.2g against %.5g ± %.2g lx\n", what, i, a.illuminanceLux(),
              a.standardErrorLux(), b.illuminanceLux(), b.standardErrorLux());
  EXPECT_GT(a.illuminanceLux(), 0.0) << what << " " << i;
  EXPECT_NEAR(a.illuminanceLux(), b.illuminanceLux(), tol) << what << " " << i;
}

Scene floorWith(bool sphere, double radius) {
  Scene sc;
  sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, addMaterial(sc, MaterialType::kPlastic, 0.5));
  if (sphere) {
    // A 5 cm bulb 0.5 m up: small (at 1024 hemisphere rays) from floor points beyond 1.13 m of
    // it, not from the floor under it nor from the sensor 0.3 m below it.
    sc.addSphere(Vec3(0.6, 0.2, 0.5), 0.05, addGlow(sc, 200.0, radius));
  } else {
    sc.addRing({0, 0, 1}, {0, 0, -1}, 0.0, 0.5, addGlow(sc, 5.0, radius));
  }
  return sc;
}

std::vector<IrradianceEstimate> floorRun(const Scene& sc, Method m, uint64_t seed) {
  TraceSettings s = settingsForQuality(Quality::kDraft);
  s.method = m;
  s.seed = seed;
  s.hemisphereSamples = 1024;
  const Tracer tracer(sc);
  return computeIrradiance(tracer, floorSensors(), s, 2);
}

TEST(SmallEmitters, RadiusRuleChangingAlongAPathCountsTheGlowOnce) {
  // A 0.5 m glow disk 1 m over the floor. Radius 0: never sampled; 100 m: sampled from every
  // point; 1 m: sampled from the floor under it (within 1.5 m of its centre) but not from the
  // third sensor nor the floor beyond. The path method gives one expectation for all three.
  const auto never = floorRun(floorWith(false, 0.0), Method::kPath, 1);
  const auto always = floorRun(floorWith(false, 100.0), Method::kPath, 2);
  const auto mixed = floorRun(floorWith(false, 1.0), Method::kPath, 3);
  for (size_t i = 0; i < never.size(); ++i) {
    expectAgree(always[i], never[i], "disk, path: always against never", i);
    expectAgree(mixed[i], never[i], "disk, path: radius 1 m against never", i);
  }
  // The cache method, the glow sampled everywhere or nowhere, and from part of the floor: a
  // lookup samples the glow with the weight of the records that left it out (cachedVertex).
  const auto cacheNever = floorRun(floorWith(false, 0.0), Method::kCache, 4);
  const auto cacheAlways = floorRun(floorWith(false, 100.0), Method::kCache, 5);
  const auto cacheMixed = floorRun(floorWith(false, 1.0), Method::kCache, 6);
  for (size_t i = 0; i < never.size(); ++i) {
    expectAgree(cacheAlways[i], cacheNever[i], "disk, cache: always against never", i);
    expectAgree(cacheAlways[i], always[i], "disk: cache against path", i);
    expectAgree(cacheMixed[i], always[i], "disk: cache radius 1 m against path always", i);
  }
}

TEST(SmallEmitters, SmallEmitterRuleChangingAlongAPathCountsTheBulbOnce) {
  // The 5 cm bulb: radius 0 (sampled only where small) against 100 m (sampled from everywhere
  // outside it), path and cache methods.
  const auto small = floorRun(floorWith(true, 0.0), Method::kPath, 1);
  const auto always = floorRun(floorWith(true, 100.0), Method::kPath, 2);
  const auto cacheSmall = floorRun(floorWith(true, 0.0), Method::kCache, 3);
  for (size_t i = 0; i < small.size(); ++i) {
    expectAgree(small[i], always[i], "bulb, path: small rule against always", i);
    expectAgree(cacheSmall[i], always[i], "bulb, cache small rule against path always", i);
  }
}

TEST(SmallEmitters, SameNumbersForAnyThreadCount) {
  // The rule is a function of the point alone: sampling a glow or not never depends on threads.
  for (Method m : {Method::kPath, Method::kCache}) {
    const Scene sc = floorWith(true, 0.0);
    const Tracer tracer(sc);
    TraceSettings s = settingsForQuality(Quality::kDraft);
    s.method = m;
    const auto one = computeIrradiance(tracer, floorSensors(), s, 1);
    const auto two = computeIrradiance(tracer, floorSensors(), s, 2);
    for (size_t i = 0; i < one.size(); ++i) {
      EXPECT_EQ(one[i].illuminanceLux(), two[i].illuminanceLux()) << i;
      EXPECT_EQ(one[i].standardErrorLux(), two[i].standardErrorLux()) << i;
    }
  }
}

TEST(SmallEmitters, NegativeRadiusLightsNothingButIsSeen) {
  // Radiance's ray.1: "If maxrad is negative, then the surface will never contribute to scene
  // illumination." A sensor under it gets nothing; an eye ray sees its radiance.
  Scene sc;
  sc.addRing({0, 0, 1}, {0, 0, -1}, 0.0, 1.0, addGlow(sc, 2.0, -1.0));
  const Tracer tracer(sc);
  TraceSettings s = settingsForQuality(Quality::kDraft);
  s.method = Method::kPath;
  const IrradianceEstimate e = computeIrradiance(tracer, {{Vec3(0.0), Vec3(0, 0, 1)}}, s, 1)[0];
  EXPECT_EQ(e.illuminanceLux(), 0.0);
  Rng rng(1, 0);
  EXPECT_EQ(rayRadiance(tracer, Vec3(0.0), Vec3(0, 0, 1), kNoShape, true, rng, s).x, 2.0);
  EXPECT_EQ(rayRadiance(tracer, Vec3(0.0), Vec3(0, 0, 1), kNoShape, false, rng, s).x, 0.0);
}

TEST(SmallEmitters, BulbSeenInAFlatMirrorCountsOnce) {
  // The bulb (radius 0) 1 m east, 0.5 m up, and a flat mirror (ρ 0.9) at z = 2 facing down:
  // direct light by the cap formula, plus the image at (1, 0, 3.5) by the same formula times
  // 0.9. The image is not sampled (glows are not imaged): the hemisphere finds it.
  Scene sc;
  const Vec3 c(1.0, 0.0, 0.5);
  const double r = 0.05, L = 200.0;
  sc.addSphere(c, r, addGlow(sc, L, 0.0));
  sc.addPolygon({{-5, -5, 2}, {-5, 5, 2}, {5, 5, 2}, {5, -5, 2}}, addMaterial(sc, MaterialType::kMirror, 0.9));
  auto cap = [&](const Vec3& centre) {
    const double d2 = glm::dot(centre, centre);
    return kLumensPerWatt * kPi * L * r * r / d2 * (centre.z / std::sqrt(d2));
  };
  const double want = cap(c) + 0.9 * cap(Vec3(1.0, 0.0, 3.5));
  TraceSettings s = settingsForQuality(Quality::kNormal);
  s.method = Method::kPath;
  const IrradianceEstimate e = estimate(sc, {Vec3(0.0), Vec3(0, 0, 1)}, s);
  report("bulb and its mirror image", e, want);
  EXPECT_GT(e.standardErrorLux(), 0.0);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
}

}  // namespace
}  // namespace candela
