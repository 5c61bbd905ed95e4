#include "engine/integrator_path.h"

#include "engine/integrator_direct.h"
#include "engine/materials/family.h"
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/sampling.h"
#include "engine/sky_tally.h"
#include "engine/source_distribution.h"
#include "photometry/site.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// After this many scattering vertices (BSDF) in a row, a path at one goes on with the
// probability of its draw's weight (the parts' albedo sum), weighted back: Russian roulette.
constexpr int kScatterRouletteRun = 2;

// A surface met by a path's ray.
struct Hit {
  Vec3 x{0.0};       // the point
  Vec3 inDir{0.0};   // direction of the ray that arrived
  Vec3 ng{0.0};      // geometric normal
  Vec3 nf{0.0};      // normal facing the incoming ray
  Vec3 ns{0.0};      // shading normal: nf, turned by a texture's perturbation (textured)
  bool textured = false;
  bool front = true; // the ray arrived on the side of ng
  double off = 0.0;  // origin offset (Tracer::originOffset)
  uint32_t flatSkip = kNoShape;  // the shape when flat (rays leaving it skip it), or kNoShape
  uint32_t shape = kNoShape;
  double t = 0.0;    // distance travelled to it, m
  // An antimatter hole's side seen as the clipped material (engine/antimatter.h): the clip set a
  // ray going on straight through it takes; -1 for every other surface.
  int32_t clipBeyond = -1;
  bool holeSide() const { return clipBeyond >= 0; }
};

// The ray being followed through specular and pass-through events.
struct Ray {
  Vec3 o{0.0}, d{0.0};
  Rgb beta{1.0};           // throughput so far
  bool reflected = false;  // a specular reflection on the way (for the sky tally's direct part)
};

Rgb diffuseVertex(TraceContext& ctx, const Hit& v, const Material& m, const PathState& st);

// The radiance of sky and distant sources seen by a ray escaping along d; tallies it as the sky
// tally asks (MIS-weighted as distantRadiance weighs it, sky and ground alike).
Rgb escapeRadiance(TraceContext& ctx, const Vec3& d, const PathState& st, const Ray& ray) {
  const Scene& scene = ctx.tracer.scene();
  SkyTally* tally = ctx.tally;
  const SkyMis mis{st.misCosPdf, st.misRatio, st.misPortalRatio, st.misOrigin, st.misNormal};
  if (tally && tally->patches && scene.sky && !(tally->directApart && st.diffuse == 0 && !ray.reflected))
    tallySky(*tally, d, ray.beta * skyMisWeight(ctx.tracer, d, mis), st.diffuse == 0 && !ray.reflected);
  return distantRadiance(ctx, ray.o, d, st.countSources, mis);
}

// Follows a specular surface (mirror, thin glass, dielectric: its family samples the event) at v:
// the ray and the path's state after it; false when the path ends (glass that neither transmits
// nor reflects).
bool followSpecular(TraceContext& ctx, const Material& m, const Hit& v, Ray& ray, PathState& st) {
  const SpecularSample e = familyOf(m).sampleSpecular(m, {ray.d, v.ng, v.nf, v.front, v.t}, ctx.rng, ray.beta);
  switch (e.kind) {
    case SpecularSample::Kind::kAbsorbed:
      return false;
    case SpecularSample::Kind::kMirror:
      st.misCosPdf = 0.0;  // the sky seen in a mirror is not sampled directly
      ray.reflected = true;
      ray.d = e.dir;
      ray.o = v.x + v.off * v.nf;
      st.skip = v.flatSkip;
      // A path that does not count sources (they are sampled at its last diffuse vertex) and
      // meets one flat mirror keeps not counting them: the mirror's virtual sources were sampled
      // too, with their visibility through transmitting surfaces before and after the mirror.
      // Beyond that one reflection (a second mirror, glass reflection) it counts them again.
      if (st.countSources || st.mirrorsMet != 0 ||
          v.shape >= ctx.tracer.sources().isMirrorImage.size() ||  // mesh triangles: never mirrors
          !ctx.tracer.sources().isMirrorImage[v.shape])
        st.countSources = true;
      ++st.mirrorsMet;
      return true;
    case SpecularSample::Kind::kStraight:
      // Straight on: whether sources count is the incoming ray's state (shadow rays through the
      // same glass already carried them from a diffuse vertex).
      ray.o = v.x - v.off * v.nf;
      st.skip = v.flatSkip;
      if (v.holeSide()) st.clip.clipped = static_cast<uint16_t>(v.clipBeyond);
      return true;
    case SpecularSample::Kind::kReflected:
      ray.reflected = true;
      ray.d = e.dir;
      ray.o = v.x + v.off * v.nf;
      st.misCosPdf = 0.0;
      st.countSources = true;
      st.skip = v.flatSkip;
      return true;
    case SpecularSample::Kind::kBent:
      ray.d = e.dir;
      ray.o = e.transmitted ? v.x - v.off * v.nf : v.x + v.off * v.nf;
      st.skip = v.flatSkip;
      if (v.holeSide() && e.transmitted) st.clip.clipped = static_cast<uint16_t>(v.clipBeyond);
      st.misCosPdf = 0.0;
      st.countSources = true;
      ray.reflected = true;  // bent: the sky tally's patch-by-patch shadow rays cannot see through it
      return true;
  }
  return false;
}

