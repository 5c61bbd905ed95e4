#include "engine/tracer.h"

#include "engine/embree_accelerator.h"
#include "engine/fresnel.h"
#include "engine/light_selection.h"
#include "engine/sampling.h"
#include "photometry/site.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Rays cast, tallied per thread and added to the tracer's total in blocks (one atomic add per
// 4096 rays) and whenever a top-level call (irradiance, a cache record) ends.
struct RayTally {
  const Tracer* owner = nullptr;
  uint64_t n = 0;
};
thread_local RayTally tRays;

// Daylight coefficients (Tracer::skyCoefficients): while a tally is active on this thread, every
// sky or ground contribution the estimator makes is also added to its patch's bin, as lux per
// cd/m² of patch luminance. `outer` is the product of the factors the enclosing calls will apply
// to the radiance being computed (1/k of a split, ρ/π of a diffuse vertex, ...), so a
// contribution's weight is known where it arises; TallyFactor scopes each such factor.
struct SkyTally {
  const SkyPatches* patches = nullptr;  // sky patches tallied (none: suns only)
  double northDeg = 0.0;
  double* direct = nullptr;    // seen from the sensor with no reflection on the way
  double* indirect = nullptr;  // everything else
  // The direct part is computed patch by patch apart (skyCoefficients), so the sensor's own sky
  // samples and unreflected escapes are not tallied.
  bool directApart = false;
  // Suns (unit, model frame) whose light is tallied at path vertices by a shadow ray each, per
  // unit normal illuminance (Tracer::sunCoefficients).
  const std::vector<Vec3>* suns = nullptr;
  double* sunIndirect = nullptr;
  Rgb outer{1.0};
};
thread_local SkyTally* tTally = nullptr;

class TallyFactor {
 public:
  explicit TallyFactor(const Rgb& f) {
    if (tTally) {
      saved_ = tTally->outer;
      tTally->outer *= f;
    }
  }
  explicit TallyFactor(double f) : TallyFactor(Rgb(f)) {}
  ~TallyFactor() {
    if (tTally) tTally->outer = saved_;
  }
  TallyFactor(const TallyFactor&) = delete;
  TallyFactor& operator=(const TallyFactor&) = delete;

 private:
  Rgb saved_{1.0};
};

// Runs f with the thread's sky tally set to `tally`.
template <class F>
void withTally(SkyTally& tally, const F& f) {
  tTally = &tally;
  try {
    f();
  } catch (...) {
    tTally = nullptr;
    throw;
  }
  tTally = nullptr;
}

// Adds weight·outer (photopic: the sky's luminance is achromatic) to the bin of model direction d.
void tallySky(const Vec3& d, const Rgb& weight, bool direct) {
  const int bin = tTally->patches->indexOf(modelToTrue(d, tTally->northDeg));
  (direct ? tTally->direct : tTally->indirect)[bin] += photopic(tTally->outer * weight);
}

bool isFlat(const Shape& s) {
  return s.type == ShapeType::kTriangle || s.type == ShapeType::kPolygon || s.type == ShapeType::kRing;
}

// Variance of E = π/(MN) Σ y over M × N strata (y photopic radiance, cell j·N + k). One sample
// per stratum gives no direct variance estimate; with three or more φ strata per row, the second
// differences along φ (wrapping) are used: for y_k = μ_k + ε_k, E[(y_k−1 − 2y_k + y_k+1)²] =
// (curvature of μ)² + σ²_k−1 + 4σ²_k + σ²_k+1, so Σ d²/6 bounds Σ σ² from above, and unlike
// collapsed pairs (Cochran, "Sampling Techniques", 5A.12) a smooth linear trend adds nothing.
// Fewer φ strata: collapsed pairs, Σ (y_a − y_b)²/2 per pair.
// Cells refined by adaptive super-sampling (ownBetween not NaN) take their own estimate of the
// variance of their mean instead (Tracer::irradiance): ownBetween ≥ 0 and ownWithin, unbiased but
// of either sign, whose sum is clamped at 0 (it estimates a sum of variances). Their second
// differences would not do: these cells lie where the radiance steps (that is why they were
// refined), so the curvature term, which refinement does not shrink, would dominate the small
// variance of their means (3.5× the measured variance under a roof opening), and dividing it by
// the cell's count, as was done, undercounted cells where the edge runs along φ (¼ of it).
// recordShare (cache method): the records' expected share of each unrefined cell's d_c², taken
// off the sum (Tracer::irradiance).
double stratifiedVariance(const std::vector<double>& y, int m, int n, const std::vector<double>* ownBetween = nullptr,
                          const std::vector<double>* ownWithin = nullptr, const std::vector<double>* recordShare = nullptr) {
  const double cells = static_cast<double>(y.size());
  if (y.empty()) return 0.0;
  double sumVar = 0.0, sumWithin = 0.0, sumRec = 0.0;
  auto refined = [&](size_t c) { return ownBetween && !std::isnan((*ownBetween)[c]); };
  if (n >= 3 && static_cast<size_t>(m) * n == y.size()) {
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < n; ++k) {
        const int c = j * n + k;
        if (refined(c)) {
          sumVar += (*ownBetween)[c];
          sumWithin += (*ownWithin)[c];
          continue;
        }
        const double d = y[j * n + (k + n - 1) % n] - 2.0 * y[c] + y[j * n + (k + 1) % n];
        sumVar += d * d / 6.0;
        if (recordShare) sumRec += (*recordShare)[c] / 6.0;
      }
  } else {
    for (size_t c = 0; c + 1 < y.size(); c += 2) sumVar += (y[c] - y[c + 1]) * (y[c] - y[c + 1]);
  }
  return kPi * kPi * std::max(0.0, sumVar + std::max(0.0, sumWithin) - sumRec) / (cells * cells);
}

}  // namespace

double IrradianceEstimate::standardErrorLux() const {
  return kLumensPerWatt * std::sqrt(std::max(0.0, variancePhotopic));
}

void Tracer::countRay() const {
  // A tally left by another tracer on this thread is dropped, never added through its pointer
  // (that tracer may be gone): every top-level call flushes its own before returning.
  if (tRays.owner != this) {
    tRays.owner = this;
    tRays.n = 0;
  }
  if (++tRays.n >= 4096) flushRays();
}

void Tracer::flushRays() const {
  if (tRays.owner != this) return;
  rays_.fetch_add(tRays.n, std::memory_order_relaxed);
  tRays.n = 0;
}

uint64_t Tracer::raysTraced() const {
  flushRays();
  return rays_.load(std::memory_order_relaxed);
}

double Tracer::originOffset(const Vec3& p) {
  // Doubles locate a hit to ~1e-15 of its coordinates; 1e-7 of the larger of 1 m and the
  // coordinates clears that by far while staying far below any modelled gap (≥ 0.1 mm).
  const double m = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 1e-7 * m;
}

AcceleratorKind parseAccelerator(const std::string& s) {
  if (s == "embree") return AcceleratorKind::kEmbree;
  if (s == "octree") return AcceleratorKind::kOctree;
  throw std::invalid_argument("accelerator must be embree or octree, not '" + s + "'");
}

