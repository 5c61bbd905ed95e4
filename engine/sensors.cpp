#include "engine/sensors.h"

#include "engine/irradiance_cache.h"
#include "engine/parallel.h"

#include <atomic>
#include <optional>

namespace candela {

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads) {
  return computeIrradiance(tracer, points, settings, threads, {});
}

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads,
                                                  const std::function<void(size_t done)>& progress) {
  // Cache method: the cache is filled first in a fixed order and frozen (engine/irradiance_cache.h),
  // so that evaluating the points in parallel reads it only.
  std::optional<IrradianceCache> cache;
  if (settings.method == Method::kCache && settings.maxBounces > 0)
    cache.emplace(buildIrradianceCache(tracer, points, settings, threads));
  const IrradianceCache* c = cache ? &*cache : nullptr;
  std::vector<IrradianceEstimate> out(points.size());
  std::atomic<size_t> done{0};
  parallelFor(points.size(), threads, [&](size_t i) {
    // Point i uses stream i whatever the thread: the callback changes nothing in the numbers.
    out[i] = tracer.irradiance(points[i].position, points[i].normal, i, settings, c);
    if (progress) progress(done.fetch_add(1, std::memory_order_relaxed) + 1);
  });
  return out;
}

}  // namespace candela
