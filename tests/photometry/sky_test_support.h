// Test helpers for sky models: quadratures independent of SkyModel's own integration.
#pragma once

#include "photometry/sky_model.h"

#include <algorithm>
#include <cmath>

namespace candela::test {

// Midpoint rule on an equal-area grid (u = sin(altitude), azimuth): d(omega) = du d(az).
// A different rule and parametrisation from SkyModel's Gauss-Legendre in (altitude, azimuth).
// Error O(1/n^2) for the smooth skies, ~1e-6 relative at n = 1000.
template <class F>
double equalAreaIntegral(F&& f, int nu = 1000, int naz = 2000) {
  double sum = 0.0;
  for (int i = 0; i < nu; ++i) {
    const double u = (i + 0.5) / nu;
    const double c = std::sqrt(1.0 - u * u);
    for (int j = 0; j < naz; ++j) {
      const double az = (j + 0.5) * kTwoPi / naz;
      sum += f(Vec3(c * std::sin(az), c * std::cos(az), u));
    }
  }
  return sum * (1.0 / nu) * (kTwoPi / naz);
}

inline double independentIlluminance(const SkyModel& sky, const Vec3& normal) {
  return equalAreaIntegral([&](const Vec3& d) { return sky.luminance(d) * std::max(0.0, glm::dot(normal, d)); });
}

}  // namespace candela::test
