#include "photometry/site.h"

#include <GeographicLib/DMS.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace candela {

namespace {

double parseAngle(const std::string& text, const FileLoc& loc, bool latitude) {
  const char* what = latitude ? "latitude" : "longitude";
  double value = 0.0;
  GeographicLib::DMS::flag ind = GeographicLib::DMS::NONE;
  try {
    value = GeographicLib::DMS::Decode(text, ind);
  } catch (const std::exception& e) {
    throw InputError(loc, std::string("bad ") + what + " '" + text + "': " + e.what());
  }
  if (!std::isfinite(value)) throw InputError(loc, std::string("bad ") + what + " '" + text + "'");
  if (latitude && ind == GeographicLib::DMS::LONGITUDE)
    throw InputError(loc, "latitude '" + text + "' has an E/W hemisphere designator");
  if (!latitude && ind == GeographicLib::DMS::LATITUDE)
    throw InputError(loc, "longitude '" + text + "' has an N/S hemisphere designator");
  const double limit = latitude ? 90.0 : 180.0;
  if (std::abs(value) > limit)
    throw InputError(loc, std::string(what) + " '" + text + "' is outside [-" +
                              std::to_string(int(limit)) + ", " + std::to_string(int(limit)) + "] degrees");
  return value;
}

double wrap360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r -= 360.0;
  return r;
}

}  // namespace

double parseLatitudeDeg(const std::string& text, const FileLoc& loc) { return parseAngle(text, loc, true); }
double parseLongitudeDeg(const std::string& text, const FileLoc& loc) { return parseAngle(text, loc, false); }

double utmConvergenceDeg(double latitudeDeg, double longitudeDeg) {
  int zone = 0;
  bool northp = true;
  double x = 0.0, y = 0.0, gamma = 0.0, k = 1.0;
  GeographicLib::UTMUPS::Forward(latitudeDeg, longitudeDeg, zone, northp, x, y, gamma, k);
  return gamma;
}

Site makeSite(double latitudeDeg, double longitudeDeg, double elevationM, double timezoneHours,
              double northDeg, const std::string& grid, const FileLoc& loc) {
  if (!(std::abs(latitudeDeg) <= 90.0)) throw InputError(loc, "latitude must be in [-90, 90] degrees");
  if (!(std::abs(longitudeDeg) <= 180.0)) throw InputError(loc, "longitude must be in [-180, 180] degrees");
  if (!(std::abs(timezoneHours) <= 18.0)) throw InputError(loc, "timezone must be in [-18, 18] hours");
  if (!std::isfinite(elevationM) || !std::isfinite(northDeg)) throw InputError(loc, "elevation and north must be finite");
  Site s;
  s.latitudeDeg = latitudeDeg;
  s.longitudeDeg = longitudeDeg;
  s.elevationM = elevationM;
  s.timezoneHours = timezoneHours;
  s.northDeg = northDeg;
  s.grid = grid;
  if (grid == "utm") {
    s.meridianConvergenceDeg = utmConvergenceDeg(latitudeDeg, longitudeDeg);
  } else if (!grid.empty()) {
    throw InputError(loc, "unknown grid '" + grid + "' (expected \"utm\")");
  }
  return s;
}

Vec3 directionFromAzAlt(double azimuthDeg, double altitudeDeg, double northDeg) {
  // A true azimuth A appears in the model at A + north clockwise from model +Y.
  const double az = degToRad(azimuthDeg + northDeg);
  const double alt = degToRad(altitudeDeg);
  return Vec3(std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt));
}

AzAlt azAltFromDirection(const Vec3& dirModel, double northDeg) {
  const Vec3 d = glm::normalize(dirModel);
  AzAlt r;
  r.altitudeDeg = radToDeg(std::asin(std::clamp(d.z, -1.0, 1.0)));
  const double horiz = std::hypot(d.x, d.y);
  r.azimuthDeg = horiz > 1e-15 ? wrap360(radToDeg(std::atan2(d.x, d.y)) - northDeg) : 0.0;
  return r;
}

