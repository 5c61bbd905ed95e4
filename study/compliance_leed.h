// LEED v4.1 EQ credit Daylight, options 1 and 2, as [[compliance]] entries of an annual case
// (docs/compliance.md, docs/leed.md).
#pragma once

#include "study/compliance_study.h"

namespace candela {

// Option 1: the spaces' sDA300/50% and ASE1000,250 from the annual study (LM-83 blinds per window
// group), area-weighted, scored by metrics/leed.h.
ComplianceReport leedOption1(const ComplianceInputs& in, const ComplianceSpec& s);

// Option 2: the illuminance at every sensor of the spaces at the entry's hours (9:00 and 15:00)
// of its clear-sky days (21 March and 21 September of the weather year), under the CIE clear
// sky with the site's sun; the share of the area between 300 and 3000 lx, averaged over the
// times, area-weighted over the spaces, and its points.
ComplianceReport leedOption2(const ComplianceInputs& in, const ComplianceSpec& s);

// Option 2's points for an average share of the area in range, %: ≥ 55 % one point, ≥ 75 % two,
// ≥ 90 % three (docs/leed.md says what this reading rests on).
int leedOption2Points(double averageInRangePct);

}  // namespace candela
