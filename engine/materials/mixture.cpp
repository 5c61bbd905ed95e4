// mixfunc (Radiance reference manual, "Mixfunc"): `mod mixfunc id 4+ foreground background vname
// funcfile transform 0 n A1..An`, the foreground where the coefficient vname is 1, the background
// where it is 0, a mixture between; mixdata, mixpict and mixtext (its coefficient 1 in a glyph,
// 0 elsewhere: engine/radiance/text_pattern.h) alike. Read with the patterns (engine/radiance/function_patterns.h);
// at a hit the hook (engine/materials/pattern_hook.h) stands one of the two in its place, chosen
// with the coefficient's probability (paths, the camera), or blends their straight transmittance
// (shadow rays). Asked before that, it is nothing.
#include "engine/materials/registry.h"

namespace candela {
namespace {

class Mixture : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kMixture; }
  const char* name() const override { return "mixfunc"; }
  HitRole role() const override { return HitRole::kMix; }
  void read(const MaterialReadContext& ctx, Material&) const override {
    ctx.fail(ctx.what() + " is read with the patterns");
  }
  // Shadow rays are walked past it: the tracer blends what its two materials let through.
  bool mayPassShadowRays(const Material&) const override { return true; }
};

}  // namespace

const MaterialFamily& mixtureFamily() {
  static const Mixture f;
  return f;
}

}  // namespace candela