std::unique_ptr<RayAccelerator> makeAccelerator(const Scene& scene, AcceleratorKind kind) {
  if (kind == AcceleratorKind::kOctree) return std::make_unique<Octree>(scene);
  return std::make_unique<EmbreeAccelerator>(scene);
}

Tracer::Tracer(const Scene& scene, AcceleratorKind kind) : Tracer(scene, makeAccelerator(scene, kind)) {}

Tracer::Tracer(const Scene& scene, OctreeOptions octree) : Tracer(scene, std::make_unique<Octree>(scene, octree)) {}

Tracer::Tracer(const Scene& scene, std::unique_ptr<RayAccelerator> accelerator)
    : scene_(scene), accel_(std::move(accelerator)), lights_(collectLights(scene)) {
  for (const Material& m : scene.materials)
    if (m.type == MaterialType::kGlass || m.type == MaterialType::kIllum ||
        (m.type == MaterialType::kTrans && photopic(m.specularTransmittance) > 0.0))
      hasTransmitters_ = true;
  // Flat mirrors get virtual light sources (images of every sampled source).
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& sh = scene.shapes[i];
    if (isFlat(sh) && scene.materials[sh.material].type == MaterialType::kMirror) mirrors_.push_back(i);
  }
  isMirrorImage_.assign(scene.shapes.size(), 0);
  for (uint32_t i : mirrors_) isMirrorImage_[i] = 1;
}

Rgb Tracer::transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB) const {
  countRay();
  if (!hasTransmitters_) return accel_->occluded(o, dir, 0.0, tMax, skipA, skipB) ? Rgb(0.0) : Rgb(1.0);
  // Walk the hits along the one ray, past each transmitting surface (same origin, growing tMin).
  Rgb t(1.0);
  double tMin = 0.0;
  for (int i = 0; i < 64; ++i) {
    RayHit h;
    if (i > 0) countRay();
    if (!accel_->intersect(o, dir, tMin, tMax, h, skipA, skipB)) return t;
    const Shape& s = scene_.shapes[h.shape];
    const Material& m = scene_.materials[s.material];
    const Vec3 x = o + h.t * dir;
    if (m.type == MaterialType::kGlass) {
      Rgb tr, rf;
      thinGlass(m.color, m.refractiveIndex, glm::dot(dir, shapeNormal(s, x)), tr, rf);
      t *= tr;
    } else if (m.type == MaterialType::kTrans) {
      t *= m.specularTransmittance;
    } else if (!(m.type == MaterialType::kIllum && m.alternate < 0)) {
      // Opaque (an illum with no alternate is invisible to all but its own rays). A dielectric
      // is opaque here too: it bends light, so no straight shadow ray passes it (as Radiance's
      // source rays); paths find what lies behind it (pathRadiance).
      return Rgb(0.0);
    }
    if (photopic(t) <= 0.0) return Rgb(0.0);
    tMin = h.t + originOffset(x);
  }
  return t;
}

Rgb Tracer::distantRadiance(const Vec3& dir, bool countSources, double misCosPdf, double misRatio) const {
  // Where sources at infinity overlap, the smallest one is seen (it lies in front of the larger,
  // as the sun in front of the sky).
  const DistantSource* seen = nullptr;
  for (const DistantSource& d : scene_.distant)
    if (glm::dot(dir, d.direction) >= d.cosHalfAngle && (!seen || d.solidAngleSr < seen->solidAngleSr)) seen = &d;
  if (seen) {
    const Material& m = scene_.materials[seen->material];
    if (m.type == MaterialType::kGlow) return m.color;
    return countSources ? m.color : Rgb(0.0);
  }
  if (!scene_.sky) return Rgb(0.0);
  const SkyDome& sky = *scene_.sky;
  if (dir.z <= 0.0) return Rgb(sky.groundLuminanceCdM2 / kLumensPerWatt);
  const Vec3 t = modelToTrue(dir, sky.northDeg);
  double w = 1.0;
  if (misCosPdf > 0.0) {
    const double ps = misRatio * sky.model->pdf(t);
    w = misCosPdf * misCosPdf / (misCosPdf * misCosPdf + ps * ps);
  }
  return Rgb(w * sky.model->luminance(t) / kLumensPerWatt);
}

// One sampled source's irradiance at p (normal n), k stratified samples; visibility(ls, lightShape)
// gives the RGB transmittance of sample ls (a shadow ray, or the path through a mirror).
template <class Visibility>
Rgb Tracer::lightEstimate(const Light& light, const Vec3& p, const Vec3& n, int k, Rng& rng, double* variance,
                          const Visibility& visibility) const {
  const Strata2D strata(k);
  // Per-thread scratch for horizon-clipped polygon sources (no allocation once warm).
  thread_local std::vector<Vec3> clipped;
  thread_local std::vector<std::array<Vec3, 3>> tris;
  thread_local std::vector<double> cumulative;
  Rgb exact(0.0);
  const bool haveExact = unoccludedIrradiance(light, scene_, p, n, exact, &clipped);
  if (haveExact && photopic(exact) <= 0.0) return Rgb(0.0);  // the source cannot reach this side
  // Polygon sources are sampled over their part above the receiver's horizon, so that every
  // sample tells about visibility.
  const bool clippedPolygon = haveExact && light.kind == Light::Kind::kArea && !light.outline.empty();
  if (clippedPolygon) {
    tris = triangulatePolygon(clipped, scene_.shapes[light.shape].n);
    cumulative.clear();
    double acc = 0.0;
    for (const auto& t : tris) {
      acc += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
      cumulative.push_back(acc);
    }
  }
  // With a closed form for the unoccluded irradiance E_u, the samples only estimate the visible
  // fraction: E = E_u · Σ f V / Σ f, f = w cos ι. This ratio estimator is exact when the source
  // is wholly visible, exactly 0 when wholly hidden (no light leaks), and its bias falls as 1/k.
  // Without a closed form: E = mean(f V).
  Rgb sumFvc(0.0), sumFc(0.0), sumRest(0.0);
  double yF2 = 0.0, yF2V = 0.0, yF2V2 = 0.0, yFc = 0.0, yRest = 0.0, yRest2 = 0.0;
  const uint32_t lightShape = light.kind == Light::Kind::kArea ? light.shape : kNoShape;
  // A far-field luminaire is one point: one shadow ray says all there is.
  const bool point = light.kind == Light::Kind::kLuminaire && haveExact;
  const int kk = point ? 1 : k;
  // Per-stratum terms for the variance (zero where a sample tells nothing).
  thread_local std::vector<double> zRatio, zRest;
  if (variance) {
    zRatio.assign(kk, 0.0);
    zRest.assign(kk, 0.0);
  }
  thread_local std::vector<double> fyS, vyS;
  if (variance) {
    fyS.assign(kk, 0.0);
    vyS.assign(kk, 0.0);
  }
  for (int i = 0; i < kk; ++i) {
    const Vec2 u = strata.sample(i, rng);
    LightSample ls;
    const bool ok = clippedPolygon ? sampleClippedPolygon(light, tris, cumulative, p, u.x, u.y, ls)
                                   : sampleLight(light, scene_, p, u.x, u.y, ls);
    if (!ok) continue;
    const double cosI = glm::dot(n, ls.dir);
    if (cosI <= 0.0) continue;
    const Rgb f = ls.weight * cosI;
    const Rgb v = visibility(ls, lightShape);
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
      fyS[i] = fy;
      vyS[i] = vy;
      zRest[i] = ry;
    }
  }
  Rgb e = sumRest / static_cast<double>(kk);
  if (haveExact) {
    // No informative sample (numerically degenerate): claim nothing rather than leak light.
    for (int ch = 0; ch < 3; ++ch) e[ch] += sumFc[ch] > 0.0 ? exact[ch] * sumFvc[ch] / sumFc[ch] : 0.0;
  }
  if (variance && kk > 1) {
    // Delta-method variance of the ratio: the linearised terms z_i = f_i (V_i − R) have
    // Var(Σ z) / (Σ f)² scaled by E_u²; the plain part's terms are the samples themselves. The
    // samples are stratified (Strata2D: i and i + 1 are neighbouring strata of one row), so the
    // variance of each sum is estimated by collapsing strata in pairs (Cochran, "Sampling
    // Techniques", 5A.12): Σ over pairs of (z_a − z_b)², which counts the difference of the two
    // strata's means as noise (an upper bound) but, unlike Σ z², not what stratification removes
    // (e.g. a panel whose part behind a screen is sampled by whole rows of strata).
    auto collapsed = [kk](const std::vector<double>& z) {
      double v = 0.0;
      for (int i = 0; i + 1 < kk; i += 2) v += (z[i] - z[i + 1]) * (z[i] - z[i + 1]);
      if (kk % 2 == 1) v += 2.0 * z[kk - 1] * z[kk - 1];  // an unpaired stratum: as if iid, doubled
      return v;
    };
    if (yFc > 0.0) {
      const double ratio = (yF2V > 0.0 || yF2 > 0.0) ? photopic(sumFvc) / yFc : 0.0;
      for (int i = 0; i < kk; ++i) zRatio[i] = fyS[i] * (vyS[i] - ratio);
      *variance += photopic(exact) * photopic(exact) * collapsed(zRatio) / (yFc * yFc);
    }
    if (yRest > 0.0) *variance += collapsed(zRest) / (static_cast<double>(kk) * kk);
  }

  return e;
}

