// [[compliance]] entries of the case file (study/compliance/compliance_spec.h, docs/compliance.md).
#include "study/case/case_compliance.h"

#include "photometry/site.h"
#include "study/case/case_toml.h"
#include "study/compliance/en12464_2_case.h"

#include <cstdio>
#include <set>

namespace candela {

using namespace case_toml;

std::vector<CivilDate> leedOption2Dates(const ComplianceSpec& s, int weatherYear) {
  if (!s.leedDates.empty()) return s.leedDates;
  return {{weatherYear, 3, 21}, {weatherYear, 9, 21}};
}

std::string_view standardKey(ComplianceStandard s) {
  switch (s) {
    case ComplianceStandard::kLeedV41Option1: return "leed-v4.1-option1";
    case ComplianceStandard::kLeedV41Option2: return "leed-v4.1-option2";
    case ComplianceStandard::kEn1838: return "en1838";
    case ComplianceStandard::kEn13201: return "en13201";
    case ComplianceStandard::kEn12464_2: return "en12464-2";
    case ComplianceStandard::kEn17037: break;
  }
  return "en17037";
}

int dayOfYear(const CivilDate& d) {
  LocalTime t;
  t.year = d.year, t.month = d.month, t.day = d.day;
  return t.dayOfYear();
}

namespace {

// A calendar date: a TOML local date (2026-03-21) or a text "YYYY-MM-DD".
CivilDate asDate(const Context& c, const toml::node& n, std::string_view key) {
  CivilDate d;
  if (auto v = n.as_date()) {
    d = {v->get().year, v->get().month, v->get().day};
  } else {
    const std::string s = asString(c, n, key);
    int used = 0;
    if (std::sscanf(s.c_str(), "%4d-%2d-%2d%n", &d.year, &d.month, &d.day, &used) != 3 ||
        static_cast<std::size_t>(used) != s.size())
      c.fail(n, keyText(key) + " must be a date YYYY-MM-DD, got '" + s + "'");
  }
  if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > daysInMonth(d.year, d.month))
    c.fail(n, keyText(key) + " is not a date of the calendar");
  return d;
}

std::vector<Vec3> asPoints3(const Context& c, const toml::node& n, std::string_view key) {
  const toml::array& a = asArray(c, n, key, 0, "an array of points [x, y, z]");
  if (a.empty()) c.fail(n, keyText(key) + " needs at least one point [x, y, z]");
  std::vector<Vec3> out;
  for (const toml::node& p : a) out.push_back(asVec3(c, p, key));
  return out;
}

ComplianceStandard asStandard(const Context& c, const toml::node& n) {
  const std::string s = asString(c, n, "standard");
  for (ComplianceStandard k : {ComplianceStandard::kEn17037, ComplianceStandard::kLeedV41Option1,
                               ComplianceStandard::kLeedV41Option2, ComplianceStandard::kEn1838,
                               ComplianceStandard::kEn13201, ComplianceStandard::kEn12464_2})
    if (s == standardKey(k)) return k;
  c.fail(n, "unknown standard '" + s + "' (expected en17037, leed-v4.1-option1, leed-v4.1-option2, en1838, en13201 "
            "or en12464-2)");
}

// A key that belongs to another standard is an error at its line, not ignored.
const toml::node* keyOf(Table& tab, std::string_view key, const ComplianceSpec& s, ComplianceStandard only) {
  const toml::node* n = tab.get(key);
  if (n && s.standard != only)
    tab.ctx().fail(*n, keyText(key) + " belongs to standard = \"" + std::string(standardKey(only)) + "\", not \"" +
                           std::string(standardKey(s.standard)) + "\"");
  return n;
}

void readEn17037(Table& tab, ComplianceSpec& s) {
  const Context& c = tab.ctx();
  const auto en = ComplianceStandard::kEn17037;
  if (const toml::node* n = keyOf(tab, "aggregation", s, en)) {
    const std::string v = asString(c, *n, "aggregation");
    if (v == "hour-first") s.aggregation = ProvisionAggregation::kHourFirst;
    else if (v == "sensor-first") s.aggregation = ProvisionAggregation::kSensorFirst;
    else c.fail(*n, "'aggregation' must be \"hour-first\" or \"sensor-first\", got '" + v + "'");
  }
  if (const toml::node* n = keyOf(tab, "sunlight_date", s, en)) {
    s.sunlightDate = asDate(c, *n, "sunlight_date");
    s.sunlightDateLoc = c.at(*n);
    if (!inSunlightDateRange(*s.sunlightDate))
      c.fail(*n, "'sunlight_date' must lie between 1 February and 21 March (EN 17037 A.4)");
  }
  if (const toml::node* n = keyOf(tab, "sunlight_points", s, en)) {
    s.sunlightPoints = asPoints3(c, *n, "sunlight_points");
    s.sunlightLoc = c.at(*n);
  }
  if (const toml::node* n = keyOf(tab, "sunlight_min_altitude", s, en)) {
    s.sunlightMinAltitudeDeg = asNumber(c, *n, "sunlight_min_altitude");
    checkRange(tab, "sunlight_min_altitude", *s.sunlightMinAltitudeDeg, 0.0, 90.0, " deg");
  }
  if (const toml::node* n = keyOf(tab, "view_points", s, en)) {
    s.viewPoints = asPoints3(c, *n, "view_points");
    s.viewLoc = c.at(*n);
  }
  if (const toml::node* n = keyOf(tab, "glare_views", s, en)) {
    for (const toml::table* t : asTableList(c, *n, "glare_views", "{ position = [x, y, z], direction = [dx, dy, dz] }")) {
      const toml::node& v = *t;
      Table vt(*t, c, "a glare view");
      GlareViewSpec g;
      g.loc = c.at(v);
      g.positionM = asVec3(c, vt.require("position"), "position");
      g.direction = asDirection(c, vt.require("direction"), "direction");
      if (const toml::node* h = vt.get("check_hours")) {
        const toml::array& hours = asArray(c, *h, "check_hours", 0, "an array of times \"YYYY-MM-DDTHH:MM\"");
        for (const toml::node& x : hours) {
          g.checkHours.push_back(asString(c, x, "check_hours"));
          parseLocalTime(g.checkHours.back(), c.at(x));  // the form is checked now, the weather hour before tracing
        }
        g.checkLoc = c.at(*h);
      }
      if (const toml::node* r = vt.get("check_resolution")) {
        const int64_t px = asInteger(c, *r, "check_resolution");
        if (px < 16 || px > 4096) c.fail(*r, "'check_resolution' must lie in 16 .. 4096 pixels");
        g.checkResolutionPx = static_cast<int>(px);
      }
      vt.finish();
      s.glareViews.push_back(g);
    }
  }
  if (const toml::node* n = keyOf(tab, "glare_exceedance", s, en)) {
    s.glareExceedance = asNumber(c, *n, "glare_exceedance");
    if (!(s.glareExceedance > 0.0 && s.glareExceedance < 1.0)) c.fail(*n, "'glare_exceedance' must lie in (0, 1)");
  }
}

void readLeedOption2(Table& tab, ComplianceSpec& s) {
  const Context& c = tab.ctx();
  const auto opt2 = ComplianceStandard::kLeedV41Option2;
  if (const toml::node* n = keyOf(tab, "dates", s, opt2)) {
    const toml::array& a = asArray(c, *n, "dates", 0, "an array of dates \"YYYY-MM-DD\"");
    if (a.empty()) c.fail(*n, "'dates' needs at least one date");
    for (const toml::node& d : a) {
      const CivilDate date = asDate(c, d, "dates");
      // LEED v4 EQ Daylight option 2: a clear-sky day within 15 days of 21 March or 21 September.
      const int doy = dayOfYear(date);
      const int march = dayOfYear({date.year, 3, 21}), september = dayOfYear({date.year, 9, 21});
      if (std::abs(doy - march) > 15 && std::abs(doy - september) > 15)
        c.fail(d, "each of 'dates' must lie within 15 days of 21 March or 21 September");
      s.leedDates.push_back(date);
    }
    s.leedDatesLoc = c.at(*n);
  }
  if (const toml::node* n = keyOf(tab, "hours", s, opt2)) {
    const toml::array& a = asArray(c, *n, "hours", 0, "an array of hours of the day (local standard time)");
    if (a.empty()) c.fail(*n, "'hours' needs at least one hour");
    s.leedHours.clear();
    for (const toml::node& h : a) {
      const double v = asNumber(c, h, "hours");
      if (!(v > 0.0 && v < 24.0)) c.fail(h, "each of 'hours' must lie between 0 and 24");
      s.leedHours.push_back(v);
    }
  }
}

}  // namespace

