#include "engine/materials.h"

#include "engine/fresnel.h"

#include <algorithm>
#include <cmath>

namespace candela {

bool isCacheable(const Material& m) {
  return (m.type == MaterialType::kPlastic || m.type == MaterialType::kMetal ||
          m.type == MaterialType::kTrans) &&
         photopic(m.diffuseReflectance) > 0.0 && photopic(m.diffuseTransmittance) <= 0.0 &&
         photopic(m.specularTransmittance) <= 0.0;
}

GlassEvent sampleThinGlass(const Material& m, const Vec3& d, const Vec3& ng, Rng& rng, Rgb& beta) {
  Rgb tr, rf;
  thinGlass(m.color, m.refractiveIndex, glm::dot(d, ng), tr, rf);
  const double pt = photopic(tr), pr = photopic(rf);
  if (pt + pr <= 0.0) return GlassEvent::kAbsorbed;
  if (rng.uniform() * (pt + pr) < pt) {
    beta *= tr * ((pt + pr) / pt);
    return GlassEvent::kTransmitted;
  }
  beta *= rf * ((pt + pr) / pr);
  return GlassEvent::kReflected;
}

void absorbInDielectric(const Material& m, double distanceM, Rgb& beta) {
  // Transmission per metre raised to the distance (as Radiance's dielectric).
  for (int c = 0; c < 3; ++c) beta[c] *= std::pow(m.color[c], distanceM);
}

DielectricEvent sampleDielectric(const Material& m, const Vec3& d, const Vec3& nf, bool front, Rng& rng) {
  // A smooth boundary into (front face) or out of (back face) a medium of index n: the ray
  // reflects with probability R (Fresnel, unpolarised; 1 beyond the critical angle) or refracts
  // (Snell), so each event carries weight 1 and the estimator is unbiased (a ray that meets the
  // back face travelled inside: absorbInDielectric). No dispersion (the Hartmann constant is ignored) and radiance is not
  // scaled by n² inside (the factors cancel for sensors and sources outside). Shadow rays cannot
  // pass (Tracer::transmittance), so sources and the sky seen through it count in full.
  const double eta = front ? m.refractiveIndex : 1.0 / m.refractiveIndex;
  const Fresnel f = fresnel(-glm::dot(d, nf), eta);
  if (rng.uniform() < f.unpolarised()) return {d - 2.0 * glm::dot(d, nf) * nf, true};
  return {refractDirection(d, nf, eta, f.cosT), false};
}

bool sampleWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) {
  // Radiance's isotropic Ward lobe, exp(−tan² δ/α²)/(4π α² √(cos θ_i cos θ_o)) for roughness α,
  // sampled by its half vector h (tan² δ = −α² ln u, φ uniform: Ward 1992; Walter 2005, "Notes
  // on the Ward BRDF"). As Radiance's sampled specular rays do, a direction below the surface is
  // drawn again (up to 8 times, then the sample is lost). Roughness 0 is the mirror direction.
  const Vec3 wi = -inDir;
  if (glm::dot(wi, nf) <= 0.0) return false;
  out = Vec3(0.0);
  const double alpha = m.roughness;
  if (alpha <= 0.0) {
    out = inDir - 2.0 * glm::dot(inDir, nf) * nf;
    return true;
  }
  const Frame frame = Frame::fromNormal(nf);
  bool ok = false;
  for (int attempt = 0; attempt < 8 && !ok; ++attempt) {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const double tan2 = -alpha * alpha * std::log(std::max(1e-300, 1.0 - u1));
    const double cosD = 1.0 / std::sqrt(1.0 + tan2), sinD = std::sqrt(std::max(0.0, 1.0 - cosD * cosD));
    const double phi = kTwoPi * u2;
    const Vec3 h = frame.toWorld(Vec3(sinD * std::cos(phi), sinD * std::sin(phi), cosD));
    out = 2.0 * glm::dot(wi, h) * h - wi;
    ok = glm::dot(out, nf) > 0.0;
  }
  return ok;
}

}  // namespace candela
