#include "study/case/case_grids.h"

#include "metrics/targets.h"
#include "study/case/case_toml.h"
#include "study/compliance/en12464_2_case.h"
#include "study/grids/grid_quantity.h"

#include <array>
#include <cmath>
#include <limits>

namespace candela {

using namespace case_toml;

std::string entryName(Table& tab, std::string dflt) {
  const toml::node* n = tab.get("name");
  if (!n) return dflt;
  const std::string name = asString(tab.ctx(), *n, "name");
  if (name.empty()) tab.ctx().fail(*n, "'name' must not be empty");
  return name;
}

std::vector<Vec2> readTaskAreaOutline(Table& tab, const FileLoc& loc) {
  const Context& c = tab.ctx();
  const toml::node* cn = tab.get("corners");
  const toml::node* pn = tab.get("polygon");
  if (cn && pn) c.fail(*pn, "give either 'corners' or 'polygon', not both");
  if (!cn && !pn) throw InputError(loc, "a task area needs 'corners' = [[x0, y0], [x1, y1]] or a 'polygon'");
  if (cn) {
    const std::vector<Vec2> k = asPointList(c, *cn, "corners");
    if (k.size() != 2) c.fail(*cn, "'corners' must be two points [[x0, y0], [x1, y1]]");
    const Vec2 lo = glm::min(k[0], k[1]), hi = glm::max(k[0], k[1]);
    if (!(hi.x > lo.x && hi.y > lo.y)) c.fail(*cn, "'corners' span a zero area");
    return {lo, Vec2(hi.x, lo.y), hi, Vec2(lo.x, hi.y)};
  }
  std::vector<Vec2> outline = asPointList(c, *pn, "polygon");
  if (outline.size() < 3) c.fail(*pn, "'polygon' needs at least 3 points");
  if (!(std::abs(polygonArea(outline)) > 0.0)) c.fail(*pn, "'polygon' encloses a zero area");
  return outline;
}

namespace {

// The grid's 'name' (default grid<n>), unique among the case's grids.
void readGridName(Table& tab, int index, std::set<std::string>& names, GridSpec& g) {
  const Context& c = tab.ctx();
  g.name = entryName(tab, "grid" + std::to_string(index + 1));
  if (!names.insert(g.name).second) {
    const toml::node* n = tab.get("name");
    throw InputError(n ? c.at(*n) : g.loc, "two grids are named '" + g.name + "'");
  }
}

void readPointsGrid(Table& tab, GridSpec& g) {
  const Context& c = tab.ctx();
  g.kind = GridKind::kPoints;
  g.pointsFile = filePath(tab, "file", "sensor points file");
  for (const char* key : {"corners", "outline", "height", "spacing", "border", "normal", "origin", "axes"})
    if (const toml::node* n = tab.get(key)) c.fail(*n, keyText(key) + " applies to kind = \"plane\" grids only");
}

// A plane grid's area: 'corners' of a rectangle or an 'outline' polygon.
void readPlaneArea(Table& tab, const FileLoc& gridLoc, PlaneGridSpec& p) {
  const Context& c = tab.ctx();
  const toml::node* cn = tab.get("corners");
  const toml::node* on = tab.get("outline");
  if (cn && on) c.fail(*on, "give either 'corners' or 'outline', not both");
  if (!cn && !on) throw InputError(gridLoc, "a plane grid needs 'corners' = [[x0, y0], [x1, y1]] or an 'outline'");
  if (cn) {
    p.isRectangle = true;
    p.outline = asPointList(c, *cn, "corners");
    if (p.outline.size() != 2) c.fail(*cn, "'corners' must be two points [[x0, y0], [x1, y1]]");
    const Vec2 d = p.outline[1] - p.outline[0];
    if (!(std::abs(d.x * d.y) > 0.0)) c.fail(*cn, "'corners' span a zero area");
  } else {
    p.isRectangle = false;
    p.outline = asPointList(c, *on, "outline");
    if (p.outline.size() < 3) c.fail(*on, "'outline' needs at least 3 points");
    if (!(std::abs(polygonArea(p.outline)) > 0.0)) c.fail(*on, "'outline' encloses a zero area");
  }
}

// 'spacing': a number (m, > 0) or "auto" (unset: EN 12464-1's automatic spacing).
std::optional<double> readSpacing(Table& tab) {
  const Context& c = tab.ctx();
  const toml::node* sn = tab.get("spacing");
  if (!sn) return std::nullopt;
  if (sn->is_string()) {
    if (sn->as_string()->get() != "auto") c.fail(*sn, "'spacing' must be a number (m) or \"auto\"");
    return std::nullopt;
  }
  const double m = asNumber(c, *sn, "spacing");
  checkMin(tab, "spacing", m, 0.0, true, " m");
  return m;
}

// Where a plane grid lies: at a 'height' (horizontal) or by 'origin' and 'axes'.
void readPlanePlacement(Table& tab, const FileLoc& gridLoc, PlaneGridSpec& p) {
  const Context& c = tab.ctx();
  const toml::node* hn = tab.get("height");
  const toml::node* orn = tab.get("origin");
  const toml::node* axn = tab.get("axes");
  if (orn || axn) {
    // A plane in any orientation: origin + u·axes[0] + v·axes[1].
    if (hn) c.fail(*hn, "'height' applies to horizontal grids; a grid with 'origin' and 'axes' is placed by them");
    if (!orn || !axn) throw InputError(gridLoc, "a grid with 'origin' also needs 'axes' = [[ux, uy, uz], [vx, vy, vz]], and vice versa");
    p.origin = asVec3(c, *orn, "origin");
    const toml::array& ax = asArray(c, *axn, "axes", 2, "two directions [[ux, uy, uz], [vx, vy, vz]]");
    p.uAxis = asDirection(c, ax[0], "axes");
    p.vAxis = asDirection(c, ax[1], "axes");
    if (std::abs(glm::dot(p.uAxis, p.vAxis)) > 1e-6) c.fail(*axn, "the two 'axes' must be perpendicular");
  } else {
    if (!hn) throw InputError(gridLoc, "a plane grid needs 'height' (m) of the horizontal plane");
    p.origin = Vec3(0.0, 0.0, asNumber(c, *hn, "height"));
  }
}

void readPlaneGrid(Table& tab, GridSpec& g) {
  const Context& c = tab.ctx();
  g.kind = GridKind::kPlane;
  if (const toml::node* n = tab.get("file")) c.fail(*n, "'file' applies to kind = \"points\" grids only");
  PlaneGridSpec& p = g.plane;
  readPlaneArea(tab, g.loc, p);
  readPlanePlacement(tab, g.loc, p);
  p.spacingM = readSpacing(tab);
  p.borderM = numberOr(tab, "border", 0.0);
  checkMin(tab, "border", p.borderM, 0.0, false, " m");
  if (const toml::node* nn = tab.get("normal")) p.normal = asDirection(c, *nn, "normal");
}

// 'quantity', 'facing' and 'modelling' (docs/case-format.md#grid): what the points measure.
void readGridQuantity(Table& tab, GridSpec& g) {
  const Context& c = tab.ctx();
  const toml::node* qn = tab.get("quantity");
  const toml::node* fn = tab.get("facing");
  if (qn) {
    const std::string name = asString(c, *qn, "quantity");
    g.quantity = parseGridQuantity(name);
    if (!g.quantity)
      c.fail(*qn, "unknown quantity '" + name +
                      "' (expected horizontal, vertical, cylindrical, semi-cylindrical or hemispherical)");
    g.quantityLoc = c.at(*qn);
    if (const toml::node* nn = tab.get("normal"))
      c.fail(*nn, "give either 'normal' (planar illuminance on it) or 'quantity', not both");
    if (g.daylightFactor && *g.quantity != GridQuantity::kHorizontal)
      c.fail(*qn, "daylight_factor is defined on horizontal illuminance: quantity must be \"horizontal\"");
  }
  const bool wantsFacing = g.quantity && needsFacing(*g.quantity);
  if (fn) {
    if (!wantsFacing) c.fail(*fn, "'facing' applies to quantity = \"vertical\" or \"semi-cylindrical\" only");
    g.facing = asVec2(c, *fn, "facing", "a horizontal direction [x, y]");
    if (g.facing == Vec2(0.0)) c.fail(*fn, "'facing' must not be the zero vector");
    const std::optional<Vec2> unit = unitDirection(g.facing);
    if (!unit) c.fail(*fn, "'facing' cannot be normalised: its length underflows");
    g.facing = *unit;
  } else if (wantsFacing) {
    c.fail(*qn, "quantity \"" + std::string(gridQuantityKey(*g.quantity)) +
                    "\" needs 'facing' = [x, y], the horizontal direction it faces");
  }
  if (const toml::node* mn = tab.get("modelling")) {
    g.modelling = asBool(c, *mn, "modelling");
    g.modellingLoc = c.at(*mn);
  }
}

}  // namespace

void readGrid(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  Table tab(t, c, "[[grid]]");
  GridSpec g;
  g.loc = tab.loc();
  readGridName(tab, index, names, g);
  std::string kind = "plane";
  const toml::node* kn = tab.get("kind");
  if (kn) kind = asString(c, *kn, "kind");
  if (kind == "points") {
    readPointsGrid(tab, g);
  } else if (kind == "plane") {
    readPlaneGrid(tab, g);
  } else {
    c.fail(*kn, "unknown grid kind '" + kind + "' (expected plane or points)");
  }
  g.targetAverageLux = optNumber(tab, "target_average");
  if (g.targetAverageLux) checkMin(tab, "target_average", *g.targetAverageLux, 0.0, false, " lx");
  g.targetUniformity = optNumber(tab, "target_uniformity");
  if (g.targetUniformity) checkRange(tab, "target_uniformity", *g.targetUniformity, 0.0, 1.0, "");
  if (auto n = tab.get("daylight_factor")) g.daylightFactor = asBool(c, *n, "daylight_factor");
  readGridQuantity(tab, g);
  tab.finish();
  // Border and spacing problems (the border eats the area, a million-point grid) show here,
  // at the grid's line, rather than in the middle of a run.
  if (g.kind == GridKind::kPlane) countPlaneGrid(g.plane, g.loc);
  out.grids.push_back(std::move(g));
}

namespace {

// One of a task area's grids, horizontal at its height: named, placed and labelled.
GridSpec taskAreaGrid(const TaskAreaSpec& a, const std::string& name, GridSpec::Area area) {
  GridSpec g;
  g.name = name;
  g.loc = a.loc;
  g.taskArea = a.name;
  g.area = area;
  g.plane.origin = Vec3(0.0, 0.0, a.heightM);
  return g;
}

// A task area's band as a grid: the lattice over the task's box grown by `toM` (clipped to the
// room when given), keeping the points between fromM and toM of the task's outline.
GridSpec taskBand(const TaskAreaSpec& a, const std::string& name, GridSpec::Area area, double fromM, double toM,
                  const std::optional<std::array<Vec2, 2>>& room) {
  GridSpec g = taskAreaGrid(a, name, area);
  PlaneGridSpec& p = g.plane;
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Vec2& v : a.outline) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  lo -= Vec2(toM);
  hi += Vec2(toM);
  if (room) {
    lo = glm::max(lo, glm::min((*room)[0], (*room)[1]));
    hi = glm::min(hi, glm::max((*room)[0], (*room)[1]));
  }
  g.clipToRoom = !room;
  p.isRectangle = true;
  p.outline = {lo, hi};
  p.band = {a.outline, fromM, toM};
  // EN 12464-1's automatic spacing for the band itself: a long, narrow area's d is its width
  // (gridDimensionM), 0.5 m for the surrounding (0.1 m spacing), 3 m for the background (0.4 m),
  // not the box the lattice covers (which gave 2 points across the surrounding).
  p.spacingM = autoGridSpacingM(toM - fromM);
  return g;
}

}  // namespace

