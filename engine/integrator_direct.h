// Direct light from the sources sampled explicitly (Tracer::sources): per-light ratio estimators
// at sensors, one light chosen by importance per sample at path vertices
// (engine/light_selection.h), the sources' images in flat mirrors (virtual sources), and the sky
// by importance sampling of its luminance, weighted against cosine sampling by the power
// heuristic (Veach 1997, "Robust Monte Carlo methods for light transport simulation", §9.2).
#pragma once

#include "engine/response.h"
#include "engine/trace_context.h"

#include <cstdint>

namespace candela {

// A point receiving light: position, unit normal of the side that receives, and the flat shape
// it lies on (skipped by its shadow rays), or kNoShape. A sensor of another quantity than planar
// illuminance (engine/response.h) gives its response, n then its axis: the sources' light is
// weighted by w(ω) instead of the cosine, the portals are seen from the axis.
// A surface whose sampled sources' light depends on its direction (MaterialFamily::
// directionalSources: Radiance's dirbrdf): the light L arriving along unit dir counts as
// L cos ι · source(dir, omega) from a sampled source (omega its solid angle from the point), and
// L cos ι · sky(dir) from the sky and ground, instead of L cos ι. Path vertices only.
class LightFilter {
 public:
  virtual Rgb source(const Vec3& dir, double omegaSr) const = 0;
  virtual Rgb sky(const Vec3& dir) const = 0;
  // Whether the sky is sampled here at all (false: it arrives by the paths leaving the point).
  virtual bool takesSky() const { return true; }

 protected:
  ~LightFilter() = default;
};

struct Receiver {
  Vec3 p{0.0};
  Vec3 n{0.0, 0.0, 1.0};
  uint32_t skip = kNoShape;
  const Response* response = nullptr;  // a non-planar response, or none (planar on n)
  const LightFilter* filter = nullptr;  // weights by direction (a path vertex), or none
  // The antimatter clip set of the point (engine/antimatter.h), which its shadow rays start
  // with; nullptr: empty (sensors).
  const ClipState* clip = nullptr;
};

// Direct irradiance at `at` from every sampled source with k stratified samples each; adds the
// variance of its photopic value to *variance when given (sensors; nullptr at path vertices,
// which choose one light per sample instead). With a sky, k sky samples by luminance are taken
// too, and where portals are seen (engine/portals.h) kSensorPortalFactor·k (sensors) or k (path
// vertices) samples through them, all weighted against the cosine-sampled rays that accompany
// them by the power heuristic with misRatio = k / (number of cosine-sampled rays). Reports to
// ctx.tally's sky bins and suns.
// Portal samples per sky sample at a sensor (path vertices take one each): at normal quality
// 4 × 64 shadow rays beside 2048 hemisphere rays, where portals are seen (docs/daylight.md#portals).
constexpr int kSensorPortalFactor = 4;

Rgb directIrradiance(TraceContext& ctx, const Receiver& at, int k, double* variance, double misRatio);

// How an escaping ray was drawn, for the sky's MIS weight: the density (per sr) of the cosine
// sampling that drew it (0: not cosine-sampled, the sky counts in full), misRatio as for
// directIrradiance, and the receiver the ray left (point, unit normal), on which the portals'
// density depends.
struct SkyMis {
  double cosPdf = 0.0;
  double ratio = 1.0;
  double portalRatio = 1.0;  // (portal samples) / (cosine rays) at the receiver
  Vec3 origin{0.0};
  Vec3 normal{0.0, 0.0, 1.0};
};

// The sky strategies' terms of the power heuristic for direction dir at receiver (p, n), per
// unit cosine-ray density (docs/daylight.md#portals): the sky's luminance density p_s times
// misRatio, and, when a portal is above the receiver's horizon, the portals' density p_P times
// portalRatio (portal samples / cosine rays) times a boost (kPortalBoost in the .cpp: inside a
// small opening the portal samples then take nearly all the weight, where the stratified cosine
// rays' error sits in the strata the opening's edge cuts). The three weights sum to 1 for every
// direction, so the estimate stays unbiased whatever the portals.
struct SkyMisTerms {
  double ps = 0.0, pp = 0.0;  // the densities (per sr): sky by luminance, portals
  double sky = 0.0;           // misRatio · p_s
  double portal = 0.0;        // boost · portalRatio · p_P (0 without portals)
};
SkyMisTerms skyMisTerms(const Tracer& tracer, const Vec3& dir, const Vec3& p, const Vec3& n, double misRatio,
                        double portalRatio);

// The power-heuristic weight of a cosine-sampled escaping ray along dir (sky or ground) against
// the sky samples; 1 when mis.cosPdf is 0.
double skyMisWeight(const Tracer& tracer, const Vec3& dir, const SkyMis& mis);

// Radiance of the sky, the ground and the distant sources seen along an escaping ray from origin
// in direction dir, the sky and ground weighted by skyMisWeight; a distant source's function
// pattern evaluated where the ray meets it (kDistantPointM along it).
Rgb distantRadiance(TraceContext& ctx, const Vec3& origin, const Vec3& dir, bool countSources, const SkyMis& mis);

}  // namespace candela
