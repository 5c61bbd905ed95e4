// What a case file says for EN 12464-2:2014 outdoor work places (docs/outdoor.md): the outdoor
// task areas ([[task_area]] with standard = "en12464-2") and the glare rating observers
// ([[observer]] with kind = "gr"). Read by study/compliance/en12464_2_case.cpp; the study is
// study/compliance/en12464_2.h.
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// An outdoor task area: its requirements (Ē_m, U0, GR_L, Ra) and what the glare rating needs of
// it (the average reflectance ρ of its surface). Its illuminance grid (horizontal, at `heightM`)
// is an ordinary [[grid]] of the same name in CaseFile::grids, with Ē_m and U0 as its targets.
struct OutdoorTaskAreaSpec {
  std::string name;
  std::vector<Vec2> outline;                 // plan polygon, m
  double heightM = 0.0;                      // the reference surface: the ground (z = 0) unless given
  double maintainedLux = 0.0;                // Ē_m, lx
  std::optional<double> uniformity;          // U0 = E_min / Ē
  std::optional<double> grLimit;             // GR_L
  std::optional<double> ra;                  // required Ra
  std::optional<double> groundReflectance;   // ρ of the area's surface (GR's L_ve), in [0, 1]; unset: the scene's
  std::optional<double> grSpacingM;          // GR observers on a lattice of this pitch over the area
  FileLoc loc, grSpacingLoc;
};

// A GR observer: an eye at `eyeHeightM` above z = 0, looking along one plan direction or all
// around in steps of `stepDeg`, each line of sight `inclinationDeg` above the horizontal
// (negative: below). Its L_ve is its task area's.
struct GrObserverSpec {
  std::string name;
  Vec2 positionM{0.0};
  double eyeHeightM = 1.5;
  std::optional<Vec2> direction;      // one line of sight in plan (unit); unset: all around
  double stepDeg = 45.0;
  double inclinationDeg = -2.0;
  std::string taskArea;               // the outdoor task area (resolved after reading)
  std::optional<double> grLimit;      // overrides the task area's GR_L
  bool fromGrid = false;              // made by a task area's gr_spacing
  FileLoc loc;
  Vec3 eyeM() const { return {positionM.x, positionM.y, eyeHeightM}; }
};

// A point of a neighbouring property where EN 12464-2's obtrusive light is judged (a window):
// the light arriving on the plane of unit normal `normal` (facing the installation).
struct PropertyPointSpec {
  std::string name;
  Vec3 positionM{0.0};
  Vec3 normal{0.0, 1.0, 0.0};
  FileLoc loc;
};

// EN 12464-2:2014 clause 4's obtrusive light (docs/outdoor.md "Obtrusive light"), as the
// [[compliance]] entry gives it: the environmental zone whose limits apply (E1 … E4), the case's
// own limits instead of or beside the zone's (post-curfew values, zone E0), and the property
// points whose vertical illuminance and the luminaires' intensity towards them are judged; the
// upward light ratio is the installation's.
struct ObtrusiveLightSpec {
  std::string zone;                                  // "E1" … "E4"; empty: the limits below only
  std::optional<double> propertyLux, intensityCd;    // the case's limits (they replace the zone's)
  std::optional<double> upwardLightRatio;            // a share in [0, 1]
  std::vector<PropertyPointSpec> points;
  FileLoc loc;
  bool any() const { return !zone.empty() || propertyLux || intensityCd || upwardLightRatio; }
};

// Everything of a case that only EN 12464-2 reads.
struct OutdoorSpec {
  std::vector<OutdoorTaskAreaSpec> areas;
  std::vector<GrObserverSpec> observers;
  bool any() const { return !areas.empty() || !observers.empty(); }
};

}  // namespace candela
