#include "study/grids/plan_section.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <tuple>

#include "engine/materials/family.h"
#include "reports/plan_svg.h"

namespace candela {

namespace {

// What a surface is on a plan, from its material.
enum class Role { kNone, kOpaque, kGlazing };

Role roleOf(const Material& m) {
  const MaterialFamily& family = familyOf(m);
  if (family.transmitting()) return Role::kGlazing;  // illum too: mkillum's windows
  // void is invisible; light and glow surfaces are a luminaire's or a source's own geometry.
  if (family.role() == HitRole::kAbsorb || family.emits()) return Role::kNone;
  return Role::kOpaque;
}

// A flat surface of the scene: its vertices (m) in order, unit normal and role.
struct Flat {
  std::span<const Vec3> points;
  Vec3 normal{0.0, 0.0, 1.0};
  Role role = Role::kNone;
  bool mesh = false;
};

// Calls f(flat) for every triangle and polygon shape and every mesh triangle that is not a
// luminaire's or invisible (Role::kNone); degenerate mesh triangles (no normal) are skipped.
template <class F>
void forEachFlat(const Scene& scene, F&& f) {
  std::array<Vec3, 3> tri;
  for (const Shape& s : scene.shapes) {
    const Role role = roleOf(scene.materials[s.material]);
    if (role == Role::kNone) continue;
    if (s.type == ShapeType::kTriangle) {
      tri = {s.a, s.a + s.b, s.a + s.c};
      f(Flat{tri, s.n, role, false});
    } else if (s.type == ShapeType::kPolygon) {
      f(Flat{std::span<const Vec3>(scene.vertices.points).subspan(s.firstVertex, s.vertexCount), s.n, role, false});
    }
  }
  const TriangleMesh& m = scene.mesh;
  for (std::size_t r = 0; r < m.runs.size(); ++r) {
    const Role role = roleOf(scene.materials[m.runs[r].material]);
    if (role == Role::kNone) continue;
    const std::size_t end = r + 1 < m.runs.size() ? m.runs[r + 1].firstTriangle : m.triangles.size();
    for (std::size_t t = m.runs[r].firstTriangle; t < end; ++t) {
      const auto& v = m.triangles[t];
      tri = {m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]]};
      const Vec3 c = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
      const double len = glm::length(c);
      if (len > 0.0) f(Flat{tri, c / len, role, true});
    }
  }
}

struct ZRange {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
};

ZRange zRange(std::span<const Vec3> pts) {
  ZRange r;
  for (const Vec3& p : pts) r.lo = std::min(r.lo, p.z), r.hi = std::max(r.hi, p.z);
  return r;
}

// Whether the surface's plan bounding box meets the region [lo, hi].
bool meetsRegion(std::span<const Vec3> pts, const Vec2& lo, const Vec2& hi) {
  Vec2 a(std::numeric_limits<double>::infinity()), b(-std::numeric_limits<double>::infinity());
  for (const Vec3& p : pts) a = glm::min(a, Vec2(p)), b = glm::max(b, Vec2(p));
  return a.x <= hi.x && a.y <= hi.y && b.x >= lo.x && b.y >= lo.y;
}

// Shoelace area (m²) of a plan polygon.
double planArea(const std::vector<Vec2>& poly) {
  double a = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * std::abs(a);
}

// The area (m²) of the surface's plan projection inside [lo, hi]: Sutherland & Hodgman (1974)
// against the rectangle's four sides. A concave polygon may leave zero-width bridges along a side,
// which add no area.
double areaInside(std::span<const Vec3> pts, const Vec2& lo, const Vec2& hi) {
  std::vector<Vec2> poly, next;
  for (const Vec3& p : pts) poly.emplace_back(p.x, p.y);
  for (int side = 0; side < 4 && !poly.empty(); ++side) {
    const int axis = side % 2;
    const bool keepAbove = side < 2;  // sides 0, 1: x >= lo.x, y >= lo.y; 2, 3: x <= hi.x, y <= hi.y
    const double bound = keepAbove ? lo[axis] : hi[axis];
    auto inside = [&](const Vec2& p) { return keepAbove ? p[axis] >= bound : p[axis] <= bound; };
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2& p = poly[i];
      const Vec2& q = poly[(i + 1) % poly.size()];
      if (inside(p)) next.push_back(p);
      if (inside(p) != inside(q)) next.push_back(p + (bound - p[axis]) / (q[axis] - p[axis]) * (q - p));
    }
    poly.swap(next);
  }
  return poly.size() >= 3 ? planArea(poly) : 0.0;
}

