#include "engine/cache_builder.h"

#include "base/parallel.h"
#include "base/rng.h"
#include "engine/integrator_path.h"
#include "engine/irradiance_estimator.h"
#include "engine/materials/family.h"
#include "engine/sampling.h"
#include "engine/sensors.h"
#include "engine/trace_context.h"
#include "engine/tracer.h"
#include "engine/random_streams.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Random streams of phase A (record radii) and phase B (record values), apart from the points'.
constexpr uint64_t kRadiusStream = streams::kRecordRadii.first;
constexpr uint64_t kRecordStream = streams::kRecords.first;
// The second level's (two-level cache).
constexpr uint64_t kRadiusStream2 = streams::kRecordRadii2.first;
constexpr uint64_t kRecordStream2 = streams::kRecords2.first;

// A record's hemisphere directions come from a stream of their own (its value stream + this),
// so that the second level's phase A (recordQueries) traces exactly the directions phase B will.
constexpr uint64_t kRecordDirectionOffset = streams::kRecordDirectionOffset;

int recordThetaStrata(const TraceSettings& s) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(s.cache.recordSamples / kPi))));
}
int recordPhiStrata(const TraceSettings& s) { return std::max(2, s.cache.recordSamples / recordThetaStrata(s)); }

// The cacheable first hits of mTheta × nPhi stratified rays from o (the strata in order,
// jittered by dirRng, each (u1, u2) made a direction by dirOf: cosine-weighted about a frame's
// normal, or a sensor response's warp), appended to out; shared by cacheQueries and recordQueries.
// 8 parameters: the ray fan (origin, warp, strata, skip, stream) and the output are separate inputs.
template <class DirectionOf>
void hemisphereCacheQueries(const Tracer& tracer, const Vec3& o, const DirectionOf& dirOf, int mTheta, int nPhi,
                            uint32_t skip, Rng& dirRng, std::vector<CacheQuery>& out) {
  const Scene& scene = tracer.scene();
  uint64_t rays = 0;
  for (int c = 0; c < mTheta * nPhi; ++c) {
    const int j = c / nPhi, k = c % nPhi;
    const double u1 = (j + dirRng.uniform()) / mTheta;
    const double u2 = (k + dirRng.uniform()) / nPhi;
    const Vec3 dir = dirOf(u1, u2);
    RayHit h;
    if (tracer.hasAntimatter()) {
      // Past clipped surfaces; no record where the listed surfaces are clipped or on a hole's
      // side (paths trace those vertices: engine/integrator_path.cpp).
      ClipState st;
      ClipResult step;
      if (!firstSeen(tracer.accelerator(), scene, o, dir, skip, st, h, step, rays)) continue;
      if (step.action == ClipAction::kShown || !isEmpty(st)) continue;
    } else {
      ++rays;
      if (!tracer.accelerator().intersect(o, dir, 0.0, kInf, h, skip)) continue;
    }
    const Shape shape = scene.surface(h.shape);  // a shape or a mesh triangle
    const Material* m = seenMaterial(scene.materials, scene.materials[shape.material]);
    if (!m || !familyOf(*m).cacheable(*m)) continue;
    const Vec3 x = o + h.t * dir;
    const Vec3 ng = shapeNormal(shape, x);
    out.push_back({x, glm::dot(dir, ng) < 0.0 ? ng : -ng, isFlat(shape) ? h.shape : kNoShape, h.shape});
  }
  tracer.addRays(rays);
}

// Phase A's input: `items` items whose cacheable first hits gather(i, out) appends in order.
struct QuerySource {
  size_t items = 0;
  std::function<void(size_t, std::vector<CacheQuery>&)> gather;
};

// What traces a build, on which threads and processes.
struct BuildContext {
  const Tracer& tracer;
  int threads;
  const Distribution& distribution;
  const std::function<void()>& checkpoint;  // may be empty
};

