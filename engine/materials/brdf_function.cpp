// plasfunc, metfunc, transfunc and their data forms plasdata, metdata, transdata (Radiance
// reference manual, "Plasfunc", "Metfunc", "Transfunc", "Plasdata", "Metdata", "Transdata";
// src/rt/m_brdf.c, m_brdf2 and dirbrdf):
//   mod plasfunc id 2+ refl funcfile transform 0 4+ red green blue spec A5 …
//   mod transfunc id 2+ brtd funcfile transform 0 6+ red green blue rspec trans tspec A7 …
//   mod plasdata id 4+ func datafile funcfile x1 … xn transform 0 4+ red green blue spec A5 …
// The function (or the data it looks up) is the directional part of the reflection (transfunc:
// of the transmission) of the light sources only, as Radiance uses it: a sampled source's light
// along l is reflected with the BRDF rdiff/π + rspec·f(l) (metfunc, metdata: f times the colour)
// and transmitted with tdiff/π + tspec·f(l) (transfunc, transdata: times the colour), where
// trans' = trans·(1 − rspec), tspec' = trans'·tspec, rdiff = colour·(1 − trans' − rspec) and
// tdiff = colour·(trans' − tspec'). Everything else (the sky, light met by paths) is reflected
// diffusely with colour·(1 − trans') and transmitted diffusely with colour·trans' (Radiance's
// ambient for these types). Shadow rays are stopped (m_brdf2: "always a shadow"); the surface is
// seen the same from both sides (the back turned to the ray, Radiance's default backface
// visibility).
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

// What a material's arguments give (above); trans' and tspec' are 0 for the opaque types.
struct Parts {
  double rspec = 0.0, trans = 0.0, tspec = 0.0;
};

Parts partsOf(const MaterialParameters& m, bool transmits) {
  Parts p;
  p.rspec = m.specularity;
  if (transmits) {
    p.trans = m.transmissivity * (1.0 - p.rspec);
    p.tspec = p.trans * m.transmittedSpecular;
  }
  return p;
}

class BrdfFunction : public MaterialFamily {
 public:
  // `coloured`: the directional part takes the colour (metfunc, metdata; transfunc, transdata for
  // their transmission).
  BrdfFunction(MaterialType type, const char* name, bool transmits, bool coloured)
      : type_(type), name_(name), transmits_(transmits), coloured_(coloured) {}
  MaterialType type() const override { return type_; }
  const char* name() const override { return name_; }
  HitRole role() const override { return HitRole::kScatter; }
  int functionPatterns() const override { return 1; }

  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    const size_t need = transmits_ ? 6 : 4;
    if (p.reals.size() < need)
      ctx.fail(ctx.what() + " needs " + std::to_string(need) + " or more real arguments (" +
               (transmits_ ? "red green blue rspec trans tspec" : "red green blue spec") + "), got " +
               std::to_string(p.reals.size()));
    m.color = ctx.vec(0);
    ctx.expectNonNegative(m.color);
    if (std::max({m.color.x, m.color.y, m.color.z}) > 1.0)
      ctx.fail(ctx.what() + " reflects more than it receives: a colour component above 1");
    m.specularity = p.reals[3];
    if (!(m.specularity >= 0.0 && m.specularity <= 1.0)) ctx.fail(ctx.what() + " needs a specularity in [0, 1]");
    if (transmits_) {
      m.transmissivity = p.reals[4];
      m.transmittedSpecular = p.reals[5];
      if (!(m.transmissivity >= 0.0 && m.transmissivity <= 1.0 && m.transmittedSpecular >= 0.0 &&
            m.transmittedSpecular <= 1.0))
        ctx.fail(ctx.what() + " needs its transmission and transmitted specularity in [0, 1]");
    }
  }
  // The parts light met by paths and the sky see: Radiance's ambient, colour·(1 − trans') and
  // colour·trans'.
  void derive(MaterialParameters& m) const override {
    const Parts p = partsOf(m, transmits_);
    m.diffuseReflectance = m.color * (1.0 - p.trans);
    m.diffuseTransmittance = m.color * p.trans;
    m.specularReflectance = Rgb(0.0);
    m.specularTransmittance = Rgb(0.0);
  }
  bool directionalSources(const Material&) const override { return true; }
  Rgb sourceBrdf(const Material& m, const PatternPoint& at, PatternEvaluator& eval, const Vec3& ldir, double omegaSr,
                 bool transmitted) const override {
    const Parts p = partsOf(m, transmits_);
    const double diffuse = transmitted ? p.trans - p.tspec : 1.0 - p.trans - p.rspec;
    Rgb f = m.color * (std::max(0.0, diffuse) * kInvPi);
    const double spec = transmitted ? p.tspec : p.rspec;
    if (spec <= 0.0) return f;
    // Radiance's dirbrdf: CrP CgP CbP are the patterned colour; a value ≤ 0 adds nothing.
    const double v = eval.directional(m.functions, at, m.color, ldir, omegaSr).x;
    if (!(v > 0.0)) return f;
    // metfunc and metdata colour their reflection, transfunc and transdata their transmission.
    const bool coloured = transmitted ? transmits_ && coloured_ : !transmits_ && coloured_;
    return f + (coloured ? m.color : Rgb(1.0)) * (spec * v);
  }
  bool transmitting() const override { return transmits_; }
  NormalIncidence normalIncidence(const Material& m) const override {
    NormalIncidence n = MaterialFamily::normalIncidence(m);
    if (transmits_) n.transmittance = photopic(m.diffuseTransmittance);
    return n;
  }

 private:
  MaterialType type_;
  const char* name_;
  bool transmits_, coloured_;
};

}  // namespace

const MaterialFamily& plasFuncFamily() {
  static const BrdfFunction f(MaterialType::kPlasFunc, "plasfunc", false, false);
  return f;
}
const MaterialFamily& metFuncFamily() {
  static const BrdfFunction f(MaterialType::kMetFunc, "metfunc", false, true);
  return f;
}
const MaterialFamily& transFuncFamily() {
  static const BrdfFunction f(MaterialType::kTransFunc, "transfunc", true, true);
  return f;
}
const MaterialFamily& plasDataFamily() {
  static const BrdfFunction f(MaterialType::kPlasData, "plasdata", false, false);
  return f;
}
const MaterialFamily& metDataFamily() {
  static const BrdfFunction f(MaterialType::kMetData, "metdata", false, true);
  return f;
}
const MaterialFamily& transDataFamily() {
  static const BrdfFunction f(MaterialType::kTransData, "transdata", true, true);
  return f;
}

}  // namespace candela