void readTaskArea(const Context& c, const toml::table& t, int index, std::set<std::string>& names, CaseFile& out) {
  if (isOutdoorTaskArea(c, t)) return readOutdoorTaskArea(c, t, index, names, out);  // EN 12464-2
  Table tab(t, c, "[[task_area]]");
  tab.get("standard");  // "en12464-1", the default
  TaskAreaSpec a;
  a.loc = tab.loc();
  a.name = entryName(tab, "task area " + std::to_string(index + 1));
  a.outline = readTaskAreaOutline(tab, a.loc);
  a.heightM = asNumber(c, tab.require("height"), "height");
  a.maintainedLux = asNumber(c, tab.require("maintained_illuminance"), "maintained_illuminance");
  checkMin(tab, "maintained_illuminance", a.maintainedLux, 0.0, true, " lx");
  a.uniformity = optNumber(tab, "uniformity");
  if (a.uniformity) checkRange(tab, "uniformity", *a.uniformity, 0.0, 1.0, "");
  if (const toml::node* n = tab.get("ugr_limit")) {
    a.ugrLimit = asNumber(c, *n, "ugr_limit");
    checkRange(tab, "ugr_limit", *a.ugrLimit, 0.0, 40.0, "");
  }
  a.ra = optNumber(tab, "ra");
  if (a.ra) checkRange(tab, "ra", *a.ra, 0.0, 100.0, "");
  std::optional<std::array<Vec2, 2>> room;
  if (const toml::node* n = tab.get("room")) {
    const std::vector<Vec2> k = asPointList(c, *n, "room");
    if (k.size() != 2) c.fail(*n, "'room' must be two corners [[x0, y0], [x1, y1]] of the space");
    room = std::array<Vec2, 2>{k[0], k[1]};
    for (const Vec2& v : a.outline)
      if (v.x < std::min(k[0].x, k[1].x) || v.x > std::max(k[0].x, k[1].x) || v.y < std::min(k[0].y, k[1].y) ||
          v.y > std::max(k[0].y, k[1].y))
        c.fail(*n, "the task area reaches outside its 'room'");
  }
  a.cylindricalLux = optNumber(tab, "cylindrical_illuminance");
  if (a.cylindricalLux) checkMin(tab, "cylindrical_illuminance", *a.cylindricalLux, 0.0, true, " lx");
  if (const toml::node* n = tab.get("modelling")) a.modelling = asBool(c, *n, "modelling");
  a.eyeHeightM = numberOr(tab, "eye_height", a.eyeHeightM);
  checkRange(tab, "eye_height", a.eyeHeightM, 0.5, 2.5, " m");
  std::optional<double> spacing;
  if (const toml::node* n = tab.get("spacing")) {
    spacing = asNumber(c, *n, "spacing");
    checkMin(tab, "spacing", *spacing, 0.0, true, " m");
  }
  a.spacingM = spacing;
  if (const toml::node* n = tab.get("emergency")) {
    const std::string v = asString(c, *n, "emergency");
    if (v != "high-risk") c.fail(*n, "'emergency' must be \"high-risk\" (EN 1838 4.4), got '" + v + "'");
    a.emergencyHighRisk = true;
  }
  tab.finish();

  GridSpec task = taskAreaGrid(a, a.name, GridSpec::Area::kTask);
  task.plane.isRectangle = false;
  task.plane.outline = a.outline;
  task.plane.spacingM = spacing;
  task.targetAverageLux = a.maintainedLux;
  task.targetUniformity = a.uniformity;
  GridSpec surrounding = taskBand(a, a.name + " surrounding", GridSpec::Area::kSurrounding, 0.0,
                                  kImmediateSurroundingWidthM, room);
  surrounding.targetAverageLux = immediateSurroundingLux(a.maintainedLux);
  surrounding.targetUniformity = kImmediateSurroundingUniformity;
  GridSpec background = taskBand(a, a.name + " background", GridSpec::Area::kBackground, kImmediateSurroundingWidthM,
                                 kImmediateSurroundingWidthM + kBackgroundWidthM, room);
  background.targetAverageLux = backgroundLux(a.maintainedLux);
  background.targetUniformity = kBackgroundUniformity;
  std::vector<GridSpec*> grids = {&task, &surrounding, &background};
  // Faces: cylindrical illuminance at the eyes of the people working there, over the task area.
  GridSpec faces = taskAreaGrid(a, a.name + " cylindrical", GridSpec::Area::kCylindrical);
  if (a.cylindricalLux || a.modelling) {
    faces.plane.origin.z = a.eyeHeightM;
    faces.plane.isRectangle = false;
    faces.plane.outline = a.outline;
    faces.plane.spacingM = spacing;
    faces.quantity = GridQuantity::kCylindrical;
    faces.quantityLoc = a.loc;
    faces.modelling = a.modelling;
    faces.modellingLoc = a.loc;
    faces.targetAverageLux = a.cylindricalLux;
    if (a.cylindricalLux) faces.targetUniformity = kCylindricalUniformity;
    grids.push_back(&faces);
  }
  for (GridSpec* g : grids) {
    if (!names.insert(g->name).second) throw InputError(a.loc, "two grids are named '" + g->name + "'");
    countPlaneGrid(g->plane, g->loc);
    out.grids.push_back(std::move(*g));
  }
  out.taskAreas.push_back(std::move(a));
}

