// Stability where interreflection methods are known to fail, each with a stated bound, for the
// path tracer and the irradiance cache: near contact, a light leak through a thin wall,
// splotches, a ρ = 0.9 closed box, and a 1 cm lamp seen through a mirror.
#include "engine/radiance/reader.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "validation/analytic.h"
#include "validation/speed_accuracy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {
namespace {

TraceSettings settings(Method m) {
  TraceSettings s = settingsForQuality(Quality::kNormal);
  s.method = m;
  s.hemisphereSamples = 1024;
  return s;
}

Scene fromText(const std::string& rad) {
  Scene sc;
  readRadianceText(rad, "<test>", sc);
  return sc;
}

TEST(Stability, NearContactMatchesTheClosedForm) {
  // The paper's sphere (R = 1 m, ρ 0.5) on a black plane under a uniform sky, sensors 5 mm above
  // the plane and 5 mm from the sphere (x = √(1.005² − 0.995²)) and 2 cm from it. Bound: 4
  // standard errors, and an error bar under 5 % (a peer's cache was −90 % here). The points see
  // mostly the sphere's dark underside and a sliver of sky at the horizon, hence 8192 samples.
  const Scene sc = fromText(
      "void glow sky 0 0 4 1 1 1 0\nsky source skydome 0 0 4 0 0 1 180\n"
      "void plastic black 0 0 5 0 0 0 0 0\nvoid plastic ball 0 0 5 0.5 0.5 0.5 0 0\n"
      "black polygon plane 0 0 12 -1e5 -1e5 0  1e5 -1e5 0  1e5 1e5 0  -1e5 1e5 0\n"
      "ball sphere s 0 0 4 0 0 1 1\n");
  const Tracer tracer(sc);
  const double h = 0.005;
  std::vector<SensorPoint> pts;
  std::vector<double> want;
  for (double gap : {0.005, 0.02}) {
    const double x = std::sqrt((1.0 + gap) * (1.0 + gap) - (1.0 - h) * (1.0 - h));
    pts.push_back({Vec3(x, 0, h), Vec3(0, 0, 1)});
    want.push_back(kLumensPerWatt * analytic::sphereOnPlane(0.5, 1.0, 1.0, x, h));
  }
  for (Method m : {Method::kPath, Method::kCache}) {
    TraceSettings s = settings(m);
    s.hemisphereSamples = 8192;
    const auto est = computeIrradiance(tracer, pts, s, 0);
    for (size_t i = 0; i < pts.size(); ++i) {
      std::printf("[ measured ] near contact (%s): %.5g ± %.2g lux, closed form %.5g lux\n",
                  m == Method::kCache ? "cache" : "path", est[i].illuminanceLux(), est[i].standardErrorLux(), want[i]);
      EXPECT_NEAR(est[i].illuminanceLux(), want[i], 4.0 * est[i].standardErrorLux());
      EXPECT_LT(est[i].standardErrorLux(), 0.05 * want[i]);
    }
  }
}

TEST(Stability, NoLightLeaksThroughAThinWall) {
  // Two 3 × 3 × 2.5 m rooms side by side sharing one floor and one ceiling polygon, parted by a
  // 1 cm wall (x = 3 to 3.01); a lamp in the left room only. Sensors on both sides of the wall,
  // 1 cm and 5 cm from it: the dark side must be exactly 0 (no light path exists), also with
  // the cache, whose lit records lie 2 cm away on the same floor polygon.
  const Scene sc = fromText(
      "void plastic grey 0 0 5 0.6 0.6 0.6 0 0\nvoid light lamp 0 0 3 5000 5000 5000\n"
      "lamp sphere bulb 0 0 4 1.5 1.5 2 0.05\n"
      "grey polygon floor 0 0 12 0 0 0  6.01 0 0  6.01 3 0  0 3 0\n"
      "grey polygon ceiling 0 0 12 0 0 2.5  0 3 2.5  6.01 3 2.5  6.01 0 2.5\n"
      "grey polygon south 0 0 12 0 0 0  0 0 2.5  6.01 0 2.5  6.01 0 0\n"
      "grey polygon north 0 0 12 0 3 0  6.01 3 0  6.01 3 2.5  0 3 2.5\n"
      "grey polygon west 0 0 12 0 0 0  0 3 0  0 3 2.5  0 0 2.5\n"
      "grey polygon east 0 0 12 6.01 0 0  6.01 0 2.5  6.01 3 2.5  6.01 3 0\n"
      "grey polygon wall_lit 0 0 12 3 0 0  3 0 2.5  3 3 2.5  3 3 0\n"
      "grey polygon wall_dark 0 0 12 3.01 0 0  3.01 3 0  3.01 3 2.5  3.01 0 2.5\n");
  const Tracer tracer(sc);
  std::vector<SensorPoint> pts;
  for (double y : {0.5, 1.5, 2.5}) {
    pts.push_back({Vec3(2.99, y, 0.01), Vec3(0, 0, 1)});   // lit side, 1 cm from the wall
    pts.push_back({Vec3(2.95, y, 0.01), Vec3(0, 0, 1)});
    pts.push_back({Vec3(3.02, y, 0.01), Vec3(0, 0, 1)});   // dark side, 1 cm from the wall
    pts.push_back({Vec3(3.06, y, 0.01), Vec3(0, 0, 1)});
    pts.push_back({Vec3(3.011, y, 1.0), Vec3(1, 0, 0)});   // on the dark face
  }
  for (Method m : {Method::kPath, Method::kCache}) {
    const auto est = computeIrradiance(tracer, pts, settings(m), 0);
    double dark = 0.0, lit = 1e300;
    for (size_t i = 0; i < pts.size(); ++i) {
      if (pts[i].position.x < 3.0) lit = std::min(lit, est[i].illuminanceLux());
      else dark = std::max(dark, est[i].illuminanceLux());
    }
    std::printf("[ measured ] thin wall (%s): lit side >= %.4g lux, dark side <= %.3g lux\n",
                m == Method::kCache ? "cache" : "path", lit, dark);
    EXPECT_GT(lit, 100.0);
    EXPECT_EQ(dark, 0.0);
  }
}

TEST(Stability, NoSplotchesAlongASymmetricWall) {
  // The uplit room (validation/speed_accuracy.cpp) is symmetric about x = 3: wall points at x and
  // 6 − x must agree within 4 combined standard errors (the cache is filled in an order that
  // knows nothing of the symmetry, so a splotch shows as a difference).
  validation::IndirectScene room;
  for (const auto& s : validation::indirectScenes())
    if (s.name == "uplit-room") room = s;
  ASSERT_FALSE(room.points.empty());
  std::vector<SensorPoint> wall;
  for (const SensorPoint& p : room.points)
    if (p.position.y < 0.1) wall.push_back(p);
  ASSERT_EQ(wall.size(), 6u);
  room.points = wall;
  for (Method m : {Method::kPath, Method::kCache}) {
    TraceSettings s = settingsForQuality(Quality::kNormal);
    s.method = m;
    const auto e = validation::runIndirectScene(room, s, 0, nullptr);
    for (int i = 0; i < 3; ++i) {
      const auto& a = e[i];
      const auto& b = e[5 - i];
      const double tol = 4.0 * std::hypot(a.standardErrorLux(), b.standardErrorLux());
      std::printf("[ measured ] uplit wall (%s): x=%.1f %.5g ± %.2g lux, x=%.1f %.5g ± %.2g lux (%.2f %%)\n",
                  m == Method::kCache ? "cache" : "path", wall[i].position.x, a.illuminanceLux(),
                  a.standardErrorLux(), wall[5 - i].position.x, b.illuminanceLux(), b.standardErrorLux(),
                  100 * (a.illuminanceLux() - b.illuminanceLux()) / b.illuminanceLux());
      EXPECT_NEAR(a.illuminanceLux(), b.illuminanceLux(), tol);
    }
  }
}

TEST(Stability, HighReflectanceClosedBoxConservesEnergy) {
  // A closed 3 m cube of ρ = 0.9 with a 2 cm light sphere (L = 1000) off centre: every watt
  // emitted lands on the walls 1/(1 − ρ) = 10 times, so the walls' mean irradiance is
  // Φ/(A(1 − ρ)), Φ = 4π² r² L, A = 54 m². 60 sensors at stratified random places on the six
  // faces (10 each, facing in) estimate the mean; its standard error comes from their spread.
  // Bound: 4 standard errors plus 0.5 % (the lamp absorbs what falls back on it: ~r²/d² per
  // bounce, about 0.2 % over ten bounces). The bounce cap is lifted (0.9^33 = 3 % would be
  // missing after 32 bounces); Russian roulette ends the paths.
  const double rho = 0.9, L = 1000.0, r = 0.02, side = 3.0;
  const Scene sc = fromText(
      "void plastic white 0 0 5 0.9 0.9 0.9 0 0\nvoid light lamp 0 0 3 1000 1000 1000\n"
      "lamp sphere bulb 0 0 4 1.2 1.4 1.7 0.02\n"
      "white polygon f0 0 0 12 0 0 0  3 0 0  3 3 0  0 3 0\n"
      "white polygon f1 0 0 12 0 0 3  0 3 3  3 3 3  3 0 3\n"
      "white polygon f2 0 0 12 0 0 0  0 0 3  3 0 3  3 0 0\n"
      "white polygon f3 0 0 12 0 3 0  3 3 0  3 3 3  0 3 3\n"
      "white polygon f4 0 0 12 0 0 0  0 3 0  0 3 3  0 0 3\n"
      "white polygon f5 0 0 12 3 0 0  3 0 3  3 3 3  3 3 0\n");
  const Tracer tracer(sc);
  std::vector<SensorPoint> pts;
  Rng rng(11, 0);
  const double in = 0.001;  // 1 mm off the face
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const bool high = face % 2 == 1;
    for (int i = 0; i < 10; ++i) {
      const double u = side * (i % 5 + rng.uniform()) / 5.0, v = side * (i / 5 + rng.uniform()) / 2.0;
      Vec3 p(0.0), n(0.0);
      p[axis] = high ? side - in : in;
      p[(axis + 1) % 3] = u;
      p[(axis + 2) % 3] = v;
      n[axis] = high ? -1.0 : 1.0;
      pts.push_back({p, n});
    }
  }
  const double want = kLumensPerWatt * 4.0 * kPi * kPi * r * r * L / (6.0 * side * side * (1.0 - rho));
  for (Method m : {Method::kPath, Method::kCache}) {
    TraceSettings s = settings(m);
    s.maxBounces = 1000;
    // The mean's error is the sensors' spread over the faces, not their own noise: the preset's
    // per-point target would buy nothing here.
    s.targetRelativeError = 0.0;
    const auto est = computeIrradiance(tracer, pts, s, 0);
    double sum = 0.0, sum2 = 0.0;
    for (const auto& e : est) sum += e.illuminanceLux(), sum2 += e.illuminanceLux() * e.illuminanceLux();
    const double n = static_cast<double>(est.size()), mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    std::printf("[ measured ] rho 0.9 box (%s): mean %.5g ± %.2g lux, energy balance %.5g lux (%+.2f %%)\n",
                m == Method::kCache ? "cache" : "path", mean, se, want, 100 * (mean - want) / want);
    EXPECT_NEAR(mean, want, 4.0 * se + 0.005 * want);
  }
}

