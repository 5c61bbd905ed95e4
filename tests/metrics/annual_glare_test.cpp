// Annual glare metrics (metrics/annual_glare.h) on constructed hourly series whose answers are
// counted by hand: the shares above the DGP classes, glare autonomy, EN 17037's level at and
// around its 5 % boundary, spatial disturbing glare, and the hour-by-hour shading combination.
#include "metrics/annual_glare.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace candela {
namespace {

// 100 occupied hours with the given counts of DGP values in each band, then 50 unoccupied hours
// of intolerable glare that must not count.
struct Series {
  std::vector<float> dgp;
  std::vector<char> occupied;
};

Series bands(int below35, int at35to40, int at40to45, int above45) {
  Series s;
  auto add = [&](int n, float v) {
    for (int i = 0; i < n; ++i) {
      s.dgp.push_back(v);
      s.occupied.push_back(1);
    }
  };
  add(below35, 0.30f);
  add(at35to40, 0.37f);
  add(at40to45, 0.42f);
  add(above45, 0.60f);
  for (int i = 0; i < 50; ++i) {
    s.dgp.push_back(0.9f);
    s.occupied.push_back(0);
  }
  return s;
}

TEST(AnnualGlareMetrics, SharesOfOccupiedHoursAboveEachClass) {
  const Series s = bands(80, 10, 6, 4);  // 100 occupied hours
  const ViewGlareMetrics m = viewGlareMetrics(s.dgp, s.occupied);
  EXPECT_EQ(m.occupiedHours, 100);
  EXPECT_DOUBLE_EQ(m.aboveHigh, 0.20);     // 10 + 6 + 4 above 0.35
  EXPECT_DOUBLE_EQ(m.aboveMedium, 0.10);   // 6 + 4 above 0.40
  EXPECT_DOUBLE_EQ(m.aboveMinimum, 0.04);  // 4 above 0.45
  EXPECT_DOUBLE_EQ(m.glareAutonomy, 0.90);  // 80 + 10 below 0.40
  EXPECT_DOUBLE_EQ(m.aboveDisturbing, 0.10);  // 0.37 is not above 0.38
  EXPECT_TRUE(m.disturbingGlare);
  EXPECT_EQ(m.level, En17037Level::kMinimum);  // only 0.45 is exceeded in ≤ 5 %
}

TEST(AnnualGlareMetrics, ThresholdsAreStrictAndTheFivePercentBoundaryReachesTheLevel) {
  // A value exactly at a limit does not exceed it.
  const std::vector<float> dgp = {0.35f, 0.40f, 0.45f, 0.2f};
  const std::vector<char> occ(4, 1);
  EXPECT_DOUBLE_EQ(shareOfHoursAbove(dgp, occ, 0.35f), 2.0 / 4.0);  // 0.40 and 0.45 (as floats)
  // Exactly 5 % above 0.35 is "exceeded for no more than 5 %": high.
  EXPECT_EQ(viewGlareMetrics(bands(95, 5, 0, 0).dgp, bands(95, 5, 0, 0).occupied).level, En17037Level::kHigh);
  // One hour more is medium (nothing above 0.40).
  EXPECT_EQ(viewGlareMetrics(bands(94, 6, 0, 0).dgp, bands(94, 6, 0, 0).occupied).level, En17037Level::kMedium);
  // 6 % above 0.45: below the minimum.
  const Series none = bands(90, 0, 4, 6);
  EXPECT_EQ(viewGlareMetrics(none.dgp, none.occupied).level, En17037Level::kNone);
  EXPECT_EQ(en17037GlareLevel(0.5, 0.05, 0.0), En17037Level::kMedium);
}

TEST(AnnualGlareMetrics, SpatialDisturbingGlareCountsViewsAtFivePercentOrMore) {
  // sDG counts "at least 5 %" of the occupied hours above 0.38.
  const Series a = bands(95, 0, 5, 0);   // 5 % above 0.38: counts
  const Series b = bands(96, 0, 4, 0);   // 4 %: does not
  const Series c = bands(100, 0, 0, 0);  // none
  const Series d = bands(50, 0, 0, 50);  // 50 %
  std::vector<ViewGlareMetrics> views;
  for (const Series* s : {&a, &b, &c, &d}) views.push_back(viewGlareMetrics(s->dgp, s->occupied));
  EXPECT_TRUE(views[0].disturbingGlare);
  EXPECT_FALSE(views[1].disturbingGlare);
  EXPECT_DOUBLE_EQ(spatialDisturbingGlare(views), 0.5);
  EXPECT_DOUBLE_EQ(spatialDisturbingGlare({}), 0.0);
}

TEST(AnnualGlareMetrics, NoOccupiedHoursGiveZeroSharesAndNoDisturbingGlare) {
  const std::vector<float> dgp = {0.9f, 0.9f};
  const std::vector<char> occ = {0, 0};
  const ViewGlareMetrics m = viewGlareMetrics(dgp, occ);
  EXPECT_EQ(m.occupiedHours, 0);
  EXPECT_DOUBLE_EQ(m.aboveMinimum, 0.0);
  EXPECT_FALSE(m.disturbingGlare);
}

TEST(AnnualGlareMetrics, CombineByHourTakesTheClosedValueWhereFlagged) {
  const std::vector<float> open = {0.5f, 0.6f, 0.7f}, closed = {0.2f, 0.3f, 0.25f};
  const std::vector<char> flags = {0, 1, 1};
  const std::vector<float> c = combineByHour(open, closed, flags);
  EXPECT_EQ(c, (std::vector<float>{0.5f, 0.3f, 0.25f}));
  EXPECT_THROW(combineByHour(open, closed, {0, 1}), std::invalid_argument);
  EXPECT_THROW(viewGlareMetrics(open, {1, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace candela
