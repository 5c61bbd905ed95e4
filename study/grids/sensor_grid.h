// Sensor grids: where illuminance is computed. Pure geometry over base/; the case-file
// reader fills a PlaneGridSpec, this file turns it into points.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/math.h"
#include "engine/sensors.h"

namespace candela {

// A planar calculation area. Plane coordinates (u, v) in metres map to the world as
// origin + u·uAxis + v·vAxis. A horizontal work plane at height h is origin (0, 0, h) with the
// default axes, so (u, v) = (x, y).
struct PlaneGridSpec {
  // Outline of the area in plane coordinates (m): either a rectangle (`isRectangle`, outline holds
  // the two opposite corners) or a simple polygon (any orientation, concave allowed).
  std::vector<Vec2> outline;
  bool isRectangle = true;
  Vec3 origin{0.0, 0.0, 0.0};  // m
  Vec3 uAxis{1.0, 0.0, 0.0};   // unit, orthogonal to vAxis
  Vec3 vAxis{0.0, 1.0, 0.0};   // unit
  // Sensor direction; unset means uAxis × vAxis (straight up for a horizontal grid).
  std::optional<Vec3> normal;
  // Maximum spacing between points in m; unset means EN 12464-1 automatic (autoGridSpacingM).
  std::optional<double> spacingM;
  double borderM = 0.0;  // band (m) along the outline left without points
  // A band around an area (EN 12464-1's immediate surrounding and background of a task area):
  // only the points outside `inner` (a polygon in plane coordinates) whose distance to it is
  // more than fromM and at most toM are kept; the outline then bounds the lattice (the room's
  // limits). Empty `inner`: no band.
  struct Band {
    std::vector<Vec2> inner;
    double fromM = 0.0, toM = 0.0;
  } band;
  // An area made of several polygons (a wall in pieces around its windows, a mesh's triangles):
  // only the points inside one of them are kept; the outline then bounds the lattice. Empty:
  // the outline is the area.
  std::vector<std::vector<Vec2>> pieces;
  // Parts of the area that are not there to be lit: points inside one of these polygons are left
  // out (a cabinet's back or a pane lying on a wall).
  std::vector<std::vector<Vec2>> holes;
};

// The plane's coordinates (u, v) are the world's (x, y): the default axes (a horizontal plane, or
// one whose sensors face elsewhere), so that plan positions can be drawn on its plan.
inline bool inPlanCoordinates(const PlaneGridSpec& p) {
  return p.uAxis == Vec3(1, 0, 0) && p.vAxis == Vec3(0, 1, 0);
}

// A generated grid. Plane grids are regular lattices: the cell (i, j) has its centre at
// latticeOriginUv + ((i + ½)·spacingM.x, (j + ½)·spacingM.y) in plane coordinates; cells outside
// a polygon or inside the border band are left out.
struct SensorGrid {
  std::vector<SensorPoint> points;
  std::vector<Vec2> uv;               // plane coordinates (m) of each point (plane grids only)
  std::vector<glm::ivec2> cell;       // lattice cell (i, j) of each point (plane grids only)
  std::vector<int> lines;             // line of each point in its file (points files only)
  bool regular = false;               // true for plane grids
  double nominalSpacingM = 0.0;       // spacing asked for, or the automatic one
  Vec2 spacingM{0.0, 0.0};            // actual spacing along u and v, m (<= nominal)
  int columns = 0, rows = 0;          // lattice cells along u and v
  Vec2 latticeOriginUv{0.0, 0.0};     // lower corner of cell (0, 0), plane coordinates
  double cellAreaM2() const { return spacingM.x * spacingM.y; }
  std::size_t size() const { return points.size(); }
};

// EN 12464-1 (2011 4.4 / 2021 5.4, "grid system"): maximum grid size p = 0.2 · 5^log10(d) m,
// d in m, p <= 10 m. The standard tabulates p rounded to a value a designer writes (1 m → 0.2,
// 2 m → 0.3, 5 m → 0.6, 10 m → 1, 25 m → 2, 50 m → 3, 100 m → 5; e.g. the summary at
// fagerhult.com, "EN 12464-1: number of calculation points"); candela reproduces that table by
// rounding p to one significant figure.
double autoGridSpacingM(double dM);

// The d of the formula for an area of sides a and b (m): the longer side, but the shorter one
// when the longer is at least twice the shorter (EN 12464-1:2011, 4.4).
double gridDimensionM(double sideAM, double sideBM);

// Number of cells along a side of `lengthM` at a maximum spacing `maxSpacingM`: ceil(length/p)
// ("the number of points ... is d/p rounded up", EN 12464-1:2021 5.4), at least 1.
int cellsAlong(double lengthM, double maxSpacingM);

// The points of a planar grid at the cell centres (none: a band that is empty). Throws
// InputError(loc, ...) when the area is empty, the border eats it, the axes are not orthonormal or the grid would exceed 10 million
// points.
SensorGrid makePlaneGrid(const PlaneGridSpec& spec, const FileLoc& loc = {});
// The number of points makePlaneGrid would make, with the same checks and errors, without
// storing them (the case file checks its grids with it; the resource estimate counts them).
std::size_t countPlaneGrid(const PlaneGridSpec& spec, const FileLoc& loc = {});

// Radiance-style sensor points, one per line "x y z dx dy dz" (m; direction = sensor normal,
// normalised here). Blank lines and '#' comments are allowed; any other malformed line throws
// InputError naming `sourceName` and the line. With `lines`, the line of each point is appended.
std::vector<SensorPoint> readPoints(std::istream& in, const std::string& sourceName,
                                    std::vector<int>* lines = nullptr);
SensorGrid readPointsFile(const std::filesystem::path& path);

// A sensor point from "x y z dx dy dz" (m; the direction normalised), checked as readPoints
// checks a line: finite, within 1e7 m of the origin, a non-zero direction. Throws InputError
// at `loc` otherwise.
SensorPoint checkedSensorPoint(const double v[6], const FileLoc& loc);

// Even-odd point-in-polygon test (concave polygons included); points on an edge count as
// inside or outside arbitrarily.
bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& p);

// Distance from p to the closest edge of the closed polygon, m.
double distanceToOutline(const std::vector<Vec2>& polygon, const Vec2& p);

// Signed area of a polygon (positive counter-clockwise), m².
double polygonArea(const std::vector<Vec2>& polygon);

}  // namespace candela
