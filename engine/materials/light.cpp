// light, spotlight and illum (Radiance reference manual, "Light", "Spotlight", "Illum"): emitters
// sampled explicitly as light sources. An illum is a light for shadow rays only: other rays see
// its alternate material, or pass straight on when it has none.
#include "engine/materials/registry.h"

#include <cmath>

namespace candela {
namespace {

class Light : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kLight; }
  const char* name() const override { return "light"; }
  HitRole role() const override { return HitRole::kEmit; }
  bool emits() const override { return true; }
  bool sampledSource() const override { return true; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    ctx.expectStrings(0);
    if (p.type == "spotlight") {
      // `mod spotlight id 0 0 7 red green blue angle xdir ydir zdir` (Radiance reference manual)
      ctx.expectReals(7);
      if (!(p.reals[3] > 0.0 && p.reals[3] <= 360.0))
        ctx.fail("spotlight '" + p.name + "' needs a cone angle in (0, 360] degrees");
      const Vec3 aim = ctx.vec(4);
      const double focal = glm::length(aim);
      if (!(focal > 0.0)) ctx.fail("spotlight '" + p.name + "' has a zero direction");
      m.spot = true;
      m.spotCosHalf = std::cos(p.reals[3] * kPi / 360.0);
      m.spotAim = aim / focal;
      m.spotFocalM = focal;
    } else {
      ctx.expectReals(3);
    }
    m.color = ctx.vec(0);
    ctx.expectRadiance(m.color);
  }
};

class Illum : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kIllum; }
  const char* name() const override { return "illum"; }
  HitRole role() const override { return HitRole::kEmit; }
  bool emits() const override { return true; }
  bool sampledSource() const override { return true; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(1);
    ctx.expectReals(3);
    m.color = ctx.vec(0);
    m.alternate = ctx.alternate();
    ctx.expectRadiance(m.color);
  }
  std::optional<int> seenInstead(const Material& m) const override { return m.alternate; }
  // Shadow rays are walked past it; with no alternate it is invisible to them (and the sky seen
  // through it guides sky sampling: mkillum's windows).
  bool mayPassShadowRays(const Material&) const override { return true; }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3&, const Vec3&) const override {
    if (m.alternate >= 0) return std::nullopt;
    return Rgb(1.0);
  }
  bool seeThrough(const Material& m) const override { return m.alternate < 0; }
  bool transmitting() const override { return true; }
};

}  // namespace

const MaterialFamily& lightFamily() {
  static const Light f;
  return f;
}

const MaterialFamily& illumFamily() {
  static const Illum f;
  return f;
}

}  // namespace candela
