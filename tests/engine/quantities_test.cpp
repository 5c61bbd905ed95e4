// Cylindrical, semi-cylindrical and hemispherical illuminance (engine/response.h) from the
// sensor estimator against their closed forms (docs/quantities.md): a point luminaire alone (no
// surface, so no indirect light: the estimate is deterministic and exact), a spherical source
// (sampled: within 4 of its standard errors of a quadrature), a uniform sky over open ground
// (sky samples and escaping rays weighted by MIS) and over a grey floor (light from below by the
// hemisphere rays, path and cache methods), with the same numbers on 1 and 2 threads.
#include "engine/daylight.h"
#include "engine/luminaire_source.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "photometry/ies_lm63.h"
#include "tests/engine/test_materials.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace candela {
namespace {

using test_support::addMaterial;

const Vec3 kUp(0.0, 0.0, 1.0);

// I = 1000 cos γ (1 + 0.5 cos(C − 30°)) of tests/data/ies/asym_c.ies, exact on its (C, γ) grid.
double asymIntensity(double cDeg, double gammaDeg) {
  return 1000.0 * std::cos(degToRad(gammaDeg)) * (1.0 + 0.5 * std::cos(degToRad(cDeg - 30.0)));
}

constexpr double kMountM = 3.0, kSensorM = 1.2;

Scene pointLuminaire() {
  Scene sc;
  LuminaireMounting m;
  m.positionM = Vec3(0.0, 0.0, kMountM);
  sc.luminaires.push_back(
      placeLuminaire(std::make_shared<const PhotometricWeb>(readIes(std::string(CANDELA_TEST_DATA) + "/ies/asym_c.ies")), m));
  return sc;
}

Vec3 planDir(double deg) { return {std::cos(degToRad(deg)), std::sin(degToRad(deg)), 0.0}; }

// The sensor at 1.2 m in direction (C, γ) of the luminaire: ε = γ at the sensor, the source
// seen in plan towards C + 180°.
struct Geometry {
  Vec3 p;
  double d, eps, towardsSourceDeg, intensity;
};
Geometry below(double cDeg, double gammaDeg) {
  Geometry g;
  const double t = degToRad(gammaDeg);
  g.d = (kMountM - kSensorM) / std::cos(t);
  g.p = Vec3(0.0, 0.0, kMountM) + g.d * (std::sin(t) * planDir(cDeg) - std::cos(t) * kUp);
  g.eps = t;
  g.towardsSourceDeg = cDeg + 180.0;
  g.intensity = asymIntensity(cDeg, gammaDeg);
  return g;
}

TEST(Quantities, PointLuminaireGivesTheClosedFormsExactly) {
  // One shadow ray per point luminaire and no surface to reflect: nothing random is left, the
  // estimate is the closed form to the web's printing precision (9 digits) and its standard
  // error is 0.
  const Scene sc = pointLuminaire();
  const Tracer tracer(sc);
  const TraceSettings s;
  double worst = 0.0;
  for (double c : {0.0, 30.0, 105.0, 240.0})
    for (double gamma : {20.0, 45.0, 60.0}) {
      const Geometry g = below(c, gamma);
      const double k = g.intensity / (g.d * g.d);
      auto check = [&](const Response& r, double want, const std::string& what) {
        const IrradianceEstimate e = estimateIrradiance(tracer, g.p, r, 0, s);
        EXPECT_NEAR(e.illuminanceLux(), want, 1e-7 * want) << what << " C " << c << " gamma " << gamma;
        EXPECT_EQ(e.standardErrorLux(), 0.0) << what;
        worst = std::max(worst, std::abs(e.illuminanceLux() / want - 1.0));
      };
      check({Quantity::kCylindrical, kUp, Vec3(1, 0, 0)}, k * std::sin(g.eps) / kPi, "cylindrical");
      for (double alpha : {0.0, 120.0, -60.0})
        check({Quantity::kSemiCylindrical, kUp, planDir(g.towardsSourceDeg + alpha)},
              k * std::sin(g.eps) * (1.0 + std::cos(degToRad(alpha))) / kPi,
              "semi-cylindrical alpha " + std::to_string(alpha));
      check({Quantity::kHemispherical, kUp, Vec3(1, 0, 0)}, k * (1.0 + std::cos(g.eps)) / 4.0, "hemispherical");
      // Vertical illuminance is planar illuminance on a horizontal normal: E cos α sin ε.
      for (double alpha : {0.0, 60.0})
        check(Response::planar(planDir(g.towardsSourceDeg + alpha)),
              k * std::sin(g.eps) * std::cos(degToRad(alpha)), "vertical alpha " + std::to_string(alpha));
    }
  std::printf("[ measured ] point luminaire: largest relative error %.2g\n", worst);
  // Facing away (α = 180°) the half-cylinder receives nothing, exactly.
  const Geometry g = below(30.0, 45.0);
  EXPECT_EQ(estimateIrradiance(tracer, g.p, Response{Quantity::kSemiCylindrical, kUp, planDir(g.towardsSourceDeg + 180.0)}, 0, s)
                .illuminanceLux(),
            0.0);
}

// ∫ over a cap of half-angle a about unit c of w(ω) dω, midpoint rule in (cos, φ) about c.
double capIntegral(const Response& r, const Vec3& c, double a, int n = 600) {
  const Frame f = Frame::fromNormal(c);
  const double lo = std::cos(a);
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double z = lo + (1.0 - lo) * (i + 0.5) / n, sz = std::sqrt(1.0 - z * z), p = kTwoPi * (j + 0.5) / n;
      s += r.weight(f.toWorld(Vec3(sz * std::cos(p), sz * std::sin(p), z)));
    }
  return s * (1.0 - lo) * kTwoPi / (n * n);
}