// The horizontal direction along which a surface of unit normal n meets a horizontal plane
// (n × z, normalised); none for a horizontal surface.
std::optional<Vec2> cutDirection(const Vec3& n) {
  const Vec2 d(n.y, -n.x);
  const double len = glm::length(d);
  if (len < 1e-9) return std::nullopt;
  return d / len;
}

// The segments where the plane z = cut crosses the surface: its edges' crossings sorted along the
// line the two planes share and paired (even–odd: a concave polygon, or one with a hole joined by
// a seam, gives several). A vertex on the plane counts as above it, so that no crossing is counted
// twice, and a surface whose top edge lies in the plane gives that edge.
void cutFlat(const Flat& f, double cut, std::vector<Vec2>& crossings, std::vector<PlanSegment>& out) {
  const std::optional<Vec2> dir = cutDirection(f.normal);
  if (!dir) return;
  crossings.clear();
  const std::size_t n = f.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = f.points[i];
    const Vec3& b = f.points[(i + 1) % n];
    const double da = a.z - cut, db = b.z - cut;
    if ((da >= 0.0) == (db >= 0.0)) continue;
    const Vec3 p = a + (da / (da - db)) * (b - a);
    crossings.emplace_back(p.x, p.y);
  }
  std::sort(crossings.begin(), crossings.end(),
            [&](const Vec2& p, const Vec2& q) { return glm::dot(p, *dir) < glm::dot(q, *dir); });
  for (std::size_t i = 0; i + 1 < crossings.size(); i += 2)
    if (glm::length(crossings[i + 1] - crossings[i]) > 1e-9) out.push_back({crossings[i], crossings[i + 1]});
}

// A vertical surface's plan projection: the segment between its extreme points along the wall.
std::optional<PlanSegment> projectVertical(const Flat& f) {
  const std::optional<Vec2> dir = cutDirection(f.normal);
  if (!dir || f.points.empty()) return std::nullopt;
  Vec2 lo(f.points[0]), hi(f.points[0]);
  for (const Vec3& p : f.points) {
    const Vec2 q(p);
    if (glm::dot(q, *dir) < glm::dot(lo, *dir)) lo = q;
    if (glm::dot(q, *dir) > glm::dot(hi, *dir)) hi = q;
  }
  if (glm::length(hi - lo) <= 1e-9) return std::nullopt;
  return PlanSegment{lo, hi};
}

// Merges touching collinear segments (to 1 mm and 10⁻⁴ rad; pieces of one wall, a mesh wall's
// triangles): lines keyed by their direction and offset, then the pieces along each line joined
// where they overlap or meet. Lines that fall on either side of a key's rounding stay apart,
// which costs elements, never geometry.
void mergeCollinear(std::vector<PlanSegment>& segments) {
  struct Piece {
    long long angle, offset;
    double t0, t1;
    Vec2 a, b;  // a at t0, b at t1
  };
  std::vector<Piece> pieces;
  pieces.reserve(segments.size());
  for (const PlanSegment& s : segments) {
    Vec2 d = glm::normalize(s.b - s.a);
    if (d.y < 0.0 || (d.y == 0.0 && d.x < 0.0)) d = -d;  // one direction per line: angle in [0, π)
    const double angle = std::atan2(d.y, d.x), offset = d.x * s.a.y - d.y * s.a.x;
    double t0 = glm::dot(d, s.a), t1 = glm::dot(d, s.b);
    Vec2 a = s.a, b = s.b;
    if (t0 > t1) std::swap(t0, t1), std::swap(a, b);
    pieces.push_back({std::llround(angle / 1e-4), std::llround(offset / 1e-3), t0, t1, a, b});
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& p, const Piece& q) {
    return std::tie(p.angle, p.offset, p.t0) < std::tie(q.angle, q.offset, q.t0);
  });
  segments.clear();
  for (std::size_t i = 0; i < pieces.size();) {
    Piece run = pieces[i];
    std::size_t j = i + 1;
    for (; j < pieces.size() && pieces[j].angle == run.angle && pieces[j].offset == run.offset &&
           pieces[j].t0 <= run.t1 + 1e-3;
         ++j)
      if (pieces[j].t1 > run.t1) run.t1 = pieces[j].t1, run.b = pieces[j].b;
    segments.push_back({run.a, run.b});
    i = j;
  }
}