// Phase A over a list of queries, gathered in parallel in batches and shared between the
// processes (each source item's queries as bytes), then walked in order on one thread by every
// process alike: an uncovered hit becomes a record whose R_i comes from stream radiusStream +
// its index. The batch's size changes nothing in the walk.
void placeRecords(IrradianceCache& cache, const BuildContext& ctx, const QuerySource& src, uint64_t radiusStream,
                  const TraceSettings& settings) {
  constexpr size_t kBatch = 512;
  std::vector<std::vector<std::byte>> hits;
  uint64_t rays = 0;  // the coverage tests' visibility rays
  for (size_t b = 0; b < src.items; b += kBatch) {
    if (ctx.checkpoint) ctx.checkpoint();
    const size_t e = std::min(src.items, b + kBatch);
    hits.assign(e - b, {});
    ctx.distribution.fillLists(hits, ItemUse::kShared, ctx.threads, [&](size_t i, std::vector<std::byte>& bytes) {
      std::vector<CacheQuery> list;
      src.gather(b + i, list);
      bytes.resize(list.size() * sizeof(CacheQuery));
      if (!list.empty()) std::memcpy(bytes.data(), list.data(), bytes.size());
    });
    std::vector<CacheQuery> queries;
    for (const std::vector<std::byte>& item : hits)
      for (size_t at = 0; at + sizeof(CacheQuery) <= item.size(); at += sizeof(CacheQuery)) {
        CacheQuery q;
        std::memcpy(&q, item.data() + at, sizeof q);
        queries.push_back(q);
      }
    // Which record covers each query in the cache as the batch begins, on every thread; then in
    // order, exactly as one thread asking covers() before each add: a query covered by a record
    // that has not shrunk since is still covered (radii only shrink, visibility is geometry), and
    // every other query is asked again.
    const size_t batchStart = cache.size();
    std::vector<int64_t> first(queries.size());
    std::vector<uint64_t> queryRays(queries.size(), 0);
    parallelFor(queries.size(), ctx.threads, [&](size_t i) {
      first[i] = cache.firstCovering(queries[i].p, queries[i].n, queries[i].shape, &queryRays[i]);
    });
    for (uint64_t r : queryRays) rays += r;
    std::vector<uint8_t> shrankFlag(batchStart, 0);
    std::vector<uint32_t> shrunk;
    for (size_t i = 0; i < queries.size(); ++i) {
      const CacheQuery& q = queries[i];
      const bool stillCovered = first[i] >= 0 && !shrankFlag[static_cast<size_t>(first[i])];
      if (stillCovered || cache.covers(q.p, q.n, q.shape, &rays)) continue;
      IrradianceRecord r;
      r.p = q.p;
      r.n = q.n;
      r.skip = q.skip;
      r.shape = q.shape;
      Rng rng(settings.seed, radiusStream + cache.size());
      r.radiusM = harmonicMeanDistance(ctx.tracer, q, settings.cache.radiusSamples, rng);
      shrunk.clear();
      cache.add(r, &shrunk);
      for (uint32_t j : shrunk)
        if (j < batchStart) shrankFlag[j] = 1;
    }
  }
  ctx.tracer.addRays(rays);
}

// Radiance's radius clamp (src/rt/ambcomp.c, doambient(): a radius times the position gradient
// relative to the value is at most 1; after Schwarzhaupt, Jensen & Jarosz 2012): R_i ≤
// E_i/|∇_t E_i|, so that the first-order extrapolation changes the value by at most a·E_i within
// the record's valid radius a·R_i. Where E grows steeply (towards the sunlit side of a contact)
// the split-sphere radius alone lets curvature bias the extrapolation (docs/accuracy.md
// #near-contact-cache-bias-cause-and-fix). The gradient counts beyond twice its standard error
// only (the record's covariance along the gradient): in an even field (an integrating sphere) the
// sampled gradient is noise alone and would shrink radii for nothing. True when R_i shrank.
bool limitRadiusByGradient(IrradianceRecord& r, const CacheSettings& c) {
  if (!c.gradients) return false;
  const double e = photopic(r.e);
  const Vec3 g = 0.265 * r.gradT[0] + 0.670 * r.gradT[1] + 0.065 * r.gradT[2];
  const double len = glm::length(g);
  if (e <= 0.0 || len <= 0.0) return false;
  const Vec3 u = g / len;
  RecordVector b{};
  for (int i = 0; i < 3; ++i) b[4 + i] = u[i];
  const double gl = len - 2.0 * std::sqrt(recordQuadratic(r, b));
  if (gl * r.radiusM <= e) return false;
  const double limited = std::max(c.minSpacingM / c.accuracy, e / gl);
  if (limited >= r.radiusM) return false;
  r.radiusM = limited;
  return true;
}

