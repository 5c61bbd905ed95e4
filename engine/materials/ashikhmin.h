// The Ashikhmin-Shirley anisotropic Phong lobe of Radiance's ashik2 (src/rt/ashikhmin.c;
// M. Ashikhmin and P. Shirley, "An anisotropic Phong BRDF model", J. Graphics Tools 5(2), 2000):
// its BRDF, its sampling density and its sampler, shared by the family (ashik2.cpp) and its tests.
#pragma once

#include "engine/materials/material.h"

namespace candela {

// Schlick's Fresnel factor (1 − c)⁵ as Radiance's schlick_fres.
inline double schlickFresnel(double c) {
  const double f = 1.0 - c;
  return f * f * f * f * f;
}

// The lobe at a hit: the frame (u along the anisotropy, v across, n the shading normal facing the
// viewer), the exponents, the viewer's cosine (clamped to 0.001 as Radiance's pdot) and the
// specular colour with Schlick's Fresnel at that cosine, s + (1 − s)(1 − cos)⁵ (m_ashikhmin).
struct AshikhminLobe {
  Vec3 u{0.0}, v{0.0}, n{0.0};
  double nu = 0.0, nv = 0.0;
  double viewCos = 1.0;
  bool valid = false;  // false: no frame (u along the normal: Radiance's "illegal orientation")
};

// The lobe of m (its exponents and anisotropyU) for a ray arriving along inDir on the side of nf.
AshikhminLobe ashikhminLobe(const MaterialParameters& m, const Vec3& inDir, const Vec3& nf);

// The specular BRDF per sr without its colour, for the viewer at wi (unit, leaving the surface)
// and light from wo (unit, leaving the surface):
//   √((nu+1)(nv+1)) (n·h)^((nu (u·h)² + nv (v·h)²)/(1 − (n·h)²)) / (8π (wo·h) max(n·wo, cos θ_view))
// (Radiance's dirashik; the paper's eq. 4 with the Fresnel factor taken out); 0 below the surface.
double ashikhminSpecular(const AshikhminLobe& lobe, const Vec3& wi, const Vec3& wo);

// The density (per sr) with which sampleAshikhmin draws wo: p_h(h) / (4 wi·h), p_h the half
// vector's density √((nu+1)(nv+1))/(2π) (n·h)^(nu cos²φ + nv sin²φ) (the paper's eq. 6 and 8).
double ashikhminDensity(const AshikhminLobe& lobe, const Vec3& wi, const Vec3& wo);

// The reflection of wi about a half vector drawn by the paper's eq. 9 from (u1, u2) in [0, 1)²:
// φ = atan(√((nu+1)/(nv+1)) tan(π u1/2)) (over the four quadrants), cos θ_h = (1 − u2)^(1/(nu
// cos²φ + nv sin²φ + 1)). Returns false when wo falls below the surface (the sample is lost).
bool sampleAshikhmin(const AshikhminLobe& lobe, const Vec3& wi, double u1, double u2, Vec3& wo);

}  // namespace candela
