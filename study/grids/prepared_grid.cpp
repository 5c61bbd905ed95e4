#include "study/grids/prepared_grid.h"

#include "study/output_names.h"

#include "base/error.h"
#include "reports/csv_writer.h"
#include "reports/plan_svg.h"


namespace candela {

namespace {

std::string fixed(double v, int decimals) { return formatFixed(v, decimals); }

std::string vecText(const Vec3& v) {
  return "(" + formatNumber(v.x, 4) + ", " + formatNumber(v.y, 4) + ", " + formatNumber(v.z, 4) + ")";
}

bool isHorizontalUp(const PlaneGridSpec& p) {
  const Vec3 n = p.normal ? *p.normal : glm::cross(p.uAxis, p.vAxis);
  return inPlanCoordinates(p) && glm::length(n - Vec3(0, 0, 1)) < 1e-9;
}

// ", facing (x, y)" for the quantities that face a plan direction, else "".
std::string facingText(const GridSpec& s) {
  if (!s.quantity || !needsFacing(*s.quantity)) return "";
  return ", facing (" + formatNumber(s.facing.x, 4) + ", " + formatNumber(s.facing.y, 4) + ")";
}

}  // namespace

int estimatesPerPoint(const GridSpec& spec) {
  if (!spec.modelling) return 1;
  const bool horizontal = spec.quantity ? *spec.quantity == GridQuantity::kHorizontal
                                        : spec.kind == GridKind::kPlane && isHorizontalUp(spec.plane);
  const bool cylindrical = spec.quantity && *spec.quantity == GridQuantity::kCylindrical;
  return 1 + !horizontal + !cylindrical;
}

// One line a reader of the report understands: orientation, height, spacing, border.
std::string gridDescription(const PreparedGrid& g) {
  const GridSpec& s = *g.spec;
  if (s.kind == GridKind::kPoints) return "sensor points from " + s.pointsFile.filename().string() + facingText(s);
  const PlaneGridSpec& p = s.plane;
  if (!s.surfaceGrid.empty()) {
    std::string d = "on the " + std::string(roomSurfaceName(s.roomSurface)) + " surface";
    d += s.onSurfaces.size() == 1 ? " " : "s ";
    for (std::size_t k = 0; k < s.onSurfaces.size() && k < 8; ++k) d += (k ? ", " : "") + s.onSurfaces[k];
    if (s.onSurfaces.size() > 8) d += " and " + std::to_string(s.onSurfaces.size() - 8) + " more";
    d += ", sensors facing " + vecText(*p.normal) + ", spacing " + fixed(g.grid.spacingM.x, 2) + " × " +
         fixed(g.grid.spacingM.y, 2) + " m";
    if (!p.holes.empty())
      d += "; no points where " + std::to_string(p.holes.size()) + " other surface" +
           (p.holes.size() == 1 ? " lies" : "s lie") + " on it (glazing, a cabinet's back)";
    return d;
  }
  std::string d = isHorizontalUp(p) ? "horizontal, " + fixed(p.origin.z, 2) + " m above floor level"
                                    : "plane through " + vecText(p.origin) + " m, sensors facing " +
                                          vecText(g.grid.points.front().normal);
  d += ", spacing " + fixed(g.grid.spacingM.x, 2) + " × " + fixed(g.grid.spacingM.y, 2) + " m";
  if (p.borderM > 0.0) d += ", border " + fixed(p.borderM, 2) + " m";
  return d + facingText(s);
}

PlanLayout planLayout(const PreparedGrid& g) {
  PlanLayout l;
  if (g.grid.regular) {
    l.regular = true;
    l.columns = g.grid.columns;
    l.rows = g.grid.rows;
    l.originM = g.grid.latticeOriginUv;
    l.spacingM = g.grid.spacingM;
    l.cells = g.grid.cell;
    l.planPositions = g.grid.uv;
    const PlaneGridSpec& p = g.spec->plane;
    l.outline = p.band.inner.empty() ? p.outline : std::vector<Vec2>{};  // a band: its points show it
    if (p.band.inner.empty() && p.isRectangle && p.outline.size() == 2) {
      const Vec2 a = p.outline[0], b = p.outline[1];
      l.outline = {a, Vec2(b.x, a.y), b, Vec2(a.x, b.y)};
    }
  } else {
    // Points files: drawn as dots at their plan (x, y) positions.
    for (const SensorPoint& s : g.grid.points) l.planPositions.emplace_back(s.position.x, s.position.y);
  }
  return l;
}

std::vector<PreparedGrid> prepareGrids(const CaseFile& c, const Box& bounds) {
  std::vector<PreparedGrid> grids;
  checkOutputNames(c);
  // A grid is judged against the scene and its luminaires: over a flat ground lit by luminaires
  // (a car park) a grid lies outside the ground's flat box, inside this one.
  Box judged = bounds;
  if (!judged.empty())
    for (const LuminairePlacement& l : c.luminaires) judged.extend(l.positionM);
  for (const GridSpec& spec : c.grids) {
    // A task area's bands without a `room` end at the scene's plan extent (its walls, for a room).
    GridSpec clipped;
    if (spec.clipToRoom) {
      clipped = spec;
      std::vector<Vec2>& o = clipped.plane.outline;
      o = {glm::max(o[0], Vec2(bounds.lo.x, bounds.lo.y)), glm::min(o[1], Vec2(bounds.hi.x, bounds.hi.y))};
      if (!(o[1].x > o[0].x && o[1].y > o[0].y)) continue;
    }
    const GridSpec& made = spec.clipToRoom ? clipped : spec;
    PreparedGrid g;
    g.spec = &spec;
    if (spec.surfaceGrid.empty()) g.outside = gridOutsideScene(made, judged);  // a surface's grid lies on the scene
    g.grid = spec.kind == GridKind::kPlane ? makePlaneGrid(made.plane, spec.loc) : readPointsFile(spec.pointsFile);
    if (g.grid.size() == 0) continue;  // a band its room leaves empty (a task area filling the room)
    // A quantity replaces the grid's normals by its own sensor at each position.
    if (spec.quantity)
      for (SensorPoint& p : g.grid.points) p = quantitySensor(*spec.quantity, p.position, spec.facing);
    g.fileStem = safeFileName(spec.name);
    grids.push_back(std::move(g));
  }
  return grids;
}

bool gridMeasures(const PreparedGrid& g, GridQuantity q) {
  const SensorPoint want = quantitySensor(q, Vec3(0.0));
  for (const SensorPoint& p : g.grid.points)
    if (p.quantity != want.quantity || p.normal != want.normal) return false;
  return !g.grid.points.empty();
}

Box gridBounds(const Scene& scene) {
  Box bounds = scene.bounds();
  if (scene.sky) {
    // Under a sky the scene may be open (a ground, a building): grids must lie within its plan
    // extent only, as a grid above the ground is outside its bounding box by design.
    bounds.lo.z = -1e300;
    bounds.hi.z = 1e300;
  }
  return bounds;
}

}  // namespace candela