Rgb Tracer::mirrorIrradiance(const Vec3& p, const Vec3& n, int k, uint32_t skip, Rng& rng, double* variance) const {
  // A flat mirror shows each source as an image behind it: the light reaching p by one
  // reflection is the light the source would give at p's mirror image p' (normal n'), passed
  // through the mirror's outline and reflectance. So the source is sampled from p' (with the
  // closed form there, as a ratio estimator), and each sample's visibility is the real path:
  // p to the mirror (which must be the first surface met) and on to the source.
  Rgb total(0.0);
  for (uint32_t ms : mirrors_) {
    const Shape& mirror = scene_.shapes[ms];
    const Vec3 nm = mirror.n, q = mirror.a;
    const double dp = glm::dot(p - q, nm);
    if (std::abs(dp) < 1e-12) continue;
    const Vec3 pi = p - 2.0 * dp * nm, ni = n - 2.0 * glm::dot(n, nm) * nm;
    const Rgb colour = scene_.materials[mirror.material].color;
    const Vec3 side = dp > 0.0 ? nm : -nm;
    for (const Light& light : lights_) {
      if (light.kind == Light::Kind::kArea && light.shape == ms) continue;
      total += colour * lightEstimate(light, pi, ni, k, rng, variance, [&](const LightSample& ls, uint32_t lightShape) {
        const Vec3 dir = ls.dir - 2.0 * glm::dot(ls.dir, nm) * nm;
        // Both legs pass transmitting surfaces (glass, trans, illum without alternate) as shadow
        // rays do, so that a path meeting them before the mirror does not count the image again
        // (pathRadiance: the first mirror after a diffuse vertex is an image).
        double tm = 0.0;
        if (!intersectShape(mirror, scene_.vertices, p, dir, 0.0, ls.distance, tm)) return Rgb(0.0);
        const Vec3 x = p + tm * dir;
        const double rest = std::isinf(ls.distance) ? kInf : (ls.distance - tm) * (1.0 - 1e-9);
        if (rest <= 0.0) return Rgb(0.0);
        const Rgb toMirror = transmittance(p, dir, tm * (1.0 - 1e-9), skip, ms);
        if (photopic(toMirror) <= 0.0) return Rgb(0.0);
        return toMirror * transmittance(x + originOffset(x) * side, ls.dir, rest, ms, lightShape);
      });
    }
  }
  return total;
}

Rgb Tracer::directIrradiance(const Vec3& p, const Vec3& n, int k, uint32_t skip, Rng& rng, double* variance,
                             double misRatio) const {
  Rgb total(0.0);
  const Strata2D strata(k);
  // Path vertices (no variance wanted): one light chosen per sample (engine/light_selection.h).
  const bool atPathVertex = variance == nullptr;
  if (atPathVertex) {
    total = sampleLightsByImportance(lights_, scene_, p, n, k, rng,
                                     [&](const Vec3& o, const Vec3& dir, double tMax, uint32_t lightShape) {
                                       return transmittance(o, dir, tMax, skip, lightShape);
                                     });
  }
  for (const Light& light : lights_) {
    if (atPathVertex) break;
    total += lightEstimate(light, p, n, k, rng, variance, [&](const LightSample& ls, uint32_t lightShape) {
      const double tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0 - 1e-9);
      return transmittance(p, ls.dir, tMax, skip, lightShape);
    });
  }
  // Sources seen in flat mirrors, as virtual sources.
  if (!mirrors_.empty()) total += mirrorIrradiance(p, n, k, skip, rng, variance);
  if (tTally && tTally->suns && atPathVertex) {
    // Sun coefficients: each sun's light at this vertex, one shadow ray (a point: its disc
    // matters for the direct sun only).
    const std::vector<Vec3>& suns = *tTally->suns;
    for (size_t j = 0; j < suns.size(); ++j) {
      const double cosI = glm::dot(n, suns[j]);
      if (cosI <= 0.0) continue;
      tTally->sunIndirect[j] += photopic(tTally->outer * transmittance(p, suns[j], kInf, skip, kNoShape)) * cosI;
    }
  }
  if (scene_.sky && !(tTally && !tTally->patches)) {
    // The sky by importance sampling of its luminance, MIS-weighted against cosine sampling.
    const SkyDome& sky = *scene_.sky;
    Rgb sum(0.0);
    double y1 = 0.0, y2 = 0.0;
    for (int i = 0; i < k; ++i) {
      const Vec2 u = strata.sample(i, rng);
      double ps = 0.0;
      const Vec3 t = sky.model->sample(u.x, u.y, &ps);
      const Vec3 dir = trueToModel(t, sky.northDeg);
      const double cosI = glm::dot(n, dir);
      if (cosI <= 0.0 || ps <= 0.0) continue;
      const double pc = cosI * kInvPi / misRatio;
      const double w = ps * ps / (ps * ps + pc * pc);
      const Rgb v = transmittance(p, dir, kInf, skip, kNoShape);
      const Rgb g = v * (w * sky.model->luminance(t) / kLumensPerWatt * cosI / ps);
      if (tTally && tTally->patches && !(tTally->directApart && !atPathVertex))
        tallySky(dir, v * (w * cosI / ps / k), !atPathVertex);
      sum += g;
      y1 += photopic(g);
      y2 += photopic(g) * photopic(g);
    }
    total += sum / static_cast<double>(k);
    if (variance && k > 1) {
      const double mean = y1 / k;
      *variance += std::max(0.0, y2 / k - mean * mean) / (k - 1);
    }
  }
  return total;
}

