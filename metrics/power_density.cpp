#include "metrics/power_density.h"

#include <cmath>

namespace candela {

std::optional<double> powerDensityWm2(double installedPowerW, double floorAreaM2) {
  if (!(floorAreaM2 > 0.0) || !std::isfinite(floorAreaM2)) return std::nullopt;
  return installedPowerW / floorAreaM2;
}

std::optional<double> normalisedPowerDensity(double powerDensityWm2, double averageLux) {
  if (!(averageLux > 0.0) || !std::isfinite(averageLux)) return std::nullopt;
  return powerDensityWm2 * 100.0 / averageLux;
}

}  // namespace candela
