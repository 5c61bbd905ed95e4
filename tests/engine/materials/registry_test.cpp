// The material seam (engine/materials/): one family for every type, in the registry's order, the
// Radiance names each reads, and what each family answers at a hit against closed forms.
#include "engine/materials/registry.h"

#include "engine/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace candela {
namespace {

TEST(MaterialRegistry, OneFamilyForEveryTypeInItsOrder) {
  std::set<std::string> names;
  for (int i = 0; i < kMaterialTypeCount; ++i) {
    const MaterialType t = static_cast<MaterialType>(i);
    EXPECT_EQ(familyOf(t).type(), t) << i;
    EXPECT_TRUE(names.insert(familyOf(t).name()).second) << familyOf(t).name();
    EXPECT_STREQ(materialTypeName(t), familyOf(t).name());
  }
}

TEST(MaterialRegistry, RadianceNamesReadTheirFamily) {
  for (const char* name :
       {"plastic", "metal", "trans", "mirror", "glass", "dielectric", "light", "illum", "glow", "interface", "plastic2",
        "metal2", "trans2", "mist", "BRTDfunc", "plasfunc", "metfunc", "transfunc", "plasdata", "metdata", "transdata",
        "ashik2", "WGMDfunc", "antimatter", "BSDF", "aBSDF"}) {
    const MaterialFamily* f = familyNamed(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_STREQ(f->name(), name);
  }
  ASSERT_NE(familyNamed("spotlight"), nullptr);
  EXPECT_EQ(familyNamed("spotlight")->type(), MaterialType::kLight);
  // A modifier "void" is no material; the types no family reads yet are refused by the reader.
  EXPECT_EQ(familyNamed("void"), nullptr);
  EXPECT_EQ(familyNamed("prism1"), nullptr);
  EXPECT_EQ(familyNamed("Plastic"), nullptr);
  // A mixture (mixfunc) is read with the patterns, not by its family.
  EXPECT_EQ(familyNamed("mixfunc"), nullptr);
  EXPECT_EQ(materialTypeNames(),
            "plastic, metal, trans, mirror, glass, dielectric, light, spotlight, illum, glow, interface, plastic2, "
            "metal2, trans2, mist, BRTDfunc, plasfunc, metfunc, transfunc, plasdata, metdata, transdata, ashik2, WGMDfunc, "
            "antimatter, BSDF, aBSDF");
}

TEST(MaterialRegistry, RolesAndFlags) {
  EXPECT_EQ(familyOf(MaterialType::kVoid).role(), HitRole::kAbsorb);
  for (MaterialType t : {MaterialType::kPlastic, MaterialType::kMetal, MaterialType::kTrans, MaterialType::kPlastic2,
                         MaterialType::kMetal2, MaterialType::kTrans2})
    EXPECT_EQ(familyOf(t).role(), HitRole::kScatter);
  for (MaterialType t : {MaterialType::kMirror, MaterialType::kGlass, MaterialType::kDielectric,
                         MaterialType::kInterface})
    EXPECT_EQ(familyOf(t).role(), HitRole::kSpecular);
  EXPECT_EQ(familyOf(MaterialType::kMixture).role(), HitRole::kMix);
  for (MaterialType t : {MaterialType::kLight, MaterialType::kIllum, MaterialType::kGlow}) {
    EXPECT_EQ(familyOf(t).role(), HitRole::kEmit);
    EXPECT_TRUE(familyOf(t).emits());
    EXPECT_EQ(familyOf(t).sampledSource(), t != MaterialType::kGlow);
  }
  EXPECT_TRUE(familyOf(MaterialType::kMirror).mirrorsSources());
  EXPECT_TRUE(familyOf(MaterialType::kGlass).isGlazing());
  EXPECT_FALSE(familyOf(MaterialType::kTrans).isGlazing());
}

Material derived(MaterialType t, Rgb color, double spec = 0.0, double trans = 0.0, double tspec = 0.0) {
  Material m;
  m.type = t;
  m.color = color;
  m.specularity = spec;
  m.transmissivity = trans;
  m.transmittedSpecular = tspec;
  deriveMaterial(m);
  return m;
}

// Radiance reference manual: plastic reflects colour·(1 − spec) diffusely and spec specularly;
// metal's specular part takes the colour; trans transmits trans·(1 − spec)·colour, tspec of it
// straight on.
TEST(MaterialFamilies, DerivedPartsAreRadiancesDefinitions) {
  const Rgb c(0.5, 0.6, 0.7);
  const Material p = derived(MaterialType::kPlastic, c, 0.05);
  EXPECT_EQ(p.diffuseReflectance, c * 0.95);
  EXPECT_EQ(p.specularReflectance, Rgb(0.05));
  const Material me = derived(MaterialType::kMetal, c, 0.9);
  EXPECT_EQ(me.specularReflectance, c * 0.9);
  const Material t = derived(MaterialType::kTrans, c, 0.0, 0.4, 0.25);
  EXPECT_EQ(t.diffuseReflectance, c * 0.6);
  EXPECT_EQ(t.diffuseTransmittance, c * 0.4 * 0.75);
  EXPECT_EQ(t.specularTransmittance, c * 0.4 * 0.25);
  // Energy: nothing leaves that did not arrive.
  const Rgb total = t.diffuseReflectance + t.diffuseTransmittance + t.specularTransmittance + t.specularReflectance;
  for (int k = 0; k < 3; ++k) EXPECT_LE(total[k], 1.0);
  EXPECT_TRUE(familyOf(p).cacheable(p));
  EXPECT_FALSE(familyOf(t).cacheable(t));  // it transmits
  EXPECT_TRUE(familyOf(p).matteOpaque(derived(MaterialType::kPlastic, c, 0.0)));
  EXPECT_FALSE(familyOf(p).matteOpaque(p));
}

// Shadow rays: clear glass of transmissivity 0.96 and index 1.52 lets 0.88 of the light through
// at normal incidence (Radiance reference manual, "Glass"; the thin-slab sum of engine/fresnel.h);
// trans lets its specular transmission through; illum without an alternate is invisible to them;
// the rest are opaque.
TEST(MaterialFamilies, StraightTransmittance) {
  Material g = derived(MaterialType::kGlass, Rgb(0.96));
  g.refractiveIndex = 1.52;
  const Vec3 down(0, 0, -1), up(0, 0, 1);
  const std::optional<Rgb> tg = familyOf(g).straightTransmittance(g, down, up);
  ASSERT_TRUE(tg.has_value());
  Rgb tr, rf;
  thinGlass(Rgb(0.96), 1.52, -1.0, tr, rf);
  EXPECT_EQ(*tg, tr);
  EXPECT_NEAR(photopic(*tg), 0.88, 0.005);
  const Material t = derived(MaterialType::kTrans, Rgb(0.8), 0.0, 0.5, 0.5);
  EXPECT_EQ(*familyOf(t).straightTransmittance(t, down, up), t.specularTransmittance);
  Material illum = derived(MaterialType::kIllum, Rgb(1.0));
  EXPECT_EQ(*familyOf(illum).straightTransmittance(illum, down, up), Rgb(1.0));
  illum.alternate = 0;
  EXPECT_FALSE(familyOf(illum).straightTransmittance(illum, down, up).has_value());
  for (MaterialType o : {MaterialType::kPlastic, MaterialType::kMetal, MaterialType::kMirror, MaterialType::kDielectric,
                         MaterialType::kLight, MaterialType::kGlow, MaterialType::kVoid}) {
    const Material m = derived(o, Rgb(0.5));
    EXPECT_FALSE(familyOf(m).straightTransmittance(m, down, up).has_value()) << materialTypeName(o);
    EXPECT_FALSE(familyOf(m).mayPassShadowRays(m)) << materialTypeName(o);
  }
}

// The camera's split of a specular surface and the path's sampled event agree: the mean weight of
// the sampled events along each direction is the split's weight, within 4 standard errors (glass
// at 60°, 4·10⁵ samples; a branch taken with probability q = p/(pt + pr) carries w/q, so the
// variance of one sample is w²(1/q − 1)).
TEST(MaterialFamilies, SampledSpecularEventsAverageToTheSplit) {
  Material g = derived(MaterialType::kGlass, Rgb(0.7, 0.8, 0.9));
  g.refractiveIndex = 1.52;
  const Vec3 ng(0, 0, 1);
  const Vec3 d = glm::normalize(Vec3(std::sin(1.047), 0.0, -std::cos(1.047)));
  const SurfaceHit h{d, ng, ng, true, 1.0};
  const SpecularSplit split = familyOf(g).splitSpecular(g, h);
  ASSERT_EQ(split.count, 2);
  EXPECT_FALSE(split.scaled);
  Rng rng(1, 0);
  Rgb straight(0.0), reflected(0.0);
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    Rgb beta(1.0);
    const SpecularSample s = familyOf(g).sampleSpecular(g, h, rng, beta);
    if (s.kind == SpecularSample::Kind::kStraight) {
      EXPECT_EQ(s.dir, d);
      straight += beta;
    } else {
      ASSERT_EQ(s.kind, SpecularSample::Kind::kReflected);
      EXPECT_EQ(s.dir, split.parts[1].dir);
      reflected += beta;
    }
  }
  const double pt = photopic(split.parts[0].weight), pr = photopic(split.parts[1].weight);
  for (int k = 0; k < 3; ++k) {
    const double wt = split.parts[0].weight[k], wr = split.parts[1].weight[k];
    const double seT = std::sqrt(wt * wt * ((pt + pr) / pt - 1.0) / n);
    const double seR = std::sqrt(wr * wr * ((pt + pr) / pr - 1.0) / n);
    EXPECT_NEAR(straight[k] / n, wt, 4.0 * seT);
    EXPECT_NEAR(reflected[k] / n, wr, 4.0 * seR);
  }
  EXPECT_NEAR(split.parts[1].dir.z, std::cos(1.047), 1e-12);  // mirrored about the normal
}

// interface: the boundary between an inside of index 1.5 and an outside of index 1.33 (glass in
// water) reflects ((n1 − n2)/(n1 + n2))² at normal incidence, from either side; an interface with
// a vacuum outside is the dielectric, event for event.
TEST(MaterialFamilies, InterfaceBetweenTwoMedia) {
  Material m;
  m.type = MaterialType::kInterface;
  m.color = Rgb(1.0);
  m.refractiveIndex = 1.5;
  m.outsideIndex = 1.33;
  const Vec3 ng(0, 0, 1);
  const double want = std::pow((1.5 - 1.33) / (1.5 + 1.33), 2);
  for (bool front : {true, false}) {
    const Vec3 d = front ? Vec3(0, 0, -1) : Vec3(0, 0, 1);
    const SpecularSplit s = familyOf(m).splitSpecular(m, {d, ng, front ? ng : -ng, front, 0.5});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.parts[0].weight.x, want, 1e-12) << front;
    EXPECT_NEAR(s.parts[1].weight.x, 1.0 - want, 1e-12) << front;
  }
  Material d = m;
  d.type = MaterialType::kDielectric;
  d.outsideIndex = 1.0;
  Material i = d;
  i.type = MaterialType::kInterface;
  const Vec3 dir = glm::normalize(Vec3(0.3, 0.1, -1.0));
  for (bool front : {true, false}) {
    const SurfaceHit h{front ? dir : -dir, ng, front ? ng : -ng, front, 0.7};
    Rng a(3, 1), b(3, 1);
    Rgb ba(1.0), bb(1.0);
    const SpecularSample sa = familyOf(d).sampleSpecular(d, h, a, ba);
    const SpecularSample sb = familyOf(i).sampleSpecular(i, h, b, bb);
    EXPECT_EQ(sa.dir, sb.dir);
    EXPECT_EQ(ba, bb);
  }
}

// mist is a boundary without scattering: every ray passes it, shadow rays unattenuated.
TEST(MaterialFamilies, MistIsABoundaryRaysPass) {
  Material m;
  m.type = MaterialType::kMist;
  EXPECT_EQ(familyOf(m).seenInstead(m), std::optional<int>(-1));
  EXPECT_EQ(*familyOf(m).straightTransmittance(m, Vec3(0, 0, 1), Vec3(0, 0, 1)), Rgb(1.0));
  EXPECT_TRUE(familyOf(m).mayPassShadowRays(m));
}

}  // namespace
}  // namespace candela
