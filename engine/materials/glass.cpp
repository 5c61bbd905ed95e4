// glass (Radiance reference manual, "Glass"): a thin pane, transmission and reflection from its
// transmissivity and refractive index (engine/fresnel.h), the ray straight on or mirrored.
#include "engine/fresnel.h"
#include "engine/materials/registry.h"

#include <algorithm>

namespace candela {
namespace {

class Glass : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kGlass; }
  const char* name() const override { return "glass"; }
  HitRole role() const override { return HitRole::kSpecular; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(0);
    const RadPrimitive& p = ctx.primitive;
    if (p.reals.size() != 3 && p.reals.size() != 4)
      ctx.fail("glass '" + p.name + "' needs 3 or 4 real arguments, got " + std::to_string(p.reals.size()));
    m.color = ctx.vec(0);
    if (p.reals.size() == 4) m.refractiveIndex = p.reals[3];
    ctx.expectNonNegative(m.color);
    if (std::max({m.color.x, m.color.y, m.color.z}) > 1.0)
      ctx.fail(ctx.what() + " transmits or reflects more than it receives: a component above 1");
  }
  bool mayPassShadowRays(const Material&) const override { return true; }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3& dir, const Vec3& ng) const override {
    Rgb tr, rf;
    thinGlass(m.color, m.refractiveIndex, glm::dot(dir, ng), tr, rf);
    return tr;
  }
  bool seeThrough(const Material&) const override { return true; }
  bool isGlazing() const override { return true; }
  bool transmitting() const override { return true; }
  double viewTransmittance(const Material& m) const override { return photopic(m.color); }
  // Thin glass at normal incidence, its multiple reflections included (engine/fresnel.h).
  NormalIncidence normalIncidence(const Material& m) const override {
    Rgb trans(0.0), refl(0.0);
    thinGlass(m.color, m.refractiveIndex, 1.0, trans, refl);
    return {photopic(refl), photopic(refl), photopic(trans)};
  }

  // Transmitted straight on or reflected, chosen by the photopic shares of the two, the weight
  // (transmittance or reflectance over its probability) multiplied into beta.
  SpecularSample sampleSpecular(const Material& m, const SurfaceHit& h, Rng& rng, Rgb& beta) const override {
    Rgb tr, rf;
    thinGlass(m.color, m.refractiveIndex, glm::dot(h.d, h.ng), tr, rf);
    const double pt = photopic(tr), pr = photopic(rf);
    if (pt + pr <= 0.0) return {};
    if (rng.uniform() * (pt + pr) < pt) {
      beta *= tr * ((pt + pr) / pt);
      return {SpecularSample::Kind::kStraight, h.d, true};
    }
    beta *= rf * ((pt + pr) / pr);
    return {SpecularSample::Kind::kReflected, mirrorDirection(h.d, h.ng), false};
  }
  SpecularSplit splitSpecular(const Material& m, const SurfaceHit& h) const override {
    SpecularSplit s;
    Rgb tr(0.0), rf(0.0);
    thinGlass(m.color, m.refractiveIndex, glm::dot(h.d, h.ng), tr, rf);
    s.count = 2;
    s.parts[0] = {tr, h.d, true};
    s.parts[1] = {rf, mirrorDirection(h.d, h.ng), false};
    return s;
  }
};

}  // namespace

const MaterialFamily& glassFamily() {
  static const Glass f;
  return f;
}

}  // namespace candela
