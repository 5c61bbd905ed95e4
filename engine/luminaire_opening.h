// A luminaire's luminous opening as a surface of the scene (the case key `opening_reflectance`,
// docs/luminaires.md): an opaque diffuse rectangle or disc in the opening plane, so that the
// diffuser or louvre blocks and reflects light from the room as the real one does. The
// luminaire's own light passes it (its shadow rays skip the shape, as an area source's skip
// their own shape) and rays that meet it from the room still see the luminaire's luminance.
#pragma once

#include "engine/scene.h"

#include <cstdint>

namespace candela {

// Adds the opening of scene.luminaires[index] as an opaque Lambertian surface of diffuse
// reflectance `reflectance` (0..1, grey) facing the photometric nadir, and records its shape in
// the luminaire's openingShape. Returns the shape, or kNoShape for an opening without area (a
// point or line luminaire), where nothing is added.
uint32_t addOpeningSurface(Scene& scene, uint32_t index, double reflectance);

}  // namespace candela
