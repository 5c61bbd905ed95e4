// Portals (engine/portals.h): spherical-triangle sampling against closed forms, the portal
// density against its own samples, and the sky estimator with portals right, partial, wrong
// and absent, all against configuration factors (within 4 standard errors over seeds).
#include "engine/daylight.h"
#include "engine/lights.h"
#include "engine/portals.h"
#include "engine/radiance/reader.h"
#include "engine/sampling.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "validation/analytic.h"
#include "tests/support/aperture_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

// Solid angle of an a × b rectangle seen from a point on its axis at distance d:
// Ω = 4 asin(ab / √((a² + 4d²)(b² + 4d²))) (e.g. Khadjavi 1968, JOSA 58).
double rectangleSolidAngle(double a, double b, double d) {
  return 4.0 * std::asin(a * b / std::sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d)));
}

TEST(Portals, TriangleSolidAngleMatchesTheRectangleClosedForm) {
  const double a = 1.0, b = 1.5, d = 3.0;
  const Vec3 p(0.0);
  const Vec3 v0(-a / 2, -b / 2, d), v1(a / 2, -b / 2, d), v2(a / 2, b / 2, d), v3(-a / 2, b / 2, d);
  const double om = triangleSolidAngle(v0 - p, v1 - p, v2 - p) + triangleSolidAngle(v0 - p, v2 - p, v3 - p);
  EXPECT_NEAR(om, rectangleSolidAngle(a, b, d), 1e-12);
  // A triangle covering more than a hemisphere's worth of the view: a point just below a large
  // triangle sees nearly 2π.
  EXPECT_NEAR(triangleSolidAngle(Vec3(-1e4, -1e4, 1e-3), Vec3(1e4, -1e4, 1e-3), Vec3(0, 1e4, 1e-3)), kTwoPi, 1e-5);
}

TEST(Portals, SphericalTriangleSamplesAreUniformInSolidAngle) {
  // A triangle seen from the origin: every sample hits it; the mean of cos θ times Ω is the
  // projected solid angle (Lambert's formula), and the share of samples in one of its four
  // midpoint sub-triangles is that sub-triangle's share of Ω (binomial, 4 σ).
  const Vec3 t0(-0.5, -0.3, 1.0), t1(1.2, -0.2, 1.5), t2(0.1, 0.9, 0.7);
  const Vec3 a = glm::normalize(t0), b = glm::normalize(t1), c = glm::normalize(t2);
  const double om = triangleSolidAngle(t0, t1, t2);
  const Vec3 m01 = 0.5 * (t0 + t1), m02 = 0.5 * (t0 + t2);
  const double share = triangleSolidAngle(t0, m01, m02) / om;
  const Vec3 n(0.0, 0.0, 1.0);
  const Strata2D strata(40000);
  Rng rng(7, 0);
  double sum = 0.0, sum2 = 0.0;
  int inSub = 0;
  for (int i = 0; i < strata.size(); ++i) {
    const Vec2 u = strata.sample(i, rng);
    Vec3 d;
    ASSERT_TRUE(sampleSphericalTriangle(a, b, c, u.x, u.y, d));
    double t = 0.0;
    ASSERT_TRUE(intersectTriangle(t0, t1 - t0, t2 - t0, Vec3(0.0), d, 0.0, 1e9, t)) << i;
    const double f = om * glm::dot(n, d);
    sum += f;
    sum2 += f * f;
    if (intersectTriangle(t0, m01 - t0, m02 - t0, Vec3(0.0), d, 0.0, 1e9, t)) ++inSub;
  }
  const double k = strata.size(), mean = sum / k, se = std::sqrt((sum2 / k - mean * mean) / (k - 1));
  EXPECT_NEAR(mean, polygonProjectedSolidAngle({t0, t1, t2}, Vec3(0.0), n), 4.0 * se);
  EXPECT_NEAR(inSub / k, share, 4.0 * std::sqrt(share * (1 - share) / k));
}

Scene sceneWithPortals(const std::vector<std::vector<Vec3>>& portals) {
  Scene scene;
  for (const auto& p : portals) scene.portals.push_back({p, "p", {}});
  return scene;
}

