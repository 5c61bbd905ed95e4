// The sky of a type under given conditions: the one place where a SkyType becomes a SkyModel.
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "photometry/sky_model.h"
#include "photometry/sky_type.h"

#include <memory>
#include <optional>

namespace candela {

// Everything that selects and drives a sky (case file [sky] + site + time, or an EPW hour).
struct SkyConditions {
  Vec3 sunDirTrue{0.0, 0.0, 1.0};       // unit vector towards the sun, true frame
  int dayOfYear = 172;                  // 1..366, for the extraterrestrial irradiance (Perez)
  double diffuseHorizontalLux = 10000.0;  // uniform and CIE skies: their horizontal illuminance, lux
  double directNormalWm2 = 0.0;         // Perez: direct normal irradiance, W/m2
  double diffuseHorizontalWm2 = 0.0;    // Perez: diffuse horizontal irradiance, W/m2
  std::optional<double> dewPointC;      // Perez efficacy: surface dew point, deg C (default W = 2 cm)
};

// The sky of a type (cie-clear is cie:12). Throws InputError at `loc` for bad conditions or a
// type without a point-in-time model (none, annual).
std::unique_ptr<SkyModel> makeSky(const SkyType& type, const SkyConditions& conditions, const FileLoc& loc = {});

}  // namespace candela
