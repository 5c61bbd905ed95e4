// Illuminance at many sensor points, in parallel, reproducibly.
#pragma once

#include "base/distribution.h"
#include "engine/tracer.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace candela {

// One sensor: a point and the unit normal of the surface it measures illuminance on.
struct SensorPoint {
  Vec3 position;  // m
  Vec3 normal;    // unit vector
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

}  // namespace candela
