#include "photometry/sun_spa.h"

#include "base/error.h"
#include "base/math.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

namespace candela {

namespace {

// One periodic term A cos(B + C * JME) of the Earth's heliocentric series.
struct EarthTerm {
  double a, b, c;
};

// Earth periodic terms, Reda & Andreas (2008) Table A4.2 (after Meeus, Astronomical Algorithms,
// from VSOP87). Units: A in 1e-8 rad (L, B) or 1e-8 AU (R), B in rad, C in rad per millennium.
constexpr EarthTerm kL0[] = {
    {175347046, 0, 0}, {3341656, 4.6692568, 6283.07585}, {34894, 4.6261, 12566.1517},
    {3497, 2.7441, 5753.3849}, {3418, 2.8289, 3.5231}, {3136, 3.6277, 77713.7715},
    {2676, 4.4181, 7860.4194}, {2343, 6.1352, 3930.2097}, {1324, 0.7425, 11506.7698},
    {1273, 2.0371, 529.691}, {1199, 1.1096, 1577.3435}, {990, 5.233, 5884.927},
    {902, 2.045, 26.298}, {857, 3.508, 398.149}, {780, 1.179, 5223.694},
    {753, 2.533, 5507.553}, {505, 4.583, 18849.228}, {492, 4.205, 775.523},
    {357, 2.92, 0.067}, {317, 5.849, 11790.629}, {284, 1.899, 796.298},
    {271, 0.315, 10977.079}, {243, 0.345, 5486.778}, {206, 4.806, 2544.314},
    {205, 1.869, 5573.143}, {202, 2.458, 6069.777}, {156, 0.833, 213.299},
    {132, 3.411, 2942.463}, {126, 1.083, 20.775}, {115, 0.645, 0.98},
    {103, 0.636, 4694.003}, {102, 0.976, 15720.839}, {102, 4.267, 7.114},
    {99, 6.21, 2146.17}, {98, 0.68, 155.42}, {86, 5.98, 161000.69},
    {85, 1.3, 6275.96}, {85, 3.67, 71430.7}, {80, 1.81, 17260.15},
    {79, 3.04, 12036.46}, {75, 1.76, 5088.63}, {74, 3.5, 3154.69},
    {74, 4.68, 801.82}, {70, 0.83, 9437.76}, {62, 3.98, 8827.39},
    {61, 1.82, 7084.9}, {57, 2.78, 6286.6}, {56, 4.39, 14143.5},
    {56, 3.47, 6279.55}, {52, 0.19, 12139.55}, {52, 1.33, 1748.02},
    {51, 0.28, 5856.48}, {49, 0.49, 1194.45}, {41, 5.37, 8429.24},
    {41, 2.4, 19651.05}, {39, 6.17, 10447.39}, {37, 6.04, 10213.29},
    {37, 2.57, 1059.38}, {36, 1.71, 2352.87}, {36, 1.78, 6812.77},
    {33, 0.59, 17789.85}, {30, 0.44, 83996.85}, {30, 2.74, 1349.87},
    {25, 3.16, 4690.48}};
constexpr EarthTerm kL1[] = {
    {628331966747.0, 0, 0}, {206059, 2.678235, 6283.07585}, {4303, 2.6351, 12566.1517},
    {425, 1.59, 3.523}, {119, 5.796, 26.298}, {109, 2.966, 1577.344},
    {93, 2.59, 18849.23}, {72, 1.14, 529.69}, {68, 1.87, 398.15},
    {67, 4.41, 5507.55}, {59, 2.89, 5223.69}, {56, 2.17, 155.42},
    {45, 0.4, 796.3}, {36, 0.47, 775.52}, {29, 2.65, 7.11},
    {21, 5.34, 0.98}, {19, 1.85, 5486.78}, {19, 4.97, 213.3},
    {17, 2.99, 6275.96}, {16, 0.03, 2544.31}, {16, 1.43, 2146.17},
    {15, 1.21, 10977.08}, {12, 2.83, 1748.02}, {12, 3.26, 5088.63},
    {12, 5.27, 1194.45}, {12, 2.08, 4694}, {11, 0.77, 553.57},
    {10, 1.3, 6286.6}, {10, 4.24, 1349.87}, {9, 2.7, 242.73},
    {9, 5.64, 951.72}, {8, 5.3, 2352.87}, {6, 2.65, 9437.76},
    {6, 4.67, 4690.48}};
constexpr EarthTerm kL2[] = {
    {52919, 0, 0}, {8720, 1.0721, 6283.0758}, {309, 0.867, 12566.152},
    {27, 0.05, 3.52}, {16, 5.19, 26.3}, {16, 3.68, 155.42},
    {10, 0.76, 18849.23}, {9, 2.06, 77713.77}, {7, 0.83, 775.52},
    {5, 4.66, 1577.34}, {4, 1.03, 7.11}, {4, 3.44, 5573.14},
    {3, 5.14, 796.3}, {3, 6.05, 5507.55}, {3, 1.19, 242.73},
    {3, 6.12, 529.69}, {3, 0.31, 398.15}, {3, 2.28, 553.57},
    {2, 4.38, 5223.69}, {2, 3.75, 0.98}};
constexpr EarthTerm kL3[] = {{289, 5.844, 6283.076}, {35, 0, 0},         {17, 5.49, 12566.15},
                             {3, 5.2, 155.42},       {1, 4.72, 3.52},     {1, 5.3, 18849.23},
                             {1, 5.97, 242.73}};
constexpr EarthTerm kL4[] = {{114, 3.142, 0}, {8, 4.13, 6283.08}, {1, 3.84, 12566.15}};
constexpr EarthTerm kL5[] = {{1, 3.14, 0}};

constexpr EarthTerm kB0[] = {{280, 3.199, 84334.662}, {102, 5.422, 5507.553}, {80, 3.88, 5223.69},
                             {44, 3.7, 2352.87},      {32, 4, 1577.34}};
constexpr EarthTerm kB1[] = {{9, 3.9, 5507.55}, {6, 1.73, 5223.69}};

constexpr EarthTerm kR0[] = {
    {100013989, 0, 0}, {1670700, 3.0984635, 6283.07585}, {13956, 3.05525, 12566.1517},
    {3084, 5.1985, 77713.7715}, {1628, 1.1739, 5753.3849}, {1576, 2.8469, 7860.4194},
    {925, 5.453, 11506.77}, {542, 4.564, 3930.21}, {472, 3.661, 5884.927},
    {346, 0.964, 5507.553}, {329, 5.9, 5223.694}, {307, 0.299, 5573.143},
    {243, 4.273, 11790.629}, {212, 5.847, 1577.344}, {186, 5.022, 10977.079},
    {175, 3.012, 18849.228}, {110, 5.055, 5486.778}, {98, 0.89, 6069.78},
    {86, 5.69, 15720.84}, {86, 1.27, 161000.69}, {65, 0.27, 17260.15},
    {63, 0.92, 529.69}, {57, 2.01, 83996.85}, {56, 5.24, 71430.7},
    {49, 3.25, 2544.31}, {47, 2.58, 775.52}, {45, 5.54, 9437.76},
    {43, 6.01, 6275.96}, {39, 5.36, 4694}, {38, 2.39, 8827.39},
    {37, 0.83, 19651.05}, {37, 4.9, 12139.55}, {36, 1.67, 12036.46},
    {35, 1.84, 2942.46}, {33, 0.24, 7084.9}, {32, 0.18, 5088.63},
    {32, 1.78, 398.15}, {28, 1.21, 6286.6}, {28, 1.9, 6279.55},
    {26, 4.59, 10447.39}};
constexpr EarthTerm kR1[] = {{103019, 1.10749, 6283.07585}, {1721, 1.0644, 12566.1517},
                             {702, 3.142, 0},               {32, 1.02, 18849.23},
                             {31, 2.84, 5507.55},           {25, 1.32, 5223.69},
                             {18, 1.42, 1577.34},           {10, 5.91, 10977.08},
                             {9, 1.42, 6275.96},            {9, 0.27, 5486.78}};
constexpr EarthTerm kR2[] = {{4359, 5.7846, 6283.0758}, {124, 5.579, 12566.152}, {12, 3.14, 0},
                             {9, 3.63, 77713.77},       {6, 1.87, 5573.14},      {3, 5.47, 18849.23}};
constexpr EarthTerm kR3[] = {{145, 4.273, 6283.076}, {7, 3.92, 12566.15}};
constexpr EarthTerm kR4[] = {{4, 2.56, 6283.08}};

// Nutation terms, Reda & Andreas (2008) Table A4.3: multipliers of X0..X4 (mean elongation of
// the Moon, mean anomalies of the Sun and Moon, Moon's argument of latitude, longitude of the
// Moon's ascending node), and coefficients a, b (longitude) and c, d (obliquity) in 0.0001".
struct NutationTerm {
  int y[5];
  double a, b, c, d;
};
constexpr NutationTerm kNutation[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},  {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},      {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},        {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},       {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},          {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},              {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},             {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},             {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},           {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},                {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},               {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},                 {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},                 {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},              {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},               {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},                {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},               {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},               {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},                 {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},                {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},                  {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},                {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},                 {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},               {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},                 {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},                 {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},                {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},                 {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},                {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},                 {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},               {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0}};
static_assert(std::size(kNutation) == 63);

constexpr double kSunRadiusDeg = 0.26667;

double wrapDeg(double d) {
  d = std::fmod(d, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}
double wrapDeg180(double d) {  // to (-180, 180]
  d = wrapDeg(d);
  return d > 180.0 ? d - 360.0 : d;
}
double sinD(double d) { return std::sin(degToRad(d)); }
double cosD(double d) { return std::cos(degToRad(d)); }

// Eq. 10-12: sum of the series L_i (or B_i, R_i) and the polynomial in JME, divided by 1e8.
double earthSeries(std::initializer_list<std::span<const EarthTerm>> series, double jme) {
  double total = 0.0, power = 1.0;
  for (const auto& s : series) {
    double sum = 0.0;
    for (const EarthTerm& t : s) sum += t.a * std::cos(t.b + t.c * jme);
    total += sum * power;
    power *= jme;
  }
  return total / 1e8;
}

// The geocentric quantities that depend only on time (steps 3.2-3.8 of the report).
struct Geocentric {
  double alphaDeg;  // apparent sun right ascension
  double deltaDeg;  // geocentric sun declination
  double nuDeg;     // apparent sidereal time at Greenwich
  double rAu;       // Earth radius vector
};

Geocentric geocentric(double jd, double deltaTSec) {
  const double jde = jd + deltaTSec / 86400.0;  // eq. 5
  const double jc = (jd - 2451545.0) / 36525.0;   // eq. 6
  const double jce = (jde - 2451545.0) / 36525.0;  // eq. 7
  const double jme = jce / 10.0;                  // eq. 8

  const double lDeg = wrapDeg(radToDeg(earthSeries({kL0, kL1, kL2, kL3, kL4, kL5}, jme)));
  const double bDeg = radToDeg(earthSeries({kB0, kB1}, jme));
  const double rAu = earthSeries({kR0, kR1, kR2, kR3, kR4}, jme);

  const double thetaDeg = wrapDeg(lDeg + 180.0);  // eq. 13, geocentric longitude
  const double betaDeg = -bDeg;                   // eq. 14, geocentric latitude

  // Eqs. 15-19: arguments of the nutation series, degrees.
  const double x[5] = {
      297.85036 + jce * (445267.111480 + jce * (-0.0019142 + jce / 189474.0)),
      357.52772 + jce * (35999.050340 + jce * (-0.0001603 - jce / 300000.0)),
      134.96298 + jce * (477198.867398 + jce * (0.0086972 + jce / 56250.0)),
      93.27191 + jce * (483202.017538 + jce * (-0.0036825 + jce / 327270.0)),
      125.04452 + jce * (-1934.136261 + jce * (0.0020708 + jce / 450000.0))};
  double dPsi = 0.0, dEps = 0.0;  // eqs. 20-23
  for (const NutationTerm& t : kNutation) {
    double arg = 0.0;
    for (int j = 0; j < 5; ++j) arg += x[j] * t.y[j];
    dPsi += (t.a + t.b * jce) * sinD(arg);
    dEps += (t.c + t.d * jce) * cosD(arg);
  }
  dPsi /= 36000000.0;  // 0.0001" -> degrees
  dEps /= 36000000.0;

  // Eq. 24: mean obliquity of the ecliptic in arc seconds (Laskar), U = JME / 10.
  const double u = jme / 10.0;
  const double eps0 =
      84381.448 +
      u * (-4680.93 +
           u * (-1.55 + u * (1999.25 + u * (-51.38 + u * (-249.67 + u * (-39.05 + u * (7.12 + u * (27.87 + u * (5.79 + u * 2.45)))))))));
  const double epsDeg = eps0 / 3600.0 + dEps;  // eq. 25

  const double dTauDeg = -20.4898 / (3600.0 * rAu);      // eq. 26, aberration
  const double lambdaDeg = thetaDeg + dPsi + dTauDeg;     // eq. 27, apparent sun longitude

  // Eqs. 28-29: apparent sidereal time at Greenwich.
  const double nu0 = wrapDeg(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                             jc * jc * (0.000387933 - jc / 38710000.0));
  const double nuDeg = nu0 + dPsi * cosD(epsDeg);

  // Eqs. 30-33: geocentric right ascension and declination.
  const double lam = degToRad(lambdaDeg), eps = degToRad(epsDeg), beta = degToRad(betaDeg);
  const double alphaDeg =
      wrapDeg(radToDeg(std::atan2(std::sin(lam) * std::cos(eps) - std::tan(beta) * std::sin(eps), std::cos(lam))));
  const double deltaDeg =
      radToDeg(std::asin(std::sin(beta) * std::cos(eps) + std::cos(beta) * std::sin(eps) * std::sin(lam)));
  return {alphaDeg, deltaDeg, nuDeg, rAu};
}

// Eq. 42 (Bennett-type formula of the report): refraction correction in degrees for the
// topocentric elevation e0 (degrees) without refraction, applied only while the upper limb can
// be above the horizon.
double refractionDeg(double e0Deg, double pressureMbar, double temperatureC, double atmosRefractDeg) {
  if (e0Deg < -(kSunRadiusDeg + atmosRefractDeg)) return 0.0;
  return (pressureMbar / 1010.0) * (283.0 / (273.0 + temperatureC)) * 1.02 /
         (60.0 * std::tan(degToRad(e0Deg + 10.3 / (e0Deg + 5.11))));
}

}  // namespace

SunGeocentric sunGeocentric(double julianDayUt, double deltaTSec) {
  const Geocentric g = geocentric(julianDayUt, deltaTSec);
  return {g.alphaDeg, g.deltaDeg, g.nuDeg, g.rAu};
}

double julianDay(int year, int month, int day, double utHours) {
  const double dayDecimal = day + utHours / 24.0;
  if (month < 3) {
    month += 12;
    --year;
  }
  double jd = std::floor(365.25 * (year + 4716.0)) + std::floor(30.6001 * (month + 1)) + dayDecimal - 1524.5;
  if (jd > 2299160.0) {  // Gregorian calendar correction
    const double a = std::floor(year / 100.0);
    jd += 2.0 - a + std::floor(a / 4.0);
  }
  return jd;
}

double estimateDeltaTSec(double y) {
  // Espenak & Meeus, "Five Millennium Canon of Solar Eclipses" (NASA/TP-2006-214141), sec. 2.6.
  if (y < 1961.0 || y >= 2150.0) {
    const double u = (y - 1820.0) / 100.0;
    return -20.0 + 32.0 * u * u;
  }
  if (y < 1986.0) {
    const double t = y - 1975.0;
    return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
  }
  if (y < 2005.0) {
    const double t = y - 2000.0;
    return 63.86 + t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + t * 0.00002373599))));
  }
  if (y < 2050.0) {
    const double t = y - 2000.0;
    return 62.92 + t * (0.32217 + t * 0.005589);
  }
  const double u = (y - 1820.0) / 100.0;
  return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - y);
}