Rgb Tracer::radiance(const Vec3& origin, const Vec3& direction, uint32_t skip, bool countSources, Rng& rng,
                     const TraceSettings& s) const {
  return pathRadiance(origin, direction, skip, countSources, rng, s, 0, 1);
}

Rgb Tracer::pathRadiance(const Vec3& origin, const Vec3& direction, uint32_t skip, bool countSources, Rng& rng,
                         const TraceSettings& s, int diffuse, int split, double misCosPdf, double misRatio,
                         CacheUse* cache, double* firstHitT, int mirrorsBefore) const {
  Rgb result(0.0), beta(1.0);
  Vec3 o = origin, d = direction;
  // A path that does not count sources (they are sampled at its last diffuse vertex) and meets
  // one flat mirror keeps not counting them: the mirror's virtual sources were sampled too, with
  // their visibility through transmitting surfaces before and after the mirror. Beyond that one
  // reflection (a second mirror, glass reflection) it counts them again. mirrorsBefore carries
  // the mirrors met before a trans surface's specular transmission continued the path.
  bool viaImage = false;
  int mirrorsMet = mirrorsBefore;
  bool reflected = false;  // a specular reflection on the way (for the sky tally's direct part)
  // Specular and pass-through events are followed iteratively; a diffuse vertex ends the loop.
  for (int vertex = 0; vertex < 64; ++vertex) {
    RayHit h;
    countRay();
    const bool hit = accel_->intersect(o, d, 0.0, kInf, h, skip);
    if (vertex == 0 && firstHitT) *firstHitT = hit ? h.t : kInf;
    if (!hit) {
      if (tTally && tTally->patches && scene_.sky && !(tTally->directApart && diffuse == 0 && !reflected)) {
        // Sky (MIS-weighted as distantRadiance weighs it) or ground (always in full).
        double w = 1.0;
        if (d.z > 0.0 && misCosPdf > 0.0) {
          const double ps = misRatio * scene_.sky->model->pdf(modelToTrue(d, scene_.sky->northDeg));
          w = misCosPdf * misCosPdf / (misCosPdf * misCosPdf + ps * ps);
        }
        tallySky(d, beta * w, diffuse == 0 && !reflected);
      }
      return result + beta * distantRadiance(d, countSources, misCosPdf, misRatio);
    }
    const Vec3 x = o + h.t * d;
    const Shape& shape = scene_.shapes[h.shape];
    const Material* m = &scene_.materials[shape.material];
    const Vec3 ng = shapeNormal(shape, x);
    const bool front = glm::dot(d, ng) < 0.0;
    const Vec3 nf = front ? ng : -ng;  // faces the incoming ray
    const double off = originOffset(x);
    const uint32_t flatSkip = isFlat(shape) ? h.shape : kNoShape;
    if (m->type == MaterialType::kIllum) {
      if (m->alternate < 0) {  // invisible to non-shadow rays: pass straight through
        o = x - off * nf;
        skip = flatSkip;
        continue;
      }
      m = &scene_.materials[m->alternate];
    }
    switch (m->type) {
      case MaterialType::kLight:
      case MaterialType::kIllum:
        return (countSources && front) ? result + beta * m->color : result;
      case MaterialType::kGlow:
        return front ? result + beta * m->color : result;
      case MaterialType::kVoid:
        return result;
      case MaterialType::kMirror:
        misCosPdf = 0.0;  // the sky seen in a mirror is not sampled directly
        reflected = true;
        beta *= m->color;
        d = d - 2.0 * glm::dot(d, ng) * ng;
        o = x + off * nf;
        skip = flatSkip;
        if (!countSources && mirrorsMet == 0 && isMirrorImage_[h.shape]) {
          viaImage = true;
        } else {
          countSources = true;
          viaImage = false;
        }
        ++mirrorsMet;
        continue;
      case MaterialType::kGlass: {
        Rgb tr, rf;
        thinGlass(m->color, m->refractiveIndex, glm::dot(d, ng), tr, rf);
        const double pt = photopic(tr), pr = photopic(rf);
        if (pt + pr <= 0.0) return result;
        if (rng.uniform() * (pt + pr) < pt) {
          beta *= tr * ((pt + pr) / pt);
          o = x - off * nf;
          // Thin glass keeps the direction: whether sources count is the incoming ray's state
          // (shadow rays through the same glass already carried them from a diffuse vertex).
        } else {
          beta *= rf * ((pt + pr) / pr);
          reflected = true;
          d = d - 2.0 * glm::dot(d, ng) * ng;
          o = x + off * nf;
          misCosPdf = 0.0;
          countSources = true;
          viaImage = false;
        }
        skip = flatSkip;
        continue;
      }
      case MaterialType::kDielectric: {
        // A smooth boundary into (front face) or out of (back face) a medium of index n: the ray
        // reflects with probability R (Fresnel, unpolarised; 1 beyond the critical angle) or
        // refracts (Snell), so each event carries weight 1 and the estimator is unbiased. A ray
        // that meets the back face travelled inside: Beer–Lambert, transmission per metre raised
        // to the distance (as Radiance's dielectric). No dispersion (the Hartmann constant is
        // ignored) and radiance is not scaled by n² inside (the factors cancel for sensors and
        // sources outside). Shadow rays cannot pass (transmittance()), so sources and the sky
        // seen through it count in full.
        if (!front)
          for (int c = 0; c < 3; ++c) beta[c] *= std::pow(m->color[c], h.t);
        const double eta = front ? m->refractiveIndex : 1.0 / m->refractiveIndex;
        const Fresnel f = fresnel(-glm::dot(d, nf), eta);
        if (rng.uniform() < f.unpolarised()) {
          d = d - 2.0 * glm::dot(d, nf) * nf;
          o = x + off * nf;
        } else {
          d = refractDirection(d, nf, eta, f.cosT);
          o = x - off * nf;
        }
        skip = flatSkip;
        misCosPdf = 0.0;
        countSources = true;
        viaImage = false;
        reflected = true;  // bent: the sky tally's patch-by-patch shadow rays cannot see through it
        continue;
      }
      default:
        break;
    }
    // plastic, metal, trans: their diffuse parts (specular lobes: see docs/engine.md).
    if (diffuse + 1 > s.maxBounces) return result;
    if (cache && cache->cache && diffuse == cache->depth && cacheable(*m)) {
      // Ward's cache: direct light sampled here, indirect irradiance interpolated.
      Rgb e(0.0);
      cache->scratch.weights.clear();
      if (cache->cache->interpolate(x, nf, e, &cache->scratch, h.shape)) {
        const Vec3 xf = x + off * nf;
        const Rgb direct = directIrradiance(xf, nf, std::max(1, s.cache.lightSamples), flatSkip, rng, nullptr, 1.0);
        const Rgb f = beta * m->diffuseReflectance * kInvPi;
        const double fy = photopic(f);
        for (const auto& [i, w] : cache->scratch.weights) {
          RecordVector b = lookupVector(cache->cache->record(i), x, nf, cache->cache->settings().gradients);
          for (double& v : b) v *= fy * w;
          cache->tally.add(i, b);
        }
        cache->tally.addCachedValue(photopic(f * e));
        result += f * (direct + e);
        if (photopic(m->specularReflectance) > 0.0)
          result += beta * glossyBounce(x, d, nf, off, flatSkip, *m, rng, s, diffuse);
        return result;
      }
      ++cache->misses;
      return result + beta * diffuseVertex(x, d, nf, off, flatSkip, *m, rng, s, diffuse, 1, countSources,
                                           misCosPdf, misRatio, mirrorsMet);
    }
    const TallyFactor tf(beta);
    return result + beta * diffuseVertex(x, d, nf, off, flatSkip, *m, rng, s, diffuse, split, countSources,
                                         misCosPdf, misRatio, mirrorsMet);
  }
  return result;
}

