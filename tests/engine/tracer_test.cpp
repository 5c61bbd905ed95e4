// estimateIrradiance against the closed forms of validation/analytic (written independently of
// the engine). Where the engine's control variate makes the estimate exact (a wholly visible
// source with a closed form and nothing else to see) the check is to 1e-9 relative; Monte Carlo
// estimates are checked within 4 of their own standard errors (standardErrorLux(), which the
// engine computes from its samples; a 4σ miss has probability ~6e-5, and seeds are fixed) plus
// a loose absolute bound so that a wildly overestimated error cannot hide a wrong answer.
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "validation/analytic.h"
#include "tests/engine/test_materials.h"
#include "engine/irradiance_estimator.h"


#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {
namespace {

constexpr double kExactRel = 1e-9;  // closed form vs closed form by another route

using test_support::addMaterial;
uint32_t addLight(Scene& sc, double radiance) { return addMaterial(sc, MaterialType::kLight, radiance, "lamp"); }
uint32_t addPlastic(Scene& sc, double rho) { return addMaterial(sc, MaterialType::kPlastic, rho, "grey"); }
uint32_t addGlow(Scene& sc, double radiance) { return addMaterial(sc, MaterialType::kGlow, radiance, "sky"); }

// A rectangle [x0,x1]×[y0,y1] at height z, its front facing down (vertices clockwise seen from
// above), as a luminaire or ceiling is modelled.
void addDownRect(Scene& sc, double x0, double y0, double x1, double y1, double z, uint32_t mat) {
  sc.addPolygon({{x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}}, mat);
}
void addUpRect(Scene& sc, double x0, double y0, double x1, double y1, double z, uint32_t mat) {
  sc.addPolygon({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, mat);
}

void expectExact(double got, double want, const char* what) {
  EXPECT_NEAR(got, want, kExactRel * std::abs(want)) << what;
}

// Monte Carlo check: within 4 standard errors of the estimate and within `looseRel` of the
// reference (the sanity bound); the error must be positive (a zero error with a wrong mean
// would otherwise pass only by the loose bound).
void expectWithinStandardErrors(const IrradianceEstimate& e, double wantLux, double looseRel, const char* what) {
  const double got = e.illuminanceLux(), se = e.standardErrorLux();
  std::printf("[ measured ] %s: %.6g lux, reference %.6g lux, standard error %.3g lux\n", what, got, wantLux, se);
  EXPECT_GT(se, 0.0) << what;
  EXPECT_NEAR(got, wantLux, 4.0 * se) << what << " (standard error " << se << " lux)";
  EXPECT_NEAR(got, wantLux, looseRel * std::abs(wantLux)) << what;
}

// ---------------------------------------------------------------- exact (control variate)

TEST(Tracer, SmallLightSphereIsExactAtSeveralAngles) {
  const double L = 50.0, r = 0.1, d = 2.0;
  const Vec3 n = glm::normalize(Vec3(1.0, 2.0, 3.0));  // a tilted receiver
  const Frame f = Frame::fromNormal(n);
  const Vec3 p(0.3, -0.2, 0.75);
  for (double thetaDeg : {0.0, 30.0, 60.0, 80.0}) {
    const double th = degToRad(thetaDeg);
    Scene sc;
    const uint32_t lamp = addLight(sc, L);
    sc.addSphere(p + d * f.toWorld(Vec3(std::sin(th), 0.0, std::cos(th))), r, lamp);
    const Tracer tracer(sc);
    const IrradianceEstimate e = estimateIrradiance(tracer, p, n, 0, TraceSettings{});
    const double want = kLumensPerWatt * analytic::sphereSource(L, r, d, std::cos(th));
    expectExact(e.illuminanceLux(), want, "sphere source");
    EXPECT_LE(e.standardErrorLux(), 1e-12 * want);
  }
}

TEST(Tracer, LightRectangleAboveIsExact) {
  const double L = 20.0, h = 2.5;
  Scene sc;
  addDownRect(sc, -1.0, -0.5, 1.5, 0.75, h, addLight(sc, L));
  const Tracer tracer(sc);
  // Under the rectangle, under a corner, and beside it.
  for (const Vec2 xy : {Vec2(0, 0), Vec2(0.3, 0.6), Vec2(-1.0, -0.5), Vec2(2.5, 1.0), Vec2(-3.0, 0.2)}) {
    const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(xy, 0.0), Vec3(0, 0, 1), 7, TraceSettings{});
    const double want = kLumensPerWatt * analytic::rectangleAbove(L, {-1.0, -0.5, 1.5, 0.75}, h, xy.x, xy.y);
    expectExact(e.illuminanceLux(), want, "rectangle source");
  }
  // Behind the one-sided source nothing arrives.
  EXPECT_EQ(estimateIrradiance(tracer, Vec3(0, 0, 3), Vec3(0, 0, -1), 0, TraceSettings{}).illuminanceLux(), 0.0);
}

// A distant `light` source (the sun): π L sin²α cos θ for a cap wholly above the horizon.
TEST(Tracer, SunIsExact) {
  const double L = 6e6, fullDeg = 0.533;
  Scene sc;
  const Vec3 dir = glm::normalize(Vec3(0.3, -0.5, 0.8));
  sc.addDistant(dir, fullDeg, addLight(sc, L));
  const Tracer tracer(sc);
  const double sinA = std::sin(degToRad(fullDeg / 2));
  const IrradianceEstimate e = estimateIrradiance(tracer, {0, 0, 0}, {0, 0, 1}, 0, TraceSettings{});
  expectExact(e.illuminanceLux(), kLumensPerWatt * kPi * L * sinA * sinA * dir.z, "sun");
}

// Uniform glow sky over an open plane: every hemisphere ray sees L, E = π L.
TEST(Tracer, UniformSkyOverOpenPlane) {
  const double L = 2.0;
  Scene sc;
  addUpRect(sc, -100, -100, 100, 100, 0.0, addPlastic(sc, 0.2));
  sc.addDistant({0, 0, 1}, 360.0, addGlow(sc, L));
  const Tracer tracer(sc);
  for (double z : {0.01, 0.001, 1.0}) {
    const IrradianceEstimate e = estimateIrradiance(tracer, {0.3, 0.4, z}, {0, 0, 1}, 3, TraceSettings{});
    expectExact(e.illuminanceLux(), kLumensPerWatt * analytic::uniformSky(L), "uniform sky");
  }
}

// ---------------------------------------------------------------- Monte Carlo

TEST(Tracer, CoaxialLightDisk) {
  // The engine has the disk's closed form (its vector irradiance) when the disk lies wholly above
  // the receiver's horizon: unoccluded, the estimate is exact.
  const double L = 30.0, R = 0.5, h = 1.5;
  Scene sc;
  sc.addRing({0.2, 0.1, h}, {0, 0, -1}, 0.0, R, addLight(sc, L));
  const Tracer tracer(sc);
  const double want = kLumensPerWatt * analytic::coaxialDisk(L, R, h);
  for (uint64_t i = 0; i < 4; ++i) {
    const IrradianceEstimate e = estimateIrradiance(tracer, {0.2, 0.1, 0.0}, {0, 0, 1}, i, TraceSettings{});
    EXPECT_NEAR(e.illuminanceLux(), want, kExactRel * want);
  }
}

// A disk crossing the receiver's horizon has no closed form in the engine: Monte Carlo, checked
// against Lambert's formula on a 4096-gon (independent of the engine's disk formula) clipped by
// hand to the half of the disk above the horizon.
TEST(Tracer, LightDiskAcrossTheHorizonIsMonteCarlo) {
  const double L = 30.0, R = 0.5;
  Scene sc;
  sc.addRing({0.0, 0.0, 0.0}, {0, 0, -1}, 0.0, R, addLight(sc, L));
  const Tracer tracer(sc);
  // Receiver 1 m below the disk's centre, tilted so its horizon passes through the disk's
  // centre line x = 0: it sees the half x > 0.
  const Vec3 p(0.0, 0.0, -1.0);
  const Vec3 n = glm::normalize(Vec3(1.0, 0.0, 0.0) * 1.0 + Vec3(0.0, 0.0, 0.0));
  const int sides = 4096;
  std::vector<Vec3> half;
  for (int k = 0; k <= sides / 2; ++k) {
    const double a = -0.5 * kPi + kPi * k / (sides / 2);
    half.push_back({R * std::cos(a), R * std::sin(a), 0.0});
  }
  const double want = kLumensPerWatt * L * polygonProjectedSolidAngle(half, p, n);
  TraceSettings s;
  s.lightSamples = 1024;
  const IrradianceEstimate e = estimateIrradiance(tracer, p, n, 3, s);
  expectWithinStandardErrors(e, want, 0.01, "half disk");
}

// Receiver under a light rectangle with a black occluder halfway up. Seen from p, the occluder
// (parallel to the source, at half its height) covers its own image scaled by 2 about p's foot
// point, so the visible part is source minus (source ∩ shadow): two closed-form rectangles.
TEST(Tracer, PartiallyShadowedRectangle) {
  const double L = 10.0, h = 2.0;
  const double sx0 = -1, sy0 = -1, sx1 = 1, sy1 = 1;        // source
  const double ox0 = 0.2, oy0 = -0.3, ox1 = 3.0, oy1 = 0.4;  // occluder at h/2
  Scene sc;
  addDownRect(sc, sx0, sy0, sx1, sy1, h, addLight(sc, L));
  addUpRect(sc, ox0, oy0, ox1, oy1, h / 2, addPlastic(sc, 0.0));
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 1024;
  for (const Vec2 p : {Vec2(0, 0), Vec2(0.3, -0.2), Vec2(-0.5, 0.5)}) {
    // Shadow of [o0, o1] on the source plane: x' = 2·o − p.
    const double qx0 = std::max(sx0, 2 * ox0 - p.x), qx1 = std::min(sx1, 2 * ox1 - p.x);
    const double qy0 = std::max(sy0, 2 * oy0 - p.y), qy1 = std::min(sy1, 2 * oy1 - p.y);
    ASSERT_TRUE(qx0 < qx1 && qy0 < qy1);
    const double full = analytic::rectangleAbove(L, {sx0, sy0, sx1, sy1}, h, p.x, p.y);
    const double hidden = analytic::rectangleAbove(L, {qx0, qy0, qx1, qy1}, h, p.x, p.y);
    const double want = kLumensPerWatt * (full - hidden);
    ASSERT_GT(hidden, 0.01 * full);  // the shadow matters
    const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(p, 0.0), {0, 0, 1}, 11, s);
    expectWithinStandardErrors(e, want, 0.02, "partially shadowed rectangle");
  }
}

