#include "metrics/contrast.h"

#include <stdexcept>

namespace candela {

double luminanceContrast(double taskCdM2, double backgroundCdM2) {
  if (!(backgroundCdM2 > 0.0)) throw std::invalid_argument("luminanceContrast: background luminance must be > 0");
  return (taskCdM2 - backgroundCdM2) / backgroundCdM2;
}

double contrastRenditionFactor(double contrast, double referenceContrast) {
  if (referenceContrast == 0.0) throw std::invalid_argument("contrastRenditionFactor: reference contrast is 0");
  return contrast / referenceContrast;
}

double matteReferenceContrast(double taskReflectance, double backgroundReflectance) {
  return luminanceContrast(taskReflectance, backgroundReflectance);
}

}  // namespace candela