// A frame's cosine-weighted directions.
auto cosineAbout(const Frame& frame) {
  return [frame](double u1, double u2) { return frame.toWorld(sampleCosineHemisphere(u1, u2)); };
}

}  // namespace

void cacheQueries(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                  std::vector<CacheQuery>& out) {
  cacheQueries(tracer, p, Response::planar(n), pointIndex, s, out);
}

void cacheQueries(const Tracer& tracer, const Vec3& p, const Response& response, uint64_t pointIndex,
                  const TraceSettings& s, std::vector<CacheQuery>& out) {
  if (s.maxBounces < 1) return;
  Rng dirRng(s.seed, kDirectionStream + pointIndex);
  const int m = hemisphereThetaStrata(s, response), n = hemispherePhiStrata(s, response);
  if (response.isPlanar())
    hemisphereCacheQueries(tracer, p, cosineAbout(Frame::fromNormal(response.n)), m, n, kNoShape, dirRng, out);
  else
    hemisphereCacheQueries(tracer, p, [&response](double u1, double u2) { return response.sample(u1, u2); }, m, n,
                           kNoShape, dirRng, out);
}

bool cacheVisible(const Tracer& tracer, const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r,
                  uint64_t& rays) {
  const Vec3 a = p + Tracer::originOffset(p) * n, b = r.p + Tracer::originOffset(r.p) * r.n;
  const Vec3 d = b - a;
  const double len = glm::length(d);
  if (len <= 0.0) return true;
  // Both endpoints' own shapes are skipped: a chord of a convex surface passes inside it.
  ++rays;
  return !tracer.accelerator().occluded(a, d / len, 0.0, len, shape, r.shape);
}

double harmonicMeanDistance(const Tracer& tracer, const CacheQuery& q, int rays, Rng& rng) {
  const Strata2D strata(std::max(1, rays), 1.0 / kPi);
  const Frame frame = Frame::fromNormal(q.n);
  const Vec3 o = q.p + Tracer::originOffset(q.p) * q.n;
  double inv = 0.0;
  uint64_t cast = 0;
  for (int i = 0; i < strata.size(); ++i) {
    const Vec2 u = strata.sample(i, rng);
    RayHit h;
    ++cast;
    if (tracer.accelerator().intersect(o, frame.toWorld(sampleCosineHemisphere(u.x, u.y)), 0.0, kInf, h, q.skip))
      inv += 1.0 / std::max(h.t, 1e-9);
  }
  tracer.addRays(cast);
  return inv > 0.0 ? strata.size() / inv : kInf;
}

void recordQueries(const Tracer& tracer, const IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                   std::vector<CacheQuery>& out) {
  Rng dirRng(s.seed, stream + kRecordDirectionOffset);
  hemisphereCacheQueries(tracer, r.p + Tracer::originOffset(r.p) * r.n, cosineAbout(Frame::fromNormal(r.n)),
                         recordThetaStrata(s), recordPhiStrata(s), r.skip, dirRng, out);
}

void computeRecord(const Tracer& tracer, IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                   const IrradianceCache* deeper, int level) {
  Rng rng(s.seed, stream), dirRng(s.seed, stream + kRecordDirectionOffset);
  TraceContext ctx(tracer, s, rng);
  HemisphereSamples h;
  h.m = recordThetaStrata(s);
  h.n = recordPhiStrata(s);
  const int cells = h.m * h.n;
  h.radiance.resize(cells);
  h.distanceM.resize(cells);
  h.local.resize(cells);
  const Frame frame = Frame::fromNormal(r.n);
  const Vec3 o = r.p + Tracer::originOffset(r.p) * r.n;
  CacheUse use;
  use.cache = deeper;
  use.depth = level;
  for (int c = 0; c < cells; ++c) {
    const int j = c / h.n, k = c % h.n;
    const double u1 = (j + dirRng.uniform()) / h.m;
    const double u2 = (k + dirRng.uniform()) / h.n;
    h.local[c] = sampleCosineHemisphere(u1, u2);
    const Vec3 dir = frame.toWorld(h.local[c]);
    // Everything but the sampled sources (which every lookup samples itself): sky and glow seen,
    // and light reflected by deeper bounces: from the second-level cache at the rays' first
    // diffuse hits when there is one, path traced with Russian roulette by albedo beyond.
    use.tally.setCell(c);
    PathState st;
    st.skip = r.skip;
    st.diffuse = level;
    st.misCosPdf = h.local[c].z * kInvPi;
    // Glows that a lookup samples from here are left out (glowSampledFrom at o; a lookup at
    // x samples by its own x: see docs/estimator.md#small-emitters).
    st.litPoint = o;
    st.lighting = true;
    st.misOrigin = o;
    st.misNormal = r.n;
    h.radiance[c] = pathRadiance(ctx, o, dir, st, deeper ? &use : nullptr, &h.distanceM[c]);
  }
  setRecordValue(r, h, frame);
  // The second level's records, shared by this record's cells and by other records, give
  // Var = Σ_j B_jᵀ C_j B_j; kept apart (sharedSd) because other records share them.
  r.sharedSd = deeper ? std::sqrt(use.tally.recordVariance(*deeper, kPi / static_cast<double>(cells), nullptr)) : 0.0;
}