// A footprint's identity: its vertices to 1 mm, in any order, so that a box's top and bottom
// faces (whose vertices run opposite ways) give one outline.
using FootprintKey = std::vector<std::pair<long long, long long>>;

FootprintKey footprintKey(const std::vector<Vec2>& outline) {
  FootprintKey key;
  for (const Vec2& p : outline) key.emplace_back(std::llround(p.x * 1e3), std::llround(p.y * 1e3));
  std::sort(key.begin(), key.end());
  return key;
}

// Keeps at most `room` of `from`, counting the rest in `dropped`; returns what is left of room.
std::size_t keepUpTo(std::vector<PlanSegment>& from, std::size_t room, std::size_t& dropped) {
  if (from.size() > room) {
    dropped += from.size() - room;
    from.resize(room);
  }
  return room - from.size();
}

}  // namespace

double floorLevel(const Scene& scene, double gridZ, const Vec2& lo, const Vec2& hi) {
  // Levels to the cm: area (m²) inside the region and area-weighted height.
  std::map<long long, std::pair<double, double>> levels;
  forEachFlat(scene, [&](const Flat& f) {
    if (f.role != Role::kOpaque || std::abs(f.normal.z) < kHorizontalNormalZ) return;
    const ZRange z = zRange(f.points);
    // A surface sloping by more than 5 cm is a ramp or a roof, not a level.
    if (z.hi - z.lo > 0.05 || z.hi > gridZ + kFurnitureAboveFloorM || !meetsRegion(f.points, lo, hi)) return;
    const double a = areaInside(f.points, lo, hi), mid = 0.5 * (z.lo + z.hi);
    if (a <= 0.0) return;
    auto& [area, weighted] = levels[std::llround(mid * 100.0)];
    area += a;
    weighted += a * mid;
  });
  if (levels.empty()) {
    const Box b = scene.bounds();
    return b.empty() ? gridZ : b.lo.z;
  }
  double largest = 0.0;
  for (const auto& [key, level] : levels) largest = std::max(largest, level.first);
  for (auto it = levels.rbegin(); it != levels.rend(); ++it)
    if (it->second.first >= 0.7 * largest) return it->second.second / it->second.first;
  return levels.begin()->second.second / levels.begin()->second.first;  // not reached
}

double planCutHeight(double gridZ, double floorZ) {
  return gridZ - floorZ < kFloorGridM ? floorZ + kFloorPlanCutM : gridZ;
}

PlanSection planSection(const Scene& scene, const SectionRequest& request, const SectionLimits& limits) {
  PlanSection s;
  const double cut = request.cutHeightM;
  s.cutHeightM = cut;
  s.floorLevelM = request.floorLevelM;
  const Vec2 lo = request.lo, hi = request.hi;
  // Raw segments before merging are bounded too (a fine mesh cut gives one per triangle crossed):
  // past this the rest are counted, not kept.
  const std::size_t rawCap = 8 * limits.maxSegments;
  std::size_t raw = 0, footprintVertices = 0;
  std::vector<Vec2> crossings;
  std::set<FootprintKey> footprints;
  forEachFlat(scene, [&](const Flat& f) {
    const ZRange z = zRange(f.points);
    if (z.hi < s.floorLevelM + kFurnitureAboveFloorM || !meetsRegion(f.points, lo, hi)) return;
    if (z.lo < cut && z.hi >= cut) {
      std::vector<PlanSegment>& out = f.role == Role::kGlazing ? s.openings : s.walls;
      const std::size_t before = out.size();
      cutFlat(f, cut, crossings, out);
      const std::size_t made = out.size() - before;
      if (raw + made > rawCap) {
        s.droppedSegments += made;
        out.resize(before);
      } else {
        raw += made;
      }
      return;
    }
    if (f.role == Role::kGlazing && z.lo >= cut && z.lo < cut + kOpeningsAboveM &&
        std::abs(f.normal.z) <= kVerticalNormalZ) {
      const std::optional<PlanSegment> p = projectVertical(f);
      if (!p) return;
      if (raw < rawCap) {
        s.openingsAbove.push_back(*p);
        ++raw;
      } else {
        ++s.droppedSegments;
      }
      return;
    }
    if (f.role == Role::kOpaque && z.hi <= cut && z.lo > s.floorLevelM + kFurnitureAboveFloorM &&
        std::abs(f.normal.z) >= kHorizontalNormalZ) {
      // The cap comes first: past it nothing more is held (a terrain's 10⁶ triangles would
      // otherwise all enter the set of footprints seen).
      if (footprintVertices + f.points.size() > limits.maxFootprintVertices) {
        ++s.droppedFootprints;
        return;
      }
      PlanFootprint fp;
      fp.outlined = !f.mesh;
      for (const Vec3& p : f.points) fp.outline.emplace_back(p.x, p.y);
      if (planArea(fp.outline) <= 1e-9 || !footprints.insert(footprintKey(fp.outline)).second) return;
      footprintVertices += fp.outline.size();
      s.furniture.push_back(std::move(fp));
    }
  });
  for (const Shape& sh : scene.shapes) {
    if (isFlat(sh) && sh.type != ShapeType::kRing) continue;
    if (roleOf(scene.materials[sh.material]) == Role::kNone) continue;
    const Box b = shapeBounds(sh, scene.vertices);
    if (b.lo.z < cut && b.hi.z >= cut && b.lo.x <= hi.x && b.lo.y <= hi.y && b.hi.x >= lo.x && b.hi.y >= lo.y)
      ++s.skippedCurved;
  }
  mergeCollinear(s.walls);
  mergeCollinear(s.openings);
  mergeCollinear(s.openingsAbove);
  std::size_t room = limits.maxSegments;
  room = keepUpTo(s.openings, room, s.droppedSegments);
  room = keepUpTo(s.openingsAbove, room, s.droppedSegments);
  keepUpTo(s.walls, room, s.droppedSegments);
  return s;
}

