#include "engine/irradiance_cache.h"

#include "engine/base/rng.h"
#include "engine/parallel.h"
#include "engine/sensor_grid.h"
#include "engine/tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Random streams of phase A (record radii) and phase B (record values), apart from the points'.
constexpr uint64_t kRadiusStream = 0x5000000000000000ULL;
constexpr uint64_t kRecordStream = 0x6000000000000000ULL;

}  // namespace

Rgb hemisphereIrradiance(const HemisphereSamples& h) {
  Rgb sum(0.0);
  for (const Rgb& l : h.radiance) sum += l;
  return h.radiance.empty() ? Rgb(0.0) : kPi * sum / static_cast<double>(h.radiance.size());
}

std::array<Vec3, 3> rotationalGradient(const HemisphereSamples& h) {
  // Cosine-weighted samples estimate ∫ f cos θ dω by π/(MN) Σ f; here f = L tan θ v(φ), so the
  // sum estimates ∫ L sin θ v dω = ∫ L (n × ω) dω. Rotating n by δ (n' = n + δ × n) changes
  // E = ∫ L max(0, n·ω) dω by δ·∫ L (n × ω) dω = (n × n')·G_r (the horizon term vanishes with
  // cos θ). As Ward & Heckbert, tan θ and v are functions of the cell, not of the jittered
  // sample, so that a uniform L gives exactly 0 (tan θ at the sample near the horizon is
  // noisy); here their means over the cell: with u = sin² θ, ∫ tan θ du = F(u) =
  // asin √u − √(u(1 − u)), and the mean of v over [φ_k, φ_k+1] is v(φ_centre) sin(π/N)/(π/N).
  // (Tan θ at the centre would miss 7 % of the gradient at M = 40: tan θ is singular at the horizon.)
  std::array<Vec3, 3> g{};
  const int m = h.m, n = h.n;
  if (m < 1 || n < 1) return g;
  auto F = [](double u) { return std::asin(std::sqrt(u)) - std::sqrt(std::max(0.0, u * (1.0 - u))); };
  std::vector<double> meanTan(m);
  for (int j = 0; j < m; ++j) meanTan[j] = m * (F(static_cast<double>(j + 1) / m) - F(static_cast<double>(j) / m));
  const double sinc = n > 1 ? std::sin(kPi / n) / (kPi / n) : 0.0;
  for (int k = 0; k < n; ++k) {
    const double phi = kTwoPi * (k + 0.5) / n;
    const Vec3 v = sinc * Vec3(-std::sin(phi), std::cos(phi), 0.0);
    Rgb row(0.0);
    for (int j = 0; j < m; ++j) row += h.radiance[j * n + k] * meanTan[j];
    for (int c = 0; c < 3; ++c) g[c] += row[c] * v;
  }
  for (int c = 0; c < 3; ++c) g[c] *= kPi / static_cast<double>(m * n);
  return g;
}

std::array<Vec3, 3> translationalGradient(const HemisphereSamples& h) {
  // Ward & Heckbert 1992, as written by Křivánek et al. (2005): moving the point moves the
  // boundaries between cells over the surfaces seen; each boundary contributes the radiance
  // difference across it times its projected motion, at the nearer of the two distances.
  //   ∇E = Σ_k [ u_k (2π/N) Σ_{j≥1} sin θ_j− cos² θ_j− (L_jk − L_j−1,k) / min(r_jk, r_j−1,k)
  //            + v_k− Σ_j (sin θ_j+ − sin θ_j−) (L_jk − L_j,k−1) / min(r_jk, r_j,k−1) ]
  // with sin² θ_j− = j/M, sin² θ_j+ = (j+1)/M, u_k at φ = 2π(k + ½)/N, v_k− at 2πk/N + π/2.
  std::array<Vec3, 3> g{};
  const int m = h.m, n = h.n;
  if (m < 1 || n < 2) return g;
  auto idx = [n](int j, int k) { return j * n + k; };
  for (int k = 0; k < n; ++k) {
    const double phiC = kTwoPi * (k + 0.5) / n, phiB = kTwoPi * k / n;
    const Vec3 u(std::cos(phiC), std::sin(phiC), 0.0);
    const Vec3 v(-std::sin(phiB), std::cos(phiB), 0.0);
    const int km = (k + n - 1) % n;
    for (int j = 0; j < m; ++j) {
      if (j > 0) {
        const double s2 = static_cast<double>(j) / m;
        const double r = std::min(h.distanceM[idx(j, k)], h.distanceM[idx(j - 1, k)]);
        if (r > 0.0 && r < kInf) {
          const double f = kTwoPi / n * std::sqrt(s2) * (1.0 - s2) / r;
          for (int c = 0; c < 3; ++c) g[c] += f * (h.radiance[idx(j, k)][c] - h.radiance[idx(j - 1, k)][c]) * u;
        }
      }
      const double r = std::min(h.distanceM[idx(j, k)], h.distanceM[idx(j, km)]);
      if (r > 0.0 && r < kInf) {
        const double f = (std::sqrt(static_cast<double>(j + 1) / m) - std::sqrt(static_cast<double>(j) / m)) / r;
        for (int c = 0; c < 3; ++c) g[c] += f * (h.radiance[idx(j, k)][c] - h.radiance[idx(j, km)][c]) * v;
      }
    }
  }
  return g;
}

