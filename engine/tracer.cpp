#include "engine/tracer.h"

#include "engine/sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool isFlat(const Shape& s) {
  return s.type == ShapeType::Triangle || s.type == ShapeType::Polygon || s.type == ShapeType::Ring;
}

// Thin glass with incoherent multiple reflections: per polarisation, single-surface Fresnel
// reflectance R and internal transmittance τ = tn^(1/cos θt) give
// T = (1−R)² τ / (1 − R² τ²) and R_total = R + (1−R)² R τ² / (1 − R² τ²), averaged over s and p.
// tn is Radiance's glass "transmissivity" argument.
void thinGlass(const Material& m, double cosI, Rgb& trans, Rgb& refl) {
  const double n = m.refractiveIndex;
  cosI = std::clamp(std::abs(cosI), 1e-6, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (n * n);
  const double cosT = std::sqrt(std::max(0.0, 1.0 - sin2T));
  const double rs = (cosI - n * cosT) / (cosI + n * cosT);
  const double rp = (cosT - n * cosI) / (cosT + n * cosI);
  trans = Rgb(0.0);
  refl = Rgb(0.0);
  for (double r : {rs * rs, rp * rp}) {
    for (int c = 0; c < 3; ++c) {
      const double tau = std::pow(m.color[c], 1.0 / cosT);
      const double den = 1.0 - r * r * tau * tau;
      trans[c] += 0.5 * (1.0 - r) * (1.0 - r) * tau / den;
      refl[c] += 0.5 * (r + (1.0 - r) * (1.0 - r) * r * tau * tau / den);
    }
  }
}

}  // namespace

Quality parseQuality(const std::string& s) {
  if (s == "draft") return Quality::Draft;
  if (s == "normal") return Quality::Normal;
  if (s == "high") return Quality::High;
  throw std::invalid_argument("quality must be draft, normal or high, not '" + s + "'");
}

TraceSettings settingsForQuality(Quality q) {
  TraceSettings s;
  switch (q) {
    case Quality::Draft:
      s.hemisphereSamples = 256;
      s.lightSamples = 16;
      s.maxBounces = 8;
      break;
    case Quality::Normal:
      s.hemisphereSamples = 2048;
      s.lightSamples = 64;
      s.maxBounces = 32;
      break;
    case Quality::High:
      s.hemisphereSamples = 8192;
      s.lightSamples = 256;
      s.maxBounces = 64;
      break;
  }
  return s;
}

double IrradianceEstimate::standardErrorLux() const {
  return kLumensPerWatt * std::sqrt(std::max(0.0, variancePhotopic));
}

double Tracer::originOffset(const Vec3& p) {
  // Doubles locate a hit to ~1e-15 of its coordinates; 1e-7 of the larger of 1 m and the
  // coordinates clears that by far while staying far below any modelled gap (≥ 0.1 mm).
  const double m = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 1e-7 * m;
}

Tracer::Tracer(const Scene& scene, OctreeOptions octree)
    : scene_(scene), octree_(scene, octree), lights_(collectLights(scene)) {
  for (const Material& m : scene.materials)
    if (m.type == MaterialType::Glass || m.type == MaterialType::Illum ||
        (m.type == MaterialType::Trans && photopic(m.specularTransmittance) > 0.0))
      hasTransmitters_ = true;
}

Rgb Tracer::transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB) const {
  if (!hasTransmitters_) return octree_.occluded(o, dir, 0.0, tMax, skipA, skipB) ? Rgb(0.0) : Rgb(1.0);
  // Walk the hits along the one ray, past each transmitting surface (same origin, growing tMin).
  Rgb t(1.0);
  double tMin = 0.0;
  for (int i = 0; i < 64; ++i) {
    Octree::Hit h;
    if (!octree_.intersect(o, dir, tMin, tMax, h, skipA, skipB)) return t;
    const Shape& s = scene_.shapes[h.shape];
    const Material& m = scene_.materials[s.material];
    const Vec3 x = o + h.t * dir;
    if (m.type == MaterialType::Glass) {
      Rgb tr, rf;
      thinGlass(m, glm::dot(dir, shapeNormal(s, x)), tr, rf);
      t *= tr;
    } else if (m.type == MaterialType::Trans) {
      t *= m.specularTransmittance;
    } else if (!(m.type == MaterialType::Illum && m.alternate < 0)) {
      return Rgb(0.0);  // opaque (an illum with no alternate is invisible to all but its own rays)
    }
    if (photopic(t) <= 0.0) return Rgb(0.0);
    tMin = h.t + originOffset(x);
  }
  return t;
}

