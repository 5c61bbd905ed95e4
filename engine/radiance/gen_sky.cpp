// gensky and gendaylit, interpreted: the primitives Radiance's programs write for a command line
// (src/gen/gensky.c, src/gen/gendaylit.c and their man pages, for the facts: options, defaults,
// formulas and output), with the sun placed by candela's NREL SPA instead of the programs' own
// solar formulas (docs/daylight.md, "Skies from gensky and gendaylit"). The sky functions the
// output names (skybright.cal, perezlum.cal) are evaluated natively by engine/radiance/sky.h.
#include "engine/radiance/gen.h"

#include "base/math.h"
#include "base/units.h"
#include "photometry/site.h"
#include "photometry/sky_perez.h"
#include "photometry/sun_spa.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace candela {

namespace {

// The year a date without -y is taken in (the programs' own formulas have no year; SPA needs
// one). Not a leap year: 2 29 needs -y with a leap year.
constexpr int kAssumedYear = 2026;

// Site defaults of both programs (src/gen/sun.c): latitude 0.66 rad north, longitude 2.13 rad
// west, standard meridian 120 degrees west.
constexpr double kDefaultLatitudeDeg = 0.66 * 180.0 / kPi;
constexpr double kDefaultLongitudeWestDeg = 2.13 * 180.0 / kPi;
constexpr double kDefaultMeridianWestDeg = 120.0;

// The command's words with the program's name for messages; every error names the `!` line.
class Args {
 public:
  Args(const RadCommand& cmd, std::string program) : cmd_(cmd), program_(std::move(program)) {}
  size_t size() const { return cmd_.words.size(); }
  const std::string& operator[](size_t i) const { return cmd_.words[i]; }
  const FileLoc& loc() const { return cmd_.loc; }
  [[noreturn]] void fail(const std::string& msg) const { throw InputError(cmd_.loc, program_ + ": " + msg); }

  double number(size_t i, const std::string& what) const {
    if (i >= size()) fail(what + " needs a number, got nothing");
    const std::string& w = cmd_.words[i];
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || end != w.c_str() + w.size() || !std::isfinite(v))
      fail(what + " needs a number, got '" + w + "'");
    return v;
  }
  double nonNegative(size_t i, const std::string& what) const {
    const double v = number(i, what);
    if (v < 0.0) fail(what + " needs a value >= 0, got '" + cmd_.words[i] + "'");
    return v;
  }
  int integer(size_t i, const std::string& what) const {
    const double v = number(i, what);
    if (v != std::floor(v) || std::abs(v) > 1e6) fail(what + " needs a whole number, got '" + cmd_.words[i] + "'");
    return static_cast<int>(v);
  }

 private:
  const RadCommand& cmd_;
  std::string program_;
};

// What both programs need to place the sun: a date and time at a site, or -ang.
struct SunRequest {
  bool fromAngles = false;
  double altitudeDeg = 0.0, azimuthDeg = 0.0;  // -ang: azimuth from south, positive towards west
  int month = 0, day = 0;
  double hour = 0.0;
  bool solarTime = false;                      // the time had a leading '+'
  bool meridianFromZone = false;               // the time named a zone (gensky: -m then ignored)
  std::optional<int> year;
  double latitudeDeg = kDefaultLatitudeDeg;
  double longitudeWestDeg = kDefaultLongitudeWestDeg;
  double meridianWestDeg = kDefaultMeridianWestDeg;
};

// gensky's time zone names and their standard meridians in degrees west (src/gen/gensky.c).
std::optional<double> zoneMeridianWestDeg(std::string zone) {
  static const std::pair<const char*, double> kZones[] = {
      {"YST", 135}, {"YDT", 120}, {"PST", 120},  {"PDT", 105},   {"MST", 105},  {"MDT", 90},   {"CST", 90},
      {"CDT", 75},  {"EST", 75},  {"EDT", 60},   {"AST", 60},    {"ADT", 45},   {"NST", 52.5}, {"NDT", 37.5},
      {"GMT", 0},   {"BST", -15}, {"CET", -15},  {"CEST", -30},  {"EET", -30},  {"EEST", -45}, {"GST", -60},
      {"GDT", -75}, {"IST", -82.5}, {"IDT", -97.5}, {"JST", -135}, {"NZST", -180}, {"NZDT", -195}};
  for (char& c : zone) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto& [name, meridian] : kZones)
    if (zone == name) return meridian;  // the first of a repeated name, as gensky's table search
  return std::nullopt;
}

