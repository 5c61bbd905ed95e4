#include "engine/sensors.h"

#include "engine/cache_builder.h"
#include "engine/random_streams.h"
#include "engine/irradiance_estimator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace candela {

namespace {

// Batch b > 0 of point i draws from stream i + b·2^40 (far from every point's own stream); the
// path-method batches of a cache-method point (below) from i + 2^39 + b·2^40.
constexpr uint64_t kBatchStride = streams::kBatchStride;
constexpr uint64_t kWithoutCacheStream = streams::kWithoutCacheOffset;

// Batches of one point until the standard error of their mean is at most target × the mean, or
// maxBatches are spent. After each round the batches still needed are predicted from the
// current error (n ∝ σ²), so few rounds are needed; the stopping rule looks at the estimate
// itself, a small bias that the test ErrorBarsCoverTheirShare checks stays within the error
// bars. The records' share of each batch's variance (cache method) is the same frozen cache's,
// so it is not divided by the batches: Var = Σ (σ²_b − r_b)/B² + (Σ √r_b / B)² (the records
// fully correlated from batch to batch, an upper bound).
class Batches {
 public:
  explicit Batches(const IrradianceEstimate& first) { add(first); }
  void add(const IrradianceEstimate& e) {
    sum_ += e.irradiance;
    sumOwn_ += std::max(0.0, e.variancePhotopic - e.varianceRecordsPhotopic);
    sumRecordsSd_ += std::sqrt(std::max(0.0, e.varianceRecordsPhotopic));
    ++n_;
  }
  int count() const { return n_; }
  double mean() const { return photopic(sum_) / n_; }
  double ownVariance() const { return sumOwn_ / (static_cast<double>(n_) * n_); }
  double recordsVariance() const { return (sumRecordsSd_ / n_) * (sumRecordsSd_ / n_); }
  double variance() const { return ownVariance() + recordsVariance(); }
  // Batches (in all) that should bring the standard error to `goal` (σ² ∝ 1/B for the own part).
  double wanted(double goal) const {
    const double left = goal * goal - recordsVariance();
    if (left <= 0.0) return std::numeric_limits<double>::infinity();
    return std::ceil(sumOwn_ / n_ / left);
  }
  IrradianceEstimate result(bool withoutCache) const {
    IrradianceEstimate out;
    out.irradiance = sum_ / static_cast<double>(n_);
    out.variancePhotopic = variance();
    out.varianceRecordsPhotopic = recordsVariance();
    out.withoutCache = withoutCache;
    return out;
  }

 private:
  Rgb sum_{0.0};
  double sumOwn_ = 0.0, sumRecordsSd_ = 0.0;
  int n_ = 0;
};

// A point's target: its standard error at most max(relative × its value, floor) (photopic).
// The per-point target has floor 0; the grids' target has relative = g and floor g × the
// group's mean (docs/estimator.md#the-grids-error-target).
struct Goal {
  double relative = 0.0;
  double floor = 0.0;
  bool any() const { return relative > 0.0 || floor > 0.0; }
  double at(double mean) const { return std::max(relative * mean, floor); }
};

// Batches of the point from `first` on (streams base + b·2^40, b ≥ 1) until the target or the
// cap; false when the records' share alone keeps the error above the target (more batches of the
// frozen cache cannot help).
bool sampleToTarget(const Tracer& tracer, const SensorPoint& pt, uint64_t base, const TraceSettings& s,
                    const IrradianceCache* cache, const Goal& g, Batches& b) {
  const int maxBatches = std::max(1, s.maxBatches);
  while (b.count() < maxBatches) {
    const double mean = b.mean();
    const double goal = g.at(mean);
    if (mean <= 0.0 || b.variance() <= goal * goal) return true;
    // Half the target's variance is what the records may take and still leave the own part
    // enough room (docs/accuracy.md#the-presets-per-point-target).
    if (cache && b.recordsVariance() > 0.5 * goal * goal) return false;
    const int target = std::min<double>(maxBatches, std::max<double>(b.count() + 1, b.wanted(goal)));
    while (b.count() < target)
      b.add(estimateIrradiance(tracer, pt.position, pt.response(), base + kBatchStride * static_cast<uint64_t>(b.count()), s, {cache}));
  }
  return true;
}

// One point: a single estimate, or with a target error, batches until it is met (above). A
// cache-method point whose cached share alone is above the target is estimated again by the
// path method (unbiased, and its batches do reduce every part of the error).
IrradianceEstimate estimatePoint(const Tracer& tracer, const SensorPoint& pt, size_t i, const TraceSettings& s,
                                 const IrradianceCache* cache, const Goal& g) {
  IrradianceEstimate first = estimateIrradiance(tracer, pt.position, pt.response(), i, s, {cache});
  if (!g.any()) return first;
  Batches b(first);
  if (sampleToTarget(tracer, pt, i, s, cache, g, b)) return b.result(false);
  TraceSettings path = s;
  path.method = Method::kPath;
  const uint64_t base = i + kWithoutCacheStream;
  Batches p(estimateIrradiance(tracer, pt.position, pt.response(), base, path));
  sampleToTarget(tracer, pt, base, path, nullptr, g, p);
  return p.result(true);
}

// The grids' target needs each group's mean before its points are estimated. It is taken from a
// pilot: up to kPilotPoints of the group's points, evenly spread, each estimated once with an
// eighth of the hemisphere samples and a quarter of the light samples (the same method and
// frozen cache; streams kGridPilot + i). Every process computes the whole pilot (kShared), and
// each pilot point has its own stream, so the scale, and with it every point's goal, is the same
// for any number of threads, processes, shards and blocks. The goal needs a scale, not a
// measurement: a pilot mean a few per cent off moves every goal by as much.
constexpr size_t kPilotPoints = 64;

TraceSettings pilotSettings(const TraceSettings& s) {
  TraceSettings p = s;
  p.hemisphereSamples = std::max(64, s.hemisphereSamples / 8);
  p.lightSamples = std::max(8, s.lightSamples / 4);
  p.firstBounceSplit = std::max(1, s.firstBounceSplit / 4);
  p.targetRelativeError = 0.0;
  p.gridTargetRelativeError = 0.0;
  return p;
}

// Each group's mean photopic irradiance by the pilot (groups [ends[k−1], ends[k])).
std::vector<double> groupScales(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                const TraceSettings& settings, const IrradianceCache* cache,
                                const std::vector<size_t>& ends, int threads, const Distribution& distribution) {
  struct Pick {
    size_t group, point;
  };
  std::vector<Pick> picks;
  size_t begin = 0;
  for (size_t k = 0; k < ends.size(); ++k) {
    const size_t n = ends[k] - begin;
    const size_t m = std::min(n, kPilotPoints);
    for (size_t j = 0; j < m; ++j) picks.push_back({k, begin + (2 * j + 1) * n / (2 * m)});
    begin = ends[k];
  }
  const TraceSettings pilot = pilotSettings(settings);
  std::vector<double> values(picks.size());
  distributedFill(distribution, values, ItemUse::kShared, threads, [&](size_t j, double& v) {
    const SensorPoint& pt = points[picks[j].point];
    v = photopic(estimateIrradiance(tracer, pt.position, pt.response(), streams::kGridPilot.first + picks[j].point, pilot, {cache})
                     .irradiance);
  });
  std::vector<double> sum(ends.size(), 0.0), count(ends.size(), 0.0);
  for (size_t j = 0; j < picks.size(); ++j) sum[picks[j].group] += values[j], count[picks[j].group] += 1.0;
  for (size_t k = 0; k < ends.size(); ++k) sum[k] = count[k] > 0.0 ? std::max(0.0, sum[k] / count[k]) : 0.0;
  return sum;
}

}  // namespace

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads) {
  return computeIrradiance(tracer, points, settings, threads, {});
}

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads,
                                                  const std::function<void(size_t done)>& progress,
                                                  const Distribution& distribution) {
  std::vector<IrradianceEstimate> out(points.size());
  // One block of every point: a single fill, as before blocks existed.
  computeIrradianceInBlocks(
      tracer, points, settings, threads, progress, distribution,
      [&out](size_t first, const IrradianceEstimate* e, size_t n) { std::copy(e, e + n, out.begin() + first); },
      std::max<size_t>(1, points.size()));
  return out;
}

