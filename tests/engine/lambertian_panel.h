// A Lambertian panel luminaire for the tests: I = i0 cos γ (cd), tabulated every stepDeg (5°
// unless given; linear interpolation is then within 0.1 % of cos γ, 1°: 4e-5) in an
// IES LM-63-2002 file with one C plane and a widthM × lengthM rectangular opening, so that its
// opening has luminance i0 / (width · length) from every direction.
#pragma once

#include "photometry/ies_lm63.h"

#include <cmath>
#include <memory>
#include <sstream>

namespace candela::test_support {

inline std::shared_ptr<const PhotometricWeb> lambertianPanel(double i0Cd = 1000.0, double widthM = 0.6,
                                                             double lengthM = 0.6, int stepDeg = 5) {
  std::ostringstream ies;
  ies << "IESNA:LM-63-2002\n[TEST] Lambertian panel written for the candela tests\nTILT=NONE\n"
      << "1 -1 1 " << 90 / stepDeg + 1 << " 1 1 2 " << widthM << " " << lengthM << " 0\n1 1 30\n";
  for (int i = 0; i <= 90; i += stepDeg) ies << i << " ";
  ies << "\n0\n";
  for (int i = 0; i <= 90; i += stepDeg) ies << i0Cd * std::cos(degToRad(i)) << " ";
  ies << "\n";
  return std::make_shared<const PhotometricWeb>(parseIes(ies.str(), "panel.ies", "."));
}

}  // namespace candela::test_support
