// Contrast and contrast rendition factor. CRF compares the task contrast under the actual
// lighting with that under the reference, a uniform luminous sphere; the rendered case (a matte
// task on a matte desk under the sun, CRF = 1) is in tests/engine/render_test.cpp.
#include "metrics/contrast.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace candela {
namespace {

TEST(Contrast, DefinitionAndSign) {
  EXPECT_DOUBLE_EQ(luminanceContrast(150.0, 100.0), 0.5);
  EXPECT_DOUBLE_EQ(luminanceContrast(20.0, 100.0), -0.8);  // dark print on white paper
  EXPECT_THROW(luminanceContrast(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(contrastRenditionFactor(0.5, 0.0), std::invalid_argument);
}

// Matte task and background: L = ρ E / π for both wherever they receive the same illuminance E,
// so C = (ρt − ρb)/ρb under any such lighting, equal to the reference sphere's: CRF = 1.
TEST(Contrast, MatteTaskHasCrfOne) {
  const double rt = 0.05, rb = 0.8;
  const double cref = matteReferenceContrast(rt, rb);
  EXPECT_DOUBLE_EQ(cref, (0.05 - 0.8) / 0.8);
  for (double e : {50.0, 500.0, 12345.0}) {
    const double c = luminanceContrast(rt * e / 3.14159265358979323846, rb * e / 3.14159265358979323846);
    EXPECT_NEAR(contrastRenditionFactor(c, cref), 1.0, 1e-12) << e;
  }
  // A veiling reflection adding the same luminance Lv to both lowers |C|: CRF < 1.
  const double e = 500.0, lv = 20.0;
  const double c = luminanceContrast(rt * e / 3.14159265358979323846 + lv, rb * e / 3.14159265358979323846 + lv);
  EXPECT_LT(contrastRenditionFactor(c, cref), 1.0);
  EXPECT_GT(contrastRenditionFactor(c, cref), 0.0);
}

}  // namespace
}  // namespace candela