// One sample of the glossy lobe of m leaving v: its reflected radiance estimate. As Radiance's
// sampled specular rays do, a sample carries the family's lobe weight (the specular reflectance
// ρ_s for the Ward lobes); sources met are counted (the light sampled at the vertex is the diffuse
// part's only); glossy reflections count as bounces. clip: the set of the ray that arrived, which
// the sample keeps.
Rgb glossyBounce(TraceContext& ctx, const Hit& v, const Material& m, int diffuse, const ClipState& clip) {
  Vec3 out(0.0);
  const MaterialFamily& family = familyOf(m);
  if (!family.sampleLobe(m, v.inDir, v.ns, ctx.rng, out)) return Rgb(0.0);
  if (v.textured && glm::dot(out, v.nf) <= 0.0) return Rgb(0.0);  // turned below the surface
  const Rgb weight = family.lobeWeight(m, v.inDir, v.ns, out);
  const TallyFactor tf(ctx.tally, weight);
  PathState next;
  next.skip = v.flatSkip;
  next.countSources = true;
  next.diffuse = diffuse + 1;
  next.lighting = true;
  next.clip = clip;
  return weight * pathRadiance(ctx, v.x + v.off * v.nf, out, next);
}

// Ward's cache at a diffuse vertex: direct light sampled here, indirect irradiance interpolated;
// nothing when no record covers the vertex.
std::optional<Rgb> cachedVertex(TraceContext& ctx, const Hit& v, const Material& m, int diffuse, const Rgb& beta,
                                CacheUse& cache) {
  Rgb e(0.0);
  cache.scratch.weights.clear();
  if (!cache.cache->interpolate(v.x, v.nf, e, &cache.scratch, v.shape, &ctx.rays)) return std::nullopt;
  const Vec3 xf = v.x + v.off * v.nf;
  // A record's hemisphere left out the glows sampled from the record's point: the lookup samples
  // each glow with the weight of those records, so that none is lost or counted twice where the
  // records lie on both sides of its rule (docs/estimator.md#small-emitters).
  const SampledSources& src = ctx.tracer.sources();
  if (!src.glowLight.empty()) {
    LightScratch& sc = ctx.light;
    sc.glowShare.assign(src.lights.size(), 0.0);
    for (size_t l = 0; l < src.lights.size(); ++l) {
      if (!src.lights[l].glow) continue;
      for (const auto& [i, w] : cache.scratch.weights) {
        const IrradianceRecord& r = cache.cache->record(i);
        if (glowSampledFrom(src.lights[l], r.p + Tracer::originOffset(r.p) * r.n, ctx.smallSin2)) sc.glowShare[l] += w;
      }
    }
    sc.useGlowShare = true;
  }
  // The cache serves vertices reached with an empty clip set only (pathRadiance): the receiver's.
  const Rgb direct = directIrradiance(ctx, {xf, v.nf, v.flatSkip}, std::max(1, ctx.settings.cache.lightSamples),
                                      nullptr, 1.0);
  ctx.light.useGlowShare = false;
  const Rgb f = beta * m.diffuseReflectance * kInvPi;
  const double fy = photopic(f);
  for (const auto& [i, w] : cache.scratch.weights) {
    RecordVector b = lookupVector(cache.cache->record(i), v.x, v.nf, cache.cache->settings().gradients);
    for (double& x : b) x *= fy * w;
    cache.tally.add(i, b);
  }
  cache.tally.addCachedValue(photopic(f * e));
  Rgb result(0.0);
  result += f * (direct + e);
  if (photopic(m.specularReflectance) > 0.0) result += beta * glossyBounce(ctx, v, m, diffuse, ClipState{});
  return result;
}

