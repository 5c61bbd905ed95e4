// Pieces `candela run` shares between its point-in-time and annual paths: the case's grids with
// their points, how they are described and laid out in plans, and the time stamp of a run.
#pragma once

#include "base/math.h"
#include "study/case_file.h"
#include "engine/scene.h"
#include "study/sensor_grid.h"
#include "reports/report_data.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace candela::cli {

// A grid of the case with its points, ready to trace.
struct PreparedGrid {
  const GridSpec* spec = nullptr;
  SensorGrid grid;
  std::string fileStem;  // <fileStem>.csv
};

// Every [[grid]] of the case, checked against `bounds` and for file-name collisions (throws
// InputError at the grid's line).
std::vector<PreparedGrid> prepareGrids(const CaseFile& c, const Box& bounds);

// One line a reader of the report understands: orientation, height, spacing, border.
std::string gridDescription(const PreparedGrid& g);

PlanLayout planLayout(const PreparedGrid& g);

// The local time now, "YYYY-MM-DD HH:MM".
std::string localTimeNow();

// Creates `outDir` and calls write(); a file-system or write failure becomes InputError at
// outDir, "cannot write the results: ...". Each writer writes atomically, so a failure leaves no
// half file.
void writeRunOutputs(const std::filesystem::path& outDir, const std::function<void()>& write);

// The bounds grids must lie in: the scene's, unbounded in z under a sky (an open scene).
Box gridBounds(const Scene& scene);

}  // namespace candela::cli
