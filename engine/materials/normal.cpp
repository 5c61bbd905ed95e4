#include "engine/materials/normal.h"

#include <algorithm>
#include <cmath>

namespace candela {

void derivePlastic(MaterialParameters& m) {
  m.diffuseReflectance = m.color * (1.0 - m.specularity);
  m.specularReflectance = Rgb(m.specularity);
}

void deriveMetal(MaterialParameters& m) {
  m.diffuseReflectance = m.color * (1.0 - m.specularity);
  m.specularReflectance = m.color * m.specularity;
}

void deriveFromDiffuseReals(MaterialParameters& m) {
  m.diffuseReflectance = m.color;
  m.diffuseTransmittance = m.transmissionColor;
  m.specularReflectance = Rgb(0.0);
  m.specularTransmittance = Rgb(0.0);
}

void deriveTrans(MaterialParameters& m) {
  const Rgb nonSpec = m.color * (1.0 - m.specularity);
  m.diffuseReflectance = nonSpec * (1.0 - m.transmissivity);
  m.diffuseTransmittance = nonSpec * m.transmissivity * (1.0 - m.transmittedSpecular);
  m.specularTransmittance = nonSpec * m.transmissivity * m.transmittedSpecular;
  m.specularReflectance = Rgb(m.specularity);
}

bool NormalFamily::cacheable(const Material& m) const {
  return photopic(m.diffuseReflectance) > 0.0 && photopic(m.diffuseTransmittance) <= 0.0 &&
         photopic(m.specularTransmittance) <= 0.0;
}

void NormalFamily::readCommon(const MaterialReadContext& ctx, Material& m, size_t reals) {
  // Radiance reference manual: "mod plastic id 0 0 5 red green blue spec rough" (metal alike),
  // "mod trans id 0 0 7 red green blue spec rough trans tspec".
  ctx.expectStrings(0);
  ctx.expectReals(reals);
  const RadPrimitive& p = ctx.primitive;
  m.color = ctx.vec(0);
  m.specularity = p.reals[3];
  m.roughness = p.reals[4];
  if (reals == 7) {
    m.transmissivity = p.reals[5];
    m.transmittedSpecular = p.reals[6];
  }
  checkCommon(ctx, m, reals == 7);
}

void NormalFamily::checkCommon(const MaterialReadContext& ctx, const Material& m, bool transmits) {
  // A surface reflects and transmits at most what it receives.
  ctx.expectNonNegative(m.color);
  const std::string what = ctx.what();
  if (std::max({m.color.x, m.color.y, m.color.z}) > 1.0)
    ctx.fail(what + " reflects more than it receives: a colour component above 1");
  if (!(m.specularity >= 0.0 && m.specularity <= 1.0)) ctx.fail(what + " needs a specularity in [0, 1]");
  if (m.roughness < 0.0 || m.roughnessV < 0.0) ctx.fail(what + " has a negative roughness");
  if (transmits && !(m.transmissivity >= 0.0 && m.transmissivity <= 1.0 && m.transmittedSpecular >= 0.0 &&
                      m.transmittedSpecular <= 1.0))
    ctx.fail(what + " needs its transmission and transmitted specularity in [0, 1]");
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

bool sampleAnisotropicWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) {
  // Ward 1992, eq. 5a–b for sampling the anisotropic lobe by its half vector: the azimuth φ from
  // tan φ = (αy/αx) tan 2πu₂, then tan² δ = −ln u₁ / (cos² φ/αx² + sin² φ/αy²); a direction
  // below the surface is drawn again, up to 8 times, as the isotropic lobe does.
  const Vec3 wi = -inDir;
  if (glm::dot(wi, nf) <= 0.0) return false;
  const double ax = m.roughness, ay = m.roughnessV;
  if (ax <= 0.0 && ay <= 0.0) {
    out = inDir - 2.0 * glm::dot(inDir, nf) * nf;
    return true;
  }
  // The frame: u as given, projected on the surface; any tangent when it is along the normal.
  Vec3 u = m.anisotropyU - glm::dot(m.anisotropyU, nf) * nf;
  const double len = glm::length(u);
  u = len > 1e-9 ? u / len : Frame::fromNormal(nf).toWorld(Vec3(1, 0, 0));
  const Vec3 v = glm::cross(nf, u);
  bool ok = false;
  for (int attempt = 0; attempt < 8 && !ok; ++attempt) {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const Vec3 h = wardHalfVector(u, v, nf, ax, ay, u1, u2);
    out = 2.0 * glm::dot(wi, h) * h - wi;
    ok = glm::dot(out, nf) > 0.0;
  }
  return ok;
}

Vec3 wardHalfVector(const Vec3& u, const Vec3& v, const Vec3& n, double ax, double ay, double u1, double u2) {
  const double sx = std::max(ax, 1e-9), sy = std::max(ay, 1e-9);
  const double phi = std::atan2(sy * std::sin(kTwoPi * u2), sx * std::cos(kTwoPi * u2));
  const double c = std::cos(phi), s = std::sin(phi);
  const double tan2 = -std::log(std::max(1e-300, 1.0 - u1)) / (c * c / (sx * sx) + s * s / (sy * sy));
  const double cosD = 1.0 / std::sqrt(1.0 + tan2), sinD = std::sqrt(std::max(0.0, 1.0 - cosD * cosD));
  return sinD * c * u + sinD * s * v + cosD * n;
}

bool sampleWgmdTransmission(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) {
  Vec3 u = m.anisotropyU - glm::dot(m.anisotropyU, nf) * nf;
  const double len = glm::length(u);
  u = len > 1e-9 ? u / len : Frame::fromNormal(nf).toWorld(Vec3(1, 0, 0));
  const Vec3 v = glm::cross(nf, u);
  const double au = m.transmissionRoughnessU, av = m.transmissionRoughnessV;
  for (int trial = 0; trial < 10; ++trial) {
    const double phi = kTwoPi * rng.uniform();
    double c = std::cos(phi) * au, s = std::sin(phi) * av;
    const double norm = 1.0 / std::sqrt(c * c + s * s);
    c *= norm;
    s *= norm;
    const double r = std::max(1e-300, 1.0 - rng.uniform());  // in (0, 1]
    const double d = std::sqrt(-std::log(r) / (c * c / (au * au) + s * s / (av * av)));
    out = inDir + d * (c * u + s * v);
    if (glm::dot(out, nf) >= 0.0) continue;  // back on the side the ray came from
    out = glm::normalize(out);
    return true;
  }
  return false;
}

bool sampleWgmdLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) {
  const Vec3 wi = -inDir;
  if (glm::dot(wi, nf) <= 0.0) return false;
  if (m.roughness <= 0.0 && m.roughnessV <= 0.0) {
    out = inDir - 2.0 * glm::dot(inDir, nf) * nf;
    return true;
  }
  Vec3 u = m.anisotropyU - glm::dot(m.anisotropyU, nf) * nf;
  const double len = glm::length(u);
  u = len > 1e-9 ? u / len : Frame::fromNormal(nf).toWorld(Vec3(1, 0, 0));
  const double u1 = rng.uniform(), u2 = rng.uniform();
  const Vec3 h = wardHalfVector(u, glm::cross(nf, u), nf, m.roughness, m.roughnessV, u1, u2);
  out = 2.0 * glm::dot(wi, h) * h - wi;
  return glm::dot(out, nf) > 0.0;
}

}  // namespace candela
