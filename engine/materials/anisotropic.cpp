// plastic2, metal2 and trans2 (Radiance reference manual, "Plastic2", "Metal2", "Trans2"):
// plastic, metal and trans with an anisotropic Ward lobe, `mod plastic2 id 4+ ux uy uz funcfile
// transform 0 6 red green blue spec urough vrough` (trans2: `0 8 … trans tspec`). The u direction
// is three functions of the function file (read as a pattern into Material::functions), evaluated
// at each hit by engine/materials/pattern_hook.h; the lobe has roughness urough along u and vrough
// across it.
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

class Anisotropic : public NormalFamily {
 public:
  Anisotropic(MaterialType type, const char* name, bool transmits, void (*derive)(MaterialParameters&))
      : type_(type), name_(name), transmits_(transmits), derive_(derive) {}
  MaterialType type() const override { return type_; }
  const char* name() const override { return name_; }
  int functionPatterns() const override { return 1; }
  void atHit(const Material& m, const PatternPoint& p, const Rgb&, PatternEvaluator& eval,
             MaterialParameters& out) const override {
    out.anisotropyU = eval.direction(m.functions, p);
  }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectReals(transmits_ ? 8 : 6);
    const RadPrimitive& p = ctx.primitive;
    m.color = ctx.vec(0);
    m.specularity = p.reals[3];
    m.roughness = p.reals[4];
    m.roughnessV = p.reals[5];
    if (transmits_) {
      m.transmissivity = p.reals[6];
      m.transmittedSpecular = p.reals[7];
    }
    checkCommon(ctx, m, transmits_);
  }
  void derive(MaterialParameters& m) const override { derive_(m); }
  bool matteOpaque(const Material& m) const override {
    return !transmits_ && photopic(m.specularReflectance) <= 0.0;
  }
  bool sampleLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) const override {
    return sampleAnisotropicWardLobe(m, inDir, nf, rng, out);
  }
  bool mayPassShadowRays(const Material& m) const override {
    return transmits_ && photopic(m.specularTransmittance) > 0.0;
  }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3&, const Vec3&) const override {
    if (!transmits_) return std::nullopt;
    return m.specularTransmittance;
  }
  bool seeThrough(const Material& m) const override { return mayPassShadowRays(m); }
  bool transmitting() const override { return transmits_; }
  double viewTransmittance(const Material& m) const override { return photopic(m.specularTransmittance); }
  NormalIncidence normalIncidence(const Material& m) const override {
    NormalIncidence n = MaterialFamily::normalIncidence(m);
    if (transmits_) n.transmittance = photopic(m.diffuseTransmittance + m.specularTransmittance);
    return n;
  }

 private:
  MaterialType type_;
  const char* name_;
  bool transmits_;
  void (*derive_)(MaterialParameters&);
};

}  // namespace

const MaterialFamily& plastic2Family() {
  static const Anisotropic f(MaterialType::kPlastic2, "plastic2", false, derivePlastic);
  return f;
}

const MaterialFamily& metal2Family() {
  static const Anisotropic f(MaterialType::kMetal2, "metal2", false, deriveMetal);
  return f;
}

const MaterialFamily& trans2Family() {
  static const Anisotropic f(MaterialType::kTrans2, "trans2", true, deriveTrans);
  return f;
}

}  // namespace candela
