// [[escape_route]], [[open_area]], [[safety_point]] (study/compliance/en1838_case.h).
#include "study/compliance/en1838_case.h"

#include "engine/polygon_split.h"
#include "metrics/en1838.h"
#include "study/compliance/en1838_grids.h"
#include "study/grids/sensor_grid.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace candela {

using namespace case_toml;

namespace {

std::string nameOf(Table& tab, const std::string& dflt, std::set<std::string>& names, const char* what) {
  std::string name = dflt;
  const toml::node* n = tab.get("name");
  if (n) name = asString(tab.ctx(), *n, "name");
  if (name.empty()) tab.ctx().fail(*n, "'name' must not be empty");
  if (!names.insert(name).second) throw InputError(tab.loc(), std::string("two ") + what + " are named '" + name + "'");
  return name;
}

double spacingOr(Table& tab, double dflt) {
  const double s = numberOr(tab, "spacing", dflt);
  if (tab.get("spacing")) checkRange(tab, "spacing", s, 0.01, 10.0, " m");
  return s;
}

void readRoute(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[escape_route]]");
  EscapeRouteSpec r;
  r.loc = tab.loc();
  r.name = nameOf(tab, "route " + std::to_string(index + 1), names, "escape routes");
  const toml::node& pn = tab.require("path");
  r.pathLoc = c.at(pn);
  r.path = asPointList(c, pn, "path");
  if (r.path.size() < 2)
    c.fail(pn, "'path' needs at least 2 points [x, y], got " + std::to_string(r.path.size()));
  for (std::size_t i = 1; i < r.path.size(); ++i)
    if (glm::length(r.path[i] - r.path[i - 1]) < 1e-9)
      c.fail(pn, "'path' repeats point " + std::to_string(i) + " (a segment of zero length)");
  r.widthM = asNumber(c, tab.require("width"), "width");
  checkMin(tab, "width", r.widthM, 0.0, true, " m");
  r.heightM = numberOr(tab, "height", 0.0);
  r.spacingM = spacingOr(tab, r.spacingM);
  tab.finish();
  out.emergency.routes.push_back(std::move(r));
}

void readOpenArea(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[open_area]]");
  OpenAreaSpec a;
  a.loc = tab.loc();
  a.name = nameOf(tab, "open area " + std::to_string(index + 1), names, "open areas");
  const toml::node* cn = tab.get("corners");
  const toml::node* pn = tab.get("polygon");
  if (cn && pn) c.fail(*pn, "give either 'corners' or 'polygon', not both");
  if (!cn && !pn) throw InputError(a.loc, "an open area needs 'corners' = [[x0, y0], [x1, y1]] or a 'polygon'");
  const toml::node& at = cn ? *cn : *pn;
  if (cn) {
    const std::vector<Vec2> k = asPointList(c, *cn, "corners");
    if (k.size() != 2)
      c.fail(*cn, "'corners' must be two opposite corners [[x0, y0], [x1, y1]], got " + std::to_string(k.size()) +
                      " points");
    const Vec2 lo = glm::min(k[0], k[1]), hi = glm::max(k[0], k[1]);
    if (!(hi.x > lo.x && hi.y > lo.y)) c.fail(*cn, "'corners' span a zero area");
    a.outline = {lo, Vec2(hi.x, lo.y), hi, Vec2(lo.x, hi.y)};
  } else {
    a.outline = asPointList(c, *pn, "polygon");
    if (a.outline.size() < 3)
      c.fail(*pn, "'polygon' needs at least 3 corners, got " + std::to_string(a.outline.size()));
    const double area = polygonArea(a.outline);
    if (!(std::abs(area) > 0.0)) c.fail(*pn, "'polygon' encloses a zero area");
    if (area < 0.0) std::reverse(a.outline.begin(), a.outline.end());
    if (outlineSelfCrossing(a.outline)) c.fail(*pn, "'polygon' crosses itself: give its corners in order round the area");
  }
  a.heightM = numberOr(tab, "height", 0.0);
  a.spacingM = spacingOr(tab, a.spacingM);
  if (insetPolygon(a.outline, kEn1838BorderM, a.spacingM).size() < 3)
    c.fail(at, isConvexPolygon(a.outline)
                   ? "the open area has no core: it is nowhere wider than twice the 0.5 m border (EN 1838 4.3.1)"
                   : "the open area's core (the area without its 0.5 m border, EN 1838 4.3.1) is not one piece, or an "
                     "edge is shorter than the border swallows: split the area into open areas of one core each");
  tab.finish();
  out.emergency.openAreas.push_back(std::move(a));
}

