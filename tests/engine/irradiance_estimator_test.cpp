// stratifiedVariance against cases its derivation (docs/estimator.md#stratified-variance) settles
// exactly: a constant radiance adds nothing, a single bump adds its second differences over 6,
// collapsed pairs apply below three φ strata, and refined cells take their own estimate.
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace candela {
namespace {

TEST(StratifiedVariance, ConstantRadianceHasNone) {
  const std::vector<double> y(4 * 12, 3.0);
  EXPECT_EQ(stratifiedVariance(y, 4, 12), 0.0);
}

TEST(StratifiedVariance, OneBumpCountsItsSecondDifferences) {
  // m = 1, n = 6: y = 1 in cell 2, 0 elsewhere. Second differences: 1 at cells 1 and 3, −2 at
  // cell 2, so Σ d²/6 = 1; Var = π² · 1 / 36.
  std::vector<double> y(6, 0.0);
  y[2] = 1.0;
  EXPECT_NEAR(stratifiedVariance(y, 1, 6), kPi * kPi / 36.0, 1e-15);
}

TEST(StratifiedVariance, CollapsedPairsBelowThreePhiStrata) {
  // n = 2: pairs (0, 1) and (2, 3); Σ (y_a − y_b)² = 1 + 4; Var = π² · 5 / 16.
  const std::vector<double> y = {1.0, 2.0, 0.0, 2.0};
  EXPECT_NEAR(stratifiedVariance(y, 2, 2), kPi * kPi * 5.0 / 16.0, 1e-15);
}

TEST(StratifiedVariance, RefinedCellsTakeTheirOwnEstimate) {
  // The bump's cell refined: its own 0.5 replaces the second differences through it only.
  std::vector<double> y(6, 0.0);
  y[2] = 1.0;
  std::vector<double> between(6, std::numeric_limits<double>::quiet_NaN()), within(6, 0.0);
  between[2] = 0.5;
  // Unrefined cells 1 and 3 keep d² = 1 each: (1 + 1)/6 + 0.5.
  EXPECT_NEAR(stratifiedVariance(y, 1, 6, &between, &within), kPi * kPi * (2.0 / 6.0 + 0.5) / 36.0, 1e-15);
}

}  // namespace
}  // namespace candela
