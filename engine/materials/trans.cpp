// trans (Radiance reference manual, "Trans"): plastic's reflection, and of the light not
// reflected specularly a fraction `trans` transmitted, a fraction `tspec` of that straight on.
#include "engine/materials/normal.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

class Trans : public NormalFamily {
 public:
  MaterialType type() const override { return MaterialType::kTrans; }
  const char* name() const override { return "trans"; }
  void read(const MaterialReadContext& ctx, Material& m) const override { readCommon(ctx, m, 7); }
  void derive(MaterialParameters& m) const override { deriveTrans(m); }
  // Its specular transmission passes straight (shadow) rays, as Radiance's trans with roughness 0.
  bool mayPassShadowRays(const Material& m) const override { return photopic(m.specularTransmittance) > 0.0; }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3&, const Vec3&) const override {
    return m.specularTransmittance;
  }
  bool seeThrough(const Material& m) const override { return mayPassShadowRays(m); }
  bool transmitting() const override { return true; }
  double viewTransmittance(const Material& m) const override { return photopic(m.specularTransmittance); }
  NormalIncidence normalIncidence(const Material& m) const override {
    NormalIncidence n = MaterialFamily::normalIncidence(m);
    n.transmittance = photopic(m.diffuseTransmittance + m.specularTransmittance);
    return n;
  }
};

}  // namespace

const MaterialFamily& transFamily() {
  static const Trans f;
  return f;
}

}  // namespace candela