std::string formatHours(double hours) {
  if (!std::isfinite(hours)) return "none";
  long total = std::lround(hours * 3600.0);
  total = ((total % 86400) + 86400) % 86400;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
  return buf;
}

namespace {

SpaResult positionOnly(const SpaInput& in) {
  const FileLoc noLoc;
  if (in.year < -2000 || in.year > 6000) throw InputError(noLoc, "year must be in [-2000, 6000]");
  if (in.month < 1 || in.month > 12) throw InputError(noLoc, "month must be in [1, 12]");
  if (in.day < 1 || in.day > 31) throw InputError(noLoc, "day must be in [1, 31]");
  if (!(in.hourOfDay >= 0.0 && in.hourOfDay <= 24.0)) throw InputError(noLoc, "hour must be in [0, 24]");
  if (!(std::abs(in.latitudeDeg) <= 90.0)) throw InputError(noLoc, "latitude must be in [-90, 90] degrees");
  if (!(std::abs(in.longitudeDeg) <= 180.0)) throw InputError(noLoc, "longitude must be in [-180, 180] degrees");
  if (!(std::abs(in.timezoneHours) <= 18.0)) throw InputError(noLoc, "timezone must be in [-18, 18] hours");
  if (!(in.pressureMbar >= 0.0 && in.pressureMbar <= 5000.0)) throw InputError(noLoc, "pressure must be in [0, 5000] mbar");
  if (!(in.temperatureC > -273.0 && in.temperatureC <= 6000.0)) throw InputError(noLoc, "temperature must be in (-273, 6000] deg C");
  if (!(std::abs(in.deltaTSec) <= 8000.0)) throw InputError(noLoc, "delta T must be in [-8000, 8000] s");
  if (!(in.elevationM >= -6500000.0)) throw InputError(noLoc, "elevation must be above -6500000 m");

  const double jd = julianDay(in.year, in.month, in.day, in.hourOfDay - in.timezoneHours);
  const Geocentric g = geocentric(jd, in.deltaTSec);
  const double phi = degToRad(in.latitudeDeg);

  // Eq. 34: observer local hour angle.
  const double hDeg = wrapDeg(g.nuDeg + in.longitudeDeg - g.alphaDeg);

  // Eqs. 35-38: parallax in right ascension and topocentric declination.
  const double xi = degToRad(8.794 / (3600.0 * g.rAu));
  const double u = std::atan(0.99664719 * std::tan(phi));
  const double x = std::cos(u) + in.elevationM / 6378140.0 * std::cos(phi);
  const double y = 0.99664719 * std::sin(u) + in.elevationM / 6378140.0 * std::sin(phi);
  const double h = degToRad(hDeg), delta = degToRad(g.deltaDeg);
  const double dAlpha = std::atan2(-x * std::sin(xi) * std::sin(h), std::cos(delta) - x * std::sin(xi) * std::cos(h));
  const double deltaP = std::atan2((std::sin(delta) - y * std::sin(xi)) * std::cos(dAlpha),
                                   std::cos(delta) - x * std::sin(xi) * std::cos(h));
  const double hP = h - dAlpha;  // eq. 40, topocentric local hour angle

  // Eqs. 41-44: elevation without and with refraction, zenith.
  const double e0Deg =
      radToDeg(std::asin(std::sin(phi) * std::sin(deltaP) + std::cos(phi) * std::cos(deltaP) * std::cos(hP)));
  const double eDeg = e0Deg + refractionDeg(e0Deg, in.pressureMbar, in.temperatureC, in.atmosRefractDeg);

  // Eqs. 45-46: astronomers' azimuth (from south, westward), then navigators' (from north, east).
  const double gammaDeg =
      radToDeg(std::atan2(std::sin(hP), std::cos(hP) * std::sin(phi) - std::tan(deltaP) * std::cos(phi)));

  SpaResult r;
  r.altitudeDeg = eDeg;
  r.zenithDeg = 90.0 - eDeg;
  r.azimuthDeg = wrapDeg(gammaDeg + 180.0);
  r.declinationDeg = radToDeg(deltaP);
  r.hourAngleDeg = radToDeg(hP);
  r.earthSunDistanceAu = g.rAu;

  return r;
}

// Geometric topocentric altitude (no refraction) at local hour t of the input's day.
double geometricAltitudeDeg(SpaInput in, double hour) {
  in.hourOfDay = hour;
  in.pressureMbar = 0.0;
  return positionOnly(in).altitudeDeg;
}

double topocentricHourAngleDeg(SpaInput in, double hour) {
  in.hourOfDay = hour;
  return wrapDeg180(positionOnly(in).hourAngleDeg);
}

// Bisection for a sign change of f on [a, b] (f(a), f(b) of opposite sign), to ~0.005 s.
template <class F>
double bisect(F f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 24 && b - a > 1e-6; ++i) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// Sunrise, transit and sunset of the LOCAL civil day. The report's appendix A.2 interpolates
// within the UT day of the date, so west of Greenwich its sunset is the one of the previous
// local evening (its example: "sunset 17:20:19" for 2003-10-17 at UTC-7 is the sunset of
// October 16; October 17's is at 17:18:51). Here the events are instead found directly on the
// full algorithm: rise/set where the geometric altitude of the sun's centre is
// h0' = -(0.26667 + atmosRefract) deg (the report's eq. A2 definition), transit where the
// topocentric hour angle changes sign. A 15-minute scan finds the brackets.
void riseTransitSet(const SpaInput& in, SpaResult& r) {
  const double h0Prime = -(kSunRadiusDeg + in.atmosRefractDeg);
  constexpr int kSteps = 96;
  double alt[kSteps + 1], ha[kSteps + 1];
  for (int i = 0; i <= kSteps; ++i) {
    alt[i] = geometricAltitudeDeg(in, 24.0 * i / kSteps) - h0Prime;
    ha[i] = topocentricHourAngleDeg(in, 24.0 * i / kSteps);
  }
  const auto altF = [&](double t) { return geometricAltitudeDeg(in, t) - h0Prime; };
  const auto haF = [&](double t) { return topocentricHourAngleDeg(in, t); };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.sunriseHour = r.sunsetHour = r.transitHour = nan;
  double maxAlt = -1e9;
  for (int i = 0; i < kSteps; ++i) {
    const double a = 24.0 * i / kSteps, b = 24.0 * (i + 1) / kSteps;
    maxAlt = std::max(maxAlt, alt[i]);
    if (alt[i] < 0.0 && alt[i + 1] >= 0.0 && std::isnan(r.sunriseHour)) r.sunriseHour = bisect(altF, a, b);
    if (alt[i] >= 0.0 && alt[i + 1] < 0.0) r.sunsetHour = bisect(altF, a, b);
    // Hour angle goes from negative to positive at transit (and jumps +180 -> -180 at
    // lower culmination, which is excluded by the size of the jump).
    if (ha[i] < 0.0 && ha[i + 1] >= 0.0 && ha[i + 1] - ha[i] < 90.0) r.transitHour = bisect(haF, a, b);
  }
  maxAlt = std::max(maxAlt, alt[kSteps]);
  r.polarDay = std::isnan(r.sunriseHour) && std::isnan(r.sunsetHour) && maxAlt >= 0.0;
}

}  // namespace

SpaResult computeSunPosition(const SpaInput& in) {
  SpaResult r = positionOnly(in);
  riseTransitSet(in, r);
  return r;
}

SpaResult computeSunPositionOnly(const SpaInput& in) { return positionOnly(in); }

}  // namespace candela