TEST(Stability, OneCentimetreLampThroughAMirrorWithTheCache) {
  // The 1 cm lamp and mirror wall of tracer_test (MirrorEqualsTheUnfoldedScene): the cache must
  // agree with the unfolded scene too (records see the lamp's image as a virtual source).
  auto scene = [](bool unfolded) {
    std::string rad = "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\nvoid light lamp 0 0 3 2e4 2e4 2e4\n"
                      "lamp sphere l1 0 0 4 0.5 0 1 0.01\n";
    if (unfolded) {
      rad += "grey polygon floor 0 0 12 -1 -1 0  3 -1 0  3 1 0  -1 1 0\nlamp sphere l2 0 0 4 1.5 0 1 0.01\n";
    } else {
      rad += "grey polygon floor 0 0 12 -1 -1 0  1 -1 0  1 1 0  -1 1 0\n"
             "void mirror glass_mirror 0 0 3 1 1 1\n"
             "glass_mirror polygon m 0 0 12 1 -1.5 0  1 -1.5 3  1 1.5 3  1 1.5 0\n";
    }
    return fromText(rad);
  };
  const Scene a = scene(false), b = scene(true);
  const Tracer ta(a), tb(b);
  const std::vector<SensorPoint> pts = {{Vec3(-0.5, 0, 0.01), Vec3(0, 0, 1)}, {Vec3(0.0, 0.3, 2.0), Vec3(0, 0, -1)},
                                        {Vec3(0.8, -0.2, 0.5), Vec3(1, 0, 0)}};
  TraceSettings s = settings(Method::kCache);
  const auto ea = computeIrradiance(ta, pts, s, 0);
  s.seed = 7;
  s.method = Method::kPath;
  const auto eb = computeIrradiance(tb, pts, s, 0);
  for (size_t i = 0; i < pts.size(); ++i) {
    std::printf("[ measured ] 1 cm lamp via mirror: cache %.5g ± %.2g lux, unfolded (path) %.5g ± %.2g lux\n",
                ea[i].illuminanceLux(), ea[i].standardErrorLux(), eb[i].illuminanceLux(), eb[i].standardErrorLux());
    EXPECT_NEAR(ea[i].illuminanceLux(), eb[i].illuminanceLux(),
                4.0 * std::hypot(ea[i].standardErrorLux(), eb[i].standardErrorLux()));
  }
}

}  // namespace
}  // namespace candela
