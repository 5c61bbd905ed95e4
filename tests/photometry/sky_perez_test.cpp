#include "photometry/sky_perez.h"

#include "base/rng.h"
#include "photometry/site.h"
#include "sky_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

PerezInput input(double dni, double dhi, double zenithDeg, int doy = 172) {
  PerezInput in;
  in.directNormalWm2 = dni;
  in.diffuseHorizontalWm2 = dhi;
  in.sunDirTrue = directionFromAzAlt(160.0, 90.0 - zenithDeg, 0.0);
  in.dayOfYear = doy;
  return in;
}

TEST(SkyPerez, HandWorkedClearCase) {
  // DNI 800, DHI 100 W/m2, Z = 30 deg, 21 June (day 172), W = 2 cm. By hand:
  // eps = (9 + 1.041 Z^3) / (1 + 1.041 Z^3) = 7.960 (bin 8); m = 1.15399 (Kasten-Young);
  // E0 = 1367 x 0.967438 = 1322.49 W/m2; Delta = 100 m / E0 = 0.08726;
  // diffuse efficacy = 152.23 + 0.35 x 2 - 45.27 cos Z - 7.98 ln Delta = 133.19 lm/W;
  // direct efficacy = 101.18 + 1.58 x 2 - 1.10 exp(5.73 Z - 5) - 8.29 Delta = 103.47 lm/W.
  const PerezSky sky(input(800.0, 100.0, 30.0));
  EXPECT_EQ(sky.clearnessBin(), 8);
  EXPECT_NEAR(sky.clearness(), 7.960, 1e-3);
  EXPECT_NEAR(relativeAirMass(30.0), 1.15399, 1e-5);
  EXPECT_NEAR(extraterrestrialNormalWm2(172), 1322.49, 0.01);
  EXPECT_NEAR(sky.brightness(), 0.08726, 1e-5);
  EXPECT_NEAR(sky.diffuseEfficacyLmPerW(), 133.19, 0.01);
  EXPECT_NEAR(sky.directEfficacyLmPerW(), 103.47, 0.01);
  EXPECT_NEAR(sky.diffuseHorizontalIlluminanceLux(), 100.0 * sky.diffuseEfficacyLmPerW(), 1e-9);
  EXPECT_NEAR(sky.directNormalIlluminanceLux(), 800.0 * sky.directEfficacyLmPerW(), 1e-9);
}

TEST(SkyPerez, SkyIntegratesToDiffuseTimesEfficacy) {
  struct Case {
    double dni, dhi, zenithDeg;
    int bin;
  };
  // From overcast (bin 1) through intermediate to clear, high and low sun.
  for (const Case& c : {Case{0.0, 150.0, 50.0, 1}, Case{60.0, 250.0, 40.0, 2}, Case{300.0, 200.0, 60.0, 4},
                        Case{500.0, 150.0, 70.0, 5}, Case{800.0, 100.0, 30.0, 8}, Case{600.0, 40.0, 80.0, 7}}) {
    const PerezSky sky(input(c.dni, c.dhi, c.zenithDeg));
    EXPECT_EQ(sky.clearnessBin(), c.bin) << c.dni << " " << c.dhi;
    const double expected = c.dhi * sky.diffuseEfficacyLmPerW();
    EXPECT_NEAR(sky.horizontalIlluminanceLux(), expected, 1e-9 * expected);
    EXPECT_NEAR(test::independentIlluminance(sky, Vec3(0, 0, 1)), expected, 1e-4 * expected)
        << "bin " << sky.clearnessBin() << " a..e " << sky.coefficient('a') << " " << sky.coefficient('b') << " "
        << sky.coefficient('c') << " " << sky.coefficient('d') << " " << sky.coefficient('e');
    // A clear sky is brighter near the sun than opposite it.
    if (c.bin >= 4) {
      const Vec3 s = directionFromAzAlt(160.0, 90.0 - c.zenithDeg + 5.0, 0.0);
      const Vec3 o = directionFromAzAlt(340.0, 90.0 - c.zenithDeg + 5.0, 0.0);
      EXPECT_GT(sky.luminance(s), sky.luminance(o));
    }
  }
}

TEST(SkyPerez, DarkAndTwilightSkies) {
  const PerezSky dark(input(0.0, 0.0, 95.0));
  EXPECT_EQ(dark.horizontalIlluminanceLux(), 0.0);
  EXPECT_EQ(dark.luminance(Vec3(0, 0, 1)), 0.0);
  double p = 0.0;
  dark.sample(0.3, 0.6, &p);  // still a valid distribution
  EXPECT_GT(p, 0.0);
  // Diffuse light with the sun just below the horizon: evaluated with the sun on the horizon,
  // no direct component.
  const PerezSky twilight(input(50.0, 10.0, 92.0));
  EXPECT_EQ(twilight.directNormalIlluminanceLux(), 0.0);
  EXPECT_NEAR(twilight.horizontalIlluminanceLux(), 10.0 * twilight.diffuseEfficacyLmPerW(), 1e-9);
}

TEST(SkyPerez, RejectsNegativeIrradiance) {
  EXPECT_THROW(PerezSky(input(-1.0, 100.0, 30.0)), InputError);
  EXPECT_THROW(PerezSky(input(100.0, -1.0, 30.0)), InputError);
}

TEST(SkyPerez, ImportanceSampledHorizontalIlluminance) {
  const PerezSky sky(input(800.0, 100.0, 30.0));
  Rng rng(3, 1);
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    double p = 0.0;
    const Vec3 d = sky.sample(rng.uniform(), rng.uniform(), &p);
    const double v = sky.luminance(d) * d.z / p;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, sky.horizontalIlluminanceLux(), 4.0 * se);
}

}  // namespace
}  // namespace candela