// The paper's check: a Lambertian sphere (R = 1 m) on a black plane under a uniform sky, sensors
// 1 cm above the plane at 0.25..3 m from the contact point.
TEST(Tracer, SphereOnBlackPlaneUnderUniformSky) {
  const double L = 1.0, R = 1.0, h = 0.01;
  for (double rho : {0.0, 0.5}) {
    Scene sc;
    addUpRect(sc, -1000, -1000, 1000, 1000, 0.0, addPlastic(sc, 0.0));
    sc.addSphere({0, 0, R}, R, addPlastic(sc, rho));
    sc.addDistant({0, 0, 1}, 360.0, addGlow(sc, L));
    const Tracer tracer(sc);
    uint64_t index = 0;
    for (double x : {0.25, 0.5, 1.0, 2.0, 3.0}) {
      const IrradianceEstimate e = estimateIrradiance(tracer, {x, 0.0, h}, {0, 0, 1}, index++, TraceSettings{});
      const double want = kLumensPerWatt * analytic::sphereOnPlane(rho, L, R, x, h);
      std::printf("[ measured ] sphere on plane rho %.1f x %.2f m: %.6g lux, reference %.6g lux, standard error %.3g lux\n",
                  rho, x, e.illuminanceLux(), want, e.standardErrorLux());
      // Loose bound: 2 % of the open-sky value.
      EXPECT_NEAR(e.illuminanceLux(), want, 0.02 * kLumensPerWatt * kPi * L) << "rho " << rho << " x " << x;
      EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux())
          << "rho " << rho << " x " << x << " (standard error " << e.standardErrorLux() << " lux)";
      EXPECT_GT(e.standardErrorLux(), 0.0);
    }
  }
}

