// The closed state of operable blinds for LM-83's sDA (IES LM-83-12 2.2.7), as a scene edit.
#pragma once

#include "engine/scene.h"

namespace candela {

// LM-83-12 2.2.7's closed state when nothing better is known: white blinds as a diffusing layer
// of 20 % visible transmittance.
inline constexpr double kBlindsTransmittance = 0.2;

// A glass material closed: a Lambertian transmitter of blindsTransmittance times the glass's
// normal transmittance, passing no beam, reflecting nothing.
void closeGlass(Material& m, double blindsTransmittance);

// Every glass pane becomes a Lambertian transmitter of kBlindsTransmittance times the glass's
// own normal transmittance (no beam passes); its reflection is not modelled (docs/annual.md).
// Returns the number of materials changed.
int closeBlinds(Scene& scene);

}  // namespace candela
