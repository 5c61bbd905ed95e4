// Sky subdivisions for daylight coefficients: Tregenza's 145 patches (P. R. Tregenza, "Subdivision
// of the sky hemisphere for luminance measurements", Lighting Res. Technol. 19(1), 1987) and
// Reinhart's MF:n refinement (144 n^2 + 1 sky patches), laid out as Radiance's reinhart.cal so
// that patch indices line up with rfluxmtx/gendaymtx matrices:
//   index 0      the ground (the whole lower hemisphere, 2 pi sr)
//   index 1..    rows from the horizon up; 7 n rows of height alpha = 90 / (7 n + 0.5) deg with
//                n x (30, 30, 24, 24, 18, 12, 6)[row / n] patches each, the first patch of a row
//                centred on (true) north and proceeding clockwise (towards east)
//   last index   the zenith cap (radius alpha / 2)
// Tregenza is n = 1 (alpha = 12 deg, cap 84..90 deg). Directions are in the true frame.
#pragma once

#include "base/math.h"

#include <vector>

namespace candela {

class SkyPatches {
 public:
  // n >= 1 (Reinhart's multiplication factor MF); throws std::invalid_argument otherwise.
  explicit SkyPatches(int n = 1);

  int multiplier() const { return n_; }
  int skyPatchCount() const { return 144 * n_ * n_ + 1; }
  int count() const { return skyPatchCount() + 1; }  // including the ground patch 0

  // Unit direction to the patch centre (the ground's is straight down).
  Vec3 centre(int index) const;
  // Solid angle in sr (the sky patches sum to 2 pi; the ground is 2 pi).
  double solidAngle(int index) const;
  // A direction uniformly distributed in solid angle over the patch, from (u1, u2) in [0,1)^2
  // (the ground: the whole lower hemisphere). Unit length, true frame.
  Vec3 sample(int index, double u1, double u2) const;
  // Patch containing a direction (need not be unit length); directions with z <= 0 are ground.
  int indexOf(const Vec3& dirTrue) const;

  double rowHeightRad() const { return alpha_; }

 private:
  int n_;
  double alpha_;
  std::vector<int> rowCount_;  // patches in each of the 7 n rows
  std::vector<int> rowStart_;  // index of the first patch of each row
};

}  // namespace candela