Rgb Tracer::diffuseVertex(const Vec3& x, const Vec3& inDir, const Vec3& nf, double off, uint32_t flatSkip, const Material& m, Rng& rng,
                          const TraceSettings& s, int diffuse, int split, bool countSources,
                          double misCosPdf, double misRatio, int mirrorsMet) const {
  const Rgb rho = m.diffuseReflectance, tauD = m.diffuseTransmittance, tauS = m.specularTransmittance;
  const Vec3 xf = x + off * nf, xb = x - off * nf;
  const int k = std::max(1, split);
  Rgb out(0.0);
  // Light reflected (and diffusely transmitted) from the sampled sources.
  if (photopic(rho) > 0.0) {
    const TallyFactor tf(rho * kInvPi);
    out += rho * kInvPi * directIrradiance(xf, nf, k, flatSkip, rng, nullptr, 1.0);
  }
  if (photopic(tauD) > 0.0) {
    const TallyFactor tf(tauD * kInvPi);
    out += tauD * kInvPi * directIrradiance(xb, -nf, k, flatSkip, rng, nullptr, 1.0);
  }
  // Indirect light: k continuations (stratified when k > 1), each one event chosen with
  // probability equal to its photopic albedo (Russian roulette by albedo: unbiased, a path ends
  // with probability 1 − albedo).
  const double pRho = photopic(rho), pTd = photopic(tauD), pTs = photopic(tauS);
  const double pSp = m.type == MaterialType::kMirror ? 0.0 : photopic(m.specularReflectance);
  const double norm = std::max(1.0, pRho + pTd + pTs + pSp);
  if (pRho + pTd + pTs + pSp <= 0.0) return out;
  const Strata2D strata(k, 1.0 / kPi);
  Rgb acc(0.0);
  for (int j = 0; j < k; ++j) {
    const Vec2 u12 = strata.sample(j, rng);
    const double u = rng.uniform() * norm;
    if (u < pRho) {
      const Vec3 dir = Frame::fromNormal(nf).toWorld(sampleCosineHemisphere(u12.x, u12.y));
      const TallyFactor tf(rho * (norm / pRho / k));
      acc += rho * (norm / pRho) *
             pathRadiance(xf, dir, flatSkip, false, rng, s, diffuse + 1, 1, glm::dot(dir, nf) * kInvPi, 1.0);
    } else if (u < pRho + pTd) {
      const Vec3 dir = Frame::fromNormal(-nf).toWorld(sampleCosineHemisphere(u12.x, u12.y));
      const TallyFactor tf(tauD * (norm / pTd / k));
      acc += tauD * (norm / pTd) *
             pathRadiance(xb, dir, flatSkip, false, rng, s, diffuse + 1, 1, -glm::dot(dir, nf) * kInvPi, 1.0);
    } else if (u < pRho + pTd + pTs) {
      // Specular transmission (trans): straight on, as Radiance's trans does with roughness 0.
      // Straight on, so sources count as they did for the incoming ray (shadow rays through the
      // trans already carried them to diffuse vertices, and mirror images through it), and the
      // sky keeps the incoming ray's MIS weight (sky samples' shadow rays pass the trans too).
      const TallyFactor tf(tauS * (norm / pTs / k));
      acc += tauS * (norm / pTs) * pathRadiance(xb, inDir, flatSkip, countSources, rng, s, diffuse, 1, misCosPdf,
                                                misRatio, nullptr, nullptr, mirrorsMet);
    } else if (u < pRho + pTd + pTs + pSp) {
      const TallyFactor tf(norm / pSp / k);
      acc += (norm / pSp) * glossyBounce(x, inDir, nf, off, flatSkip, m, rng, s, diffuse);
    }
  }
  return out + acc / static_cast<double>(k);
}

Rgb Tracer::glossyBounce(const Vec3& x, const Vec3& inDir, const Vec3& nf, double off, uint32_t flatSkip,
                         const Material& m, Rng& rng, const TraceSettings& s, int diffuse) const {
  // Radiance's isotropic Ward lobe, exp(−tan² δ/α²)/(4π α² √(cos θ_i cos θ_o)) for roughness α,
  // sampled by its half vector h (tan² δ = −α² ln u, φ uniform: Ward 1992; Walter 2005, "Notes
  // on the Ward BRDF"). As Radiance's sampled specular rays do, a sample carries the specular
  // reflectance ρ_s, and a direction below the surface is drawn again (up to 8 times, then the
  // sample is lost). Roughness 0 is the mirror direction. Sources met are counted (the light
  // sampled at the vertex is the diffuse part's only); glossy reflections count as bounces.
  const Vec3 wi = -inDir;
  if (glm::dot(wi, nf) <= 0.0) return Rgb(0.0);
  Vec3 out(0.0);
  const double alpha = m.roughness;
  bool ok = false;
  if (alpha <= 0.0) {
    out = inDir - 2.0 * glm::dot(inDir, nf) * nf;
    ok = true;
  } else {
    const Frame frame = Frame::fromNormal(nf);
    for (int attempt = 0; attempt < 8 && !ok; ++attempt) {
      const double u1 = rng.uniform(), u2 = rng.uniform();
      const double tan2 = -alpha * alpha * std::log(std::max(1e-300, 1.0 - u1));
      const double cosD = 1.0 / std::sqrt(1.0 + tan2), sinD = std::sqrt(std::max(0.0, 1.0 - cosD * cosD));
      const double phi = kTwoPi * u2;
      const Vec3 h = frame.toWorld(Vec3(sinD * std::cos(phi), sinD * std::sin(phi), cosD));
      out = 2.0 * glm::dot(wi, h) * h - wi;
      ok = glm::dot(out, nf) > 0.0;
    }
  }
  if (!ok) return Rgb(0.0);
  const TallyFactor tf(m.specularReflectance);
  return m.specularReflectance * pathRadiance(x + off * nf, out, flatSkip, true, rng, s, diffuse + 1, 1);
}