void readCompliance(const Context& c, const toml::table& t, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[compliance]]");
  ComplianceSpec s;
  s.loc = tab.loc();
  s.standard = asStandard(c, tab.require("standard"));
  s.name = std::string(standardKey(s.standard));
  if (const toml::node* n = tab.get("name")) s.name = asString(c, *n, "name");
  if (s.name.empty()) c.fail(*tab.get("name"), "'name' must not be empty");
  if (!names.insert(s.name).second)
    throw InputError(s.loc, "two [[compliance]] entries are named '" + s.name + "' (give each a 'name')");
  if (const toml::node* n = tab.get("spaces")) {
    s.spacesLoc = c.at(*n);
    if (s.standard == ComplianceStandard::kEn1838)
      c.fail(*n, "'spaces' is for the daylight standards; en1838 checks [[escape_route]], [[open_area]], "
                 "[[safety_point]] and high-risk task areas");
    if (s.standard == ComplianceStandard::kEn13201)
      c.fail(*n, "'spaces' is for the daylight standards; en13201 checks the [[road]] tables");
    if (s.standard == ComplianceStandard::kEn12464_2)
      c.fail(*n, "'spaces' is for the daylight standards; en12464-2 checks the [[task_area]]s with standard = \"en12464-2\"");
    const toml::array& a = asArray(c, *n, "spaces", 0, "an array of grid names");
    if (a.empty()) c.fail(*n, "'spaces' needs at least one grid name");
    for (const toml::node& g : a) {
      std::string name = asString(c, g, "spaces");
      bool known = false;
      for (const GridSpec& grid : out.grids) known = known || grid.name == name;
      if (!known) c.fail(g, "'spaces' names '" + name + "', which is no grid of the case");
      s.spaces.push_back(std::move(name));
    }
  } else {
    s.spacesLoc = s.loc;
  }
  readEn17037(tab, s);
  readLeedOption2(tab, s);
  if (const toml::node* n = keyOf(tab, "maintenance_factor", s, ComplianceStandard::kEn1838)) {
    s.emergencyMaintenanceFactor = asNumber(c, *n, "maintenance_factor");
    if (!(s.emergencyMaintenanceFactor > 0.0 && s.emergencyMaintenanceFactor <= 1.0))
      c.fail(*n, "'maintenance_factor' must be in (0, 1]");
  }
  if (const toml::node* n = keyOf(tab, "leave_out", s, ComplianceStandard::kEn1838)) {
    s.emergencyLeaveOutLoc = c.at(*n);
    const toml::array& patterns = asArray(c, *n, "leave_out", 0, "an array of surface identifiers or patterns");
    if (patterns.empty()) c.fail(*n, "'leave_out' must name at least one surface (an identifier or a pattern such as \"desk_*\")");
    for (const toml::node& p : patterns) {
      s.emergencyLeaveOut.push_back(asString(c, p, "leave_out"));
      if (s.emergencyLeaveOut.back().empty()) c.fail(p, "'leave_out' holds an empty identifier");
    }
  }
  readObtrusiveLight(tab, s);
  tab.finish();
  out.compliance.push_back(std::move(s));
}

}  // namespace candela