// gensky's time: [+]hours[.fraction] or [+]hours:minutes, then an optional zone name
// (standard time only).
void parseGenskyTime(const Args& a, const std::string& text, SunRequest& s) {
  size_t i = 0;
  s.solarTime = !text.empty() && text[0] == '+';
  if (s.solarTime) ++i;
  const size_t start = i;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  if (i == start) a.fail("bad time '" + text + "': hours[.fraction] or hours:minutes, optionally a zone (12:30PST)");
  double hours = std::atof(text.substr(start, i - start).c_str());
  if (i < text.size() && (text[i] == ':' || text[i] == '.')) {
    const char sep = text[i++];
    const size_t f = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    const std::string digits = text.substr(f, i - f);
    if (sep == ':') {
      if (digits.empty()) a.fail("bad time '" + text + "': minutes missing after ':'");
      const double minutes = std::atof(digits.c_str());
      if (minutes >= 60.0) a.fail("impossible time '" + text + "': minutes run from 0 to 59");
      hours += minutes / 60.0;
    } else if (!digits.empty()) {
      hours += std::atof(("0." + digits).c_str());
    }
  }
  s.hour = hours;
  if (i < text.size()) {
    const std::string zone = text.substr(i);
    if (s.solarTime) a.fail("bad time '" + text + "': solar time (+) takes no time zone");
    const auto meridian = zoneMeridianWestDeg(zone);
    if (!meridian) a.fail("unknown time zone '" + zone + "' in '" + text + "'");
    s.meridianWestDeg = *meridian;
    s.meridianFromZone = true;
  }
  if (!(s.hour >= 0.0 && s.hour <= 24.0)) a.fail("time '" + text + "' is not within 0 to 24 hours");
}

// Month and day (the first two words after the program) or -ang altitude azimuth.
void parseDateOrAngles(const Args& a, SunRequest& s) {
  if (a[1] == "-ang") {
    s.fromAngles = true;
    s.altitudeDeg = a.number(2, "-ang altitude");
    s.azimuthDeg = a.number(3, "-ang azimuth");
    if (std::abs(s.altitudeDeg) > 90.0) a.fail("-ang altitude must be within [-90, 90] degrees");
    return;
  }
  s.month = a.integer(1, "the month");
  if (s.month < 1 || s.month > 12) a.fail("bad month '" + a[1] + "' (1 to 12)");
  s.day = a.integer(2, "the day");
  if (s.day < 1 || s.day > 31) a.fail("bad day '" + a[2] + "' (1 to 31)");
}

// The site options shared by both programs; returns the words used (0 if not a site option).
size_t siteOption(const Args& a, size_t i, SunRequest& s, bool zoneWins) {
  const std::string& w = a[i];
  if (w == "-a") {
    s.latitudeDeg = a.number(i + 1, "-a (latitude, degrees north)");
    if (std::abs(s.latitudeDeg) > 90.0) a.fail("-a latitude must be within [-90, 90] degrees");
    return 2;
  }
  if (w == "-o") {
    s.longitudeWestDeg = a.number(i + 1, "-o (longitude, degrees west)");
    if (std::abs(s.longitudeWestDeg) > 180.0) a.fail("-o longitude must be within [-180, 180] degrees");
    return 2;
  }
  if (w == "-m") {
    const double m = a.number(i + 1, "-m (standard meridian, degrees west)");
    if (std::abs(m) > 270.0) a.fail("-m standard meridian must be within [-270, 270] degrees (18 hours)");
    if (!(zoneWins && s.meridianFromZone)) s.meridianWestDeg = m;  // gensky: a time zone overrides -m
    return 2;
  }
  if (w == "-y") {
    s.year = a.integer(i + 1, "-y (year)");
    if (*s.year < -2000 || *s.year > 6000) a.fail("-y year must be within -2000 to 6000 (NREL SPA's range)");
    return 2;
  }
  return 0;
}

// Day of the year without leap days, as both programs count it (src/gen/sun.c, jdate).
int radianceDayOfYear(int month, int day) {
  static const int kBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  return kBefore[month - 1] + day;
}

