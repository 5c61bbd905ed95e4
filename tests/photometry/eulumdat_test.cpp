#include "photometry/eulumdat.h"

#include "base/error.h"
#include "photometry/ies_lm63.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

const std::string kLdt = std::string(CANDELA_TEST_DATA) + "/ldt/";
const std::string kIes = std::string(CANDELA_TEST_DATA) + "/ies/";

// The .ldt fixtures hold I / (flux / 1000) / CF with 6 decimals (flux 2000 lm), so the
// rebuilt candelas agree with the IES fixtures of the same formula to ~1e-5 cd.
void expectSameWeb(const PhotometricWeb& a, const PhotometricWeb& b) {
  for (double c = -10.0; c < 370.0; c += 7.3)
    for (double g = 0.0; g <= 180.0; g += 3.3)
      ASSERT_NEAR(a.intensityCd(c, g), b.intensityCd(c, g), 2e-5) << "C " << c << " gamma " << g;
  EXPECT_NEAR(a.totalLumens(), b.totalLumens(), 1e-6 * b.totalLumens());
}

TEST(Eulumdat, HeaderAndScaling) {
  const PhotometricWeb web = readEulumdat(kLdt + "lambert_isym1.ldt");
  EXPECT_EQ(web.format(), "EULUMDAT");
  EXPECT_NEAR(web.intensityCd(0.0, 0.0), 1000.0, 1e-5);  // 500 cd/klm x 2000 lm
  EXPECT_DOUBLE_EQ(web.lampLumens(), 2000.0);
  EXPECT_DOUBLE_EQ(web.inputWatts(), 30.0);
  EXPECT_NEAR(web.totalLumens(), kPi * 1000.0, 0.005 * kPi * 1000.0);
  EXPECT_NEAR(web.lightOutputRatio(), web.totalLumens() / 2000.0, 1e-12);
  EXPECT_NEAR(web.openingWidthM(), 0.6, 1e-12);
  EXPECT_NEAR(web.openingLengthM(), 0.6, 1e-12);
  EXPECT_EQ(web.openingShape(), OpeningShape::kRectangular);
  EXPECT_NEAR(web.info().luminaireLengthM, 0.62, 1e-12);
  EXPECT_DOUBLE_EQ(web.info().declaredLorPercent, 78.5);
  EXPECT_DOUBLE_EQ(web.info().declaredDownwardFluxPercent, 100.0);
  EXPECT_EQ(web.keywords().at("LUMINAIRE"), "analytic lambert_isym1.ldt");
  ASSERT_EQ(web.info().lampSets.size(), 1u);
  EXPECT_EQ(web.info().lampSets[0].colour, "4000 K");
}

TEST(Eulumdat, NegativeLampCountIsAbsolutePhotometry) {
  const PhotometricWeb web = readEulumdat(kLdt + "lambert_absolute.ldt");
  EXPECT_TRUE(web.isAbsolute());
  EXPECT_TRUE(std::isnan(web.lightOutputRatio()));
  EXPECT_NEAR(web.intensityCd(0.0, 0.0), 1000.0, 1e-3);  // 318.309... cd/klm x 3141.6 lm
}

TEST(Eulumdat, AgreesWithIesOfTheSameDistribution) {
  expectSameWeb(readEulumdat(kLdt + "asym_isym0.ldt"), readIes(kIes + "asym_c.ies"));
  expectSameWeb(readEulumdat(kLdt + "lambert_isym1.ldt"), readIes(kIes + "lambert_full.ies"));
}

TEST(Eulumdat, SymmetryIndicatorsMatchFullFiles) {
  expectSameWeb(readEulumdat(kLdt + "half_isym2.ldt"), readIes(kIes + "half_full.ies"));
  expectSameWeb(readEulumdat(kLdt + "h9027_isym3.ldt"), readIes(kIes + "h9027_full.ies"));
  expectSameWeb(readEulumdat(kLdt + "quad_isym4.ldt"), readIes(kIes + "quad_full.ies"));  // CF 2
}

struct BadFile {
  const char* name;
  int line;
  const char* text;
};

class LdtErrors : public testing::TestWithParam<BadFile> {};

TEST_P(LdtErrors, NamesFileAndLine) {
  const BadFile& b = GetParam();
  try {
    readEulumdat(kLdt + b.name);
    FAIL() << b.name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, b.line) << e.what();
    const std::string what = e.what();
    EXPECT_NE(what.find(std::string(b.name) + ":" + std::to_string(b.line) + ": "), std::string::npos) << what;
    EXPECT_NE(what.find(b.text), std::string::npos) << what;
  }
}

