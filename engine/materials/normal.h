// Radiance's "normal" materials, plastic, metal and trans (its m_normal.c): a diffuse part, an
// isotropic Ward lobe of roughness α, and for trans the transmitted parts. What the three share.
#pragma once

#include "engine/materials/family.h"

namespace candela {

bool sampleWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

// Radiance's parts of the normal materials (reference manual, "Plastic", "Metal", "Trans"):
// plastic's diffuse part is colour·(1 − spec), its specular part uncoloured spec; metal's specular
// part takes the colour; trans splits the non-specular light into reflected (1 − trans), diffusely
// transmitted trans·(1 − tspec) and specularly transmitted trans·tspec.
void derivePlastic(MaterialParameters& m);
void deriveMetal(MaterialParameters& m);
// BRTDfunc, WGMDfunc, BSDF without a hit: the diffuse parts of their reals (the front's
// reflectance, the transmittance), no specular part (those are evaluated at hits).
void deriveFromDiffuseReals(MaterialParameters& m);
void deriveTrans(MaterialParameters& m);

class NormalFamily : public MaterialFamily {
 public:
  HitRole role() const override { return HitRole::kScatter; }
  // Diffuse reflection served by the irradiance cache: something reflected diffusely, nothing
  // transmitted.
  bool cacheable(const Material& m) const override;
  // Radiance's isotropic Ward lobe (sampleWardLobe).
  bool sampleLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) const override {
    return sampleWardLobe(m, inDir, nf, rng, out);
  }

 protected:
  // plastic/metal's five arguments (colour, specularity, roughness), trans's two more, checked.
  static void readCommon(const MaterialReadContext& ctx, Material& m, size_t reals);
  // What cannot exist: more reflected or transmitted than received, a roughness below 0.
  static void checkCommon(const MaterialReadContext& ctx, const Material& m, bool transmits);
};

// Radiance's anisotropic Ward lobe (plastic2, metal2, trans2): roughness along m.anisotropyU
// (projected on the surface) and roughnessV across it.
bool sampleAnisotropicWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

// A half vector of Ward's anisotropic lobe (1992, eq. 5a–b) about unit n, of roughness ax along
// unit u and ay along unit v (u, v, n orthonormal), from (u1, u2) in [0, 1)².
Vec3 wardHalfVector(const Vec3& u, const Vec3& v, const Vec3& n, double ax, double ay, double u1, double u2);

// WGMDfunc's lobe: one draw of the same half vector (u projected on the surface), lost when the
// reflection falls below the surface (no redraw: its weight, the BRDF over the density, then
// keeps the estimate unbiased); roughness 0 is the mirror direction.
bool sampleWgmdLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

// WGMDfunc's rough specular transmission (src/rt/m_wgmdf.c, agaussamp): the straight-through
// direction inDir displaced in the surface's plane by Ward's anisotropic Gaussian of rms slopes
// m.transmissionRoughnessU along u (m.anisotropyU projected) and …V across it, normalised; a
// draw on the side the ray arrived from is drawn again, at most 10 times as Radiance's MAXITER
// (false: all were).
bool sampleWgmdTransmission(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

// One direction of the glossy (Ward) lobe of m for a ray arriving along inDir on the side of nf;
// false when the sample is lost (arrival from behind, or eight draws below the surface).
bool sampleWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

}  // namespace candela