// The sun's altitude and azimuth (degrees; azimuth from south, positive towards west, as the
// programs use it) by the NREL SPA for the request's date, time and site. Local standard time is
// that of the standard meridian; solar time is found by matching SPA's hour angle.
void placeSun(const Args& a, SunRequest& s) {
  if (s.fromAngles) return;
  const int year = s.year.value_or(kAssumedYear);
  if (s.day > daysInMonth(year, s.month))
    a.fail("impossible date: month " + std::to_string(s.month) + " of " + std::to_string(year) + " has " +
           std::to_string(daysInMonth(year, s.month)) + " days" + (s.year ? "" : " (a date without -y is in 2026)"));
  SpaInput in;
  in.year = year;
  in.month = s.month;
  in.day = s.day;
  in.latitudeDeg = s.latitudeDeg;
  in.longitudeDeg = -s.longitudeWestDeg;
  const LocalTime t{year, s.month, s.day, 0, 0, 0.0, std::nullopt};
  in.deltaTSec = estimateDeltaTSec(year + (t.dayOfYear() - 0.5) / 365.25);
  SpaResult r;
  if (!s.solarTime) {
    in.timezoneHours = -s.meridianWestDeg / 15.0;
    if (std::abs(in.timezoneHours) > 18.0) a.fail("standard meridian more than 18 hours from Greenwich");
    in.hourOfDay = s.hour;
    r = computeSunPositionOnly(in);
  } else {
    // Apparent solar time st has hour angle 15 (st - 12) degrees. Local mean time at the site's
    // longitude is within the equation of time (< 17 min) of it; three corrections of SPA's own
    // hour angle bring the clock time to well under a millisecond.
    in.timezoneHours = in.longitudeDeg / 15.0;
    double clock = s.hour;
    for (int k = 0; k < 4; ++k) {
      in.hourOfDay = std::clamp(clock, 0.0, 24.0);
      r = computeSunPositionOnly(in);
      const double err = std::remainder(15.0 * (s.hour - 12.0) - r.hourAngleDeg, 360.0);
      clock += err / 15.0;
    }
  }
  s.altitudeDeg = r.altitudeDeg;
  s.azimuthDeg = std::remainder(r.azimuthDeg - 180.0, 360.0);
}

// The programs' sun vector: +X east, +Y north, azimuth from south towards west.
Vec3 sunVector(double altitudeRad, double azimuthRad) {
  return Vec3(-std::sin(azimuthRad) * std::cos(altitudeRad), -std::cos(azimuthRad) * std::cos(altitudeRad),
              std::sin(altitudeRad));
}

// `void light solar` and `solar source sun` as both programs write them.
void addSun(std::vector<RadPrimitive>& out, const FileLoc& loc, double radiance, const Vec3& dir, double angleDeg) {
  out.push_back(generatedPrimitive("void", "light", "solar", loc, {}, {radiance, radiance, radiance}));
  out.push_back(generatedPrimitive("solar", "source", "sun", loc, {}, {dir.x, dir.y, dir.z, angleDeg}));
}

// Sky-dependent normalisation polynomial E0 F2 / L0 of both programs (gensky.c, normsc), for the
// clear (intermediate = false) or intermediate sky, at a solar altitude in radians.
double normsc(bool intermediate, double altitudeRad) {
  static const double kClear[5] = {2.766521, 0.547665, -0.369832, 0.009237, 0.059229};
  static const double kInter[5] = {3.5556, -2.7152, -1.3081, 1.0660, 0.60227};
  const double* nf = intermediate ? kInter : kClear;
  const double x = (altitudeRad - kPi / 4.0) / (kPi / 4.0);
  double v = nf[4];
  for (int i = 3; i >= 0; --i) v = v * x + nf[i];
  return v;
}

double clearF2(double altitudeRad) {
  const double sz = std::sin(altitudeRad);
  return 0.274 * (0.91 + 10.0 * std::exp(-3.0 * (kPi / 2.0 - altitudeRad)) + 0.45 * sz * sz);
}

double intermediateF2(double altitudeRad) {
  return (2.739 + .9891 * std::sin(.3119 + 2.6 * altitudeRad)) *
         std::exp(-(kPi / 2.0 - altitudeRad) * (.4441 + 1.48 * altitudeRad));
}

// Radiance's efficacies (src/common/color.h): SKYEFFICACY 203 lm/W (gensky's zenith formulas
// give kcd/m2), SUNEFFICACY 208 lm/W.
constexpr double kSkyEfficacy = 203.0;
constexpr double kSunEfficacy = 208.0;
// gensky's solid angle of the 0.5-degree sun, sr, as it writes it (-R divides by it).
constexpr double kGenskySunSr = 5.98e-5;

enum class GenskySky { kClear = 1, kOvercast = 2, kUniform = 3, kIntermediate = 4 };

struct GenskyOptions {
  GenskySky sky = GenskySky::kClear;
  bool sun = true;
  std::optional<double> zenith;  // -b (W/sr/m2) or -B (horizontal W/m2) value
  bool zenithHorizontal = false;
  std::optional<double> solar;   // -r (W/sr/m2) or -R (horizontal W/m2) value
  bool solarHorizontal = false;
  double turbidity = 2.45;
  double groundReflectance = 0.2;
};

