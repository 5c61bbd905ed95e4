#include "engine/materials/registry.h"

namespace candela {
namespace {

// glow (Radiance reference manual, "Glow"): an emitter that rays find, not a light source of its
// own (small glows are sampled from nearby points as well: engine/lights.h); a negative radius
// lights nothing.
class Glow : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kGlow; }
  const char* name() const override { return "glow"; }
  HitRole role() const override { return HitRole::kEmit; }
  bool emits() const override { return true; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(0);
    ctx.expectReals(4);
    m.color = ctx.vec(0);
    m.glowRadiusM = ctx.primitive.reals[3];
    ctx.expectRadiance(m.color);
  }
};

}  // namespace

const MaterialFamily& glowFamily() {
  static const Glow f;
  return f;
}

}  // namespace candela
