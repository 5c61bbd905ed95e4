// EN 17037:2018+A1:2023 view out (clause 5.2, Annex C) at eye positions: the horizontal sight
// angle through the windows, the outside distance of the view and the layers seen (sky,
// landscape, ground), each graded, and the point's level the lowest of the three
// (docs/en17037-view-sunlight.md has the definitions and what is approximate).
//
// Windows are the surfaces a line of sight passes (study/sight_line.h: clear glass, trans with a
// specular part, dielectric, illum); a direction is a view out when its ray from the eye crosses
// at least one of them before anything opaque.
//  - Horizontal sight angle: rays in the eye's horizontal plane every horizontalStepDeg over
//    360°; sightAngleDeg is the largest run of neighbouring view-out directions (one window, or
//    windows with nothing opaque between), totalSightAngleDeg all of them (several windows).
//  - Outside distance: along those horizontal view-out rays, from the last glazing crossed to the
//    first opaque surface behind it (+infinity when the ray leaves the model); the level is graded
//    on the smallest (outsideDistanceM), the median is reported too.
//  - Layers: rays every layerStepDeg in azimuth and elevation over the whole sphere; of those that
//    are views out, one leaving the model upwards sees the sky, downwards the ground (candela's
//    ground below the horizon); one stopped by an upward-or-downward-facing flat surface (|n_z| ≥
//    0.9) below the eye sees the ground, by anything else the landscape. A horizontal ray leaving
//    the model sees the open horizon: landscape.
#pragma once

#include "base/math.h"
#include "engine/tracer.h"
#include "metrics/en17037_view_sunlight.h"

#include <cstdint>
#include <vector>

namespace candela {

struct ViewOutOptions {
  double horizontalStepDeg = 0.05;  // step of the horizontal sight rays (0 < step ≤ 10)
  double layerStepDeg = 0.5;        // step in azimuth and elevation of the layer rays (0 < step ≤ 10)
  // Grade the sum of every window's sight angle instead of the largest contiguous one.
  bool gradeTotalAngle = false;
  int threads = 0;  // 0: all cores; results do not depend on it
};

// A surface below the eye whose unit normal has |z| at least this is ground (floors, terraces,
// terrain; a lower roof too).
inline constexpr double kGroundNormalZ = 0.9;

struct ViewOut {
  Vec3 eye{0.0};
  double sightAngleDeg = 0.0;       // largest contiguous horizontal angle through windows
  double totalSightAngleDeg = 0.0;  // every horizontal direction through windows
  // Smallest and median outside distance over the horizontal view-out rays (m); +infinity when
  // nothing is met outside, 0 when there is no view out at all.
  double outsideDistanceM = 0.0;
  double medianOutsideDistanceM = 0.0;
  uint8_t layers = 0;  // ViewLayer bits
  En17037Level sightLevel = En17037Level::kNone;
  En17037Level distanceLevel = En17037Level::kNone;
  En17037Level layersLevel = En17037Level::kNone;
  En17037Level level = En17037Level::kNone;  // the lowest of the three
};

// The view out from each eye (m, model frame; z is the eye height). Throws std::invalid_argument
// for steps out of range.
std::vector<ViewOut> viewOut(const Tracer& tracer, const std::vector<Vec3>& eyes, const ViewOutOptions& options = {});

}  // namespace candela
