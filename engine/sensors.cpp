#include "engine/sensors.h"

#include "engine/cache_builder.h"
#include "base/parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

namespace candela {

namespace {

// Batch b > 0 of point i draws from stream i + b·2^40 (far from every point's own stream).
constexpr uint64_t kBatchStride = 1ULL << 40;

// One point: a single estimate, or with a target error, batches until the standard error of
// their mean is at most target × the mean. After each round the batches still needed are
// predicted from the current error (n ∝ σ²), so few rounds are needed; the stopping rule looks at
// the estimate itself, a small bias that the test ErrorBarsCoverTheirShare checks stays within
// the error bars.
IrradianceEstimate estimatePoint(const Tracer& tracer, const SensorPoint& pt, size_t i, const TraceSettings& s,
                                 const IrradianceCache* cache) {
  IrradianceEstimate first = tracer.irradiance(pt.position, pt.normal, i, s, cache);
  if (s.targetRelativeError <= 0.0) return first;
  Rgb sum = first.irradiance;
  double sumVar = first.variancePhotopic;
  int batches = 1;
  const int maxBatches = std::max(1, s.maxBatches);
  while (batches < maxBatches) {
    const double mean = photopic(sum) / batches;
    const double se = std::sqrt(std::max(0.0, sumVar)) / batches;
    if (mean <= 0.0 || se <= s.targetRelativeError * mean) break;
    // The standard error of a mean of B batches is √(Σ var)/B ≈ σ₁/√B: B = (se₁ / (t·mean))².
    const double perBatch = std::sqrt(sumVar / batches);
    const double want = std::ceil(std::pow(perBatch / (s.targetRelativeError * mean), 2.0));
    const int target = std::min<double>(maxBatches, std::max<double>(batches + 1, want));
    for (; batches < target; ++batches) {
      const IrradianceEstimate e =
          tracer.irradiance(pt.position, pt.normal, i + kBatchStride * static_cast<uint64_t>(batches), s, cache);
      sum += e.irradiance;
      sumVar += e.variancePhotopic;
    }
  }
  IrradianceEstimate out;
  out.irradiance = sum / static_cast<double>(batches);
  out.variancePhotopic = sumVar / (static_cast<double>(batches) * batches);
  return out;
}

}  // namespace

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
    out[i] = estimatePoint(tracer, points[i], i, settings, c);
    if (progress) progress(done.fetch_add(1, std::memory_order_relaxed) + 1);
  });
  return out;
}

}  // namespace candela
