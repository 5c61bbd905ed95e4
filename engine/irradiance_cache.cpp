#include "engine/irradiance_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

Rgb hemisphereIrradiance(const HemisphereSamples& h) {
  Rgb sum(0.0);
  for (const Rgb& l : h.radiance) sum += l;
  return h.radiance.empty() ? Rgb(0.0) : kPi * sum / static_cast<double>(h.radiance.size());
}

std::vector<CellWeights> cellWeights(const HemisphereSamples& h) {
  const int m = h.m, n = h.n;
  std::vector<CellWeights> w(static_cast<size_t>(std::max(0, m * n)));
  if (m < 1 || n < 1) return w;
  auto idx = [n](int j, int k) { return j * n + k; };
  const double cellE = kPi / static_cast<double>(m * n);
  for (CellWeights& c : w) c.e = cellE;
  // Rotational gradient (Ward & Heckbert 1992): π/(MN) Σ L tan θ v(φ), tan θ and v the cell's
  // means, F(u) = ∫ tan θ du with u = sin² θ (derivation: docs/estimator.md#rotational-gradient).
  auto F = [](double u) { return std::asin(std::sqrt(u)) - std::sqrt(std::max(0.0, u * (1.0 - u))); };
  const double sinc = n > 1 ? std::sin(kPi / n) / (kPi / n) : 0.0;
  for (int j = 0; j < m; ++j) {
    const double meanTan = m * (F(static_cast<double>(j + 1) / m) - F(static_cast<double>(j) / m));
    for (int k = 0; k < n; ++k) {
      const double phi = kTwoPi * (k + 0.5) / n;
      w[idx(j, k)].rot = cellE * meanTan * sinc * Vec3(-std::sin(phi), std::cos(phi), 0.0);
    }
  }
  // Translational gradient of Ward & Heckbert 1992, as written by Křivánek et al. (2005): each
  // boundary term f (L_a − L_b) adds +f to cell a's weight and −f to cell b's (the formula:
  // docs/estimator.md#translational-gradient).
  if (n < 2) return w;
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
          const Vec3 f = kTwoPi / n * std::sqrt(s2) * (1.0 - s2) / r * u;
          w[idx(j, k)].trans += f;
          w[idx(j - 1, k)].trans -= f;
        }
      }
      const double r = std::min(h.distanceM[idx(j, k)], h.distanceM[idx(j, km)]);
      if (r > 0.0 && r < kInf) {
        const Vec3 f = (std::sqrt(static_cast<double>(j + 1) / m) - std::sqrt(static_cast<double>(j) / m)) / r * v;
        w[idx(j, k)].trans += f;
        w[idx(j, km)].trans -= f;
      }
    }
  }
  return w;
}

std::array<Vec3, 3> rotationalGradient(const HemisphereSamples& h) {
  std::array<Vec3, 3> g{};
  const std::vector<CellWeights> w = cellWeights(h);
  for (size_t c = 0; c < w.size(); ++c)
    for (int ch = 0; ch < 3; ++ch) g[ch] += h.radiance[c][ch] * w[c].rot;
  return g;
}

std::array<Vec3, 3> translationalGradient(const HemisphereSamples& h) {
  std::array<Vec3, 3> g{};
  const std::vector<CellWeights> w = cellWeights(h);
  for (size_t c = 0; c < w.size(); ++c)
    for (int ch = 0; ch < 3; ++ch) g[ch] += h.radiance[c][ch] * w[c].trans;
  return g;
}

void addOuter(std::array<double, 28>& c, const RecordVector& x, double s) {
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i <= j; ++i) c[j * (j + 1) / 2 + i] += s * x[i] * x[j];
}

double recordQuadratic(const IrradianceRecord& r, const RecordVector& b) {
  double q = 0.0;
  for (int j = 0; j < 7; ++j) {
    q += r.covariance[j * (j + 1) / 2 + j] * b[j] * b[j];
    for (int i = 0; i < j; ++i) q += 2.0 * r.covariance[j * (j + 1) / 2 + i] * b[i] * b[j];
  }
  return std::max(0.0, q);
}

RecordVector lookupVector(const IrradianceRecord& r, const Vec3& p, const Vec3& n, bool gradients) {
  RecordVector b{};
  b[0] = 1.0;
  if (gradients) {
    const Vec3 rot = glm::cross(r.n, n), dp = p - r.p;
    for (int i = 0; i < 3; ++i) {
      b[1 + i] = rot[i];
      b[4 + i] = dp[i];
    }
  }
  return b;
}

