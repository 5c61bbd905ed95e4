// dielectric and interface (Radiance reference manual, "Dielectric", "Interface"): a smooth
// boundary between two media. "mod dielectric id 0 0 5 rtn gtn btn n hc": a medium of index n
// behind the surface, its transmission per metre of path (scene units: metres), a vacuum in
// front; the Hartmann constant is read, not used (no dispersion). "mod interface id 0 0 8 rtn1
// gtn1 btn1 n1 rtn2 gtn2 btn2 n2": the inside medium (behind) and the outside one (in front).
#include "engine/fresnel.h"
#include "engine/materials/registry.h"

#include <cmath>

namespace candela {
namespace {

// Beer–Lambert absorption of a ray that travelled distanceM in the medium met on the side it
// arrives from (behind: the inside's color; in front: the outside's, 1 for a dielectric),
// multiplied into beta: transmission per metre raised to the distance (as Radiance's dielectric).
void absorbOnTheWay(const Material& m, const SurfaceHit& h, Rgb& beta) {
  if (!h.front) {
    for (int c = 0; c < 3; ++c) beta[c] *= std::pow(m.color[c], h.t);
  } else if (m.outsideTransmission != Rgb(1.0)) {
    for (int c = 0; c < 3; ++c) beta[c] *= std::pow(m.outsideTransmission[c], h.t);
  }
}

// The relative index of the side the ray enters over the side it leaves.
double relativeIndex(const Material& m, bool front) {
  return front ? m.refractiveIndex / m.outsideIndex : m.outsideIndex / m.refractiveIndex;
}

class Dielectric : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kDielectric; }
  const char* name() const override { return "dielectric"; }
  HitRole role() const override { return HitRole::kSpecular; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(0);
    ctx.expectReals(5);
    const RadPrimitive& p = ctx.primitive;
    m.color = ctx.vec(0);
    m.refractiveIndex = p.reals[3];
    m.hartmannConstant = p.reals[4];
    for (int c = 0; c < 3; ++c)
      if (!(m.color[c] > 0.0 && m.color[c] <= 1.0))
        ctx.fail("dielectric '" + p.name + "' needs a transmission per metre in (0, 1] for each channel");
    if (!(m.refractiveIndex > 0.0)) ctx.fail("dielectric '" + p.name + "' needs a refractive index > 0");
    ctx.expectNonNegative(m.color);
  }
  bool transmitting() const override { return true; }
  double viewTransmittance(const Material&) const override { return 1.0; }
  // One boundary at normal incidence; what passes depends on the path inside.
  NormalIncidence normalIncidence(const Material& m) const override {
    const double r = fresnelReflectance(1.0, m.refractiveIndex);
    return {r, r, std::nullopt};
  }
  // Opaque to shadow rays: it bends light, so no straight ray passes it (as Radiance's source
  // rays); paths find what lies behind it.

  // A ray that meets the back face travelled inside (absorbed on the way), then reflects with
  // probability R (Fresnel, unpolarised; 1 beyond the critical angle) or refracts (Snell), so
  // each event carries weight 1 and the estimator is unbiased. Radiance is not scaled by n²
  // inside (the factors cancel for sensors and sources outside).
  SpecularSample sampleSpecular(const Material& m, const SurfaceHit& h, Rng& rng, Rgb& beta) const override {
    absorbOnTheWay(m, h, beta);
    const double eta = relativeIndex(m, h.front);
    const Fresnel f = fresnel(-glm::dot(h.d, h.nf), eta);
    if (rng.uniform() < f.unpolarised()) return {SpecularSample::Kind::kBent, mirrorDirection(h.d, h.nf), false};
    return {SpecularSample::Kind::kBent, refractDirection(h.d, h.nf, eta, f.cosT), true};
  }
  SpecularSplit splitSpecular(const Material& m, const SurfaceHit& h) const override {
    SpecularSplit s;
    s.scaled = true;
    absorbOnTheWay(m, h, s.factor);
    const double eta = relativeIndex(m, h.front);
    const Fresnel f = fresnel(-glm::dot(h.d, h.nf), eta);
    const double r = f.unpolarised();
    const Vec3 refl = mirrorDirection(h.d, h.nf);
    if (f.tir || r >= 1.0) {
      s.count = 1;
      s.parts[0] = {Rgb(1.0), refl, false};
      return s;
    }
    s.count = 2;
    s.parts[0] = {Rgb(r), refl, false};
    s.parts[1] = {Rgb(1.0 - r), refractDirection(h.d, h.nf, eta, f.cosT), true};
    return s;
  }
};

class Interface : public Dielectric {
 public:
  MaterialType type() const override { return MaterialType::kInterface; }
  const char* name() const override { return "interface"; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(0);
    ctx.expectReals(8);
    const RadPrimitive& p = ctx.primitive;
    m.color = ctx.vec(0);
    m.refractiveIndex = p.reals[3];
    m.outsideTransmission = ctx.vec(4);
    m.outsideIndex = p.reals[7];
    for (int c = 0; c < 3; ++c)
      if (!(m.color[c] > 0.0 && m.color[c] <= 1.0 && m.outsideTransmission[c] > 0.0 &&
            m.outsideTransmission[c] <= 1.0))
        ctx.fail("interface '" + p.name + "' needs transmissions per metre in (0, 1] for each channel");
    if (!(m.refractiveIndex > 0.0 && m.outsideIndex > 0.0))
      ctx.fail("interface '" + p.name + "' needs refractive indices > 0");
  }
  NormalIncidence normalIncidence(const Material& m) const override {
    const double r = fresnelReflectance(1.0, m.refractiveIndex / m.outsideIndex);
    return {r, r, std::nullopt};
  }
};

}  // namespace

const MaterialFamily& interfaceFamily() {
  static const Interface f;
  return f;
}

const MaterialFamily& dielectricFamily() {
  static const Dielectric f;
  return f;
}

}  // namespace candela
