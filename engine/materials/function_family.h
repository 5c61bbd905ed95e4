// What BRTDfunc and WGMDfunc share (src/rt/m_brdf.c, m_wgmdf.c): materials whose specular parts
// are functions evaluated at each hit (three patterns of functions, Material::functions), whose
// diffuse parts are their reals, which may let a straight ray through and send sampled sources'
// light through directional functions. Each family says how it reads and what it has at a hit.
#pragma once

#include "engine/materials/family.h"
#include "engine/materials/normal.h"  // deriveFromDiffuseReals

namespace candela {

class FunctionFamily : public MaterialFamily {
 public:
  HitRole role() const override { return HitRole::kScatter; }
  int functionPatterns() const override { return 3; }
  // Without a hit: the front's diffuse parts (the report's table); specular parts at hits only.
  void derive(MaterialParameters& m) const override { deriveFromDiffuseReals(m); }
  bool directionalSources(const Material& m) const override { return m.directionalFunctions; }
  bool mayPassShadowRays(const Material& m) const override { return m.specularTransmission; }
  // At a hit, the transmittance the hook evaluated (pattern_hook.h); opaque without one.
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3&, const Vec3&) const override {
    if (!m.specularTransmission) return std::nullopt;
    return m.specularTransmittance;
  }
  bool seeThrough(const Material& m) const override { return m.specularTransmission; }
  bool transmitting() const override { return true; }
  NormalIncidence normalIncidence(const Material& m) const override {
    NormalIncidence n = MaterialFamily::normalIncidence(m);
    n.transmittance = photopic(m.transmissionColor);
    return n;
  }
};

}  // namespace candela
