// Ward's irradiance cache (Ward, Rubinstein & Clear 1988, "A ray tracing solution for diffuse
// interreflection"): indirect irradiance computed at a few surface points and interpolated
// elsewhere, with the translational and rotational gradients of Ward & Heckbert 1992
// ("Irradiance gradients") and the neighbour clamping of Křivánek et al. 2006 ("Making
// radiance and irradiance caching practical").
//
// How candela uses it (docs/accuracy.md): the cache holds the indirect irradiance at the first
// diffuse surfaces that sensor hemisphere rays meet. It is filled before any point is evaluated,
// in a fixed order (phase A, sequential: which records exist and their radii; phase B, parallel:
// their values, each from its own random stream), then frozen; the points are then evaluated in
// parallel against the frozen cache (engine/cache_builder.h). Results are therefore identical
// for any thread count.
// With two levels (CacheSettings::levels), a second cache serves the first diffuse hits of the
// first level's record rays, with fewer samples and a looser a (Ward et al. 1988: deeper values
// matter less, their contribution being attenuated by reflectance); it is filled the same way
// and frozen before the first level's values are computed.
#pragma once

#include "base/math.h"
#include "base/units.h"
#include "engine/trace_settings.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace candela {

class IrradianceCache;

// One cached value: indirect irradiance (W/m², RGB) at point p on a surface of unit normal n.
struct IrradianceRecord {
  Vec3 p{0.0};
  Vec3 n{0.0, 0.0, 1.0};
  double radiusM = 0.0;         // R_i: harmonic mean distance to the surfaces seen, clamped (m)
  Rgb e{0.0};                   // indirect irradiance, W/m²
  std::array<Vec3, 3> gradT{};  // translational gradient per channel, W/m² per m (Ward & Heckbert)
  std::array<Vec3, 3> gradR{};  // rotational gradient per channel, W/m² per rad
  double variancePhotopic = 0.0;  // variance of photopic(e) from the record's own samples
  // Covariance of the photopic (E, G_r, G_t) (see recordQuadratic), for error bars.
  std::array<double, 28> covariance{};
  // Standard deviation of photopic(e) due to the second level's records (two-level cache),
  // which many first-level records share: not in `covariance`, added fully correlated.
  double sharedSd = 0.0;
  uint32_t skip = 0xffffffffu;  // flat shape the record lies on (excluded from its rays)
  uint32_t shape = 0xffffffffu; // shape the record lies on
};

// A surface point where a sensor ray's first diffuse reflection needs indirect irradiance: the
// hit p, the unit normal n on the side the ray arrived from, the flat shape to skip (or ~0u).
struct CacheQuery {
  Vec3 p{0.0};
  Vec3 n{0.0, 0.0, 1.0};
  uint32_t skip = 0xffffffffu;   // flat shape hit (its rays skip it), or ~0u
  uint32_t shape = 0xffffffffu;  // the shape hit
};

// Hemisphere samples of one record in the paper's M × N stratification (θ_j = asin√((j+X)/M),
// φ_k = 2π(k+Y)/N): cell (j, k) is at index j·N + k.
struct HemisphereSamples {
  int m = 0, n = 0;
  std::vector<Rgb> radiance;     // L_jk, W/sr/m²
  std::vector<double> distanceM; // distance to the first hit (infinity when the ray escapes)
  std::vector<Vec3> local;       // sampled direction in the record's frame (z = normal)
};

// E ≈ π/(MN) Σ L_jk (the paper's eq. 3).
Rgb hemisphereIrradiance(const HemisphereSamples& h);
// Rotational gradient G_r = ∫ L (n × ω) dω ≈ π/(MN) Σ L_jk tan θ_jk v(φ_jk), v = n × u(φ), such
// that E(n') ≈ E(n) + (n × n')·G_r; returned in the frame's local coordinates per channel.
std::array<Vec3, 3> rotationalGradient(const HemisphereSamples& h);
// Translational gradient of Ward & Heckbert 1992 (in the form of Křivánek et al., "Radiance
// caching", eq. for ∇_t): the motion of the cell boundaries projected on the surfaces seen, at
// distances min(r) of the two cells sharing a boundary; local coordinates per channel.
std::array<Vec3, 3> translationalGradient(const HemisphereSamples& h);

// A record's interpolated photopic value at (p, n) is Q·β: Q = (E, G_r, G_t) photopic (seven
// numbers, world coordinates), β = (1, n_i × n, p − p_i) (the gradient terms 0 without gradients).
using RecordVector = std::array<double, 7>;
RecordVector lookupVector(const IrradianceRecord& r, const Vec3& p, const Vec3& n, bool gradients);