void parseGenskyOptions(const Args& a, SunRequest& s, GenskyOptions& o) {
  for (size_t i = 4; i < a.size();) {
    const std::string& w = a[i];
    if (const size_t n = siteOption(a, i, s, true)) {
      i += n;
      continue;
    }
    if (w == "+s" || w == "-s" || w == "+i" || w == "-i") {
      o.sky = w[1] == 's' ? GenskySky::kClear : GenskySky::kIntermediate;
      o.sun = w[0] == '+';
    } else if (w == "-c" || w == "+c") {
      o.sky = GenskySky::kOvercast;
    } else if (w == "-u" || w == "+u") {
      o.sky = GenskySky::kUniform;
    } else if (w == "-b" || w == "-B") {
      o.zenith = a.nonNegative(i + 1, w + (w == "-b" ? " (zenith radiance, W/sr/m2)" : " (horizontal diffuse irradiance, W/m2)"));
      o.zenithHorizontal = w == "-B";
      ++i;
    } else if (w == "-r" || w == "-R") {
      o.solar = a.nonNegative(i + 1, w + (w == "-r" ? " (solar radiance, W/sr/m2)" : " (horizontal direct irradiance, W/m2)"));
      o.solarHorizontal = w == "-R";
      ++i;
    } else if (w == "-t") {
      o.turbidity = a.nonNegative(i + 1, "-t (turbidity)");
      ++i;
    } else if (w == "-g") {
      o.groundReflectance = a.number(i + 1, "-g (ground reflectance)");
      if (o.groundReflectance < 0.0 || o.groundReflectance > 1.0) a.fail("-g ground reflectance must be within [0, 1]");
      ++i;
    } else {
      a.fail("unknown option '" + w + "' (gensky takes +s -s +i -i -c -u -b -B -r -R -t -g -a -o -m -y)");
    }
    ++i;
  }
}

}  // namespace

// A sky command's suspicious input, kept as a warning (sky_input_out_of_range) when the reader
// keeps warnings.
void warnSky(const RadExpandContext& ctx, const RadCommand& cmd, const std::string& program, const std::string& what) {
  if (ctx.warnings) ctx.warnings->push_back(Warning{"sky_input_out_of_range", program + ": " + what, cmd.loc});
}

std::vector<RadPrimitive> expandGensky(const RadCommand& cmd, const RadExpandContext& ctx) {
  const Args a(cmd, "gensky");
  if (a.size() == 2 && a[1] == "-defaults") a.fail("-defaults prints gensky's defaults, it writes no sky");
  if (a.size() < 4) a.fail("needs month day time, or -ang altitude azimuth, then options");
  SunRequest s;
  parseDateOrAngles(a, s);
  if (!s.fromAngles) parseGenskyTime(a, a[3], s);
  GenskyOptions o;
  parseGenskyOptions(a, s, o);
  placeSun(a, s);
  // Above the solar constant no horizontal irradiance occurs on Earth (gensky scales to it all
  // the same).
  if (o.zenith && o.zenithHorizontal && *o.zenith > 1367.0)
    warnSky(ctx, cmd, "gensky", "-B " + compactNumber(*o.zenith) +
                                    " W/m2 of diffuse horizontal irradiance is above the solar constant (1367 W/m2)");
  if (o.solar && o.solarHorizontal && *o.solar > 1367.0)
    warnSky(ctx, cmd, "gensky", "-R " + compactNumber(*o.solar) +
                                    " W/m2 of direct horizontal irradiance is above the solar constant (1367 W/m2)");

  const bool overcast = o.sky == GenskySky::kOvercast || o.sky == GenskySky::kUniform;
  double altitude = degToRad(s.altitudeDeg);
  const double azimuth = degToRad(s.azimuthDeg);
  // gensky.c: a sun within 3 degrees of the zenith is lowered to 87 degrees (sunny skies).
  if (!overcast && altitude > degToRad(87.0)) altitude = degToRad(87.0);
  const Vec3 sun = sunVector(altitude, azimuth);

  // Normalisation: horizontal irradiance of the sky = zenith radiance x normfactor x pi.
  double norm = 1.0, f2 = 0.0;
  switch (o.sky) {
    case GenskySky::kUniform: norm = 1.0; break;
    case GenskySky::kOvercast: norm = 0.777778; break;
    case GenskySky::kClear:
      f2 = clearF2(altitude);
      norm = normsc(false, altitude) / f2 / kPi;
      break;
    case GenskySky::kIntermediate:
      f2 = intermediateF2(altitude);
      norm = normsc(true, altitude) / f2 / kPi;
      break;
  }
  double zenith = 0.0;
  if (o.zenith && o.zenithHorizontal) {
    zenith = *o.zenith / (norm * kPi);
  } else if (o.zenith) {
    zenith = *o.zenith;
  } else {
    // Zenith luminance in kcd/m2: overcast 8.6 sin(alt) + 0.123; clear (1.376 T - 1.81) tan(alt)
    // + 0.38; intermediate the mean of both (gensky.c).
    zenith = overcast ? 8.6 * sun.z + .123 : (1.376 * o.turbidity - 1.81) * std::tan(altitude) + 0.38;
    if (o.sky == GenskySky::kIntermediate) zenith = (zenith + 8.6 * sun.z + .123) / 2.0;
    zenith = zenith < 0.0 ? 0.0 : zenith * 1000.0 / kSkyEfficacy;
  }
  double ground = zenith * norm;
  bool withSun = o.sun;
  double solar = 0.0;
  if (!overcast && sun.z > 0.0 && (!o.solar || *o.solar > 0.0)) {
    if (o.solar && o.solarHorizontal) {
      solar = *o.solar / (kGenskySunSr * sun.z);
    } else if (o.solar) {
      solar = *o.solar;
    } else {
      solar = 1.5e9 / kSunEfficacy * (1.147 - .147 / std::max(sun.z, .16));
      if (o.sky == GenskySky::kIntermediate) solar *= 0.15;
    }
    ground += 6e-5 / kPi * solar * sun.z;
  } else {
    withSun = false;
  }
  ground *= o.groundReflectance;

  std::vector<RadPrimitive> out;
  if (withSun) addSun(out, cmd.loc, solar, sun, 0.5);
  std::vector<double> args = {static_cast<double>(o.sky), zenith, ground};
  if (!overcast) args.insert(args.end(), {f2, sun.x, sun.y, sun.z});
  out.push_back(generatedPrimitive("void", "brightfunc", "skyfunc", cmd.loc, {"skybr", "skybright.cal"}, args));
  return out;
}

