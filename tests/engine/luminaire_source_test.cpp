// Luminaires traced as light sources: the inverse-square and cosine laws in the far field, the
// documented aim/spin conventions, and the area-source answer in the near field.
#include "engine/lights.h"
#include "engine/luminaire_source.h"
#include "engine/tracer.h"
#include "photometry/ies_lm63.h"
#include "validation/analytic.h"

#include "tests/engine/lambertian_panel.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela {
namespace {

const std::string kIes = std::string(CANDELA_TEST_DATA) + "/ies/";

// I = 1000 cos γ (1 + 0.5 cos(C − 30°)) of tests/data/ies/asym_c.ies (5° × 15° grid).
double asymIntensity(double cDeg, double gammaDeg) {
  return 1000.0 * std::cos(degToRad(gammaDeg)) * (1.0 + 0.5 * std::cos(degToRad(cDeg - 30.0)));
}

Scene sceneWith(const std::string& file, const Vec3& pos, const Vec3& aim, double spinDeg, double mult = 1.0) {
  Scene sc;
  LuminaireMounting p;
  p.positionM = pos;
  p.aim = aim;
  p.spinDeg = spinDeg;
  p.scale = mult;
  sc.luminaires.push_back(placeLuminaire(std::make_shared<const PhotometricWeb>(readIes(kIes + file)), p));
  return sc;
}

double lux(const Tracer& t, const Vec3& p, const Vec3& n) { return estimateIrradiance(t, p, n, 0, TraceSettings{}).illuminanceLux(); }

// Directions on the file's (C, γ) grid, where bilinear interpolation is exact: E = I cos ι / d²
// to the printing precision of the file (9 digits), far inside the 0.5 % a photometric web promises.
TEST(LuminaireSource, InverseSquareAndCosineLawOnAPlane) {
  const double h = 3.0;
  const Scene sc = sceneWith("asym_c.ies", {1.0, 2.0, h}, {0, 0, -1}, 0.0);
  const Tracer tracer(sc);
  for (double c : {0.0, 30.0, 105.0, 240.0}) {
    for (double g : {20.0, 45.0, 60.0}) {  // not γ = 0: the test function depends on C there
      const Vec3 dir(std::sin(degToRad(g)) * std::cos(degToRad(c)), std::sin(degToRad(g)) * std::sin(degToRad(c)),
                     -std::cos(degToRad(g)));
      const double d = h / std::cos(degToRad(g));
      const Vec3 p = Vec3(1.0, 2.0, h) + d * dir;
      const double want = asymIntensity(c, g) * std::cos(degToRad(g)) / (d * d);
      EXPECT_NEAR(lux(tracer, p, {0, 0, 1}), want, 1e-6 * want) << "C " << c << " gamma " << g;
    }
  }
}

TEST(LuminaireSource, SpinTurnsTheC0PlaneCounterClockwiseSeenFromAbove) {
  // Spin 90: the C0 plane points to +Y, so the receiver towards +Y sees I(C0).
  const double g = 30.0, h = 2.0, r = h * std::tan(degToRad(g));
  const Scene sc = sceneWith("asym_c.ies", {0, 0, h}, {0, 0, -1}, 90.0);
  const Tracer spun(sc);
  const double d2 = h * h + r * r, cosI = h / std::sqrt(d2);
  EXPECT_NEAR(lux(spun, {0, r, 0}, {0, 0, 1}), asymIntensity(0.0, g) * cosI / d2, 1e-6);
  EXPECT_NEAR(lux(spun, {-r, 0, 0}, {0, 0, 1}), asymIntensity(90.0, g) * cosI / d2, 1e-6);
}

TEST(LuminaireSource, AimMovesTheNadir) {
  // Aimed along +X (C0 then points to +Y): the direction γ = 45° in the C0 plane reaches the wall
  // x = 4 at y = 4, with incidence 45° on it and d = 4√2.
  const Scene sc = sceneWith("asym_c.ies", {0, 0, 1}, {1, 0, 0}, 0.0);
  const Tracer tracer(sc);
  const double d2 = 32.0;
  const double want = asymIntensity(0.0, 45.0) * std::cos(degToRad(45.0)) / d2;
  EXPECT_NEAR(lux(tracer, {4, 4, 1}, {-1, 0, 0}), want, 1e-6 * want);
  // Nothing reaches a receiver behind the fitting (γ > 90° is dark in this file).
  EXPECT_EQ(lux(tracer, {-4, 0, 1}, {1, 0, 0}), 0.0);
}

TEST(LuminaireSource, MultiplierAndMaintenanceFactorScale) {
  const Scene s1 = sceneWith("asym_c.ies", {0, 0, 2}, {0, 0, -1}, 0.0, 1.0);
  const Scene s2 = sceneWith("asym_c.ies", {0, 0, 2}, {0, 0, -1}, 0.0, 2.5);
  const Tracer one(s1), two(s2);
  EXPECT_NEAR(lux(two, {0, 0, 0}, {0, 0, 1}), 2.5 * lux(one, {0, 0, 0}, {0, 0, 1}), 1e-9);
}

// A Lambertian 0.6 m × 0.6 m panel (I = I0 cos γ, I0 = 1000 cd, so luminance L = I0/A) 0.3 m
// above a sensor: the area-source answer is Lambert's, E = L · F·π for the square; the point-source
// answer I0/h² would overstate it.
TEST(LuminaireSource, NearFieldPanelGivesTheAreaSourceAnswer) {
  Scene sc;
  LuminaireMounting p;
  p.positionM = {0, 0, 0.3};
  sc.luminaires.push_back(
      placeLuminaire(test_support::lambertianPanel(), p));
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 4096;
  const IrradianceEstimate e = estimateIrradiance(tracer, {0, 0, 0}, {0, 0, 1}, 0, s);
  const double luminance = 1000.0 / 0.36;  // cd/m²
  const double area = analytic::rectangleAbove(luminance, {-0.3, -0.3, 0.3, 0.3}, 0.3, 0.0, 0.0);  // lux
  const double point = 1000.0 / (0.3 * 0.3);
  // Area source (Lambert, 0.6 m square at 0.3 m): 4835.7 lux; point source: 11111.1 lux.
  // The estimate is the area source's, within its standard error (4096 stratified samples).
  EXPECT_NEAR(e.illuminanceLux(), area, std::max(4.0 * e.standardErrorLux(), 0.005 * area));
  EXPECT_GT(std::abs(e.illuminanceLux() - point), 0.3 * point);
}

TEST(LuminaireSource, ShadowsApplyInBothRegimes) {
  // A black plate between the fitting and the sensor blocks it, far and near.
  for (double h : {0.3, 3.0}) {
    Scene sc = sceneWith("asym_c.ies", {0, 0, h}, {0, 0, -1}, 0.0);
    Material black;
    black.type = MaterialType::kPlastic;
    const uint32_t m = sc.addMaterial(black);
    sc.addPolygon({{-1, -1, h / 2}, {1, -1, h / 2}, {1, 1, h / 2}, {-1, 1, h / 2}}, m);
    const Tracer tracer(sc);
    EXPECT_EQ(lux(tracer, {0, 0, 0}, {0, 0, 1}), 0.0) << "h " << h;
  }
}

// A far panel (0.6 m square, 4 m up: beyond five times its size, where it was once traced as a
// point) whose centre a thin black screen hides from the sensor: the screen over y > 0 at z = 2
// hides the opening points with y > −p.y as seen from p (z = 0), so the visible part is the
// rectangle [−0.3, 0.3] × [−0.3, −p.y] and E = L · Lambert's projected solid angle of it —
// 42 % of the panel here, where one ray to the centre would give 0.
TEST(LuminaireSource, FarPanelPartlyHiddenGivesThePenumbraOfItsVisiblePart) {
  const double h = 4.0, zScreen = 2.0;
  Scene sc;
  LuminaireMounting m;
  m.positionM = {0, 0, h};
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(1000.0, 0.6, 0.6, 1), m));
  Material black;
  black.type = MaterialType::kPlastic;
  sc.addPolygon({{-3, 0, zScreen}, {3, 0, zScreen}, {3, 3, zScreen}, {-3, 3, zScreen}}, sc.addMaterial(black));
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 4096;
  const Vec3 p(0.1, 0.05, 0.0), up(0, 0, 1);
  const double edge = -p.y * (h / zScreen - 1.0);
  const double luminance = 1000.0 / 0.36;
  const double want =
      luminance * polygonProjectedSolidAngle({{-0.3, -0.3, h}, {0.3, -0.3, h}, {0.3, edge, h}, {-0.3, edge, h}}, p, up);
  const double whole = luminance * polygonProjectedSolidAngle({{-0.3, -0.3, h}, {0.3, -0.3, h}, {0.3, 0.3, h}, {-0.3, 0.3, h}}, p, up);
  const IrradianceEstimate e = estimateIrradiance(tracer, p, up, 0, s);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
  EXPECT_GT(e.standardErrorLux(), 0.0);  // the penumbra is sampled, and says so
  EXPECT_NEAR(want / whole, 0.42, 0.01);  // the geometry is what the comment says
}

