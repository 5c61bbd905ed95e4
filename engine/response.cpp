#include "engine/response.h"

#include "engine/sampling.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

// x − sin x without cancellation for small x (its series to x¹¹ below 0.1: relative error < 1e-15).
double xMinusSin(double x) {
  if (x >= 0.1) return x - std::sin(x);
  const double x2 = x * x;
  return x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0))));
}

// x − sin x = m on [0, π], m in [0, π]: f is increasing and convex there, so Newton from the cube
// root guess (x³/6 ≥ x − sin x puts it at or left of the root) overshoots once at most, and the
// bracket keeps it in [0, π].
double solveHalf(double m) {
  if (m <= 0.0) return 0.0;
  double lo = 0.0, hi = kPi;
  double x = std::min(kPi, std::cbrt(6.0 * m));
  for (int i = 0; i < 100; ++i) {
    const double f = xMinusSin(x) - m;
    if (f > 0.0) hi = std::min(hi, x);
    else lo = std::max(lo, x);
    const double s = std::sin(0.5 * x), slope = 2.0 * s * s;  // 1 − cos x
    double next = slope > 0.0 ? x - f / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-15 * std::max(1.0, x)) return next;
    x = next;
  }
  return x;
}

}  // namespace

double solveXMinusSin(double m) {
  m = std::clamp(m, 0.0, kTwoPi);
  // f(2π − x) = 2π − f(x): the upper half by symmetry.
  return m <= kPi ? solveHalf(m) : kTwoPi - solveHalf(kTwoPi - m);
}

Vec3 Response::sample(double u1, double u2) const {
  switch (kind) {
    case Quantity::kPlanar: return Frame::fromNormal(n).toWorld(sampleCosineHemisphere(u1, u2));
    case Quantity::kCylindrical:
    case Quantity::kSemiCylindrical: {
      // θ has density sin²θ / (π/2) on [0, π] (w ∝ sin θ, dω = sin θ dθ dφ): its distribution
      // (2θ − sin 2θ)/(2π) = u1 gives 2θ = solveXMinusSin(2π u1).
      const double theta = 0.5 * solveXMinusSin(kTwoPi * u1);
      double phi = kTwoPi * u2;
      Frame f = Frame::fromNormal(n);
      if (kind == Quantity::kSemiCylindrical) {
        // φ from the facing has density (1 + cos φ)/(2π) on [−π, π]: with y = φ + π its
        // distribution is (y − sin y)/(2π) = u2.
        phi = solveXMinusSin(kTwoPi * u2) - kPi;
        f.t = facing;
        f.b = glm::cross(n, facing);
      }
      const double st = std::sin(theta);
      return f.toWorld(Vec3(st * std::cos(phi), st * std::sin(phi), std::cos(theta)));
    }
    case Quantity::kHemispherical: {
      // μ = cos θ has density (2/3)(1 + μ) on [0, 1]; P(cos θ ≥ μ) = 1 − (2μ + μ²)/3 = u1.
      const double mu = std::sqrt(std::max(0.0, 4.0 - 3.0 * u1)) - 1.0;
      const double st = std::sqrt(std::max(0.0, 1.0 - mu * mu)), phi = kTwoPi * u2;
      return Frame::fromNormal(n).toWorld(Vec3(st * std::cos(phi), st * std::sin(phi), mu));
    }
  }
  return n;
}

}  // namespace candela
