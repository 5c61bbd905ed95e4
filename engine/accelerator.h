// The ray-query interface the tracer uses. The paper's octree implements it (engine/octree.h);
// other structures may too, where they are measurably faster (docs/performance.md).
#pragma once

#include "base/math.h"

#include <cstdint>
#include <limits>

namespace candela {

inline constexpr uint32_t kNoShape = std::numeric_limits<uint32_t>::max();

struct RayHit {
  double t = 0.0;                // distance along the (unit) direction, m
  uint32_t shape = kNoShape;     // index into Scene::shapes
};

class RayAccelerator {
 public:
  virtual ~RayAccelerator() = default;
  // Nearest hit along o + t·dir (dir unit length) with t in (tMin, tMax), ignoring shapes
  // skipA/skipB. t must equal intersectShape's value for that shape.
  // 7 parameters: the ray, its interval, the result and the two shapes a ray leaving a surface skips.
  virtual bool intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, RayHit& hit,
                         uint32_t skipA = kNoShape, uint32_t skipB = kNoShape) const = 0;
  // Any hit in (tMin, tMax) ignoring shapes skipA and skipB (shadow rays).
  virtual bool occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA = kNoShape,
                        uint32_t skipB = kNoShape) const = 0;
};

}  // namespace candela
