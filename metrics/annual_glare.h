// Annual glare metrics over a view's hourly daylight glare probability (DGP, Wienold &
// Christoffersen 2006; metrics/glare.h): the shares of occupied hours above the DGP comfort
// classes, glare autonomy, EN 17037's level of protection from glare, and the spatial share of
// views with disturbing glare (docs/annual-glare.md).
//
// Pure functions: the caller supplies the hourly DGP (imageless or rendered, any source) and the
// occupancy flags; nothing here knows about skies or scenes.
#pragma once

#include "metrics/compliance_levels.h"

#include <span>
#include <vector>

namespace candela {

// Thresholds; every default is the one of its source.
struct AnnualGlareThresholds {
  // DGP comfort classes (Wienold 2009, "Dynamic daylight glare evaluation", Building Simulation
  // 2009; the bands evalglare and ClimateStudio report): imperceptible < 0.35 ≤ perceptible <
  // 0.40 ≤ disturbing < 0.45 ≤ intolerable. EN 17037:2018+A1 (protection from glare, Annex A)
  // grades a view by the DGP that is exceeded in no more than `exceedanceShare` of the usage
  // time: high ≤ 0.35, medium ≤ 0.40, minimum ≤ 0.45.
  double high = 0.35, medium = 0.40, minimum = 0.45;
  double exceedanceShare = 0.05;  // 5 % of the usage time
  // Glare autonomy (Jones 2019, Accelerad's "imageless method"; Honeybee's default): the share
  // of occupied hours in which the view's DGP is below this limit (0.40: no disturbing glare).
  double autonomyLimit = 0.40;
  // Spatial disturbing glare (ClimateStudio, Solemma: "the percentage of views ... that
  // experience Disturbing or Intolerable Glare (DGP > 38%) for at least 5% of occupied hours"):
  // a view counts when DGP > disturbingDgp in at least disturbingShare of its occupied hours.
  double disturbingDgp = 0.38;
  double disturbingShare = 0.05;
};

// One view's year, shares of its occupied hours (0..1; 0 when none is occupied).
struct ViewGlareMetrics {
  int occupiedHours = 0;
  double aboveHigh = 0.0;         // DGP > 0.35
  double aboveMedium = 0.0;       // DGP > 0.40
  double aboveMinimum = 0.0;      // DGP > 0.45
  double glareAutonomy = 0.0;     // DGP < autonomyLimit
  double aboveDisturbing = 0.0;   // DGP > disturbingDgp
  bool disturbingGlare = false;   // aboveDisturbing ≥ disturbingShare (counts for sDG)
  En17037Level level = En17037Level::kNone;
};

// Share (0..1) of the occupied hours in which dgp[h] > threshold; 0 without occupied hours.
// Throws std::invalid_argument when the sizes differ.
double shareOfHoursAbove(std::span<const float> dgp, const std::vector<char>& occupied, double threshold);

// EN 17037's level from the shares of occupied hours above its three DGP limits: the highest
// level whose limit is exceeded in no more than exceedanceShare of the hours ("exceeded for no
// more than 5 %": a share of exactly 5 % reaches it).
En17037Level en17037GlareLevel(double aboveHigh, double aboveMedium, double aboveMinimum,
                               const AnnualGlareThresholds& t = {});

// Every metric of one view. Throws std::invalid_argument when the sizes differ.
ViewGlareMetrics viewGlareMetrics(std::span<const float> dgp, const std::vector<char>& occupied,
                                  const AnnualGlareThresholds& t = {});

// Spatial disturbing glare: the share (0..1) of views with disturbingGlare (0 without views).
double spatialDisturbingGlare(const std::vector<ViewGlareMetrics>& views);

// Operable shading chosen hour by hour: closed[h] where closedHours[h] is set, else open[h] (e.g.
// DGP or Ev of a view with the blinds open and closed, LM-83's flags from metrics/annual.h).
// Throws std::invalid_argument when the sizes differ.
std::vector<float> combineByHour(std::span<const float> open, std::span<const float> closed,
                                 const std::vector<char>& closedHours);

}  // namespace candela
