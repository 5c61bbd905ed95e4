#include "study/sunlight_exposure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/error.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"

namespace candela {
namespace {

// Golden, Colorado (the office demos' weather file's site).
Site golden(double northDeg = 0.0) { return makeSite(39.74, -105.18, 1829.0, -7.0, northDeg); }

// An independent sun path: Spencer's (1971) Fourier series for the declination and the equation
// of time ("Fourier series representation of the position of the sun", Search 2(5)), and the
// hour angle closed form sin(alt) = sin φ sin δ + cos φ cos δ cos ω. No refraction: SPA's
// refraction at ~11° altitude (≈ 0.08°) shifts each end by about half a minute, Spencer's
// declination is within ~0.03° and his equation of time within ~0.5 min, far inside the 0.1 h
// the tests allow (the tolerance).
struct ClosedFormDay {
  double hoursAboveMin = 0.0;  // the sun above the minimum altitude, hours
  double solarNoonHour = 0.0;  // local standard time
};

ClosedFormDay closedForm(const Site& site, int dayOfYear, double minAltitudeDeg) {
  const double g = 2.0 * kPi * (dayOfYear - 1) / 365.0;
  const double decl = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2 * g) +
                      0.000907 * std::sin(2 * g) - 0.002697 * std::cos(3 * g) + 0.00148 * std::sin(3 * g);
  const double eotMin = 229.18 * (0.000075 + 0.001868 * std::cos(g) - 0.032077 * std::sin(g) -
                                  0.014615 * std::cos(2 * g) - 0.040849 * std::sin(2 * g));
  const double lat = degToRad(site.latitudeDeg);
  const double cosW = (std::sin(degToRad(minAltitudeDeg)) - std::sin(lat) * std::sin(decl)) /
                      (std::cos(lat) * std::cos(decl));
  ClosedFormDay d;
  d.hoursAboveMin = 2.0 * radToDeg(std::acos(cosW)) / 15.0;
  d.solarNoonHour = 12.0 - eotMin / 60.0 - (site.longitudeDeg - 15.0 * site.timezoneHours) / 15.0;
  return d;
}

int dayOfYear(const CivilDate& d) {
  LocalTime t;
  t.year = d.year;
  t.month = d.month;
  t.day = d.day;
  return t.dayOfYear();
}

// A floor far below the point (nothing above it) and, optionally, a vertical wall in the plane
// x = 1 of the given material, blocking (when opaque) every direction with a positive x: the
// model's east with north 0, so the sun until it crosses the meridian.
Scene sceneWithEastWall(const std::string& wallMaterial) {
  Scene sc;
  std::string text =
      "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
      "void glass clear 0 0 3 0.9 0.9 0.9\n"
      "void trans frosted 0 0 7 0.8 0.8 0.8 0 0 0.6 0\n"
      "grey polygon floor 0 0 12 -1e4 -1e4 -1  1e4 -1e4 -1  1e4 1e4 -1  -1e4 1e4 -1\n";
  if (!wallMaterial.empty())
    text += wallMaterial + " polygon wall 0 0 12 1 -1e5 -1e5  1 1e5 -1e5  1 1e5 1e5  1 -1e5 1e5\n";
  readRadianceText(text, "sun_scene.rad", sc);
  return sc;
}

constexpr double kToleranceHours = 0.1;
const CivilDate kDate{2026, 3, 1};
constexpr double kMinAltitudeDeg = 11.0;

TEST(SunlightExposureTest, UnobstructedPointGetsTheHoursTheSunIsAboveTheMinimumAltitude) {
  const Scene sc = sceneWithEastWall("");
  const Tracer tracer(sc);
  const Site site = golden();
  for (const CivilDate date : {CivilDate{2026, 2, 1}, kDate, CivilDate{2026, 3, 21}}) {
    const ClosedFormDay ref = closedForm(site, dayOfYear(date), kMinAltitudeDeg);
    const SunlightExposure r = sunlightExposure(tracer, site, date, {Vec3(0.0)}, kMinAltitudeDeg);
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_NEAR(r.points[0].hours, ref.hoursAboveMin, kToleranceHours) << date.month << "-" << date.day;
    EXPECT_NEAR(r.sunAboveMinHours, ref.hoursAboveMin, kToleranceHours);
    ASSERT_EQ(r.points[0].intervals.size(), 1u);
    const SunlitInterval& iv = r.points[0].intervals[0];
    EXPECT_NEAR(0.5 * (iv.startHour + iv.endHour), ref.solarNoonHour, kToleranceHours);
    EXPECT_EQ(r.points[0].level, sunlightExposureLevel(r.points[0].hours));
  }
}

TEST(SunlightExposureTest, CoarseStepWithBisectionAgreesWithFineStep) {
  const Scene sc = sceneWithEastWall("grey");
  const Tracer tracer(sc);
  SunlightOptions coarse;
  coarse.stepMinutes = 30.0;
  SunlightOptions fine;
  fine.stepMinutes = 0.5;
  fine.refineEdges = false;  // halfway between samples: within 15 s of each edge
  const double a = sunlightExposure(tracer, golden(), kDate, {Vec3(0.0)}, kMinAltitudeDeg, coarse).points[0].hours;
  const double b = sunlightExposure(tracer, golden(), kDate, {Vec3(0.0)}, kMinAltitudeDeg, fine).points[0].hours;
  EXPECT_NEAR(a, b, 2.0 * 15.0 / 3600.0 + 2.0 / 3600.0);
}

TEST(SunlightExposureTest, WallBlockingTheMorningSunLeavesTheAfternoon) {
  const Scene sc = sceneWithEastWall("grey");
  const Tracer tracer(sc);
  const Site site = golden();
  const ClosedFormDay ref = closedForm(site, dayOfYear(kDate), kMinAltitudeDeg);
  const SunlightExposure r = sunlightExposure(tracer, site, kDate, {Vec3(0.0)}, kMinAltitudeDeg);
  const SunlightPoint& p = r.points[0];
  // The sun reaches the point once it is west of the meridian (azimuth 180° at solar noon)
  // until it sinks below the minimum altitude: half the day's hours.
  EXPECT_NEAR(p.hours, 0.5 * ref.hoursAboveMin, kToleranceHours);
  ASSERT_EQ(p.intervals.size(), 1u);
  EXPECT_NEAR(p.intervals[0].startHour, ref.solarNoonHour, kToleranceHours);
  EXPECT_NEAR(p.intervals[0].endHour, ref.solarNoonHour + 0.5 * ref.hoursAboveMin, kToleranceHours);
}

TEST(SunlightExposureTest, SiteNorthTurnsTheSunNotTheWall) {
  // True north along model +X: the wall at x = 1 stands on the true north side, which the sun of
  // a February or March day never reaches at 40° N (it rises and sets south of east and west).
  const Scene sc = sceneWithEastWall("grey");
  const Tracer tracer(sc);
  const ClosedFormDay ref = closedForm(golden(), dayOfYear(kDate), kMinAltitudeDeg);
  EXPECT_NEAR(sunlightExposure(tracer, golden(90.0), kDate, {Vec3(0.0)}, kMinAltitudeDeg).points[0].hours,
              ref.hoursAboveMin, kToleranceHours);
  // True north along model −X: the wall is on the true south side; the point sees the sun only
  // while it is in the true northern half of the sky (never, that day).
  EXPECT_EQ(sunlightExposure(tracer, golden(-90.0), kDate, {Vec3(0.0)}, kMinAltitudeDeg).points[0].hours, 0.0);
}

TEST(SunlightExposureTest, ClearGlazingIsSeenThroughFrostedIsNot) {
  const Site site = golden();
  const ClosedFormDay ref = closedForm(site, dayOfYear(kDate), kMinAltitudeDeg);
  const Scene glass = sceneWithEastWall("clear");
  EXPECT_NEAR(sunlightExposure(Tracer(glass), site, kDate, {Vec3(0.0)}, kMinAltitudeDeg).points[0].hours,
              ref.hoursAboveMin, kToleranceHours);
  const Scene frosted = sceneWithEastWall("frosted");
  EXPECT_NEAR(sunlightExposure(Tracer(frosted), site, kDate, {Vec3(0.0)}, kMinAltitudeDeg).points[0].hours,
              0.5 * ref.hoursAboveMin, kToleranceHours);
}

TEST(SunlightExposureTest, ResultsDoNotDependOnThreads) {
  const Scene sc = sceneWithEastWall("grey");
  const Tracer tracer(sc);
  const std::vector<Vec3> pts = {Vec3(0.0), Vec3(0.5, 0.0, 0.0), Vec3(2.0, 0.0, 0.0), Vec3(-3.0, 1.0, 5.0)};
  SunlightOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const SunlightExposure a = sunlightExposure(tracer, golden(), kDate, pts, kMinAltitudeDeg, one);
  const SunlightExposure b = sunlightExposure(tracer, golden(), kDate, pts, kMinAltitudeDeg, two);
  for (size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(a.points[i].hours, b.points[i].hours);
  // x = 2 lies east of the wall: the morning that x = 0 misses, until the same meridian crossing
  // (each edge bisected to 1 s).
  EXPECT_NEAR(a.points[0].hours + a.points[2].hours, a.sunAboveMinHours, 2.0 / 3600.0);
  EXPECT_NEAR(a.points[2].intervals.at(0).endHour, a.points[0].intervals.at(0).startHour, 1.0 / 3600.0);
}

TEST(SunlightExposureTest, DateOutsideTheReferencePeriodIsAnInputError) {
  const FileLoc loc{"case.toml", 12, 1};
  for (const CivilDate d : {CivilDate{2026, 1, 31}, CivilDate{2026, 3, 22}, CivilDate{2026, 6, 21},
                            CivilDate{2026, 2, 29}, CivilDate{2026, 13, 1}}) {
    try {
      checkSunlightDate(d, loc);
      ADD_FAILURE() << d.month << "-" << d.day << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("case.toml:12"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(checkSunlightDate({2026, 2, 1}));
  EXPECT_NO_THROW(checkSunlightDate({2028, 2, 29}));
  EXPECT_NO_THROW(checkSunlightDate({2026, 3, 21}));
}

}  // namespace
}  // namespace candela
