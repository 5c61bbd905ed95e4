#include "photometry/annual_sky.h"

#include "photometry/sky_patches.h"
#include "photometry/sky_perez.h"
#include "photometry/sun_spa.h"
#include "sky_test_support.h"
#include "photometry/make_sky.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace candela {
namespace {

const EpwFile& goldenEpw() {
  static const EpwFile epw = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  return epw;
}

Site goldenSite() {
  const EpwLocation& loc = goldenEpw().location;
  return makeSite(loc.latitudeDeg, loc.longitudeDeg, loc.elevationM, loc.timezoneHours, 0.0);
}

const AnnualSky& goldenSky(int mf) {
  static const AnnualSky mf1 = makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{1, 0.2, 4});
  static const AnnualSky mf2 = makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{2, 0.2, 4});
  return mf == 1 ? mf1 : mf2;
}

// The sky engine/daylight.cpp builds for an EPW hour: makeSky("perez") with the sun clamped to
// the horizon, the record's irradiances and the day of the year (no dew point).
std::unique_ptr<SkyModel> pointInTimeSky(const EpwRecord& rec, const AnnualHour& hour) {
  SkyConditions cond;
  cond.sunDirTrue = directionFromAzAlt(hour.sunAzimuthDeg, std::max(hour.sunAltitudeDeg, 0.0), 0.0);
  cond.dayOfYear = hour.dayOfYear;
  cond.directNormalWm2 = rec.directNormalWhm2;
  cond.diffuseHorizontalWm2 = rec.diffuseHorizontalWhm2;
  return makeSky({SkyKind::kPerez}, cond);
}

// Patch bounds in (sin altitude, azimuth) from SkyPatches alone: the row from the centre's
// altitude, the azimuth width from the solid angle (omega = width x (mu1 - mu0)).
struct PatchBounds {
  double mu0, mu1, az0, az1;
};
PatchBounds boundsOf(const SkyPatches& sp, int p) {
  const double alpha = sp.rowHeightRad();
  if (p == sp.skyPatchCount()) return {std::sin(7 * sp.multiplier() * alpha), 1.0, 0.0, kTwoPi};
  const Vec3 c = sp.centre(p);
  const int row = int(std::asin(c.z) / alpha);
  const double mu0 = std::sin(row * alpha), mu1 = std::sin((row + 1) * alpha);
  const double width = sp.solidAngle(p) / (mu1 - mu0);
  const double az = std::atan2(c.x, c.y);
  return {mu0, mu1, az - 0.5 * width, az + 0.5 * width};
}

// Midpoint rule on an n x n equal-area grid over the patch: a different rule from the Gauss
// points of annual_sky.cpp. Returns the mean luminance, the integral of L cos(theta) d(omega),
// and the min/max of the sampled luminance.
struct FinePatch {
  double mean = 0, horizontal = 0, lo = std::numeric_limits<double>::max(), hi = 0;
};
FinePatch fineIntegrate(const SkyModel& sky, const PatchBounds& b, int n) {
  FinePatch f;
  const double dmu = (b.mu1 - b.mu0) / n, daz = (b.az1 - b.az0) / n;
  for (int i = 0; i < n; ++i) {
    const double mu = b.mu0 + (i + 0.5) * dmu, c = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < n; ++j) {
      const double az = b.az0 + (j + 0.5) * daz;
      const double l = sky.luminance(Vec3(c * std::sin(az), c * std::cos(az), mu));
      f.mean += l;
      f.horizontal += l * mu * dmu * daz;
      f.lo = std::min(f.lo, l);
      f.hi = std::max(f.hi, l);
    }
  }
  f.mean /= double(n) * n;
  return f;
}

