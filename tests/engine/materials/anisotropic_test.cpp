// plastic2, metal2, trans2: the anisotropic Ward lobe against its closed form, and the u direction
// read from a function file through the pattern hook.
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/radiance/reader.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace candela {
namespace {

// Ward's anisotropic lobe is a Gaussian over the half vector's slopes (h·u/h·n, h·v/h·n) with
// variances αu²/2 and αv²/2 (Ward 1992, eq. 5a). At normal incidence, with roughnesses small
// enough that no sample falls below the surface (P < 1e-5), the mean squared slopes of 10⁵
// samples are those variances within 4 standard errors (σ² √(2/n) each: the fourth moment of a
// Gaussian is 3σ⁴).
TEST(AnisotropicWard, SlopesHaveTheLobesVariances) {
  Material m;
  m.type = MaterialType::kPlastic2;
  m.roughness = 0.08;
  m.roughnessV = 0.25;
  const Vec3 n(0, 0, 1), u(1, 0, 0), v(0, 1, 0);
  m.anisotropyU = Vec3(1.0, 0.0, 0.4);  // not in the surface: projected
  Rng rng(7, 0);
  const int count = 100000;
  double su = 0.0, sv = 0.0;
  for (int i = 0; i < count; ++i) {
    Vec3 out;
    ASSERT_TRUE(familyOf(m).sampleLobe(m, -n, n, rng, out));
    const Vec3 h = glm::normalize(n + out);
    su += std::pow(glm::dot(h, u) / glm::dot(h, n), 2);
    sv += std::pow(glm::dot(h, v) / glm::dot(h, n), 2);
  }
  const double varU = 0.5 * m.roughness * m.roughness, varV = 0.5 * m.roughnessV * m.roughnessV;
  EXPECT_NEAR(su / count, varU, 4.0 * varU * std::sqrt(2.0 / count));
  EXPECT_NEAR(sv / count, varV, 4.0 * varV * std::sqrt(2.0 / count));
}

// Equal roughnesses give the isotropic lobe: the same mean tan² δ, α² (tan² δ = −α² ln u).
TEST(AnisotropicWard, EqualRoughnessesAreTheIsotropicLobe) {
  Material m;
  m.type = MaterialType::kMetal2;
  m.roughness = m.roughnessV = 0.15;
  m.anisotropyU = Vec3(0.3, 0.9, 0.0);
  const Vec3 n(0, 0, 1);
  Rng rng(11, 0);
  const int count = 100000;
  double sum = 0.0, sq = 0.0;
  for (int i = 0; i < count; ++i) {
    Vec3 out;
    ASSERT_TRUE(familyOf(m).sampleLobe(m, -n, n, rng, out));
    const Vec3 h = glm::normalize(n + out);
    const double c = glm::dot(h, n), t2 = (1.0 - c * c) / (c * c);
    sum += t2;
    sq += t2 * t2;
  }
  const double mean = sum / count, se = std::sqrt((sq / count - mean * mean) / count);
  EXPECT_NEAR(mean, 0.15 * 0.15, 4.0 * se);
}

// The u direction of a function file, turned by the material's transform: (1, 0, 0) turned 90°
// about z is +y at every hit.
TEST(AnisotropicWard, DirectionFromTheFunctionFileThroughItsTransform) {
  const std::filesystem::path dir = test_support::scratchDir("anisotropic", "read");
  std::ofstream(dir / "u.cal") << "ux = 1; uy = 0; uz = 0;\n";
  std::ofstream(dir / "scene.rad") << "void plastic2 brushed 6 ux uy uz u.cal -rz 90 0 6 .5 .5 .5 .05 .05 .2\n"
                                      "brushed polygon p 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n";
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  ASSERT_EQ(sc.materials.size(), 1u);
  const Material& m = sc.materials[0];
  EXPECT_EQ(m.type, MaterialType::kPlastic2);
  EXPECT_DOUBLE_EQ(m.roughness, 0.05);
  EXPECT_DOUBLE_EQ(m.roughnessV, 0.2);
  ASSERT_GE(m.functions, 0);
  PatternEvaluator eval(sc);
  Material out;
  const Material& at = patterned(sc, m, {Vec3(0.5, 0.5, 0.0), Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0}, eval, out);
  EXPECT_NEAR(at.anisotropyU.x, 0.0, 1e-12);
  EXPECT_NEAR(at.anisotropyU.y, 1.0, 1e-12);
  EXPECT_EQ(at.diffuseReflectance, m.diffuseReflectance);  // no pattern: the colour unchanged
  // Too few strings, a missing function: refused at the line, where a surface uses it.
  std::ofstream(dir / "bad.rad") << "void metal2 m 2 ux u.cal 0 6 .5 .5 .5 .9 .1 .1\nm polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n";
  try {
    Scene bad;
    readRadianceFile(dir / "bad.rad", bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.rad:1: metal2 'm' needs 4 or more string arguments"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