void setRecordValue(IrradianceRecord& r, const HemisphereSamples& h, const Frame& frame) {
  r.e = hemisphereIrradiance(h);
  const std::vector<CellWeights> w = cellWeights(h);
  std::array<Vec3, 3> gr{}, gt{};
  for (size_t c = 0; c < w.size(); ++c)
    for (int ch = 0; ch < 3; ++ch) {
      gr[ch] += h.radiance[c][ch] * w[c].rot;
      gt[ch] += h.radiance[c][ch] * w[c].trans;
    }
  for (int ch = 0; ch < 3; ++ch) {
    r.gradR[ch] = frame.toWorld(gr[ch]);
    r.gradT[ch] = frame.toWorld(gt[ch]);
  }
  // Covariance of Q = Σ_c λ_c y_c: Σ_c σ_c² λ_c λ_cᵀ, σ_c² estimated locally as stratifiedVariance
  // does globally (derivation: docs/estimator.md#record-covariance).
  const int m = h.m, n = h.n, cells = m * n;
  std::vector<double> y(cells), s2(cells, 0.0);
  for (int c = 0; c < cells; ++c) y[c] = photopic(h.radiance[c]);
  if (n >= 3) {
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < n; ++k) {
        const double d = y[j * n + (k + n - 1) % n] - 2.0 * y[j * n + k] + y[j * n + (k + 1) % n];
        s2[j * n + k] = d * d / 6.0;
      }
  } else {
    for (int c = 0; c + 1 < cells; c += 2) s2[c] = s2[c + 1] = 0.5 * (y[c] - y[c + 1]) * (y[c] - y[c + 1]);
  }
  r.covariance.fill(0.0);
  for (int c = 0; c < cells; ++c) {
    const Vec3 rot = frame.toWorld(w[c].rot), trans = frame.toWorld(w[c].trans);
    addOuter(r.covariance, {w[c].e, rot.x, rot.y, rot.z, trans.x, trans.y, trans.z}, s2[c]);
  }
  r.variancePhotopic = r.covariance[0];
}

void CacheTally::merge(const std::vector<int>* counts) {
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.cell < b.cell || (a.cell == b.cell && a.record < b.record);
  });
  size_t out = 0;
  for (size_t a = 0; a < entries_.size();) {
    Entry e = entries_[a];
    size_t b = a + 1;
    for (; b < entries_.size() && entries_[b].cell == e.cell && entries_[b].record == e.record; ++b)
      for (int q = 0; q < 7; ++q) e.beta[q] += entries_[b].beta[q];
    const double inv = counts ? 1.0 / (*counts)[e.cell] : 1.0;
    for (double& x : e.beta) x *= inv;
    entries_[out++] = e;
    a = b;
  }
  entries_.resize(out);
  merged_ = true;
}