TEST(Quantities, SphereSourceWithinFourStandardErrorsOfQuadrature) {
  // A sampled area source has no closed form for w: the plain mean of its samples, whose error
  // bar (strata collapsed in pairs) bounds the distance to the quadrature.
  Scene sc;
  const double radiance = 2000.0, r = 0.25;
  const Vec3 centre(0.0, 0.0, kMountM);
  sc.addSphere(centre, r, addMaterial(sc, MaterialType::kLight, radiance));
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 16;
  s.hemisphereSamples = 64;
  for (const Vec3 p : {Vec3(0.4, 0.2, kSensorM), Vec3(1.5, -1.0, kSensorM), Vec3(-3.0, 0.5, kSensorM)}) {
    const Vec3 toC = centre - p;
    const double dist = glm::length(toC), a = std::asin(r / dist);
    const Vec3 plan = glm::normalize(Vec3(toC.x, toC.y, 0.0));
    const Vec3 side = glm::cross(kUp, plan);
    for (const Response& resp : {Response{Quantity::kCylindrical, kUp, Vec3(1, 0, 0)},
                                 Response{Quantity::kSemiCylindrical, kUp, plan},
                                 Response{Quantity::kSemiCylindrical, kUp, glm::normalize(-0.5 * plan + 0.866 * side)},
                                 Response{Quantity::kHemispherical, kUp, Vec3(1, 0, 0)}}) {
      const double want = kLumensPerWatt * radiance * capIntegral(resp, toC / dist, a);
      const IrradianceEstimate e = estimateIrradiance(tracer, p, resp, 7, s);
      EXPECT_GT(e.standardErrorLux(), 0.0);
      EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux() + 1e-6 * want)
          << static_cast<int>(resp.kind) << " at " << p.x << " " << p.y;
      std::printf("[ measured ] sphere source, kind %d: error %.3g %% of %.4g lx, %.2f standard errors\n",
                  static_cast<int>(resp.kind), 100.0 * (e.illuminanceLux() / want - 1.0), want,
                  (e.illuminanceLux() - want) / e.standardErrorLux());
    }
  }
}

// A uniform sky of 10 000 lux on the open horizontal plane (L = 10000/π cd/m²) and its ground
// of reflectance rho below the horizon (Lg = rho · 10000/π), with `floorRho` > 0 a grey floor at
// z = 0 (1e4 m across) of that reflectance instead of open ground.
Scene uniformSky(double rho, double floorRho = 0.0) {
  Scene sc;
  if (floorRho > 0.0)
    sc.addPolygon({{-1e4, -1e4, 0}, {1e4, -1e4, 0}, {1e4, 1e4, 0}, {-1e4, 1e4, 0}},
                  addMaterial(sc, MaterialType::kPlastic, floorRho));
  DaylightSpec d;
  d.skyType = parseSkyType("uniform").value();
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = rho;
  addDaylight(sc, d);
  return sc;
}

struct Expected {
  Response response;
  double lux;
  const char* what;
};

