// The scene cut horizontally for the report's plans (issue 18, EN 12464-1 reports: "per room a
// plan showing walls, openings and furniture cut at the grid height"): where the plane z = cut
// crosses the scene's polygons, triangles and mesh triangles, sorted by what their material makes
// them (walls or glazing), and the furniture tops between the floor and the cut. Pure functions
// over the scene (tests/study/grids/plan_section_test.cpp), and the study's step that gives each
// horizontal grid's plan its section (docs/reports.md, "Plans").
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "engine/scene.h"
#include "reports/report_data.h"
#include "study/grids/prepared_grid.h"

namespace candela {

// A grid less than this above its floor (m) is a floor-level grid (a circulation area, assessed
// at the floor): a cut there meets nothing but the floor's edges, so its plan is cut
// kFloorPlanCutM above the floor instead, as an architect's plan is.
inline constexpr double kFloorGridM = 0.3;
inline constexpr double kFloorPlanCutM = 1.0;
// Horizontal surfaces within this of the floor level (m) are the floor itself (a mat, a plinth's
// base, the floor's other face), not furniture.
inline constexpr double kFurnitureAboveFloorM = 0.02;
// Vertical glazing wholly above the cut whose bottom lies less than this above it (m) is drawn as
// a window above the cut (a sill higher than a work plane); higher glazing is a clerestory of
// another storey, left out.
inline constexpr double kOpeningsAboveM = 2.0;
// A surface is horizontal (a floor or furniture level) when its unit normal's |z| is at least
// this (tilted by at most about 26°), and vertical (a window) when at most kVerticalNormalZ.
inline constexpr double kHorizontalNormalZ = 0.9;
inline constexpr double kVerticalNormalZ = 0.1;

// What one section may hold: the plan of a 10⁶-triangle model stays a page of a few MB.
struct SectionLimits {
  std::size_t maxSegments = 20000;           // walls and openings, after merging
  std::size_t maxFootprintVertices = 20000;  // furniture outlines' vertices
};

// A section to compute: the cut plane's and the floor's heights (m), and the plan region it must
// cover (plan coordinates, m); surfaces wholly outside the region are left out.
struct SectionRequest {
  double cutHeightM = 0.0;
  double floorLevelM = 0.0;
  Vec2 lo{-1e300}, hi{1e300};
};

// The floor under a plan of a grid at gridZ (m) over the region [lo, hi]: of the levels of the
// opaque horizontal surfaces at most kFurnitureAboveFloorM above the grid (a floor grid lies on
// its floor), each with its area inside the region, the highest whose area is at least 70 % of
// the largest's. The floor spans the whole region while furniture covers part of it, and of two
// storeys' slabs, both spanning it, the upper one is the grid's. Either face counts (Radiance
// scenes orient floors either way: plastic reflects on both sides). Without any such surface,
// the scene's lowest z (gridZ for an empty scene).
double floorLevel(const Scene& scene, double gridZ, const Vec2& lo, const Vec2& hi);

// The height of the plan cut (m) for a grid at gridZ over a floor at floorZ: the grid's height,
// or kFloorPlanCutM above the floor for a grid less than kFloorGridM above it.
double planCutHeight(double gridZ, double floorZ);

// The section at request.cutHeightM:
//  - walls: the segments where opaque surfaces (plastic, metal, mirror) cross the plane;
//  - openings: those of glazing (glass, dielectric, trans, and illum, mkillum's windows);
//  - openingsAbove: vertical glazing wholly above the plane, its bottom less than kOpeningsAboveM
//    above it, as its plan projection (the architect's dashed window above the cut);
//  - furniture: the outlines of opaque horizontal surfaces wholly between kFurnitureAboveFloorM
//    above the floor and the cut (desk tops, shelves), a surface projected once (a box's top and
//    bottom faces give one outline).
// Light, glow and void surfaces are a luminaire's or invisible: left out. Spheres, cones and rings
// are not cut (counted in skippedCurved). Collinear segments of one kind that touch are merged;
// then at most limits.maxSegments are kept (openings first, then openings above, then walls),
// the rest counted in droppedSegments, and furniture up to limits.maxFootprintVertices vertices.
PlanSection planSection(const Scene& scene, const SectionRequest& request, const SectionLimits& limits = {});

// The height of a grid whose plan is an x, y plan (m): a plane grid's plane in plan coordinates
// (study/grids/sensor_grid.h inPlanCoordinates: z = its origin's), a points file's points' mean z when
// they lie within 0.1 m of one level; none for any other grid, and none for a ceiling's grid
// ([[surface_grid]]): its plan is a reflected ceiling plan with the luminaires, and a cut at its
// height would take the ceiling itself for the floor.
std::optional<double> gridPlanHeight(const PreparedGrid& g);

// Fills data.planSections, one per distinct cut height (to the mm) among the horizontal grids'
// plans, and each such grid's GridReport::planSection; data.grids[i] is grids[i]'s report. The
// floor is found once per distinct grid height, over the union of those grids' plan extents
// grown by 1 m (a grid on a desk top still sees the floor around the desk).
void addPlanSections(ReportData& data, const Scene& scene, const std::vector<PreparedGrid>& grids,
                     const SectionLimits& limits = {});

}  // namespace candela
