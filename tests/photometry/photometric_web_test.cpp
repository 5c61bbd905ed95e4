// PhotometricWeb against closed forms: fluxes of analytic distributions, symmetry expansion,
// axis conventions, type B conversion. Fixtures in tests/data/ies were written for these tests
// from the formulas named in their [TEST] lines.
#include "photometry/photometric_web.h"

#include "photometry/ies_lm63.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

const std::string kIes = std::string(CANDELA_TEST_DATA) + "/ies/";
constexpr double kI0 = 1000.0;

TEST(PhotometricWeb, LambertianFluxIsPiTimesI0) {
  // I = I0 cos(gamma) sampled every 5 deg: the linear interpolant of cos deviates by at most
  // h^2/8 = 9.5e-4 I0, so the flux is within 0.2 % of pi I0; the brief asks for 0.5 %.
  const PhotometricWeb web = readIes(kIes + "lambert_full.ies");
  EXPECT_NEAR(web.totalLumens(), kPi * kI0, 0.005 * kPi * kI0);
  const PhotometricWeb rot = readIes(kIes + "lambert_rot.ies");
  EXPECT_NEAR(rot.totalLumens(), web.totalLumens(), 1e-9 * web.totalLumens());
  EXPECT_NEAR(web.lightOutputRatio(), web.totalLumens() / 4000.0, 1e-12);
  EXPECT_DOUBLE_EQ(web.intensityCd(0.0, 0.0), kI0);
  EXPECT_DOUBLE_EQ(web.intensityCd(123.0, 120.0), 0.0);  // outside the measured 0-90
}

TEST(PhotometricWeb, ZonalLumensOfLambertianMatchClosedForm) {
  // Zone [a, b] of I0 cos(gamma): pi I0 (sin^2 b - sin^2 a).
  const PhotometricWeb web = readIes(kIes + "lambert_full.ies");
  const std::vector<double> z = web.zonalLumens(10.0);
  ASSERT_EQ(z.size(), 18u);
  double sum = 0.0;
  for (size_t k = 0; k < z.size(); ++k) {
    const double a = degToRad(10.0 * k), b = degToRad(10.0 * (k + 1));
    const double exact = k < 9 ? kPi * kI0 * (std::pow(std::sin(b), 2) - std::pow(std::sin(a), 2)) : 0.0;
    EXPECT_NEAR(z[k], exact, 0.005 * kPi * kI0) << "zone " << k;
    sum += z[k];
  }
  EXPECT_NEAR(sum, web.totalLumens(), 1e-9 * sum);
}

TEST(PhotometricWeb, LinearInGammaIsIntegratedExactly) {
  // I = I0 (1 - gamma/pi) is linear in gamma, so the bilinear interpolant is exact and so is
  // the integral: 2 pi I0 int_0^pi (1 - g/pi) sin g dg = 2 pi I0. Zones of 7 deg do not align
  // with the 5 deg grid; their closed form uses F(g) = -cos g - (sin g - g cos g)/pi. The file
  // rounds candelas to 1e-6 cd, so fluxes may differ by up to 4 pi x 5e-7 = 6.3e-6 lm.
  const PhotometricWeb web = readIes(kIes + "linear_2019.ies");
  EXPECT_NEAR(web.totalLumens(), 2.0 * kPi * kI0, 1e-5);
  const auto F = [](double g) { return -std::cos(g) - (std::sin(g) - g * std::cos(g)) / kPi; };
  const std::vector<double> z = web.zonalLumens(7.0);
  for (size_t k = 0; k < z.size(); ++k) {
    const double a = degToRad(7.0 * k), b = degToRad(std::min(180.0, 7.0 * (k + 1)));
    EXPECT_NEAR(z[k], 2.0 * kPi * kI0 * (F(b) - F(a)), 1e-5) << "zone " << k;
  }
  EXPECT_NEAR(web.intensityCd(77.0, 37.5), kI0 * (1.0 - 37.5 / 180.0), 1e-6);
}

