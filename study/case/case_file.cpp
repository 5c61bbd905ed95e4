#include "study/case/case_file.h"

#include "base/input_file.h"
#include "base/units.h"
#include "engine/portals.h"
#include "study/case/case_compliance.h"
#include "study/compliance/en13201_case.h"
#include "study/compliance/en12464_2_case.h"
#include "study/compliance/en1838_case.h"
#include "study/case/case_grids.h"
#include "study/case/case_window_groups.h"
#include "study/case/honeybee_folder.h"
#include "study/case/case_toml.h"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace candela {

namespace fs = std::filesystem;

namespace {

using namespace case_toml;

void readCase(const Context& c, const toml::table& t, CaseFile& out) {
  Table tab(t, c, "[case]");
  if (auto n = tab.get("name")) out.name = asString(c, *n, "name");
  if (auto n = tab.get("description")) out.description = asString(c, *n, "description");
  if (tab.get("floor_area")) {
    out.floorAreaM2 = numberOr(tab, "floor_area", 0.0);
    checkMin(tab, "floor_area", *out.floorAreaM2, 0.0, true, " m²");
  }
  if (auto n = tab.get("reference_grid")) {
    out.referenceGrid = asString(c, *n, "reference_grid");
    out.referenceGridLoc = c.at(*n);
    if (out.referenceGrid.empty()) c.fail(*n, "'reference_grid' must not be empty");
  }
  tab.finish();
}

void readScene(const Context& c, const toml::table& t, CaseFile& out) {
  Table tab(t, c, "[[scene]]");
  if (const toml::node* hb = tab.get("honeybee_folder")) {  // study/case/honeybee_folder.h
    if (const toml::node* f = tab.get("file")) c.fail(*f, "a [[scene]] gives either 'file' or 'honeybee_folder'");
    const std::string text = asString(c, *hb, "honeybee_folder");
    fs::path folder = fs::path(text).is_relative() ? c.dir / text : fs::path(text);
    std::error_code ec;
    if (text.empty() || !fs::is_directory(folder, ec))
      c.fail(*hb, "Honeybee folder '" + text + "' not found (looked for " + folder.lexically_normal().string() + ")");
    tab.finish();
    readHoneybeeFolder(folder.lexically_normal(), c.at(*hb), out);
    return;
  }
  ScenePath s;
  s.loc = c.at(tab.require("file"));
  s.file = filePath(tab, "file", "scene file");
  tab.finish();
  out.scenes.push_back(std::move(s));
}

// [[portal]]: an opening without glazing, as a planar polygon of [x, y, z] vertices (m); it only
// guides sky sampling (docs/daylight.md#portals).
void readPortal(const Context& c, const toml::table& t, int index, CaseFile& out) {
  Table tab(t, c, "[[portal]]");
  Portal p;
  p.loc = tab.loc();
  p.name = "portal" + std::to_string(index + 1);
  if (auto n = tab.get("name")) p.name = asString(c, *n, "name");
  const toml::node& on = tab.require("outline");
  const toml::array& a = asArray(c, on, "outline", 0, "an array of [x, y, z] vertices");
  std::vector<const toml::node*> nodes;
  for (const toml::node& e : a) {
    p.outline.push_back(asVec3(c, e, "outline"));
    nodes.push_back(&e);
  }
  size_t bad = 0;
  const std::string why = portalOutlineProblem(p.outline, &bad);
  if (!why.empty()) c.fail(bad < nodes.size() ? *nodes[bad] : on, why);
  tab.finish();
  out.portals.push_back(std::move(p));
}

void readLuminaire(const Context& c, const toml::table& t, int entry, CaseFile& out) {
  Table tab(t, c, "[[luminaire]]");
  LuminairePlacement p;
  p.entry = entry;
  p.loc = tab.loc();
  p.file = filePath(tab, "file", "luminaire file");
  p.name = "luminaire" + std::to_string(entry + 1);
  if (auto n = tab.get("name")) p.name = asString(c, *n, "name");
  p.positionM = asVec3(c, tab.require("position"), "position");
  if (auto n = tab.get("aim")) p.aim = asDirection(c, *n, "aim");
  p.spinDeg = numberOr(tab, "spin", 0.0);
  p.multiplier = numberOr(tab, "multiplier", 1.0);
  checkMin(tab, "multiplier", p.multiplier, 0.0, false, "");
  p.maintenanceFactor = numberOr(tab, "maintenance_factor", 1.0);
  if (tab.get("maintenance_factor")) {
    if (!(p.maintenanceFactor > 0.0 && p.maintenanceFactor <= 1.0))
      c.fail(*tab.get("maintenance_factor"), "'maintenance_factor' must be in (0, 1], got " +
                                                 compactNumber(p.maintenanceFactor));
  }
  if (tab.get("opening_reflectance")) {
    p.openingReflectance = numberOr(tab, "opening_reflectance", 0.0);
    checkRange(tab, "opening_reflectance", *p.openingReflectance, 0.0, 1.0, " (a diffuse reflectance)");
  }
  if (tab.get("power_w")) {
    p.powerW = numberOr(tab, "power_w", 0.0);
    checkMin(tab, "power_w", *p.powerW, 0.0, true, " W (the luminaire's input power)");
  }

  if (const toml::node* n = tab.get("emergency")) p.emergency = asBool(c, *n, "emergency");
  if (const toml::node* n = tab.get("emergency_factor")) {
    p.emergencyFactor = asNumber(c, *n, "emergency_factor");
    if (!(p.emergencyFactor > 0.0 && p.emergencyFactor <= 1.0))
      c.fail(*n, "'emergency_factor' must be in (0, 1] (the share of the flux in emergency mode), got " +
                     compactNumber(p.emergencyFactor));
    if (!p.emergency) c.fail(*n, "'emergency_factor' needs 'emergency = true'");
  }

  int rows = 1, columns = 1;
  Vec2 spacing(0.0);
  if (const toml::node* an = tab.get("array")) {
    const toml::table* at = an->as_table();
    if (!at) c.fail(*an, "'array' must be a table {rows = .., columns = .., spacing = [dx, dy]}");
    Table arr(*at, c, "the luminaire 'array'");
    const toml::node& rn = arr.require("rows");
    const toml::node& cn = arr.require("columns");
    const int64_t r = asInteger(c, rn, "rows"), k = asInteger(c, cn, "columns");
    if (r < 1 || r > 1000) c.fail(rn, "'rows' must be between 1 and 1000, got " + std::to_string(r));
    if (k < 1 || k > 1000) c.fail(cn, "'columns' must be between 1 and 1000, got " + std::to_string(k));
    const toml::node& sn = arr.require("spacing");
    spacing = asVec2(c, sn, "spacing", "[dx, dy] in m");
    if (!(spacing.x > 0.0) || !(spacing.y > 0.0)) c.fail(sn, "luminaire array 'spacing' must be positive (m)");
    arr.finish();
    rows = static_cast<int>(r);
    columns = static_cast<int>(k);
  }
  tab.finish();
  out.luminaireEntries.push_back({p.name, asString(c, tab.require("file"), "file"), p.loc});
  // Columns run along +X and rows along +Y from `position`, the first fitting.
  const bool isArray = rows > 1 || columns > 1;
  for (int r = 0; r < rows; ++r) {
    for (int k = 0; k < columns; ++k) {
      LuminairePlacement q = p;
      q.row = r;
      q.column = k;
      q.positionM = p.positionM + Vec3(k * spacing.x, r * spacing.y, 0.0);
      if (isArray) q.name = p.name + "[" + std::to_string(r + 1) + "," + std::to_string(k + 1) + "]";
      out.luminaires.push_back(std::move(q));
    }
  }
}

// A number in degrees or a text such as "37d52'N", kept as written for photometry to parse.
void readAngle(Table& tab, std::string_view key, double limit, std::optional<double>& deg, std::string& text,
               FileLoc& loc) {
  const toml::node* n = tab.get(key);
  if (!n) return;
  loc = tab.ctx().at(*n);
  if (n->is_string()) {
    text = n->as_string()->get();
    if (text.empty()) tab.ctx().fail(*n, keyText(key) + " must not be empty");
    return;
  }
  deg = asNumber(tab.ctx(), *n, key);
  checkRange(tab, key, *deg, -limit, limit, " deg");
}

void readSite(const Context& c, const toml::table& t, SiteSpec& s) {
  Table tab(t, c, "[site]");
  s.present = true;
  s.loc = tab.loc();
  readAngle(tab, "latitude", 90.0, s.latitudeDeg, s.latitudeText, s.latitudeLoc);
  readAngle(tab, "longitude", 180.0, s.longitudeDeg, s.longitudeText, s.longitudeLoc);
  s.elevationM = numberOr(tab, "elevation", 0.0);
  checkRange(tab, "elevation", s.elevationM, -500.0, 9000.0, " m");
  s.timezoneHours = optNumber(tab, "timezone");
  if (s.timezoneHours) checkRange(tab, "timezone", *s.timezoneHours, -12.0, 14.0, " h");
  s.northDeg = numberOr(tab, "north", 0.0);
  checkRange(tab, "north", s.northDeg, -360.0, 360.0, " deg");
  if (auto n = tab.get("grid")) s.grid = asString(c, *n, "grid");
  tab.finish();
}

// "YYYY-MM-DDTHH:MM[:SS]" (a space may replace the T); a TOML local date-time is accepted too.
std::string readTime(const Context& c, const toml::node& n) {
  if (auto dt = n.as_date_time()) {
    const toml::date_time& v = dt->get();
    if (v.offset) c.fail(n, "'time' is local standard time at the site; write it without a UTC offset");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", v.date.year, v.date.month, v.date.day,
                  v.time.hour, v.time.minute, v.time.second);
    return buf;
  }
  const std::string s = asString(c, n, "time");
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0, used = 0;
  char sep = 0;
  const int fields = std::sscanf(s.c_str(), "%4d-%2d-%2d%c%2d:%2d%n", &y, &mo, &d, &sep, &h, &mi, &used);
  bool ok = fields >= 6 && (sep == 'T' || sep == ' ');
  if (ok && static_cast<std::size_t>(used) < s.size()) {
    int more = 0;
    ok = std::sscanf(s.c_str() + used, ":%2d%n", &sec, &more) == 1 && static_cast<std::size_t>(used + more) == s.size();
  }
  ok = ok && mo >= 1 && mo <= 12 && d >= 1 && d <= 31 && h >= 0 && h <= 24 && mi >= 0 && mi <= 59 && sec >= 0 &&
       sec <= 60;
  if (!ok) c.fail(n, "'time' must read YYYY-MM-DDTHH:MM (local standard time), got '" + s + "'");
  return s;
}

