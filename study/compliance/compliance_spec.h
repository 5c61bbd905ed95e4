// A [[compliance]] entry of a case file (docs/compliance.md): which standard the case is checked
// against, the spaces (grids) it judges and the standard's own inputs. Each entry's figures go
// to summary.json under compliance.<name> and into a report section.
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "study/compliance/en12464_2_spec.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

enum class ComplianceStandard { kEn17037, kLeedV41Option1, kLeedV41Option2, kEn1838, kEn13201, kEn12464_2 };

// "en17037", "leed-v4.1-option1", "leed-v4.1-option2", "en1838", "en13201", "en12464-2": as written in the case file, and the
// entry's default name.
std::string_view standardKey(ComplianceStandard s);

struct CivilDate {
  int year = 2026;
  int month = 3;  // 1..12
  int day = 21;   // 1..31
};

// EN 17037 5.3 / A.4: the reference day of the exposure to sunlight lies between 1 February
// and 21 March, both included.
constexpr bool inSunlightDateRange(const CivilDate& d) { return d.month == 2 || (d.month == 3 && d.day <= 21); }

// A glare view: an eye and its line of sight (unit, model frame; up is +Z).
struct GlareViewSpec {
  Vec3 positionM{0.0};
  Vec3 direction{0.0, 1.0, 0.0};
  // `check_hours`: hours of the year rendered to check the imageless DGP (local standard time,
  // "YYYY-MM-DDTHH:MM" as written: the hour that starts then).
  std::vector<std::string> checkHours;
  // `check_resolution`: the check images' side in pixels (a square 180° fisheye).
  int checkResolutionPx = 256;
  FileLoc loc, checkLoc;
};

// EN 17037 part 1, the order in which space and time are aggregated (docs/compliance.md):
// hour first, each daylight hour passes when the share of the plane at the threshold reaches
// F_plane, the space when such hours reach F_time (the standard's Table A.1 wording, and
// ClimateStudio's); sensor first, each sensor passes when it reaches the threshold in F_time of
// the daylight hours, the space when the passing sensors reach F_plane (as Honeybee's recipe).
enum class ProvisionAggregation { kHourFirst, kSensorFirst };

struct ComplianceSpec {
  std::string name;                       // summary.json's key under `compliance`
  ComplianceStandard standard = ComplianceStandard::kEn17037;
  std::vector<std::string> spaces;        // grids judged as spaces; empty: every grid of the case
  FileLoc spacesLoc;
  // EN 17037 part 1: aggregation order (the other is computed too and reported when it disagrees).
  ProvisionAggregation aggregation = ProvisionAggregation::kHourFirst;
  // EN 17037 part 3: the reference day (1 February .. 21 March), points and minimum sun altitude.
  std::optional<CivilDate> sunlightDate;  // unset: 21 March of the weather file's first year
  FileLoc sunlightDateLoc;
  std::vector<Vec3> sunlightPoints;
  std::optional<double> sunlightMinAltitudeDeg;  // unset: the standard's value for the latitude
  FileLoc sunlightLoc;
  // EN 17037 part 2: eyes.
  std::vector<Vec3> viewPoints;
  FileLoc viewLoc;
  // EN 17037 part 4 / annual glare: views and the share of occupied hours allowed above a
  // level's DGP (5 %).
  std::vector<GlareViewSpec> glareViews;
  double glareExceedance = 0.05;
  // LEED v4.1 option 2: the two clear-sky days (within 15 days of 21 March and 21 September)
  // and the hours (local standard time) the illuminance is computed at.
  std::vector<CivilDate> leedDates;       // unset: 21 March and 21 September
  FileLoc leedDatesLoc;
  std::vector<double> leedHours{9.0, 15.0};
  // EN 1838: the maintenance factor of the emergency luminaires (`maintenance_factor`, in (0, 1];
  // the luminaires' own is for the normal lighting and is not used).
  double emergencyMaintenanceFactor = 1.0;
  // EN 1838: surfaces left out of the emergency study (`leave_out`: identifiers or patterns, as
  // [[surface_grid]]'s): the furniture, for the empty floor the standard means.
  std::vector<std::string> emergencyLeaveOut;
  FileLoc emergencyLeaveOutLoc;
  // EN 12464-2: obtrusive light (`environmental_zone`, `obtrusive_limits`, `property_points`).
  ObtrusiveLightSpec obtrusive;
  FileLoc loc;
};

// LEED option 2's clear-sky days: the entry's `dates`, else 21 March and 21 September of
// `weatherYear`.
std::vector<CivilDate> leedOption2Dates(const ComplianceSpec& s, int weatherYear);

}  // namespace candela
