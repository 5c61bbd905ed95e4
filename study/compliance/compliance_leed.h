// LEED v4.1 EQ credit Daylight, options 1 and 2, as [[compliance]] entries of an annual case
// (docs/compliance.md, docs/leed.md).
#pragma once

#include "study/compliance/compliance_study.h"

namespace candela {

// Option 1: the spaces' sDA300/50% and ASE1000,250 from the annual study (LM-83 blinds per window
// group), area-weighted, scored by metrics/leed.h.
ComplianceReport leedOption1(const ComplianceInputs& in, const ComplianceSpec& s);

// Option 2: the illuminance at every sensor of the spaces at the entry's hours (9:00 and 15:00)
// of its clear-sky days (21 March and 21 September of the weather year), under the CIE clear
// sky with the site's sun, their intensities from the weather year (equinoxWindowLight); the
// share of the area between 300 and 3000 lx, averaged over the times, area-weighted over the
// spaces, and its points.
ComplianceReport leedOption2(const ComplianceInputs& in, const ComplianceSpec& s);

// The sky's and the sun's intensity for option 2 at `hourOfDay` (local standard time) of `date`:
// USGBC's guidance for the credit asks for "typical meteorological year data for the nearest
// weather station (average of the hourly value for both equinox 15-day window)". So: the mean
// over the days within 15 days of the equinox nearest `date` (21 March or 21 September; 31 days)
// of the weather year's diffuse horizontal and direct normal illuminance at that instant, each
// day's value interpolated between the two hour-ending records whose middles enclose it (9:00:
// half the hour ending 9:00, half the one ending 10:00). The illuminances are the annual study's
// (Perez efficacies of the file's irradiances).
struct EquinoxLight {
  double diffuseHorizontalLux = 0.0;
  double directNormalLux = 0.0;
  int days = 0;  // the days averaged
};
EquinoxLight equinoxWindowLight(const AnnualSky& sky, const CivilDate& date, double hourOfDay);

// Option 2's points for an average share of the area in range, %: ≥ 55 % one point, ≥ 75 % two,
// ≥ 90 % three (docs/leed.md says what this reading rests on).
int leedOption2Points(double averageInRangePct);

}  // namespace candela
