// What a sensor measures: its response w(ω) to light arriving from direction ω (unit, towards
// the source), so that the quantity is E = ∫ L(ω) w(ω) dω. Planar illuminance on a surface of
// normal n has w = max(0, n·ω); the illuminance quantities of EN 12464-1:2021 (cylindrical,
// semi-cylindrical, hemispherical; CIE S 017:2020 17-21-057..060) are the others. The
// estimator (engine/irradiance_estimator.h) evaluates the direct light with w exactly and draws
// the hemisphere (or sphere) rays with the density w/W, W = ∫ w dω, so each quantity is a
// stratified importance-sampled integral like the planar one (derivations: docs/quantities.md).
#pragma once

#include "base/math.h"

#include <cmath>
#include <cstdint>

namespace candela {

enum class Quantity : uint8_t {
  kPlanar,           // max(0, n·ω): horizontal, vertical or any plane
  kCylindrical,      // sin θ / π: θ from the axis; light from above and below counts
  kSemiCylindrical,  // sin θ (1 + cos α) / π: α in plan between the facing and ω
  kHemispherical,    // (1 + cos θ) / 4 for θ ≤ 90°, 0 below the horizon
};

// Solves x − sin x = m for x in [0, 2π], m in [0, 2π] (Kepler's equation with eccentricity 1):
// the inverse of the cumulative distributions of the cylindrical family's warps. Safeguarded
// Newton; |error| below 1e-13.
double solveXMinusSin(double m);

struct Response {
  Quantity kind = Quantity::kPlanar;
  Vec3 n{0.0, 0.0, 1.0};       // planar: the unit normal; the others: the unit vertical axis
  Vec3 facing{1.0, 0.0, 0.0};  // semi-cylindrical: unit, perpendicular to n

  static Response planar(const Vec3& normal) { return {Quantity::kPlanar, normal, Vec3(1.0, 0.0, 0.0)}; }

  bool isPlanar() const { return kind == Quantity::kPlanar; }

  // w(d) for unit d.
  double weight(const Vec3& d) const {
    const double c = glm::dot(n, d);
    switch (kind) {
      case Quantity::kPlanar: return c > 0.0 ? c : 0.0;
      case Quantity::kCylindrical: return std::sqrt(std::max(0.0, 1.0 - c * c)) * kInvPi;
      case Quantity::kSemiCylindrical:
        // sin θ (1 + cos α) = |d_h| + d_h·f with d_h the horizontal part of d and f ⊥ n.
        return (std::sqrt(std::max(0.0, 1.0 - c * c)) + glm::dot(facing, d)) * kInvPi;
      case Quantity::kHemispherical: return c >= 0.0 ? 0.25 * (1.0 + c) : 0.0;
    }
    return 0.0;
  }
  // W = ∫ w dω (sr): π for a plane and for every mean of planes (cylindrical, semi-cylindrical);
  // 3π/4 for the hemispherical response cut at the horizon.
  double integral() const { return kind == Quantity::kHemispherical ? 0.75 * kPi : kPi; }
  // The density (per sr) the hemisphere rays are drawn with: w / W.
  double density(const Vec3& d) const { return weight(d) / integral(); }
  // A direction of density w/W from the unit square; u1 runs from the axis (θ = 0) outwards, u2
  // around it (φ = 2π u2; for semi-cylindrical from the back through the facing to the back), so
  // that strata in (u1, u2) are the paper's θ × φ strata and φ wraps around.
  Vec3 sample(double u1, double u2) const;
  // The same response seen in a flat mirror of unit normal m (its virtual sources): w'(d) = w(R d).
  Response mirrored(const Vec3& m) const {
    Response r = *this;
    r.n = n - 2.0 * glm::dot(n, m) * m;
    r.facing = facing - 2.0 * glm::dot(facing, m) * m;
    return r;
  }
};

}  // namespace candela