TEST(PhotometricWeb, AsymmetricTypeCFluxAndInterpolation) {
  // I = I0 cos(g) (1 + 0.5 cos(C - 30)): the C term integrates to zero, flux = pi I0.
  const PhotometricWeb web = readIes(kIes + "asym_c.ies");
  EXPECT_NEAR(web.totalLumens(), kPi * kI0, 0.005 * kPi * kI0);
  const auto f = [](double c, double g) {
    return kI0 * std::cos(degToRad(g)) * (1.0 + 0.5 * std::cos(degToRad(c - 30.0)));
  };
  EXPECT_NEAR(web.intensityCd(45.0, 30.0), f(45.0, 30.0), 1e-5);  // a grid node
  // Bilinear: the centre of a cell is the mean of its four corners.
  const double mid = 0.25 * (f(45, 30) + f(60, 30) + f(45, 35) + f(60, 35));
  EXPECT_NEAR(web.intensityCd(52.5, 32.5), mid, 1e-5);
  // C is periodic: between the last plane (345) and 360 = 0.
  EXPECT_NEAR(web.intensityCd(-7.5, 30.0), 0.5 * (f(345, 30) + f(0, 30)), 1e-5);
  EXPECT_NEAR(web.intensityCd(352.5 + 720.0, 30.0), web.intensityCd(-7.5, 30.0), 1e-9);
  // Peak at C = 30, gamma = 0 (the grid node of largest value).
  EXPECT_NEAR(web.maxIntensityCd(), 1500.0, 1e-5);
  EXPECT_NEAR(web.maxIntensityDirection().cDeg, 30.0, 1e-9);
  EXPECT_NEAR(web.maxIntensityDirection().gammaDeg, 0.0, 1e-9);
}

TEST(PhotometricWeb, LocalDirectionAxes) {
  // Nadir is -Z, C0 is +X, C90 is +Y (counterclockwise seen from above); length is irrelevant.
  const PhotometricWeb web = readIes(kIes + "asym_c.ies");
  EXPECT_NEAR(web.intensityCd(Vec3(0, 0, -5)), web.intensityCd(0.0, 0.0), 1e-9);
  EXPECT_NEAR(web.intensityCd(Vec3(2, 0, -2)), web.intensityCd(0.0, 45.0), 1e-9);
  EXPECT_NEAR(web.intensityCd(Vec3(0, 3, -3)), web.intensityCd(90.0, 45.0), 1e-9);
  EXPECT_NEAR(web.intensityCd(Vec3(0, -1, -1)), web.intensityCd(270.0, 45.0), 1e-9);
  EXPECT_NEAR(web.intensityCd(Vec3(-1, 0, -1)), web.intensityCd(180.0, 45.0), 1e-9);
  EXPECT_NE(web.intensityCd(Vec3(0, 1, -1)), web.intensityCd(Vec3(0, -1, -1)));
  EXPECT_DOUBLE_EQ(web.intensityCd(Vec3(0, 0, 1)), 0.0);  // zenith: outside 0-90
  EXPECT_DOUBLE_EQ(web.intensityCd(Vec3(0, 0, 0)), 0.0);
  const Vec3 d = PhotometricWeb::directionOf(135.0, 60.0);
  const CGamma cg = PhotometricWeb::cGammaOf(d);
  EXPECT_NEAR(cg.cDeg, 135.0, 1e-9);
  EXPECT_NEAR(cg.gammaDeg, 60.0, 1e-9);
}

// Each stored symmetry gives the intensities of the full 0-360 file of the same distribution.
void expectSameWeb(const PhotometricWeb& a, const PhotometricWeb& b, double tolCd) {
  for (double c = -10.0; c < 370.0; c += 7.3)
    for (double g = 0.0; g <= 180.0; g += 3.3)
      ASSERT_NEAR(a.intensityCd(c, g), b.intensityCd(c, g), tolCd) << "C " << c << " gamma " << g;
  EXPECT_NEAR(a.totalLumens(), b.totalLumens(), 1e-6 * b.totalLumens());
}