// Unoccluded, a far opening (0.6 m × 0.5 m of an asymmetric web, 3.9 m away) gives the point law
// averaged over the opening, (1/A) ∫ I(p − y) cos ι / r² dA — computed here by the midpoint rule
// on 400 × 400 cells (its error, O(cell²), is below 1e-6 of the value) — not the centre's point
// law, which differs from it by more than the estimate's error.
TEST(LuminaireSource, FarUnoccludedOpeningGivesTheAreaAveragedPointLaw) {
  std::ostringstream ies;
  ies << "IESNA:LM-63-2002\n[TEST] asymmetric web with an opening\nTILT=NONE\n"
      << "1 -1 1 19 25 1 2 0.6 0.5 0\n1 1 30\n";
  for (int g = 0; g <= 90; g += 5) ies << g << " ";
  ies << "\n";
  for (int c = 0; c <= 360; c += 15) ies << c << " ";
  ies << "\n";
  for (int c = 0; c <= 360; c += 15) {
    for (int g = 0; g <= 90; g += 5) ies << asymIntensity(c, g) << " ";
    ies << "\n";
  }
  Scene sc;
  LuminaireMounting m;
  m.positionM = {0, 0, 3.0};
  m.spinDeg = 20.0;
  sc.luminaires.push_back(placeLuminaire(std::make_shared<const PhotometricWeb>(parseIes(ies.str(), "a.ies", ".")), m));
  const LuminaireSource& lum = sc.luminaires[0];
  ASSERT_DOUBLE_EQ(lum.widthM, 0.6);
  ASSERT_DOUBLE_EQ(lum.lengthM, 0.5);
  const Vec3 p(2.0, 1.5, 0.0), n(0, 0, 1);
  constexpr int kCells = 400;
  double want = 0.0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const Vec3 y = lum.position + ((i + 0.5) / kCells - 0.5) * lum.widthM * lum.axisX +
                     ((j + 0.5) / kCells - 0.5) * lum.lengthM * lum.axisY;
      const Vec3 e = p - y;
      const double d = glm::length(e);
      want += lum.intensityCd(e / d) * glm::dot(n, -e) / d / (d * d);
    }
  want /= kCells * kCells;
  const Vec3 e0 = p - lum.position;
  const double d0 = glm::length(e0);
  const double pointLaw = lum.intensityCd(e0 / d0) * glm::dot(n, -e0) / d0 / (d0 * d0);
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 4096;  // the point law is only 0.13 % off here: resolve it
  const IrradianceEstimate est = estimateIrradiance(tracer, p, n, 0, s);
  EXPECT_NEAR(est.illuminanceLux(), want, 4.0 * est.standardErrorLux() + 1e-6 * want);
  EXPECT_GT(std::abs(pointLaw - want), 4.0 * est.standardErrorLux());
  std::printf("[ measured ] far opening: %.5f ± %.5f lx, area average %.5f lx, point law %.5f lx\n",
              est.illuminanceLux(), est.standardErrorLux(), want, pointLaw);
}

}  // namespace
}  // namespace candela