IrradianceEstimate Tracer::irradiance(const Vec3& p, const Vec3& n, uint64_t pointIndex,
                                      const TraceSettings& s) const {
  return irradiance(p, n, pointIndex, s, nullptr);
}

namespace {
// The stream of a point's hemisphere directions under the cache method, apart from its other
// samples, so that phase A (cacheQueries) traces exactly the directions evaluation will.
constexpr uint64_t kDirectionStream = 0x4000000000000000ULL;
// The stream of a point's patch-by-patch direct sky samples (skyCoefficients).
constexpr uint64_t kPatchStream = 0x1000000000000000ULL;
}  // namespace

void Tracer::skyCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                             const SkyPatches& patches, double* direct, double* indirect,
                             bool directByPatch) const {
  if (!scene_.sky) throw std::logic_error("skyCoefficients needs a scene with a sky");
  TraceSettings t = s;
  t.method = Method::kPath;
  t.adaptiveFraction = 0.0;
  t.targetRelativeError = 0.0;
  // The sky seen directly, patch by patch: s.lightSamples stratified directions in each (uniform
  // in solid angle; the ground takes 4× as many, being 2π sr), each with its shadow ray through
  // glass and trans as the point estimator's would. Every patch gets its own samples, so a
  // small bright patch (the circumsolar sky) is known as well as a large dim one, which sky
  // samples drawn over the whole hemisphere cannot give a patch seen through a window.
  Rng rng(s.seed, kPatchStream + pointIndex);
  for (int b = 0; directByPatch && b < patches.count(); ++b) {
    const Strata2D strata(std::max(1, s.lightSamples) * (b == 0 ? 4 : 1));
    double sum = 0.0;
    for (int i = 0; i < strata.size(); ++i) {
      const Vec2 u = strata.sample(i, rng);
      const Vec3 d = trueToModel(patches.sample(b, u.x, u.y), scene_.sky->northDeg);
      const double c = glm::dot(n, d);
      if (c <= 0.0) continue;
      sum += c * photopic(transmittance(p, d, kInf, kNoShape, kNoShape));
    }
    direct[b] += patches.solidAngle(b) * sum / strata.size();
  }
  SkyTally tally;
  tally.patches = &patches;
  tally.northDeg = scene_.sky->northDeg;
  tally.direct = direct;
  tally.indirect = indirect;
  tally.directApart = directByPatch;
  withTally(tally, [&] { irradiance(p, n, pointIndex, t, nullptr); });
  flushRays();
}

void Tracer::sunCoefficients(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                             const std::vector<Vec3>& sunDirsModel, double* indirect) const {
  TraceSettings t = s;
  t.method = Method::kPath;
  t.adaptiveFraction = 0.0;
  t.targetRelativeError = 0.0;
  SkyTally tally;
  tally.suns = &sunDirsModel;
  tally.sunIndirect = indirect;
  withTally(tally, [&] { irradiance(p, n, pointIndex, t, nullptr); });
}

bool Tracer::cacheable(const Material& m) {
  return (m.type == MaterialType::kPlastic || m.type == MaterialType::kMetal ||
          m.type == MaterialType::kTrans) &&
         photopic(m.diffuseReflectance) > 0.0 && photopic(m.diffuseTransmittance) <= 0.0 &&
         photopic(m.specularTransmittance) <= 0.0;
}

void Tracer::cacheQueries(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                          std::vector<CacheQuery>& out) const {
  if (s.maxBounces < 1) return;
  Rng dirRng(s.seed, kDirectionStream + pointIndex);
  const int mTheta = std::max(1, static_cast<int>(std::lround(std::sqrt(s.hemisphereSamples / kPi))));
  const int nPhi = std::max(1, s.hemisphereSamples / mTheta);
  hemisphereCacheQueries(p, Frame::fromNormal(n), mTheta, nPhi, kNoShape, dirRng, out);
}

void Tracer::hemisphereCacheQueries(const Vec3& o, const Frame& frame, int mTheta, int nPhi, uint32_t skip,
                                    Rng& dirRng, std::vector<CacheQuery>& out) const {
  for (int c = 0; c < mTheta * nPhi; ++c) {
    const int j = c / nPhi, k = c % nPhi;
    const double u1 = (j + dirRng.uniform()) / mTheta;
    const double u2 = (k + dirRng.uniform()) / nPhi;
    const Vec3 dir = frame.toWorld(sampleCosineHemisphere(u1, u2));
    RayHit h;
    countRay();
    if (!accel_->intersect(o, dir, 0.0, kInf, h, skip)) continue;
    const Shape& shape = scene_.shapes[h.shape];
    const Material* m = &scene_.materials[shape.material];
    if (m->type == MaterialType::kIllum) {
      if (m->alternate < 0) continue;
      m = &scene_.materials[m->alternate];
    }
    if (!cacheable(*m)) continue;
    const Vec3 x = o + h.t * dir;
    const Vec3 ng = shapeNormal(shape, x);
    out.push_back({x, glm::dot(dir, ng) < 0.0 ? ng : -ng, isFlat(shape) ? h.shape : kNoShape, h.shape});
  }
  flushRays();
}

bool Tracer::cacheVisible(const Vec3& p, const Vec3& n, uint32_t shape, const IrradianceRecord& r) const {
  const Vec3 a = p + originOffset(p) * n, b = r.p + originOffset(r.p) * r.n;
  const Vec3 d = b - a;
  const double len = glm::length(d);
  if (len <= 0.0) return true;
  // Both endpoints' own shapes are skipped: a chord of a convex surface passes inside it.
  countRay();
  return !accel_->occluded(a, d / len, 0.0, len, shape, r.shape);
}

double Tracer::harmonicMeanDistance(const CacheQuery& q, int rays, Rng& rng) const {
  const Strata2D strata(std::max(1, rays), 1.0 / kPi);
  const Frame frame = Frame::fromNormal(q.n);
  const Vec3 o = q.p + originOffset(q.p) * q.n;
  double inv = 0.0;
  for (int i = 0; i < strata.size(); ++i) {
    const Vec2 u = strata.sample(i, rng);
    RayHit h;
    countRay();
    if (accel_->intersect(o, frame.toWorld(sampleCosineHemisphere(u.x, u.y)), 0.0, kInf, h, q.skip))
      inv += 1.0 / std::max(h.t, 1e-9);
  }
  flushRays();
  return inv > 0.0 ? strata.size() / inv : kInf;
}