// IrradianceRecord::covariance is the symmetric 7 × 7 covariance C of Q, packed (element i ≤ j
// at j(j+1)/2 + i). addOuter: C += s x xᵀ; recordQuadratic: bᵀ C b = Var(Q·b).
void addOuter(std::array<double, 28>& c, const RecordVector& x, double s);
double recordQuadratic(const IrradianceRecord& r, const RecordVector& b);

// Per-cell weights λ_c of Q in the record's local frame: E = Σ λ_c.e L_c, G_r = Σ λ_c.rot L_c,
// G_t = Σ λ_c.trans L_c (the gradients below are these sums; the variance of Q follows from them).
struct CellWeights {
  double e = 0.0;
  Vec3 rot{0.0}, trans{0.0};
};
std::vector<CellWeights> cellWeights(const HemisphereSamples& h);
// Sets r.e, its gradients (world coordinates, `frame` = the record's), its covariance and
// variancePhotopic from its hemisphere samples.
void setRecordValue(IrradianceRecord& r, const HemisphereSamples& h, const Frame& frame);

// How much each record's noise enters a stratified estimate E = scale · Σ_c ȳ_c (ȳ_c the mean of
// cell c's samples), for error bars. Record i's share of a sample's photopic value is
// Q_i·β (β summed over the sample's lookups, times the path's weight and ρ/π).
class CacheTally {
 public:
  void clear() {
    entries_.clear();
    cached_.clear();
    merged_ = false;
  }
  void setCell(int cell) { cell_ = cell; }
  void add(uint32_t record, const RecordVector& beta) { entries_.push_back({cell_, record, beta}); }
  // The photopic radiance the current cell's samples took from the records (interpolated
  // irradiance times the path's weight and ρ/π), summed per cell; cachedValue(c): 0 if none.
  // Adaptive super-sampling chooses its strata without it (engine/irradiance_estimator.cpp).
  void addCachedValue(double photopicRadiance) {
    if (cell_ >= static_cast<int>(cached_.size())) cached_.resize(cell_ + 1, 0.0);
    cached_[cell_] += photopicRadiance;
  }
  double cachedValue(int cell) const { return cell < static_cast<int>(cached_.size()) ? cached_[cell] : 0.0; }
  bool empty() const { return entries_.empty(); }
  // Entries so far (before recordVariance merges them): marks where a sample's lookups begin.
  size_t mark() const { return entries_.size(); }
  // The records' expected share of S = Σ_q (x_q − x̄)² over m samples (sample q's entries from
  // marks[q] to marks[q + 1], x_q the photopic radiance it took from the records):
  // E[S_rec] = Σ_i Σ_q (β_qi − β̄_i)ᵀ C_i (β_qi − β̄_i), the records independent.
  // The records' expected share of each cell's squared second difference along φ over the
  // entries before `end` (cells j·n + k, φ wrapping): out[c] = Σ_i d_ciᵀ C_i d_ci with
  // d_ci = β_c−1,i − 2β_ci + β_c+1,i (n ≥ 3).
  void secondDifferenceVariance(const IrradianceCache& cache, size_t end, int m, int n,
                                std::vector<double>& out) const;
  double spreadVariance(const IrradianceCache& cache, const std::vector<size_t>& marks) const;
  // Var(E) from the records (independent: their own random streams), Σ_i B_iᵀ C_i B_i with
  // B_i = scale Σ_c β̄_ci; counts: samples per cell (nullptr: one each). Records sharing
  // second-level records add (Σ_i |B_i,E| σ_shared,i)²: an upper bound (full correlation).
  double recordVariance(const IrradianceCache& cache, double scale, const std::vector<int>* counts);

 private:
  struct Entry {
    int cell;
    uint32_t record;
    RecordVector beta;
  };
  void merge(const std::vector<int>* counts);  // sorts, sums per (cell, record), divides by counts
  int cell_ = 0;
  bool merged_ = false;
  std::vector<Entry> entries_;
  std::vector<double> cached_;
  // Scratch of the variance sums, reused from call to call.
  mutable std::vector<std::pair<uint32_t, size_t>> keys_;        // (record, entry index)
  mutable std::vector<std::pair<int, RecordVector>> cellBeta_;   // (cell, β summed)
  mutable std::vector<int> centres_;
  std::vector<std::pair<uint32_t, RecordVector>> perRecord_;
};


// The second level's settings (Ward et al. 1988): a quarter of the record samples (at least 64)
// and twice the error a.
CacheSettings deeperLevel(const CacheSettings& first);

