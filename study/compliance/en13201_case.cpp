// [[road]] (study/compliance/en13201_case.h).
#include "study/compliance/en13201_case.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace candela {

using namespace case_toml;

namespace {

void readRoad(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[road]]");
  RoadSpec r;
  r.loc = tab.loc();
  r.name = "road " + std::to_string(index + 1);
  if (const toml::node* n = tab.get("name")) {
    r.name = asString(c, *n, "name");
    if (r.name.empty()) c.fail(*n, "'name' must not be empty");
  }
  if (!names.insert(r.name).second) throw InputError(r.loc, "two roads are named '" + r.name + "'");
  r.start = asVec2(c, tab.require("start"), "start", "[x, y]: the plan point on the near edge where the field begins");
  const toml::node& dn = tab.require("direction");
  const Vec2 d = asVec2(c, dn, "direction", "[x, y]: the plan direction the road runs in");
  const std::optional<Vec2> unit = d == Vec2(0.0) ? std::nullopt : unitDirection(d);
  if (!unit) c.fail(dn, "'direction' must be a non-zero plan direction [x, y]");
  r.direction = *unit;
  r.lengthM = asNumber(c, tab.require("length"), "length");
  checkRange(tab, "length", r.lengthM, 1.0, 1000.0, " m");
  r.widthM = asNumber(c, tab.require("width"), "width");
  checkRange(tab, "width", r.widthM, 0.5, 200.0, " m");
  if (const toml::node* n = tab.get("lanes")) {
    const int64_t lanes = asInteger(c, *n, "lanes");
    if (lanes < 1 || lanes > 20) c.fail(*n, "'lanes' must be between 1 and 20, got " + std::to_string(lanes));
    r.lanes = static_cast<int>(lanes);
  }
  const toml::node& cn = tab.require("class");
  const std::string cls = asString(c, cn, "class");
  const std::optional<RoadClass> rc = parseRoadClass(cls);
  if (!rc) c.fail(cn, "unknown road lighting class '" + cls + "' (EN 13201-2: M1..M6, C0..C5, P1..P6 or HS1..HS3)");
  r.roadClass = *rc;
  if (const toml::node* n = tab.get("additional_classes")) {
    const toml::array* a = n->as_array();
    if (!a) c.fail(*n, "'additional_classes' must be an array of class names such as [\"SC3\", \"EV4\"]");
    for (const toml::node& e : *a) {
      const std::string name = asString(c, e, "additional_classes");
      const std::optional<AdditionalRoadClass> ac = parseAdditionalRoadClass(name);
      if (!ac) c.fail(e, "unknown additional class '" + name + "' (EN 13201-2: SC1..SC9 or EV1..EV6)");
      for (const AdditionalRoadClass& have : r.additional)
        if (have.kind == ac->kind) c.fail(e, "two additional classes of one kind: " + have.name() + " and " + ac->name());
      r.additional.push_back(*ac);
    }
  }
  if (const toml::node* n = tab.get("surface")) {
    r.surface = asString(c, *n, "surface");
    std::transform(r.surface.begin(), r.surface.end(), r.surface.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    if (!findRTable(r.surface))
      c.fail(*n, "'surface' " + r.surface + " is no r-table candela has (CIE 144's standard tables: " +
                     supportedRTables() + "; docs/road.md)");
  }
  r.q0 = findRTable(r.surface)->q0;
  if (const toml::node* n = tab.get("q0")) {
    r.q0 = asNumber(c, *n, "q0");
    if (!(r.q0 > 0.0 && r.q0 < 1.0)) c.fail(*n, "'q0' must be in (0, 1) sr⁻¹ (the surface's average luminance coefficient)");
  }
  tab.finish();
  out.roadLighting.roads.push_back(std::move(r));
}

}  // namespace

void readRoadTables(const Context& c, const toml::table& root, CaseFile& out) {
  std::set<std::string> names;
  int index = 0;
  if (auto a = tableArray(c, root, "road"))
    for (const toml::node& n : *a) readRoad(c, *n.as_table(), index++, names, out);
}

void checkRoadCompliance(const CaseFile& c) {
  auto isRoad = [](const ComplianceSpec& s) { return s.standard == ComplianceStandard::kEn13201; };
  const auto entry = std::find_if(c.compliance.begin(), c.compliance.end(), isRoad);
  if (entry == c.compliance.end()) {
    if (!c.roadLighting.roads.empty())
      throw InputError(c.roadLighting.roads.front().loc,
                       "[[road]] needs a [[compliance]] entry with standard = \"en13201\" to be checked");
    return;
  }
  if (c.roadLighting.roads.empty())
    throw InputError(entry->loc, "standard = \"en13201\" has nothing to check: add a [[road]]");
  for (auto s = std::next(entry); s != c.compliance.end(); ++s)
    if (isRoad(*s)) throw InputError(s->loc, "only one [[compliance]] entry may be standard = \"en13201\"");
}

}  // namespace candela
