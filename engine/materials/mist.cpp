// mist (Radiance reference manual, "Mist"): the boundary of a participating medium,
// `mod mist id N s1 … sN 0 0|3|6|7 [rext gext bext [ralb galb balb [g]]]`. candela reads it as a
// boundary without scattering: rays and shadow rays pass it as if it were not there; the
// medium's extinction and scattering inside, and its light sources, are not modelled
// (docs/engine.md).
#include "engine/materials/registry.h"

namespace candela {
namespace {

class Mist : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kMist; }
  const char* name() const override { return "mist"; }
  HitRole role() const override { return HitRole::kAbsorb; }  // never asked: rays pass (seenInstead)
  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    // None: a volume that only names the sources scattering in it (the strings), its medium the
    // global one (Radiance's own spotcones.rad).
    if (p.reals.size() != 0 && p.reals.size() != 3 && p.reals.size() != 6 && p.reals.size() != 7)
      ctx.fail(ctx.what() + " needs 0, 3, 6 or 7 real arguments, got " + std::to_string(p.reals.size()));
    if (p.reals.empty()) return;
    m.color = ctx.vec(0);  // the extinction coefficients, read and not used
    ctx.expectNonNegative(m.color);
  }
  // Not there for any ray.
  std::optional<int> seenInstead(const Material&) const override { return -1; }
  bool mayPassShadowRays(const Material&) const override { return true; }
  std::optional<Rgb> straightTransmittance(const Material&, const Vec3&, const Vec3&) const override {
    return Rgb(1.0);
  }
  bool seeThrough(const Material&) const override { return true; }
  double viewTransmittance(const Material&) const override { return 1.0; }
};

}  // namespace

const MaterialFamily& mistFamily() {
  static const Mist f;
  return f;
}

}  // namespace candela