void computeIrradianceInBlocks(const Tracer& tracer, const std::vector<SensorPoint>& points,
                               const TraceSettings& settings, int threads,
                               const std::function<void(size_t done)>& progress, const Distribution& distribution,
                               const std::function<void(size_t first, const IrradianceEstimate* estimates, size_t n)>& block,
                               size_t blockPoints, const std::vector<size_t>& groupEnds) {
  // Cache method: the cache is filled first in a fixed order and frozen (engine/irradiance_cache.h),
  // so that evaluating the points in parallel reads it only.
  // While the cache is built no point is done: progress(0) lets an observer that stops runs
  // (the Python module's Ctrl-C) throw there too.
  std::optional<IrradianceCache> cache;
  if (settings.method == Method::kCache && settings.maxBounces > 0)
    cache.emplace(buildIrradianceCache(tracer, points, settings, threads, distribution, [&progress] {
      if (progress) progress(0);
    }));
  const IrradianceCache* c = cache ? &*cache : nullptr;
  // The grids' target replaces the per-point one where the points come in groups.
  const bool grids = settings.gridTargetRelativeError > 0.0 && !groupEnds.empty();
  if (grids && groupEnds.back() != points.size())
    throw std::invalid_argument("computeIrradianceInBlocks: the groups must end at the last point");
  const std::vector<double> scales =
      grids ? groupScales(tracer, points, settings, c, groupEnds, threads, distribution) : std::vector<double>{};
  // The setup (cache, pilot) is over: an observer's ETA counts from here (cli/progress.h).
  if (progress && (c || grids)) progress(0);
  const auto goalOf = [&](size_t i) {
    if (!grids) return Goal{settings.targetRelativeError, 0.0};
    const size_t k = static_cast<size_t>(std::upper_bound(groupEnds.begin(), groupEnds.end(), i) - groupEnds.begin());
    return Goal{settings.gridTargetRelativeError, settings.gridTargetRelativeError * scales[k]};
  };
  blockPoints = std::max<size_t>(1, blockPoints);
  std::vector<IrradianceEstimate> out(std::min(blockPoints, points.size()));
  std::atomic<size_t> done{0};
  for (size_t first = 0; first < points.size(); first += blockPoints) {
    const size_t n = std::min(blockPoints, points.size() - first);
    distributedFill(distribution, out.data(), n, ItemUse::kResult, threads, [&](size_t j, IrradianceEstimate& e) {
      // Point i uses stream i whatever the thread, process or block: the callback changes
      // nothing in the numbers.
      const size_t i = first + j;
      e = estimatePoint(tracer, points[i], i, settings, c, goalOf(i));
      if (progress) progress(done.fetch_add(1, std::memory_order_relaxed) + 1);
    });
    block(first, out.data(), n);
  }
}

}  // namespace candela
