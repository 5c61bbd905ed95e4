// Radiance's "normal" materials, plastic, metal and trans (its m_normal.c): a diffuse part, an
// isotropic Ward lobe of roughness α, and for trans the transmitted parts. What the three share.
#pragma once

#include "engine/materials/family.h"

namespace candela {

class NormalFamily : public MaterialFamily {
 public:
  HitRole role() const override { return HitRole::kScatter; }
  // Diffuse reflection served by the irradiance cache: something reflected diffusely, nothing
  // transmitted.
  bool cacheable(const Material& m) const override;

 protected:
  // plastic/metal's five arguments (colour, specularity, roughness), trans's two more, checked.
  static void readCommon(const MaterialReadContext& ctx, Material& m, size_t reals);
};

// One direction of the glossy (Ward) lobe of m for a ray arriving along inDir on the side of nf;
// false when the sample is lost (arrival from behind, or eight draws below the surface).
bool sampleWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

}  // namespace candela
