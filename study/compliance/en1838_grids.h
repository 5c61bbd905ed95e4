// The calculation points of EN 1838 (docs/emergency.md): escape routes' centre lines and central
// bands, strip by strip; open areas' core (the area without its 0.5 m border) with its boundary;
// a polygon's lattice with its boundary. Plan coordinates x, y in m.
#pragma once

#include "base/math.h"
#include "study/compliance/en1838_spec.h"

#include <vector>

namespace candela {

// Whether the polygon (counter-clockwise, ≥ 3 vertices) is convex; collinear vertices allowed.
bool isConvexPolygon(const std::vector<Vec2>& ccw);

// The convex polygon `ccw` shrunk by `distanceM` on every side: the intersection of the half-planes
// its edges moved inwards bound (exact for convex polygons). Empty when nothing is left.
std::vector<Vec2> insetConvexPolygon(const std::vector<Vec2>& ccw, double distanceM);

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
