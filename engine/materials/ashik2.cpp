// ashik2 (Radiance reference manual, "Ashik2"; src/rt/ashikhmin.c, m_ashikhmin): the
// Ashikhmin-Shirley anisotropic BRDF,
//   mod ashik2 id 4+ ux uy uz funcfile transform 0 8 dred dgrn dblu sred sgrn sblu u-exp v-exp
// The u direction is three functions of the function file, evaluated at each hit as plastic2's
// (read as a pattern into Material::functions), turned by the transform; v = n × u, u = v × n on
// the shading normal n, as Radiance's getacoords_as. The parts at a hit, as m_ashikhmin computes
// them:
// - diffuse: the diffuse colour times the patterns' colour, ρ_d E/π for the sky and the light
//   paths meet (Radiance's ambient), and ρ_d E (1 − (1 − cos θ_l)⁵)/π for the light of a sampled
//   source at θ_l from the normal (dirashik; MaterialFamily::sourceBrdf);
// - specular: the specular colour s raised by Schlick's Fresnel at the viewer's angle,
//   s + (1 − s)(1 − cos θ_v)⁵, not times the patterns' colour; the lobe sampled by its half vector
//   (ashikhmin.h), each sample carrying the BRDF times cos θ_o over its density,
//   s' cos θ_o / max(cos θ_o, cos θ_v); paths count the sources they meet, as for the Ward lobes.
#include "engine/materials/ashikhmin.h"
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

#include <algorithm>
#include <cmath>

