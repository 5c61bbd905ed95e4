#include "metrics/grid_stats.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace candela {
namespace {

// Hand computation for {100, 200, 300, 400}: sum 1000, Eavg 250, Emin 100, Emax 400,
// U0 = 100/250 = 0.4, Ud = 100/400 = 0.25.
TEST(GridStats, HandComputedValues) {
  const GridStats s = computeGridStats({100.0, 200.0, 300.0, 400.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.averageLux, 250.0);
  EXPECT_DOUBLE_EQ(s.minimumLux, 100.0);
  EXPECT_DOUBLE_EQ(s.maximumLux, 400.0);
  EXPECT_DOUBLE_EQ(s.u0, 0.4);
  EXPECT_DOUBLE_EQ(s.ud, 0.25);
}

TEST(GridStats, SinglePointIsPerfectlyUniform) {
  const GridStats s = computeGridStats({523.5});
  EXPECT_EQ(s.count, 1u);
  EXPECT_DOUBLE_EQ(s.u0, 1.0);
  EXPECT_DOUBLE_EQ(s.ud, 1.0);
}

TEST(GridStats, EmptyAndDarkGridsGiveZeros) {
  const GridStats e = computeGridStats({});
  EXPECT_EQ(e.count, 0u);
  EXPECT_EQ(e.averageLux, 0.0);
  EXPECT_EQ(e.u0, 0.0);
  const GridStats d = computeGridStats({0.0, 0.0});
  EXPECT_EQ(d.count, 2u);
  EXPECT_EQ(d.u0, 0.0);  // no division by zero
  EXPECT_EQ(d.ud, 0.0);
}

// Weights 1, 1, 2 (m²) on {100, 200, 400}: (100 + 200 + 800) / 4 = 275 lux.
TEST(GridStats, AreaWeightedAverage) {
  EXPECT_DOUBLE_EQ(weightedAverageIlluminance({100.0, 200.0, 400.0}, {1.0, 1.0, 2.0}), 275.0);
  const GridStats s = computeGridStats({100.0, 200.0, 400.0}, {1.0, 1.0, 2.0});
  EXPECT_DOUBLE_EQ(s.averageLux, 275.0);
  EXPECT_DOUBLE_EQ(s.u0, 100.0 / 275.0);
  // Equal weights reproduce the plain mean.
  EXPECT_DOUBLE_EQ(weightedAverageIlluminance({100.0, 200.0, 400.0}, {0.3, 0.3, 0.3}),
                   averageIlluminance({100.0, 200.0, 400.0}));
}

TEST(GridStats, WeightErrors) {
  EXPECT_THROW(weightedAverageIlluminance({1.0, 2.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(weightedAverageIlluminance({1.0}, {0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

TEST(GridStatsMedian, OddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(computeGridStats({5.0, 1.0, 3.0}).medianLux, 3.0);
  EXPECT_DOUBLE_EQ(computeGridStats({4.0, 1.0, 3.0, 10.0}).medianLux, 3.5);
}

}  // namespace
}  // namespace candela
