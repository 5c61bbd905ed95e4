// [[task_area]] standard = "en12464-2", [[observer]] kind = "gr" (study/compliance/en12464_2_case.h).
#include "study/compliance/en12464_2_case.h"

#include "metrics/en12464_2.h"
#include "study/case/case_grids.h"
#include "study/grids/sensor_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

using namespace case_toml;

namespace {

// GR is defined from 10 (unnoticeable) to 90 (unbearable) on CIE 112's scale (docs/outdoor.md).
constexpr double kGrScaleMin = 10.0, kGrScaleMax = 90.0;

std::optional<double> grLimitOf(Table& tab) {
  std::optional<double> v = optNumber(tab, "gr_limit");
  if (v) checkRange(tab, "gr_limit", *v, kGrScaleMin, kGrScaleMax, "");
  return v;
}

}  // namespace

bool isOutdoorTaskArea(const Context& c, const toml::table& t) {
  const toml::node* n = t.get("standard");
  if (!n) return false;
  const std::string s = asString(c, *n, "standard");
  if (s == "en12464-2") return true;
  if (s != "en12464-1")
    c.fail(*n, "a task area's 'standard' must be \"en12464-1\" (indoor, the default) or \"en12464-2\" (outdoor), got '" +
                   s + "'");
  return false;
}

void readOutdoorTaskArea(const Context& c, const toml::table& t, int index, std::set<std::string>& gridNames,
                         CaseFile& out) {
  Table tab(t, c, "[[task_area]] (standard = \"en12464-2\")");
  tab.get("standard");
  OutdoorTaskAreaSpec a;
  a.loc = tab.loc();
  a.name = entryName(tab, "task area " + std::to_string(index + 1));
  a.outline = readTaskAreaOutline(tab, a.loc);
  a.heightM = numberOr(tab, "height", 0.0);
  a.maintainedLux = asNumber(c, tab.require("maintained_illuminance"), "maintained_illuminance");
  checkMin(tab, "maintained_illuminance", a.maintainedLux, 0.0, true, " lx");
  a.uniformity = optNumber(tab, "uniformity");
  if (a.uniformity) checkRange(tab, "uniformity", *a.uniformity, 0.0, 1.0, "");
  a.grLimit = grLimitOf(tab);
  a.ra = optNumber(tab, "ra");
  if (a.ra) checkRange(tab, "ra", *a.ra, 0.0, 100.0, "");
  a.groundReflectance = optNumber(tab, "ground_reflectance");
  if (a.groundReflectance) checkRange(tab, "ground_reflectance", *a.groundReflectance, 0.0, 1.0, "");
  if (const toml::node* n = tab.get("gr_spacing")) {
    a.grSpacingM = asNumber(c, *n, "gr_spacing");
    checkMin(tab, "gr_spacing", *a.grSpacingM, 0.0, true, " m");
    a.grSpacingLoc = c.at(*n);
  }
  std::optional<double> spacing;
  if (const toml::node* n = tab.get("spacing")) {
    spacing = asNumber(c, *n, "spacing");
    checkMin(tab, "spacing", *spacing, 0.0, true, " m");
  }
  tab.finish();

  GridSpec g;
  g.name = a.name;
  g.loc = a.loc;
  g.plane.origin = Vec3(0.0, 0.0, a.heightM);
  g.plane.isRectangle = false;
  g.plane.outline = a.outline;
  g.plane.spacingM = spacing;
  g.targetAverageLux = a.maintainedLux;
  g.targetUniformity = a.uniformity;
  if (!gridNames.insert(g.name).second) throw InputError(a.loc, "two grids are named '" + g.name + "'");
  countPlaneGrid(g.plane, g.loc);
  out.grids.push_back(std::move(g));
  out.outdoor.areas.push_back(std::move(a));
}

bool isGrObserver(const Context& c, const toml::table& t) {
  const toml::node* n = t.get("kind");
  if (!n) return false;
  const std::string k = asString(c, *n, "kind");
  if (k == "gr") return true;
  if (k != "ugr")
    c.fail(*n, "an observer's 'kind' must be \"ugr\" (CIE 117, indoor, the default) or \"gr\" (CIE 112, outdoor), "
               "got '" + k + "'");
  return false;
}