void readSky(const Context& c, const toml::table& t, SkySpec& s) {
  Table tab(t, c, "[sky]");
  s.present = true;
  s.loc = tab.loc();
  const toml::node& tn = tab.require("type");
  const std::string type = asString(c, tn, "type");
  std::string why;
  const std::optional<SkyType> parsed = parseSkyType(type, &why);
  if (!parsed) c.fail(tn, why);
  s.type = *parsed;
  if (auto n = tab.get("time")) {
    s.time = readTime(c, *n);
    s.timeLoc = c.at(*n);
  }
  auto nonNegative = [&](const char* key, std::optional<double>& v) {
    v = optNumber(tab, key);
    if (v) checkMin(tab, key, *v, 0.0, false, "");
  };
  nonNegative("diffuse_horizontal_illuminance", s.diffuseHorizontalIlluminanceLux);
  nonNegative("direct_normal_illuminance", s.directNormalIlluminanceLux);
  nonNegative("direct_normal_irradiance", s.directNormalIrradianceWm2);
  nonNegative("diffuse_horizontal_irradiance", s.diffuseHorizontalIrradianceWm2);
  s.groundReflectance = numberOr(tab, "ground_reflectance", 0.2);
  checkRange(tab, "ground_reflectance", s.groundReflectance, 0.0, 1.0, "");
  if (auto n = tab.get("sun")) s.sun = asBool(c, *n, "sun");
  if (tab.get("weather")) s.weather = filePath(tab, "weather", "weather file");
  s.sunAltitudeDeg = optNumber(tab, "sun_altitude");
  if (s.sunAltitudeDeg) checkRange(tab, "sun_altitude", *s.sunAltitudeDeg, -90.0, 90.0, " deg");
  s.sunAzimuthDeg = optNumber(tab, "sun_azimuth");
  if (s.sunAzimuthDeg) checkRange(tab, "sun_azimuth", *s.sunAzimuthDeg, -360.0, 360.0, " deg");
  if (s.sunAltitudeDeg.has_value() != s.sunAzimuthDeg.has_value())
    throw InputError(s.loc, "give both 'sun_altitude' and 'sun_azimuth', or neither");
  if (s.type.kind == SkyKind::kAnnual && s.weather.empty())
    throw InputError(s.loc, "an annual sky needs a 'weather' file (EPW)");
  tab.finish();
}