TEST(Eulumdat, LampSetsInTheBlockLayoutOfRealFiles) {
  // A manufacturer's file (tests/data/reference): each set's lines 26a-f together. It was once
  // refused with "bad number 'LED110-CLO/730' for number of lamps".
  const PhotometricWeb web =
      readEulumdat(std::string(CANDELA_REFERENCE) + "/photometry/eulumdat-rs/demo_two_lamp_sets.ldt");
  const auto& sets = web.info().lampSets;
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].count, 1);
  EXPECT_EQ(sets[0].type, "LED110-CLO/730");
  EXPECT_EQ(sets[0].totalFluxLm, 9408.0);
  EXPECT_EQ(sets[0].wattsW, 72.0);
  EXPECT_EQ(sets[1].type, "LED120-CLO/730");
  EXPECT_EQ(sets[1].totalFluxLm, 10080.0);
  EXPECT_EQ(sets[1].colourRendering, "70");
  EXPECT_EQ(sets[1].wattsW, 79.0);
  // Intensities are per 1000 lm of lamp set 1 (EULUMDAT's convention).
  EXPECT_EQ(web.info().lampLumens, 9408.0);
}

TEST(Eulumdat, LampSetsFieldByFieldWhereThatIsUnambiguous) {
  const PhotometricWeb web = readEulumdat(kLdt + "two_sets_by_field.ldt");
  const auto& sets = web.info().lampSets;
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].type, "LED");
  EXPECT_EQ(sets[1].type, "T8 58W");
  EXPECT_EQ(sets[1].count, 2);
  EXPECT_EQ(sets[1].colour, "3000 K");
  EXPECT_EQ(sets[1].wattsW, 20.0);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, LdtErrors,
    testing::Values(BadFile{"bad_truncated.ldt", 130, "truncated"},
                    BadFile{"bad_isym.ldt", 3, "symmetry indicator"},
                    BadFile{"bad_number.ldt", 13, "bad number '6x0'"},
                    BadFile{"bad_c_angles.ldt", 45, "C angles must increase"},
                    BadFile{"bad_negative.ldt", 111, "negative luminous intensity"},
                    BadFile{"bad_extra.ldt", 141, "unexpected line"},
                    BadFile{"bad_flux.ldt", 29, "lamp flux"},
                    BadFile{"bad_mc.ldt", 4, "multiple of 4"},
                    // Counts a small file cannot hold are refused before any allocation.
                    BadFile{"huge_mc.ldt", 4, "Mc = 400000000 needs 400000000 more lines"},
                    BadFile{"huge_ng.ldt", 6, "Ng = 1000000000 needs"},
                    BadFile{"huge_lamp_sets.ldt", 26, "the number of lamp sets = 10000000 needs 60000000 more lines"}),
    [](const testing::TestParamInfo<BadFile>& info) {
      std::string n = info.param.name;
      return n.substr(0, n.find('.'));
    });

}  // namespace
}  // namespace candela

namespace candela {
namespace {

TEST(Eulumdat, ExamplePanelAgreesWithItsIesTwin) {
  // cases/luminaires/led_panel_600.{ies,ldt}: I = I0 cos^1.2(g) (1 + 0.04 cos 2C) with
  // I0 = 3600 lm x 2.2 / (2 pi), i.e. 3600 lm. The .ies rounds to 0.1 cd, the .ldt to
  // 0.01 cd/klm (0.036 cd), hence 0.1 cd; the 5 deg interpolant is within 0.1 % of 3600 lm.
  // The .ies has C planes every 22.5 deg, the .ldt every 15 deg: compare on the planes both hold
  // (multiples of 45 deg), where the interpolation runs along gamma only.
  const std::string dir = std::string(CANDELA_TEST_DATA) + "/../../cases/luminaires/";
  const PhotometricWeb ies = readIes(dir + "led_panel_600.ies");
  const PhotometricWeb ldt = readEulumdat(dir + "led_panel_600.ldt");
  for (double c = 0.0; c < 360.0; c += 45.0)
    for (double g = 0.0; g <= 180.0; g += 2.5)
      ASSERT_NEAR(ies.intensityCd(c, g), ldt.intensityCd(c, g), 0.1) << c << " " << g;
  EXPECT_NEAR(ies.totalLumens(), 3600.0, 3.6);
  // Over C the flux is a trapezoid sum, which integrates the periodic cos 2C ripple exactly on
  // either grid, so both fluxes agree up to the rounding of the values.
  EXPECT_NEAR(ldt.totalLumens(), ies.totalLumens(), 1e-4 * ies.totalLumens());
  EXPECT_TRUE(ldt.isAbsolute());
  EXPECT_NEAR(ldt.openingWidthM(), ies.openingWidthM(), 1e-12);
}

}  // namespace
}  // namespace candela
