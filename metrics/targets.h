// Design targets of a grid and their verdicts, checked as a designer checks EN 12464-1:2021
// (Table 5.x: maintained illuminance Em and uniformity U0 per task area).
#pragma once

#include <optional>
#include <string>

#include "metrics/grid_stats.h"

namespace candela {

// Targets of one grid; an unset target is not checked.
struct GridTargets {
  std::optional<double> averageLux;  // required maintained illuminance Em in lux (Eavg >= Em)
  std::optional<double> uniformity;  // required U0 = Emin/Eavg (U0 >= target)
};

enum class Verdict { kNotChecked, kPass, kFail };

// "pass", "fail" or "n/a".
const char* verdictName(Verdict v);

// Verdicts of one grid against its targets, with the margins a designer reads.
struct TargetCheck {
  Verdict average = Verdict::kNotChecked;
  Verdict uniformity = Verdict::kNotChecked;
  Verdict overall = Verdict::kNotChecked;  // fail if any checked target fails, pass if all pass
  double averageRatio = 0.0;               // Eavg / Em (1.0 = exactly on target), 0 if unchecked
  double uniformityRatio = 0.0;            // U0 / U0,target, 0 if unchecked
};

// EN 12464-1 compares the calculated maintained values with the requirements as they are
// ("shall not be below"): a value equal to the target passes. `relativeTolerance` lets a
// caller accept e.g. the rounding of printed values (default 0: strict).
TargetCheck checkTargets(const GridStats& stats, const GridTargets& targets, double relativeTolerance = 0.0);

// EN 12464-1:2021, the areas around a task area (clause 4.3 in the 2002 and 2011 editions): the
// immediate surrounding is a band at least 0.5 m wide around it, the background a band at least
// 3 m wide around that, within the limits of the space; U0 at least 0.40 and 0.10. Values as
// tabulated in Fagerhult's summary of the 2021 edition (fagerhult.com, "EN 12464-1: illuminance
// and uniformity requirements") and Trilux's (trilux.com, "Background lighting").
inline constexpr double kImmediateSurroundingWidthM = 0.5;
inline constexpr double kBackgroundWidthM = 3.0;
inline constexpr double kImmediateSurroundingUniformity = 0.40;
inline constexpr double kBackgroundUniformity = 0.10;
// The uniformity EN 12464-1:2021 asks of the cylindrical illuminance Ē_z where it requires one
// (trilux.com, "Photometric requirements according to EN 12464-1": "at least 0,10").
inline constexpr double kCylindricalUniformity = 0.10;
// The maintained illuminance the immediate surrounding needs for a task area's Ē_m (the
// standard's table relating them: ≥ 750 lx → 500 lx, 500 → 300, 300 → 200, 200 → 150, and
// 150 lx or less: the task area's own value); a task value between the table's rows takes the
// row at or below it (400 lx → 200 lx, as 300 lx).
double immediateSurroundingLux(double taskLux);
// The background's: a third of the immediate surrounding's.
inline double backgroundLux(double taskLux) { return immediateSurroundingLux(taskLux) / 3.0; }

// The surfaces of a room EN 12464-1:2021 sets requirements for (walls and ceiling); floors and
// surfaces between (tilted more than 30° from either) have none.
enum class RoomSurface { kNone, kWall, kCeiling, kFloor };
const char* roomSurfaceName(RoomSurface s);  // "wall", "ceiling", "floor", "surface"

// `room_type` of a [[surface_grid]]: which of the standard's wall and ceiling requirements apply.
// kGeneral: any work place, walls Ē_m ≥ 50 lx and ceiling Ē_m ≥ 30 lx; kOffice, kEducation and
// kHealthcare (offices, schools, hospitals): walls ≥ 75 lx and ceiling ≥ 50 lx; U0 ≥ 0.10 for
// all (EN 12464-1:2021, illumination of walls and ceilings, as summarised by esse-ci.com, "Wall
// and ceiling illuminance", and trilux.com, "Photometric requirements according to EN 12464-1").
enum class RoomType { kGeneral, kOffice, kEducation, kHealthcare };
// "general", "office", "education", "healthcare" (and "school" for education); unset: unknown.
std::optional<RoomType> parseRoomType(const std::string& key);
const char* roomTypeKey(RoomType t);
inline constexpr double kRoomSurfaceUniformity = 0.10;
// The required Ē_m and U0 of a room surface of a room type; unset targets for a floor or a
// surface that is neither wall nor ceiling.
GridTargets roomSurfaceTargets(RoomType type, RoomSurface surface);

}  // namespace candela