void readView(const Context& c, const toml::table& t, int index, CaseFile& out) {
  Table tab(t, c, "[[view]]");
  ViewSpec v;
  v.loc = tab.loc();
  v.name = "view" + std::to_string(index + 1);
  if (auto n = tab.get("name")) v.name = asString(c, *n, "name");
  if (const toml::node* n = tab.get("type")) {
    const std::string type = asString(c, *n, "type");
    if (type == "perspective") v.type = ViewType::kPerspective;
    else if (type == "fisheye") v.type = ViewType::kFisheye;
    else c.fail(*n, "unknown view type '" + type + "' (expected perspective or fisheye)");
  }
  v.positionM = asVec3(c, tab.require("position"), "position");
  v.direction = asDirection(c, tab.require("direction"), "direction");
  if (const toml::node* n = tab.get("up")) v.up = asDirection(c, *n, "up");
  if (glm::length(glm::cross(v.direction, v.up)) < 1e-6)
    throw InputError(tab.get("up") ? c.at(*tab.get("up")) : v.loc, "view 'up' must not be parallel to 'direction'");
  v.fovDeg = v.type == ViewType::kFisheye ? Vec2(180.0, 180.0) : Vec2(60.0, 45.0);
  if (const toml::node* n = tab.get("fov")) {
    v.fovDeg = asVec2(c, *n, "fov", "[horizontal, vertical] in degrees");
    const double maxDeg = v.type == ViewType::kFisheye ? 360.0 : 179.0;
    if (!(v.fovDeg.x > 0.0 && v.fovDeg.y > 0.0 && v.fovDeg.x <= maxDeg && v.fovDeg.y <= maxDeg))
      c.fail(*n, "'fov' angles must be in (0, " + std::to_string(static_cast<int>(maxDeg)) + "] degrees");
  }
  if (const toml::node* n = tab.get("resolution")) {
    const toml::array& a = asArray(c, *n, "resolution", 2, "[width, height] in pixels");
    const int64_t w = asInteger(c, a[0], "resolution"), h = asInteger(c, a[1], "resolution");
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
      c.fail(*n, "'resolution' must be between 1 and 16384 pixels, got [" + std::to_string(w) + ", " +
                     std::to_string(h) + "]");
    v.resolution = glm::ivec2(static_cast<int>(w), static_cast<int>(h));
  }
  const toml::node* task = tab.get("task");
  const toml::node* background = tab.get("background");
  if (task) v.taskM = asVec3(c, *task, "task");
  if (background) v.backgroundM = asVec3(c, *background, "background");
  if ((task != nullptr) != (background != nullptr))
    c.fail(task ? *task : *background, "a view's contrast needs both 'task' and 'background' points");
  tab.finish();
  out.views.push_back(std::move(v));
}

