// antimatter (Radiance reference manual, "Antimatter"; src/rt/m_clip.c):
// `void antimatter id N mod1 … modN 0 0`, the surfaces of a closed volume that subtracts the
// surfaces of the listed modifiers; the first, when not void, is the material the volume's surface
// is seen as from inside a subtracted object. Rays are walked through it by the tracer's clip steps
// (engine/antimatter.h), before any family is asked anything; where a ray is not followed that way
// (sight lines, a plan's section) an antimatter surface is not there, as mist's.
#include "engine/materials/registry.h"

#include <algorithm>

namespace candela {
namespace {

class Antimatter : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kAntimatter; }
  const char* name() const override { return "antimatter"; }
  HitRole role() const override { return HitRole::kAbsorb; }  // never asked: the clip step or seenInstead
  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    ctx.expectReals(0);
    if (p.strings.empty())
      ctx.fail(ctx.what() + " lists no modifier (it needs the materials it subtracts, the first seen inside them)");
    // Each name as Radiance's lastmod finds it: the material of that name defined before (void
    // skipped; a name listed twice counted once, as m_clip's set).
    for (size_t i = 0; i < p.strings.size(); ++i) {
      const std::string& name = p.strings[i];
      if (name == "void") continue;
      const int index = ctx.findMaterial(name);
      if (index < 0)
        ctx.fail(ctx.what() + ": its modifier '" + name + "' is not a material defined before it");
      if (i == 0) m.shownMaterial = index;
      if (std::find(m.clipList.begin(), m.clipList.end(), index) == m.clipList.end()) m.clipList.push_back(index);
    }
  }
  // Where rays are not walked through the clip steps: not there.
  std::optional<int> seenInstead(const Material&) const override { return -1; }
  bool mayPassShadowRays(const Material&) const override { return true; }
  std::optional<Rgb> straightTransmittance(const Material&, const Vec3&, const Vec3&) const override {
    return Rgb(1.0);
  }
  double viewTransmittance(const Material&) const override { return 1.0; }
};

}  // namespace

const MaterialFamily& antimatterFamily() {
  static const Antimatter f;
  return f;
}

}  // namespace candela