// The sampled sources' light at a vertex of a material whose sources' light depends on its
// direction (MaterialFamily::sourceBrdf), on one side (transmitted: through from the other); the
// sky's by the diffuse part the paths leaving the vertex carry.
class SourceBrdfFilter final : public LightFilter {
 public:
  SourceBrdfFilter(TraceContext& ctx, const Material& m, const PatternPoint& at, bool transmitted)
      : ctx_(ctx), m_(m), at_(at), transmitted_(transmitted),
        sky_((transmitted ? m.diffuseTransmittance : m.diffuseReflectance) * kInvPi),
        takesSky_(!familyOf(m).samplesScattering(m)) {}
  Rgb source(const Vec3& dir, double omegaSr) const override {
    return familyOf(m_).sourceBrdf(m_, at_, ctx_.patterns(), dir, omegaSr, transmitted_);
  }
  Rgb sky(const Vec3&) const override { return sky_; }
  bool takesSky() const override { return takesSky_; }

 private:
  TraceContext& ctx_;
  const Material& m_;
  const PatternPoint& at_;
  bool transmitted_;
  Rgb sky_;
  bool takesSky_;  // false: the sky arrives by the drawn paths (sampleScattering)
};

// Light leaving a vertex v of a material whose paths go on by its scattering function (BSDF,
// aBSDF: MaterialFamily::sampleScattering): the sampled sources on both sides by the function in
// their direction, everything else (the sky included, counted in full) along k drawn
// continuations, which do not count the sources sampled here; a straight (direct) part goes on
// as the ray that arrived, counting what it counted.
Rgb scatterVertex(TraceContext& ctx, const Hit& v, const Material& m, const PathState& st) {
  const MaterialFamily& family = familyOf(m);
  const Vec3 nf = v.ns;
  const Vec3 xf = v.x + v.off * v.nf, xb = v.x - v.off * v.nf;
  const uint32_t self = v.textured ? kNoShape : v.flatSkip;
  const int k = std::max(1, st.split);
  const PatternPoint at{v.x, v.inDir, v.ng, v.t};
  const SourceBrdfFilter front(ctx, m, at, false), back(ctx, m, at, true);
  Rgb out = directIrradiance(ctx, {xf, nf, self, nullptr, &front, &st.clip}, k, nullptr, 1.0);
  out += directIrradiance(ctx, {xb, -nf, self, nullptr, &back, &st.clip}, k, nullptr, 1.0);
  const Vec3 beyond = xb + family.transmittedOffset(m, v.ng);
  const Strata2D strata(k, 1.0 / kPi);
  Rgb acc(0.0);
  for (int j = 0; j < k; ++j) {
    ScatterSample s;
    if (!family.sampleScattering(m, at, strata.sample(j, ctx.rng), ctx.rng, s)) continue;
    // A draw carries the parts' albedo sum: the path does not end here (less noise where a
    // window is met). After kScatterRouletteRun scattering vertices in a row (layers facing each
    // other), Russian roulette by that albedo bounds the path, as at diffuse vertices.
    if (st.scatterRun >= kScatterRouletteRun && !s.straight) {
      const double q = std::min(1.0, photopic(s.weight));
      if (!(q > 0.0) || ctx.rng.uniform() >= q) continue;
      s.weight /= q;
    }
    const TallyFactor tf(ctx.tally, s.weight / static_cast<double>(k));
    if (s.straight) {
      PathState through = st;
      through.skip = v.flatSkip;
      through.split = 1;
      if (v.holeSide()) through.clip.clipped = static_cast<uint16_t>(v.clipBeyond);
      acc += s.weight * pathRadiance(ctx, xb, v.inDir, through);
      continue;
    }
    PathState bounce;
    bounce.skip = self;
    bounce.diffuse = st.diffuse + 1;
    bounce.lighting = true;
    bounce.clip = st.clip;
    bounce.litPoint = s.transmitted ? xb : xf;
    bounce.scatterRun = static_cast<uint8_t>(std::min(255, st.scatterRun + 1));
    acc += s.weight * pathRadiance(ctx, s.transmitted ? beyond : xf, s.dir, bounce);
  }
  return out + acc / static_cast<double>(k);
}