void readGrObserver(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[observer]] (kind = \"gr\")");
  tab.get("kind");
  GrObserverSpec o;
  o.loc = tab.loc();
  o.name = "observer" + std::to_string(index + 1);
  if (const toml::node* n = tab.get("name")) o.name = asString(c, *n, "name");
  if (!names.insert(o.name).second) c.fail(*tab.get("name"), "two observers are named '" + o.name + "'");
  o.positionM = asVec2(c, tab.require("position"), "position", "[x, y] in metres (the plan position)");
  if (const toml::node* dir = tab.get("direction")) {
    const Vec2 d = asVec2(c, *dir, "direction", "[x, y]: the line of sight in plan");
    const std::optional<Vec2> unit = d == Vec2(0.0) ? std::nullopt : unitDirection(d);
    if (!unit) c.fail(*dir, "'direction' must be a non-zero plan direction [x, y]");
    o.direction = *unit;
  }
  if (const toml::node* n = tab.get("direction_step")) {
    if (o.direction) c.fail(*n, "'direction_step' is for an observer looking all around: leave out 'direction'");
    o.stepDeg = asNumber(c, *n, "direction_step");
    checkRange(tab, "direction_step", o.stepDeg, 1.0, 360.0, " deg");
  }
  o.eyeHeightM = numberOr(tab, "eye_height", o.eyeHeightM);
  checkMin(tab, "eye_height", o.eyeHeightM, 0.0, true, " m");
  o.inclinationDeg = numberOr(tab, "inclination", o.inclinationDeg);
  checkRange(tab, "inclination", o.inclinationDeg, -45.0, 45.0, " deg");
  if (const toml::node* n = tab.get("task_area")) o.taskArea = asString(c, *n, "task_area");
  o.grLimit = grLimitOf(tab);
  tab.finish();
  out.outdoor.observers.push_back(std::move(o));
}

// The most GR observers a task area's `gr_spacing` lattice may hold (about 200 B each once read,
// and each a glare rating over its viewing directions: 20 MB, seconds).
constexpr double kMaxGrLattice = 1e5;

std::vector<GrObserverSpec> gridGrObservers(const OutdoorTaskAreaSpec& a) {
  std::vector<GrObserverSpec> out;
  if (!a.grSpacingM) return out;
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Vec2& v : a.outline) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const Vec2 size = hi - lo;
  // Bounded before anything is made: a lattice of more than kMaxGrLattice observers is refused.
  const double cx = std::max(1.0, std::ceil(size.x / *a.grSpacingM - 1e-9));
  const double cy = std::max(1.0, std::ceil(size.y / *a.grSpacingM - 1e-9));
  if (cx * cy > kMaxGrLattice)
    throw InputError(a.grSpacingLoc, "'gr_spacing' of " + std::to_string(*a.grSpacingM) + " m makes a lattice of " +
                                         std::to_string(static_cast<long long>(std::min(cx * cy, 9e18))) + " observers over the task area '" + a.name +
                                         "', more than the " + std::to_string(static_cast<long>(kMaxGrLattice)) +
                                         " a task area may have");
  const int nx = static_cast<int>(cx), ny = static_cast<int>(cy);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p(lo.x + (i + 0.5) * size.x / nx, lo.y + (j + 0.5) * size.y / ny);
      if (!insidePolygon(a.outline, p)) continue;
      GrObserverSpec o;
      o.name = a.name + " GR " + std::to_string(out.size() + 1);
      o.positionM = p;
      o.taskArea = a.name;
      o.fromGrid = true;
      o.loc = a.grSpacingLoc;
      out.push_back(std::move(o));
    }
  return out;
}

