#include "study/grids/grid_quantity.h"

namespace candela {

namespace {

struct QuantityNames {
  GridQuantity q;
  const char* key;
  const char* name;
  const char* column;
};

// EN 12464-1:2021 and CIE S 017:2020 (17-21-057 to 17-21-060) name and symbol them so.
constexpr QuantityNames kNames[] = {
    {GridQuantity::kHorizontal, "horizontal", "Horizontal illuminance Ē_h", "horizontal_illuminance_lux"},
    {GridQuantity::kVertical, "vertical", "Vertical illuminance Ē_v", "vertical_illuminance_lux"},
    {GridQuantity::kCylindrical, "cylindrical", "Cylindrical illuminance Ē_z", "cylindrical_illuminance_lux"},
    {GridQuantity::kSemiCylindrical, "semi-cylindrical", "Semi-cylindrical illuminance Ē_sz",
     "semi_cylindrical_illuminance_lux"},
    {GridQuantity::kHemispherical, "hemispherical", "Hemispherical illuminance Ē_hs", "hemispherical_illuminance_lux"},
};

const QuantityNames& names(GridQuantity q) {
  for (const QuantityNames& n : kNames)
    if (n.q == q) return n;
  return kNames[0];
}

}  // namespace

std::optional<GridQuantity> parseGridQuantity(const std::string& name) {
  for (const QuantityNames& n : kNames)
    if (name == n.key) return n.q;
  return std::nullopt;
}

const char* gridQuantityKey(GridQuantity q) { return names(q).key; }
std::string gridQuantityName(GridQuantity q) { return names(q).name; }
std::string gridQuantityColumn(GridQuantity q) { return names(q).column; }

SensorPoint quantitySensor(GridQuantity q, const Vec3& position, const Vec2& facing) {
  const Vec3 up(0.0, 0.0, 1.0);
  const double len = glm::length(facing);
  const Vec3 f = len > 0.0 ? Vec3(facing.x / len, facing.y / len, 0.0) : Vec3(1.0, 0.0, 0.0);
  SensorPoint s{position, up};
  switch (q) {
    case GridQuantity::kHorizontal: break;
    case GridQuantity::kVertical: s.normal = f; break;
    case GridQuantity::kCylindrical: s.quantity = Quantity::kCylindrical; break;
    case GridQuantity::kSemiCylindrical:
      s.quantity = Quantity::kSemiCylindrical;
      s.normal = f;  // the direction it faces (engine/sensors.h)
      break;
    case GridQuantity::kHemispherical: s.quantity = Quantity::kHemispherical; break;
  }
  return s;
}

}  // namespace candela
