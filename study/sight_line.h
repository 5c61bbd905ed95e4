// A straight line of sight through a scene, as EN 17037's view out and exposure to sunlight
// judge it (docs/en17037-view-sunlight.md): clear glazing is seen through, whatever its
// transmittance; anything else stops the eye. Shared by study/view_out.h and
// study/sunlight_exposure.h.
#pragma once

#include "base/math.h"
#include "engine/accelerator.h"
#include "engine/scene.h"
#include "engine/tracer.h"

#include <cstdint>

namespace candela {

// Glazing that lets less regular (image-forming) light through than this fraction is not seen
// through: a frosted trans (no specular transmission) or a near-black glass.
inline constexpr double kSeeThroughMinTransmittance = 0.01;

// Whether a sight line passes a surface of material m unbent and unblocked:
//  - glass: its transmissivity (photopic) at least kSeeThroughMinTransmittance;
//  - trans: its specular transmittance (photopic) likewise;
//  - dielectric: yes — a pane of two parallel faces shifts a line of sight but does not turn it
//    (Tracer::transmittance stops shadow rays at a dielectric instead, for its bending);
//  - illum: as its alternate material (mkillum's window with its glass), invisible without one;
//  - anything else (plastic, metal, mirror, light, glow, void): no.
bool seenThrough(const Scene& scene, const Material& m);

// What a line of sight from o along unit dir meets up to tMax.
struct SightLine {
  bool blocked = false;       // stopped by a surface not seen through
  double blockedAtM = 0.0;    // distance to it along dir (blocked only)
  uint32_t blocker = kNoShape;  // its surface id (blocked only)
  int glazingCrossed = 0;     // surfaces seen through before the stop (or the escape)
  double firstGlazingM = 0.0, lastGlazingM = 0.0;  // distances to the first and last of them
  Vec3 blockerNormal{0.0};    // unit geometric normal of the blocker (blocked only)
};

// Walks the hits along one ray (64 at most; past that the line counts as blocked). `rays`
// counts the accelerator queries made.
SightLine traceSightLine(const Tracer& tracer, const Vec3& o, const Vec3& dir, double tMax, uint64_t& rays);

}  // namespace candela
