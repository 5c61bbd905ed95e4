// EN 1838:2013 emergency lighting as a study (docs/emergency.md): the emergency luminaires alone
// (their flux × emergency_factor × the entry's maintenance factor), direct light only (the
// standard disregards reflected light: bounces 0 with the path estimator, whose point sources'
// light is exact), at the points of the escape routes, open areas' cores, high-risk task areas
// and safety points (study/compliance/en1838_grids.h); verdicts from metrics/en1838.h.
#pragma once

#include "base/warning.h"
#include "engine/scene.h"
#include "engine/sensors.h"
#include "engine/trace_settings.h"
#include "metrics/en1838.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/trace_options.h"

#include <memory>
#include <optional>
#include <vector>

namespace candela {

// The case's en1838 entry, or null.
const ComplianceSpec* en1838Entry(const CaseFile& c);

// The emergency scene: the case's geometry without daylight, and only its emergency luminaires,
// each scaled by multiplier × emergency_factor × `maintenanceFactor` (its own maintenance factor
// is the normal lighting's); every opaque reflecting material blacked out (blackOutReflection);
// the surfaces `leaveOut` names (the entry's `leave_out`) removed, a pattern that names none an
// InputError at leaveOutLoc.
std::unique_ptr<Scene> loadEmergencyScene(const CaseFile& c, double maintenanceFactor,
                                          const std::vector<std::string>& leaveOut = {},
                                          const FileLoc& leaveOutLoc = {});

// Makes an opaque reflecting material (plastic, metal, mirror and their function, data, anisotropic
// and Ashikhmin variants) a black plastic, keeping its name, line and antimatter bit: no light
// reflected off it reaches a sensor. Returns whether it did. Emitters, glazing and translucent
// materials are left as read.
bool blackOutReflection(Material& m);

// `s` made direct-only: no diffuse bounce, the path estimator (no irradiance cache), one batch.
TraceSettings directOnlySettings(TraceSettings s);

// The sensors of every route, area and point, and the results they make: the points in the order
// computeEn1838 traces them.
struct En1838Points {
  std::vector<SensorPoint> sensors;
  // Where each part's values start in `sensors` and how many it has, in the result's order.
  struct Span {
    std::size_t first = 0, count = 0;
  };
  std::vector<std::vector<Span>> routeCentre, routeBand;  // [route][strip]
  std::vector<Span> openAreas, highRisk, safetyPoints;
  std::vector<std::vector<Vec2>> cores;                   // the open areas' core polygons
};
En1838Points en1838Points(const CaseFile& c);

// Traces the points in `scene` with `settings` (made direct-only here) and judges them.
En1838Result computeEn1838(const CaseFile& c, const ComplianceSpec& entry, const Scene& emergencyScene,
                           const TraceSettings& settings, int threads);

// no_emergency_luminaire (docs/warnings.md): the case asks for en1838 and marks no luminaire
// `emergency = true` (every value will be 0 lx).
std::optional<Warning> noEmergencyLuminaireWarning(const CaseFile& c);

// The run's step (study/grid_study.cpp): for the case's en1838 entry, the emergency scene, its
// results and the report's compliance entry with its plan. Nothing without an entry.
void addEn1838Compliance(const CaseFile& c, const ResolvedTrace& trace, ReportData& data);

}  // namespace candela