TEST(Portals, DensityIntegratesToOneAndMatchesItsSamples) {
  // Two portals, one partly below the receiver's horizon, one wholly below (never chosen).
  const Scene scene = sceneWithPortals({{Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(1, 1, 2), Vec3(-1, 1, 2)},
                                        {Vec3(3, -1, -1), Vec3(3, 1, -1), Vec3(3, 1, 1), Vec3(3, -1, 1)},
                                        {Vec3(-1, -1, -2), Vec3(-1, 1, -2), Vec3(1, 1, -2), Vec3(1, -1, -2)}});
  const PortalSet set(scene);
  ASSERT_EQ(set.size(), 3u);
  const Vec3 p(0.2, 0.1, 0.0), n(0.0, 0.0, 1.0);
  PortalView view;
  set.view(p, n, view);
  ASSERT_GT(view.total, 0.0);
  EXPECT_EQ(view.cumulative[2], view.cumulative[1]);  // below the horizon: weight 0
  // ∫ pdf dω over the sphere = 1, by uniform sphere sampling.
  const Strata2D strata(200000);
  Rng rng(3, 0);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < strata.size(); ++i) {
    const Vec2 u = strata.sample(i, rng);
    const double z = 1.0 - 2.0 * u.x, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = kTwoPi * u.y;
    const double f = 4.0 * kPi * set.pdf(p, n, Vec3(r * std::cos(phi), r * std::sin(phi), z));
    sum += f;
    sum2 += f * f;
  }
  const double k = strata.size(), mean = sum / k;
  EXPECT_NEAR(mean, 1.0, 4.0 * std::sqrt((sum2 / k - mean * mean) / (k - 1)));
  // Samples: the first portal's density is h/S with h its largest vertex cosine.
  for (int i = 0; i < 100; ++i) {
    Vec3 d;
    ASSERT_TRUE(set.sample(view, p, (i + 0.5) / 100.0, 0.37, d));
    EXPECT_GT(set.pdf(p, n, d), 0.0);
  }
}

using test_support::kRoofOpening;  // the validation case's roof

Scene daylit(const char* rad, const std::vector<std::vector<Vec3>>& portals, const char* sky, double rhoGround) {
  Scene scene = sceneWithPortals(portals);
  if (rad) readRadianceText(rad, "<portal test>", scene);
  DaylightSpec d;
  d.skyType = parseSkyType(sky).value();
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = rhoGround;
  d.sun = false;
  addDaylight(scene, d);
  return scene;
}

// Mean and standard error over seeds 1..n of the illuminance at (p, nrm), draft quality.
std::pair<double, double> overSeeds(const Scene& scene, const Vec3& p, const Vec3& nrm, int n) {
  const Tracer tracer(scene);
  TraceSettings s = settingsForQuality(Quality::kDraft);
  double sum = 0.0, sum2 = 0.0;
  for (int seed = 1; seed <= n; ++seed) {
    s.seed = static_cast<uint64_t>(seed);
    const double e = computeIrradiance(tracer, {{p, nrm}}, s, 1)[0].illuminanceLux();
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1))};
}

TEST(Portals, SkyThroughARoofOpeningIsUnbiasedWhateverThePortals) {
  // E = π L F under a uniform sky for portals: exact, covering only half the opening, beside
  // the opening over the black roof, and below the floor (never chosen). A wrong portal may cost
  // variance, never bias: each mean over 24 seeds within 4 of its standard errors.
  const double L = 10000.0 / kPi;
  const std::vector<Vec3> exact = {Vec3(-0.5, -0.75, 3), Vec3(0.5, -0.75, 3), Vec3(0.5, 0.75, 3), Vec3(-0.5, 0.75, 3)};
  const std::vector<Vec3> half = {Vec3(-0.5, -0.75, 3), Vec3(0.0, -0.75, 3), Vec3(0.0, 0.75, 3), Vec3(-0.5, 0.75, 3)};
  const std::vector<Vec3> beside = {Vec3(1, -1, 3), Vec3(3, -1, 3), Vec3(3, 1, 3), Vec3(1, 1, 3)};
  const std::vector<Vec3> below = {Vec3(-1, -1, -1), Vec3(1, -1, -1), Vec3(1, 1, -1), Vec3(-1, 1, -1)};
  const std::vector<std::pair<const char*, std::vector<std::vector<Vec3>>>> sets = {
      {"exact", {exact}}, {"half", {half}}, {"beside", {beside}}, {"below", {below}}, {"half+beside", {half, beside}}};
  for (const auto& [what, portals] : sets) {
    const Scene scene = daylit(kRoofOpening, portals, "uniform", 0.0);
    for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 1.0}}) {
      const double ref = analytic::rectangleAbove(L, {-0.5, -0.75, 0.5, 0.75}, 3.0, x, y);
      const auto [mean, se] = overSeeds(scene, Vec3(x, y, 0), Vec3(0, 0, 1), 24);
      EXPECT_NEAR(mean, ref, 4.0 * se) << what << " at (" << x << ", " << y << "), se " << se;
    }
  }
}