void CacheTally::secondDifferenceVariance(const IrradianceCache& cache, size_t end, int m, int n,
                                          std::vector<double>& out) const {
  out.assign(static_cast<size_t>(m * n), 0.0);
  if (n < 3) return;
  std::vector<std::pair<uint32_t, size_t>>& keys = keys_;
  keys.clear();
  for (size_t e = 0; e < end; ++e) keys.emplace_back(entries_[e].record, e);
  std::sort(keys.begin(), keys.end());
  std::vector<std::pair<int, RecordVector>>& cellBeta = cellBeta_;
  for (size_t a = 0; a < keys.size();) {
    size_t b = a;
    cellBeta.clear();
    for (; b < keys.size() && keys[b].first == keys[a].first; ++b) cellBeta.emplace_back(entries_[keys[b].second].cell, entries_[keys[b].second].beta);
    std::sort(cellBeta.begin(), cellBeta.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    auto betaAt = [&](int cell) {
      RecordVector v{};
      auto it = std::lower_bound(cellBeta.begin(), cellBeta.end(), cell, [](const auto& x, int c) { return x.first < c; });
      for (; it != cellBeta.end() && it->first == cell; ++it)
        for (int k = 0; k < 7; ++k) v[k] += it->second[k];
      return v;
    };
    const IrradianceRecord& r = cache.record(keys[a].first);
    std::vector<int>& centres = centres_;
    centres.clear();
    for (const auto& [cell, beta] : cellBeta) {
      const int j = cell / n, k = cell % n;
      for (int dk = -1; dk <= 1; ++dk) centres.push_back(j * n + (k + dk + n) % n);
    }
    std::sort(centres.begin(), centres.end());
    centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
    for (int c : centres) {
      const int j = c / n, k = c % n;
      const RecordVector lo = betaAt(j * n + (k + n - 1) % n), mid = betaAt(c), hi = betaAt(j * n + (k + 1) % n);
      RecordVector d;
      for (int q = 0; q < 7; ++q) d[q] = lo[q] - 2.0 * mid[q] + hi[q];
      out[c] += recordQuadratic(r, d);
    }
    a = b;
  }
}

double CacheTally::spreadVariance(const IrradianceCache& cache, const std::vector<size_t>& marks) const {
  const size_t m = marks.size() - 1;
  if (m < 2) return 0.0;
  // β_qi per (record, sample), summed over a sample's lookups of the same record.
  std::vector<std::pair<uint32_t, size_t>>& keys = keys_;
  keys.clear();
  for (size_t q = 0; q < m; ++q)
    for (size_t e = marks[q]; e < marks[q + 1]; ++e) keys.emplace_back(entries_[e].record, e);
  std::sort(keys.begin(), keys.end());
  double s = 0.0;
  std::vector<RecordVector> perSample(m);
  for (size_t a = 0; a < keys.size();) {
    size_t b = a;
    for (RecordVector& v : perSample) v.fill(0.0);
    for (; b < keys.size() && keys[b].first == keys[a].first; ++b) {
      const size_t e = keys[b].second;
      const size_t q = static_cast<size_t>(std::upper_bound(marks.begin(), marks.end(), e) - marks.begin()) - 1;
      for (int k = 0; k < 7; ++k) perSample[q][k] += entries_[e].beta[k];
    }
    RecordVector mean{};
    for (const RecordVector& v : perSample)
      for (int k = 0; k < 7; ++k) mean[k] += v[k] / static_cast<double>(m);
    const IrradianceRecord& r = cache.record(keys[a].first);
    for (const RecordVector& v : perSample) {
      RecordVector d;
      for (int k = 0; k < 7; ++k) d[k] = v[k] - mean[k];
      s += recordQuadratic(r, d);
    }
    a = b;
  }
  return s;
}

double CacheTally::recordVariance(const IrradianceCache& cache, double scale, const std::vector<int>* counts) {
  if (!merged_) merge(counts);
  std::vector<std::pair<uint32_t, RecordVector>>& perRecord = perRecord_;
  perRecord.clear();
  for (const Entry& e : entries_) perRecord.emplace_back(e.record, e.beta);
  std::sort(perRecord.begin(), perRecord.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  double var = 0.0, sharedSd = 0.0;
  for (size_t a = 0; a < perRecord.size();) {
    RecordVector sum{};
    size_t b = a;
    for (; b < perRecord.size() && perRecord[b].first == perRecord[a].first; ++b)
      for (int q = 0; q < 7; ++q) sum[q] += scale * perRecord[b].second[q];
    const IrradianceRecord& r = cache.record(perRecord[a].first);
    var += recordQuadratic(r, sum);
    sharedSd += std::abs(sum[0]) * r.sharedSd;
    a = b;
  }
  return var + sharedSd * sharedSd;
}

CacheSettings deeperLevel(const CacheSettings& first) {
  CacheSettings s = first;
  s.recordSamples = std::max(64, first.recordSamples / 4);
  s.accuracy = 2.0 * first.accuracy;
  s.levels = 1;
  return s;
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
  const double valid = settings_.accuracy * r.radiusM;
  // Beyond the valid radius the weight is below 1/a whatever the normals (|d|/R alone exceeds a):
  // 0 without the two square roots. The margin keeps every weight above 1/a exactly as before.
  if (glm::dot(d, d) > valid * valid * (1.0 + 1e-9)) return 0.0;
  // A record in front of p (p lies behind the record's surface, e.g. a record on a box top and
  // p on the floor beside it) sees another situation: Ward et al. 1988's "in front" test.
  if (glm::dot(d, 0.5 * (n + r.n)) < -0.05 * valid) return 0.0;
  const double den = glm::length(d) / r.radiusM + std::sqrt(std::max(0.0, 1.0 - nn));
  return den > 1e-12 ? 1.0 / den : 1e12;
}

uint32_t IrradianceCache::add(const IrradianceRecord& rec, std::vector<uint32_t>* shrunk) {
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
    const double before = o.radiusM;
    o.radiusM = std::max(minR, std::min(o.radiusM, r.radiusM + d));
    if (shrunk && o.radiusM != before) shrunk->push_back(i);
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

int64_t IrradianceCache::firstCovering(const Vec3& p, const Vec3& n, uint32_t shape, uint64_t* rays) const {
  const double k = 1.0 / settings_.accuracy;
  int64_t first = -1;
  visitUntil(p, 0.0, [&](uint32_t i) {
    if (!(weight(records_[i], p, n) > k && usable(records_[i], p, n, shape, rays))) return false;
    first = i;
    return true;
  });
  return first;
}

bool IrradianceCache::interpolate(const Vec3& p, const Vec3& n, Rgb& out, Used* used, uint32_t shape,
                                  uint64_t* rays) const {
  const double k = 1.0 / settings_.accuracy;
  // Gathered in the octree's fixed order, so sums are reproducible.
  std::vector<std::pair<double, uint32_t>> local;
  std::vector<std::pair<double, uint32_t>>& found = used ? used->found : local;
  found.clear();
  visit(p, 0.0, [&](uint32_t i) {
    const double w = weight(records_[i], p, n);
    if (w > k && usable(records_[i], p, n, shape, rays)) found.emplace_back(w, i);
  });
  if (found.empty()) return false;
  Rgb sum(0.0);
  double sumW = 0.0;
  for (const auto& [w, i] : found) {
    const IrradianceRecord& r = records_[i];
    Rgb e = r.e;
    if (settings_.gradients) {
      const Vec3 rot = glm::cross(r.n, n), dp = p - r.p;
      for (int c = 0; c < 3; ++c) e[c] = std::max(0.0, e[c] + glm::dot(rot, r.gradR[c]) + glm::dot(dp, r.gradT[c]));
    }
    sum += w * e;
    sumW += w;
  }
  out = sum / sumW;
  if (used) {
    for (const auto& [w, i] : found) used->weights.emplace_back(i, w / sumW);
  }
  return true;
}

}  // namespace candela
