#include "study/compliance/en13201_grids.h"

#include "metrics/en13201.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {
constexpr double kMaxLongitudinalSpacingM = 3.0;   // EN 13201-3: D ≤ 3 m
constexpr double kMaxTransverseSpacingM = 1.5;     // illuminance: d ≤ 1.5 m
constexpr int kLuminancePointsPerLane = 3;
constexpr double kMaxEdgeStripM = 5.0;
}  // namespace

int longitudinalPointCount(double lengthM) {
  if (lengthM <= 30.0) return 10;
  return static_cast<int>(std::ceil(lengthM / kMaxLongitudinalSpacingM - 1e-9));
}

int illuminanceTransverseCount(double widthM) {
  return std::max(3, static_cast<int>(std::ceil(widthM / kMaxTransverseSpacingM - 1e-9)));
}

std::vector<double> bandPositions(double fromM, double widthM, int count) {
  std::vector<double> v;
  const double d = widthM / count;
  for (int k = 0; k < count; ++k) v.push_back(fromM + (k + 0.5) * d);
  return v;
}

std::vector<Vec2> RoadGrids::points(const std::vector<double>& acrossM) const {
  std::vector<Vec2> out;
  out.reserve(alongM.size() * acrossM.size());
  for (double a : alongM)
    for (double c : acrossM) out.push_back(plan(a, c));
  return out;
}

RoadGrids roadGrids(const RoadSpec& road) {
  RoadGrids g;
  g.start = road.start;
  g.along = road.direction;
  g.across = Vec2(-road.direction.y, road.direction.x);
  const int n = longitudinalPointCount(road.lengthM);
  g.spacingAlongM = road.lengthM / n;
  g.alongM = bandPositions(0.0, road.lengthM, n);
  const double laneM = road.widthM / road.lanes;
  for (int lane = 0; lane < road.lanes; ++lane) {
    const std::vector<double> p = bandPositions(lane * laneM, laneM, kLuminancePointsPerLane);
    g.luminanceAcrossM.insert(g.luminanceAcrossM.end(), p.begin(), p.end());
    const Vec2 eye = g.plan(-kObserverDistanceM, (lane + 0.5) * laneM);
    g.observers.push_back(Vec3(eye, kObserverEyeHeightM));
  }
  g.illuminanceAcrossM = bandPositions(0.0, road.widthM, illuminanceTransverseCount(road.widthM));
  g.stripWidthM = std::min(kMaxEdgeStripM, 0.5 * road.widthM);
  const int ns = illuminanceTransverseCount(g.stripWidthM);
  g.nearInsideM = bandPositions(0.0, g.stripWidthM, ns);
  g.nearOutsideM = bandPositions(-g.stripWidthM, g.stripWidthM, ns);
  g.farInsideM = bandPositions(road.widthM - g.stripWidthM, g.stripWidthM, ns);
  g.farOutsideM = bandPositions(road.widthM, g.stripWidthM, ns);
  return g;
}

}  // namespace candela
