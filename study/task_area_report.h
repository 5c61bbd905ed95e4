// EN 12464-1:2021 task areas in the report: each [[task_area]]'s three grids and the observers
// standing in them, and each [[surface_grid]]'s walls and ceiling, with the verdicts
// (docs/en12464.md).
#pragma once

#include "reports/report_data.h"
#include "study/case/case_file.h"

namespace candela {

// The grid reports' task-area labels and data.taskAreas, from the case and the grid and
// observer reports already in `data` (grids matched by name).
void addTaskAreaReports(const CaseFile& c, ReportData& data);

// The grid reports' surface labels and data.surfaceGrids, from the case's [[surface_grid]]
// entries and the grids they made (c: the case with them, study/grids/surface_grids.h).
void addSurfaceGridReports(const CaseFile& c, ReportData& data);

}  // namespace candela
