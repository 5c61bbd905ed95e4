// The paper's octree (Ward & Rubinstein 1988; Glassner 1984): a cube around the scene, subdivided
// by AddSurface whenever a leaf would hold more than N surfaces and is larger than the minimum
// cube size; rays walk the voxels front to back and stop at the first voxel holding a hit.
#pragma once

#include "engine/accelerator.h"
#include "engine/scene.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace candela {

struct OctreeOptions {
  int maxSetSize = 6;         // N: surfaces a leaf may hold before it is split (Radiance oconv -n)
  double minCubeSizeM = 0.0;  // no split below this edge length; 0: root size / 4096
};

struct OctreeStats {
  size_t nodes = 0, leaves = 0, items = 0, memoryBytes = 0;
  int depth = 0;
};

class Octree : public RayAccelerator {
 public:
  Octree() = default;
  Octree(const Scene& scene, OctreeOptions options = {});

  using Hit = RayHit;

  // Nearest hit along o + t·dir (dir unit length) with t in (tMin, tMax), ignoring shapes skipA/skipB.
  bool intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, Hit& hit,
                 uint32_t skipA = kNoShape, uint32_t skipB = kNoShape) const override;
  // Any hit in (tMin, tMax) ignoring shapes skipA and skipB (shadow rays).
  bool occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA = kNoShape,
                uint32_t skipB = kNoShape) const override;

  OctreeStats stats() const;
  const Box& cube() const { return cube_; }

 private:
  struct Node {
    uint32_t first = 0;  // leaf: first index into items_; internal: first of 8 children
    uint32_t count = 0;  // leaf: number of items; kInternal for an internal node
  };
  static constexpr uint32_t kInternal = std::numeric_limits<uint32_t>::max();

  struct RayState;
  template <bool kAnyHit>
  bool traverse(RayState& r, uint32_t node, const Vec3& t0, const Vec3& t1) const;
  template <bool kAnyHit>
  bool run(RayState& r) const;
  uint32_t local(uint32_t shape) const {
    if (shape != kNoShape && shape >= meshBase_) return shape;  // a mesh triangle: its own id
    return shape < shapeToLocal_.size() ? shapeToLocal_[shape] : kNoShape;
  }

  // Primitives are renumbered in depth-first leaf order (items_ holds these local numbers), so
  // that the triangles a ray meets in neighbouring voxels lie close together in memory. Triangles
  // are repeated compactly (v0, e1, e2); other shapes go through intersectShape. Mesh triangles
  // (surface ids from meshBase_ on) are not renumbered nor copied: items_ hold their surface ids
  // and the test reads the scene's mesh (Scene::intersectSurface), so they cost only items_.
 public:
  struct Triangle {
    Vec3 v0, e1, e2;
  };

 private:
  std::vector<uint32_t> localToShape_, shapeToLocal_;

  const Scene* scene_ = nullptr;
  uint32_t meshBase_ = 0;  // Scene::shapes.size(): surface ids from here on are mesh triangles
  Box cube_;
  std::vector<Triangle> triangles_;
  std::vector<uint8_t> isTriangle_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> items_;
};

}  // namespace candela