// The quantities under sky radiance L over the upper hemisphere and Lb below (cd/m²):
// cylindrical and semi-cylindrical π/2 (L + Lb) (each hemisphere gives ∫ sin θ/π dω = π/2, and
// 1 + cos α averages to 1 over a uniform ring), hemispherical 3π/4 L, horizontal π L.
std::vector<Expected> underSky(double L, double Lb) {
  return {{{Quantity::kCylindrical, kUp, Vec3(1, 0, 0)}, 0.5 * kPi * (L + Lb), "cylindrical"},
          {{Quantity::kSemiCylindrical, kUp, planDir(70.0)}, 0.5 * kPi * (L + Lb), "semi-cylindrical"},
          {{Quantity::kHemispherical, kUp, Vec3(1, 0, 0)}, 0.75 * kPi * L, "hemispherical"},
          {Response::planar(kUp), kPi * L, "horizontal"}};
}

TEST(Quantities, UniformSkyOverOpenGroundWithinFourStandardErrors) {
  const Scene sc = uniformSky(0.2);
  const Tracer tracer(sc);
  TraceSettings s;
  s.hemisphereSamples = 256;
  s.lightSamples = 16;
  const double L = 10000.0 / kPi;
  for (const Expected& x : underSky(L, 0.2 * L))
    for (uint64_t seed : {1, 2, 3}) {
      s.seed = seed;
      const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0.0, 0.0, kSensorM), x.response, 0, s);
      EXPECT_NEAR(e.illuminanceLux(), x.lux, 4.0 * e.standardErrorLux() + 1e-9 * x.lux) << x.what;
      std::printf("[ measured ] uniform sky, %s seed %d: error %.3g %%, %.2f standard errors (%.3g %%)\n", x.what,
                  static_cast<int>(seed), 100.0 * (e.illuminanceLux() / x.lux - 1.0),
                  (e.illuminanceLux() - x.lux) / std::max(1e-300, e.standardErrorLux()),
                  100.0 * e.standardErrorLux() / x.lux);
    }
}

TEST(Quantities, GreyFloorUnderSkyPathAndCacheOnOneAndTwoThreads) {
  // The floor (ρ 0.5) under the sky has irradiance π L and radiance ρ L; the ground beyond it
  // (ρ 0.5) the same, so the lower hemisphere is ρ L throughout. Its light reaches the
  // cylinder only by the hemisphere rays (the sky's own samples are above the horizon).
  const double rho = 0.5, L = 10000.0 / kPi;
  const Scene sc = uniformSky(rho, rho);
  const Tracer tracer(sc);
  const std::vector<Expected> want = underSky(L, rho * L);
  std::vector<SensorPoint> points;
  std::vector<double> exact;
  for (int i = 0; i < 3; ++i)
    for (const Expected& x : want) {
      // A semi-cylindrical sensor's normal is its facing (engine/sensors.h).
      const bool semi = x.response.kind == Quantity::kSemiCylindrical;
      SensorPoint p{Vec3(0.7 * i, -0.4 * i, kSensorM), semi ? x.response.facing : x.response.n, x.response.kind};
      EXPECT_EQ(p.response().weight(planDir(10.0)), x.response.weight(planDir(10.0)));
      points.push_back(p);
      exact.push_back(x.lux);
    }
  for (Method method : {Method::kPath, Method::kCache}) {
    TraceSettings s;
    s.hemisphereSamples = 256;
    s.lightSamples = 16;
    s.maxBounces = 4;
    s.method = method;
    s.cache.recordSamples = 256;
    const std::vector<IrradianceEstimate> one = computeIrradiance(tracer, points, s, 1);
    const std::vector<IrradianceEstimate> two = computeIrradiance(tracer, points, s, 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const char* what = want[i % want.size()].what;
      const char* m = method == Method::kPath ? "path" : "cache";
      EXPECT_EQ(one[i].illuminanceLux(), two[i].illuminanceLux()) << what << " " << m;
      EXPECT_EQ(one[i].standardErrorLux(), two[i].standardErrorLux()) << what << " " << m;
      EXPECT_NEAR(one[i].illuminanceLux(), exact[i], 4.0 * one[i].standardErrorLux()) << what << " " << m << " point " << i;
      std::printf("[ measured ] grey floor, %s, %s: error %.3g %%, %.2f standard errors (%.3g %%)\n", m, what,
                  100.0 * (one[i].illuminanceLux() / exact[i] - 1.0),
                  (one[i].illuminanceLux() - exact[i]) / one[i].standardErrorLux(),
                  100.0 * one[i].standardErrorLux() / exact[i]);
    }
  }
}

}  // namespace
}  // namespace candela
