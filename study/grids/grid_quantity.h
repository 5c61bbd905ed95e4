// The illuminance quantities a [[grid]] computes (`quantity`, `facing`, `modelling` in
// docs/case-format.md; the method in docs/quantities.md): their names in the case file, the
// report and the CSV, and the sensor each one puts at a grid point.
#pragma once

#include "base/math.h"
#include "engine/sensors.h"

#include <optional>
#include <string>

namespace candela {

enum class GridQuantity { kHorizontal, kVertical, kCylindrical, kSemiCylindrical, kHemispherical };

// "horizontal", "vertical", "cylindrical", "semi-cylindrical", "hemispherical"; nullopt otherwise.
std::optional<GridQuantity> parseGridQuantity(const std::string& name);
// The case file's name of q (as parseGridQuantity reads it).
const char* gridQuantityKey(GridQuantity q);
// What a reader calls it, with its symbol: "Cylindrical illuminance Ē_z".
std::string gridQuantityName(GridQuantity q);
// Its CSV column: "cylindrical_illuminance_lux", "semi_cylindrical_illuminance_lux", ...
std::string gridQuantityColumn(GridQuantity q);
// Whether q needs `facing` (vertical: the plane's normal; semi-cylindrical: where it faces).
inline bool needsFacing(GridQuantity q) { return q == GridQuantity::kVertical || q == GridQuantity::kSemiCylindrical; }

// The sensor of quantity q at `position` (m): planar on +Z (horizontal) or on the unit
// horizontal `facing` (vertical); about the vertical axis +Z otherwise, semi-cylindrical facing
// `facing` (its `normal`, engine/sensors.h: the grid CSV's dx, dy, dz). `facing` is a plan
// direction (need not be unit; not zero where needsFacing).
SensorPoint quantitySensor(GridQuantity q, const Vec3& position, const Vec2& facing = Vec2(1.0, 0.0));

}  // namespace candela
