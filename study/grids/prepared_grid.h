// The case's grids with their points, as every study traces them: checked, named for their
// files, described and laid out for the report.
#pragma once

#include "base/math.h"
#include "engine/scene.h"
#include "study/case/case_file.h"
#include "study/grids/sensor_grid.h"
#include "reports/report_data.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// A grid of the case with its points, ready to trace.
struct PreparedGrid {
  const GridSpec* spec = nullptr;
  SensorGrid grid;
  std::string fileStem;  // <fileStem>.csv
  // grid_outside_scene: the grid reaches beyond the box of the scene and its luminaires
  // (gridOutsideScene); the studies' input warnings carry it.
  std::optional<Warning> outside;
};

// Every [[grid]] of the case, judged against `bounds` grown by the case's luminaires (a warning
// in PreparedGrid::outside), and every output name of the case for
// collisions (study/output_names.h); throws InputError at the entry's line.
std::vector<PreparedGrid> prepareGrids(const CaseFile& c, const Box& bounds);

// Estimates a point of the grid costs the study: 1, plus for `modelling` its cylindrical and
// horizontal sensors unless the grid's own quantity is that (default normals of an upward plane
// grid are horizontal). An upper bound before the points are made (a points file's normals are
// not read).
int estimatesPerPoint(const GridSpec& spec);

// One line a reader of the report understands: orientation, height, spacing, border.
std::string gridDescription(const PreparedGrid& g);

PlanLayout planLayout(const PreparedGrid& g);

// Whether every sensor of the grid measures q (a horizontal plane grid's default normals measure
// horizontal illuminance; a points file's points do when their normals are +Z); false for a grid
// without points.
bool gridMeasures(const PreparedGrid& g, GridQuantity q);

// The bounds grids must lie in: the scene's, unbounded in z under a sky (an open scene).
Box gridBounds(const Scene& scene);

}  // namespace candela