void readSafetyPoint(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[safety_point]]");
  SafetyPointSpec p;
  p.loc = tab.loc();
  p.name = nameOf(tab, "safety point " + std::to_string(index + 1), names, "safety points");
  p.positionM = asVec3(c, tab.require("position"), "position");
  const toml::node& fn = tab.require("facing");
  const Vec2 f = asVec2(c, fn, "facing", "[x, y]: the plan direction the equipment is seen from");
  const std::optional<Vec2> unit = f == Vec2(0.0) ? std::nullopt : unitDirection(f);
  if (!unit) c.fail(fn, "'facing' must be a non-zero plan direction [x, y]");
  p.facing = *unit;
  tab.finish();
  out.emergency.safetyPoints.push_back(std::move(p));
}

}  // namespace

void readEmergencyTables(const Context& c, const toml::table& root, CaseFile& out) {
  std::set<std::string> routes, areas, points;
  int index = 0;
  if (auto a = tableArray(c, root, "escape_route"))
    for (const toml::node& n : *a) readRoute(c, *n.as_table(), index++, routes, out);
  index = 0;
  if (auto a = tableArray(c, root, "open_area"))
    for (const toml::node& n : *a) readOpenArea(c, *n.as_table(), index++, areas, out);
  index = 0;
  if (auto a = tableArray(c, root, "safety_point"))
    for (const toml::node& n : *a) readSafetyPoint(c, *n.as_table(), index++, points, out);
}

void checkEmergencyCompliance(const CaseFile& c) {
  const auto en1838 = std::find_if(c.compliance.begin(), c.compliance.end(), [](const ComplianceSpec& s) {
    return s.standard == ComplianceStandard::kEn1838;
  });
  const bool highRisk = std::any_of(c.taskAreas.begin(), c.taskAreas.end(),
                                    [](const TaskAreaSpec& a) { return a.emergencyHighRisk; });
  if (en1838 == c.compliance.end()) {
    auto needs = [](const FileLoc& at, const std::string& what) {
      throw InputError(at, what + " needs a [[compliance]] entry with standard = \"en1838\" to be checked");
    };
    if (!c.emergency.routes.empty()) needs(c.emergency.routes.front().loc, "[[escape_route]]");
    if (!c.emergency.openAreas.empty()) needs(c.emergency.openAreas.front().loc, "[[open_area]]");
    if (!c.emergency.safetyPoints.empty()) needs(c.emergency.safetyPoints.front().loc, "[[safety_point]]");
    for (const TaskAreaSpec& a : c.taskAreas)
      if (a.emergencyHighRisk) needs(a.loc, "a task area with emergency = \"high-risk\"");
    return;
  }
  if (!c.emergency.any() && !highRisk)
    throw InputError(en1838->loc, "standard = \"en1838\" has nothing to check: add [[escape_route]], [[open_area]], "
                                  "[[safety_point]] or a [[task_area]] with emergency = \"high-risk\"");
  for (auto s = std::next(en1838); s != c.compliance.end(); ++s)
    if (s->standard == ComplianceStandard::kEn1838)
      throw InputError(s->loc, "only one [[compliance]] entry may be standard = \"en1838\"");
}

}  // namespace candela
