// NaN or infinity is never written as a result.
#include "study/finite_results.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <limits>

namespace candela {
namespace {

TEST(FiniteResults, NonFiniteValuesAreRefusedWithTheirIndex) {
  std::vector<IrradianceEstimate> est(3);
  est[0].irradiance = Rgb(1.0);
  EXPECT_NO_THROW(checkFinite(est, "grid"));
  est[2].irradiance = Rgb(std::numeric_limits<double>::quiet_NaN());
  try {
    checkFinite(est, "grid 'desk'");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("grid 'desk' at index 2"), std::string::npos) << e.what();
  }
  est[2].irradiance = Rgb(1.0);
  est[1].variancePhotopic = std::numeric_limits<double>::infinity();
  EXPECT_THROW(checkFinite(est, "grid"), std::runtime_error);
  EXPECT_THROW(checkFinite(std::vector<float>{1.0f, -std::numeric_limits<float>::infinity()}, "year"),
               std::runtime_error);
  EXPECT_NO_THROW(checkFinite(std::vector<double>{0.0, 1e300}, "image"));
}

}  // namespace
}  // namespace candela
