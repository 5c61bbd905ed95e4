// The ray-query service: the scene, its ray-query structure, the sources sampled explicitly, the
// openings the sky is sampled through, straight (shadow) rays through transmitting surfaces and
// the count of rays cast. It estimates nothing: the estimators query it and are called directly
// (engine/irradiance_estimator.h: the sensor estimator, direct light + the paper's stratified
// hemisphere, eq. 3; engine/integrator_direct.h, engine/integrator_path.h; the daylight
// coefficients, engine/daylight_coefficients.h; the irradiance cache's builder,
// engine/cache_builder.h).
#pragma once

#include "base/rng.h"
#include "engine/antimatter.h"
#include "engine/lights.h"
#include "engine/octree.h"
#include "engine/portals.h"
#include "engine/trace_settings.h"
#include "engine/scene.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace candela {

// Which ray-query structure a tracer builds: Embree (the default: 3.4× the octree's rays/s on
// 10⁵ triangles, docs/performance.md) or the paper's octree.
enum class AcceleratorKind { kEmbree, kOctree };
// Parses "embree" or "octree"; throws std::invalid_argument otherwise.
AcceleratorKind parseAccelerator(const std::string& s);
std::unique_ptr<RayAccelerator> makeAccelerator(const Scene& scene, AcceleratorKind kind);

class PatternEvaluator;

class Tracer {
 public:
  // Traces with the default accelerator, or the one named.
  explicit Tracer(const Scene& scene, AcceleratorKind kind = AcceleratorKind::kEmbree);
  // Traces with the paper's octree built with `octree` options.
  Tracer(const Scene& scene, OctreeOptions octree);
  // Traces with a given accelerator built over the same scene.
  Tracer(const Scene& scene, std::unique_ptr<RayAccelerator> accelerator);
  // The tracer keeps a reference to the scene: a temporary would dangle.
  explicit Tracer(Scene&&, AcceleratorKind = AcceleratorKind::kEmbree) = delete;
  Tracer(Scene&&, OctreeOptions) = delete;
  Tracer(Scene&&, std::unique_ptr<RayAccelerator>) = delete;

  // Fraction of light (RGB) that passes from o along unit dir over distance tMax: 0 behind an
  // opaque surface, glass and trans transmit their specular part. Shapes skipA/skipB are ignored.
  Rgb transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB) const;
  // The same within a top-level call: the rays cast are added to `rays` (the call's count,
  // TraceContext::rays), not yet to the total.
  Rgb transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB,
                    uint64_t& rays) const;
  // The same, and the surface id of the first `glass` surface the ray crosses from o (kNoShape:
  // none, or the ray is blocked) in firstGlass: which window a beam came through (the annual
  // study's window groups, docs/annual.md). The transmittance is the other overloads', bit for bit.
  // Glass and trans modified by function patterns are evaluated by `patterns` (the caller's
  // evaluator; nullptr: one of the call's own, made when needed).
  // clip: the antimatter clip set of the point the ray leaves (engine/antimatter.h; nullptr:
  // empty, a sensor's).
  // 9 parameters: the ray, its interval, its two skipped shapes, its count and first glass, and
  // the state it carries (patterns' evaluator, clip set).
  Rgb transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB,
                    uint64_t& rays, uint32_t& firstGlass, PatternEvaluator* patterns = nullptr,
                    const ClipState* clip = nullptr) const;
  // The scene has function patterns (engine/materials/pattern_hook.h).
  bool hasPatterns() const { return scene_.functions != nullptr; }
  // The scene has antimatter: rays are walked through the clip steps (engine/antimatter.h).
  bool hasAntimatter() const { return hasAntimatter_; }

  // Rays cast so far (nearest-hit and shadow rays, each query of the accelerator counted once;
  // a shadow ray walked through glass counts each surface met). Complete after the calls that
  // cast them have returned.
  uint64_t raysTraced() const { return rays_.load(std::memory_order_relaxed); }
  // Adds the rays a top-level call cast (TraceContext) to the total.
  void addRays(uint64_t n) const { rays_.fetch_add(n, std::memory_order_relaxed); }

  const Scene& scene() const { return scene_; }
  const RayAccelerator& accelerator() const { return *accel_; }
  // The lights and mirror images the direct integrator samples.
  const SampledSources& sources() const { return sources_; }
  // The openings the sky is sampled through (declared and found; engine/portals.h). Empty
  // without a sky.
  const PortalSet& portals() const { return portals_; }

  // Offset of a ray origin from the surface it leaves, in metres (see docs/engine.md).
  static double originOffset(const Vec3& p);

 private:
  const Scene& scene_;
  std::unique_ptr<RayAccelerator> accel_;
  mutable std::atomic<uint64_t> rays_{0};
  SampledSources sources_;
  PortalSet portals_;
  bool hasTransmitters_ = false;
  bool hasAntimatter_ = false;
};

}  // namespace candela
