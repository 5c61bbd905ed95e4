#include "study/grids/surface_grids.h"

#include "base/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace candela {

bool globMatch(const std::string& pattern, const std::string& name) {
  // Greedy with one backtrack point: the last '*' seen and where it started to match.
  std::size_t p = 0, n = 0, star = std::string::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || (pattern[p] != '*' && pattern[p] == name[n]))) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

std::optional<Vec3> sideFacing(const Vec3& front, const Vec3& onPlane, const Vec3& inside) {
  const double d = glm::dot(inside - onPlane, front);
  if (std::abs(d) < 0.01) return std::nullopt;
  return d > 0.0 ? front : -front;
}

namespace {

// A flat surface the entry matched: its outline (world, m), unit front normal and identifier.
struct Piece {
  std::vector<Vec3> outline;
  Vec3 normal{0.0};
  std::string name;
};

// Surfaces of one plane (normals equal up to sign, within 1 mm of one another along it).
struct PlaneGroup {
  Vec3 normal{0.0};  // the first piece's front normal
  double offsetM = 0.0;  // normal · point on the plane
  std::vector<const Piece*> pieces;
  std::vector<Piece> covering;  // other surfaces lying on the plane (holes of its grid)
  bool holds(const Piece& p) const {
    const double c = glm::dot(normal, p.normal);
    if (std::abs(c) < 1.0 - 1e-9) return false;
    return std::abs(glm::dot(normal, p.outline.front()) - offsetM) < 1e-3;
  }
  // Whether every vertex of p lies within 2 mm of the plane (p parallel to it).
  bool covers(const Piece& p) const {
    if (std::abs(glm::dot(normal, p.normal)) < 1.0 - 1e-9) return false;
    return std::all_of(p.outline.begin(), p.outline.end(),
                       [&](const Vec3& v) { return std::abs(glm::dot(normal, v) - offsetM) < 2e-3; });
  }
};

[[noreturn]] void notFlat(const SurfaceGridSpec& s, const std::string& name, ShapeType t) {
  const char* what = t == ShapeType::kSphere ? "a sphere" : t == ShapeType::kCone ? "a cone or cylinder" : "a ring";
  throw InputError(s.patternsLoc, "surface '" + name + "' is " + what +
                                      ": a surface grid lies on flat surfaces (polygons and triangles) only");
}

// Surface `id`'s outline and front normal when it is flat (a polygon or triangle); else none.
std::optional<Piece> flatPiece(const Scene& scene, uint32_t id) {
  const Shape sh = scene.surface(id);
  Piece p;
  p.normal = sh.n;
  if (sh.type == ShapeType::kPolygon)
    p.outline.assign(scene.vertices.points.begin() + sh.firstVertex,
                     scene.vertices.points.begin() + sh.firstVertex + sh.vertexCount);
  else if (sh.type == ShapeType::kTriangle)
    p.outline = {sh.a, sh.a + sh.b, sh.a + sh.c};
  else
    return std::nullopt;
  return p;
}

// Every surface whose identifier matches a pattern (marked in `matched`); each pattern must
// match one.
std::vector<Piece> matchedPieces(const SurfaceGridSpec& s, const Scene& scene, std::vector<bool>& matched) {
  std::vector<bool> used(s.patterns.size(), false);
  matched.assign(scene.surfaceCount(), false);
  std::vector<Piece> pieces;
  const std::string* last = nullptr;  // mesh runs share a name: tested once a run
  bool lastMatches = false;
  for (uint32_t id = 0; id < scene.surfaceCount(); ++id) {
    const std::string& name = scene.surfaceName(id);
    if (&name != last) {
      last = &name;
      lastMatches = false;
      for (std::size_t k = 0; k < s.patterns.size(); ++k)
        if (globMatch(s.patterns[k], name)) lastMatches = used[k] = true;
    }
    if (!lastMatches) continue;
    std::optional<Piece> p = flatPiece(scene, id);
    if (!p) notFlat(s, name, scene.shapes[id].type);
    p->name = name;
    matched[id] = true;
    pieces.push_back(std::move(*p));
  }
  for (std::size_t k = 0; k < s.patterns.size(); ++k)
    if (!used[k]) throw InputError(s.patternsLoc, "no surface of the scene is named '" + s.patterns[k] + "'");
  return pieces;
}

std::vector<PlaneGroup> byPlane(const SurfaceGridSpec& s, const std::vector<Piece>& pieces) {
  std::vector<PlaneGroup> groups;
  for (const Piece& p : pieces) {
    auto g = std::find_if(groups.begin(), groups.end(), [&](const PlaneGroup& q) { return q.holds(p); });
    if (g == groups.end()) {
      if (groups.size() == kMaxSurfaceGridPlanes)
        throw InputError(s.patternsLoc, "the surfaces matched lie in more than " +
                                            std::to_string(kMaxSurfaceGridPlanes) +
                                            " planes (a curved or detailed mesh): name the flat surfaces to assess");
      groups.push_back({p.normal, glm::dot(p.normal, p.outline.front()), {}, {}});
      g = groups.end() - 1;
    }
    g->pieces.push_back(&p);
  }
  return groups;
}

// The surfaces not matched that lie on a group's plane: the back of a cabinet standing against
// a wall, a pane or a luminaire flush with a ceiling. The wall is not there to be lit: its grid
// leaves them out.
void addCovering(const Scene& scene, const std::vector<bool>& matched, std::vector<PlaneGroup>& groups) {
  for (uint32_t id = 0; id < scene.surfaceCount(); ++id) {
    if (matched[id]) continue;
    std::optional<Piece> p = flatPiece(scene, id);
    if (!p) continue;
    for (PlaneGroup& g : groups)
      if (g.covers(*p)) g.covering.push_back(*p);
  }
}

// Wall: facing within 30° of horizontal; ceiling: facing within 30° of straight down; floor: up.
RoomSurface classify(const Vec3& facing) {
  const double limit = std::cos(glm::radians(60.0));  // sin 30°
  if (std::abs(facing.z) <= limit) return RoomSurface::kWall;
  if (facing.z <= -std::cos(glm::radians(30.0))) return RoomSurface::kCeiling;
  if (facing.z >= std::cos(glm::radians(30.0))) return RoomSurface::kFloor;
  return RoomSurface::kNone;
}

// A group's label from its identifiers (sorted, each once): its one identifier, or what they
// share ("wall_south" for wall_south_below and wall_south_pier1), or the first with a count.
std::string groupLabel(const std::vector<std::string>& names) {
  if (names.size() == 1) return names.front();
  std::string common = names.front();
  for (const std::string& n : names) {
    std::size_t k = 0;
    while (k < common.size() && k < n.size() && common[k] == n[k]) ++k;
    common.resize(k);
  }
  while (!common.empty() && (common.back() == '_' || common.back() == '-' || common.back() == '.' || common.back() == ' '))
    common.pop_back();
  if (common.size() >= 2) return common;
  return names.front() + " and " + std::to_string(names.size() - 1) + " more";
}

GridSpec groupGrid(const SurfaceGridSpec& s, const PlaneGroup& g, const Vec3& facing) {
  GridSpec out;
  out.loc = s.loc;
  out.surfaceGrid = s.name;
  out.roomSurface = classify(facing);
  PlaneGridSpec& p = out.plane;
  // Horizontal surfaces keep the plan's axes (a reflected ceiling plan reads like the floor
  // plan); walls run u along the wall, to the right of one facing it, and v up it.
  if (std::abs(facing.z) > 1.0 - 1e-9) {
    p.uAxis = Vec3(1, 0, 0);
    p.vAxis = Vec3(0, 1, 0);
  } else {
    p.uAxis = glm::normalize(glm::cross(Vec3(0, 0, 1), facing));
    p.vAxis = glm::cross(facing, p.uAxis);
  }
  p.normal = facing;
  const Vec3 onPlane = g.pieces.front()->outline.front();
  p.origin = glm::dot(facing, onPlane) * facing + s.offsetM * facing;
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  std::vector<std::string> names;
  for (const Piece* piece : g.pieces) {
    std::vector<Vec2>& uv = p.pieces.emplace_back();
    for (const Vec3& v : piece->outline) {
      uv.emplace_back(glm::dot(v - p.origin, p.uAxis), glm::dot(v - p.origin, p.vAxis));
      lo = glm::min(lo, uv.back());
      hi = glm::max(hi, uv.back());
    }
    names.push_back(piece->name);
  }
  // A wall's elevation runs from u = 0 at its left end, as one facing it sees it (v stays the
  // height for a vertical wall); horizontal surfaces keep the plan's x and y.
  if (std::abs(facing.z) <= 1.0 - 1e-9) {
    p.origin += lo.x * p.uAxis;
    for (std::vector<Vec2>& piece : p.pieces)
      for (Vec2& uv : piece) uv.x -= lo.x;
    hi.x -= lo.x;
    lo.x = 0.0;
  }
  for (const Piece& c : g.covering) {
    std::vector<Vec2>& uv = p.holes.emplace_back();
    for (const Vec3& v : c.outline) uv.emplace_back(glm::dot(v - p.origin, p.uAxis), glm::dot(v - p.origin, p.vAxis));
  }
  p.isRectangle = true;
  p.outline = {lo, hi};
  p.spacingM = s.spacingM;
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  out.name = s.name + ": " + groupLabel(names);
  out.onSurfaces = std::move(names);
  GridTargets t;
  if (s.roomType) t = roomSurfaceTargets(*s.roomType, out.roomSurface);
  out.targetAverageLux = s.targetAverageLux ? s.targetAverageLux : t.averageLux;
  out.targetUniformity = s.targetUniformity ? s.targetUniformity : t.uniformity;
  return out;
}

Vec3 boxCentre(const std::vector<Piece>& pieces) {
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Piece& p : pieces)
    for (const Vec3& v : p.outline) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  return 0.5 * (lo + hi);
}

}  // namespace

