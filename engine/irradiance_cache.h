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
// parallel against the frozen cache. Results are therefore identical for any thread count.
#pragma once

#include "engine/base/math.h"
#include "engine/base/units.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace candela {

struct SensorPoint;
struct TraceSettings;
class Tracer;

// One cached value: indirect irradiance (W/m², RGB) at point p on a surface of unit normal n.
struct IrradianceRecord {
  Vec3 p{0.0};
  Vec3 n{0.0, 0.0, 1.0};
  double radiusM = 0.0;         // R_i: harmonic mean distance to the surfaces seen, clamped (m)
  Rgb e{0.0};                   // indirect irradiance, W/m²
  std::array<Vec3, 3> gradT{};  // translational gradient per channel, W/m² per m (Ward & Heckbert)
  std::array<Vec3, 3> gradR{};  // rotational gradient per channel, W/m² per rad
  double variancePhotopic = 0.0;  // variance of photopic(e) from the record's own samples
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

struct CacheSettings {
  double accuracy = 0.1;       // Ward's a: records are used where w_i > 1/a
  int recordSamples = 1024;    // hemisphere rays per record
  int radiusSamples = 128;     // rays per record for its harmonic mean distance (phase A)
  int lightSamples = 4;        // light samples at a sensor ray's hit (direct light there is not cached)
  double minSpacingM = 0.005;  // bounds on a record's valid radius a·R_i (m)
  double maxSpacingM = 1.0;
  bool gradients = true;
  // Use a record only where a ray joins it to the point without meeting a third surface: a thin
  // wall between a lit and a dark room then stops light leaking along the floor (costs one
  // shadow ray per candidate record).
  bool visibilityCheck = true;
};

class IrradianceCache {
 public:
  // `bounds`: the scene's box (the octree root); records outside it are still stored.
  IrradianceCache(const Box& bounds, const CacheSettings& settings);

  // Adds a record whose value is still to be computed; applies min/max spacing and neighbour
  // clamping (R_i ≤ R_j + |P_i − P_j| both ways). Returns its index.
  uint32_t add(const IrradianceRecord& r);
  // visible(p, n, shape, record): nothing but p's and the record's own shapes between them.
  using Visibility = std::function<bool(const Vec3&, const Vec3&, uint32_t, const IrradianceRecord&)>;
  void setVisibility(Visibility v) { visible_ = std::move(v); }

  // True when some record has w_i(p, n) > 1/a (and is visible from p when checked). `shape`:
  // the shape p lies on.
  bool covers(const Vec3& p, const Vec3& n, uint32_t shape = 0xffffffffu) const;
  // What an interpolation used, for error bars: each record with its normalised weight, and an
  // interpolation share: a quarter of the squared gradient correction (photopic, (W/m²)²),
  // i.e. how far the records had to be extrapolated.
  struct Used {
    std::vector<std::pair<uint32_t, double>> weights;
    double extrapolationVariance = 0.0;
  };
  // Gradient-corrected weighted mean (W/m²) of the records with w_i > 1/a; false when none.
  // Appends to *used when given.
  bool interpolate(const Vec3& p, const Vec3& n, Rgb& out, Used* used = nullptr,
                   uint32_t shape = 0xffffffffu) const;

  size_t size() const { return records_.size(); }
  IrradianceRecord& record(size_t i) { return records_[i]; }
  const IrradianceRecord& record(size_t i) const { return records_[i]; }
  const CacheSettings& settings() const { return settings_; }

  // Ward's weight 1/(|p − p_i|/R_i + √(1 − n·n_i)); 0 when the record faces away or lies in
  // front of p (p behind the record's surface).
  double weight(const IrradianceRecord& r, const Vec3& p, const Vec3& n) const;

 private:
  struct Node {
    Vec3 centre;
    double half;
    std::vector<uint32_t> records;
    std::array<int32_t, 8> child;
  };
  // Calls fn(record index) for every record whose valid sphere (radius a·R_i) may reach p, or
  // whose centre lies within `extraM` of p.
  void visit(const Vec3& p, double extraM, const std::function<void(uint32_t)>& fn) const;
  void visitNode(int32_t node, const Vec3& p, double extraM, const std::function<void(uint32_t)>& fn) const;

  bool usable(const IrradianceRecord& r, const Vec3& p, const Vec3& n, uint32_t shape) const {
    return !visible_ || !settings_.visibilityCheck || visible_(p, n, shape, r);
  }

  CacheSettings settings_;
  Visibility visible_;
  std::vector<IrradianceRecord> records_;
  std::vector<Node> nodes_;
};

// Phases A and B: the records the points' first diffuse hits need, with their values.
// Deterministic: phase A walks the points and their hemisphere cells in order on one thread;
// phase B computes record i from random stream i on `threads` threads.
IrradianceCache buildIrradianceCache(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                     const TraceSettings& settings, int threads);

}  // namespace candela
