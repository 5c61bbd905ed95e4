// Every file a case's run writes, named before anything is traced, so that two entries that
// would write the same file (grids `a b` and `a_b`, a grid `desk` and a grid `desk_direct_sun`
// of an annual run, a view `x_preview` beside a view `x`) are an input error naming both.
#pragma once

#include "study/case/case_file.h"

namespace candela {

// Throws InputError at the later entry's line when two outputs of the case collide, or when an
// entry would overwrite summary.csv, summary.json, report.html or the result marker.
void checkOutputNames(const CaseFile& c);

}  // namespace candela
