// EN 1838:2013 emergency lighting: the requirements and the verdicts over computed illuminances
// (docs/emergency.md cites the clause of every number). Pure functions: the points and their
// direct illuminance come from study/compliance/en1838.h.
#pragma once

#include "base/math.h"
#include "metrics/targets.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace candela {

// 4.2.1: an escape route up to 2 m wide: ≥ 1 lx on the centre line, the central band (at least
// half the route's width) ≥ 50 % of that; wider routes as several strips of 2 m.
inline constexpr double kEn1838CentreLineLux = 1.0;
inline constexpr double kEn1838CentralBandShare = 0.5;
inline constexpr double kEn1838MaxStripWidthM = 2.0;
// 4.2.2 (escape routes) and 4.3.2 (open areas): max/min at most 40.
inline constexpr double kEn1838MaxMinRatio = 40.0;
// 4.3.1: anti-panic areas: ≥ 0.5 lx on the floor of the core area, the area without its 0.5 m border.
inline constexpr double kEn1838OpenAreaLux = 0.5;
inline constexpr double kEn1838BorderM = 0.5;
// 4.4.1–4.4.2: high-risk task areas: ≥ 10 % of the task's maintained illuminance and ≥ 15 lx;
// uniformity (min/max) ≥ 0.1.
inline constexpr double kEn1838HighRiskShare = 0.1;
inline constexpr double kEn1838HighRiskMinLux = 15.0;
inline constexpr double kEn1838HighRiskUniformity = 0.1;
// 4.1 h) and i): 5 lx vertical at first-aid posts, fire-fighting equipment and call points.
inline constexpr double kEn1838SafetyPointLux = 5.0;
// EN 1838:2013 4.1: a luminaire "near" a point of emphasis is within 2 m of it, horizontally.
inline constexpr double kEn1838NearM = 2.0;

// Minimum, maximum and mean of a set of illuminances (lx); max/min is +inf when the minimum is 0.
struct En1838Stats {
  std::size_t points = 0;
  std::size_t minIndex = 0;  // the point of the minimum (the first of equal ones)
  double minLux = 0.0, maxLux = 0.0, averageLux = 0.0;
  double maxToMin() const;
};
En1838Stats en1838Stats(const std::vector<double>& lux);

// One strip of an escape route (the whole route when it is at most 2 m wide): its lateral offset
// of the centre line from the route's (m, left positive), its width, and the illuminance on its
// centre line and over its central band (half its width).
struct RouteStripResult {
  double offsetM = 0.0, widthM = 0.0;
  En1838Stats centreLine, band;
};

struct EscapeRouteResult {
  std::string name;
  double widthM = 0.0, heightM = 0.0;
  std::vector<Vec2> path;
  std::vector<RouteStripResult> strips;
  // Over every strip: the least and greatest centre-line values, the largest strip's max/min and
  // the least central-band value.
  double minCentreLineLux = 0.0, maxCentreLineLux = 0.0, uniformityRatio = 0.0, centralBandMinLux = 0.0;
  Vec3 minCentreLineAtM{0.0};       // where the centre line's minimum lies
  Verdict verdict = Verdict::kNotChecked;
};
// Fills the route's figures and verdict from its strips (4.2.1, 4.2.2).
void judgeEscapeRoute(EscapeRouteResult& r);

struct OpenAreaResult {
  std::string name;
  double heightM = 0.0;
  std::vector<Vec2> outline, core;  // the area and its core (without the 0.5 m border)
  En1838Stats stats;                // over the core
  Vec3 minAtM{0.0};                 // where its minimum lies
  double uniformityRatio = 0.0;     // max/min
  Verdict verdict = Verdict::kNotChecked;
};
void judgeOpenArea(OpenAreaResult& a);  // 4.3.1, 4.3.2

struct HighRiskAreaResult {
  std::string name;
  double heightM = 0.0;
  std::vector<Vec2> outline;
  double maintainedLux = 0.0;       // the task's maintained illuminance (normal lighting)
  double requiredLux = 0.0;         // max(10 % of it, 15 lx)
  En1838Stats stats;
  Vec3 minAtM{0.0};
  double uniformity = 0.0;          // min/max
  Verdict verdict = Verdict::kNotChecked;
};
void judgeHighRiskArea(HighRiskAreaResult& a);  // 4.4.1, 4.4.2: the minimum against requiredLux

struct SafetyPointResult {
  std::string name;
  Vec3 positionM{0.0};
  Vec2 facing{0.0, 1.0};
  double verticalLux = 0.0;
  // Horizontal distance to the nearest emergency luminaire's photometric centre (m); infinite
  // without one.
  double nearestLuminaireM = std::numeric_limits<double>::infinity();
  Verdict verdict = Verdict::kNotChecked;
};
// 4.1 h), i): 5 lx vertical, and an emergency luminaire near (within 2 m horizontally).
void judgeSafetyPoint(SafetyPointResult& p);

// A luminaire on the plan: emergency or not.
struct En1838Luminaire {
  std::string name;
  Vec2 positionM{0.0};
  bool emergency = false;
};

// One calculation point and its illuminance (the per-point CSV, en1838_points.csv): which part it
// belongs to ("centre line", "central band", "open area core", "high-risk area", "safety point"),
// the route's, area's or point's name, and the sensor (a safety point's faces its equipment).
struct En1838PointValue {
  std::string part, name;
  Vec3 positionM{0.0}, normal{0.0, 0.0, 1.0};
  double lux = 0.0;
};

struct En1838Result {
  std::vector<En1838PointValue> points;  // every point, in the order of the parts below
  std::vector<EscapeRouteResult> routes;
  std::vector<OpenAreaResult> openAreas;
  std::vector<HighRiskAreaResult> highRiskAreas;
  std::vector<SafetyPointResult> safetyPoints;
  std::vector<En1838Luminaire> luminaires;
  std::size_t emergencyLuminaires = 0;
  double maintenanceFactor = 1.0;
  std::vector<std::string> leftOut;  // the surfaces left out (`leave_out`)
  Verdict verdict = Verdict::kNotChecked;  // fail if any fails, pass if all pass
};
// The overall verdict from the parts' (call after judging them).
void judgeEn1838(En1838Result& r);

}  // namespace candela