// Light leaving a diffuse vertex v of material m towards the incoming ray. The incoming ray's
// countSources, MIS density and ratio and flat mirrors met carry on through specular
// transmission (trans), which keeps its direction.
Rgb diffuseVertex(TraceContext& ctx, const Hit& v, const Material& m, const PathState& st) {
  if (familyOf(m).samplesScattering(m)) return scatterVertex(ctx, v, m, st);
  const Rgb rho = m.diffuseReflectance, tauD = m.diffuseTransmittance, tauS = m.specularTransmittance;
  // Directions by the shading normal (a texture turns it, as Radiance's raynormal); the points
  // off the surface by the geometric one. A textured surface is no skip for its own rays: what
  // the turned normal sends below the surface meets the surface itself.
  const Vec3 nf = v.ns;
  const Vec3 xf = v.x + v.off * v.nf, xb = v.x - v.off * v.nf;
  const uint32_t self = v.textured ? kNoShape : v.flatSkip;
  const int k = std::max(1, st.split);
  Rgb out(0.0);
  // Light reflected (and diffusely transmitted) from the sampled sources: by the BRDF of the
  // sources' direction where the material has one (the sky by its diffuse parts).
  if (familyOf(m).directionalSources(m)) {
    const PatternPoint at{v.x, v.inDir, v.ng, v.t};
    const SourceBrdfFilter front(ctx, m, at, false);
    out += directIrradiance(ctx, {xf, nf, self, nullptr, &front, &st.clip}, k, nullptr, 1.0);
    if (familyOf(m).transmitting()) {
      const SourceBrdfFilter back(ctx, m, at, true);
      out += directIrradiance(ctx, {xb, -nf, self, nullptr, &back, &st.clip}, k, nullptr, 1.0);
    }
  } else if (photopic(rho) > 0.0) {
    const TallyFactor tf(ctx.tally, rho * kInvPi);
    out += rho * kInvPi * directIrradiance(ctx, {xf, nf, self, nullptr, nullptr, &st.clip}, k, nullptr, 1.0);
  }
  if (photopic(tauD) > 0.0 && !familyOf(m).directionalSources(m)) {
    const TallyFactor tf(ctx.tally, tauD * kInvPi);
    out += tauD * kInvPi * directIrradiance(ctx, {xb, -nf, self, nullptr, nullptr, &st.clip}, k, nullptr, 1.0);
  }
  // Indirect light: k continuations (stratified when k > 1), each one event chosen with
  // probability equal to its photopic albedo (Russian roulette by albedo: unbiased, a path ends
  // with probability 1 − albedo).
  const double pRho = photopic(rho), pTd = photopic(tauD), pTs = photopic(tauS);
  const double pSp = photopic(m.specularReflectance);
  const double norm = std::max(1.0, pRho + pTd + pTs + pSp);
  if (pRho + pTd + pTs + pSp <= 0.0) return out;
  const Strata2D strata(k, 1.0 / kPi);
  PathState bounce;  // a diffuse continuation: cosine-sampled, sources sampled here
  bounce.skip = self;
  bounce.diffuse = st.diffuse + 1;
  bounce.lighting = true;
  bounce.clip = st.clip;
  Rgb acc(0.0);
  for (int j = 0; j < k; ++j) {
    const Vec2 u12 = strata.sample(j, ctx.rng);
    const double u = ctx.rng.uniform() * norm;
    if (u < pRho) {
      const Vec3 dir = Frame::fromNormal(nf).toWorld(sampleCosineHemisphere(u12.x, u12.y));
      if (v.textured && glm::dot(dir, v.nf) <= 0.0) continue;  // turned below the surface
      const TallyFactor tf(ctx.tally, rho * (norm / pRho / k));
      bounce.misCosPdf = glm::dot(dir, nf) * kInvPi;
      bounce.litPoint = xf;
      bounce.misOrigin = xf;
      bounce.misNormal = nf;
      acc += rho * (norm / pRho) * pathRadiance(ctx, xf, dir, bounce);
    } else if (u < pRho + pTd) {
      const Vec3 dir = Frame::fromNormal(-nf).toWorld(sampleCosineHemisphere(u12.x, u12.y));
      if (v.textured && glm::dot(dir, v.nf) >= 0.0) continue;  // turned above the surface
      const TallyFactor tf(ctx.tally, tauD * (norm / pTd / k));
      bounce.misCosPdf = -glm::dot(dir, nf) * kInvPi;
      bounce.litPoint = xb;
      bounce.misOrigin = xb;
      bounce.misNormal = -nf;
      acc += tauD * (norm / pTd) * pathRadiance(ctx, xb, dir, bounce);
    } else if (u < pRho + pTd + pTs && familyOf(m).roughTransmission(m)) {
      // A rough specular transmission (WGMDfunc): a draw of its lobe, counting the sources it
      // meets (none are sampled for it), a bounce as glossy reflections are.
      Vec3 dir(0.0);
      if (!familyOf(m).sampleTransmittedLobe(m, v.inDir, nf, ctx.rng, dir)) continue;
      const TallyFactor tf(ctx.tally, tauS * (norm / pTs / k));
      PathState lobe;
      lobe.skip = self;
      lobe.countSources = true;
      lobe.diffuse = st.diffuse + 1;
      lobe.lighting = true;
      lobe.clip = st.clip;
      acc += tauS * (norm / pTs) * pathRadiance(ctx, xb, dir, lobe);
    } else if (u < pRho + pTd + pTs) {
      // Specular transmission (trans): straight on, as Radiance's trans does with roughness 0.
      // Straight on, so sources count as they did for the incoming ray (shadow rays through the
      // trans already carried them to diffuse vertices, and mirror images through it), and the
      // sky keeps the incoming ray's MIS weight (sky samples' shadow rays pass the trans too).
      const TallyFactor tf(ctx.tally, tauS * (norm / pTs / k));
      PathState through = st;
      through.skip = v.flatSkip;
      through.split = 1;
      if (v.holeSide()) through.clip.clipped = static_cast<uint16_t>(v.clipBeyond);
      acc += tauS * (norm / pTs) * pathRadiance(ctx, xb, v.inDir, through);
    } else if (u < pRho + pTd + pTs + pSp) {
      const TallyFactor tf(ctx.tally, norm / pSp / k);
      acc += (norm / pSp) * glossyBounce(ctx, v, m, st.diffuse, st.clip);
    }
  }
  return out + acc / static_cast<double>(k);
}

