// Filling Ward's irradiance cache (engine/irradiance_cache.h) before any point is evaluated:
// phase A walks the points' hemisphere rays in a fixed order on one thread and places a record
// at every first diffuse hit no record covers (its radius from the harmonic mean distance);
// phase B computes the records' values in parallel, record i from its own random stream. With
// two levels, phase A over the first level's record rays places the second level, whose values
// are computed and frozen before the first level's.
#pragma once

#include "base/distribution.h"
#include "engine/irradiance_cache.h"
#include "engine/response.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace candela {

struct SensorPoint;
class Rng;
class Tracer;

// Phases A and B: the records the points' first diffuse hits need, with their values.
// Deterministic: phase A walks the points and their hemisphere cells in order on one thread;
// phase B computes record i from random stream i on `threads` threads. With two levels, between
// the two phases: phase A over the first level's record rays gives the second level's records,
// whose values are computed (phase B) and frozen; the first level's values then use them.
// After phase B, radii are limited by the records' gradients (R_i ≤ E_i/|∇_t E_i|) and phases A
// and B run again for the queries that left uncovered (twice at most). With a distribution,
// phase A's first hits are gathered and phase B's values computed shared between the processes;
// every process walks phase A's hits itself (the serial part, docs/distributed.md).
// `checkpoint`, when set, is called (from any thread) after each batch of phase A and each
// record's value: a caller that must be able to stop the build throws from it.
IrradianceCache buildIrradianceCache(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                     const TraceSettings& settings, int threads,
                                     const Distribution& distribution = localDistribution(),
                                     const std::function<void()>& checkpoint = {});

// The first diffuse hits, on surfaces the cache serves, of the initial hemisphere cells that
// estimateIrradiance(tracer, p, n, pointIndex, s, {cache}) will trace (same directions), appended to out.
// 6 parameters: the sensor estimate's own inputs plus the output list.
void cacheQueries(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                  std::vector<CacheQuery>& out);
// The same for a sensor of another response (engine/response.h): its warp's directions.
void cacheQueries(const Tracer& tracer, const Vec3& p, const Response& response, uint64_t pointIndex,
                  const TraceSettings& s, std::vector<CacheQuery>& out);
// Harmonic mean distance (m) to the surfaces seen from q over `rays` stratified cosine rays
// (Ward et al. 1988's R_i); infinity when every ray escapes.
double harmonicMeanDistance(const Tracer& tracer, const CacheQuery& q, int rays, Rng& rng);
// Fills r.e, its gradients and variance from s.cache.recordSamples hemisphere rays, random
// stream `stream`; r lies at diffuse bounce `level` (1: a sensor ray's first hit). The first
// diffuse hits of its rays take their indirect irradiance from `deeper` when given (a frozen
// second-level cache); beyond, bounces are path traced with Russian roulette (the closure).
// 6 parameters: the record, its stream and level, the settings and the deeper cache are all inputs.
void computeRecord(const Tracer& tracer, IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                   const IrradianceCache* deeper = nullptr, int level = 1);
// The first diffuse hits, on surfaces the cache serves, of the hemisphere rays that
// computeRecord(tracer, r, stream, s, ...) will trace (same directions), appended to out.
void recordQueries(const Tracer& tracer, const IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                   std::vector<CacheQuery>& out);
// Whether a record may serve point p (normal n) on `shape`: the segment between the two
// points, each lifted off its surface, meets no shape but theirs. Its ray is added to `rays`.
// 6 parameters: IrradianceCache::Visibility's five and the tracer.
bool cacheVisible(const Tracer& tracer, const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r,
                  uint64_t& rays);

}  // namespace candela