namespace {

// gendaylit's constants (src/gen/gendaylit.c): solar constant 1367 W/m2 and 127 500 lx, the sun's
// half angle 0.2665 degrees, the range Perez's parameters are held to.
constexpr double kSolarConstantWm2 = 1367.0;
constexpr double kSolarConstantLux = 127500.0;
constexpr double kHalfSunDeg = 0.2665;
constexpr double kClearnessMin = 1.0, kClearnessMax = 12.01;
constexpr double kBrightnessMin = 0.01, kBrightnessMax = 0.6;

// Thrown where gendaylit prints its "error sky" (all zeros) and stops.
struct ErrorSky {};

enum class DaylitInput { kNone, kPerez, kDirectNormal, kIlluminance, kDirectHorizontal, kGlobal };

// The state gendaylit's computation goes through, with its functions' rules: Perez's parameters
// are clamped to their range whenever its checks run, and efficacies are taken at the clamped
// values (gendaylit.c, check_parametrization and the efficacy models).
struct Daylit {
  double epsilon = 0, delta = 0;
  double diffuseWm2 = 0, directWm2 = 0, globalWm2 = 0, diffuseLux = 0, directLux = 0;
  double altitude = 0, zenithDeg = 0;
  int dayNumber = 0;
  double waterCm = 2.0;

