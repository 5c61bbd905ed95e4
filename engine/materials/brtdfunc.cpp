// BRTDfunc (Radiance reference manual, "BRTDfunc"; src/rt/m_brdf.c): reflectance and
// transmittance as functions of the ray,
//   mod BRTDfunc id 10+ rrefl grefl brefl rtrns gtrns btrns rbrtd gbrtd bbrtd funcfile transform
//   0 9+ rdf gdf bdf rdb gdb bdb rdt gdt bdt A10 …
// Six expressions give the mirror reflectance and the straight-through transmittance per channel,
// evaluated at each hit with NxP NyP NzP and RdotP turned towards the ray and CrP CgP CbP the
// pattern's colour (Radiance's setbrdfunc); the reals give the diffuse reflectance of the front
// and the back side and the diffuse transmittance, each times the pattern's colour. The
// directional functions rbrtd gbrtd bbrtd (0: none) are functions of a light source's direction
// (lx, ly, lz, omega), the BRDF of its light on either side beside the diffuse parts (Radiance's
// dirbrdf: the sampled sources only; the sky and paths see the diffuse and specular parts). The
// glaze script's coated glazings are BRTDfuncs without them.
#include "engine/materials/function_family.h"
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

class BrtdFunc : public FunctionFamily {
 public:
  MaterialType type() const override { return MaterialType::kBrtdFunc; }
  const char* name() const override { return "BRTDfunc"; }
  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    if (p.reals.size() < 9)
      ctx.fail(ctx.what() + " needs 9 or more real arguments (front, back diffuse reflectance, diffuse "
                            "transmittance), got " + std::to_string(p.reals.size()));
    m.directionalFunctions = p.strings[6] != "0" || p.strings[7] != "0" || p.strings[8] != "0";
    m.color = ctx.vec(0);
    m.backColor = ctx.vec(3);
    m.transmissionColor = ctx.vec(6);
    for (const Rgb& c : {m.color, m.backColor, m.transmissionColor}) ctx.expectNonNegative(c);
    m.roughness = 0.0;  // the reflected part is a mirror's
    m.specularTransmission = !(p.strings[3] == "0" && p.strings[4] == "0" && p.strings[5] == "0");
  }
  void atHit(const Material& m, const PatternPoint& p, const Rgb& patternColour, PatternEvaluator& eval,
             MaterialParameters& out) const override {
    const bool front = glm::dot(p.d, p.ng) < 0.0;
    out.diffuseReflectance = (front ? m.color : m.backColor) * patternColour;
    out.diffuseTransmittance = m.transmissionColor * patternColour;
    out.specularReflectance = glm::max(eval.oriented(m.functions, p, patternColour), Rgb(0.0));
    out.specularTransmittance =
        m.specularTransmission ? glm::max(eval.oriented(m.functions + 1, p, patternColour), Rgb(0.0)) : Rgb(0.0);
  }
  Rgb sourceBrdf(const Material& m, const PatternPoint& at, PatternEvaluator& eval, const Vec3& ldir, double omegaSr,
                 bool transmitted) const override {
    const Rgb f = (transmitted ? m.diffuseTransmittance : m.diffuseReflectance) * kInvPi;
    // Radiance's dirbrdf: the three functions (CrP CgP CbP the pattern's colour); nothing when
    // their brightness is not above 0.
    const Rgb d = eval.directional(m.functions + 2, at, m.patternColour, ldir, omegaSr);
    return photopic(d) > 0.0 ? f + glm::max(d, Rgb(0.0)) : f;
  }
  bool sampleLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out) const override {
    return sampleWardLobe(m, inDir, nf, rng, out);  // roughness 0: the mirror direction
  }
};

}  // namespace

const MaterialFamily& brtdFuncFamily() {
  static const BrtdFunc f;
  return f;
}

}  // namespace candela