// ---------------------------------------------------------------- reproducibility

Scene sphereOnPlaneScene() {
  Scene sc;
  addUpRect(sc, -1000, -1000, 1000, 1000, 0.0, addPlastic(sc, 0.2));
  sc.addSphere({0, 0, 1}, 1.0, addPlastic(sc, 0.5));
  sc.addDistant({0, 0, 1}, 360.0, addGlow(sc, 1.0));
  addDownRect(sc, -0.5, 1.0, 0.5, 1.5, 2.5, addLight(sc, 20.0));
  return sc;
}

TEST(Tracer, ThreadsDoNotChangeResultsAndSeedsDo) {
  const Scene sc = sphereOnPlaneScene();
  const Tracer tracer(sc);
  std::vector<SensorPoint> pts;
  for (int i = 0; i < 12; ++i) pts.push_back({Vec3(0.25 + 0.25 * i, 0.1 * i, 0.01), Vec3(0, 0, 1)});
  TraceSettings s = settingsForQuality(Quality::kDraft);
  const auto one = computeIrradiance(tracer, pts, s, 1);
  const auto two = computeIrradiance(tracer, pts, s, 2);
  const auto again = computeIrradiance(tracer, pts, s, 2);
  s.seed = 2;
  const auto other = computeIrradiance(tracer, pts, s, 2);
  ASSERT_EQ(one.size(), pts.size());
  int differ = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(one[i].irradiance, two[i].irradiance) << i;  // bit-identical
    EXPECT_EQ(one[i].variancePhotopic, two[i].variancePhotopic) << i;
    EXPECT_EQ(two[i].irradiance, again[i].irradiance) << i;
    differ += other[i].irradiance != one[i].irradiance;
  }
  EXPECT_EQ(differ, static_cast<int>(pts.size()));  // every point is a Monte Carlo estimate
}