IrradianceCache::IrradianceCache(const Box& bounds, const CacheSettings& settings) : settings_(settings) {
  Node root;
  if (bounds.empty()) {
    root.centre = Vec3(0.0);
    root.half = 1.0;
  } else {
    root.centre = bounds.center();
    const Vec3 sz = bounds.size();
    root.half = 0.5 * std::max({sz.x, sz.y, sz.z, 1e-3}) * 1.001;
  }
  root.child.fill(-1);
  nodes_.push_back(root);
}

double IrradianceCache::weight(const IrradianceRecord& r, const Vec3& p, const Vec3& n) const {
  const double nn = glm::dot(n, r.n);
  if (nn <= 0.0) return 0.0;
  const Vec3 d = p - r.p;
  // A record in front of p (p lies behind the record's surface, e.g. a record on a box top and
  // p on the floor beside it) sees another situation: Ward et al. 1988's "in front" test.
  const double valid = settings_.accuracy * r.radiusM;
  if (glm::dot(d, 0.5 * (n + r.n)) < -0.05 * valid) return 0.0;
  const double den = glm::length(d) / r.radiusM + std::sqrt(std::max(0.0, 1.0 - nn));
  return den > 1e-12 ? 1.0 / den : 1e12;
}

void IrradianceCache::visitNode(int32_t node, const Vec3& p, double extraM,
                                const std::function<void(uint32_t)>& fn) const {
  const Node& nd = nodes_[node];
  // Records stored here have their centres in this cube and valid radii ≤ half.
  if (node != 0) {
    const Vec3 d = glm::abs(p - nd.centre);
    const double reach = 2.0 * nd.half + extraM;
    if (d.x > reach || d.y > reach || d.z > reach) return;
  }
  for (uint32_t r : nd.records) fn(r);
  for (int32_t c : nd.child)
    if (c >= 0) visitNode(c, p, extraM, fn);
}

void IrradianceCache::visit(const Vec3& p, double extraM, const std::function<void(uint32_t)>& fn) const {
  visitNode(0, p, extraM, fn);
}

uint32_t IrradianceCache::add(const IrradianceRecord& rec) {
  IrradianceRecord r = rec;
  const double a = settings_.accuracy;
  // Minimum and maximum spacing bound the valid radius a·R_i.
  r.radiusM = std::clamp(a * r.radiusM, settings_.minSpacingM, settings_.maxSpacingM) / a;
  // Neighbour clamping (Křivánek et al. 2006): R is a distance to the geometry, so it cannot
  // change faster than the distance between two records: R_j ≤ R_i + d and R_i ≤ R_j + d.
  const double minR = settings_.minSpacingM / a;
  visit(r.p, r.radiusM, [&](uint32_t i) {
    IrradianceRecord& o = records_[i];
    if (glm::dot(o.n, r.n) <= 0.0) return;
    const double d = glm::length(o.p - r.p);
    r.radiusM = std::max(minR, std::min(r.radiusM, o.radiusM + d));
    o.radiusM = std::max(minR, std::min(o.radiusM, r.radiusM + d));
  });
  const uint32_t id = static_cast<uint32_t>(records_.size());
  records_.push_back(r);
  // The deepest node containing p whose half-size still holds the valid radius.
  const double valid = a * r.radiusM;
  int32_t node = 0;
  for (int depth = 0; depth < 48; ++depth) {
    const Node& nd = nodes_[node];
    const double childHalf = 0.5 * nd.half;
    if (childHalf < valid) break;
    const Vec3 d = r.p - nd.centre;
    if (std::abs(d.x) > nd.half || std::abs(d.y) > nd.half || std::abs(d.z) > nd.half) break;
    const int octant = (d.x > 0.0 ? 1 : 0) | (d.y > 0.0 ? 2 : 0) | (d.z > 0.0 ? 4 : 0);
    if (nd.child[octant] < 0) {
      Node c;
      c.half = childHalf;
      c.centre = nd.centre + childHalf * Vec3(octant & 1 ? 1 : -1, octant & 2 ? 1 : -1, octant & 4 ? 1 : -1);
      c.child.fill(-1);
      nodes_.push_back(c);
      nodes_[node].child[octant] = static_cast<int32_t>(nodes_.size() - 1);
    }
    node = nodes_[node].child[octant];
  }
  nodes_[node].records.push_back(id);
  return id;
}

