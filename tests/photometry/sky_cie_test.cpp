#include "photometry/sky_cie.h"

#include "base/rng.h"
#include "photometry/site.h"
#include "sky_test_support.h"
#include "photometry/make_sky.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

const Vec3 kSun = directionFromAzAlt(200.0, 35.0, 0.0);  // a mid-latitude afternoon sun

TEST(SkyUniform, ClosedForms) {
  const UniformSky sky(10000.0);
  // E_h = pi L; a vertical plane sees half the hemisphere with cosine weighting: E_v = pi L / 2.
  EXPECT_NEAR(sky.luminance(Vec3(0, 0, 1)), 10000.0 / kPi, 1e-6);
  EXPECT_NEAR(sky.illuminanceOnPlane(Vec3(1, 0, 0)), 5000.0, 1e-6 * 5000.0);
  EXPECT_NEAR(sky.illuminanceOnPlane(Vec3(0.3, -0.2, 0.5)),
              // Plane tilted by t from horizontal, sky only: E = pi L (1 + cos t) / 2.
              10000.0 / kPi * kPi * (1.0 + 0.5 / std::sqrt(0.38)) / 2.0, 1e-5 * 10000.0);
  EXPECT_EQ(sky.luminance(Vec3(0, 0, -1)), 0.0);
}

TEST(SkyOvercast, ZenithLuminanceAndVerticalRatio) {
  const CieOvercastSky sky(10000.0);
  // Moon-Spencer: E_h = 2 pi Lz / 3 * int_0^{pi/2} (1 + 2 sin h) sin h cos h dh
  //                   = 2 pi Lz / 3 * (1/2 + 2/3) = (7 pi / 9) Lz.
  EXPECT_NEAR(sky.zenithLuminance(), 10000.0 / (7.0 * kPi / 9.0), 1e-6 * 10000.0 / (7.0 * kPi / 9.0));
  EXPECT_NEAR(sky.luminance(directionFromAzAlt(10.0, 0.0, 0.0) + Vec3(0, 0, 1e-12)), sky.zenithLuminance() / 3.0, 1e-6);
  // E_v = 2 Lz / 3 * int_0^{pi/2} (1 + 2 sin h) cos^2 h dh (the cos(az) factor over the facing
  // half integrates to 2) = (2 Lz / 3)(pi/4 + 2/3), so E_v / E_h = (3 pi / 2 + 4) / (7 pi)
  // = 0.39618 (sky only, no ground).
  const double ratio = (1.5 * kPi + 4.0) / (7.0 * kPi);
  EXPECT_NEAR(ratio, 0.396, 5e-4);
  for (const Vec3& n : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(std::sqrt(0.5), std::sqrt(0.5), 0)}) {
    EXPECT_NEAR(sky.illuminanceOnPlane(n) / sky.horizontalIlluminanceLux(), ratio, 1e-6);
    EXPECT_NEAR(test::independentIlluminance(sky, n) / 10000.0, ratio, 1e-5);
  }
}

TEST(SkyCieGeneral, ParametersAndZenithValue) {
  EXPECT_DOUBLE_EQ(cieSkyParams(12).c, 10.0);
  EXPECT_DOUBLE_EQ(cieSkyParams(15).d, -2.8);
  for (int t = 1; t <= 15; ++t) {
    const CieGeneralSky sky(t, kSun, 20000.0);
    EXPECT_NEAR(sky.relativeLuminance(Vec3(0, 0, 1)), 1.0, 1e-12) << t;
    EXPECT_NEAR(sky.luminance(Vec3(0, 0, 1)), sky.zenithLuminance(), 1e-9 * sky.zenithLuminance()) << t;
  }
  // Type 5 (a = 0, c = 0, e = 0) is the uniform sky.
  const CieGeneralSky five(5, kSun, 20000.0);
  EXPECT_NEAR(five.luminance(directionFromAzAlt(77.0, 12.0, 0.0)), 20000.0 / kPi, 1e-6);
}

TEST(SkyCieGeneral, ClearSkyIsBrighterTowardsTheSun) {
  const CieGeneralSky sky(12, kSun, 20000.0);
  const Vec3 nearSun = directionFromAzAlt(200.0, 40.0, 0.0);
  const Vec3 opposite = directionFromAzAlt(20.0, 40.0, 0.0);
  EXPECT_GT(sky.luminance(nearSun), 3.0 * sky.luminance(opposite));
  // Closed-form check of one value: L/Lz = f(chi) phi(Z) / (f(Zs) phi(0)), with Z = 50 deg,
  // chi = 5 deg, Zs = 55 deg for type 12 (a = -1, b = -0.32, c = 10, d = -3, e = 0.45).
  const auto f = [](double chi) { return 1 + 10 * (std::exp(-3 * chi) - std::exp(-1.5 * kPi)) + 0.45 * std::pow(std::cos(chi), 2); };
  const auto phi = [](double z) { return 1 - std::exp(-0.32 / std::cos(z)); };
  const double expected = f(degToRad(5.0)) * phi(degToRad(50.0)) / (f(degToRad(55.0)) * phi(0.0));
  EXPECT_NEAR(sky.relativeLuminance(nearSun), expected, 1e-12);
}