IrradianceCache buildIrradianceCache(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                     const TraceSettings& settings, int threads,
                                     const Distribution& distribution, const std::function<void()>& checkpoint) {
  // Records [from, to) of a cache get their values, record i from its own stream, shared
  // between the processes (every later phase reads them).
  auto computeValues = [&](IrradianceCache& c, size_t from, size_t to,
                           const std::function<void(size_t, IrradianceRecord&)>& compute) {
    if (to > from)
      distributedFill(distribution, &c.record(from), to - from, ItemUse::kShared, threads,
                      [&](size_t k, IrradianceRecord& r) {
                        compute(from + k, r);
                        if (checkpoint) checkpoint();
                      });
  };
  auto visibility = [&tracer](const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r,
                              uint64_t& rays) { return cacheVisible(tracer, p, n, shape, r, rays); };
  IrradianceCache cache(tracer.scene().bounds(), settings.cache);
  cache.setVisibility(visibility);
  const BuildContext ctx{tracer, threads, distribution, checkpoint};
  // Phase A: first diffuse hits of each point's initial hemisphere cells.
  const QuerySource pointQueries{points.size(), [&](size_t i, std::vector<CacheQuery>& out) {
                                    cacheQueries(tracer, points[i].position, points[i].response(), i, settings, out);
                                  }};
  placeRecords(cache, ctx, pointQueries, kRadiusStream, settings);
  // Second level: phase A over the first level's record rays (the directions phase B will
  // trace), then its values, frozen before the first level's values use it. A record ray's
  // first hit is the second diffuse bounce: only when bounces go that far.
  const bool twoLevels = settings.cache.levels >= 2 && settings.maxBounces >= 2;
  std::optional<IrradianceCache> deeper;
  if (twoLevels) {
    TraceSettings s2 = settings;
    s2.cache = deeperLevel(settings.cache);
    deeper.emplace(tracer.scene().bounds(), s2.cache);
    deeper->setVisibility(visibility);
    const QuerySource recordRays{cache.size(), [&](size_t i, std::vector<CacheQuery>& out) {
                                   recordQueries(tracer, cache.record(i), kRecordStream + i, settings, out);
                                 }};
    placeRecords(*deeper, ctx, recordRays, kRadiusStream2, s2);
    computeValues(*deeper, 0, deeper->size(), [&](size_t i, IrradianceRecord& r) {
      computeRecord(tracer, r, kRecordStream2 + i, s2, nullptr, 2);
    });
  }
  // Phase B: the values, record i from stream i.
  const IrradianceCache* d = deeper ? &*deeper : nullptr;
  computeValues(cache, 0, cache.size(), [&](size_t i, IrradianceRecord& r) {
    computeRecord(tracer, r, kRecordStream + i, settings, d, 1);
  });
  // The radii limited by the gradients, and records where the smaller radii left gaps (phases A
  // and B again over the new records only), twice at most.
  size_t from = 0;
  for (int round = 0; round < 2; ++round) {
    bool shrunk = false;
    for (size_t i = from; i < cache.size(); ++i) shrunk |= limitRadiusByGradient(cache.record(i), settings.cache);
    if (!shrunk) break;
    const size_t before = cache.size();
    placeRecords(cache, ctx, pointQueries, kRadiusStream, settings);
    computeValues(cache, before, cache.size(), [&](size_t i, IrradianceRecord& r) {
      computeRecord(tracer, r, kRecordStream + i, settings, d, 1);
    });
    from = before;
  }
  return cache;
}

}  // namespace candela