// Test hours: the clearest (largest DNI), the most overcast bright hour, the lowest sun with
// diffuse light, and every 400th hour with diffuse light.
std::vector<int> testHours() {
  const EpwFile& epw = goldenEpw();
  const AnnualSky& sky = goldenSky(1);
  std::vector<int> hours;
  int clear = -1, overcast = -1, low = -1;
  int lit = 0;
  for (int h = 0; h < int(epw.records.size()); ++h) {
    const EpwRecord& r = epw.records[h];
    if (!(sky.hours[h].diffuseHorizontalLux > 0.0)) continue;
    if (clear < 0 || r.directNormalWhm2 > epw.records[clear].directNormalWhm2) clear = h;
    if (r.directNormalWhm2 == 0.0 && (overcast < 0 || r.diffuseHorizontalWhm2 > epw.records[overcast].diffuseHorizontalWhm2))
      overcast = h;
    if (low < 0 || sky.hours[h].sunAltitudeDeg < sky.hours[low].sunAltitudeDeg) low = h;
    if (lit++ % 400 == 0) hours.push_back(h);
  }
  for (int h : {clear, overcast, low})
    if (h >= 0) hours.push_back(h);
  return hours;
}

double projectedSolidAngle(const PatchBounds& b) {
  return (b.az1 - b.az0) * 0.5 * (b.mu1 * b.mu1 - b.mu0 * b.mu0);  // integral of mu dmu daz
}

TEST(AnnualSky, ScaleQuadratureAgreesWithCalibrateAndAnIndependentIntegral) {
  // perezRelativeHorizontal (~2 300 evaluations) against SkyModel::calibrate's Gauss-Legendre
  // (stated accuracy ~1e-6, measured up to 5e-6 at a sun within 2 deg of the horizon where its
  // Cartesian grid meets the circumsolar cusp) and an equal-area midpoint rule
  // at 700 x 1400 (~2e-7 here). Every 97th hour with diffuse light, so all seasons and altitudes appear.
  const EpwFile& epw = goldenEpw();
  const AnnualSky& annual = goldenSky(1);
  int checked = 0;
  double worstModel = 0, worstIndependent = 0;
  for (size_t h = 0; h < epw.records.size(); h += 97) {
    if (!(annual.hours[h].diffuseHorizontalLux > 0.0)) continue;
    const auto sky = pointInTimeSky(epw.records[h], annual.hours[h]);
    if (!(sky->scale() > 0.0)) continue;  // degenerate shape (see DegenerateShape)
    const Vec3 sun = directionFromAzAlt(annual.hours[h].sunAzimuthDeg, std::max(annual.hours[h].sunAltitudeDeg, 0.0), 0.0);
    const double mine = perezRelativeHorizontal(*sky, sun);
    const double model = sky->horizontalIlluminanceLux() / sky->scale();
    worstModel = std::max(worstModel, std::abs(mine / model - 1.0));
    if (checked % 8 == 0) {
      const double independent =
          test::equalAreaIntegral([&](const Vec3& d) { return sky->relativeLuminance(d) * d.z; }, 700, 1400);
      worstIndependent = std::max(worstIndependent, std::abs(mine / independent - 1.0));
    }
    ++checked;
  }
  std::printf("[ info ] %d hours: worst relative difference %.2e vs calibrate, %.2e vs equal-area\n", checked,
              worstModel, worstIndependent);
  EXPECT_GT(checked, 30);
  EXPECT_LT(worstModel, 1e-5);
  EXPECT_LT(worstIndependent, 2e-6);
}

