#include "engine/integrator_direct.h"

#include "engine/light_selection.h"
#include "engine/radiance/sky.h"
#include "engine/sampling.h"
#include "engine/sky_tally.h"
#include "photometry/site.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The portal strategy's sample count in the power heuristic is taken kPortalBoost times its
// real one: its samples see a smooth integrand where the opening matches the portal, while the
// stratified cosine rays' error sits in the strata its edge cuts, which the heuristic's counts
// do not see. Measured on the four aperture cases at normal quality (docs/daylight.md#portals):
// boost 1, 4, 16 give 0.10–0.31 %, 0.04–0.34 %, 0.04–0.36 % rms error (4 portal samples per
// sky sample). Any positive boost keeps the weights a partition of unity: unbiased.
constexpr double kPortalBoost = 4.0;

// Variance of a sum of stratified terms z, strata collapsed in pairs (Cochran, "Sampling
// Techniques", 5A.12; derivation: docs/estimator.md#ratio-estimator).
double collapsedPairs(const std::vector<double>& z, int kk) {
  double v = 0.0;
  for (int i = 0; i + 1 < kk; i += 2) v += (z[i] - z[i + 1]) * (z[i] - z[i + 1]);
  if (kk % 2 == 1) v += 2.0 * z[kk - 1] * z[kk - 1];  // an unpaired stratum: as if iid, doubled
  return v;
}