// The radiance an emitter sends back along the ray that met it at v (its front side).
Rgb emitted(const Scene& scene, const Material& m, const Hit& v) {
  if (m.pattern < 0) return m.color;
  return emittedRadiance(scene, m, v.inDir, -glm::dot(v.inDir, v.nf));
}

// Whether a ray in state st counts the glow `shape` it met. A glow of negative radius lights
// nothing (only eyes see it); a glow sampled from the ray's litPoint is counted by that sample
// instead — unless a flat mirror was met since (glows are not sampled in mirrors,
// integrator_direct.cpp) or sources count anyway (after specular reflection, camera rays).
bool countsGlow(const TraceContext& ctx, const Material& m, uint32_t shape, const PathState& st) {
  if (m.glowRadiusM < 0.0) return !st.lighting;
  if (st.countSources || st.mirrorsMet != 0) return true;
  const SampledSources& src = ctx.tracer.sources();
  if (shape >= src.glowLight.size() || src.glowLight[shape] < 0) return true;
  return !glowSampledFrom(src.lights[src.glowLight[shape]], st.litPoint, ctx.smallSin2);
}

}  // namespace

Rgb pathRadiance(TraceContext& ctx, const Vec3& origin, const Vec3& direction, PathState st, CacheUse* cache,
                 double* firstHitT) {
  const Scene& scene = ctx.tracer.scene();
  Rgb result(0.0);
  Ray ray;
  ray.o = origin;
  ray.d = direction;
  // Specular and pass-through events are followed iteratively; a diffuse vertex ends the loop.
  for (int vertex = 0; vertex < 64; ++vertex) {
    RayHit h;
    const bool hit = ctx.intersect(ray.o, ray.d, 0.0, kInf, h, st.skip);
    if (vertex == 0 && firstHitT) *firstHitT = hit ? h.t : kInf;
    if (!hit) return result + ray.beta * escapeRadiance(ctx, ray.d, st, ray);
    Hit v;
    v.x = ray.o + h.t * ray.d;
    v.inDir = ray.d;
    v.t = h.t;
    v.shape = h.shape;
    const Shape shape = scene.surface(h.shape);  // a shape or a mesh triangle
    const Material* m = &scene.materials[shape.material];
    v.ng = shapeNormal(shape, v.x);
    v.front = glm::dot(ray.d, v.ng) < 0.0;
    v.nf = v.front ? v.ng : -v.ng;
    v.off = Tracer::originOffset(v.x);
    v.flatSkip = isFlat(shape) ? h.shape : kNoShape;
    if (ctx.tracer.hasAntimatter()) {
      // Clipped surfaces and antimatter boundaries are passed (the state updated); a hole's side
      // is the clipped material, turned to face the ray (nf unchanged).
      const ClipResult c = clipStep(*m, ray.d, v.ng, st.clip);
      if (c.action == ClipAction::kPass) {
        ray.o = v.x - v.off * v.nf;
        st.skip = v.flatSkip;
        continue;
      }
      if (c.action == ClipAction::kShown) {
        m = &scene.materials[static_cast<size_t>(c.shown)];
        v.ng = -v.ng;
        v.front = !v.front;
        v.clipBeyond = c.beyond;
      }
    }
    std::optional<Material> patternedHere;  // the hook's copy when patterns modify m
    m = materialAt(scene, *m, {v.x, ray.d, v.ng, v.t}, ctx.patternEval, ctx.rng, patternedHere);
    if (!m) {  // an illum with no alternate or a void in a mixture: pass straight through
      ray.o = v.x - v.off * v.nf;
      st.skip = v.flatSkip;
      if (v.holeSide()) st.clip.clipped = static_cast<uint16_t>(v.clipBeyond);  // on through: newcset
      continue;
    }
    // A proxy's hidden side, and a proxy met by an eye's ray before any reflection (Radiance lets
    // rays that are neither specular nor ambient through): straight on.
    const bool eyeRay = !st.lighting && st.diffuse == 0 && !ray.reflected;
    if (familyOf(*m).hidesSide(*m, v.front) || (eyeRay && familyOf(*m).passesPrimaryRays(*m))) {
      ray.o = v.x - v.off * v.nf;
      st.skip = v.flatSkip;
      continue;
    }
    v.ns = shadingNormal(*m, v.nf, v.front);  // a texture turns it
    v.textured = m->perturbation != Vec3(0.0);
    if (const std::optional<Vec3> smooth = scene.smoothNormal(h.shape, v.x)) {  // OBJ `vn`
      v.ns = smoothShadingNormal(*m, *smooth, v.nf, v.front);
      v.textured = true;
    }
    const MaterialFamily& family = familyOf(*m);
    switch (family.role()) {
      case HitRole::kEmit:
        if (family.sampledSource())
          return (st.countSources && v.front) ? result + ray.beta * emitted(scene, *m, v) : result;
        return v.front && countsGlow(ctx, *m, h.shape, st) ? result + ray.beta * emitted(scene, *m, v) : result;
      case HitRole::kAbsorb:
      case HitRole::kMix:  // resolved above
        return result;
      case HitRole::kSpecular:
        if (!followSpecular(ctx, *m, v, ray, st)) return result;
        continue;
      case HitRole::kScatter:
        break;
    }
    // plastic, metal, trans: their diffuse parts (specular lobes: see docs/engine.md).
    if (st.diffuse + 1 > ctx.settings.maxBounces) return result;
    // The cache's records hold light gathered with an empty clip set: vertices in another, and
    // a hole's sides, are traced.
    const bool clipFree = !ctx.tracer.hasAntimatter() || (!v.holeSide() && isEmpty(st.clip));
    if (cache && cache->cache && st.diffuse == cache->depth && family.cacheable(*m) && !v.textured && clipFree) {
      if (const std::optional<Rgb> cached = cachedVertex(ctx, v, *m, st.diffuse, ray.beta, *cache)) return *cached;
      PathState miss = st;
      miss.split = 1;
      return result + ray.beta * diffuseVertex(ctx, v, *m, miss);
    }
    const TallyFactor tf(ctx.tally, ray.beta);
    return result + ray.beta * diffuseVertex(ctx, v, *m, st);
  }
  return result;
}

Rgb rayRadiance(const Tracer& tracer, const Vec3& origin, const Vec3& direction, uint32_t skip, bool countSources,
                Rng& rng, const TraceSettings& s) {
  TraceContext ctx(tracer, s, rng);
  PathState st;
  st.skip = skip;
  st.countSources = countSources;
  // Without sources counted the caller samples them at the origin: a ray carrying light.
  st.litPoint = origin;
  st.lighting = !countSources;
  return pathRadiance(ctx, origin, direction, st);
}

}  // namespace candela