void checkPatchMeans(int mf) {
  // Against an independent 48 x 48 midpoint integration of the point-in-time PerezSky over each
  // patch (error O(h^2) with h = 1/48 of a patch, < 1e-5 here). The Gauss 4 x 4 mean is exact to
  // ~1e-5 where the sky is smooth (bound 2e-4). Two places are not smooth at the patch scale:
  // near the sun the circumsolar term exp(d gamma) (d ~ -3..-7 per radian) has a cusp, which
  // limits a product rule to a few 1e-3 (bound 1e-2 within 2 patch widths of the sun); in the
  // horizon row the gradation 1 + a exp(b / sin h) varies like exp(b / mu) for mu in [0, 0.2],
  // whose derivatives grow like 1 / mu^2 at the horizon (bound 5e-3, measured up to ~2e-3). The sums check the scale: with the fine means, sum_p integral_p L cos d(omega) must be
  // the diffuse illuminance (fine-grid error ~1e-5); with the 4 x 4 means times the patches'
  // projected solid angles it differs by the covariance of L and cos(theta) within each patch,
  // bounded by sum_p (delta mu_p / 2) omega_p (Lmax_p - Lmin_p).
  const EpwFile& epw = goldenEpw();
  const AnnualSky& annual = goldenSky(mf);
  const SkyPatches sp(mf);
  const double patchWidthRad = sp.rowHeightRad();
  double worstFar = 0, worstNear = 0, worstHorizon = 0, worstSum = 0, worstCosSum = 0;
  for (int h : testHours()) {
    const AnnualHour& hour = annual.hours[h];
    const auto sky = pointInTimeSky(epw.records[h], hour);
    ASSERT_NEAR(sky->horizontalIlluminanceLux(), hour.diffuseHorizontalLux, 1e-9 * hour.diffuseHorizontalLux);
    if (!(sky->scale() > 0.0)) continue;
    const Vec3 sun = directionFromAzAlt(hour.sunAzimuthDeg, std::max(hour.sunAltitudeDeg, 0.0), 0.0);
    double fineSum = 0, cosSum = 0, bound = 0;
    for (int p = 1; p < sp.count(); ++p) {
      const PatchBounds b = boundsOf(sp, p);
      const FinePatch f = fineIntegrate(*sky, b, 48);
      const double mine = annual.at(h, p);
      const bool near = std::acos(std::clamp(glm::dot(sp.centre(p), sun), -1.0, 1.0)) < 2.0 * patchWidthRad;
      const bool horizon = b.mu0 == 0.0;
      const double rel = std::abs(mine - f.mean) / std::max(f.mean, 1e-3 * hour.diffuseHorizontalLux / kPi);
      double& worst = near ? worstNear : horizon ? worstHorizon : worstFar;
      worst = std::max(worst, rel);
      EXPECT_LT(rel, near ? 1e-2 : horizon ? 5e-3 : 2e-4)
          << "hour " << h << " patch " << p << " mine " << mine << " fine " << f.mean;
      fineSum += f.horizontal;
      cosSum += mine * projectedSolidAngle(b);
      bound += 0.5 * (b.mu1 - b.mu0) * sp.solidAngle(p) * (f.hi - f.lo);
    }
    const double e = hour.diffuseHorizontalLux;
    worstSum = std::max(worstSum, std::abs(fineSum / e - 1.0));
    worstCosSum = std::max(worstCosSum, std::abs(cosSum / e - 1.0));
    EXPECT_NEAR(fineSum, e, 2e-5 * e) << "hour " << h;
    EXPECT_NEAR(cosSum, e, bound + 2e-5 * e) << "hour " << h;
  }
  std::printf("[ info ] MF:%d patch means vs fine: worst %.2e (elsewhere), %.2e (horizon row), %.2e (near the "
              "sun); sum of fine integrals %.2e; sum of means x projected solid angle %.2e (relative)\n",
              mf, worstFar, worstHorizon, worstNear, worstSum, worstCosSum);
}

TEST(AnnualSky, PatchMeansMatchFineIntegrationMf1) { checkPatchMeans(1); }
TEST(AnnualSky, PatchMeansMatchFineIntegrationMf2) { checkPatchMeans(2); }

TEST(AnnualSky, PatchBoundsOfTheTestTileTheSky) {
  // The fine integrations above use bounds derived from SkyPatches::centre/solidAngle only; they
  // validate annual_sky.cpp's own copy of the Reinhart layout, so check them against indexOf.
  for (int n : {1, 2, 3}) {
    const SkyPatches sp(n);
    double total = 0;
    for (int p = 1; p < sp.count(); ++p) {
      const PatchBounds b = boundsOf(sp, p);
      total += (b.az1 - b.az0) * (b.mu1 - b.mu0);
      for (double fm : {0.02, 0.5, 0.98}) {
        const double mu = b.mu0 + fm * (b.mu1 - b.mu0), c = std::sqrt(1 - mu * mu);
        for (double fa : {0.02, 0.5, 0.98}) {
          const double az = b.az0 + fa * (b.az1 - b.az0);
          EXPECT_EQ(sp.indexOf(Vec3(c * std::sin(az), c * std::cos(az), mu)), p) << n << " " << p;
        }
      }
    }
    EXPECT_NEAR(total, kTwoPi, 1e-9);
  }
  EXPECT_EQ(goldenSky(1).patchCount, SkyPatches(1).count());
  EXPECT_EQ(goldenSky(2).patchCount, SkyPatches(2).count());
}

