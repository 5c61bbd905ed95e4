// The modelling ratio of EN 12464-1:2021 (metrics/modelling.h): Ē_z/Ē_h of the grid's averages,
// passing within 0.30–0.60, ends included.
#include "metrics/modelling.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace candela {
namespace {

TEST(Modelling, RatioOfTheAverages) {
  // Ē_z = 150, Ē_h = 400: not the mean of the points' ratios (0.4375).
  const ModellingResult m = modellingRatio({100.0, 200.0}, {400.0, 400.0});
  EXPECT_DOUBLE_EQ(m.cylindricalAverageLux, 150.0);
  EXPECT_DOUBLE_EQ(m.horizontalAverageLux, 400.0);
  EXPECT_DOUBLE_EQ(m.ratio, 0.375);
  EXPECT_EQ(m.verdict, Verdict::kPass);
  EXPECT_DOUBLE_EQ(modellingRatio({100.0, 250.0}, {200.0, 600.0}).ratio, 175.0 / 400.0);
}

TEST(Modelling, VerdictAgainst030To060EndsIncluded) {
  EXPECT_EQ(modellingRatio({30.0}, {100.0}).verdict, Verdict::kPass);
  EXPECT_EQ(modellingRatio({60.0}, {100.0}).verdict, Verdict::kPass);
  EXPECT_EQ(modellingRatio({29.9}, {100.0}).verdict, Verdict::kFail);
  EXPECT_EQ(modellingRatio({60.1}, {100.0}).verdict, Verdict::kFail);
  // No horizontal light: no ratio, and no good modelling either.
  const ModellingResult dark = modellingRatio({0.0}, {0.0});
  EXPECT_EQ(dark.ratio, 0.0);
  EXPECT_EQ(dark.verdict, Verdict::kFail);
  EXPECT_EQ(pointModellingRatio(5.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pointModellingRatio(5.0, 20.0), 0.25);
}

TEST(Modelling, LengthsMustMatch) {
  EXPECT_THROW(modellingRatio({1.0, 2.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace candela