void readObserver(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  if (isGrObserver(c, t)) return readGrObserver(c, t, index, names, out);  // EN 12464-2's GR
  Table tab(t, c, "[[observer]]");
  tab.get("kind");  // "ugr", the default
  ObserverSpec o;
  o.loc = tab.loc();
  o.name = "observer" + std::to_string(index + 1);
  if (auto n = tab.get("name")) o.name = asString(c, *n, "name");
  if (!names.insert(o.name).second) c.fail(*tab.get("name"), "two observers are named '" + o.name + "'");
  o.positionM = asVec2(c, tab.require("position"), "position", "[x, y] in metres (the plan position)");
  const toml::node& dir = tab.require("direction");
  o.direction = asVec2(c, dir, "direction", "[x, y]: the horizontal line of sight");
  if (o.direction == Vec2(0.0)) c.fail(dir, "'direction' must not be zero");
  const std::optional<Vec2> unit = unitDirection(o.direction);
  if (!unit) c.fail(dir, "'direction' cannot be normalised: its length underflows");
  o.direction = *unit;
  o.eyeHeightM = numberOr(tab, "eye_height", 1.2);
  checkMin(tab, "eye_height", o.eyeHeightM, 0.0, true, "m");
  if (const toml::node* n = tab.get("ugr_limit")) {
    o.ugrLimit = asNumber(c, *n, "ugr_limit");
    checkRange(tab, "ugr_limit", *o.ugrLimit, 0.0, 40.0, "");
  }
  tab.finish();
  out.observers.push_back(std::move(o));
}

