// A camera view for tests: type, eye, direction, up, field of view (degrees) and resolution.
#pragma once

#include "engine/camera.h"

namespace candela::test_support {

// Relative tolerance of a pixel of an Image (engine/render.h): its values are held as float32,
// rounded once from the double estimate (at most 2^-24 of the value) and, for a mean over the
// image, summed from those roundings; 2^-23 bounds both.
inline constexpr double kFloatRel = 0x1p-23;

inline View makeView(ViewType type, Vec3 pos, Vec3 dir, Vec3 up, Vec2 fovDeg, int w, int h) {
  View v;
  v.type = type;
  v.positionM = pos;
  v.direction = dir;
  v.up = up;
  v.fovDeg = fovDeg;
  v.resolution = {w, h};
  return v;
}

}  // namespace candela::test_support
