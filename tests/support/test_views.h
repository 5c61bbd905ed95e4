// A camera view for tests: type, eye, direction, up, field of view (degrees) and resolution.
#pragma once

#include "engine/camera.h"

namespace candela::test_support {

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