bool IrradianceCache::covers(const Vec3& p, const Vec3& n, uint32_t shape) const {
  const double k = 1.0 / settings_.accuracy;
  bool found = false;
  visit(p, 0.0, [&](uint32_t i) {
    if (!found && weight(records_[i], p, n) > k && usable(records_[i], p, n, shape)) found = true;
  });
  return found;
}

bool IrradianceCache::interpolate(const Vec3& p, const Vec3& n, Rgb& out, Used* used, uint32_t shape) const {
  const double k = 1.0 / settings_.accuracy;
  // Gathered in the octree's fixed order, so sums are reproducible.
  thread_local std::vector<std::pair<double, uint32_t>> found;
  found.clear();
  visit(p, 0.0, [&](uint32_t i) {
    const double w = weight(records_[i], p, n);
    if (w > k && usable(records_[i], p, n, shape)) found.emplace_back(w, i);
  });
  if (found.empty()) return false;
  Rgb sum(0.0);
  double sumW = 0.0, extrap = 0.0;
  for (const auto& [w, i] : found) {
    const IrradianceRecord& r = records_[i];
    Rgb e = r.e;
    if (settings_.gradients) {
      const Vec3 rot = glm::cross(r.n, n), dp = p - r.p;
      for (int c = 0; c < 3; ++c) e[c] = std::max(0.0, e[c] + glm::dot(rot, r.gradR[c]) + glm::dot(dp, r.gradT[c]));
    }
    sum += w * e;
    sumW += w;
    const double dy = photopic(e) - photopic(r.e);
    extrap += w * 0.25 * dy * dy;
  }
  out = sum / sumW;
  if (used) {
    for (const auto& [w, i] : found) used->weights.emplace_back(i, w / sumW);
    used->extrapolationVariance = extrap / sumW;
  }
  return true;
}

IrradianceCache buildIrradianceCache(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                     const TraceSettings& settings, int threads) {
  IrradianceCache cache(tracer.scene().bounds(), settings.cache);
  cache.setVisibility([&tracer](const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r) {
    return tracer.cacheVisible(p, n, shape, r);
  });
  // Phase A: first diffuse hits of each point's initial hemisphere cells, gathered in parallel in
  // batches, then walked in order on one thread: an uncovered hit becomes a record.
  constexpr size_t kBatch = 64;
  std::vector<std::vector<CacheQuery>> hits;
  for (size_t b = 0; b < points.size(); b += kBatch) {
    const size_t e = std::min(points.size(), b + kBatch);
    hits.assign(e - b, {});
    parallelFor(e - b, threads, [&](size_t i) {
      tracer.cacheQueries(points[b + i].position, points[b + i].normal, b + i, settings, hits[i]);
    });
    for (const auto& list : hits) {
      for (const CacheQuery& q : list) {
        if (cache.covers(q.p, q.n, q.shape)) continue;
        IrradianceRecord r;
        r.p = q.p;
        r.n = q.n;
        r.skip = q.skip;
        r.shape = q.shape;
        Rng rng(settings.seed, kRadiusStream + cache.size());
        r.radiusM = tracer.harmonicMeanDistance(q, settings.cache.radiusSamples, rng);
        cache.add(r);
      }
    }
  }
  // Phase B: the values, record i from stream i.
  parallelFor(cache.size(), threads, [&](size_t i) {
    tracer.computeRecord(cache.record(i), kRecordStream + i, settings);
  });
  return cache;
}

}  // namespace candela
