#include "study/view_out.h"

#include "base/parallel.h"
#include "base/units.h"
#include "study/sight_line.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What one eye's horizontal rays found.
struct HorizontalView {
  double largestDeg = 0.0, totalDeg = 0.0;
  double minDistanceM = 0.0, medianDistanceM = 0.0;
  bool openHorizon = false;  // a view-out ray left the model: the horizon is seen
};

// The longest circular run of true values.
size_t longestCircularRun(const std::vector<uint8_t>& v) {
  const size_t n = v.size();
  if (std::all_of(v.begin(), v.end(), [](uint8_t b) { return b != 0; })) return n;
  size_t best = 0, run = 0;
  for (size_t k = 0; k < 2 * n; ++k) {  // twice round: a run across index 0 is counted whole
    run = v[k % n] ? run + 1 : 0;
    best = std::max(best, run);
  }
  return std::min(best, n);
}

HorizontalView horizontalView(const Tracer& tracer, const Vec3& eye, const ViewOutOptions& o, uint64_t& rays) {
  const size_t n = static_cast<size_t>(std::llround(360.0 / o.horizontalStepDeg));
  const double step = degToRad(360.0 / static_cast<double>(n));
  std::vector<uint8_t> through(n, 0);
  std::vector<double> distances;
  distances.reserve(n);
  HorizontalView h;
  for (size_t i = 0; i < n; ++i) {
    const double a = (static_cast<double>(i) + 0.5) * step;
    const SightLine line = traceSightLine(tracer, eye, Vec3(std::cos(a), std::sin(a), 0.0), kInf, rays);
    if (line.glazingCrossed == 0) continue;
    through[i] = 1;
    distances.push_back(line.blocked ? line.blockedAtM - line.lastGlazingM : kInf);
    if (!line.blocked) h.openHorizon = true;
  }
  const double stepDeg = 360.0 / static_cast<double>(n);
  h.totalDeg = static_cast<double>(distances.size()) * stepDeg;
  h.largestDeg = static_cast<double>(longestCircularRun(through)) * stepDeg;
  if (!distances.empty()) {
    h.minDistanceM = *std::min_element(distances.begin(), distances.end());
    const auto mid = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
    std::nth_element(distances.begin(), mid, distances.end());
    h.medianDistanceM = *mid;
  }
  return h;
}

// The layers seen along one row of elevation (radians) of the layer rays.
uint8_t layersOfRow(const Tracer& tracer, const Vec3& eye, double elevation, size_t azimuths, uint64_t& rays) {
  uint8_t layers = 0;
  const double ce = std::cos(elevation), se = std::sin(elevation);
  const double step = 2.0 * kPi / static_cast<double>(azimuths);
  for (size_t i = 0; i < azimuths; ++i) {
    const double a = (static_cast<double>(i) + 0.5) * step;
    const Vec3 dir(ce * std::cos(a), ce * std::sin(a), se);
    const SightLine line = traceSightLine(tracer, eye, dir, kInf, rays);
    if (line.glazingCrossed == 0) continue;
    if (!line.blocked) {
      layers |= dir.z > 0.0 ? kLayerSky : kLayerGround;
    } else {
      const double hitZ = eye.z + line.blockedAtM * dir.z;
      const bool ground = std::abs(line.blockerNormal.z) >= kGroundNormalZ && hitZ < eye.z;
      layers |= ground ? kLayerGround : kLayerLandscape;
    }
  }
  return layers;
}

void checkOptions(const ViewOutOptions& o) {
  if (!(o.horizontalStepDeg > 0.0 && o.horizontalStepDeg <= 10.0))
    throw std::invalid_argument("view-out horizontal step must be in (0, 10] degrees");
  if (!(o.layerStepDeg > 0.0 && o.layerStepDeg <= 10.0))
    throw std::invalid_argument("view-out layer step must be in (0, 10] degrees");
}

}  // namespace

std::vector<ViewOut> viewOut(const Tracer& tracer, const std::vector<Vec3>& eyes, const ViewOutOptions& o) {
  checkOptions(o);
  const size_t rows = static_cast<size_t>(std::llround(180.0 / o.layerStepDeg));
  const size_t azimuths = 2 * rows;
  const double rowStep = kPi / static_cast<double>(rows);

  // Work items: per eye its horizontal rays (item 0) and its rows of layer rays (items 1..rows),
  // each writing its own slot, so that the result does not depend on the threads.
  const size_t perEye = rows + 1;
  std::vector<HorizontalView> horizontal(eyes.size());
  std::vector<uint8_t> rowLayers(eyes.size() * rows, 0);
  parallelFor(eyes.size() * perEye, o.threads, [&](size_t item) {
    const size_t e = item / perEye, k = item % perEye;
    uint64_t rays = 0;
    if (k == 0) {
      horizontal[e] = horizontalView(tracer, eyes[e], o, rays);
    } else {
      const double elevation = -0.5 * kPi + (static_cast<double>(k - 1) + 0.5) * rowStep;
      rowLayers[e * rows + (k - 1)] = layersOfRow(tracer, eyes[e], elevation, azimuths, rays);
    }
    tracer.addRays(rays);
  });

  std::vector<ViewOut> out(eyes.size());
  for (size_t e = 0; e < eyes.size(); ++e) {
    ViewOut& v = out[e];
    const HorizontalView& h = horizontal[e];
    v.eye = eyes[e];
    v.sightAngleDeg = h.largestDeg;
    v.totalSightAngleDeg = h.totalDeg;
    v.outsideDistanceM = h.minDistanceM;
    v.medianOutsideDistanceM = h.medianDistanceM;
    for (size_t r = 0; r < rows; ++r) v.layers |= rowLayers[e * rows + r];
    if (h.openHorizon) v.layers |= kLayerLandscape;
    v.sightLevel = viewSightAngleLevel(o.gradeTotalAngle ? v.totalSightAngleDeg : v.sightAngleDeg);
    v.distanceLevel = viewDistanceLevel(v.outsideDistanceM);
    v.layersLevel = viewLayersLevel(v.layers);
    v.level = lowerLevel(lowerLevel(v.sightLevel, v.distanceLevel), v.layersLevel);
  }
  return out;
}

}  // namespace candela
