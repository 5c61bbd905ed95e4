#include "photometry/sky_cie.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace candela {

namespace {

// ISO 15469:2004 / CIE S 011/E:2003, Table 1. Gradation groups (a, b): I (4.0, -0.70),
// II (1.1, -0.8), III (0, -1.0), IV (-1.0, -0.55), V (-1.0, -0.32), VI (-1.0, -0.15).
// Indicatrix groups (c, d, e): 1 (0, -1.0, 0), 2 (2, -1.5, 0.15), 3 (5, -2.5, 0.30),
// 4 (10, -3.0, 0.45), 5 (16, -3.0, 0.30), 6 (24, -2.8, 0.15).
constexpr CieSkyParams kTypes[15] = {
    {4.0, -0.70, 0, -1.0, 0.00},    // 1  I.1   overcast, steep gradation, azimuthal uniformity
    {4.0, -0.70, 2, -1.5, 0.15},    // 2  I.2   overcast, steep gradation, slight brightening to the sun
    {1.1, -0.80, 0, -1.0, 0.00},    // 3  II.1  overcast, moderate gradation, azimuthal uniformity
    {1.1, -0.80, 2, -1.5, 0.15},    // 4  II.2  overcast, moderate gradation, slight brightening
    {0.0, -1.00, 0, -1.0, 0.00},    // 5  III.1 sky of uniform luminance
    {0.0, -1.00, 2, -1.5, 0.15},    // 6  III.2 partly cloudy, no gradation, slight brightening
    {0.0, -1.00, 5, -2.5, 0.30},    // 7  III.3 partly cloudy, brighter circumsolar region
    {0.0, -1.00, 10, -3.0, 0.45},   // 8  III.4 partly cloudy, distinct solar corona
    {-1.0, -0.55, 2, -1.5, 0.15},   // 9  IV.2  partly cloudy, obscured sun
    {-1.0, -0.55, 5, -2.5, 0.30},   // 10 IV.3  partly cloudy, brighter circumsolar region
    {-1.0, -0.55, 10, -3.0, 0.45},  // 11 IV.4  white-blue sky, distinct solar corona
    {-1.0, -0.32, 10, -3.0, 0.45},  // 12 V.4   CIE standard clear sky, low luminance turbidity
    {-1.0, -0.32, 16, -3.0, 0.30},  // 13 V.5   CIE standard clear sky, polluted atmosphere
    {-1.0, -0.15, 16, -3.0, 0.30},  // 14 VI.5  cloudless turbid sky, broad solar corona
    {-1.0, -0.15, 24, -2.8, 0.15},  // 15 VI.6  white-blue turbid sky, broad solar corona
};

double gradation(const CieSkyParams& p, double cosZ) {
  // b < 0 for every type, so exp(b / cos Z) -> 0 at the horizon and phi -> 1.
  return cosZ <= 0.0 ? 1.0 : 1.0 + p.a * std::exp(p.b / cosZ);
}

double indicatrix(const CieSkyParams& p, double chi) {
  const double c = std::cos(chi);
  return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * 0.5 * kPi)) + p.e * c * c;
}

}  // namespace

const CieSkyParams& cieSkyParams(int type) {
  if (type < 1 || type > 15) throw std::out_of_range("CIE general sky type must be 1..15");
  return kTypes[type - 1];
}

CieGeneralSky::CieGeneralSky(int type, const Vec3& sunDirTrue, double horizontalLux)
    : type_(type), p_(cieSkyParams(type)), sun_(glm::normalize(sunDirTrue)) {
  const double zs = std::acos(std::clamp(sun_.z, -1.0, 1.0));
  norm_ = 1.0 / (indicatrix(p_, zs) * gradation(p_, 1.0));
  calibrate(horizontalLux);
}

double CieGeneralSky::relativeLuminance(const Vec3& d) const {
  const double chi = std::acos(std::clamp(glm::dot(d, sun_), -1.0, 1.0));
  return std::max(0.0, indicatrix(p_, chi) * gradation(p_, d.z) * norm_);
}

}  // namespace candela
