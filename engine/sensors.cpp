#include "engine/sensors.h"

#include "engine/parallel.h"

#include <atomic>

namespace candela {

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads) {
  std::vector<IrradianceEstimate> out(points.size());
  parallelFor(points.size(), threads, [&](size_t i) {
    out[i] = tracer.irradiance(points[i].position, points[i].normal, i, settings);
  });
  return out;
}

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads,
                                                  const std::function<void(size_t done)>& progress) {
  if (!progress) return computeIrradiance(tracer, points, settings, threads);
  std::vector<IrradianceEstimate> out(points.size());
  std::atomic<size_t> done{0};
  parallelFor(points.size(), threads, [&](size_t i) {
    // Point i still uses stream i: the callback changes nothing in the numbers.
    out[i] = tracer.irradiance(points[i].position, points[i].normal, i, settings);
    progress(done.fetch_add(1, std::memory_order_relaxed) + 1);
  });
  return out;
}

}  // namespace candela
