// The ray tracer's facade: the scene, its ray-query structure, the sources sampled explicitly and
// the count of rays cast. The estimators work through it: the sensor estimator
// (engine/irradiance_estimator.h: direct light from sampled sources + stratified cosine-weighted
// hemisphere, the paper's eq. 3, with path-traced interreflection up to a bounce limit), the
// integrators (engine/integrator_direct.h, engine/integrator_path.h) and the irradiance cache's
// builder (engine/cache_builder.h).
#pragma once

#include "base/rng.h"
#include "engine/antimatter.h"
#include "engine/cache_builder.h"
#include "engine/irradiance_cache.h"
#include "engine/lights.h"
#include "engine/octree.h"
#include "engine/portals.h"
#include "engine/response.h"
#include "engine/trace_settings.h"
#include "engine/scene.h"
#include "photometry/sky_patches.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace candela {


// Irradiance estimate at a point: RGB irradiance in W/m² and the variance of its photopic value
// (from the estimator's own sample variance; stratification makes it an upper bound).
struct IrradianceEstimate {
  Rgb irradiance{0.0};
  double variancePhotopic = 0.0;
  // The part of variancePhotopic due to the irradiance cache's records (cache method): the
  // cache is frozen, so every batch of a point shares it and more batches do not reduce it.
  double varianceRecordsPhotopic = 0.0;
  bool withoutCache = false;  // cache method: the point was estimated by the path method instead
  double illuminanceLux() const { return illuminanceFromIrradiance(irradiance); }
  double standardErrorLux() const;
};

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

  // Irradiance on the side of unit normal n at point p. `pointIndex` selects the random stream,
  // so the result depends only on (seed, pointIndex), never on threads.
  IrradianceEstimate irradiance(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s) const;
  // The same with the indirect irradiance at the first diffuse hits of the hemisphere rays taken
  // from a frozen cache (Method::kCache); a hit no record covers is path traced instead.
  IrradianceEstimate irradiance(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                                const IrradianceCache* cache) const;
  // The quantity a sensor response measures at p (engine/response.h: cylindrical,
  // semi-cylindrical, hemispherical or planar illuminance), in the same units; cache as above.
  IrradianceEstimate irradiance(const Vec3& p, const Response& response, uint64_t pointIndex, const TraceSettings& s,
                                const IrradianceCache* cache = nullptr) const;

  // Daylight coefficients at a sensor (docs/annual.md): the illuminance in lux that a luminance
  // of 1 cd/m² over each patch of `patches` (index 0 the ground) gives at p, added to direct[]
  // (seen from p with no reflection between: straight through thin glass and trans) and
  // indirect[] (after any reflection), each patches.count() long. The same estimator as
  // irradiance() — sky sampled by s.lightSamples importance samples (MIS) and by the stratified
  // hemisphere, interreflection path traced — with the method forced to path and no adaptive
  // supersampling. The scene needs a sky (its model only guides sampling; a uniform sky suits
  // every patch); its other sources add nothing to the tallies.
  // directByPatch: the direct part is sampled patch by patch (s.lightSamples stratified shadow
  // rays in each, 4× for the ground), so that every patch's share is known alike; false tallies
  // the point estimator's own sky samples instead (the same random numbers as irradiance(), for
  // tests).
  // 8 parameters: the public daylight-coefficient entry point, each one a separate input.
  void skyCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                       const SkyPatches& patches, double* direct, double* indirect,
                       bool directByPatch = true) const;

  // Interreflected illuminance in lux at p from each sun direction (unit, model frame) per lux
  // of direct normal illuminance, added to indirect[] (one per sun): the light of the suns
  // reaching every diffuse vertex of the paths, one shadow ray per sun per vertex. The sun's
  // direct light at p is not included.
  void sunCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                       const std::vector<Vec3>& sunDirsModel, double* indirect) const;

  // Whether the cache serves diffuse reflection off material m (opaque, diffusely reflecting).
  static bool cacheable(const Material& m);

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

  // Radiance arriving at o from direction -dir, i.e. along a ray leaving o in direction dir.
  // Sampled sources are counted only when countSources is true (after specular reflection or for
  // camera rays); diffuse paths get them by explicit source sampling instead.
  Rgb radiance(const Vec3& o, const Vec3& dir, uint32_t skip, bool countSources, Rng& rng,
               const TraceSettings& s) const;

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
