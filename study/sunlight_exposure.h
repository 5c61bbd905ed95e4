// EN 17037:2018+A1:2023 exposure to sunlight (clause 5.3, Annex D): at each reference point, the
// time on one day between 1 February and 21 March during which the sun stands above a minimum
// altitude and can be seen from the point — a cloudless sky, glazing seen through
// (study/sight_line.h), anything else blocking (docs/en17037-view-sunlight.md).
//
// The day is sampled every SunlightOptions::stepMinutes of local standard time (sun positions by
// NREL SPA, photometry/sun_spa.h, in the site's true frame turned into the model by its north);
// each change between sunlit and not is then located by bisection to within 1 s.
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "engine/tracer.h"
#include "metrics/en17037_view_sunlight.h"
#include "photometry/site.h"
#include "study/compliance/compliance_spec.h"

#include <vector>

namespace candela {

// Throws InputError at loc unless date is a real date between 1 February and 21 March
// (inclusive), EN 17037's range for the reference day.
void checkSunlightDate(const CivilDate& date, const FileLoc& loc = {});

struct SunlightOptions {
  double stepMinutes = 1.0;  // sampling step of the day, minutes (0 < step ≤ 60)
  bool refineEdges = true;   // bisect each change to 1 s (else: halfway between samples)
  int threads = 0;           // 0: all cores; results do not depend on it
};

// A stretch of sun, in local standard hours of the day [0, 24].
struct SunlitInterval {
  double startHour = 0.0;
  double endHour = 0.0;
};

struct SunlightPoint {
  Vec3 position{0.0};
  double hours = 0.0;  // sum of the intervals
  std::vector<SunlitInterval> intervals;
  En17037Level level = En17037Level::kNone;
};

struct SunlightExposure {
  CivilDate date;
  double minAltitudeDeg = 0.0;
  // The time the sun stands above minAltitudeDeg that day (hours): what an unobstructed point gets.
  double sunAboveMinHours = 0.0;
  std::vector<SunlightPoint> points;
};

// Hours of possible sunlight at each point (m, model frame) on `date` at `site` (its latitude,
// longitude, elevation, timezone and trueNorthDeg() are used). Throws InputError at dateLoc for a
// date outside 1 February – 21 March, std::invalid_argument for options out of range.
SunlightExposure sunlightExposure(const Tracer& tracer, const Site& site, const CivilDate& date,
                                  const std::vector<Vec3>& points, double minAltitudeDeg,
                                  const SunlightOptions& options = {}, const FileLoc& dateLoc = {});

}  // namespace candela
