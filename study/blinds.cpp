#include "study/blinds.h"

#include "engine/materials/family.h"
#include "engine/fresnel.h"

namespace candela {

void closeGlass(Material& m, double blindsTransmittance) {
  Rgb t, reflected;
  thinGlass(m.color, m.refractiveIndex, 1.0, t, reflected);  // the glass's normal transmittance
  m.type = MaterialType::kTrans;
  m.diffuseReflectance = Rgb(0.0);
  m.specularReflectance = Rgb(0.0);
  m.specularTransmittance = Rgb(0.0);
  m.diffuseTransmittance = blindsTransmittance * t;
}

int closeBlinds(Scene& scene) {
  int changed = 0;
  for (Material& m : scene.materials) {
    if (!familyOf(m).isGlazing()) continue;
    closeGlass(m, kBlindsTransmittance);
    ++changed;
  }
  return changed;
}

}  // namespace candela