Vec3 trueToModel(const Vec3& d, double northDeg) {
  // Clockwise rotation (seen from +Z) by north: azimuth grows by northDeg.
  const double a = degToRad(northDeg);
  const double c = std::cos(a), s = std::sin(a);
  return Vec3(c * d.x + s * d.y, -s * d.x + c * d.y, d.z);
}

Vec3 modelToTrue(const Vec3& d, double northDeg) { return trueToModel(d, -northDeg); }

bool isLeapYear(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int daysInMonth(int year, int month) {
  static const int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) return 0;
  return kDays[month - 1] + (month == 2 && isLeapYear(year) ? 1 : 0);
}

int LocalTime::dayOfYear() const {
  int n = day;
  for (int m = 1; m < month; ++m) n += daysInMonth(year, m);
  return n;
}

namespace {

// Reads exactly `digits` decimal digits at text[pos], advancing pos; -1 on failure.
int readDigits(const std::string& t, size_t& pos, int digits) {
  int v = 0;
  for (int i = 0; i < digits; ++i) {
    if (pos >= t.size() || !std::isdigit(static_cast<unsigned char>(t[pos]))) return -1;
    v = v * 10 + (t[pos++] - '0');
  }
  return v;
}

bool expect(const std::string& t, size_t& pos, char c) {
  if (pos < t.size() && t[pos] == c) {
    ++pos;
    return true;
  }
  return false;
}

}  // namespace

LocalTime parseLocalTime(const std::string& text, const FileLoc& loc) {
  const auto bad = [&](const std::string& why) {
    return InputError(loc, "bad time '" + text + "' (expected YYYY-MM-DDTHH:MM[:SS][+HH:MM]): " + why);
  };
  LocalTime t;
  size_t p = 0;
  t.year = readDigits(text, p, 4);
  if (t.year < 0 || !expect(text, p, '-')) throw bad("year");
  t.month = readDigits(text, p, 2);
  if (t.month < 1 || t.month > 12 || !expect(text, p, '-')) throw bad("month");
  t.day = readDigits(text, p, 2);
  if (t.day < 1 || t.day > daysInMonth(t.year, t.month)) throw bad("day");
  if (!expect(text, p, 'T') && !expect(text, p, ' ')) throw bad("missing 'T' before the time");
  t.hour = readDigits(text, p, 2);
  if (t.hour < 0 || t.hour > 24 || !expect(text, p, ':')) throw bad("hour");
  t.minute = readDigits(text, p, 2);
  if (t.minute < 0 || t.minute > 59) throw bad("minute");
  if (expect(text, p, ':')) {
    const int s = readDigits(text, p, 2);
    if (s < 0 || s > 59) throw bad("second");
    t.second = s;
    if (expect(text, p, '.')) {
      double scale = 0.1;
      size_t start = p;
      while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) {
        t.second += scale * (text[p++] - '0');
        scale *= 0.1;
      }
      if (p == start) throw bad("fraction of a second");
    }
  }
  if (t.hour == 24 && (t.minute != 0 || t.second != 0.0)) throw bad("24:00 is the only time in hour 24");
  if (p < text.size()) {
    if (text[p] == 'Z' && p + 1 == text.size()) {
      t.utcOffsetHours = 0.0;
      ++p;
    } else if (text[p] == '+' || text[p] == '-') {
      const double sign = text[p++] == '-' ? -1.0 : 1.0;
      const int oh = readDigits(text, p, 2);
      int om = 0;
      if (oh < 0 || oh > 18) throw bad("offset hours");
      if (expect(text, p, ':') || (p < text.size())) {
        om = readDigits(text, p, 2);
        if (om < 0 || om > 59) throw bad("offset minutes");
      }
      t.utcOffsetHours = sign * (oh + om / 60.0);
    }
    if (p != text.size()) throw bad("unexpected '" + text.substr(p) + "'");
  }
  return t;
}

}  // namespace candela
