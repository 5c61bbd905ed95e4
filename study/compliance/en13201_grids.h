// The EN 13201-3 calculation grids and observers of a road (docs/road.md): pure geometry over a
// RoadSpec, in plan, on the road surface z = 0.
#pragma once

#include "base/math.h"
#include "study/compliance/en13201_spec.h"

#include <vector>

namespace candela {

// Points along the field: N = 10 when the field is at most 30 m long, else the least N with
// D = S/N ≤ 3 m; they lie at D/2, 3D/2, ... from the field's start.
int longitudinalPointCount(double lengthM);
// Points across a band `widthM` wide: luminance 3 a lane; illuminance n ≥ 3 with d = W/n ≤ 1.5 m.
// Each at d/2, 3d/2, ... from the band's edge.
int illuminanceTransverseCount(double widthM);
std::vector<double> bandPositions(double fromM, double widthM, int count);

// A road's grids as distances along (from the field's start) and across (from the near edge,
// positive to the left of the direction), and as plan points.
struct RoadGrids {
  Vec2 start{0.0}, along{1.0, 0.0}, across{0.0, 1.0};
  std::vector<double> alongM;              // N positions, D/2 + i D
  double spacingAlongM = 0.0;              // D
  std::vector<double> luminanceAcrossM;    // 3 per lane, lane 1 first
  std::vector<double> illuminanceAcrossM;  // over the whole width
  // Edge strips (edge illuminance ratio): `stripWidthM` = min(5 m, width/2) wide, inside and
  // outside each edge (near edge at 0, far edge at width).
  double stripWidthM = 0.0;
  std::vector<double> nearInsideM, nearOutsideM, farInsideM, farOutsideM;
  // The luminance observers: one a lane, 60 m before the field, in the lane's middle, eyes 1.5 m up.
  std::vector<Vec3> observers;
  Vec2 plan(double alongM, double acrossM) const { return start + along * alongM + across * acrossM; }
  // Every (along, across) pair in order: along-major (all of one cross-section, then the next).
  std::vector<Vec2> points(const std::vector<double>& acrossM) const;
};
RoadGrids roadGrids(const RoadSpec& road);

}  // namespace candela
