#include "engine/fresnel.h"

#include <algorithm>
#include <cmath>

namespace candela {

Fresnel fresnel(double cosI, double eta) {
  // Fresnel's equations in amplitude form (Born & Wolf, "Principles of Optics", 1.5.2):
  // r_s = (n1 cos θi − n2 cos θt) / (n1 cos θi + n2 cos θt),
  // r_p = (n2 cos θi − n1 cos θt) / (n2 cos θi + n1 cos θt), divided through by n1; the power
  // reflectances are their squares.
  Fresnel f;
  cosI = std::clamp(cosI, 0.0, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return f;  // total internal reflection
  f.tir = false;
  f.cosT = std::sqrt(1.0 - sin2T);
  const double rs = (cosI - eta * f.cosT) / (cosI + eta * f.cosT);
  const double rp = (eta * cosI - f.cosT) / (eta * cosI + f.cosT);
  f.rs = rs * rs;
  f.rp = rp * rp;
  return f;
}

double fresnelReflectance(double cosI, double eta) { return fresnel(cosI, eta).unpolarised(); }

Vec3 refractDirection(const Vec3& d, const Vec3& nf, double eta, double cosT) {
  // Snell's law in vector form: t = d/eta + (cos θi/eta − cos θt) nf with cos θi = −d·nf; the
  // tangential part of d shrinks by 1/eta and the normal part makes t a unit vector.
  const double cosI = -glm::dot(d, nf);
  return glm::normalize(d / eta + (cosI / eta - cosT) * nf);
}

void thinGlass(const Rgb& transmissivity, double refractiveIndex, double cosI, Rgb& trans, Rgb& refl) {
  const Fresnel f = fresnel(std::clamp(std::abs(cosI), 1e-6, 1.0), refractiveIndex);
  trans = Rgb(0.0);
  refl = Rgb(0.0);
  for (double r : {f.rs, f.rp}) {
    for (int c = 0; c < 3; ++c) {
      const double tau = std::pow(transmissivity[c], 1.0 / f.cosT);
      const double den = 1.0 - r * r * tau * tau;
      trans[c] += 0.5 * (1.0 - r) * (1.0 - r) * tau / den;
      refl[c] += 0.5 * (r + (1.0 - r) * (1.0 - r) * r * tau * tau / den);
    }
  }
}

}  // namespace candela
