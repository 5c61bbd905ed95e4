#include "metrics/power_density.h"

#include <gtest/gtest.h>

#include <limits>

namespace candela {
namespace {

// W/m² = W / m²; W/m²/100 lx = W/m² · 100 / Ē. The office demo's figures: 600 W over 12 m × 8 m.
TEST(PowerDensity, WattsPerSquareMetreAndPer100Lux) {
  EXPECT_EQ(powerDensityWm2(600.0, 96.0).value(), 6.25);
  EXPECT_EQ(normalisedPowerDensity(6.25, 500.0).value(), 1.25);
  EXPECT_EQ(normalisedPowerDensity(0.0, 500.0).value(), 0.0);  // no power: 0, not unknown
}

// No area, or no light: the figure has no meaning and is not given (never inf or NaN).
TEST(PowerDensity, UndefinedWithoutAreaOrLight) {
  EXPECT_FALSE(powerDensityWm2(600.0, 0.0).has_value());
  EXPECT_FALSE(powerDensityWm2(600.0, -1.0).has_value());
  EXPECT_FALSE(normalisedPowerDensity(6.25, 0.0).has_value());
  EXPECT_FALSE(normalisedPowerDensity(6.25, std::numeric_limits<double>::quiet_NaN()).has_value());
}

}  // namespace
}  // namespace candela
