// Modelling (EN 12464-1:2021, directionality of light): how well the light shows the form of
// faces and objects, rated by the ratio of the average cylindrical illuminance Ē_z to the
// average horizontal illuminance Ē_h at the same points, on a plane at 1.2 m (seated) or 1.6 m
// (standing). The standard takes 0.30 to 0.60 as good modelling: below, flat (mostly
// downward light); above, harsh (mostly sideways light).
#pragma once

#include "metrics/targets.h"

#include <vector>

namespace candela {

inline constexpr double kModellingRatioMin = 0.30, kModellingRatioMax = 0.60;

struct ModellingResult {
  double cylindricalAverageLux = 0.0;  // Ē_z, lux
  double horizontalAverageLux = 0.0;   // Ē_h, lux
  double ratio = 0.0;                  // Ē_z / Ē_h; 0 when Ē_h is 0
  // kPass within [kModellingRatioMin, kModellingRatioMax] (the ends included), kFail outside
  // or when Ē_h is 0.
  Verdict verdict = Verdict::kNotChecked;
};

// The grid's modelling from the cylindrical and horizontal illuminance (lux) of each of its
// points (the same points, in the same order). Throws std::invalid_argument on a length mismatch.
ModellingResult modellingRatio(const std::vector<double>& cylindricalLux, const std::vector<double>& horizontalLux);

// The per-point ratio E_z / E_h, 0 where E_h is 0.
inline double pointModellingRatio(double cylindricalLux, double horizontalLux) {
  return horizontalLux > 0.0 ? cylindricalLux / horizontalLux : 0.0;
}

}  // namespace candela
