// Pictures of annual daylight results: the temporal map of one sensor's hourly illuminance
// (days across, hours of the day down, log false colour) and the categorical sDA/ASE plan.
#pragma once

#include <string>
#include <vector>

#include "reports/falsecolor.h"
#include "reports/plan_svg.h"
#include "reports/png_writer.h"
#include "reports/report_data.h"

namespace candela {

// Per-sensor verdicts of the sDA/ASE plan (metrics/annual.h decides them).
std::vector<bool> sdaPassPerSensor(const AnnualGridReport& annual);
std::vector<bool> aseExceededPerSensor(const AnnualGridReport& annual);

struct TemporalMapOptions {
  int dayPx = 2;    // pixels per day (x)
  int hourPx = 10;  // pixels per hour (y)
  ColorScale scale{10.0, 100000.0, true};  // lux, logarithmic: the usual 10 lx – 100 klx range
};

// The picture and where the map lies in it: day d (0 = 1 January) and hour-ending h (1–24) fill
// the rectangle x ∈ [mapLeft + d·dayPx, +dayPx), y ∈ [mapTop + (h−1)·hourPx, +hourPx).
struct TemporalMap {
  Image8 image;
  int mapLeft = 0, mapTop = 0;
  int dayPx = 0, hourPx = 0;
  int days = 365;  // 366 when the stamps hold 29 February
};

// Temporal map of `lux` (one value per time step, labelled by `hours`): midnight at the top,
// month numbers 1–12 along the bottom, hours 0–24 at the left, a colour bar in lx on the right.
// Values are clamped to the scale; a day/hour without a time step stays light grey. Throws
// std::invalid_argument when the lengths differ or a stamp is not a calendar date.
TemporalMap temporalMap(const std::vector<double>& lux, const std::vector<HourStamp>& hours,
                        const TemporalMapOptions& options = {});

// Plan of the sDA/ASE verdicts, inline SVG: sensors meeting DA300 ≥ 50 % in gold, the others in
// slate blue, sensors with ASE above 250 h crossed in red; a legend with the counts below.
std::string sdaAsePlanSvg(const PlanLayout& layout, const std::vector<bool>& sdaPass,
                          const std::vector<bool>& aseExceeded, const PlanOptions& options = {});

// Colours of the sDA/ASE plan, "#rrggbb".
inline constexpr const char* kSdaPassColor = "#f0b82d";
inline constexpr const char* kSdaFailColor = "#4b5d7a";
inline constexpr const char* kAseColor = "#d7301f";

}  // namespace candela