// One sampled source's irradiance at `at` (at.skip unused), k stratified samples;
// visibility(ls, lightShape) gives the RGB transmittance of sample ls (a shadow ray, or the path
// through a mirror). With a closed form for the unoccluded irradiance E_u, the samples only
// estimate the visible fraction: E = E_u · Σ f V / Σ f, f = w cos ι. This ratio estimator is
// exact when the source is wholly visible, exactly 0 when wholly hidden (no light leaks), and its
// bias falls as 1/k. Without a closed form: E = mean(f V). A light's function pattern P at each
// sample multiplies V (the closed form is the unpatterned source's, the samples its patterned
// share: exact for a constant pattern).
// About 90 lines: the sampling loop and the variance share its per-sample sums; split, they
// would pass a dozen of them.
template <class Visibility>
Rgb lightEstimate(TraceContext& ctx, const Light& light, const Receiver& at, int k, double* variance,
                  const Visibility& visibility) {
  const Scene& scene = ctx.tracer.scene();
  const Vec3& p = at.p;
  const Vec3& n = at.n;
  LightScratch& sc = ctx.light;
  const Strata2D strata(k);
  // A non-planar response has no closed form for an area source: the plain mean of its samples
  // (unbiased) estimates it; a point luminaire is still one point, one shadow ray.
  const Response* response = at.response;
  Rgb exact(0.0);
  const bool haveExact = !response && unoccludedIrradiance(light, scene, p, n, exact, &sc.clipped);
  if (haveExact && photopic(exact) <= 0.0) return Rgb(0.0);  // the source cannot reach this side
  // Polygon sources are sampled over their part above the receiver's horizon, so that every
  // sample tells about visibility.
  const bool clippedPolygon = haveExact && light.kind == Light::Kind::kArea && !light.outline.empty();
  if (clippedPolygon) {
    sc.tris = triangulatePolygon(sc.clipped, scene.shapes[light.shape].n);
    sc.cumulative.clear();
    double acc = 0.0;
    for (const auto& t : sc.tris) {
      acc += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
      sc.cumulative.push_back(acc);
    }
  }
  Rgb sumFvc(0.0), sumFc(0.0), sumRest(0.0);
  double yF2 = 0.0, yF2V = 0.0, yF2V2 = 0.0, yFc = 0.0, yRest = 0.0, yRest2 = 0.0;
  const uint32_t lightShape = light.ownShape;
  // A point luminaire (no opening; the only luminaire with a closed form) is one point: one
  // shadow ray says all there is. A luminaire with an opening is sampled over it at every
  // distance (lights.cpp), k stratified points, by the plain mean below.
  const bool point = light.kind == Light::Kind::kLuminaire &&
                     (response ? scene.luminaires[light.luminaire].sizeM() <= 0.0 : haveExact);
  const int kk = point ? 1 : k;
  // Per-stratum terms for the variance (zero where a sample tells nothing).
  if (variance) {
    sc.zRatio.assign(kk, 0.0);
    sc.zRest.assign(kk, 0.0);
    sc.fyS.assign(kk, 0.0);
    sc.vyS.assign(kk, 0.0);
  }
  for (int i = 0; i < kk; ++i) {
    const Vec2 u = strata.sample(i, ctx.rng);
    LightSample ls;
    const bool ok = clippedPolygon ? sampleClippedPolygon(light, sc.tris, sc.cumulative, p, u.x, u.y, ls, ctx.patternsIfAny())
                                   : sampleLight(light, scene, p, u.x, u.y, ls, ctx.patternsIfAny());
    if (!ok) continue;
    const double cosI = response ? response->weight(ls.dir) : glm::dot(n, ls.dir);
    if (cosI <= 0.0) continue;
    const Rgb f = ls.weight * cosI;
    // Nothing sent this way (a downlight seen from above its opening): no shadow ray; the sums
    // would add 0.
    if (f.x <= 0.0 && f.y <= 0.0 && f.z <= 0.0) continue;
    const Rgb v = ls.pattern * visibility(ls, lightShape);  // a pattern counts as visibility does
    const double c = haveExact ? 1.0 : 0.0;
    sumFvc += f * v * c;
    sumFc += f * c;
    sumRest += f * v * (1.0 - c);
    const double fy = photopic(f) * c, vy = photopic(f * v) / std::max(photopic(f), 1e-300);
    yF2 += fy * fy;
    yF2V += fy * fy * vy;
    yF2V2 += fy * fy * vy * vy;
    yFc += fy;
    const double ry = photopic(f * v) * (1.0 - c);
    yRest += ry;
    yRest2 += ry * ry;
    if (variance) {
      sc.fyS[i] = fy;
      sc.vyS[i] = vy;
      sc.zRest[i] = ry;
    }
  }
  Rgb e = sumRest / static_cast<double>(kk);
  if (haveExact) {
    // No informative sample (numerically degenerate): claim nothing rather than leak light.
    for (int ch = 0; ch < 3; ++ch) e[ch] += sumFc[ch] > 0.0 ? exact[ch] * sumFvc[ch] / sumFc[ch] : 0.0;
  }
  if (variance && kk > 1) {
    // Delta-method variance of the ratio, strata collapsed in pairs
    // (derivation: docs/estimator.md#ratio-estimator).
    if (yFc > 0.0) {
      const double ratio = (yF2V > 0.0 || yF2 > 0.0) ? photopic(sumFvc) / yFc : 0.0;
      for (int i = 0; i < kk; ++i) sc.zRatio[i] = sc.fyS[i] * (sc.vyS[i] - ratio);
      *variance += photopic(exact) * photopic(exact) * collapsedPairs(sc.zRatio, kk) / (yFc * yFc);
    }
    if (yRest > 0.0) *variance += collapsedPairs(sc.zRest, kk) / (static_cast<double>(kk) * kk);
  }

  return e;
}

