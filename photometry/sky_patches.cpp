#include "photometry/sky_patches.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela {

SkyPatches::SkyPatches(int n) : n_(n) {
  if (n < 1) throw std::invalid_argument("sky patch multiplier must be >= 1");
  // Tregenza's bands of 12 degrees hold 30, 30, 24, 24, 18, 12, 6 patches; the zenith cap is
  // half a band high so that 7 n rows + cap span 90 degrees.
  static const int kTregenza[7] = {30, 30, 24, 24, 18, 12, 6};
  alpha_ = degToRad(90.0 / (7.0 * n + 0.5));
  int start = 1;
  for (int r = 0; r < 7 * n; ++r) {
    rowCount_.push_back(n * kTregenza[r / n]);
    rowStart_.push_back(start);
    start += rowCount_.back();
  }
}

Vec3 SkyPatches::centre(int index) const {
  if (index <= 0) return Vec3(0.0, 0.0, -1.0);
  if (index >= skyPatchCount()) return Vec3(0.0, 0.0, 1.0);
  const int r = int(std::upper_bound(rowStart_.begin(), rowStart_.end(), index) - rowStart_.begin()) - 1;
  const double az = kTwoPi * (index - rowStart_[r]) / rowCount_[r];
  const double alt = (r + 0.5) * alpha_;
  return Vec3(std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt));
}

double SkyPatches::solidAngle(int index) const {
  if (index <= 0) return kTwoPi;
  if (index >= skyPatchCount()) return kTwoPi * (1.0 - std::cos(0.5 * alpha_));
  const int r = int(std::upper_bound(rowStart_.begin(), rowStart_.end(), index) - rowStart_.begin()) - 1;
  // Zone between two altitudes: 2 pi (sin h1 - sin h0), shared equally by the row's patches.
  return kTwoPi / rowCount_[r] * (std::sin((r + 1) * alpha_) - std::sin(r * alpha_));
}

Vec3 SkyPatches::sample(int index, double u1, double u2) const {
  // Uniform in solid angle: sin(altitude) uniform over the patch's range, azimuth uniform.
  double z0 = 0.0, z1 = 0.0, az0 = 0.0, width = kTwoPi;
  if (index <= 0) {
    z0 = -1.0;
  } else if (index >= skyPatchCount()) {
    z0 = std::sin(7 * n_ * alpha_);
    z1 = 1.0;
  } else {
    const int r = int(std::upper_bound(rowStart_.begin(), rowStart_.end(), index) - rowStart_.begin()) - 1;
    z0 = std::sin(r * alpha_);
    z1 = std::sin((r + 1) * alpha_);
    width = kTwoPi / rowCount_[r];
    az0 = width * (index - rowStart_[r]) - 0.5 * width;  // patches are centred on multiples of the width
  }
  const double z = z0 + u1 * (z1 - z0), az = az0 + u2 * width;
  const double rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3(rxy * std::sin(az), rxy * std::cos(az), z);
}

int SkyPatches::indexOf(const Vec3& dirTrue) const {
  const double len = glm::length(dirTrue);
  if (!(dirTrue.z > 0.0) || !(len > 0.0)) return 0;
  const double alt = std::asin(std::min(1.0, dirTrue.z / len));
  const int r = int(alt / alpha_);
  if (r >= 7 * n_) return skyPatchCount();
  double az = std::atan2(dirTrue.x, dirTrue.y);
  if (az < 0.0) az += kTwoPi;
  // Patches are centred on multiples of the width, so round rather than truncate.
  const int col = int(std::floor(az / (kTwoPi / rowCount_[r]) + 0.5)) % rowCount_[r];
  return rowStart_[r] + col;
}

}  // namespace candela