std::optional<double> gridPlanHeight(const PreparedGrid& g) {
  if (g.spec->roomSurface == RoomSurface::kCeiling) return std::nullopt;
  if (g.spec->kind == GridKind::kPlane)
    return inPlanCoordinates(g.spec->plane) ? std::optional<double>(g.spec->plane.origin.z) : std::nullopt;
  if (g.grid.points.empty()) return std::nullopt;
  ZRange z;
  double sum = 0.0;
  for (const SensorPoint& p : g.grid.points) {
    z.lo = std::min(z.lo, p.position.z), z.hi = std::max(z.hi, p.position.z);
    sum += p.position.z;
  }
  if (z.hi - z.lo > 0.1) return std::nullopt;
  return sum / static_cast<double>(g.grid.points.size());
}

void addPlanSections(ReportData& data, const Scene& scene, const std::vector<PreparedGrid>& grids,
                     const SectionLimits& limits) {
  if (data.grids.size() != grids.size()) return;
  // A plan region: the union of some grids' plan extents (m).
  struct Region {
    Vec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    std::vector<std::size_t> grids;
    void add(std::size_t g, const PlanExtent& e) {
      lo = glm::min(lo, e.lo), hi = glm::max(hi, e.hi);
      grids.push_back(g);
    }
  };
  // The grids by height (mm).
  std::map<long long, std::pair<double, Region>> heights;
  for (std::size_t i = 0; i < grids.size(); ++i) {
    if (!data.grids[i].planIsXY || data.grids[i].values.empty()) continue;
    const std::optional<double> h = gridPlanHeight(grids[i]);
    if (!h) continue;
    auto& [z, region] = heights[std::llround(*h * 1e3)];
    z = *h;
    region.add(i, planExtent(data.grids[i].layout));
  }
  // The cuts (mm, and whether raised above a floor-level grid's floor: the caption says so), one
  // section each.
  std::map<std::pair<long long, bool>, std::pair<SectionRequest, Region>> cuts;
  for (const auto& [key, level] : heights) {
    const auto& [z, region] = level;
    const double floorZ = floorLevel(scene, z, region.lo - Vec2(1.0), region.hi + Vec2(1.0));
    const double cut = planCutHeight(z, floorZ);
    auto& [request, cutRegion] = cuts[{std::llround(cut * 1e3), cut != z}];
    request.cutHeightM = cut;
    request.floorLevelM = floorZ;
    for (std::size_t g : region.grids) cutRegion.add(g, planExtent(data.grids[g].layout));
  }
  for (auto& [key, cut] : cuts) {
    auto& [request, region] = cut;
    // Walls along a plan's edge (a grid up to the walls) lie on its extent: a margin keeps them.
    request.lo = region.lo - Vec2(0.1);
    request.hi = region.hi + Vec2(0.1);
    PlanSection section = planSection(scene, request, limits);
    section.raisedAboveFloor = key.second;
    for (std::size_t g : region.grids) data.grids[g].planSection = static_cast<int>(data.planSections.size());
    data.planSections.push_back(std::move(section));
  }
}

}  // namespace candela