// ---------------------------------------------------------------- near surfaces, leaks

// Sensors just above a reflecting floor under a light rectangle see the rectangle exactly (the
// floor is below their horizon); any self-intersection of their rays would darken them.
TEST(Tracer, SensorsJustAboveAFloorSeeNoSelfIntersection) {
  const double L = 20.0, zFloor = 0.8, zLight = 3.0;
  Scene sc;
  addUpRect(sc, -10, -10, 10, 10, zFloor, addPlastic(sc, 0.5));
  addDownRect(sc, -0.6, -0.6, 0.6, 0.6, zLight, addLight(sc, L));
  const Tracer tracer(sc);
  for (double gap : {0.01, 0.001}) {
    for (const Vec2 xy : {Vec2(0, 0), Vec2(1.0, -0.4)}) {
      const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(xy, zFloor + gap), {0, 0, 1}, 0, TraceSettings{});
      const double want =
          kLumensPerWatt * analytic::rectangleAbove(L, {-0.6, -0.6, 0.6, 0.6}, zLight - zFloor - gap, xy.x, xy.y);
      expectExact(e.illuminanceLux(), want, "sensor above floor");
    }
  }
}

// Sensors 5 mm from a reflecting sphere, facing away from it, lit by a small light sphere in
// their hemisphere: the big sphere lies wholly behind their horizon, so E is the closed form.
TEST(Tracer, SensorsNearASphereSeeNoSelfIntersection) {
  const double L = 50.0, R = 0.5, gap = 0.005, r = 0.05, d = 1.5;
  const Vec3 c(0.2, 0.1, 1.0);
  for (const Vec3 u0 : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(1, -1, -2), Vec3(-0.3, 0.8, 0.2)}) {
    const Vec3 u = glm::normalize(u0);
    const Frame f = Frame::fromNormal(u);
    const double th = degToRad(40.0);
    const Vec3 p = c + (R + gap) * u;
    Scene sc;
    sc.addSphere(c, R, addPlastic(sc, 0.5));
    sc.addSphere(p + d * f.toWorld(Vec3(std::sin(th), 0.0, std::cos(th))), r, addLight(sc, L));
    const Tracer tracer(sc);
    const IrradianceEstimate e = estimateIrradiance(tracer, p, u, 0, TraceSettings{});
    expectExact(e.illuminanceLux(), kLumensPerWatt * analytic::sphereSource(L, r, d, std::cos(th)),
                "sensor near sphere");
  }
}

