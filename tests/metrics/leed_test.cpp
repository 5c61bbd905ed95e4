#include "metrics/leed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace candela {
namespace {

LeedOption1Result one(double sda, double ase = 0.0, LeedProjectType type = LeedProjectType::kGeneral) {
  return leedV41Option1({{"room", 50.0, sda, ase}}, type);
}

// Table 1's boundaries are "at least": each value earns its points, the one just below does not.
// A single space is its own average, and "each space >= 55 %" holds from 55 % on.
TEST(LeedV41Option1, PointsAtAndAroundEachBoundary) {
  EXPECT_EQ(one(39.99).points, 0);
  EXPECT_EQ(one(40.0).points, 1);
  EXPECT_EQ(one(54.99).points, 1);
  EXPECT_FALSE(one(54.99).eachSpaceAtLeast55);
  // 55 %: 2 from the average, and the one space at 55 % adds the third.
  EXPECT_EQ(one(55.0).averagePoints, 2);
  EXPECT_TRUE(one(55.0).eachSpaceAtLeast55);
  EXPECT_EQ(one(55.0).points, 3);
  EXPECT_FALSE(one(55.0).exemplaryPerformance);
  EXPECT_EQ(one(74.99).averagePoints, 2);
  EXPECT_EQ(one(75.0).averagePoints, 3);
  // 3 points already: the each-space line is exemplary performance.
  EXPECT_EQ(one(75.0).points, 3);
  EXPECT_TRUE(one(75.0).exemplaryPerformance);
}

TEST(LeedV41Option1, HealthcareTopsAtTwoPointsWithExemplaryPerformance) {
  const auto h = LeedProjectType::kHealthcare;
  EXPECT_EQ(one(39.99, 0, h).points, 0);
  EXPECT_EQ(one(40.0, 0, h).points, 1);
  EXPECT_EQ(one(55.0, 0, h).points, 2);
  EXPECT_TRUE(one(55.0, 0, h).exemplaryPerformance);  // each space >= 55 %
  EXPECT_EQ(one(90.0, 0, h).points, 2);
  EXPECT_TRUE(one(90.0, 0, h).exemplaryPerformance);
}

// ASE above 10 % is flagged for the glare statement; exactly 10 % is not ("greater than 10%").
// It never changes the points.
TEST(LeedV41Option1, AseAboveTenPercentIsFlaggedNotFailed) {
  EXPECT_FALSE(one(60.0, 10.0).spaces[0].aseAbove10);
  EXPECT_TRUE(one(60.0, 10.01).spaces[0].aseAbove10);
  EXPECT_EQ(one(60.0, 10.01).points, one(60.0, 0.0).points);
  const LeedOption1Result r = leedV41Option1({{"a", 10, 80, 30}, {"b", 10, 80, 5}, {"c", 10, 80, 11}});
  ASSERT_EQ(r.glareToAddress.size(), 2u);
  EXPECT_EQ(r.glareToAddress[0], "a");
  EXPECT_EQ(r.glareToAddress[1], "c");
  EXPECT_NE(r.verdict.find("address glare"), std::string::npos);
}

// Unequal spaces: the average is by floor area, not by space. 30 m² at 90 % and 90 m² at 30 %:
// (30·90 + 90·30)/120 = 45 % (1 point), where the plain mean (60 %) would give 2.
TEST(LeedV41Option1, AverageIsWeightedByFloorArea) {
  const LeedOption1Result r = leedV41Option1({{"small", 30.0, 90.0, 0.0}, {"large", 90.0, 30.0, 0.0}});
  EXPECT_NEAR(r.averageSdaPercent, 45.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.totalFloorAreaM2, 120.0);
  EXPECT_EQ(r.points, 1);
  EXPECT_FALSE(r.eachSpaceAtLeast55);
  // Each space at >= 55 % but a 2-point average: the third point.
  const LeedOption1Result s = leedV41Option1({{"a", 10.0, 56.0, 0.0}, {"b", 30.0, 70.0, 0.0}});
  EXPECT_NEAR(s.averageSdaPercent, (10 * 56.0 + 30 * 70.0) / 40.0, 1e-12);
  EXPECT_EQ(s.averagePoints, 2);
  EXPECT_EQ(s.points, 3);
  // One space just under 55 %: no extra point though the average is 2-point.
  EXPECT_EQ(leedV41Option1({{"a", 10.0, 54.9, 0.0}, {"b", 30.0, 70.0, 0.0}}).points, 2);
}

TEST(LeedV41Option1, RejectsBadInput) {
  EXPECT_THROW(leedV41Option1({}), std::invalid_argument);
  EXPECT_THROW(leedV41Option1({{"a", 0.0, 50.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(leedV41Option1({{"a", 10.0, 101.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(leedV41Option1({{"a", 10.0, 50.0, -1.0}}), std::invalid_argument);
}

TEST(LeedV41Option1, GridFloorAreaIsSensorsTimesCell) {
  EXPECT_DOUBLE_EQ(gridFloorAreaM2(1058, 0.24 * 0.24), 1058 * 0.0576);
  EXPECT_THROW(gridFloorAreaM2(-1, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Option 2's share in range and its standard error, against closed forms of the normal model.
TEST(InRangeShare, ExactEstimatesHaveNoUncertainty) {
  const InRangeShare r = inRangeShare({299.0, 300.0, 1500.0, 3000.0, 3001.0}, {0, 0, 0, 0, 0}, 300.0, 3000.0);
  EXPECT_DOUBLE_EQ(r.sharePct, 60.0);  // the bounds are inclusive
  EXPECT_DOUBLE_EQ(r.standardErrorPct, 0.0);
}

TEST(InRangeShare, AnEstimateOnABoundIsACoinToss) {
  // E = 300 ± 20: p = Φ(135) − Φ(0) = 1/2, p(1 − p) = 1/4; three sensors far inside add nothing
  // (p = 1 to double precision): SE = √(1/4) / 4 = 12.5 %.
  const InRangeShare r = inRangeShare({300.0, 1000.0, 1200.0, 1400.0}, {20.0, 20.0, 20.0, 20.0}, 300.0, 3000.0);
  EXPECT_DOUBLE_EQ(r.sharePct, 100.0);
  EXPECT_NEAR(r.standardErrorPct, 12.5, 1e-12);
  // One σ inside the lower bound: p = Φ(1) − Φ(−134) = 0.841344746..., p(1 − p) = 0.133498...
  const double p = 0.8413447460685429;
  EXPECT_NEAR(inRangeShare({320.0}, {20.0}, 300.0, 3000.0).standardErrorPct, 100.0 * std::sqrt(p * (1 - p)), 1e-9);
}

TEST(InRangeShare, RejectsBadInput) {
  EXPECT_THROW(inRangeShare({1.0}, {}, 300.0, 3000.0), std::invalid_argument);
  EXPECT_THROW(inRangeShare({1.0}, {-1.0}, 300.0, 3000.0), std::invalid_argument);
  EXPECT_THROW(inRangeShare({1.0}, {1.0}, 3000.0, 300.0), std::invalid_argument);
}

}  // namespace
}  // namespace candela
