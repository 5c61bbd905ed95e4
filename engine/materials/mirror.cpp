// mirror (Radiance reference manual, "Mirror"): reflects its colour specularly. Its optional
// string argument, an alternate material for rays other than source rays, is read and kept.
#include "engine/materials/registry.h"

#include <algorithm>

namespace candela {
namespace {

class Mirror : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kMirror; }
  const char* name() const override { return "mirror"; }
  HitRole role() const override { return HitRole::kSpecular; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    ctx.expectStrings(1);
    ctx.expectReals(3);
    m.color = ctx.vec(0);
    m.alternate = ctx.alternate();
    ctx.expectNonNegative(m.color);
    if (std::max({m.color.x, m.color.y, m.color.z}) > 1.0)
      ctx.fail(ctx.what() + " transmits or reflects more than it receives: a component above 1");
  }
  void derive(MaterialParameters& m) const override { m.specularReflectance = m.color; }
  bool mirrorsSources() const override { return true; }
  SpecularSample sampleSpecular(const Material& m, const SurfaceHit& h, Rng&, Rgb& beta) const override {
    beta *= m.color;
    return {SpecularSample::Kind::kMirror, mirrorDirection(h.d, h.ng), false};
  }
  SpecularSplit splitSpecular(const Material& m, const SurfaceHit& h) const override {
    SpecularSplit s;
    s.factor = m.color;
    s.scaled = true;
    s.count = 1;
    s.parts[0] = {Rgb(1.0), mirrorDirection(h.d, h.ng), false};
    return s;
  }
};

}  // namespace

const MaterialFamily& mirrorFamily() {
  static const Mirror f;
  return f;
}

}  // namespace candela