namespace candela {

AshikhminLobe ashikhminLobe(const MaterialParameters& m, const Vec3& inDir, const Vec3& nf) {
  AshikhminLobe lobe;
  lobe.n = nf;
  lobe.nu = m.exponentU;
  lobe.nv = m.exponentV;
  lobe.viewCos = std::max(0.001, -glm::dot(inDir, nf));  // Radiance's pdot, never 0
  const Vec3 v = glm::cross(nf, m.anisotropyU);
  const double len = glm::length(v);
  if (!(len > 1e-12)) return lobe;
  lobe.v = v / len;
  lobe.u = glm::cross(lobe.v, nf);
  lobe.valid = true;
  return lobe;
}

namespace {
// (n·h)^(nu (u·h)² + nv (v·h)²)/(1 − (n·h)²)): 1 along the normal.
double lobePower(const AshikhminLobe& l, const Vec3& h) {
  const double nh = glm::dot(l.n, h);
  if (nh <= 0.0) return 0.0;
  const double s2 = 1.0 - nh * nh;
  if (s2 <= 1e-14) return 1.0;
  const double uh = glm::dot(l.u, h), vh = glm::dot(l.v, h);
  return std::pow(nh, (l.nu * uh * uh + l.nv * vh * vh) / s2);
}
}  // namespace

double ashikhminSpecular(const AshikhminLobe& l, const Vec3& wi, const Vec3& wo) {
  const double co = glm::dot(l.n, wo);
  if (!l.valid || co <= 0.0 || glm::dot(l.n, wi) <= 0.0) return 0.0;
  const Vec3 h = glm::normalize(wi + wo);
  return std::sqrt((l.nu + 1.0) * (l.nv + 1.0)) * lobePower(l, h) /
         (8.0 * kPi * glm::dot(wo, h) * std::max(co, l.viewCos));
}

double ashikhminDensity(const AshikhminLobe& l, const Vec3& wi, const Vec3& wo) {
  if (!l.valid) return 0.0;
  const Vec3 h = glm::normalize(wi + wo);
  const double ih = glm::dot(wi, h);
  if (ih <= 0.0) return 0.0;
  return std::sqrt((l.nu + 1.0) * (l.nv + 1.0)) * kInvPi * 0.5 * lobePower(l, h) / (4.0 * ih);
}

bool sampleAshikhmin(const AshikhminLobe& l, const Vec3& wi, double u1, double u2, Vec3& wo) {
  if (!l.valid) return false;
  // tan φ = √((nu+1)/(nv+1)) tan ψ with ψ = 2π u1 uniform: the same density in φ as the paper's
  // quarter-turn form reflected into the four quadrants.
  const double psi = kTwoPi * u1;
  const double a = std::sqrt(l.nu + 1.0), b = std::sqrt(l.nv + 1.0);
  const double cx = b * std::cos(psi), sy = a * std::sin(psi), r = std::hypot(cx, sy);
  const double cosPhi = cx / r, sinPhi = sy / r;
  const double cosT = std::pow(1.0 - u2, 1.0 / (l.nu * cosPhi * cosPhi + l.nv * sinPhi * sinPhi + 1.0));
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  const Vec3 h = sinT * cosPhi * l.u + sinT * sinPhi * l.v + cosT * l.n;
  wo = 2.0 * glm::dot(wi, h) * h - wi;
  return glm::dot(wo, l.n) > 0.0;
}

namespace {

class Ashik2 : public NormalFamily {
 public:
  MaterialType type() const override { return MaterialType::kAshik2; }
  const char* name() const override { return "ashik2"; }
  int functionPatterns() const override { return 1; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectReals(8);
    const RadPrimitive& p = ctx.primitive;
    m.color = ctx.vec(0);
    m.specularColor = ctx.vec(3);
    m.exponentU = p.reals[6];
    m.exponentV = p.reals[7];
    const std::string what = ctx.what();
    for (const Rgb& c : {m.color, m.specularColor}) {
      ctx.expectNonNegative(c);
      if (std::max({c.x, c.y, c.z}) > 1.0)
        ctx.fail(what + " reflects more than it receives: a diffuse or specular colour component above 1");
    }
    if (!(m.exponentU >= 0.0 && m.exponentV >= 0.0))
      ctx.fail(what + " needs its u and v exponents at least 0 (the lobe's √((nu+1)(nv+1)) and its powers)");
    // The rms slope of a Ward lobe as wide (Walter et al. 2007: a Phong exponent n is a Beckmann
    // roughness √(2/(n+2))): only read by the camera to tell a spread lobe from a mirror.
    m.roughness = std::sqrt(2.0 / (std::min(m.exponentU, m.exponentV) + 2.0));
  }
  void derive(MaterialParameters& m) const override {
    m.diffuseReflectance = m.color;
    m.specularReflectance = m.specularColor;  // at normal incidence; with the viewer's Fresnel at a hit
  }
  void atHit(const Material& m, const PatternPoint& p, const Rgb&, PatternEvaluator& eval,
             MaterialParameters& out) const override {
    out.anisotropyU = eval.direction(m.functions, p);
    const bool front = glm::dot(p.d, p.ng) < 0.0;
    const Vec3 ns = shadingNormal(out, front ? p.ng : -p.ng, front);
    const double fresnel = schlickFresnel(std::max(0.001, -glm::dot(p.d, ns)));
    out.diffuseReflectance = out.color;
    // Radiance adds the Fresnel term only when the specular colour is not black.
    out.specularReflectance = photopic(m.specularColor) > 0.0
                                  ? m.specularColor + (Rgb(1.0) - m.specularColor) * fresnel
                                  : Rgb(0.0);
  }
  // Never: a diffuse part weighs its sources' light by their angle (below), which no irradiance
  // estimate stands for.
  bool matteOpaque(const Material&) const override { return false; }
  // Radiance's dirashik: a sampled source's light on the diffuse part takes 1 − F(cos θ_l) of
  // its own angle (Schlick's F); the sky and the light paths meet do not (its ambient).
  bool directionalSources(const Material& m) const override { return photopic(m.diffuseReflectance) > 0.0; }
  Rgb sourceBrdf(const Material& m, const PatternPoint& at, PatternEvaluator&, const Vec3& ldir, double,
                 bool transmitted) const override {
    if (transmitted) return Rgb(0.0);
    return m.diffuseReflectance * (kInvPi * (1.0 - schlickFresnel(std::abs(glm::dot(at.ng, ldir)))));
  }
  bool sampleLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) const override {
    if (glm::dot(inDir, nf) >= 0.0) return false;
    const double u1 = rng.uniform(), u2 = rng.uniform();
    return sampleAshikhmin(ashikhminLobe(m, inDir, nf), -inDir, u1, u2, out);
  }
  // f cos θ_o / p = s' cos θ_o / max(cos θ_o, cos θ_v): the lobe's powers and normalisation cancel
  // between the BRDF and the half vector's density (the paper's §3.3).
  Rgb lobeWeight(const Material& m, const Vec3& inDir, const Vec3& nf, const Vec3& out) const override {
    const double co = glm::dot(out, nf);
    if (co <= 0.0) return Rgb(0.0);
    return m.specularReflectance * (co / std::max(co, std::max(0.001, -glm::dot(inDir, nf))));
  }
};

}  // namespace

const MaterialFamily& ashik2Family() {
  static const Ashik2 f;
  return f;
}

}  // namespace candela