TEST(AnnualSky, SunPositionsAtMidHourAndTheirPatches) {
  const EpwFile& epw = goldenEpw();
  const AnnualSky& annual = goldenSky(1);
  const SkyPatches sp(1);
  // Timezone handling: the same records read at UTC (timezone 0) with the hour shifted by the
  // file's -7 h must give the same sun, so hour h at UTC-7 equals hour h + 7 at UTC.
  Site utc = goldenSite();
  utc.timezoneHours = 0.0;
  EpwFile shifted = epw;
  shifted.records.clear();
  for (const EpwRecord& r : epw.records)
    if (r.hour + 7 <= 24) {
      EpwRecord s = r;
      s.hour += 7;
      shifted.records.push_back(s);
    }
  const AnnualSky atUtc = makeAnnualSky(shifted, utc, AnnualSkyOptions{});
  size_t k = 0;
  for (size_t h = 0; h < epw.records.size(); ++h) {
    const EpwRecord& r = epw.records[h];
    const AnnualHour& hour = annual.hours[h];
    if (h % 50 == 0) {  // the full SPA (with rise/set) at hour - 0.5
      SpaInput in;
      in.year = r.year, in.month = r.month, in.day = r.day, in.hourOfDay = r.hour - 0.5;
      in.timezoneHours = -7.0, in.latitudeDeg = 39.74, in.longitudeDeg = -105.18, in.elevationM = 1829.0;
      in.deltaTSec = estimateDeltaTSec(r.year + (hour.dayOfYear - 0.5) / 365.25);
      const SpaResult spa = computeSunPosition(in);
      EXPECT_NEAR(hour.sunAltitudeDeg, spa.altitudeDeg, 1e-9);
      EXPECT_NEAR(hour.sunAzimuthDeg, spa.azimuthDeg, 1e-9);
    }
    if (r.hour + 7 <= 24) {
      const AnnualHour& u = atUtc.hours[k++];
      EXPECT_NEAR(glm::dot(u.sunDirTrue, hour.sunDirTrue), 1.0, 1e-12) << h;
    }
    EXPECT_NEAR(glm::length(hour.sunDirTrue), 1.0, 1e-12);
    EXPECT_NEAR(std::asin(hour.sunDirTrue.z), degToRad(hour.sunAltitudeDeg), 1e-9);
    EXPECT_EQ(hour.sunUp, hour.sunAltitudeDeg > 0.0);
    // Golden's meridian is 0.18 deg west of UTC-7's, and |equation of time| < 17 min: solar noon
    // lies between 11:43 and 12:18, so the 11:30 sun (record 12) is east of south and the 12:30
    // sun (record 13) west of it; a reader taking hours as hour-beginning or at the full hour
    // would break this on some days.
    if (r.hour == 12) EXPECT_LT(hour.sunAzimuthDeg, 180.0) << h;
    if (r.hour == 13) EXPECT_GT(hour.sunAzimuthDeg, 180.0) << h;
    if (!hour.sunUp) {
      EXPECT_EQ(hour.sunPatch, -1);
      EXPECT_EQ(hour.directNormalLux, 0.0);
      continue;
    }
    // The patch contains the sun: its altitude band and azimuth width around the centre.
    ASSERT_GE(hour.sunPatch, 1);
    const PatchBounds b = boundsOf(sp, hour.sunPatch);
    EXPECT_GE(hour.sunDirTrue.z, b.mu0 - 1e-12);
    EXPECT_LE(hour.sunDirTrue.z, b.mu1 + 1e-12);
    if (hour.sunPatch < sp.skyPatchCount()) {
      const Vec3 c = sp.centre(hour.sunPatch);
      double dAz = std::remainder(std::atan2(hour.sunDirTrue.x, hour.sunDirTrue.y) - std::atan2(c.x, c.y), kTwoPi);
      EXPECT_LE(std::abs(dAz), 0.5 * (b.az1 - b.az0) + 1e-12);
    }
  }
  EXPECT_EQ(k, atUtc.hours.size());
}