// Irradiance from the images of the sampled sources in flat mirrors (virtual sources).
Rgb mirrorIrradiance(TraceContext& ctx, const Receiver& at, int k, double* variance) {
  // A flat mirror shows each source as an image behind it: the light reaching p by one
  // reflection is the light the source would give at p's mirror image p' (normal n'), passed
  // through the mirror's outline and reflectance. So the source is sampled from p' (with the
  // closed form there, as a ratio estimator), and each sample's visibility is the real path:
  // p to the mirror (which must be the first surface met) and on to the source.
  const Scene& scene = ctx.tracer.scene();
  const Vec3& p = at.p;
  const Vec3& n = at.n;
  const uint32_t skip = at.skip;
  Rgb total(0.0);
  for (uint32_t ms : ctx.tracer.sources().mirrors) {
    const Shape& mirror = scene.shapes[ms];
    const Vec3 nm = mirror.n, q = mirror.a;
    const double dp = glm::dot(p - q, nm);
    if (std::abs(dp) < 1e-12) continue;
    const Vec3 pi = p - 2.0 * dp * nm, ni = n - 2.0 * glm::dot(n, nm) * nm;
    const Rgb colour = scene.materials[mirror.material].color;
    const Vec3 side = dp > 0.0 ? nm : -nm;
    // A response seen in the mirror: w at the real arrival direction, the image's reflected.
    const Response mirrored = at.response ? at.response->mirrored(nm) : Response{};
    const Receiver image{pi, ni, skip, at.response ? &mirrored : nullptr, nullptr, at.clip};
    for (const Light& light : ctx.tracer.sources().lights) {
      // Glows are not sampled in mirrors: paths count them there (pathRadiance).
      if (light.glow || (light.kind == Light::Kind::kArea && light.shape == ms)) continue;
      total += colour * lightEstimate(ctx, light, image, k, variance, [&](const LightSample& ls, uint32_t lightShape) {
        const Vec3 dir = ls.dir - 2.0 * glm::dot(ls.dir, nm) * nm;
        // Both legs pass transmitting surfaces (glass, trans, illum without alternate) as shadow
        // rays do, so that a path meeting them before the mirror does not count the image again
        // (pathRadiance: the first mirror after a diffuse vertex is an image).
        double tm = 0.0;
        if (!intersectShape(mirror, scene.vertices, p, dir, 0.0, ls.distance, tm)) return Rgb(0.0);
        const Vec3 x = p + tm * dir;
        const double rest = std::isinf(ls.distance) ? kInf : (ls.distance - tm) * (1.0 - 1e-9);
        if (rest <= 0.0) return Rgb(0.0);
        const Rgb toMirror = ctx.transmittance(p, dir, tm * (1.0 - 1e-9), skip, ms, at.clip);
        if (photopic(toMirror) <= 0.0) return Rgb(0.0);
        const Rgb weight = at.filter ? at.filter->source(dir, ls.solidAngleSr) : Rgb(1.0);
        return weight * toMirror *
               ctx.transmittance(x + Tracer::originOffset(x) * side, ls.dir, rest, ms, lightShape, at.clip);
      });
    }
  }
  return total;
}

// Sun coefficients (sunCoefficients): each sun's light at a path vertex, one shadow ray
// (a point: its disc matters for the direct sun only).
void tallySuns(TraceContext& ctx, const Receiver& at) {
  SkyTally& tally = *ctx.tally;
  const std::vector<Vec3>& suns = *tally.suns;
  for (size_t j = 0; j < suns.size(); ++j) {
    const double cosI = glm::dot(at.n, suns[j]);
    if (cosI <= 0.0) continue;
    const Rgb weight = at.filter ? at.filter->source(suns[j], 0.0) : Rgb(1.0);
    tally.sunIndirect[j] +=
        photopic(tally.outer * weight * ctx.transmittance(at.p, suns[j], kInf, at.skip, kNoShape, at.clip)) * cosI;
  }
}

// Luminance (cd/m²) of the sky, or of the ground below the horizon, towards model direction dir.
double skyOrGroundLuminance(const SkyDome& sky, const Vec3& dir) {
  if (dir.z > 0.0) return sky.model->luminance(modelToTrue(dir, sky.northDeg));
  if (sky.groundFunction)
    return std::max(0.0, sky.groundFactorCdM2 * sky.groundFunction->value(modelToTrue(dir, sky.northDeg)));
  return sky.groundLuminanceCdM2;
}

