// A daylight site: where on Earth the model stands, how it is turned, and what local time means.
//
// Frames (architecture.md): model space is +X east, +Y north, +Z up, but "north" there is model
// north. True north lies `northDeg` clockwise from model +Y (seen from above). The sun and sky are
// described in the TRUE frame (+X true east, +Y true north, +Z up) and rotated into the model by
// trueToModel(); the geometry is never moved.
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <optional>
#include <string>

namespace candela {

// Latitude in degrees (north positive) from decimal degrees ("37.87") or a DMS string parsed by
// GeographicLib::DMS ("37d52'N", "37:52:00", "33d52'S" = -33.867).
// Throws InputError at `loc` when malformed, when it carries an E/W designator, or when outside
// [-90, 90].
double parseLatitudeDeg(const std::string& text, const FileLoc& loc = {});
// Longitude in degrees (east positive), e.g. "-122.27" or "122d16'W"; range [-180, 180].
double parseLongitudeDeg(const std::string& text, const FileLoc& loc = {});

// Meridian convergence (degrees) of the UTM/UPS grid at a point, from GeographicLib::UTMUPS:
// the bearing of grid north measured clockwise from true north. Positive east of the zone's
// central meridian in the northern hemisphere (to first order gamma = dLon * sin(lat)).
double utmConvergenceDeg(double latitudeDeg, double longitudeDeg);

struct Site {
  double latitudeDeg = 0.0;    // north positive
  double longitudeDeg = 0.0;   // east positive
  double elevationM = 0.0;     // above mean sea level, m
  double timezoneHours = 0.0;  // local standard time minus UTC, hours (e.g. -8 for PST)
  // The model's north setting in degrees. With grid "" it is true north measured clockwise from
  // model +Y. With grid "utm" the model is drawn in UTM/UPS grid coordinates and northDeg is grid
  // north measured clockwise from model +Y; see trueNorthDeg().
  double northDeg = 0.0;
  std::string grid;                    // "" (none) or "utm"
  double meridianConvergenceDeg = 0.0;  // set by makeSite for grid "utm", else 0

  // True north measured clockwise from model +Y, in degrees: the angle the sun and sky are
  // rotated by. Grid north has bearing gamma (clockwise from true north), so true north lies
  // -gamma clockwise from grid north and trueNorthDeg = northDeg - meridianConvergenceDeg.
  double trueNorthDeg() const { return northDeg - meridianConvergenceDeg; }
};

// Checks ranges (latitude, longitude, timezone in [-18, 18] h) and computes the convergence for
// grid "utm". Throws InputError at `loc` for bad values or an unknown grid name.
Site makeSite(double latitudeDeg, double longitudeDeg, double elevationM, double timezoneHours,
              double northDeg, const std::string& grid = "", const FileLoc& loc = {});

// Unit direction in MODEL space for a true azimuth (degrees clockwise from true north) and
// altitude (degrees above the horizon), for a model whose true north lies northDeg clockwise
// from model +Y.
Vec3 directionFromAzAlt(double azimuthDeg, double altitudeDeg, double northDeg);

struct AzAlt {
  double azimuthDeg = 0.0;   // true azimuth, clockwise from true north, in [0, 360)
  double altitudeDeg = 0.0;  // above the horizon, [-90, 90]
};
// Inverse of directionFromAzAlt for a model-space direction (need not be unit length, must be
// non-zero). At the zenith and nadir the azimuth is reported as 0.
AzAlt azAltFromDirection(const Vec3& dirModel, double northDeg);

// Rotations about +Z between the model frame and the true frame (+Y true north).
Vec3 trueToModel(const Vec3& dirTrue, double northDeg);
Vec3 modelToTrue(const Vec3& dirModel, double northDeg);

// A civil date and time as written, e.g. "2026-03-21T12:00" (local standard time at the site) or
// "2003-10-17T12:30:30-07:00" (with an explicit offset from UTC; "Z" means UTC).
struct LocalTime {
  int year = 2000;
  int month = 1;   // 1..12
  int day = 1;     // 1..31
  int hour = 0;    // 0..24 (24:00:00 only)
  int minute = 0;  // 0..59
  double second = 0.0;                    // [0, 60)
  std::optional<double> utcOffsetHours;  // present when the string carries an offset

  double hourOfDay() const { return hour + minute / 60.0 + second / 3600.0; }
  int dayOfYear() const;  // 1..366
};

// Parses "YYYY-MM-DDTHH:MM[:SS[.fff]][Z|(+|-)HH[:MM]]" (a space may replace 'T'). Throws
// InputError at `loc` when malformed or out of range (e.g. 2026-02-30).
LocalTime parseLocalTime(const std::string& text, const FileLoc& loc = {});

bool isLeapYear(int year);
int daysInMonth(int year, int month);

}  // namespace candela
