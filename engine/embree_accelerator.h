// Ray queries through Intel Embree 3 (a float BVH with SIMD traversal) behind the RayAccelerator
// interface, with the same answers as the octree: the nearest shape's t is recomputed in double
// with intersectShape, so the tracer sees the exact value it would get from the octree.
// Triangles are Embree triangles (float, relative to the scene's bounding-box centre; the scene's
// compact mesh shares its index array with Embree and its vertices once per vertex); polygons,
// spheres, rings and cones are Embree user geometry whose callbacks call intersectShape.
// Speed against the octree: docs/performance.md.
#pragma once

#include "engine/accelerator.h"
#include "engine/scene.h"

#include <atomic>
#include <cstdint>
#include <vector>

struct RTCDeviceTy;
struct RTCSceneTy;

namespace candela {

struct EmbreeOptions {
  // RTC_SCENE_FLAG_ROBUST: watertight triangle test, conservative traversal. Needed: without it
  // about one in nine rays aimed exactly at the shared vertices and edges of a tessellated floor
  // pass through it (the floor of embree_accelerator_test.cpp), which no double re-test repairs.
  // It costs ~20 % of the speed (docs/performance.md).
  bool robust = true;
  bool highQuality = true;  // RTC_BUILD_QUALITY_HIGH (spatial splits) instead of MEDIUM
  bool compact = false;     // RTC_SCENE_FLAG_COMPACT: less memory, slower
};

struct EmbreeStats {
  size_t triangles = 0;    // shapes given to Embree as triangles
  size_t userShapes = 0;   // shapes given as user geometry (intersectShape in the callbacks)
  size_t memoryBytes = 0;  // Embree's own allocations (BVH) plus this class's buffers and tables
};

class EmbreeAccelerator : public RayAccelerator {
 public:
  // Builds the BVH over every shape of `scene`, which must outlive the accelerator.
  explicit EmbreeAccelerator(const Scene& scene, EmbreeOptions options = {});
  ~EmbreeAccelerator() override;
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  // Nearest hit along o + t·dir (dir unit length) with t in (tMin, tMax), ignoring shapes
  // skipA/skipB; t is intersectShape's double value for the shape found. Thread-safe.
  bool intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, RayHit& hit,
                 uint32_t skipA = kNoShape, uint32_t skipB = kNoShape) const override;
  // Any hit in (tMin, tMax) ignoring shapes skipA and skipB, confirmed by intersectShape.
  bool occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA = kNoShape,
                uint32_t skipB = kNoShape) const override;

  EmbreeStats stats() const;

 private:
  struct Query;
  friend struct EmbreeCallbacks;

  // Runs rtcIntersect1; `exact` makes every triangle candidate pass intersectShape first.
  bool nearest(Query& q, bool exact, RayHit& hit) const;
  // Embree's (geometry, primitive) → index into Scene::shapes.
  uint32_t toShape(unsigned geomID, unsigned primID) const {
    if (geomID == meshGeom_) return meshBase_ + primID;
    return geomID == triangleGeom_ ? triangleShapes_[primID] : userShapes_[primID];
  }
  void attachMesh(const EmbreeOptions& options);

  const Scene& scene_;
  Vec3 centre_{0.0};  // Embree coordinates are relative to this point (float precision)
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* rtcScene_ = nullptr;
  unsigned triangleGeom_ = ~0u, userGeom_ = ~0u, meshGeom_ = ~0u;
  uint32_t meshBase_ = 0;                              // surface id of the mesh's triangle 0
  std::vector<uint32_t> triangleShapes_, userShapes_;  // Embree primID → Scene shape index
  std::vector<float> vertices_;                        // 3 float3 per triangle, relative to centre_
  std::vector<uint32_t> indices_;
  std::vector<float> meshVertices_;                    // the scene mesh's vertices, relative to centre_
  std::atomic<int64_t> embreeBytes_{0};  // from Embree's memory monitor
};

}  // namespace candela
