// Uniform, CIE overcast (Moon & Spencer) and the fifteen CIE standard general skies.
//
// General skies: ISO 15469:2004(E) / CIE S 011/E:2003, "Spatial distribution of daylight - CIE
// standard general sky". Relative luminance
//   L/Lz = f(chi) phi(Z) / (f(Zs) phi(0)),
//   gradation  phi(Z) = 1 + a exp(b / cos Z)          (phi = 1 at the horizon, b < 0),
//   indicatrix f(chi) = 1 + c (exp(d chi) - exp(d pi/2)) + e cos^2 chi,
// Z the zenith angle of the sky element, Zs that of the sun, chi the angle between them.
#pragma once

#include "photometry/sky_model.h"

namespace candela {

// Constant luminance L: E_h = pi L.
class UniformSky : public SkyModel {
 public:
  explicit UniformSky(double horizontalLux) { calibrate(horizontalLux); }
  double relativeLuminance(const Vec3&) const override { return 1.0; }
  std::string name() const override { return "uniform"; }
};

// CIE standard overcast sky (Moon & Spencer 1942; CIE 1955): L(h) = Lz (1 + 2 sin h) / 3, h the
// altitude. Relative luminance is L/Lz; E_h = (7 pi / 9) Lz.
class CieOvercastSky : public SkyModel {
 public:
  explicit CieOvercastSky(double horizontalLux) { calibrate(horizontalLux); }
  double relativeLuminance(const Vec3& d) const override { return (1.0 + 2.0 * d.z) / 3.0; }
  std::string name() const override { return "cie-overcast"; }
  double zenithLuminance() const { return scale(); }  // cd/m2
};

// Gradation (a, b) and indicatrix (c, d, e) parameters of a general sky type (1..15), ISO
// 15469 Table 1 (six gradation and six indicatrix groups combined into 15 types).
struct CieSkyParams {
  double a, b, c, d, e;
};
const CieSkyParams& cieSkyParams(int type);

class CieGeneralSky : public SkyModel {
 public:
  // type 1..15 (12 is the CIE standard clear sky), sunDirTrue unit vector towards the sun (the
  // sun may be below the horizon), horizontalLux the sky's horizontal illuminance in lux.
  CieGeneralSky(int type, const Vec3& sunDirTrue, double horizontalLux);
  // L/Lz: 1 at the zenith.
  double relativeLuminance(const Vec3& d) const override;
  std::string name() const override { return "cie:" + std::to_string(type_); }
  double zenithLuminance() const { return scale(); }  // cd/m2
  int type() const { return type_; }

 private:
  int type_;
  CieSkyParams p_;
  Vec3 sun_;
  double norm_;  // 1 / (f(Zs) phi(0))
};

}  // namespace candela
