// Solar position by the NREL Solar Position Algorithm (SPA): I. Reda and A. Andreas, "Solar
// Position Algorithm for Solar Radiation Applications", NREL/TP-560-34302 (2003, revised 2008).
// Uncertainty +/-0.0003 deg for years -2000..6000. Implemented from the report's equations; the
// periodic-term tables are the report's Tables A4.2 and A4.3. Sunrise, transit and sunset use
// the report's definitions but are found on the local day (see riseTransitSet in the .cpp).
#pragma once

#include <string>

namespace candela {

struct SpaInput {
  int year = 2000;
  int month = 1;
  int day = 1;
  double hourOfDay = 12.0;      // local standard time in hours (12.5 = 12:30), at the given timezone
  double timezoneHours = 0.0;   // local standard time minus UTC, hours (west negative)
  double latitudeDeg = 0.0;     // geodetic, north positive
  double longitudeDeg = 0.0;    // east positive
  double elevationM = 0.0;      // observer elevation, m
  double pressureMbar = 1013.25;  // annual mean local pressure, mbar; 0 disables refraction
  double temperatureC = 15.0;     // annual mean local temperature, deg C
  double deltaTSec = 69.0;        // TT - UT1, seconds (see estimateDeltaTSec)
  double atmosRefractDeg = 0.5667;  // refraction at sunrise/sunset, deg (report's default)
};

struct SpaResult {
  double zenithDeg = 0.0;      // topocentric zenith angle, refraction included
  double azimuthDeg = 0.0;     // topocentric azimuth, clockwise from north, [0, 360)
  double altitudeDeg = 0.0;    // 90 - zenith
  double declinationDeg = 0.0;     // topocentric declination
  double hourAngleDeg = 0.0;       // topocentric local hour angle
  double earthSunDistanceAu = 1.0;  // heliocentric radius vector R, AU
  // Sun transit, sunrise and sunset of the LOCAL civil day (not the UT day, see sun_spa.cpp),
  // in local standard hours [0, 24]. Sunrise/sunset are NaN when the event does not happen that
  // day; polarDay is true when the sun stays above the rise/set altitude all day.
  double transitHour = 0.0;
  double sunriseHour = 0.0;
  double sunsetHour = 0.0;
  bool polarDay = false;
};

// Throws InputError (no location) for inputs outside the algorithm's valid ranges.
SpaResult computeSunPosition(const SpaInput& in);
// The same position without the sunrise/transit/sunset search (those fields stay 0, polarDay
// false): ~250 times cheaper, for callers that need many positions (photometry/annual_sky.h).
SpaResult computeSunPositionOnly(const SpaInput& in);

// Julian day (UT) of a calendar date and UT fraction of day, Gregorian from 1582-10-15
// (report eq. 4).
double julianDay(int year, int month, int day, double utHours);

// Apparent geocentric sun position (report steps 3.1-3.8): right ascension and declination in
// degrees, apparent Greenwich sidereal time in degrees, Earth-sun distance in AU.
struct SunGeocentric {
  double rightAscensionDeg = 0.0;
  double declinationDeg = 0.0;
  double siderealTimeDeg = 0.0;
  double earthSunDistanceAu = 1.0;
};
SunGeocentric sunGeocentric(double julianDayUt, double deltaTSec);

// DeltaT = TT - UT1 in seconds, estimated by the Espenak & Meeus (NASA, 2006) polynomials for
// 1986..2150 (outside that range the nearest end polynomial is used; accuracy degrades to
// seconds-to-minutes). decimalYear e.g. 2026.2.
double estimateDeltaTSec(double decimalYear);

// "hh:mm:ss" for a decimal hour (rounded to the second), "none" for NaN.
std::string formatHours(double hours);

}  // namespace candela