void readSettings(const Context& c, const toml::table& t, Settings& s) {
  Table tab(t, c, "[settings]");
  if (const toml::node* n = tab.get("quality")) {
    const std::string q = asString(c, *n, "quality");
    try {
      s.quality = parseQuality(q);
    } catch (const std::invalid_argument&) {
      c.fail(*n, "unknown quality '" + q + "' (expected draft, normal or high)");
    }
  }
  if (const toml::node* n = tab.get("seed")) {
    const int64_t v = asInteger(c, *n, "seed");
    if (v < 0) c.fail(*n, "'seed' must not be negative");
    s.seed = static_cast<uint64_t>(v);
  }
  auto count = [&](const char* key, int64_t lo, int64_t hi) -> std::optional<int> {
    const toml::node* n = tab.get(key);
    if (!n) return std::nullopt;
    const int64_t v = asInteger(c, *n, key);
    if (v < lo || v > hi)
      c.fail(*n, keyText(key) + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                     std::to_string(v));
    return static_cast<int>(v);
  };
  s.bounces = count("bounces", 0, 100);
  s.samples = count("samples", 1, 1'000'000);
  s.threads = count("threads", 0, 4096).value_or(0);
  if (const toml::node* n = tab.get("target_error")) {
    const double pct = asNumber(c, *n, "target_error");
    if (!(pct >= 0.0 && pct <= 100.0)) c.fail(*n, "'target_error' must be between 0 and 100 (percent)");
    s.targetRelativeError = pct / 100.0;
  }
  if (const toml::node* n = tab.get("method")) {
    const std::string m = asString(c, *n, "method");
    try {
      s.method = parseMethod(m);
    } catch (const std::invalid_argument&) {
      c.fail(*n, "unknown method '" + m + "' (expected cache or path)");
    }
  }
  if (const toml::node* n = tab.get("patterns")) {
    try {
      s.scene.patterns = parsePatternPolicy(asString(c, *n, "patterns"));
    } catch (const std::invalid_argument& e) {
      c.fail(*n, e.what());
    }
  }
  if (const toml::node* n = tab.get("nonplanar")) {
    try {
      s.scene.nonplanar = parseNonplanarPolicy(asString(c, *n, "nonplanar"));
    } catch (const std::invalid_argument& e) {
      c.fail(*n, e.what());
    }
  }
  if (tab.get("obj_map")) s.scene.objMapping = filePath(tab, "obj_map", "OBJ mapping file");
  tab.finish();
}

