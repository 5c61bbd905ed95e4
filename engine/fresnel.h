// Fresnel reflection at a smooth boundary between two non-absorbing media, Snell refraction
// (the `dielectric` material, engine/materials.cpp) and thin glass (the `glass` material).
#pragma once

#include "base/math.h"
#include "base/units.h"

namespace candela {

// Power reflectances of one smooth boundary for light arriving at cosine cosI (> 0) from a
// medium of index n1 into one of index n2, eta = n2 / n1 (relative index): the s (TE) and p (TM)
// components and their mean, the reflectance for unpolarised light. cosT is the cosine of the
// refraction angle (Snell: sin θt = sin θi / eta); tir: total internal reflection (sin θi > eta,
// only when eta < 1), where rs = rp = 1 and cosT = 0.
struct Fresnel {
  double rs = 1.0, rp = 1.0;
  double cosT = 0.0;
  bool tir = true;
  double unpolarised() const { return 0.5 * (rs + rp); }
};
Fresnel fresnel(double cosI, double eta);

// Unpolarised reflectance: fresnel(cosI, eta).unpolarised().
double fresnelReflectance(double cosI, double eta);

// Refracted direction of unit direction d arriving at a boundary whose unit normal nf faces the
// incoming ray (dot(d, nf) < 0), with relative index eta and cosT from fresnel(); a unit vector.
Vec3 refractDirection(const Vec3& d, const Vec3& nf, double eta, double cosT);

// Thin glass (Radiance's `glass`) with incoherent multiple reflections, for light arriving at
// cosine ±cosI: per polarisation, single-surface Fresnel reflectance R and internal
// transmittance τ = tn^(1/cos θt) give T = (1−R)² τ / (1 − R² τ²) and
// R_total = R + (1−R)² R τ² / (1 − R² τ²), averaged over s and p. tn is the glass's
// "transmissivity" per channel, n its refractive index.
void thinGlass(const Rgb& transmissivity, double refractiveIndex, double cosI, Rgb& trans, Rgb& refl);

}  // namespace candela