  void clampParameters() {
    if (epsilon < kClearnessMin) epsilon = kClearnessMin;
    if (epsilon > kClearnessMax) epsilon = kClearnessMax - 0.001;
    if (delta < kBrightnessMin) delta = kBrightnessMin;
    if (delta > kBrightnessMax) delta = kBrightnessMax;
  }
  double eccentricity() const { return extraterrestrialNormalWm2(dayNumber) / kSolarConstantWm2; }
  // Kasten's (1966) relative air mass, as gendaylit.c uses it (the zenith held at 90 degrees).
  double airMass() {
    zenithDeg = std::min(zenithDeg, 90.0);
    return 1.0 / (std::cos(degToRad(zenithDeg)) + 0.15 * std::exp(std::log(93.885 - zenithDeg) * -1.253));
  }
  double z3() const {
    const double z = degToRad(zenithDeg);
    return 1.041 * z * z * z;
  }
  // Perez et al. (1990) brightness and clearness.
  double brightness() { return diffuseWm2 * airMass() / (kSolarConstantWm2 * eccentricity()); }
  double clearness() const { return ((diffuseWm2 + directWm2) / diffuseWm2 + z3()) / (1.0 + z3()); }
  double diffuseEfficacy() {
    clampParameters();
    if (epsilon >= kClearnessMax) throw ErrorSky{};
    return perezDiffuseEfficacy(perezClearnessBin(epsilon), waterCm, degToRad(zenithDeg), delta);
  }
  double directEfficacy() const {
    return std::max(0.0, perezDirectEfficacy(perezClearnessBin(epsilon), waterCm, degToRad(zenithDeg), delta));
  }
  void checkIrradiances() {
    diffuseWm2 = std::max(diffuseWm2, 0.0);
    directWm2 = std::max(directWm2, 0.0);
    if (directWm2 + diffuseWm2 == 0.0 && altitude > 0.0) throw ErrorSky{};
    if (directWm2 > kSolarConstantWm2) throw ErrorSky{};
  }
  void checkIlluminances() {
    diffuseLux = std::max(diffuseLux, 0.0);
    directLux = std::max(directLux, 0.0);
    if (directLux + diffuseLux == 0.0 && altitude > 0.0) throw ErrorSky{};
    if (directLux > kSolarConstantLux) throw ErrorSky{};
  }
  void illuminancesFromIrradiances() {
    diffuseLux = diffuseWm2 * diffuseEfficacy();
    directLux = directWm2 * directEfficacy();
    checkIlluminances();
  }
  // -L: irradiances from illuminances by gendaylit's fixed-point iteration (illu_to_irra_index):
  // its loop condition holds for any clamped parameters, so it always runs nine times.
  void irradiancesFromIlluminances() {
    diffuseWm2 = diffuseLux * kSolarConstantWm2 / kSolarConstantLux;
    directWm2 = directLux * kSolarConstantWm2 / kSolarConstantLux;
    epsilon = clearness();
    delta = brightness();
    clampParameters();
    for (int k = 0; k < 9; ++k) {
      diffuseWm2 = diffuseLux / diffuseEfficacy();
      const double de = directEfficacy();
      directWm2 = de < 0.1 ? 0.0 : directLux / de;
      delta = brightness();
      epsilon = clearness();
      clampParameters();
    }
  }
  // Relative Perez luminance at zenith angle dzeta and sun angle gamma (radians), gendaylit's
  // calc_rel_lum_perez: Delta raised to 0.2 for 1.065 < epsilon < 2.8.
  PerezCoefficients coefficients() const {
    const double dl = (epsilon > 1.065 && epsilon < 2.8 && delta < 0.2) ? 0.2 : delta;
    return perezCoefficients(perezClearnessBin(epsilon), degToRad(zenithDeg), dl);
  }
};

double perezValue(const PerezCoefficients& k, double dzeta, double gamma) {
  const double c = std::cos(gamma);
  return (1.0 + k.a * std::exp(k.b / std::cos(dzeta))) * (1.0 + k.c * std::exp(k.d * gamma) + k.e * c * c);
}

// gendaylit's normalisation integral (integ_lv): the 145 cells of Tregenza's subdivision (rows
// at zenith angles 84, 72, ..., 12, 0 degrees with 30, 30, 24, 24, 18, 12, 6, 1 cells, azimuth
// from the sun's), sum of L cos(theta) times 2 pi / 145.
double tregenzaIntegral(const PerezCoefficients& k, double sunZenithRad) {
  static const int kCount[8] = {30, 30, 24, 24, 18, 12, 6, 1};
  double sum = 0.0;
  for (int row = 0; row < 8; ++row) {
    const double theta = degToRad(84.0 - 12.0 * row);
    for (int c = 0; c < kCount[row]; ++c) {
      const double phi = degToRad(360.0 * c / kCount[row]);
      const double cg = std::cos(sunZenithRad) * std::cos(theta) + std::sin(sunZenithRad) * std::sin(theta) * std::cos(phi);
      const double gamma = cg > 1.0 ? 0.0 : std::acos(cg);
      sum += perezValue(k, theta, gamma) * std::cos(theta);
    }
  }
  return sum * (kTwoPi / 145.0);
}

struct DaylitOptions {
  DaylitInput input = DaylitInput::kNone;
  double first = 0.0, second = 0.0;  // the input option's values
  int output = 0;                    // -O: 0 visible W, 1 solar W, 2 lumen
  bool sun = true, cloudy = false;
  double groundReflectance = 0.2;
  double dewPointC = 10.97353115;    // gendaylit's default: W = exp(0.07 Td - 0.075) = 2 cm
};

void parseDaylitOptions(const Args& a, SunRequest& s, DaylitOptions& o) {
  for (size_t i = 4; i < a.size();) {
    const std::string& w = a[i];
    if (const size_t n = siteOption(a, i, s, false)) {
      i += n;
      continue;
    }
    auto input = [&](DaylitInput kind, int values, const char* what) {
      o.input = kind;
      o.first = a.number(i + 1, w + " (" + what + ")");
      if (values == 2) o.second = a.number(i + 2, w + " (" + what + ")");
      i += values;
    };
    if (w == "-P") {
      input(DaylitInput::kPerez, 2, "epsilon delta");
    } else if (w == "-W") {
      input(DaylitInput::kDirectNormal, 2, "direct normal and diffuse horizontal irradiance, W/m2");
    } else if (w == "-L") {
      input(DaylitInput::kIlluminance, 2, "direct normal and diffuse horizontal illuminance, lux");
    } else if (w == "-G") {
      input(DaylitInput::kDirectHorizontal, 2, "direct horizontal and diffuse horizontal irradiance, W/m2");
    } else if (w == "-E") {
      input(DaylitInput::kGlobal, 1, "global horizontal irradiance, W/m2");
    } else if (w == "-O") {
      const int v = a.integer(i + 1, "-O (output unit 0, 1 or 2)");
      if (v < 0 || v > 2) a.fail("-O needs 0 (visible W), 1 (solar W) or 2 (lumen), got '" + a[i + 1] + "'");
      // Luminances in cd/m2 would be read as radiances and multiplied by 179 lm/W once more.
      if (v == 2) a.fail("-O 2 writes luminances (cd/m2) where candela reads radiances (W/sr/m2); use -O 0");
      o.output = v;
      ++i;
    } else if (w == "+s" || w == "-s") {
      o.cloudy = false;
      o.sun = w[0] == '+';
    } else if (w == "-c" || w == "+c") {
      o.cloudy = true;
      o.sun = false;
    } else if (w == "-g") {
      o.groundReflectance = a.number(i + 1, "-g (ground reflectance)");
      if (o.groundReflectance < 0.0 || o.groundReflectance > 1.0) a.fail("-g ground reflectance must be within [0, 1]");
      ++i;
    } else if (w == "-d") {
      const double td = a.number(i + 1, "-d (dew point, degrees C)");
      if (td >= -40.0 && td <= 40.0) o.dewPointC = td;  // gendaylit keeps its default outside [-40, 40]
      ++i;
    } else if (w == "-t" || w == "-b" || w == "-R") {
      a.number(i + 1, w);  // read by gendaylit, used by none of its formulas
      ++i;
    } else if (w == "-w") {
      // gendaylit's warnings off: candela's expansion prints none
    } else if (w == "-C" || w == "-CIE" || w == "-l") {
      a.fail("'" + w + "' asks for a coloured sky (perezlum_c.cal), which candela does not implement");
    } else if (w == "-i") {
      a.fail("-i (the sun's position corrected within a time step at sunrise and sunset) is not implemented");
    } else {
      a.fail("unknown option '" + w + "' (gendaylit takes -P -W -L -G -E -O +s -s -c -g -d -a -o -m -y -w)");
    }
    ++i;
  }
  if (o.input == DaylitInput::kNone)
    a.fail("needs the sky's input: -P epsilon delta, -W, -L or -G direct diffuse, or -E global");
}

// gendaylit's inputs turned into Perez's parameters and the diffuse and direct components
// (gendaylit.c, computesky).
void resolveInputs(Daylit& d, const DaylitOptions& o) {
  switch (o.input) {
    case DaylitInput::kPerez:
      d.epsilon = o.first;
      d.delta = o.second;
      d.clampParameters();
      d.diffuseWm2 = d.delta / d.airMass() * (kSolarConstantWm2 * d.eccentricity());
      d.directWm2 = d.diffuseWm2 * ((d.epsilon - 1.0) * (1.0 + d.z3()));
      d.checkIrradiances();
      if (o.output != 1) d.illuminancesFromIrradiances();
      return;
    case DaylitInput::kIlluminance:
      d.directLux = o.first;
      d.diffuseLux = o.second;
      d.checkIlluminances();
      d.irradiancesFromIlluminances();
      d.clampParameters();
      return;
    case DaylitInput::kDirectNormal:
    case DaylitInput::kDirectHorizontal:
    case DaylitInput::kGlobal:
      break;
    case DaylitInput::kNone:
      return;
  }
  if (o.input == DaylitInput::kDirectNormal) {
    d.directWm2 = o.first;
    d.diffuseWm2 = o.second;
  } else if (d.altitude <= 0.0) {
    d.directWm2 = d.diffuseWm2 = 0.0;
  } else if (o.input == DaylitInput::kDirectHorizontal) {
    d.directWm2 = o.first / std::sin(d.altitude);
    d.diffuseWm2 = o.second;
  } else {
    // Erbs, Klein & Duffie (1982) diffuse fraction of the global irradiance by the clearness
    // index kt = G / (1367 E0 sin(alt)), G held below the extraterrestrial value.
    const double s0 = kSolarConstantWm2 * d.eccentricity() * std::sin(d.altitude);
    const double g = o.first > s0 ? 0.999 * s0 : o.first;
    const double kt = g / s0;
    if (kt <= 0.22)
      d.diffuseWm2 = g * (1.0 - 0.09 * kt);
    else if (kt <= 0.8)
      d.diffuseWm2 = g * (0.9511 - 0.1604 * kt + 4.388 * kt * kt - 16.638 * kt * kt * kt + 12.336 * kt * kt * kt * kt);
    else
      d.diffuseWm2 = g * 0.165;
    d.directWm2 = (g - d.diffuseWm2) / std::sin(d.altitude);
  }
  d.checkIrradiances();
  d.delta = d.brightness();
  d.epsilon = d.clearness();
  d.clampParameters();
  if (o.output != 1) d.illuminancesFromIrradiances();
}

std::vector<RadPrimitive> errorSky(const FileLoc& loc, const Vec3& sun) {
  return {generatedPrimitive("void", "brightfunc", "skyfunc", loc, {"skybright", "perezlum.cal"},
                    {0, 0, 0, 0, 0, 0, 0, sun.x, sun.y, sun.z})};
}

}  // namespace