TEST(AnnualSky, GroundGlowAndGlobalIlluminance) {
  const AnnualSky& annual = goldenSky(2);
  const AnnualSky rho5 = makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{1, 0.5, 2});
  const double discFactor = 0.5 * (1.0 + std::cos(degToRad(0.5 * 0.533)));
  for (size_t h = 0; h < annual.hours.size(); ++h) {
    const AnnualHour& hour = annual.hours[h];
    double sky = 0.0;  // the sky's horizontal illuminance is the diffuse unless the shape is degenerate
    for (int p = 1; p < annual.patchCount; ++p) sky = std::max(sky, double(annual.at(h, p)));
    const double skyLux = sky > 0.0 ? hour.diffuseHorizontalLux : 0.0;
    const double global = skyLux + hour.directNormalLux * std::sin(degToRad(hour.sunAltitudeDeg)) * discFactor;
    EXPECT_NEAR(hour.globalHorizontalLux, global, 1e-9 * (1.0 + global)) << h;
    EXPECT_NEAR(hour.globalHorizontalLux,
                skyLux + hour.directNormalLux * std::max(0.0, std::sin(degToRad(hour.sunAltitudeDeg))),
                2e-5 * (1.0 + global));  // the disc factor is 1 - 1.1e-5
    EXPECT_NEAR(annual.at(h, 0), 0.2 * hour.globalHorizontalLux / kPi, 1e-6 * (1.0 + annual.at(h, 0)));
    EXPECT_NEAR(rho5.at(h, 0), 0.5 * rho5.hours[h].globalHorizontalLux / kPi, 1e-6 * (1.0 + rho5.at(h, 0)));
  }
}

TEST(AnnualSky, HourCountAndSunUpHoursMatchSpaSunriseSunset) {
  const EpwFile& epw = goldenEpw();
  const AnnualSky& annual = goldenSky(1);
  ASSERT_EQ(annual.hours.size(), 8760u);
  ASSERT_EQ(annual.luminance.size(), size_t(8760) * 146);
  EXPECT_EQ(annual.missingValues, 0);
  // SPA's sunrise/sunset (upper limb at the horizon with 0.5667 deg refraction, i.e. the centre's
  // geometric altitude -0.833 deg) bracket every mid-hour with the sun's apparent centre above
  // the horizon; the converse fails only for mid-hours within the few minutes the sun needs to
  // climb those extra ~0.27 deg, about 2 min of every 60 at 39.7 N, so ~730 x 2/60 = 24 hours.
  int up = 0, between = 0, dayStart = 0;
  SpaResult day;
  for (size_t h = 0; h < epw.records.size(); ++h) {
    const EpwRecord& r = epw.records[h];
    if (h == 0 || r.day != epw.records[h - 1].day) {
      SpaInput in;
      in.year = r.year, in.month = r.month, in.day = r.day, in.hourOfDay = 12.0;
      in.timezoneHours = -7.0, in.latitudeDeg = 39.74, in.longitudeDeg = -105.18, in.elevationM = 1829.0;
      day = computeSunPosition(in);
      dayStart = int(h);
    }
    const double mid = r.hour - 0.5;
    const bool inDay = mid > day.sunriseHour && mid < day.sunsetHour;
    up += annual.hours[h].sunUp;
    between += inDay;
    if (annual.hours[h].sunUp) EXPECT_TRUE(inDay) << "record " << h << " of the day starting " << dayStart;
  }
  std::printf("[ info ] sun-up mid-hours %d, between SPA sunrise and sunset %d\n", up, between);
  EXPECT_GE(between - up, 0);
  EXPECT_LE(between - up, 50);
  // Half the year plus refraction's lengthening of the day (a few minutes per day).
  EXPECT_GT(up, 4380 - 30);
  EXPECT_LT(up, 4380 + 100);
}