Rgb Tracer::distantRadiance(const Vec3& dir, bool countSources) const {
  // Where sources at infinity overlap, the smallest one is seen (it lies in front of the larger,
  // as the sun in front of the sky).
  const DistantSource* seen = nullptr;
  for (const DistantSource& d : scene_.distant)
    if (glm::dot(dir, d.direction) >= d.cosHalfAngle && (!seen || d.solidAngleSr < seen->solidAngleSr)) seen = &d;
  if (!seen) return Rgb(0.0);
  const Material& m = scene_.materials[seen->material];
  if (m.type == MaterialType::Glow) return m.color;
  return countSources ? m.color : Rgb(0.0);
}

Rgb Tracer::directIrradiance(const Vec3& p, const Vec3& n, int k, uint32_t skip, Rng& rng, double* variance) const {
  Rgb total(0.0);
  const Strata2D strata(k);
  for (const Light& light : lights_) {
    Rgb exact;
    const bool haveExact = unoccludedIrradiance(light, scene_, p, n, exact);
    if (haveExact && photopic(exact) <= 0.0) continue;  // the source cannot reach this side
    // Control variate: E = E_exact + mean(w cos (V − 1)), unbiased, and exact wherever the source
    // is wholly visible; without a closed form: E = mean(w cos V).
    Rgb sum(0.0);
    double sumY = 0.0, sumY2 = 0.0;
    const uint32_t lightShape = light.kind == Light::Kind::Area ? light.shape : kNoShape;
    for (int i = 0; i < k; ++i) {
      const Vec2 u = strata.sample(i, rng);
      LightSample ls;
      Rgb g(0.0);
      if (sampleLight(light, scene_, p, u.x, u.y, ls)) {
        const double c = glm::dot(n, ls.dir);
        if (c > 0.0) {
          const Rgb f = ls.weight * c;
          const double tMax = std::isinf(ls.distance) ? kInf : ls.distance * (1.0 - 1e-9);
          const Rgb v = transmittance(p, ls.dir, tMax, skip, lightShape);
          g = haveExact ? f * (v - Rgb(1.0)) : f * v;
        }
      }
      sum += g;
      const double y = photopic(g);
      sumY += y;
      sumY2 += y * y;
    }
    total += (haveExact ? exact : Rgb(0.0)) + sum / static_cast<double>(k);
    if (variance && k > 1) {
      const double mean = sumY / k;
      *variance += std::max(0.0, sumY2 / k - mean * mean) / (k - 1);
    }
  }
  return total;
}