void resolveOutdoor(CaseFile& out) {
  OutdoorSpec& s = out.outdoor;
  for (const OutdoorTaskAreaSpec& a : s.areas) {
    std::vector<GrObserverSpec> lattice = gridGrObservers(a);
    if (a.grSpacingM && lattice.empty())
      throw InputError(a.grSpacingLoc, "'gr_spacing' puts no observer inside the task area '" + a.name + "'");
    for (GrObserverSpec& o : lattice) s.observers.push_back(std::move(o));
  }
  for (GrObserverSpec& o : s.observers) {
    const OutdoorTaskAreaSpec* area = nullptr;
    if (!o.taskArea.empty()) {
      for (const OutdoorTaskAreaSpec& a : s.areas) area = a.name == o.taskArea ? &a : area;
      if (!area)
        throw InputError(o.loc, "observer '" + o.name + "': 'task_area' names '" + o.taskArea +
                                    "', which is no [[task_area]] with standard = \"en12464-2\"");
    } else {
      for (const OutdoorTaskAreaSpec& a : s.areas)
        if (!area && insidePolygon(a.outline, o.positionM)) area = &a;
      if (!area && s.areas.size() == 1) area = &s.areas.front();
      if (!area)
        throw InputError(o.loc, "observer '" + o.name + "' stands in no outdoor task area: name the one whose "
                                "lighting it rates with 'task_area' (its L_ve, docs/outdoor.md)");
      o.taskArea = area->name;
    }
  }
  const auto entry = std::find_if(out.compliance.begin(), out.compliance.end(), [](const ComplianceSpec& c) {
    return c.standard == ComplianceStandard::kEn12464_2;
  });
  if (entry == out.compliance.end()) {
    if (!s.areas.empty())
      throw InputError(s.areas.front().loc, "a [[task_area]] with standard = \"en12464-2\" needs a [[compliance]] "
                                            "entry with standard = \"en12464-2\" to be checked");
    if (!s.observers.empty())
      throw InputError(s.observers.front().loc, "[[observer]] kind = \"gr\" needs a [[compliance]] entry with "
                                                "standard = \"en12464-2\" to be checked");
    return;
  }
  if (s.areas.empty() && !entry->obtrusive.any())
    throw InputError(entry->loc, "standard = \"en12464-2\" has nothing to check: add a [[task_area]] with "
                                 "standard = \"en12464-2\" or the obtrusive light's 'environmental_zone'");
  for (auto e = std::next(entry); e != out.compliance.end(); ++e)
    if (e->standard == ComplianceStandard::kEn12464_2)
      throw InputError(e->loc, "only one [[compliance]] entry may be standard = \"en12464-2\"");
}

void readObtrusiveLight(Table& tab, ComplianceSpec& s) {
  const Context& c = tab.ctx();
  ObtrusiveLightSpec& o = s.obtrusive;
  const bool en = s.standard == ComplianceStandard::kEn12464_2;
  for (const char* key : {"environmental_zone", "obtrusive_limits", "property_points"})
    if (const toml::node* n = tab.get(key); n && !en)
      c.fail(*n, keyText(key) + " belongs to standard = \"en12464-2\", not \"" + std::string(standardKey(s.standard)) +
                     "\"");
  if (!en) return;
  if (const toml::node* n = tab.get("environmental_zone")) {
    o.zone = asString(c, *n, "environmental_zone");
    o.loc = c.at(*n);
    if (!obtrusiveZoneLimits(o.zone))
      c.fail(*n, "'environmental_zone' must be \"E1\", \"E2\", \"E3\" or \"E4\" (their limits before curfew are "
                 "built in; for E0 or after curfew give 'obtrusive_limits'), got '" + o.zone + "'");
  }
  if (const toml::node* n = tab.get("obtrusive_limits")) {
    const toml::table* t = n->as_table();
    if (!t) c.fail(*n, "'obtrusive_limits' must be { property_illuminance = lx, intensity = cd, upward_light_ratio = share }");
    Table lt(*t, c, "'obtrusive_limits'");
    o.propertyLux = optNumber(lt, "property_illuminance");
    if (o.propertyLux) checkMin(lt, "property_illuminance", *o.propertyLux, 0.0, false, " lx");
    o.intensityCd = optNumber(lt, "intensity");
    if (o.intensityCd) checkMin(lt, "intensity", *o.intensityCd, 0.0, false, " cd");
    o.upwardLightRatio = optNumber(lt, "upward_light_ratio");
    if (o.upwardLightRatio) checkRange(lt, "upward_light_ratio", *o.upwardLightRatio, 0.0, 1.0, "");
    lt.finish();
    if (!o.propertyLux && !o.intensityCd && !o.upwardLightRatio)
      c.fail(*n, "'obtrusive_limits' gives no limit: property_illuminance, intensity or upward_light_ratio");
    if (o.zone.empty()) o.loc = c.at(*n);
  }
  if (const toml::node* n = tab.get("property_points")) {
    if (!o.any()) c.fail(*n, "'property_points' need the limits they are judged against: 'environmental_zone' or "
                             "'obtrusive_limits'");
    for (const toml::table* t : asTableList(c, *n, "property_points", "{ name, position = [x, y, z], normal = [nx, ny, nz] }")) {
      const toml::node& p = *t;
      Table pt(*t, c, "a property point");
      PropertyPointSpec q;
      q.loc = c.at(p);
      q.name = pt.get("name") ? asString(c, *pt.get("name"), "name") : "P" + std::to_string(o.points.size() + 1);
      q.positionM = asVec3(c, pt.require("position"), "position");
      q.normal = asDirection(c, pt.require("normal"), "normal");
      pt.finish();
      o.points.push_back(q);
    }
  }
}

}  // namespace candela
