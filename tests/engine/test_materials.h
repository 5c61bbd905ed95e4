// A material of one value (reflectance, transmissivity or radiance, by type) for scenes the
// engine tests build by hand.
#pragma once

#include "engine/scene.h"

#include <string>

namespace candela::test_support {

inline uint32_t addMaterial(Scene& sc, MaterialType type, double value, const std::string& name = "m") {
  Material m;
  m.type = type;
  m.name = name;
  m.color = Rgb(value);
  return sc.addMaterial(m);
}

}  // namespace candela::test_support