std::vector<GridSpec> surfaceGridSpecs(const SurfaceGridSpec& s, const Scene& scene) {
  std::vector<bool> matched;
  const std::vector<Piece> pieces = matchedPieces(s, scene, matched);
  std::vector<PlaneGroup> groups = byPlane(s, pieces);
  addCovering(scene, matched, groups);
  // The room is taken to be where the matched surfaces' box is centred (the middle of a room's
  // walls), else the scene's centre (a ceiling alone: its box lies in its plane).
  const Vec3 matchedCentre = boxCentre(pieces);
  const Box bounds = scene.bounds();
  const Vec3 sceneCentre = 0.5 * (bounds.lo + bounds.hi);
  std::vector<GridSpec> grids;
  std::set<std::string> names;
  for (const PlaneGroup& g : groups) {
    const Vec3 onPlane = g.pieces.front()->outline.front();
    Vec3 facing = g.normal;
    if (s.side == SurfaceGridSpec::Side::kBack) facing = -g.normal;
    if (s.side == SurfaceGridSpec::Side::kAuto)
      facing = sideFacing(g.normal, onPlane, matchedCentre)
                   .value_or(sideFacing(g.normal, onPlane, sceneCentre).value_or(g.normal));
    GridSpec grid = groupGrid(s, g, facing);
    // Two planes with one label (a mesh named "walls"): numbered.
    if (!names.insert(grid.name).second) {
      int k = 2;
      while (!names.insert(grid.name + " (" + std::to_string(k) + ")").second) ++k;
      grid.name += " (" + std::to_string(k) + ")";
    }
    if (countPlaneGrid(grid.plane, s.loc) == 0) continue;  // a sliver narrower than the spacing
    grids.push_back(std::move(grid));
  }
  if (grids.empty())
    throw InputError(s.loc, "no grid point falls on the surfaces matched: they are narrower than the spacing");
  return grids;
}

CaseFile withSurfaceGrids(const CaseFile& c, const Scene& scene) {
  CaseFile out = c;
  std::set<std::string> names;
  for (const GridSpec& g : c.grids) names.insert(g.name);
  for (const SurfaceGridSpec& s : c.surfaceGrids)
    for (GridSpec& g : surfaceGridSpecs(s, scene)) {
      if (!names.insert(g.name).second) throw InputError(s.loc, "two grids are named '" + g.name + "'");
      out.grids.push_back(std::move(g));
    }
  return out;
}

}  // namespace candela
