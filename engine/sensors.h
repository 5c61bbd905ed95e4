// Illuminance at many sensor points, in parallel, reproducibly.
#pragma once

#include "base/distribution.h"
#include "engine/response.h"
#include "engine/tracer.h"
#include "engine/irradiance_estimator.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace candela {

// One sensor: a point and the unit normal of the surface it measures illuminance on, or a
// quantity about the vertical (engine/response.h; EN 12464-1 defines them so): cylindrical and
// hemispherical illuminance about +Z (normal +Z), semi-cylindrical facing the horizontal unit
// `normal`. 56 B: a grid of 10⁶ points holds its sensors in 56 MB.
struct SensorPoint {
  Vec3 position;  // m
  Vec3 normal;    // unit vector
  Quantity quantity = Quantity::kPlanar;
  Response response() const {
    const Vec3 up(0.0, 0.0, 1.0);
    switch (quantity) {
      case Quantity::kPlanar: return Response::planar(normal);
      case Quantity::kSemiCylindrical: return {quantity, up, normal};
      default: return {quantity, up, Vec3(1.0, 0.0, 0.0)};
    }
  }
};

// Estimates irradiance at every sensor (point i uses random stream i), on `threads` threads
// (0 = all cores).
std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads);

// Same results, and after each point calls progress(done), done = points finished so far
// (1..n, in no particular order). It is called concurrently from the worker threads, so it must
// be thread-safe and cheap (e.g. a throttled progress bar); an empty function is allowed.
// With a distribution, the cache's records and the points are shared between its processes
// (base/distribution.h): every process gets every estimate, the same bytes as one process
// computes; done counts this process's points.
// 6 parameters: the batch entry point's inputs, its progress and its processes.
std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads,
                                                  const std::function<void(size_t done)>& progress,
                                                  const Distribution& distribution = localDistribution());

// Points evaluated per block by computeIrradianceInBlocks: 65 536 estimates (3 MiB) at a time.
inline constexpr size_t kSensorBlockPoints = size_t{1} << 16;

// The same estimates, handed out in order a block at a time instead of held: after the cache is
// filled over all the points, the points [first, first + n) are estimated (shared between the
// processes as above) and block(first, estimates, n) is called on every process, blocks in
// increasing order, n ≤ blockPoints; the estimates are gone after the call. A study of 10⁶ points
// holds one block of estimates, not 10⁶ (docs/distributed.md#memory-for-large-grids). The
// numbers do not depend on blockPoints.
// groupEnds: the points in groups of consecutive points (a study's grids), group k being
// [groupEnds[k−1], groupEnds[k]) and the last end points.size(); with groups and
// settings.gridTargetRelativeError > 0 the grids' target replaces the per-point one (each
// point's goal set by its group's mean, docs/estimator.md#the-grids-error-target).
// 9 parameters: computeIrradiance's six, the block consumer, the block size and the groups.
void computeIrradianceInBlocks(const Tracer& tracer, const std::vector<SensorPoint>& points,
                               const TraceSettings& settings, int threads,
                               const std::function<void(size_t done)>& progress, const Distribution& distribution,
                               const std::function<void(size_t first, const IrradianceEstimate* estimates, size_t n)>& block,
                               size_t blockPoints = kSensorBlockPoints, const std::vector<size_t>& groupEnds = {});

}  // namespace candela