TEST(Portals, OpenSkyWithAWrongPortalIsUnbiased) {
  // No roof: the open horizontal plane reads E_h = 10000 lux whatever portal is declared.
  const Scene scene = daylit(nullptr, {{Vec3(1, -1, 3), Vec3(3, -1, 3), Vec3(3, 1, 3), Vec3(1, 1, 3)}}, "cie-overcast", 0.0);
  const auto [mean, se] = overSeeds(scene, Vec3(0.0), Vec3(0, 0, 1), 24);
  EXPECT_NEAR(mean, 10000.0, 4.0 * se + 1e-9 * 10000.0);
}

TEST(Portals, GroundThroughAWindowIsWeightedLikeTheSky) {
  // A 2 × 1 m window (z 0.5–1.5 m) in an infinite black wall x = 0; a sensor 1 m in, at the
  // window's mid height, facing it: the upper half shows the uniform sky (L), the lower half the
  // ground (ρ E_h / π = L/2 for ρ = 0.5). Each half is a rectangle parallel to the sensor's
  // plane, with a corner on its axis: E = π L F + π (L/2) F (Howell B-3).
  const char* wall = "void plastic black 0 0 5 0 0 0 0 0\n"
                     "black polygon w1 0 0 12 0 -1e4 -1e4  0 -1e4 0.5  0 1e4 0.5  0 1e4 -1e4\n"
                     "black polygon w2 0 0 12 0 -1e4 1.5  0 -1e4 1e4  0 1e4 1e4  0 1e4 1.5\n"
                     "black polygon w3 0 0 12 0 -1e4 0.5  0 -1e4 1.5  0 -1 1.5  0 -1 0.5\n"
                     "black polygon w4 0 0 12 0 1 0.5  0 1 1.5  0 1e4 1.5  0 1e4 0.5\n";
  const double L = 10000.0 / kPi;
  const double f = analytic::rectangleAbove(1.0, {-1.0, 0.0, 1.0, 0.5}, 1.0, 0.0, 0.0);  // π F per unit L
  const double ref = (L + 0.5 * L) * f;
  for (const bool withPortal : {false, true}) {
    std::vector<std::vector<Vec3>> portals;
    if (withPortal) portals.push_back({Vec3(0, -1, 0.5), Vec3(0, 1, 0.5), Vec3(0, 1, 1.5), Vec3(0, -1, 1.5)});
    const Scene scene = daylit(wall, portals, "uniform", 0.5);
    const auto [mean, se] = overSeeds(scene, Vec3(1.0, 0.0, 1.0), Vec3(-1, 0, 0), 24);
    EXPECT_NEAR(mean, ref, 4.0 * se) << (withPortal ? "with" : "without") << " the portal, se " << se;
  }
}

TEST(Portals, GlazingIsFoundAndHolesAreNot) {
  Scene scene;
  readRadianceText("void glass pane 0 0 3 0.9 0.9 0.9\n"
                   "void trans film 0 0 7 0.8 0.8 0.8 0 0 0.5 1\n"
                   "void trans diffuser 0 0 7 0.8 0.8 0.8 0 0 0.5 0\n"
                   "void illum window 0 0 3 1 1 1\n"
                   "void dielectric block 0 0 5 0.9 0.9 0.9 1.5 0\n"
                   "void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n"
                   "pane polygon g 0 0 12 0 0 1  1 0 1  1 0 2  0 0 2\n"
                   "film polygon t 0 0 12 2 0 1  3 0 1  3 0 2  2 0 2\n"
                   "diffuser polygon d 0 0 12 4 0 1  5 0 1  5 0 2  4 0 2\n"
                   "window polygon i 0 0 12 6 0 1  7 0 1  7 0 2  6 0 2\n"
                   "block polygon b 0 0 12 8 0 1  9 0 1  9 0 2  8 0 2\n"
                   "wall polygon w 0 0 12 0 1 0  9 1 0  9 1 3  0 1 3\n",
                   "<glazing>", scene);
  scene.portals.push_back({{Vec3(0, 0, 3), Vec3(1, 0, 3), Vec3(1, 1, 3)}, "declared", {}});
  const PortalSet set(scene);
  // Declared one, glass, specular trans and the illum without alternate: not the diffusing
  // trans, the dielectric (shadow rays stop there) nor the wall.
  EXPECT_EQ(set.size(), 4u);
  EXPECT_EQ(set.foundCount(), 3u);
}

}  // namespace
}  // namespace candela
