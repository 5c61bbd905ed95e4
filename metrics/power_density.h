// The power density of a lighting installation (EN 12464-1:2021 asks for the energy efficiency
// of the lighting to be considered; the design tools state it as W/m² and as W/m²/100 lx, the
// installed power per floor area normalised to 100 lx of maintained illuminance): pure
// functions of the installed power, the area and the average illuminance.
#pragma once

#include <optional>

namespace candela {

// Installed power over the floor area, W/m²; unset when the area is not > 0.
std::optional<double> powerDensityWm2(double installedPowerW, double floorAreaM2);

// W/m²/100 lx = (W/m²) · 100 / Ē, Ē the average illuminance (lx) the power gives; unset when Ē is
// not > 0 (no light: the figure has no meaning).
std::optional<double> normalisedPowerDensity(double powerDensityWm2, double averageLux);

}  // namespace candela