TEST(PhotometricWeb, SymmetryVariantsMatchFullFiles) {
  expectSameWeb(readIes(kIes + "quad_0_90.ies"), readIes(kIes + "quad_full.ies"), 1e-5);
  expectSameWeb(readIes(kIes + "half_0_180.ies"), readIes(kIes + "half_full.ies"), 1e-5);
  expectSameWeb(readIes(kIes + "h9027_90_270.ies"), readIes(kIes + "h9027_full.ies"), 1e-5);
  expectSameWeb(readIes(kIes + "lambert_rot.ies"), readIes(kIes + "lambert_full.ies"), 1e-5);
}

TEST(PhotometricWeb, UplightOnlyAbove) {
  // |cos g| on 90-180: pi I0 upwards, nothing below the horizon.
  const PhotometricWeb web = readIes(kIes + "uplight_90_180.ies");
  EXPECT_NEAR(web.totalLumens(), kPi * kI0, 0.005 * kPi * kI0);
  EXPECT_DOUBLE_EQ(web.intensityCd(0.0, 45.0), 0.0);
  EXPECT_NEAR(web.intensityCd(Vec3(0, 0, 1)), kI0, 1e-9);
  EXPECT_DOUBLE_EQ(web.lumensBetween(0.0, 90.0), 0.0);
}

TEST(PhotometricWeb, TypeBAxesAndFlux) {
  // I = I0 cosH cosV (1 + 0.5 sinV): cosH cosV is the cosine to the beam axis (-Z), so the
  // flux is pi I0; the factor (1 + 0.5 sinV) makes the +V side (towards +X) brighter.
  const PhotometricWeb web = readIes(kIes + "typeb.ies");
  ASSERT_EQ(web.type(), PhotometricType::kB);
  const auto f = [](double hDeg, double vDeg) {
    const double h = degToRad(hDeg), v = degToRad(vDeg);
    return kI0 * std::cos(h) * std::cos(v) * (1.0 + 0.5 * std::sin(v));
  };
  const auto dirHV = [](double hDeg, double vDeg) {
    const double h = degToRad(hDeg), v = degToRad(vDeg);
    return Vec3(std::cos(h) * std::sin(v), std::sin(h), -std::cos(h) * std::cos(v));
  };
  EXPECT_NEAR(web.intensityCd(Vec3(0, 0, -1)), kI0, 1e-6);
  EXPECT_NEAR(web.intensityCd(dirHV(0, 30)), f(0, 30), 1e-4);    // towards +X
  EXPECT_NEAR(web.intensityCd(dirHV(0, -30)), f(0, -30), 1e-4);  // towards -X
  EXPECT_NEAR(web.intensityCd(dirHV(30, 0)), f(30, 0), 1e-4);    // towards +Y
  EXPECT_NEAR(web.intensityCd(dirHV(-30, 0)), f(-30, 0), 1e-4);  // mirrored lateral half
  EXPECT_NEAR(web.intensityCd(dirHV(20, 40)), f(20, 40), 1e-4);
  EXPECT_DOUBLE_EQ(web.intensityCd(Vec3(0, 0, 1)), 0.0);  // behind the floodlight
  // (C, gamma) goes through the same direction.
  EXPECT_NEAR(web.intensityCd(0.0, 30.0), f(0, 30), 1e-4);
  EXPECT_NEAR(web.intensityCd(180.0, 30.0), f(0, -30), 1e-4);
  EXPECT_NEAR(web.totalLumens(), kPi * kI0, 0.005 * kPi * kI0);
  double zonal = 0.0;
  for (double z : web.zonalLumens(10.0)) zonal += z;
  EXPECT_NEAR(zonal, web.totalLumens(), 0.002 * web.totalLumens());  // quadrature vs exact
  // Grid maximum: H = 0, V = 20 deg (the analytic peak is at V = 21.5 deg, between nodes).
  EXPECT_NEAR(web.maxIntensityDirection().cDeg, 0.0, 1e-9);
  EXPECT_NEAR(web.maxIntensityDirection().gammaDeg, 20.0, 1e-9);
}

}  // namespace
}  // namespace candela
