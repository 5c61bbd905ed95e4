#include "photometry/epw.h"

#include "photometry/site.h"
#include "base/input_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <limits>

namespace candela {

namespace {

constexpr int kHeaderLines = 8;
constexpr int kRecordFields = 35;

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

double number(const std::string& raw, const FileLoc& loc, const char* what) {
  const std::string s = trim(raw);
  double v = 0.0;
  const char* first = s.data();
  if (!s.empty() && s[0] == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
    throw InputError(loc, std::string("bad number '") + s + "' for " + what);
  return v;
}

int integer(const std::string& raw, const FileLoc& loc, const char* what, int lo, int hi) {
  const double v = number(raw, loc, what);
  if (v != std::floor(v) || v < lo || v > hi)
    throw InputError(loc, std::string(what) + " " + trim(raw) + " is outside " + std::to_string(lo) + ".." +
                              std::to_string(hi));
  return int(v);
}

// Whether record b is the hour right after record a (EPW hours are hour-ending, 1..24). Typical
// years mix source years, so February may or may not have a 29th; the year may wrap at New Year.
bool nextHour(const EpwRecord& a, const EpwRecord& b) {
  if (a.hour < 24) return b.month == a.month && b.day == a.day && b.hour == a.hour + 1;
  if (b.hour != 1) return false;
  if (b.month == a.month) return b.day == a.day + 1;
  const bool monthEnds = a.day == daysInMonth(2000, a.month) || (a.month == 2 && a.day == 28);
  return monthEnds && b.day == 1 && b.month == a.month % 12 + 1;
}

std::string stamp(const EpwRecord& r) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%02d-%02d hour %d", r.month, r.day, r.hour);
  return buf;
}

double orMissing(double v, double missingAtOrAbove) {
  return v >= missingAtOrAbove ? std::numeric_limits<double>::quiet_NaN() : v;
}

// A radiation or illuminance field: the data dictionary's missing marks (9999 and above for
// radiation, 999900 for illuminance), an empty field, or -999 and below (Meteonorm and other
// exporters) are missing (NaN); any other negative value is refused.
double measured(const std::string& raw, const FileLoc& loc, const char* what, double missingAtOrAbove) {
  if (trim(raw).empty()) return std::numeric_limits<double>::quiet_NaN();
  const double v = number(raw, loc, what);
  if (v <= -999.0) return std::numeric_limits<double>::quiet_NaN();
  return orMissing(v, missingAtOrAbove);
}

}  // namespace

EpwFile parseEpw(std::istream& in, const std::string& fileName) {
  EpwFile f;
  std::string line;
  int lineNo = 0;
  for (int h = 0; h < kHeaderLines; ++h) {
    if (!std::getline(in, line)) throw InputError(FileLoc{fileName, lineNo, 0}, "EPW header ends early (8 lines expected)");
    ++lineNo;
    const FileLoc loc{fileName, lineNo, 0};
    if (h == 0) {
      const auto fields = splitCsv(line);
      if (fields.empty() || trim(fields[0]) != "LOCATION")
        throw InputError(loc, "EPW must start with a LOCATION line");
      if (fields.size() < 10) throw InputError(loc, "LOCATION needs 10 fields, got " + std::to_string(fields.size()));
      EpwLocation& l = f.location;
      l.city = trim(fields[1]);
      l.region = trim(fields[2]);
      l.country = trim(fields[3]);
      l.source = trim(fields[4]);
      l.wmo = trim(fields[5]);
      l.latitudeDeg = number(fields[6], loc, "latitude");
      l.longitudeDeg = number(fields[7], loc, "longitude");
      l.timezoneHours = number(fields[8], loc, "time zone");
      l.elevationM = number(fields[9], loc, "elevation");
      if (std::abs(l.latitudeDeg) > 90.0) throw InputError(loc, "latitude outside [-90, 90]");
      if (std::abs(l.longitudeDeg) > 180.0) throw InputError(loc, "longitude outside [-180, 180]");
      if (std::abs(l.timezoneHours) > 18.0) throw InputError(loc, "time zone outside [-18, 18] h");
    }
  }
  while (std::getline(in, line)) {
    ++lineNo;
    if (trim(line).empty()) continue;
    const FileLoc loc{fileName, lineNo, 0};
    const auto v = splitCsv(line);
    if (v.size() < size_t(kRecordFields))
      throw InputError(loc, "EPW record has " + std::to_string(v.size()) + " fields, expected " +
                                std::to_string(kRecordFields));
    EpwRecord r;
    r.line = lineNo;
    r.year = integer(v[0], loc, "year", -9999, 9999);
    r.month = integer(v[1], loc, "month", 1, 12);
    r.day = integer(v[2], loc, "day", 1, 31);
    if (r.day > daysInMonth(2000, r.month))  // typical years mix source years: allow Feb 29
      throw InputError(loc, "day " + std::to_string(r.day) + " does not exist in month " + std::to_string(r.month));
    r.hour = integer(v[3], loc, "hour", 1, 24);
    r.minute = integer(v[4], loc, "minute", 0, 60);
    // Field indices from the EPW data dictionary (0-based): 6 dry bulb, 7 dew point,
    // 13 global horizontal, 14 direct normal, 15 diffuse horizontal radiation,
    // 16 global horizontal, 17 direct normal, 18 diffuse horizontal illuminance.
    r.dryBulbC = orMissing(number(v[6], loc, "dry bulb temperature"), 99.9);
    r.dewPointC = orMissing(number(v[7], loc, "dew point temperature"), 99.9);
    r.globalHorizontalWhm2 = measured(v[13], loc, "global horizontal radiation", 9999.0);
    r.directNormalWhm2 = measured(v[14], loc, "direct normal radiation", 9999.0);
    r.diffuseHorizontalWhm2 = measured(v[15], loc, "diffuse horizontal radiation", 9999.0);
    r.globalHorizontalLux = measured(v[16], loc, "global horizontal illuminance", 999900.0);
    r.directNormalLux = measured(v[17], loc, "direct normal illuminance", 999900.0);
    r.diffuseHorizontalLux = measured(v[18], loc, "diffuse horizontal illuminance", 999900.0);
    for (double x : {r.globalHorizontalWhm2, r.directNormalWhm2, r.diffuseHorizontalWhm2})
      if (x < 0.0) throw InputError(loc, "negative irradiation");
    if (std::isnan(r.directNormalWhm2) || std::isnan(r.diffuseHorizontalWhm2)) ++f.missingIrradianceHours;
    // Records run hour by hour: a repeat (8760 copies of one hour pass for a year) or a gap would
    // put the weather at the wrong sun.
    if (!f.records.empty() && !nextHour(f.records.back(), r)) {
      const EpwRecord& prev = f.records.back();
      const bool repeat = prev.month == r.month && prev.day == r.day && prev.hour == r.hour;
      throw InputError(loc, "record " + stamp(r) + " follows " + stamp(prev) +
                                (repeat ? ": the hour is repeated" : ": hours are missing or out of order") +
                                "; EPW records run hour by hour");
    }
    f.records.push_back(r);
  }
  if (f.records.empty()) throw InputError(FileLoc{fileName, lineNo, 0}, "EPW file has no hourly records");
  return f;
}

EpwFile readEpw(const std::string& path) {
  std::istringstream in(readInputFile(path, "EPW file"));
  return parseEpw(in, path);
}

}  // namespace candela