// The sky by importance sampling of its luminance (k samples) and, when portals are above the
// receiver's horizon, uniformly in the portals' solid angle (engine/portals.h; kPortalFactor·k
// samples at a sensor, k at a path vertex): three strategies with the cosine rays, weighted by
// the power heuristic (Veach 1997, §9.2) with the terms of skyMisTerms. A sample of strategy i
// adds w_i f / (n_i p_i). Below the horizon only portal samples arrive (the ground through a
// window), weighted against the cosine rays the same way.
Rgb skyIrradiance(TraceContext& ctx, const Receiver& at, int k, double* variance, double misRatio) {
  const SkyDome& sky = *ctx.tracer.scene().sky;
  const PortalSet& portals = ctx.tracer.portals();
  SkyTally* tally = ctx.tally;
  const bool atPathVertex = variance == nullptr;
  PortalView& view = ctx.light.portals;
  bool usePortals = false;
  if (!portals.empty()) {
    portals.view(at.p, at.n, view);
    usePortals = view.total > 0.0;
  }
  const int kSky = k, kPortal = usePortals ? (atPathVertex ? k : kSensorPortalFactor * k) : 0;
  const double portalRatio = misRatio * kPortal / k;
  const Strata2D skyStrata(kSky), portalStrata(std::max(1, kPortal));
  Rgb sum(0.0);
  double y1[2] = {0.0, 0.0}, y2[2] = {0.0, 0.0};
  for (int i = 0; i < kSky + kPortal; ++i) {
    const bool throughPortal = i >= kSky;
    Vec3 dir(0.0);
    if (throughPortal) {
      const Vec2 u = portalStrata.sample(i - kSky, ctx.rng);
      if (!portals.sample(view, at.p, u.x, u.y, dir)) continue;
    } else {
      const Vec2 u = skyStrata.sample(i, ctx.rng);
      double ps = 0.0;
      dir = trueToModel(sky.model->sample(u.x, u.y, &ps), sky.northDeg);
      if (ps <= 0.0) continue;
    }
    // A response's weight and the density its hemisphere rays are drawn with (w/W); the cosine
    // and cos/π for planar illuminance.
    const double cosI = at.response ? at.response->weight(dir) : glm::dot(at.n, dir);
    if (cosI <= 0.0) continue;
    const SkyMisTerms t = skyMisTerms(ctx.tracer, dir, at.p, at.n, misRatio, portalRatio);
    const double pc = at.response ? at.response->density(dir) : cosI * kInvPi;
    const double denom = t.sky * t.sky + t.portal * t.portal + pc * pc;
    // w_i / (m_i p_i) of the strategy that drew dir.
    const double wOverMp = throughPortal ? (t.pp > 0.0 ? t.portal * t.portal / denom / (kPortal * t.pp) : 0.0)
                                         : (t.ps > 0.0 ? t.sky * t.sky / denom / (kSky * t.ps) : 0.0);
    if (!(wOverMp > 0.0)) continue;
    Rgb v = ctx.transmittance(at.p, dir, kInf, at.skip, kNoShape, at.clip);
    if (at.filter) v *= at.filter->sky(dir);
    const Rgb g = v * (wOverMp * skyOrGroundLuminance(sky, dir) / kLumensPerWatt * cosI);
    if (tally && tally->patches && !(tally->directApart && !atPathVertex))
      tallySky(*tally, dir, v * (wOverMp * cosI), !atPathVertex);
    sum += g;
    y1[throughPortal] += photopic(g);
    y2[throughPortal] += photopic(g) * photopic(g);
  }
  if (variance) {
    // The estimate is the sum of the samples' terms, the two groups independent:
    // Var = Σ_g n_g s_g², s_g² the variance of one term of group g.
    const int n[2] = {kSky, kPortal};
    for (int g = 0; g < 2; ++g) {
      if (n[g] < 2) continue;
      const double mean = y1[g] / n[g];
      *variance += n[g] * std::max(0.0, y2[g] / n[g] - mean * mean) * n[g] / (n[g] - 1);
    }
  }
  return sum;
}

}  // namespace

