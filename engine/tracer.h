// The ray tracer: octree, light sources and the Monte Carlo irradiance estimator at sensor points
// (direct light from sampled sources + stratified cosine-weighted hemisphere, the paper's eq. 3,
// with path-traced interreflection up to a bounce limit).
#pragma once

#include "base/rng.h"
#include "engine/irradiance_cache.h"
#include "engine/lights.h"
#include "engine/octree.h"
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
  double illuminanceLux() const { return illuminanceFromIrradiance(irradiance); }
  double standardErrorLux() const;
};

// Which ray-query structure a tracer builds: Embree (the default: 3.4× the octree's rays/s on
// 10⁵ triangles, docs/performance.md) or the paper's octree.
enum class AcceleratorKind { kEmbree, kOctree };
// Parses "embree" or "octree"; throws std::invalid_argument otherwise.
AcceleratorKind parseAccelerator(const std::string& s);
std::unique_ptr<RayAccelerator> makeAccelerator(const Scene& scene, AcceleratorKind kind);

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
  void skyCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                       const SkyPatches& patches, double* direct, double* indirect,
                       bool directByPatch = true) const;

  // Interreflected illuminance in lux at p from each sun direction (unit, model frame) per lux
  // of direct normal illuminance, added to indirect[] (one per sun): the light of the suns
  // reaching every diffuse vertex of the paths, one shadow ray per sun per vertex. The sun's
  // direct light at p is not included.
  void sunCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                       const std::vector<Vec3>& sunDirsModel, double* indirect) const;

  // Irradiance-cache support (engine/irradiance_cache.cpp).
  // The first diffuse hits, on surfaces the cache serves, of the initial hemisphere cells that
  // irradiance(p, n, pointIndex, s, cache) will trace (same directions), appended to out.
  void cacheQueries(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                    std::vector<CacheQuery>& out) const;
  // Harmonic mean distance (m) to the surfaces seen from q over `rays` stratified cosine rays
  // (Ward et al. 1988's R_i); infinity when every ray escapes.
  double harmonicMeanDistance(const CacheQuery& q, int rays, Rng& rng) const;
  // Fills r.e, its gradients and variance from s.cache.recordSamples hemisphere rays, random
  // stream `stream`; r lies at diffuse bounce `level` (1: a sensor ray's first hit). The first
  // diffuse hits of its rays take their indirect irradiance from `deeper` when given (a frozen
  // second-level cache); beyond, bounces are path traced with Russian roulette (the closure).
  void computeRecord(IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                     const IrradianceCache* deeper = nullptr, int level = 1) const;
  // The first diffuse hits, on surfaces the cache serves, of the hemisphere rays that
  // computeRecord(r, stream, s, ...) will trace (same directions), appended to out.
  void recordQueries(const IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                     std::vector<CacheQuery>& out) const;
  // Whether a record may serve point p (normal n) on `shape`: the segment between the two
  // points, each lifted off its surface, meets no shape but theirs.
  bool cacheVisible(const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r) const;
  // Whether the cache serves diffuse reflection off material m (opaque, diffusely reflecting).
  static bool cacheable(const Material& m);

  // Fraction of light (RGB) that passes from o along unit dir over distance tMax: 0 behind an
  // opaque surface, glass and trans transmit their specular part. Shapes skipA/skipB are ignored.
  Rgb transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB) const;

  // Radiance arriving at o from direction -dir, i.e. along a ray leaving o in direction dir.
  // Sampled sources are counted only when countSources is true (after specular reflection or for
  // camera rays); diffuse paths get them by explicit source sampling instead.
  Rgb radiance(const Vec3& o, const Vec3& dir, uint32_t skip, bool countSources, Rng& rng,
               const TraceSettings& s) const;

  // Rays cast so far (nearest-hit and shadow rays, each query of the accelerator counted once;
  // a shadow ray walked through glass counts each surface met). Complete after the calls of
  // computeIrradiance have returned.
  uint64_t raysTraced() const;

  const Scene& scene() const { return scene_; }
  const RayAccelerator& accelerator() const { return *accel_; }
  const std::vector<Light>& lights() const { return lights_; }

  // Offset of a ray origin from the surface it leaves, in metres (see docs/engine.md).
  static double originOffset(const Vec3& p);

 private:
  // Direct irradiance at p (normal n) from every sampled source with k stratified samples each;
  // adds the variance of its photopic value to *variance when given.
  // With a sky, k sky samples by luminance are taken too, weighted against the cosine-sampled
  // rays that accompany them by the power heuristic (Veach 1997) with misRatio = k / (number of
  // cosine-sampled rays).
  Rgb directIrradiance(const Vec3& p, const Vec3& n, int k, uint32_t skip, Rng& rng, double* variance,
                       double misRatio) const;
  // Path-traced radiance; `diffuse` counts diffuse reflections so far; the first diffuse vertex
  // takes `split` stratified continuations.
  // misCosPdf: density (per sr) of the cosine sampling that drew dir, for the sky's MIS weight
  // (0: not cosine-sampled, the sky counts in full); misRatio as for directIrradiance.
  // cache: at the diffuse vertex diffuse == cache->depth of a cacheable material, the indirect
  // irradiance comes from it (CacheUse records the error share and misses). firstHitT: the
  // distance to the first surface met (infinity when none). mirrorsBefore: flat mirrors met since
  // the last diffuse vertex, before a trans surface's specular transmission continued the path.
  struct CacheUse {
    const IrradianceCache* cache = nullptr;
    int depth = 0;  // the diffuse count at which the cache serves (0: sensor rays' first hits)
    // Each record's share of each cell's radiance (beta·ρ/π·normalised weight·lookup vector).
    CacheTally tally;
    IrradianceCache::Used scratch;
    int misses = 0;
  };
  Rgb pathRadiance(const Vec3& o, const Vec3& dir, uint32_t skip, bool countSources, Rng& rng,
                   const TraceSettings& s, int diffuse, int split, double misCosPdf = 0.0,
                   double misRatio = 1.0, CacheUse* cache = nullptr, double* firstHitT = nullptr,
                   int mirrorsBefore = 0) const;
  // Light leaving a diffuse vertex at x (facing normal nf) towards the incoming ray. The incoming
  // ray's countSources, MIS density and ratio and flat mirrors met carry on through specular
  // transmission (trans), which keeps its direction.
  Rgb diffuseVertex(const Vec3& x, const Vec3& inDir, const Vec3& nf, double off, uint32_t flatSkip, const Material& m, Rng& rng,
                    const TraceSettings& s, int diffuse, int split, bool countSources, double misCosPdf,
                    double misRatio, int mirrorsMet) const;
  // One source's irradiance at p with k samples (ratio estimator on its closed form where there
  // is one); visibility(LightSample, lightShape) → RGB transmittance.
  template <class Visibility>
  Rgb lightEstimate(const Light& light, const Vec3& p, const Vec3& n, int k, Rng& rng, double* variance,
                    const Visibility& visibility) const;
  // Irradiance from the images of the sampled sources in flat mirrors (virtual sources).
  Rgb mirrorIrradiance(const Vec3& p, const Vec3& n, int k, uint32_t skip, Rng& rng, double* variance) const;
  // One sample of the glossy (Ward) lobe of m leaving x: its reflected radiance estimate.
  Rgb glossyBounce(const Vec3& x, const Vec3& inDir, const Vec3& nf, double off, uint32_t flatSkip,
                   const Material& m, Rng& rng, const TraceSettings& s, int diffuse) const;
  // The cacheable first hits of mTheta × nPhi stratified cosine rays from o (the strata in
  // order, jittered by dirRng), appended to out; shared by cacheQueries and recordQueries.
  void hemisphereCacheQueries(const Vec3& o, const Frame& frame, int mTheta, int nPhi, uint32_t skip, Rng& dirRng,
                              std::vector<CacheQuery>& out) const;
  // Radiance of the sky/distant sources seen along an escaping ray.
  Rgb distantRadiance(const Vec3& dir, bool countSources, double misCosPdf, double misRatio) const;

  void countRay() const;
  void flushRays() const;

  const Scene& scene_;
  std::unique_ptr<RayAccelerator> accel_;
  mutable std::atomic<uint64_t> rays_{0};
  std::vector<Light> lights_;
  bool hasTransmitters_ = false;
  std::vector<uint32_t> mirrors_;      // flat mirror shapes (virtual sources)
  std::vector<char> isMirrorImage_;    // per shape: a flat mirror with virtual sources
};

}  // namespace candela
