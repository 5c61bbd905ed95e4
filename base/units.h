// Photometric units and colour conventions (architecture.md, "Photometry").
#pragma once

#include "base/math.h"

namespace candela {

// Three colour channels, linear, in Radiance's primaries.
using Rgb = glm::dvec3;

// Radiance's luminous efficacy for its radiometric "watts": 179 lm/W (Radiance rtrace -I docs).
inline constexpr double kLumensPerWatt = 179.0;

// Coordinates, radii and lengths that any input may give, m: within 10 000 km of the origin, where
// ray offsets and the accelerators' single precision keep the surfaces (Embree aborts near
// 1.8e18 m). Scene files, sensor points and case files are bounded by it.
inline constexpr double kMaxCoordinateM = 1e7;

// Photopic weights of Radiance's RGB primaries: Y = 0.265 R + 0.670 G + 0.065 B.
inline constexpr double kWeightR = 0.265;
inline constexpr double kWeightG = 0.670;
inline constexpr double kWeightB = 0.065;

// Photopic value of an RGB triple (same unit as the input).
inline double photopic(const Rgb& c) { return kWeightR * c.x + kWeightG * c.y + kWeightB * c.z; }

// Luminance in cd/m² of a Radiance radiance triple in W/sr/m².
inline double luminanceFromRadiance(const Rgb& radiance) { return kLumensPerWatt * photopic(radiance); }

// Illuminance in lux of a Radiance irradiance triple in W/m².
inline double illuminanceFromIrradiance(const Rgb& irradiance) { return kLumensPerWatt * photopic(irradiance); }

}  // namespace candela