class IrradianceCache {
 public:
  // `bounds`: the scene's box (the octree root); records outside it are still stored.
  IrradianceCache(const Box& bounds, const CacheSettings& settings);

  // Adds a record whose value is still to be computed; applies min/max spacing and neighbour
  // clamping (R_i ≤ R_j + |P_i − P_j| both ways; radii only ever shrink). Returns its index; the
  // records whose radius the clamping shrank are appended to *shrunk when given.
  uint32_t add(const IrradianceRecord& r, std::vector<uint32_t>* shrunk = nullptr);
  // visible(p, n, shape, record, rays): nothing but p's and the record's own shapes between them;
  // the rays it casts are added to `rays`.
  using Visibility = std::function<bool(const Vec3&, const Vec3&, uint32_t, const IrradianceRecord&, uint64_t&)>;
  void setVisibility(Visibility v) { visible_ = std::move(v); }

  // True when some record has w_i(p, n) > 1/a (and is visible from p when checked). `shape`:
  // the shape p lies on; the visibility rays cast are added to *rays when given.
  bool covers(const Vec3& p, const Vec3& n, uint32_t shape = 0xffffffffu, uint64_t* rays = nullptr) const {
    return firstCovering(p, n, shape, rays) >= 0;
  }
  // The first record in the octree's order that covers (p, n), or -1.
  int64_t firstCovering(const Vec3& p, const Vec3& n, uint32_t shape = 0xffffffffu, uint64_t* rays = nullptr) const;
  // What an interpolation used, for error bars: each record with its normalised weight; and
  // the records found, scratch reused from call to call.
  struct Used {
    std::vector<std::pair<uint32_t, double>> weights;
    std::vector<std::pair<double, uint32_t>> found;
  };
  // Gradient-corrected weighted mean (W/m²) of the records with w_i > 1/a; false when none.
  // Appends to *used when given; visibility rays as for covers.
  bool interpolate(const Vec3& p, const Vec3& n, Rgb& out, Used* used = nullptr,
                   uint32_t shape = 0xffffffffu, uint64_t* rays = nullptr) const;

  size_t size() const { return records_.size(); }
  IrradianceRecord& record(size_t i) { return records_[i]; }
  const IrradianceRecord& record(size_t i) const { return records_[i]; }
  const CacheSettings& settings() const { return settings_; }

  // Ward's weight 1/(|p − p_i|/R_i + √(1 − n·n_i)); 0 when the record faces away, lies in
  // front of p (p behind the record's surface) or beyond its valid radius a·R_i (where the weight
  // is below 1/a and no lookup takes it).
  double weight(const IrradianceRecord& r, const Vec3& p, const Vec3& n) const;

 private:
  struct Node {
    Vec3 centre;
    double half;
    std::vector<uint32_t> records;
    std::array<int32_t, 8> child;
  };
  // Calls fn(record index) for every record whose valid sphere (radius a·R_i) may reach p, or
  // whose centre lies within `extraM` of p. A template, not a std::function: every lookup of a
  // run passes here (a tenth of the office demo's time), and the calls inline.
  template <class Fn>
  void visit(const Vec3& p, double extraM, Fn&& fn) const {
    visitUntil(p, extraM, [&fn](uint32_t i) {
      fn(i);
      return false;
    });
  }
  // The same records in the same order until fn returns true (then true): covers stops at the
  // first record that serves.
  template <class Fn>
  bool visitUntil(const Vec3& p, double extraM, Fn&& fn) const {
    return visitNode(0, p, extraM, fn);
  }
  template <class Fn>
  bool visitNode(int32_t node, const Vec3& p, double extraM, Fn& fn) const {
    const Node& nd = nodes_[static_cast<size_t>(node)];
    // Records stored here have their centres in this cube and valid radii ≤ half.
    if (node != 0) {
      const Vec3 d = glm::abs(p - nd.centre);
      const double reach = 2.0 * nd.half + extraM;
      if (d.x > reach || d.y > reach || d.z > reach) return false;
    }
    for (uint32_t r : nd.records)
      if (fn(r)) return true;
    for (int32_t c : nd.child)
      if (c >= 0 && visitNode(c, p, extraM, fn)) return true;
    return false;
  }

  bool usable(const IrradianceRecord& r, const Vec3& p, const Vec3& n, uint32_t shape, uint64_t* rays) const {
    uint64_t uncounted = 0;
    return !visible_ || !settings_.visibilityCheck || visible_(p, n, shape, r, rays ? *rays : uncounted);
  }

  CacheSettings settings_;
  Visibility visible_;
  std::vector<IrradianceRecord> records_;
  std::vector<Node> nodes_;
};

}  // namespace candela
