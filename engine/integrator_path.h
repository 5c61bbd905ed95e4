// Path-traced radiance: specular and pass-through events followed iteratively (engine/materials.h),
// and at a diffuse vertex the sampled sources' light (engine/integrator_direct.h) plus a few
// continuations chosen by Russian roulette on the albedo; at the vertex a frozen irradiance cache
// serves, its interpolated indirect irradiance instead (Ward, Rubinstein & Clear 1988).
#pragma once

#include "engine/irradiance_cache.h"
#include "engine/trace_context.h"

#include <cstdint>

namespace candela {

// A path's state as a ray leaves a vertex (or the sensor, the camera).
struct PathState {
  uint32_t skip = kNoShape;   // the flat shape the ray leaves (not to be hit again), or kNoShape
  int diffuse = 0;      // diffuse reflections so far
  int split = 1;        // continuations the next diffuse vertex takes (stratified)
  // Flat mirrors met since the last diffuse vertex, carried through a trans surface's specular
  // transmission (which keeps the direction).
  int mirrorsMet = 0;
  // Whether sampled sources met count: true after specular reflection and for camera rays; a
  // diffuse vertex samples them itself, so its continuations do not count them.
  bool countSources = false;
  // The ray carries light to a receiver (sensor, record, diffuse or glossy vertex) rather than
  // to an eye: a glow of negative radius sends nothing along it (Radiance's ray.1 "Glow").
  bool lighting = false;
  // The antimatter clip set the ray carries (engine/antimatter.h): empty from sensors and the
  // camera, as Radiance's primary rays; reflected, scattered and straight-on rays inherit it.
  // Beside the flags, in what was padding: the state is no larger than without it.
  ClipState clip;
  // Scattering vertices (BSDF) met in a row just before this ray (0 after any other vertex), in
  // the padding after the clip set: the state stays two cache lines.
  uint8_t scatterRun = 0;
  // Density (per sr) of the cosine sampling that drew the ray, for the sky's MIS weight
  // (0: not cosine-sampled, the sky counts in full); misRatio as for directIrradiance.
  double misCosPdf = 0.0;
  double misRatio = 1.0;
  double misPortalRatio = 1.0;  // (portal samples) / (cosine rays), for the portals' MIS term
  // The receiver the cosine-sampled ray left (point, unit normal): the portals' density in the
  // MIS weight depends on it (engine/portals.h).
  Vec3 misOrigin{0.0};
  Vec3 misNormal{0.0, 0.0, 1.0};
  // Where the sources were sampled that this ray must not count again (while countSources is
  // false): the receiver point of the last diffuse vertex or sensor, exactly as passed to
  // directIrradiance, so that a glow met is left out exactly when glowSampledFrom sampled it.
  Vec3 litPoint{0.0};
};
static_assert(sizeof(PathState) == 128, "a path's state stays two cache lines (ClipState in the padding)");

// A frozen cache serving the diffuse vertex at diffuse count `depth`, and what the lookups used
// (for error bars): each record's share of each cell's radiance (beta·ρ/π·normalised
// weight·lookup vector). One per top-level call.
struct CacheUse {
  const IrradianceCache* cache = nullptr;
  int depth = 0;  // the diffuse count at which the cache serves (0: sensor rays' first hits)
  CacheTally tally;
  IrradianceCache::Used scratch;
};

// Radiance arriving at origin along -direction. cache: at the diffuse vertex st.diffuse ==
// cache->depth of a cacheable material, the indirect irradiance comes from it. firstHitT: the
// distance to the first surface met (infinity when none).
Rgb pathRadiance(TraceContext& ctx, const Vec3& origin, const Vec3& direction, PathState st,
                 CacheUse* cache = nullptr, double* firstHitT = nullptr);

// Radiance arriving at o from direction -dir, i.e. along a ray leaving o in direction dir, as a
// top-level call (its own context). Sampled sources are counted only when countSources is true
// (after specular reflection or for camera rays); diffuse paths get them by explicit source
// sampling instead.
Rgb rayRadiance(const Tracer& tracer, const Vec3& o, const Vec3& dir, uint32_t skip, bool countSources, Rng& rng,
                const TraceSettings& s);

}  // namespace candela
