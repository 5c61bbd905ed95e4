// The calculation points of EN 1838 (docs/emergency.md): escape routes' centre lines and central
// bands, strip by strip; open areas' core (the area without its 0.5 m border) with its boundary;
// a polygon's lattice with its boundary. Plan coordinates x, y in m.
#pragma once

#include "base/math.h"
#include "study/case/case_file.h"
#include "study/compliance/en1838_spec.h"

#include <vector>

namespace candela {

// Whether the polygon (counter-clockwise, ≥ 3 vertices) is convex; collinear vertices allowed.
bool isConvexPolygon(const std::vector<Vec2>& ccw);

// The convex polygon `ccw` shrunk by `distanceM` on every side: the intersection of the half-planes
// its edges moved inwards bound (exact for convex polygons). Empty when nothing is left.
std::vector<Vec2> insetConvexPolygon(const std::vector<Vec2>& ccw, double distanceM);

// The simple polygon `ccw` (counter-clockwise) shrunk by `distanceM`: the points at least that far
// from its boundary (EN 1838's core area). Convex: insetConvexPolygon. Concave: each edge moved
// inwards, consecutive ones meeting at their lines' crossing where the corner is convex and joined
// by an arc of radius distanceM about a reflex corner (sampled at most 10° and `arcStepM` apart);
// empty when that outline is not one simple polygon every vertex of which lies distanceM from the
// boundary (an edge shorter than the inset swallowed, or a core in several pieces).
std::vector<Vec2> insetPolygon(const std::vector<Vec2>& ccw, double distanceM, double arcStepM);

// The default pitch of a high-risk task area's points without its own `spacing`, m.
inline constexpr double kHighRiskSpacingM = 0.25;

// An upper bound of the points en1838Points makes for the case's routes, open areas, high-risk
// task areas and safety points, counted without making them (the run's memory check comes first).
double en1838PointBound(const CaseFile& c);

// Points of a simple polygon: every vertex and its edges at most `spacingM` apart (the boundary,
// where the minima of a lit area usually lie), then the interior lattice of pitch `spacingM`
// centred in the polygon's box, inside it (even-odd rule).
std::vector<Vec2> polygonPoints(const std::vector<Vec2>& polygon, double spacingM);

// One strip of an escape route: its lateral offset and width (m), the points of its centre line
// (both ends of each segment included) and of its central band (half its width, edges included).
struct RouteStripPoints {
  double offsetM = 0.0, widthM = 0.0;
  std::vector<Vec2> centreLine, band;
};
// A route up to 2 m wide is one strip on its path; a wider one ⌈w/2⌉ strips of equal width
// (EN 1838 4.2.1: "as a number of 2 m wide strips"). Each segment of the path is sampled on its
// own: at a bend a strip off the route's middle overlaps inside and leaves the outer corner.
std::vector<RouteStripPoints> routeStrips(const EscapeRouteSpec& route);

}  // namespace candela