// "HH:MM" (00:00 .. 24:00) as hours.
double readClock(const Context& c, const toml::node& n, std::string_view key) {
  const std::string text = asString(c, n, key);
  int h = 0, m = 0, used = 0;
  if (std::sscanf(text.c_str(), "%d:%d%n", &h, &m, &used) != 2 || static_cast<std::size_t>(used) != text.size() ||
      h < 0 || h > 24 || m < 0 || m > 59 || (h == 24 && m > 0))
    c.fail(n, keyText(key) + " must be a time of day \"HH:MM\" (00:00 .. 24:00), got '" + text + "'");
  return h + m / 60.0;
}

void readAnnual(const Context& c, const toml::table& t, AnnualSpec& a) {
  Table tab(t, c, "[annual]");
  a.present = true;
  a.loc = tab.loc();
  if (const toml::node* n = tab.get("occupancy_start")) a.occupancyStartHour = readClock(c, *n, "occupancy_start");
  if (const toml::node* n = tab.get("occupancy_end")) a.occupancyEndHour = readClock(c, *n, "occupancy_end");
  if (a.occupancyEndHour <= a.occupancyStartHour)
    throw InputError(a.loc, "'occupancy_end' must be later than 'occupancy_start'");
  auto positive = [&](const char* key, double& v) {
    v = numberOr(tab, key, v);
    if (tab.get(key)) checkMin(tab, key, v, 0.0, true, " lux");
  };
  positive("da_threshold", a.daThresholdLux);
  positive("udi_low", a.udiLowLux);
  positive("udi_high", a.udiHighLux);
  positive("ase_threshold", a.aseThresholdLux);
  if (!(a.udiLowLux < a.daThresholdLux && a.daThresholdLux < a.udiHighLux))
    throw InputError(a.loc, "the thresholds must satisfy udi_low < da_threshold < udi_high");
  a.sdaFraction = numberOr(tab, "sda_fraction", a.sdaFraction);
  checkRange(tab, "sda_fraction", a.sdaFraction, 0.0, 1.0, "");
  a.aseHours = numberOr(tab, "ase_hours", a.aseHours);
  checkRange(tab, "ase_hours", a.aseHours, 0.0, 8784.0, " h");
  auto count = [&](const char* key, int lo, int hi, int& v) {
    const toml::node* n = tab.get(key);
    if (!n) return;
    const int64_t x = asInteger(c, *n, key);
    if (x < lo || x > hi)
      c.fail(*n, keyText(key) + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                     std::to_string(x));
    v = static_cast<int>(x);
  };
  count("sky_subdivision", 1, 8, a.skySubdivision);
  count("sun_samples", 1, 256, a.sunSamples);
  if (const toml::node* n = tab.get("blinds")) a.blinds = asBool(c, *n, "blinds");
  if (tab.get("report_sensor")) {
    int v = 0;
    count("report_sensor", 0, 100'000'000, v);
    a.reportSensor = v;
    a.reportSensorLoc = c.at(*tab.get("report_sensor"));
  }
  tab.finish();
}

// [case] reference_grid names a grid of the case (a [[grid]] or a task area's) that is not a
// daylight-factor grid and measures horizontal illuminance (the points' normals are checked when
// the grids are made: study/luminaire_schedule.h).
void checkReferenceGrid(const CaseFile& c) {
  if (c.referenceGrid.empty()) return;
  std::string names;
  for (const GridSpec& g : c.grids) {
    if (g.name == c.referenceGrid) {
      if (g.daylightFactor)
        throw InputError(c.referenceGridLoc, "'reference_grid' names grid '" + g.name +
                                                 "', a daylight-factor grid: W/m²/100 lx needs an illuminance grid");
      if (g.quantity && *g.quantity != GridQuantity::kHorizontal)
        throw InputError(c.referenceGridLoc, "'reference_grid' names grid '" + g.name + "' of " +
                                                 gridQuantityKey(*g.quantity) +
                                                 " illuminance: W/m²/100 lx needs horizontal illuminance");
      return;
    }
    names += (names.empty() ? "" : ", ") + ("'" + g.name + "'");
  }
  throw InputError(c.referenceGridLoc, "'reference_grid' names no grid of the case: '" + c.referenceGrid +
                                           "' (the grids: " + (names.empty() ? "none" : names) + ")");
}