TEST(AnnualSky, TwilightMissingAndZeroHours) {
  const EpwFile& golden = goldenEpw();
  const AnnualSky& annual = goldenSky(1);
  // Pick a summer day: the hour after sunset (sun down at mid-hour) and a bright noon hour.
  int twilight = -1, noon = -1;
  for (int h = 24 * 180; h < 24 * 181; ++h) {
    if (twilight < 0 && h > 24 * 180 + 12 && !annual.hours[h].sunUp) twilight = h;
    if (golden.records[h].hour == 13) noon = h;
  }
  ASSERT_GE(twilight, 0);
  EpwFile epw;
  epw.location = golden.location;
  EpwRecord tw = golden.records[twilight];
  tw.diffuseHorizontalWhm2 = 20.0;  // twilight with recorded diffuse light (and a spurious beam)
  tw.directNormalWhm2 = 50.0;
  EpwRecord nanDni = golden.records[noon], nanDhi = golden.records[noon], zeroDni = golden.records[noon];
  nanDni.directNormalWhm2 = std::numeric_limits<double>::quiet_NaN();
  zeroDni.directNormalWhm2 = 0.0;
  nanDhi.diffuseHorizontalWhm2 = std::numeric_limits<double>::quiet_NaN();
  EpwRecord zero = golden.records[noon];
  zero.directNormalWhm2 = zero.diffuseHorizontalWhm2 = 0.0;
  epw.records = {tw, nanDni, zeroDni, nanDhi, zero};
  const AnnualSky s = makeAnnualSky(epw, goldenSite(), AnnualSkyOptions{});
  EXPECT_EQ(s.missingValues, 2);
  EXPECT_EQ(s.missingHours, 2);

  // Twilight: Perez with the sun on the horizon at its azimuth, no direct light; the sky holds
  // the diffuse illuminance and the ground glows with it alone.
  const AnnualHour& t = s.hours[0];
  EXPECT_FALSE(t.sunUp);
  EXPECT_EQ(t.sunPatch, -1);
  EXPECT_EQ(t.directNormalLux, 0.0);
  const auto sky = pointInTimeSky(tw, t);
  EXPECT_GT(t.diffuseHorizontalLux, 0.0);
  EXPECT_NEAR(t.diffuseHorizontalLux, sky->horizontalIlluminanceLux(), 1e-9 * t.diffuseHorizontalLux);
  EXPECT_NEAR(t.globalHorizontalLux, t.diffuseHorizontalLux, 1e-9 * t.diffuseHorizontalLux);
  EXPECT_NEAR(s.at(0, 0), 0.2 * t.diffuseHorizontalLux / kPi, 1e-4);
  const SkyPatches sp(1);
  double fineSum = 0;
  for (int p = 1; p < sp.count(); ++p) {
    const FinePatch f = fineIntegrate(*sky, boundsOf(sp, p), 32);
    fineSum += f.horizontal;
    EXPECT_NEAR(s.at(0, p), f.mean, 5e-3 * f.mean + 1e-6) << p;
  }
  EXPECT_NEAR(fineSum, t.diffuseHorizontalLux, 1e-4 * t.diffuseHorizontalLux);

  // A missing DNI is a zero DNI: same hour, same values.
  EXPECT_EQ(s.hours[1].directNormalLux, 0.0);
  for (int p = 0; p < s.patchCount; ++p) EXPECT_EQ(s.at(1, p), s.at(2, p));
  // A missing DHI: no sky, the sun's beam alone (Perez's direct efficacy for epsilon = 1).
  EXPECT_EQ(s.hours[3].diffuseHorizontalLux, 0.0);
  EXPECT_GT(s.hours[3].directNormalLux, 0.0);
  for (int p = 1; p < s.patchCount; ++p) EXPECT_EQ(s.at(3, p), 0.0f);
  EXPECT_NEAR(s.at(3, 0), 0.2 * s.hours[3].globalHorizontalLux / kPi, 1e-3);
  // All zeros.
  EXPECT_EQ(s.hours[4].globalHorizontalLux, 0.0);
  for (int p = 0; p < s.patchCount; ++p) EXPECT_EQ(s.at(4, p), 0.0f);
  EXPECT_TRUE(s.hours[4].sunUp);
}

TEST(AnnualSky, RejectsBadOptions) {
  EXPECT_THROW(makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{0, 0.2, 4}), InputError);
  EXPECT_THROW(makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{1, 1.5, 4}), InputError);
  EXPECT_THROW(makeAnnualSky(goldenEpw(), goldenSite(), AnnualSkyOptions{1, 0.2, 0}), InputError);
}

}  // namespace
}  // namespace candela
