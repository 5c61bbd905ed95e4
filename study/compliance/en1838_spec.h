// What a case file says for EN 1838:2013 emergency lighting (docs/emergency.md): the escape
// routes, anti-panic open areas and safety equipment points the emergency luminaires are checked
// at. Read by study/compliance/en1838_case.cpp; the study is study/compliance/en1838.h.
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// An [[escape_route]]: a plan polyline (its centre line) of a route `widthM` wide at `heightM`
// above z = 0 (the floor: EN 1838 measures on the floor).
struct EscapeRouteSpec {
  std::string name;
  std::vector<Vec2> path;       // ≥ 2 points, m
  double widthM = 0.0;          // > 0
  double heightM = 0.0;         // the measuring plane's z, m
  double spacingM = 0.2;        // the points' spacing along and across the route, m
  FileLoc loc, pathLoc;
};

// An [[open_area]] (anti-panic): a convex plan polygon (two `corners` make a rectangle) whose
// core, the area without its 0.5 m border, is checked at `heightM`.
struct OpenAreaSpec {
  std::string name;
  std::vector<Vec2> outline;    // ≥ 3 vertices, counter-clockwise after reading
  double heightM = 0.0;
  double spacingM = 0.25;       // lattice of the core area, and along its boundary, m
  FileLoc loc;
};

// A [[safety_point]]: safety equipment, a fire-fighting point, call point or first-aid post, where
// the vertical illuminance facing `facing` (a plan direction: the side the equipment is seen from)
// must reach 5 lx.
struct SafetyPointSpec {
  std::string name;
  Vec3 positionM{0.0};
  Vec2 facing{0.0, 1.0};        // unit
  FileLoc loc;
};

// Everything of a case that only EN 1838 reads.
struct EmergencySpec {
  std::vector<EscapeRouteSpec> routes;
  std::vector<OpenAreaSpec> openAreas;
  std::vector<SafetyPointSpec> safetyPoints;
  bool any() const { return !routes.empty() || !openAreas.empty() || !safetyPoints.empty(); }
};

}  // namespace candela