void readOutput(const Context& c, const toml::table& t, OutputSpec& o) {
  Table tab(t, c, "[output]");
  if (const toml::node* n = tab.get("dir")) {
    const std::string d = asString(c, *n, "dir");
    if (d.empty()) c.fail(*n, "'dir' must not be empty");
    if (d.find('\0') != std::string::npos) c.fail(*n, "'dir' must not contain a NUL character");
    o.dir = fs::path(d);
    if (o.dir.is_relative()) o.dir = c.dir / o.dir;
    o.dir = o.dir.lexically_normal();
  }
  tab.finish();
}

}  // namespace

CaseFile parseCaseFile(std::string_view text, const fs::path& path) {
  Context c{path.string(), path.parent_path()};
  toml::table root;
  try {
    root = toml::parse(text, path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(c.at(e.source()), "TOML syntax error: " + std::string(e.description()));
  }

  CaseFile out;
  out.path = path;
  out.name = path.stem().string();
  out.output.dir = (c.dir / "out").lexically_normal();

  static const std::set<std::string> kTopLevel = {"case",      "scene",        "luminaire", "portal",   "site",
                                                  "sky",       "grid",         "task_area", "surface_grid",
                                                  "view",      "observer",     "settings",  "annual",   "output",
                                                  "compliance", "window_group", "escape_route", "open_area",
                                                  "safety_point", "road"};
  for (auto&& [key, node] : root) {
    if (!kTopLevel.count(std::string(key.str())))
      throw InputError(c.at(key.source()), "unknown key '" + std::string(key.str()) +
                                               "' (expected case, scene, luminaire, portal, site, sky, grid, task_area, "
                                               "surface_grid, view, observer, window_group, settings, annual, output, "
                                               "compliance, escape_route, open_area, safety_point or road)");
  }
  if (auto t = singleTable(c, root, "case")) readCase(c, *t, out);
  if (auto a = tableArray(c, root, "scene"))
    for (const toml::node& n : *a) readScene(c, *n.as_table(), out);
  if (auto a = tableArray(c, root, "luminaire")) {
    int entry = 0;
    for (const toml::node& n : *a) readLuminaire(c, *n.as_table(), entry++, out);
  }
  if (auto a = tableArray(c, root, "portal")) {
    int index = 0;
    for (const toml::node& n : *a) readPortal(c, *n.as_table(), index++, out);
  }
  if (auto t = singleTable(c, root, "site")) readSite(c, *t, out.site);
  if (auto t = singleTable(c, root, "sky")) readSky(c, *t, out.sky);
  std::set<std::string> gridNames;
  if (auto a = tableArray(c, root, "grid")) {
    int index = 0;
    for (const toml::node& n : *a) readGrid(c, *n.as_table(), index++, gridNames, out);
  }
  if (auto a = tableArray(c, root, "task_area")) {
    int index = 0;
    for (const toml::node& n : *a) readTaskArea(c, *n.as_table(), index++, gridNames, out);
  }
  if (auto a = tableArray(c, root, "surface_grid")) {
    int index = 0;
    for (const toml::node& n : *a) readSurfaceGrid(c, *n.as_table(), index++, gridNames, out);
  }
  if (auto a = tableArray(c, root, "view")) {
    int index = 0;
    for (const toml::node& n : *a) readView(c, *n.as_table(), index++, out);
  }
  if (auto a = tableArray(c, root, "observer")) {
    std::set<std::string> names;
    int index = 0;
    for (const toml::node& n : *a) readObserver(c, *n.as_table(), index++, names, out);
  }
  if (auto a = tableArray(c, root, "window_group")) {
    std::set<std::string> names;
    int index = 0;
    for (const toml::node& n : *a) readWindowGroup(c, *n.as_table(), index++, names, out);
    if (out.sky.type.kind != SkyKind::kAnnual)
      throw InputError(out.windowGroups.front().loc, "[[window_group]] needs [sky] type = \"annual\" (LM-83's "
                                                     "operable blinds are part of the annual sDA)");
  }
  readEmergencyTables(c, root, out);
  readRoadTables(c, root, out);
  checkReferenceGrid(out);
  if (auto t = singleTable(c, root, "settings")) readSettings(c, *t, out.settings);
  if (auto t = singleTable(c, root, "annual")) {
    readAnnual(c, *t, out.annual);
    if (out.sky.type.kind != SkyKind::kAnnual)
      throw InputError(out.annual.loc, "an [annual] table needs [sky] type = \"annual\"");
  }
  if (auto t = singleTable(c, root, "output")) readOutput(c, *t, out.output);
  if (auto a = tableArray(c, root, "compliance")) {
    std::set<std::string> names;
    for (const toml::node& n : *a) readCompliance(c, *n.as_table(), names, out);
    // EN 1838, EN 13201 and EN 12464-2 are point-in-time studies of the luminaires; the others are
    // annual.
    for (const ComplianceSpec& s : out.compliance) {
      const bool pointInTime = s.standard == ComplianceStandard::kEn1838 ||
                               s.standard == ComplianceStandard::kEn13201 ||
                               s.standard == ComplianceStandard::kEn12464_2;
      if (!pointInTime && out.sky.type.kind != SkyKind::kAnnual)
        throw InputError(s.loc, "[[compliance]] needs an annual study ([sky] type = \"annual\" with a weather file) "
                                "for standard = \"" + std::string(standardKey(s.standard)) + "\"");
      if (pointInTime && out.sky.type.kind == SkyKind::kAnnual)
        throw InputError(s.loc, "[[compliance]] standard = \"" + std::string(standardKey(s.standard)) +
                                    "\" needs a point-in-time study, not an annual sky");
    }
  }
  checkEmergencyCompliance(out);
  checkRoadCompliance(out);
  resolveOutdoor(out);
  return out;
}

CaseFile readCaseFile(const fs::path& path) { return parseCaseFile(readInputFile(path, "case file"), path); }

std::optional<Warning> gridOutsideScene(const GridSpec& grid, const Box& sceneBounds, double toleranceM) {
  if (sceneBounds.empty()) return std::nullopt;
  const Vec3 lo = sceneBounds.lo - Vec3(toleranceM), hi = sceneBounds.hi + Vec3(toleranceM);
  auto inside = [&](const Vec3& p) {
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
  };
  auto outside = [&](const Vec3& p) {
    auto c = [](double v) { return compactNumber(std::round(v * 1000.0) / 1000.0); };
    auto vec = [&](const Vec3& v) { return "(" + c(v.x) + ", " + c(v.y) + ", " + c(v.z) + ")"; };
    // Under a sky the box is open upwards and downwards (gridBounds): say so, not 1e+300.
    const bool open = sceneBounds.hi.z >= 1e299;
    const std::string box = open ? "(" + c(sceneBounds.lo.x) + ", " + c(sceneBounds.lo.y) + ")..(" +
                                       c(sceneBounds.hi.x) + ", " + c(sceneBounds.hi.y) + ") m in plan"
                                 : vec(sceneBounds.lo) + ".." + vec(sceneBounds.hi) + " m";
    return Warning{"grid_outside_scene",
                   "grid '" + grid.name + "' reaches outside the scene: point " + vec(p) +
                       " m is not within the box of the scene and its luminaires " + box,
                   grid.loc};
  };
  if (grid.kind == GridKind::kPoints) {
    for (const SensorPoint& s : readPointsFile(grid.pointsFile).points)
      if (!inside(s.position)) return outside(s.position);
    return std::nullopt;
  }
  const PlaneGridSpec& p = grid.plane;
  std::vector<Vec2> outline = p.outline;
  if (p.isRectangle && outline.size() == 2)
    outline = {outline[0], Vec2(outline[1].x, outline[0].y), outline[1], Vec2(outline[0].x, outline[1].y)};
  for (const Vec2& uv : outline) {
    const Vec3 w = p.origin + uv.x * p.uAxis + uv.y * p.vAxis;
    if (!inside(w)) return outside(w);
  }
  return std::nullopt;
}

}  // namespace candela