namespace {
// A record's hemisphere directions come from a stream of their own (its value stream + this),
// so that the second level's phase A (recordQueries) traces exactly the directions phase B will.
constexpr uint64_t kRecordDirectionOffset = 1ULL << 56;

int recordThetaStrata(const TraceSettings& s) {
  return std::max(1, static_cast<int>(std::lround(std::sqrt(s.cache.recordSamples / kPi))));
}
int recordPhiStrata(const TraceSettings& s) { return std::max(2, s.cache.recordSamples / recordThetaStrata(s)); }
}  // namespace

void Tracer::recordQueries(const IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                           std::vector<CacheQuery>& out) const {
  Rng dirRng(s.seed, stream + kRecordDirectionOffset);
  hemisphereCacheQueries(r.p + originOffset(r.p) * r.n, Frame::fromNormal(r.n), recordThetaStrata(s),
                         recordPhiStrata(s), r.skip, dirRng, out);
}

void Tracer::computeRecord(IrradianceRecord& r, uint64_t stream, const TraceSettings& s,
                           const IrradianceCache* deeper, int level) const {
  Rng rng(s.seed, stream), dirRng(s.seed, stream + kRecordDirectionOffset);
  HemisphereSamples h;
  h.m = recordThetaStrata(s);
  h.n = recordPhiStrata(s);
  const int cells = h.m * h.n;
  h.radiance.resize(cells);
  h.distanceM.resize(cells);
  h.local.resize(cells);
  const Frame frame = Frame::fromNormal(r.n);
  const Vec3 o = r.p + originOffset(r.p) * r.n;
  thread_local CacheUse use;
  use.cache = deeper;
  use.depth = level;
  use.tally.clear();
  for (int c = 0; c < cells; ++c) {
    const int j = c / h.n, k = c % h.n;
    const double u1 = (j + dirRng.uniform()) / h.m;
    const double u2 = (k + dirRng.uniform()) / h.n;
    h.local[c] = sampleCosineHemisphere(u1, u2);
    const Vec3 dir = frame.toWorld(h.local[c]);
    // Everything but the sampled sources (which every lookup samples itself): sky and glow seen,
    // and light reflected by deeper bounces: from the second-level cache at the rays' first
    // diffuse hits when there is one, path traced with Russian roulette by albedo beyond.
    use.tally.setCell(c);
    h.radiance[c] = pathRadiance(o, dir, r.skip, false, rng, s, level, 1, h.local[c].z * kInvPi, 1.0,
                                 deeper ? &use : nullptr, &h.distanceM[c]);
  }
  setRecordValue(r, h, frame);
  // The second level's records, shared by this record's cells and by other records, give
  // Var = Σ_j B_jᵀ C_j B_j; kept apart (sharedSd) because other records share them.
  r.sharedSd = deeper ? std::sqrt(use.tally.recordVariance(*deeper, kPi / static_cast<double>(cells), nullptr)) : 0.0;
  flushRays();
}

