// Sample warps from the unit square, with their densities. Stratification is done by the
// caller passing jittered (u1, u2) from strata (see Strata2D).
#pragma once

#include "base/math.h"
#include "base/rng.h"

#include <algorithm>
#include <cmath>

namespace candela {

// Cosine-weighted direction about +Z (Malley's method; the paper's eq. 3 stratification maps
// strata in (u1, u2) to θ = asin√u1, φ = 2πu2). pdf = cos θ / π per steradian.
inline Vec3 sampleCosineHemisphere(double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = kTwoPi * u2;
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1)));
}

// Uniform direction in the cone of half-angle with cosine cosMax about +Z; pdf = 1/(2π(1 − cosMax)).
inline Vec3 sampleUniformCone(double u1, double u2, double cosMax) {
  const double cosT = 1.0 - u1 * (1.0 - cosMax);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  const double phi = kTwoPi * u2;
  return Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
}

// Uniform point on a triangle (barycentric square-root warp); pdf = 1/area.
inline Vec3 sampleTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double u1, double u2) {
  const double s = std::sqrt(u1);
  return (1.0 - s) * a + s * (1.0 - u2) * b + s * u2 * c;
}

// Uniform point on an annulus r0 ≤ r ≤ r1 in the (t, b) plane; pdf = 1/(π(r1² − r0²)).
inline Vec2 sampleAnnulus(double r0, double r1, double u1, double u2) {
  const double r = std::sqrt(r0 * r0 + u1 * (r1 * r1 - r0 * r0));
  const double phi = kTwoPi * u2;
  return Vec2(r * std::cos(phi), r * std::sin(phi));
}

// Jittered strata of the unit square: n samples as an nx × ny grid with nx·ny ≈ n and
// ny ≈ nx / aspect; hemispheres pass aspect = 1/π so that the φ strata (ny) number about π times
// the θ strata (nx), the paper's M × N with N ≈ πM.
class Strata2D {
 public:
  Strata2D(int n, double aspect = 1.0) {
    n_ = n < 1 ? 1 : n;
    // At most n strata in φ: with n = 1 or 2 and aspect 1/π, √(n π) rounds to more strata than
    // samples, and the samples would only ever cover the first of them (a half or two thirds
    // of the azimuths).
    ny_ = std::clamp(static_cast<int>(std::lround(std::sqrt(n_ / aspect))), 1, n_);
    nx_ = std::max(1, n_ / ny_);
    // Samples beyond nx·ny are drawn unstratified (keeps exactly n samples).
  }
  int size() const { return n_; }
  // The i-th jittered sample.
  Vec2 sample(int i, Rng& rng) const {
    const double j1 = rng.uniform(), j2 = rng.uniform();
    if (i >= nx_ * ny_) return Vec2(j1, j2);
    return Vec2((i / ny_ + j1) / nx_, (i % ny_ + j2) / ny_);
  }

 private:
  int n_, nx_, ny_;
};

}  // namespace candela