Rgb Tracer::radiance(const Vec3& origin, const Vec3& direction, uint32_t skip, bool countSources, Rng& rng,
                     const TraceSettings& s) const {
  Rgb result(0.0), beta(1.0);
  Vec3 o = origin, d = direction;
  int diffuse = 0;
  const int maxVertices = 64 + s.maxBounces;
  for (int vertex = 0; vertex < maxVertices; ++vertex) {
    Octree::Hit h;
    if (!octree_.intersect(o, d, 0.0, kInf, h, skip)) {
      result += beta * distantRadiance(d, countSources);
      break;
    }
    const Vec3 x = o + h.t * d;
    const Shape& shape = scene_.shapes[h.shape];
    const Material* m = &scene_.materials[shape.material];
    const Vec3 ng = shapeNormal(shape, x);
    const bool front = glm::dot(d, ng) < 0.0;
    const Vec3 nf = front ? ng : -ng;  // faces the incoming ray
    const double off = originOffset(x);
    const uint32_t flatSkip = isFlat(shape) ? h.shape : kNoShape;
    if (m->type == MaterialType::Illum) {
      if (m->alternate < 0) {  // invisible to non-shadow rays: pass straight through
        o = x - off * nf;
        skip = flatSkip;
        continue;
      }
      m = &scene_.materials[m->alternate];
    }
    if (m->type == MaterialType::Light || m->type == MaterialType::Illum) {
      if (countSources && front) result += beta * m->color;
      break;
    }
    if (m->type == MaterialType::Glow) {
      if (front) result += beta * m->color;
      break;
    }
    if (m->type == MaterialType::Void) break;
    if (m->type == MaterialType::Mirror) {
      beta *= m->color;
      d = d - 2.0 * glm::dot(d, ng) * ng;
      o = x + off * nf;
      skip = flatSkip;
      countSources = true;
      continue;
    }
    if (m->type == MaterialType::Glass) {
      Rgb tr, rf;
      thinGlass(*m, glm::dot(d, ng), tr, rf);
      const double pt = photopic(tr), pr = photopic(rf);
      if (pt + pr <= 0.0) break;
      if (rng.uniform() * (pt + pr) < pt) {
        beta *= tr * ((pt + pr) / pt);
        o = x - off * nf;
      } else {
        beta *= rf * ((pt + pr) / pr);
        d = d - 2.0 * glm::dot(d, ng) * ng;
        o = x + off * nf;
      }
      skip = flatSkip;
      countSources = true;
      continue;
    }
    // plastic, metal, trans: the diffuse parts (specular lobes: see docs/engine.md).
    if (diffuse + 1 > s.maxBounces) break;
    const Rgb rho = m->diffuseReflectance, tauD = m->diffuseTransmittance, tauS = m->specularTransmittance;
    const Vec3 xf = x + off * nf, xb = x - off * nf;
    if (photopic(rho) > 0.0) result += beta * rho * kInvPi * directIrradiance(xf, nf, 1, flatSkip, rng, nullptr);
    if (photopic(tauD) > 0.0) result += beta * tauD * kInvPi * directIrradiance(xb, -nf, 1, flatSkip, rng, nullptr);
    // Continue with one event chosen with probability equal to its photopic albedo (Russian
    // roulette by albedo: unbiased, paths end with probability 1 − albedo).
    const double pRho = photopic(rho), pTd = photopic(tauD), pTs = photopic(tauS);
    const double norm = std::max(1.0, pRho + pTd + pTs);
    const double u = rng.uniform() * norm;
    const double u1 = rng.uniform(), u2 = rng.uniform();
    if (u < pRho) {
      beta *= rho / pRho * norm;
      d = Frame::fromNormal(nf).toWorld(sampleCosineHemisphere(u1, u2));
      o = xf;
      ++diffuse;
      countSources = false;
    } else if (u < pRho + pTd) {
      beta *= tauD / pTd * norm;
      d = Frame::fromNormal(-nf).toWorld(sampleCosineHemisphere(u1, u2));
      o = xb;
      ++diffuse;
      countSources = false;
    } else if (u < pRho + pTd + pTs) {
      beta *= tauS / pTs * norm;
      o = xb;
      countSources = true;
    } else {
      break;
    }
    skip = flatSkip;
  }
  return result;
}

IrradianceEstimate Tracer::irradiance(const Vec3& p, const Vec3& n, uint64_t pointIndex,
                                      const TraceSettings& s) const {
  Rng rng(s.seed, pointIndex);
  IrradianceEstimate est;
  double var = 0.0;
  est.irradiance = directIrradiance(p, n, std::max(1, s.lightSamples), kNoShape, rng, &var);
  // Hemisphere: the paper's eq. 3, E ≈ (π / MN) Σ L(θ_j, φ_k) with θ_j = asin√((j + X)/M) and
  // φ_k = 2π(k + Y)/N, N ≈ πM.
  const int count = std::max(1, s.hemisphereSamples);
  const Strata2D strata(count, 1.0 / kPi);
  const Frame frame = Frame::fromNormal(n);
  Rgb sum(0.0);
  double sumY = 0.0, sumY2 = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec2 u = strata.sample(i, rng);
    const Vec3 dir = frame.toWorld(sampleCosineHemisphere(u.x, u.y));
    const Rgb l = radiance(p, dir, kNoShape, false, rng, s);
    sum += l;
    const double y = photopic(l);
    sumY += y;
    sumY2 += y * y;
  }
  est.irradiance += kPi * sum / static_cast<double>(count);
  if (count > 1) {
    const double mean = sumY / count;
    var += kPi * kPi * std::max(0.0, sumY2 / count - mean * mean) / (count - 1);
  }
  est.variancePhotopic = var;
  return est;
}

}  // namespace candela
