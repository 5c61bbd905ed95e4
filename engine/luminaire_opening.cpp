#include "engine/luminaire_opening.h"

#include "engine/accelerator.h"

namespace candela {

uint32_t addOpeningSurface(Scene& scene, uint32_t index, double reflectance) {
  LuminaireSource& l = scene.luminaires[index];
  const bool hasArea = l.circular ? l.widthM > 0.0 : l.widthM > 0.0 && l.lengthM > 0.0;
  if (!hasArea) return kNoShape;
  // Radiance plastic with no specular part: diffuse reflectance = colour (both sides).
  Material m;
  m.type = MaterialType::kPlastic;
  m.name = l.name + ".opening";
  m.color = Rgb(reflectance);
  const uint32_t material = scene.addMaterial(m);
  const std::string name = l.name + ".opening";
  uint32_t shape;
  if (l.circular) {
    shape = scene.addRing(l.position, -l.axisZ, 0.0, 0.5 * l.widthM, material, name);
  } else {
    const Vec3 hx = 0.5 * l.widthM * l.axisX, hy = 0.5 * l.lengthM * l.axisY;
    // Counter-clockwise seen from below the fitting: the front normal is the nadir, −axisZ.
    const Vec3& c = l.position;
    shape = scene.addPolygon({c - hx - hy, c - hx + hy, c + hx + hy, c + hx - hy}, material, name);
  }
  l.openingShape = shape;
  return shape;
}

}  // namespace candela
