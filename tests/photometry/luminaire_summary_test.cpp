#include "photometry/luminaire_summary.h"

#include "photometry/ies_lm63.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

const std::string kIes = std::string(CANDELA_TEST_DATA) + "/ies/";

TEST(LuminaireSummary, LambertianBeamAndFieldAngles) {
  // cos(gamma) falls to 50 % at 60 deg and to 10 % at acos(0.1) = 84.26 deg on either side of
  // nadir. The 5 deg linear interpolant moves these by < 0.03 deg per side (h^2/8 cos / sin).
  const LuminaireSummary s = summarizeLuminaire(readIes(kIes + "lambert_rot.ies"));
  EXPECT_NEAR(s.beamC0Deg, 120.0, 0.1);
  EXPECT_NEAR(s.beamC90Deg, 120.0, 0.1);
  EXPECT_NEAR(s.fieldC0Deg, 2.0 * radToDeg(std::acos(0.1)), 0.1);
  EXPECT_NEAR(s.maxIntensityCd, 1000.0, 1e-9);
  EXPECT_NEAR(s.efficacyLmPerW, s.totalLumens / 40.0, 1e-9);
  EXPECT_NEAR(s.lightOutputRatio, s.totalLumens / 4000.0, 1e-12);
  EXPECT_NEAR(s.downwardLumens, s.totalLumens, 1e-9 * s.totalLumens);
  EXPECT_DOUBLE_EQ(s.upwardLumens, 0.0);
  ASSERT_EQ(s.zonalLumens.size(), 18u);
}

TEST(LuminaireSummary, AsymmetricPlanesDiffer) {
  // I = cos g (1 + 0.5 cos(C - 30)): brighter towards C30 so the C0-C180 curve peaks on the C0
  // side; the beam is still finite in both planes.
  const LuminaireSummary s = summarizeLuminaire(readIes(kIes + "asym_c.ies"));
  EXPECT_GT(s.beamC0Deg, 0.0);
  EXPECT_LT(s.beamC0Deg, 180.0);
  const PlaneCurve p = planeCurve(readIes(kIes + "asym_c.ies"), 0.0, 5.0);
  ASSERT_EQ(p.angleDeg.size(), 73u);
  EXPECT_GT(p.intensityCd[36 + 6], p.intensityCd[36 - 6]);  // +30 deg (C0) vs -30 deg (C180)
}

TEST(LuminaireSummary, TextNamesTheKeyFigures) {
  const std::string t = formatSummary(summarizeLuminaire(readIes(kIes + "lambert_full.ies")));
  EXPECT_NE(t.find("Format:"), std::string::npos);
  EXPECT_NE(t.find("IES LM-63-2002"), std::string::npos);
  EXPECT_NE(t.find("Luminous flux:"), std::string::npos);
  EXPECT_NE(t.find("Beam angle (50%):"), std::string::npos);
  EXPECT_NE(t.find("lm/W"), std::string::npos);
  EXPECT_NE(t.find("  0- 10 deg"), std::string::npos);
}

TEST(LuminaireSummary, AbsolutePhotometryHasNoLor) {
  const std::string t = formatSummary(summarizeLuminaire(readIes(kIes + "linear_2019.ies")));
  EXPECT_NE(t.find("absolute photometry"), std::string::npos);
  EXPECT_EQ(t.find("Light output ratio"), std::string::npos);
}

}  // namespace
}  // namespace candela