Rgb directIrradiance(TraceContext& ctx, const Receiver& at, int k, double* variance, double misRatio) {
  const Tracer& tracer = ctx.tracer;
  const Scene& scene = tracer.scene();
  const std::vector<Light>& lights = tracer.sources().lights;
  Rgb total(0.0);
  // Path vertices (no variance wanted): one light chosen per sample (engine/light_selection.h).
  const bool atPathVertex = variance == nullptr;
  if (atPathVertex) {
    total = sampleLightsByImportance(lights, scene, at.p, at.n, k, ctx.rng, ctx.light.cdf, ctx.patternsIfAny(),
                                     [&](const Vec3& o, const LightSample& ls, double tMax, uint32_t lightShape) {
                                       const Rgb v = ctx.transmittance(o, ls.dir, tMax, at.skip, lightShape, at.clip);
                                       return at.filter ? v * at.filter->source(ls.dir, ls.solidAngleSr) : v;
                                     }, ctx.smallSin2, ctx.light.useGlowShare ? ctx.light.glowShare.data() : nullptr);
  }
  for (const Light& light : lights) {
    if (atPathVertex) break;
    if (!glowSampledFrom(light, at.p, ctx.smallSin2)) continue;
    total += lightEstimate(ctx, light, at, k, variance, [&](const LightSample& ls, uint32_t lightShape) {
      const double tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0 - 1e-9);
      return ctx.transmittance(at.p, ls.dir, tMax, at.skip, lightShape, at.clip);
    });
  }
  // Sources seen in flat mirrors, as virtual sources.
  if (!tracer.sources().mirrors.empty()) total += mirrorIrradiance(ctx, at, k, variance);
  if (ctx.tally && ctx.tally->suns && atPathVertex) tallySuns(ctx, at);
  if (scene.sky && !(ctx.tally && !ctx.tally->patches) && !(at.filter && !at.filter->takesSky()))
    total += skyIrradiance(ctx, at, k, variance, misRatio);
  return total;
}

SkyMisTerms skyMisTerms(const Tracer& tracer, const Vec3& dir, const Vec3& p, const Vec3& n, double misRatio,
                        double portalRatio) {
  const SkyDome& sky = *tracer.scene().sky;
  SkyMisTerms t;
  t.ps = dir.z > 0.0 ? sky.model->pdf(modelToTrue(dir, sky.northDeg)) : 0.0;
  bool any = false;
  if (!tracer.portals().empty()) t.pp = tracer.portals().pdf(p, n, dir, &any);
  t.sky = misRatio * t.ps;
  t.portal = any ? kPortalBoost * portalRatio * t.pp : 0.0;
  return t;
}

double skyMisWeight(const Tracer& tracer, const Vec3& dir, const SkyMis& mis) {
  if (!(mis.cosPdf > 0.0)) return 1.0;
  const SkyMisTerms t = skyMisTerms(tracer, dir, mis.origin, mis.normal, mis.ratio, mis.portalRatio);
  const double c2 = mis.cosPdf * mis.cosPdf;
  return c2 / (c2 + t.sky * t.sky + t.portal * t.portal);
}

Rgb distantRadiance(TraceContext& ctx, const Vec3& origin, const Vec3& dir, bool countSources, const SkyMis& mis) {
  const Tracer& tracer = ctx.tracer;
  const Scene& scene = tracer.scene();
  // Where sources at infinity overlap, the smallest one is seen (it lies in front of the larger,
  // as the sun in front of the sky).
  const DistantSource* seen = nullptr;
  for (const DistantSource& d : scene.distant)
    if (glm::dot(dir, d.direction) >= d.cosHalfAngle && (!seen || d.solidAngleSr < seen->solidAngleSr)) seen = &d;
  if (seen) {
    const Material& m = scene.materials[seen->material];
    if (m.isSampledSource() && !countSources) return Rgb(0.0);  // a glow is seen whether sources count or not
    const int pattern = functionPatternOf(scene, m);
    if (pattern < 0) return m.color;
    const PatternPoint at{origin + kDistantPointM * dir, dir, -dir, kDistantPointM};
    return m.color * glm::max(ctx.patterns().colour(pattern, at), Rgb(0.0));
  }
  if (!scene.sky) return Rgb(0.0);
  return Rgb(skyMisWeight(tracer, dir, mis) * skyOrGroundLuminance(*scene.sky, dir) / kLumensPerWatt);
}

}  // namespace candela
