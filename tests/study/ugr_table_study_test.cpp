// The UGR table of photometric files: the reference flux, the refusal of point sources, and the
// same luminaire in both file formats.
#include "study/ugr_table_study.h"

#include "base/error.h"
#include "photometry/photometric_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

const std::string kData = CANDELA_TEST_DATA;
const std::string kCases = kData + "/../../cases/luminaires/";
const std::string kReference = std::string(CANDELA_REFERENCE) + "/photometry/";

TEST(UgrTableStudy, PointSourceIsRefusedAtTheOpeningsLine) {
  const PhotometricWeb web = readPhotometricFile(kData + "/ies/lambert_full.ies");
  try {
    luminaireUgrTable(web);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lambert_full.ies:6: luminous opening is a point"), std::string::npos)
        << e.what();
  }
}

TEST(UgrTableStudy, ConeFluxesAreTheWebsScaledToTheReferenceLampFlux) {
  // T16 fluorescent, 8100 lm of lamps, LOR 40 %: at 1000 lm of lamps the luminaire gives 1000 × LOR.
  const PhotometricWeb web = readPhotometricFile(kReference + "eulumdat-rs/fluorescent_luminaire.ldt");
  const UgrLuminaire l = ugrLuminaireOf(web, kUgrReferenceLampLumens / web.lampLumens());
  EXPECT_NEAR(l.downwardConeLm[3] + l.upwardLm, 1000.0 * web.lightOutputRatio(), 1e-6);
  for (int n = 0; n < 3; ++n) EXPECT_LT(l.downwardConeLm[n], l.downwardConeLm[n + 1]);
  const LuminaireUgrTable t = luminaireUgrTable(web);
  EXPECT_DOUBLE_EQ(t.lampLumens, 8100.0);
  EXPECT_FALSE(t.absolutePhotometry);
  EXPECT_NEAR(t.fluxCorrection(), 8.0 * std::log10(8.1), 1e-12);
  ASSERT_EQ(t.table.crosswise.size(), 19u);
}

TEST(UgrTableStudy, UncorrectedTableDoesNotDependOnTheFilesFlux) {
  // Absolute photometry is scaled to 1000 lm of luminaire flux; the panel's IES and EULUMDAT
  // forms hold the same measurement, so their tables agree to the files' rounding.
  const PhotometricWeb ies = readPhotometricFile(kCases + "led_panel_600.ies");
  const PhotometricWeb ldt = readPhotometricFile(kCases + "led_panel_600.ldt");
  const LuminaireUgrTable a = luminaireUgrTable(ies), b = luminaireUgrTable(ldt);
  EXPECT_TRUE(a.absolutePhotometry);
  EXPECT_NEAR(a.lampLumens, ies.totalLumens(), 1e-9);
  for (size_t i = 0; i < a.table.crosswise.size(); ++i)
    for (size_t j = 0; j < a.table.crosswise[i].size(); ++j) {
      EXPECT_NEAR(a.table.crosswise[i][j], b.table.crosswise[i][j], 0.01);
      EXPECT_NEAR(a.table.endwise[i][j], b.table.endwise[i][j], 0.01);
    }
}

}  // namespace
}  // namespace candela
