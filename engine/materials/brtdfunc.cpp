// BRTDfunc (Radiance reference manual, "BRTDfunc"; src/rt/m_brdf.c): reflectance and
// transmittance as functions of the ray,
//   mod BRTDfunc id 10+ rrefl grefl brefl rtrns gtrns btrns rbrtd gbrtd bbrtd funcfile transform
//   0 9+ rdf gdf bdf rdb gdb bdb rdt gdt bdt A10 …
// Six expressions give the mirror reflectance and the straight-through transmittance per channel,
// evaluated at each hit with NxP NyP NzP and RdotP turned towards the ray and CrP CgP CbP the
// pattern's colour (Radiance's setbrdfunc); the reals give the diffuse reflectance of the front
// and the back side and the diffuse transmittance, each times the pattern's colour. The
// directional functions rbrtd… (light-source contributions only, in Radiance) must be 0 (none):
// other values are refused with the reason (docs/engine.md). The glaze script's coated glazings
// are BRTDfuncs of this kind.
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

class BrtdFunc : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kBrtdFunc; }
  const char* name() const override { return "BRTDfunc"; }
  HitRole role() const override { return HitRole::kScatter; }
  int functionPatterns() const override { return 2; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    if (p.reals.size() < 9)
      ctx.fail(ctx.what() + " needs 9 or more real arguments (front, back diffuse reflectance, diffuse "
                            "transmittance), got " + std::to_string(p.reals.size()));
    for (size_t k = 6; k < 9; ++k)
      if (p.strings[k].empty() || p.strings[k][0] != '0')
        ctx.fail(ctx.what() + ": its directional function '" + p.strings[k] +
                 "' (rbrtd gbrtd bbrtd) is not implemented; candela reads BRTDfuncs whose directional "
                 "functions are 0 (specular and diffuse parts only)");
    m.color = ctx.vec(0);
    m.backColor = ctx.vec(3);
    m.transmissionColor = ctx.vec(6);
    for (const Rgb& c : {m.color, m.backColor, m.transmissionColor}) ctx.expectNonNegative(c);
    m.roughness = 0.0;  // the reflected part is a mirror's
    m.specularTransmission = !(p.strings[3] == "0" && p.strings[4] == "0" && p.strings[5] == "0");
  }
  // Without a hit: the front's diffuse parts (the report's table); specular parts at hits only.
  void derive(MaterialParameters& m) const override {
    m.diffuseReflectance = m.color;
    m.diffuseTransmittance = m.transmissionColor;
    m.specularReflectance = Rgb(0.0);
    m.specularTransmittance = Rgb(0.0);
  }
  void atHit(const Material& m, const PatternPoint& p, const Rgb& patternColour, PatternEvaluator& eval,
             MaterialParameters& out) const override {
    const bool front = glm::dot(p.d, p.ng) < 0.0;
    out.diffuseReflectance = (front ? m.color : m.backColor) * patternColour;
    out.diffuseTransmittance = m.transmissionColor * patternColour;
    out.specularReflectance = glm::max(eval.oriented(m.functions, p, patternColour), Rgb(0.0));
    out.specularTransmittance =
        m.specularTransmission ? glm::max(eval.oriented(m.functions + 1, p, patternColour), Rgb(0.0)) : Rgb(0.0);
  }
  bool sampleLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) const override {
    return sampleWardLobe(m, inDir, nf, rng, out);  // roughness 0: the mirror direction
  }
  bool mayPassShadowRays(const Material& m) const override { return m.specularTransmission; }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3&, const Vec3&) const override {
    if (!m.specularTransmission) return std::nullopt;
    return m.specularTransmittance;  // at a hit: evaluated by the hook (pattern_hook.h)
  }
  bool seeThrough(const Material& m) const override { return m.specularTransmission; }
  bool transmitting() const override { return true; }
  NormalIncidence normalIncidence(const Material& m) const override {
    NormalIncidence n = MaterialFamily::normalIncidence(m);
    n.transmittance = photopic(m.transmissionColor);
    return n;
  }
};

}  // namespace

const MaterialFamily& brtdFuncFamily() {
  static const BrtdFunc f;
  return f;
}

}  // namespace candela