IrradianceEstimate Tracer::irradiance(const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                                      const IrradianceCache* cache) const {
  Rng rng(s.seed, pointIndex);
  // Path method: directions from the point's one stream (as before the cache existed); cache
  // method: from a stream of their own (see cacheQueries).
  Rng dirRng(s.seed, kDirectionStream + pointIndex);
  Rng& jitter = cache ? dirRng : rng;
  thread_local CacheUse use;
  use.cache = cache;
  use.depth = 0;
  use.tally.clear();
  IrradianceEstimate est;
  double var = 0.0;
  const int mThetaN = std::max(1, static_cast<int>(std::lround(std::sqrt(s.hemisphereSamples / kPi))));
  const int cellsN = mThetaN * std::max(1, s.hemisphereSamples / mThetaN);
  const double misRatio = static_cast<double>(std::max(1, s.lightSamples)) / cellsN;
  est.irradiance = directIrradiance(p, n, std::max(1, s.lightSamples), kNoShape, rng, &var, misRatio);

  // Hemisphere: the paper's eq. 3, E ≈ (π / MN) Σ L(θ_j, φ_k) with θ_j = asin√((j + X)/M) and
  // φ_k = 2π(k + Y)/N, N ≈ πM: one sample per stratum.
  const int mTheta = std::max(1, static_cast<int>(std::lround(std::sqrt(s.hemisphereSamples / kPi))));
  const int nPhi = std::max(1, s.hemisphereSamples / mTheta);
  const int cells = mTheta * nPhi;
  const Frame frame = Frame::fromNormal(n);
  thread_local std::vector<Rgb> value;
  thread_local std::vector<double> y, diff, ownBetween, ownWithin;
  thread_local std::vector<int> order, counts;
  value.assign(cells, Rgb(0.0));
  y.assign(cells, 0.0);
  counts.assign(cells, 1);
  ownBetween.assign(cells, std::numeric_limits<double>::quiet_NaN());
  ownWithin.assign(cells, 0.0);
  auto sampleCell = [&](int cell, double su, double sv, int sub) {
    // Jittered sample of sub-stratum (su, sv) of `sub`×`sub` inside the cell.
    const int j = cell / nPhi, k = cell % nPhi;
    const double u1 = (j + (su + jitter.uniform()) / sub) / mTheta;
    const double u2 = (k + (sv + jitter.uniform()) / sub) / nPhi;
    const Vec3 dir = frame.toWorld(sampleCosineHemisphere(u1, u2));
    const TallyFactor tf(kPi / cells);  // the ray's share of E (sky tally: never refined)
    use.tally.setCell(cell);
    if (cache)
      return pathRadiance(p, dir, kNoShape, false, rng, s, 0, 1, glm::dot(dir, n) * kInvPi, misRatio, &use);
    return pathRadiance(p, dir, kNoShape, false, rng, s, 0, s.firstBounceSplit, glm::dot(dir, n) * kInvPi, misRatio);
  };
  for (int c = 0; c < cells; ++c) {
    value[c] = sampleCell(c, 0, 0, 1);
    y[c] = photopic(value[c]);
  }
  // Adaptive super-sampling (after Radiance's ambient super-samples, -as): strata whose
  // neighbours disagree most (range of the four neighbours' values; φ wraps around) get sub×sub
  // more samples. The choice for a stratum never looks at its own sample, so every sample in it
  // stays an unbiased estimate of its mean (choosing by its own value, as -as does, biases the
  // strata left alone towards their neighbours).
  const int sub = 2;
  // (Not while tallying sky coefficients: a refined stratum's first sample would change weight.)
  // Under the cache method the first samples' second differences also carry the records' noise
  // (neighbouring cells using different records differ by it), which the records' own term
  // Σ BᵀC B below counts already: its expected share of each d_c², Σ_i d_ciᵀ C_i d_ci, is
  // subtracted (the sum clamped at 0 only after summing over the cells).
  thread_local std::vector<double> dRec;
  dRec.assign(cells, 0.0);
  if (cache) use.tally.secondDifferenceVariance(*cache, use.tally.mark(), mTheta, nPhi, dRec);
  const int refine =
      tTally ? 0 : std::min(cells, static_cast<int>(s.adaptiveFraction * cells) / (sub * sub));
  if (refine > 0) {
    diff.assign(cells, 0.0);
    // Under the cache method the strata are chosen without the radiance their samples took from
    // the records: neighbouring strata share records, so a choice made on the records' values
    // looks at the refined stratum's own records after all, and its sub-samples (spread over
    // the records around) then weigh an extreme record more exactly when it is extreme. That
    // added variance the error bar cannot see: measured over 400 seeds in the integrating
    // sphere (ρ 0.5, 512 samples, a 0.2, 256-ray records), the records' share of the variance
    // was 2.7× their Σ BᵀCB, and 1.07× with this choice (docs/accuracy.md).
    thread_local std::vector<double> ySel;
    ySel = y;
    if (cache)
      for (int c = 0; c < cells; ++c) ySel[c] -= use.tally.cachedValue(c);
    for (int c = 0; c < cells; ++c) {
      const int j = c / nPhi, k = c % nPhi;
      double lo = std::min(ySel[j * nPhi + (k + 1) % nPhi], ySel[j * nPhi + (k + nPhi - 1) % nPhi]);
      double hi = std::max(ySel[j * nPhi + (k + 1) % nPhi], ySel[j * nPhi + (k + nPhi - 1) % nPhi]);
      if (j > 0) lo = std::min(lo, ySel[c - nPhi]), hi = std::max(hi, ySel[c - nPhi]);
      if (j + 1 < mTheta) lo = std::min(lo, ySel[c + nPhi]), hi = std::max(hi, ySel[c + nPhi]);
      diff[c] = hi - lo;
    }
    order.resize(cells);
    for (int c = 0; c < cells; ++c) order[c] = c;
    std::partial_sort(order.begin(), order.begin() + refine, order.end(), [&](int a, int b) {
      return diff[a] > diff[b] || (diff[a] == diff[b] && a < b);
    });
    thread_local std::vector<double> yFirst;
    yFirst = y;
    for (int r = 0; r < refine; ++r) {
      const int c = order[r];
      if (diff[c] <= 0.0) break;
      // The variance of this cell's mean ȳ = (y0 + Σ y_q)/(1 + m) of its first sample y0 (over
      // the whole cell: mean μ, variance σ²) and one sample y_q in each of its m sub-strata
      // (means μ_q, variances σ_q²), all independent: Var(ȳ) = (σ² + W)/(1 + m)², W = Σ σ_q².
      // With ȳ_s the sub-samples' mean, S = Σ (y_q − ȳ_s)² and A = (y0 − ȳ_s)²:
      // E[S] = B + (1 − 1/m) W, B = Σ (μ_q − μ)², and E[A] = σ² + W/m², σ² = (W + B)/m; so
      // Ŵ = m (m A − S)/2 is unbiased for W, and Var(ȳ) = (S/m + (1 + 1/m²) Ŵ)/(1 + m)² in
      // expectation. The S part is kept apart, Ŵ's (of either sign) summed over cells first.
      Rgb acc = value[c];
      double ySub[sub * sub], mean = 0.0;
      thread_local std::vector<size_t> marks;
      marks.clear();
      for (int q = 0; q < sub * sub; ++q) {
        marks.push_back(use.tally.mark());
        const Rgb v = sampleCell(c, q / sub, q % sub, sub);
        acc += v;
        ySub[q] = photopic(v);
        mean += ySub[q] / (sub * sub);
      }
      const double mm = sub * sub, a = (y[c] - mean) * (y[c] - mean), norm = (1.0 + mm) * (1.0 + mm);
      double sq = 0.0;
      for (int q = 0; q < sub * sub; ++q) sq += (ySub[q] - mean) * (ySub[q] - mean);
      ownBetween[c] = sq / mm / norm;
      ownWithin[c] = mm * (mm * a - sq) / 2.0 * (1.0 + 1.0 / (mm * mm)) / norm;
      if (cache) {
        // Under the cache method y0 is not a sample like the others: phase A placed records at
        // the first samples' hits, so y0 always finds a record, while a sub-sample may miss
        // and be path traced (in the sphere at normal-like settings 17 % of them do, with far
        // more variance). E[A] = σ² + W/m² then fails and Ŵ above comes out far too small (the
        // variance apart from the records' was reported at 0.69 of the measured). Instead, Var(ȳ) = (Var(y0) + W)/(1 + m)²
        // with each part bounded from its own samples: Var(y0) by y0's second difference with
        // its neighbours' first samples (d0²/6, as an unrefined cell), W by S m/(m − 1)
        // (E[S] = B + (1 − 1/m) W, so this is W + B m/(m − 1) ≥ W); from both the records'
        // expected shares (counted in Σ BᵀC B) are taken off.
        const int j = c / nPhi, k = c % nPhi;
        const double d = yFirst[j * nPhi + (k + nPhi - 1) % nPhi] - 2.0 * yFirst[c] + yFirst[j * nPhi + (k + 1) % nPhi];
        marks.push_back(use.tally.mark());
        const double srec = use.tally.spreadVariance(*cache, marks);
        ownBetween[c] = d * d / 6.0 / norm;
        ownWithin[c] = ((sq - srec) * mm / (mm - 1.0) - dRec[c] / 6.0) / norm;
      }
      value[c] = acc / static_cast<double>(1 + sub * sub);
      counts[c] = 1 + sub * sub;
      y[c] = photopic(value[c]);
    }
  }
  Rgb sum(0.0);
  for (int c = 0; c < cells; ++c) sum += value[c];
  est.irradiance += kPi * sum / static_cast<double>(cells);
  const double strat = stratifiedVariance(y, mTheta, nPhi, &ownBetween, &ownWithin, cache ? &dRec : nullptr);
  var += strat;
  if (cache && !use.tally.empty()) {
    // The cached share, by the law of total variance: Var(E) = E[Var(E | records)] +
    // Var(E[E | records]). The first is what the hemisphere's strata show with the records
    // held fixed (stratifiedVariance above, less the records' expected share of the second
    // differences, dRec). The second: record i enters the estimate through its seven
    // quantities Q_i = (E, G_r, G_t) with coefficients B_i summed over the rays that use it
    // (engine/irradiance_cache.h), and the records are independent (own streams), so it is
    // Σ_i B_iᵀ C_i B_i — the gradients' noise and its correlation with E_i included (a value
    // extrapolated by a noisy gradient: Var(E_i) + Var(G·Δ) + 2 Cov, mostly cancelling where a
    // record is used on all its sides).
    const double rec = use.tally.recordVariance(*cache, kPi / static_cast<double>(cells), &counts);
    var += rec;
  }
  est.variancePhotopic = var;
  flushRays();
  return est;
}

}  // namespace candela