std::vector<RadPrimitive> expandGendaylit(const RadCommand& cmd, const RadExpandContext& ctx) {
  const Args a(cmd, "gendaylit");
  if (a.size() == 2 && a[1] == "-defaults") a.fail("-defaults prints gendaylit's defaults, it writes no sky");
  if (a.size() < 4) a.fail("needs month day hour, or -ang altitude azimuth, then -P, -W, -L, -G or -E");
  SunRequest s;
  parseDateOrAngles(a, s);
  if (!s.fromAngles) {
    // gendaylit reads the hour as a decimal number (atof), '+' for solar time.
    const std::string& h = a[3];
    s.solarTime = !h.empty() && h[0] == '+';
    s.hour = a.number(3, "the hour");
    if (s.hour < 0.0 || s.hour >= 24.0) a.fail("bad hour '" + h + "' (0 to 24, decimal)");
  }
  DaylitOptions o;
  parseDaylitOptions(a, s, o);
  placeSun(a, s);
  // gendaylit reads negative irradiances and illuminances as 0: said so.
  if (o.input != DaylitInput::kPerez && (o.first < 0.0 || o.second < 0.0))
    warnSky(ctx, cmd, "gendaylit", "a negative irradiance or illuminance (" + compactNumber(std::min(o.first, o.second)) +
                                       ") is read as 0");

  Daylit d;
  d.waterCm = std::exp(0.07 * o.dewPointC - 0.075);
  d.altitude = degToRad(s.altitudeDeg);
  const double azimuth = degToRad(s.azimuthDeg);
  // gendaylit prints the error sky (all zeros) for a sun below the horizon at the given time;
  // candela does so for -ang too (where gendaylit's formulas would divide by zero).
  if (d.altitude <= 0.0) return errorSky(cmd.loc, sunVector(d.altitude, azimuth));
  if (!s.fromAngles) d.dayNumber = radianceDayOfYear(s.month, s.day);
  if (!o.cloudy && d.altitude > degToRad(87.0)) d.altitude = degToRad(87.0);
  const Vec3 sun = sunVector(d.altitude, azimuth);
  d.zenithDeg = 90.0 - radToDeg(d.altitude);
  try {
    resolveInputs(d, o);
    const PerezCoefficients k = d.coefficients();
    const double zenithRad = degToRad(d.zenithDeg);
    const double integral = tregenzaIntegral(k, zenithRad);
    const double sunSr = kTwoPi * (1.0 - std::cos(degToRad(kHalfSunDeg)));
    double diffNorm = 0.0, solar = 0.0;
    if (o.output == 0) {
      diffNorm = d.diffuseLux / integral / kLumensPerWatt;
      solar = d.directLux / sunSr / kLumensPerWatt;
    } else if (o.output == 1) {
      diffNorm = d.diffuseWm2 / integral;
      solar = d.directWm2 / sunSr;
    } else {
      diffNorm = d.diffuseLux / integral;
      solar = d.directLux / sunSr;
    }
    // Ground: zenith radiance times gensky's normalisation for a sky of that clearness, plus the
    // sun's share (gendaylit.c).
    const double zenith = perezValue(k, 0.0, zenithRad) * diffNorm;
    double norm = 0.777778;
    if (d.epsilon >= 6.0) norm = normsc(false, d.altitude) / clearF2(d.altitude) / kPi;
    if (d.epsilon > 1.0 && d.epsilon < 6.0) norm = normsc(true, d.altitude) / intermediateF2(d.altitude) / kPi;
    double ground = zenith * norm;
    if (o.sun && d.epsilon > 1.0) ground += 6.8e-5 / kPi * solar * sun.z;
    ground *= o.groundReflectance;
    if (k.b > 0.0) throw ErrorSky{};  // gendaylit: a positive Perez b gives the error sky

    std::vector<RadPrimitive> out;
    if (o.sun) addSun(out, cmd.loc, d.epsilon > 1.0 ? solar : 0.0, sun, 2.0 * kHalfSunDeg);
    out.push_back(generatedPrimitive("void", "brightfunc", "skyfunc", cmd.loc, {"skybright", "perezlum.cal"},
                            {diffNorm, ground, k.a, k.b, k.c, k.d, k.e, sun.x, sun.y, sun.z}));
    return out;
  } catch (const ErrorSky&) {
    // gendaylit's error sky (no light), which it writes with a warning on stderr.
    warnSky(ctx, cmd, "gendaylit", "these inputs make no sky (a direct component above the solar constant, 1367 W/m2 "
                                   "or 127 500 lx, an impossible clearness, or no light with the sun up): the sky is "
                                   "dark, as gendaylit's error sky");
    return errorSky(cmd.loc, sun);
  }
}

}  // namespace candela
