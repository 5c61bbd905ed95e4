// Guards against silent nonsense: checks over a case, its scene and its results that find input
// which is valid but whose result is probably not what the user meant (docs/warnings.md lists
// every code, what triggers it and why it matters). Each check appends to a list; the studies
// return the list in their results (RunResult::data.warnings, PointsResult, RenderResult) and
// throw the first one as an InputError when the request is strict, before anything is written.
// The checks that look at geometry cast a handful of rays per sensor or luminaire through the
// run's own tracer, so they cost little next to the run itself; none changes a number.
#pragma once

#include "base/warning.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "photometry/epw.h"
#include "study/case/case_file.h"
#include "study/grids/prepared_grid.h"

#include <string>
#include <vector>

namespace candela {

using Warnings = std::vector<Warning>;

// Sensors checked together: a grid of a case, or the points of `candela points`.
struct SensorSet {
  std::string name;                            // "grid 'workplane'", "points"
  const std::vector<SensorPoint>* points = nullptr;
  FileLoc loc;                                 // the [[grid]] entry or the points file
  std::vector<FileLoc> pointLocs;              // per point (points files: its line), or empty
};

// The case's grids as sensor sets (points files with the line of each point).
std::vector<SensorSet> sensorSets(const std::vector<PreparedGrid>& grids);

// What reading the scene files replaced or repaired (pattern_replaced, nonplanar_triangulated, ...):
// the scene's inputWarnings, in file order.
void checkSceneInput(const Scene& scene, Warnings& out);

// no_light_source: no luminaire, no emitting surface, no distant source and no sky.
void checkLightSources(const Scene& scene, const FileLoc& where, Warnings& out);

// luminaire_outside_scene, millimetre_positions, and (with sensors) luminaire_above_ceiling,
// luminaire_in_closed_volume, luminaire_reaches_no_sensor: up to 16 shadow rays per luminaire
// and grid towards its sensors, and 6 more when none is reached.
void checkLuminaires(const Tracer& tracer, const std::vector<LuminairePlacement>& luminaires,
                     const std::vector<SensorSet>& sensors, Warnings& out);

// millimetre_positions for the case's other positions: EN 17037 sunlight and view points and
// glare views ([[compliance]]) and [[observer]] eyes lying more than ten times the scene's size
// outside its box `box` and inside it once divided by 1000 (one warning a list, at its key).
void checkMillimetrePositions(const CaseFile& c, const Box& box, Warnings& out);

// view_out_unglazed_opening: an EN 17037 view point from which a horizontal line of sight (one
// a degree) leaves the model without crossing glazing: view out (study/view_out.h) counts
// glazing only, so the opening reads 0 deg and "none" (one warning a [[compliance]] entry).
void checkViewOutOpenings(const Tracer& tracer, const CaseFile& c, Warnings& out);

// grid_spacing_exceeds_extent: a plane grid whose spacing is larger than its calculation area
// (after the border) along a side.
void checkGridSpacing(const PreparedGrid& grid, Warnings& out);

// modelling_height: a grid with `modelling = true` with a point farther than 0.1 m from both
// 1.2 m (seated) and 1.6 m (standing) above the floor, the heights EN 12464-1:2021 rates
// modelling at.
void checkModellingHeight(const PreparedGrid& grid, Warnings& out);

// sensor_near_surface (a surface within 5 mm that cuts the sensor's hemisphere) and
// sensor_outside_room (outside the scene's box without a sky, or open to the outside where most
// sensors of the set are enclosed): 11 rays per sensor.
void checkSensors(const Tracer& tracer, const SensorSet& set, Warnings& out);

// site_contradicts_weather: [site] more than 1° of latitude or longitude, or a different time
// zone, away from the weather file's LOCATION.
void checkSiteAgainstWeather(const CaseFile& c, const EpwLocation& weather, Warnings& out);
// The same for a point-in-time [sky] with a weather file (reads the file's LOCATION); nothing
// without a weather file or a [site].
void checkCaseSite(const CaseFile& c, Warnings& out);

// sky_without_sun: a case's point-in-time sky whose type has a sun (cie-clear, cie:7 … cie:15),
// with `sun = true` and the sun above the horizon, but no direct normal illuminance to give it
// (no `direct_normal_illuminance`, no `weather` file): `scene`'s sun disc carries no light.
void checkSkySun(const CaseFile& c, const Scene& scene, Warnings& out);

// untrusted_error_bar: points that read exactly 0 with a standard error of 0 while a glow
// surface (one not sampled directly from them: engine/lights.h, glowSampledFrom) lies in front of them with
// nothing in between: no sample found it, so the zero error bar claims a certainty it does not
// have. `lux` and `errorLux` (illuminance and its standard error) have one entry per point of
// the set.
void checkErrorBars(const Tracer& tracer, const SensorSet& set, const double* lux, const double* errorLux,
                    Warnings& out);

// sensor_reads_nothing: points of a set that read exactly 0 with a standard error of 0 while
// another point of the set reads more than 0: no sample from them found light (inside a cabinet,
// a closed volume), and they pull the set's minimum and uniformity down to 0.
void checkDarkSensors(const SensorSet& set, const double* lux, const double* errorLux, Warnings& out);
// luminaire_photometry: a photometric file whose light output ratio exceeds 100 % (more light
// out than the lamps give: a wrong lamp flux or conversion factor) or whose intensities are all
// zero (the luminaire gives no light). Once per file, at its first [[luminaire]] entry.
void checkPhotometry(const Scene& scene, const std::vector<LuminairePlacement>& luminaires, Warnings& out);

// luminaire_power_unknown: a [[luminaire]] entry whose photometric file gives no input power
// (0 W) and which has no `power_w`: the installed power and W/m² leave it out, so they are a
// lower bound. Once per entry, at its line.
void checkLuminairePower(const Scene& scene, const CaseFile& c, Warnings& out);

// weather_missing_hours: records of the weather file with missing irradiance (counted by the
// EPW reader: a missing mark, an empty field or -999), whose sky is taken as dark.
void checkWeatherGaps(const EpwFile& weather, const std::string& fileName, Warnings& out);

// The point-in-time study's checks on its input, before tracing, in the order it runs them
// (`candela run` of a case without an annual sky): light sources, site, luminaires (placement,
// photometry, power), grids
// (spacing, modelling height), sensors. The tracer is the study's own.
Warnings pointInTimeWarnings(const CaseFile& c, const Tracer& tracer, const std::vector<PreparedGrid>& grids);

// The annual study's checks on its input: site against weather, grids, sensors (through a
// tracer of their own, so the coefficients' ray counts stay theirs). Luminaires play no part in
// annual metrics.
Warnings annualInputWarnings(const CaseFile& c, const EpwLocation& weather, const Scene& scene,
                             const std::vector<PreparedGrid>& grids);

}  // namespace candela
