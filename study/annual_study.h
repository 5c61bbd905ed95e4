// A climate-based annual daylight study (docs/annual.md): a case with [sky] type = "annual".
// Daylight coefficients of every grid's sensors, a year of hourly illuminance from the weather
// file, the annual metrics (DA, cDA, UDI, sDA, ASE, hours of sun) with LM-83's blinds rule,
// and the result folder: <grid>_annual.csv, the hourly float32 files, summary.csv,
// summary.json and report.html.
#pragma once

#include "study/case_file.h"
#include "study/observer.h"
#include "study/run_case.h"

namespace candela {

// Throws InputError for bad input before anything is written.
RunResult runAnnualStudy(const CaseFile& c, const RunContext& run, StudyObserver& observer);

}  // namespace candela