TEST(SkyModels, HorizontalIlluminanceMatchesIndependentQuadrature) {
  // Every model scaled to 12000 lx must give 12000 lx on an unobstructed horizontal plane when
  // integrated by a different rule (equal-area midpoint, error ~1e-6).
  std::vector<std::unique_ptr<SkyModel>> skies;
  SkyConditions c;
  c.sunDirTrue = kSun;
  c.diffuseHorizontalLux = 12000.0;
  for (SkyKind k : {SkyKind::kUniform, SkyKind::kCieOvercast, SkyKind::kCieClear}) skies.push_back(makeSky({k}, c));
  for (int t = 1; t <= 15; ++t) skies.push_back(makeSky({SkyKind::kCieGeneral, t}, c));
  c.sunDirTrue = directionFromAzAlt(100.0, 8.0, 0.0);  // low sun: sharp, near-horizon corona
  skies.push_back(makeSky({SkyKind::kCieGeneral, 15}, c));
  for (const auto& sky : skies) {
    EXPECT_NEAR(sky->horizontalIlluminanceLux(), 12000.0, 1e-9 * 12000.0) << sky->name();
    EXPECT_NEAR(test::independentIlluminance(*sky, Vec3(0, 0, 1)), 12000.0, 1e-4 * 12000.0) << sky->name();
    // Gauss-Legendre with 1-degree panels agrees with the 2-degree calibration.
    EXPECT_NEAR(sky->illuminanceOnPlane(Vec3(0, 0, 1)), 12000.0, 1e-6 * 12000.0) << sky->name();
  }
}

TEST(SkyTypes, NamesParseBackAndBadNamesAreRefused) {
  for (const char* name : {"none", "uniform", "cie-overcast", "cie-clear", "perez", "annual", "cie:1", "cie:15"})
    EXPECT_EQ(skyTypeName(parseSkyType(name).value()), name);
  for (const char* bad : {"cie:0", "cie:16", "cie:", "cie:3x", "clear", ""}) {
    std::string why;
    EXPECT_FALSE(parseSkyType(bad, &why)) << bad;
    EXPECT_NE(why.find(std::string("'") + bad + "'"), std::string::npos) << why;
  }
}

TEST(SkyModels, FactoryRejectsTypesWithoutAModel) {
  const FileLoc loc{"case.toml", 9, 0};
  for (const SkyType bad : {SkyType{SkyKind::kNone}, SkyType{SkyKind::kAnnual}, SkyType{SkyKind::kCieGeneral, 16}}) {
    try {
      makeSky(bad, SkyConditions{}, loc);
      ADD_FAILURE() << skyTypeName(bad);
    } catch (const InputError& e) {
      EXPECT_EQ(e.loc().line, 9);
    }
  }
  EXPECT_EQ(makeSky({SkyKind::kCieClear}, SkyConditions{})->name(), "cie:12");
}

TEST(SkySampling, PdfIntegratesToOneAndMatchesSample) {
  const CieGeneralSky sky(12, kSun, 20000.0);
  // The pdf is piecewise constant on 1.4-degree cells; the midpoint grid (1000 x 2000) straddles
  // cell edges in ~0.3 % of its points, each error bounded by the pdf jump: 1e-3 is generous.
  EXPECT_NEAR(test::equalAreaIntegral([&](const Vec3& d) { return sky.pdf(d); }), 1.0, 1e-3);
  Rng rng(7, 0);
  int mismatches = 0;
  for (int i = 0; i < 10000; ++i) {
    double p = 0.0;
    const Vec3 d = sky.sample(rng.uniform(), rng.uniform(), &p);
    EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
    EXPECT_GT(d.z, 0.0);
    if (std::abs(sky.pdf(d) - p) > 1e-9 * p) ++mismatches;  // only on cell edges, by rounding
  }
  EXPECT_LE(mismatches, 5);
}

TEST(SkySampling, ImportanceSampledHorizontalIlluminance) {
  // E_h estimated as the mean of L cos(theta) / pdf over n samples; the standard error is
  // computed from the samples and the estimate must lie within 4 of them.
  for (int type : {1, 12, 15}) {
    const CieGeneralSky sky(type, kSun, 20000.0);
    Rng rng(11, type);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
      double p = 0.0;
      const Vec3 d = sky.sample(rng.uniform(), rng.uniform(), &p);
      const double v = sky.luminance(d) * d.z / p;
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 20000.0, 4.0 * se) << type << " se " << se;
    EXPECT_LT(se, 0.01 * 20000.0) << type;  // the sampling actually follows the luminance
  }
}

}  // namespace
}  // namespace candela