void readSurfaceGrid(const Context& c, const toml::table& t, int index, std::set<std::string>& names,
                     CaseFile& out) {
  Table tab(t, c, "[[surface_grid]]");
  SurfaceGridSpec s;
  s.loc = tab.loc();
  s.name = entryName(tab, "surfaces " + std::to_string(index + 1));
  if (!names.insert(s.name).second) throw InputError(s.loc, "two grids are named '" + s.name + "'");
  const toml::node& pn = tab.require("surfaces");
  s.patternsLoc = c.at(pn);
  const toml::array& patterns = asArray(c, pn, "surfaces", 0, "an array of surface identifiers or patterns");
  if (patterns.empty()) c.fail(pn, "'surfaces' must name at least one surface (an identifier or a pattern such as \"wall_*\")");
  for (const toml::node& n : patterns) {
    s.patterns.push_back(asString(c, n, "surfaces"));
    if (s.patterns.back().empty()) c.fail(n, "'surfaces' holds an empty identifier");
  }
  if (const toml::node* n = tab.get("room_type")) {
    const std::string key = asString(c, *n, "room_type");
    s.roomType = parseRoomType(key);
    if (!s.roomType)
      c.fail(*n, "unknown room_type '" + key + "' (expected general, office, education, school or healthcare)");
  }
  if (const toml::node* n = tab.get("side")) {
    const std::string side = asString(c, *n, "side");
    if (side == "auto") s.side = SurfaceGridSpec::Side::kAuto;
    else if (side == "front") s.side = SurfaceGridSpec::Side::kFront;
    else if (side == "back") s.side = SurfaceGridSpec::Side::kBack;
    else c.fail(*n, "unknown side '" + side + "' (expected auto, front or back)");
  }
  s.spacingM = readSpacing(tab);
  s.offsetM = numberOr(tab, "offset", s.offsetM);
  checkRange(tab, "offset", s.offsetM, 0.0, 0.1, " m");
  s.targetAverageLux = optNumber(tab, "target_average");
  if (s.targetAverageLux) checkMin(tab, "target_average", *s.targetAverageLux, 0.0, false, " lx");
  s.targetUniformity = optNumber(tab, "target_uniformity");
  if (s.targetUniformity) checkRange(tab, "target_uniformity", *s.targetUniformity, 0.0, 1.0, "");
  tab.finish();
  out.surfaceGrids.push_back(std::move(s));
}

}  // namespace candela
