// The scene a case file describes: its Radiance files in order, then its luminaires. Shared by
// `candela points --case` and `candela run`.
#pragma once

#include "study/case/case_file.h"
#include "engine/daylight.h"
#include "engine/scene.h"
#include "photometry/epw.h"
#include "photometry/site.h"

#include <memory>

namespace candela {

// Reads every [[scene]] file, places every [[luminaire]] (arrays already expanded by the case
// reader; photometric files shared by several placements are read once) and adds the daylight of
// [site] and [sky]. Throws InputError naming the bad file and line.
std::unique_ptr<Scene> loadCaseScene(const CaseFile& c, bool withDaylight = true);

// The case's geometry as loadCaseScene reads it (its scene files, window groups in their first
// state, its portals), without luminaires or daylight.
void readCaseGeometry(const CaseFile& c, Scene& scene);

// Removes from the scene every surface whose identifier matches one of the patterns (globs as
// [[surface_grid]]'s: `*` any run, `?` one character); used[k] is set when pattern k matched.
// Before luminaires are placed (their openings are surfaces the indices of which it would move).
void removeSurfaces(Scene& scene, const std::vector<std::string>& patterns, std::vector<bool>& used);

// Places luminaires in `scene` (files shared by several placements are read once), with their
// opening surfaces where `openingReflectance` is set. Throws InputError naming a bad file.
void placeLuminaires(Scene& scene, const std::vector<LuminairePlacement>& luminaires);

// The daylight a case's [site] and [sky] describe (sky type "none" without a [sky]). With
// `weather`, the direct normal and diffuse horizontal irradiance (and illuminance) of the EPW
// hour containing `time` are used (hour-ending records: 12:30 is in hour 13).
DaylightSpec daylightFromCase(const CaseFile& c);

// The site of a case: its [site] table, or else the weather file's LOCATION (annual studies).
// Throws InputError at [site] for a bad latitude/longitude text.
Site caseSite(const CaseFile& c, const EpwLocation* weather = nullptr);

// The scene of an annual daylight study ([sky] type = "annual", docs/annual.md): the [[scene]]
// geometry under a uniform sky that only guides the sampling of the sky coefficients
// (skyCoefficients). Luminaires are left out: annual metrics are of daylight alone.
std::unique_ptr<Scene> loadAnnualScene(const CaseFile& c, double northDeg);
// What loadAnnualScene does after reading the files: the case's portals and the annual sky
// (study/window_states.h reads its scenes otherwise).
void finishAnnualScene(const CaseFile& c, double northDeg, Scene& scene);


}  // namespace candela