// A closed box of reflecting walls with light sources outside (an area light on top, the sun,
// a light sphere): inside it is dark, exactly, at 1 mm from the walls and in the corners.
TEST(Tracer, LightTightBoxIsDarkInside) {
  Scene sc;
  const uint32_t wall = addPlastic(sc, 0.5);
  // Unit cube, all faces facing inward.
  addUpRect(sc, 0, 0, 1, 1, 0.0, wall);    // floor
  addDownRect(sc, 0, 0, 1, 1, 1.0, wall);  // ceiling
  sc.addPolygon({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, wall);  // y = 0, facing +y
  sc.addPolygon({{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, wall);  // y = 1, facing −y
  sc.addPolygon({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, wall);  // x = 0, facing +x
  sc.addPolygon({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, wall);  // x = 1, facing −x
  const uint32_t lamp = addLight(sc, 100.0);
  addDownRect(sc, -0.5, -0.5, 1.5, 1.5, 2.0, lamp);
  sc.addSphere({2.0, 0.5, 0.5}, 0.2, lamp);
  sc.addDistant(glm::normalize(Vec3(-1, -1, 2)), 0.533, addLight(sc, 1e6));
  const Tracer tracer(sc);
  const double e = 0.001;
  struct Probe {
    Vec3 p, n;
  };
  const Probe probes[] = {
      {{0.5, 0.5, 1 - e}, {0, 0, 1}},     // under the ceiling, facing the light above it
      {{0.5, 0.5, 1 - e}, {0, 0, -1}},
      {{1 - e, 0.5, 0.5}, {1, 0, 0}},     // facing the light sphere through the wall
      {{e, 0.5, 0.5}, {1, 0, 0}},
      {{e, e, e}, glm::normalize(Vec3(1, 1, 1))},      // corners
      {{1 - e, 1 - e, 1 - e}, glm::normalize(Vec3(1, 1, 1))},
      {{1 - e, e, 1 - e}, glm::normalize(Vec3(-1, -1, 2))},  // facing the sun
      {{0.5, 0.5, 0.5}, {0, 0, 1}},
  };
  uint64_t i = 0;
  for (const Probe& pr : probes) {
    const IrradianceEstimate est = estimateIrradiance(tracer, pr.p, pr.n, i++, settingsForQuality(Quality::kDraft));
    EXPECT_EQ(est.illuminanceLux(), 0.0) << "at (" << pr.p.x << ", " << pr.p.y << ", " << pr.p.z << ") facing ("
                                         << pr.n.x << ", " << pr.n.y << ", " << pr.n.z << ")";
  }
}

// ---------------------------------------------------------------- transmittance

// Thin glass at normal incidence: R = ((n−1)/(n+1))², T = (1−R)² τ / (1 − R² τ²) (incoherent
// multiple reflections), τ the glass colour; trans passes its specular transmittance; an opaque
// surface stops everything.
TEST(Tracer, TransmittanceThroughGlassTransAndOpaque) {
  Scene sc;
  Material glass;
  glass.type = MaterialType::kGlass;
  glass.name = "glass";
  glass.color = Rgb(0.9, 0.8, 0.7);
  glass.refractiveIndex = 1.5;
  addUpRect(sc, -1, -1, 1, 1, 1.0, sc.addMaterial(glass));
  Material tr;
  tr.type = MaterialType::kTrans;
  tr.name = "frosted";
  tr.color = Rgb(0.8);
  tr.specularity = 0.0;
  tr.transmissivity = 0.5;
  tr.transmittedSpecular = 0.6;
  addUpRect(sc, -1, -1, 1, 1, 2.0, sc.addMaterial(tr));
  addUpRect(sc, -1, -1, 1, 1, 3.0, addPlastic(sc, 0.5));
  const Tracer tracer(sc);
  const double R = 0.04;  // ((1.5 − 1)/(1.5 + 1))²
  Rgb glassT;
  for (int c = 0; c < 3; ++c) {
    const double tau = glass.color[c];
    glassT[c] = (1 - R) * (1 - R) * tau / (1 - R * R * tau * tau);
  }
  const Rgb t1 = tracer.transmittance({0, 0, 0}, {0, 0, 1}, 1.5, kNoShape, kNoShape);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t1[c], glassT[c], 1e-12);
  const Rgb t2 = tracer.transmittance({0, 0, 0}, {0, 0, 1}, 2.5, kNoShape, kNoShape);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t2[c], glassT[c] * 0.8 * 0.5 * 0.6, 1e-12);
  EXPECT_EQ(tracer.transmittance({0, 0, 0}, {0, 0, 1}, 3.5, kNoShape, kNoShape), Rgb(0.0));
  EXPECT_EQ(tracer.transmittance({0, 0, 0}, {0, 0, -1}, 10.0, kNoShape, kNoShape), Rgb(1.0));
}

TEST(Tracer, QualityPresets) {
  EXPECT_EQ(parseQuality("draft"), Quality::kDraft);
  EXPECT_EQ(parseQuality("high"), Quality::kHigh);
  EXPECT_THROW(parseQuality("best"), std::invalid_argument);
  const TraceSettings d = settingsForQuality(Quality::kDraft), n = settingsForQuality(Quality::kNormal),
                      h = settingsForQuality(Quality::kHigh);
  EXPECT_LT(d.hemisphereSamples, n.hemisphereSamples);
  EXPECT_LT(n.hemisphereSamples, h.hemisphereSamples);
  EXPECT_LE(d.lightSamples, n.lightSamples);
  EXPECT_LE(n.lightSamples, h.lightSamples);
}

}  // namespace
}  // namespace candela

// ---------------------------------------------------------------- mirrors and glossy reflection

namespace candela {
namespace {

Scene mirrorWallScene(bool unfolded) {
  // A grey floor (ρ 0.5) x ∈ [−1, 1], y ∈ [−1, 1], a 1 cm lamp at (0.5, 0, 1) and a perfect
  // mirror wall at x = 1 facing −x (y ∈ [−1.5, 1.5], z ∈ [0, 3]). Unfolded: no mirror, the floor
  // continued to x = 3 and the lamp's image at (1.5, 0, 1): everything a point at x < 1 sees
  // through the mirror is there instead, so both scenes give the same irradiance everywhere.
  Scene sc;
  const uint32_t lamp = addLight(sc, 2e4), grey = addPlastic(sc, 0.5);
  sc.addSphere(Vec3(0.5, 0, 1), 0.01, lamp);
  if (unfolded) {
    addUpRect(sc, -1, -1, 3, 1, 0, grey);
    sc.addSphere(Vec3(1.5, 0, 1), 0.01, lamp);
  } else {
    addUpRect(sc, -1, -1, 1, 1, 0, grey);
    const uint32_t mirror = addMaterial(sc, MaterialType::kMirror, 1.0, "mirror");
    sc.addPolygon({{1, -1.5, 0}, {1, -1.5, 3}, {1, 1.5, 3}, {1, 1.5, 0}}, mirror);
  }
  return sc;
}

TEST(Tracer, SmallLampSeenInAMirrorIsExact) {
  // A sensor on the floor facing up receives the lamp directly and its image (virtual source)
  // through the mirror, both wholly visible: two closed forms.
  const Scene sc = mirrorWallScene(false);
  const Tracer tracer(sc);
  TraceSettings s;
  s.maxBounces = 0;
  const Vec3 p(0.0, 0.0, 0.0);
  const IrradianceEstimate e = estimateIrradiance(tracer, p, Vec3(0, 0, 1), 0, s);
  const double d1 = std::hypot(0.5, 1.0), d2 = std::hypot(1.5, 1.0);
  const double want = kLumensPerWatt * (analytic::sphereSource(2e4, 0.01, d1, 1.0 / d1) +
                                        analytic::sphereSource(2e4, 0.01, d2, 1.0 / d2));
  expectExact(e.illuminanceLux(), want, "lamp and its mirror image");
}

TEST(Tracer, MirrorEqualsTheUnfoldedScene) {
  // Interreflection through the mirror (floor → mirror → floor, lamp → mirror → floor → sensor)
  // must neither be lost nor counted twice: the mirror scene against its unfolding, at points on
  // the floor and above it facing down, within 4 combined standard errors.
  const Scene a = mirrorWallScene(false), b = mirrorWallScene(true);
  const Tracer ta(a), tb(b);
  TraceSettings s;
  s.hemisphereSamples = 1024;
  const std::vector<std::pair<Vec3, Vec3>> pts = {
      {{-0.5, 0.0, 0.01}, {0, 0, 1}}, {{0.9, 0.5, 0.01}, {0, 0, 1}}, {{0.0, 0.3, 2.0}, {0, 0, -1}},
      {{0.8, -0.2, 0.5}, {1, 0, 0}}};
  for (size_t i = 0; i < pts.size(); ++i) {
    const IrradianceEstimate ea = estimateIrradiance(ta, pts[i].first, pts[i].second, i, s);
    const IrradianceEstimate eb = estimateIrradiance(tb, pts[i].first, pts[i].second, i + 100, s);
    const double tol = 4.0 * std::hypot(ea.standardErrorLux(), eb.standardErrorLux());
    std::printf("[ measured ] mirror %.5g ± %.2g lux, unfolded %.5g ± %.2g lux\n", ea.illuminanceLux(),
                ea.standardErrorLux(), eb.illuminanceLux(), eb.standardErrorLux());
    EXPECT_NEAR(ea.illuminanceLux(), eb.illuminanceLux(), tol) << i;
    EXPECT_NEAR(ea.illuminanceLux(), eb.illuminanceLux(), 0.03 * eb.illuminanceLux()) << i;
  }
}

TEST(Tracer, GlossyPlasticReflectsItsSpecularEnergy) {
  // An infinite plastic floor (colour c, specularity s) under a uniform sky of radiance L: the
  // floor's irradiance is πL, its diffuse radiance c(1 − s)L, and with roughness 0 its specular
  // radiance sL (the sky mirrored). A sampled glossy ray carries ρ_s (Radiance's convention) and
  // every direction above the floor sees the sky, so any roughness gives the same sL. A sensor
  // facing down sees E = πL (c(1 − s) + s); before glossy reflection, πL c(1 − s).
  for (double roughness : {0.0, 0.05, 0.2}) {
    Scene sc;
    const uint32_t sky = addGlow(sc, 1.0);
    sc.addDistant(Vec3(0, 0, 1), 180.0, sky, "sky");
    Material m;
    m.type = MaterialType::kPlastic;
    m.name = "gloss";
    m.color = Rgb(0.4);
    m.specularity = 0.1;
    m.roughness = roughness;
    deriveMaterial(m);
    const uint32_t gloss = sc.addMaterial(m);
    addUpRect(sc, -1e4, -1e4, 1e4, 1e4, 0.0, gloss);
    const Tracer tracer(sc);
    TraceSettings s;
    const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0, 0, 1), Vec3(0, 0, -1), 0, s);
    const double want = kLumensPerWatt * kPi * (0.4 * 0.9 + 0.1);
    expectWithinStandardErrors(e, want, 0.01, roughness == 0.0 ? "mirror-like plastic" : "glossy plastic");
  }
}

}  // namespace
}  // namespace candela
