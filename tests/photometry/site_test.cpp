#include "photometry/site.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

TEST(Site, ParsesDecimalAndDmsAngles) {
  EXPECT_DOUBLE_EQ(parseLatitudeDeg("37.87"), 37.87);
  EXPECT_NEAR(parseLatitudeDeg("37d52'N"), 37.0 + 52.0 / 60.0, 1e-12);
  EXPECT_NEAR(parseLatitudeDeg("33d52'S"), -(33.0 + 52.0 / 60.0), 1e-12);
  EXPECT_NEAR(parseLongitudeDeg("122d16'W"), -(122.0 + 16.0 / 60.0), 1e-12);
  EXPECT_NEAR(parseLongitudeDeg("8:32:30E"), 8.0 + 32.0 / 60.0 + 30.0 / 3600.0, 1e-12);
}

TEST(Site, RejectsBadAnglesWithLocation) {
  const FileLoc loc{"case.toml", 7, 1};
  EXPECT_THROW(parseLatitudeDeg("91", loc), InputError);
  EXPECT_THROW(parseLatitudeDeg("12d30'E", loc), InputError);  // a longitude designator
  EXPECT_THROW(parseLongitudeDeg("12d30'N", loc), InputError);
  EXPECT_THROW(parseLongitudeDeg("181", loc), InputError);
  try {
    parseLatitudeDeg("north-ish", loc);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 7);
    EXPECT_NE(std::string(e.what()).find("case.toml:7: bad latitude 'north-ish'"), std::string::npos) << e.what();
  }
}

TEST(Site, DirectionConventions) {
  // North 0: azimuth 0 is +Y, 90 is +X (east), altitude 90 is +Z.
  const Vec3 n = directionFromAzAlt(0.0, 0.0, 0.0);
  const Vec3 e = directionFromAzAlt(90.0, 0.0, 0.0);
  const Vec3 z = directionFromAzAlt(123.0, 90.0, 0.0);
  EXPECT_NEAR(n.y, 1.0, 1e-15);
  EXPECT_NEAR(e.x, 1.0, 1e-15);
  EXPECT_NEAR(z.z, 1.0, 1e-15);
  // True north 30 deg clockwise from model +Y: the sun due true north appears at model
  // azimuth 30, i.e. (sin 30, cos 30, 0).
  const Vec3 r = directionFromAzAlt(0.0, 0.0, 30.0);
  EXPECT_NEAR(r.x, 0.5, 1e-15);
  EXPECT_NEAR(r.y, std::sqrt(3.0) / 2.0, 1e-15);
}

TEST(Site, AzAltRoundTrip) {
  for (double north : {0.0, 17.5, -40.0, 200.0}) {
    for (double az = 0.0; az < 360.0; az += 37.0) {
      for (double alt : {-60.0, 0.0, 12.0, 89.0}) {
        const Vec3 d = directionFromAzAlt(az, alt, north);
        EXPECT_NEAR(glm::length(d), 1.0, 1e-14);
        const AzAlt back = azAltFromDirection(d, north);
        EXPECT_NEAR(back.altitudeDeg, alt, 1e-9);
        EXPECT_NEAR(back.azimuthDeg, az, 1e-9);
        // trueToModel applied to the true-frame direction gives the same vector.
        const Vec3 t = directionFromAzAlt(az, alt, 0.0);
        EXPECT_NEAR(glm::length(trueToModel(t, north) - d), 0.0, 1e-14);
        EXPECT_NEAR(glm::length(modelToTrue(d, north) - t), 0.0, 1e-14);
      }
    }
  }
}

TEST(Site, UtmConvergenceSign) {
  // Zone 33 has central meridian 15E. Spherical first-order convergence: gamma = dLon sin(lat);
  // the ellipsoidal value differs at order dLon^3, ~0.1 % here.
  const double lat = 45.0, lon = 17.0;
  EXPECT_NEAR(utmConvergenceDeg(lat, lon), 2.0 * std::sin(degToRad(lat)), 0.01);
  EXPECT_NEAR(utmConvergenceDeg(lat, 13.0), -2.0 * std::sin(degToRad(lat)), 0.01);
  EXPECT_NEAR(utmConvergenceDeg(-lat, lon), -2.0 * std::sin(degToRad(lat)), 0.01);
  // Model +Y = grid north: true north is west of grid north east of the central meridian.
  const Site s = makeSite(lat, lon, 100.0, 1.0, 0.0, "utm");
  EXPECT_NEAR(s.trueNorthDeg(), -s.meridianConvergenceDeg, 1e-12);
  EXPECT_LT(s.trueNorthDeg(), 0.0);
  EXPECT_DOUBLE_EQ(makeSite(lat, lon, 0.0, 1.0, 10.0).trueNorthDeg(), 10.0);
  EXPECT_THROW(makeSite(lat, lon, 0.0, 1.0, 0.0, "lambert"), InputError);
  EXPECT_THROW(makeSite(lat, lon, 0.0, 19.0, 0.0), InputError);
}

TEST(Site, ParsesLocalTime) {
  LocalTime t = parseLocalTime("2026-03-21T12:00");
  EXPECT_EQ(t.year, 2026);
  EXPECT_EQ(t.month, 3);
  EXPECT_EQ(t.day, 21);
  EXPECT_EQ(t.hour, 12);
  EXPECT_FALSE(t.utcOffsetHours.has_value());
  EXPECT_EQ(t.dayOfYear(), 80);
  t = parseLocalTime("2003-10-17T12:30:30-07:00");
  EXPECT_NEAR(t.hourOfDay(), 12.508333333333333, 1e-12);
  ASSERT_TRUE(t.utcOffsetHours.has_value());
  EXPECT_DOUBLE_EQ(*t.utcOffsetHours, -7.0);
  t = parseLocalTime("2024-12-31 23:59:59.5Z");
  EXPECT_EQ(t.dayOfYear(), 366);
  EXPECT_DOUBLE_EQ(*t.utcOffsetHours, 0.0);
  EXPECT_DOUBLE_EQ(*parseLocalTime("2026-06-01T08:00+05:30").utcOffsetHours, 5.5);
}

TEST(Site, RejectsBadTimes) {
  const FileLoc loc{"case.toml", 12, 0};
  for (const char* bad : {"2026-02-30T12:00", "2026-13-01T12:00", "2026-03-21", "2026-03-21T25:00",
                          "2026-03-21T12:60", "2026-03-21T12:00x", "21/03/2026 12:00", "2026-03-21T24:30"}) {
    try {
      parseLocalTime(bad, loc);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.loc().line, 12) << bad;
    }
  }
}

}  // namespace
}  // namespace candela
