// A point-in-time study (docs/run.md): every [[grid]] of the case traced with one tracer under
// its luminaires and sky, the metrics and EN 12464-1 target verdicts, every [[view]] through the
// view pipeline, and the result folder: <grid>.csv, the views' pictures, summary.csv,
// summary.json and report.html, committed as a whole (study/run_outputs.h).
#pragma once

#include "study/case/case_file.h"
#include "study/observer.h"
#include "study/run_case.h"

namespace candela {

RunResult runGridStudy(const CaseFile& c, const RunContext& run, StudyObserver& observer);

}  // namespace candela
