// Perez all-weather sky luminance distribution driven by measured irradiance.
//
// Sources:
//  - R. Perez, R. Seals, J. Michalsky (1993), "All-weather model for sky luminance
//    distribution - preliminary configuration and validation", Solar Energy 50(3), 235-245:
//    l = (1 + a exp(b / cos Z)) (1 + c exp(d gamma) + e cos^2 gamma), coefficients of Table 1.
//  - R. Perez, P. Ineichen, R. Seals, J. Michalsky, R. Stewart (1990), "Modeling daylight
//    availability and irradiance components from direct and global irradiance", Solar Energy
//    44(5), 271-289: sky clearness epsilon, brightness Delta and the luminous efficacy models of
//    Table 4 (diffuse and direct).
#pragma once

#include "photometry/sky_model.h"

#include <optional>

namespace candela {

struct PerezInput {
  double directNormalWm2 = 0.0;       // direct normal irradiance, W/m2
  double diffuseHorizontalWm2 = 0.0;  // diffuse horizontal irradiance, W/m2
  Vec3 sunDirTrue{0.0, 0.0, 1.0};     // unit vector towards the sun, true frame
  int dayOfYear = 172;                // 1..366, for the extraterrestrial irradiance
  std::optional<double> dewPointC;    // surface dew point, deg C; without it W = 2 cm
  // false skips SkyModel::calibrate (its hemisphere integral and the 256 x 64 sampling table):
  // scale() and luminance() are then 0 and sample()/pdf() must not be called; the shape
  // (relativeLuminance, coefficient) and the efficacies/illuminances stay valid. For callers that
  // normalise the shape themselves, e.g. the hourly sky vectors of photometry/annual_sky.h.
  bool calibrate = true;
};

class PerezSky : public SkyModel {
 public:
  // Throws InputError at `loc` for negative or non-finite irradiances or a bad day of year.
  explicit PerezSky(const PerezInput& in, const FileLoc& loc = {});

  double relativeLuminance(const Vec3& d) const override;
  std::string name() const override { return "perez"; }

  double clearness() const { return epsilon_; }    // epsilon, 1 (overcast) .. > 6.2 (clear)
  double brightness() const { return delta_; }     // Delta = DHI m / E0
  int clearnessBin() const { return bin_; }        // 1..8
  double precipitableWaterCm() const { return w_; }
  double coefficient(char which) const;            // 'a'..'e' of the luminance distribution

  double diffuseEfficacyLmPerW() const { return diffuseEfficacy_; }  // Perez 1990, lm/W
  double directEfficacyLmPerW() const { return directEfficacy_; }    // Perez 1990, lm/W, >= 0
  // DHI x diffuse efficacy: the sky's horizontal illuminance, lux.
  double diffuseHorizontalIlluminanceLux() const { return diffuseLux_; }
  // DNI x direct efficacy: illuminance of the sun disk on a plane normal to it, lux (0 with the
  // sun below the horizon). The sun is a separate source, not part of luminance().
  double directNormalIlluminanceLux() const { return directLux_; }

 private:
  Vec3 sun_;
  double epsilon_ = 1.0, delta_ = 0.0, w_ = 2.0;
  int bin_ = 1;
  double a_ = 0, b_ = 0, c_ = 0, d_ = 0, e_ = 0;
  double diffuseEfficacy_ = 0, directEfficacy_ = 0, diffuseLux_ = 0, directLux_ = 0;
};

// The tables behind PerezSky, for callers that follow another program's use of them (engine's
// gendaylit): no clamping here, the caller decides.
struct PerezCoefficients {
  double a = 0, b = 0, c = 0, d = 0, e = 0;
};
// Sky clearness bin 1..8 of epsilon (Perez et al. 1990, Table 1 bounds 1.065 ... 6.2).
int perezClearnessBin(double epsilon);
// Perez, Seals & Michalsky (1993) Table 1 coefficients for a bin, the solar zenith in radians and
// the sky brightness Delta.
PerezCoefficients perezCoefficients(int bin, double zenithRad, double delta);
// Perez et al. (1990) Table 4 luminous efficacies, lm/W, for a bin, precipitable water W (cm),
// solar zenith (radians) and Delta: diffuse a + b W + c cos Z + d ln(Delta) (Delta > 0), direct
// a + b W + c exp(5.73 Z - 5) + d Delta (not clamped at 0).
double perezDiffuseEfficacy(int bin, double waterCm, double zenithRad, double delta);
double perezDirectEfficacy(int bin, double waterCm, double zenithRad, double delta);

// Extraterrestrial normal irradiance in W/m2 for a day of the year: 1367 W/m2 times Spencer's
// (1971) eccentricity correction (as given in Iqbal, An Introduction to Solar Radiation, 1983).
double extraterrestrialNormalWm2(int dayOfYear);

// Relative optical air mass for a zenith angle in degrees (Kasten & Young 1989, Applied Optics
// 28(22)); finite (~38) at the horizon, clamped there for larger angles.
double relativeAirMass(double zenithDeg);

}  // namespace candela
