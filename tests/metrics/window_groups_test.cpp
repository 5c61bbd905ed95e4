#include "metrics/window_groups.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace candela {
namespace {

// 100 sensors, one hour, two groups; `a` and `b` sensors lit (2000 lx) through groups 0 and 1
// alone, `both` through both (1500 lx each), the rest dark. Returns the hour's closure.
uint32_t closureOf(int a, int b, int both, bool occupied = true) {
  const int n = 100;
  std::vector<float> d0(n, 0.0f), d1(n, 0.0f), total(n, 0.0f);
  int s = 0;
  for (int i = 0; i < a; ++i, ++s) d0[s] = total[s] = 2000.0f;
  for (int i = 0; i < b; ++i, ++s) d1[s] = total[s] = 2000.0f;
  for (int i = 0; i < both; ++i, ++s) {
    d0[s] = d1[s] = 1500.0f;
    total[s] = 3000.0f;
  }
  std::vector<int> counts(4, 0);
  countSunlitByClosure(total.data(), {d0.data(), d1.data()}, n, 1, 1000.0, counts);
  // Counts by hand: nothing closed, 0 closed (b + both left), 1 closed (a + both), both closed.
  EXPECT_EQ(counts[0], a + b + both);
  EXPECT_EQ(counts[1], b + both);
  EXPECT_EQ(counts[2], a + both);
  EXPECT_EQ(counts[3], 0);
  return blindsClosureFromCounts(counts, 2, n, {static_cast<char>(occupied)})[0];
}

// LM-83's 2 %: with 100 sensors 2 sunlit keep the blinds open, 3 close them.
TEST(WindowGroupBlinds, ClosesOnlyTheGroupThatSunlightsTheRoom) {
  EXPECT_EQ(closureOf(2, 0, 0), 0u);
  EXPECT_EQ(closureOf(3, 0, 0), 1u);         // group 0 alone
  EXPECT_EQ(closureOf(0, 30, 0), 2u);        // group 1 alone
  EXPECT_EQ(closureOf(3, 2, 0), 1u);         // group 0 suffices: 2 left
  EXPECT_EQ(closureOf(3, 3, 0), 3u);         // each above 2 %: both must close
  EXPECT_EQ(closureOf(30, 30, 0, false), 0u);  // unoccupied: open
}

// Neither group alone puts more than 2 % in the sun, but together they do: LM-83 closes groups
// "in any combination, until the criterion value for each hour is achieved" — the one that leaves
// fewer sensors sunlit (group 0 leaves b = 1, group 1 leaves a = 2).
TEST(WindowGroupBlinds, ClosesTheFewestGroupsThatMeetTheCriterion) {
  EXPECT_EQ(closureOf(2, 1, 0), 1u);
  EXPECT_EQ(closureOf(1, 2, 0), 2u);
  // Beams through both groups' glass: closing either removes 1500 of 3000 lx, leaving 1500:
  // still sunlit, so only both closed meet the criterion.
  EXPECT_EQ(closureOf(0, 0, 5), 3u);
}

TEST(WindowGroupBlinds, WithoutACompliantCombinationEveryGroupCloses) {
  // Sun through an opening without glass (in no group): 5 sensors at 2000 lx whatever closes.
  const std::vector<float> total(5, 2000.0f), none(5, 0.0f);
  std::vector<int> counts(2, 0);
  countSunlitByClosure(total.data(), {none.data()}, 5, 1, 1000.0, counts);
  EXPECT_EQ(counts[1], 5);
  EXPECT_EQ(blindsClosureFromCounts(counts, 1, 5, {1})[0], 1u);
  EXPECT_EQ(closedHoursOfGroup({1u, 3u, 0u, 2u}, 0), 2);
  EXPECT_EQ(closedHoursOfGroup({1u, 3u, 0u, 2u}, 1), 2);
}

TEST(WindowGroupBlinds, RejectsBadSizes) {
  std::vector<float> d(1, 0.0f);
  std::vector<int> counts(3, 0);
  EXPECT_THROW(countSunlitByClosure(d.data(), {d.data()}, 1, 1, 1000.0, counts), std::invalid_argument);
  EXPECT_THROW(blindsClosureFromCounts(counts, 1, 1, {1}), std::invalid_argument);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// A two-window room where light is linear in each window: E = s + a·τ_A + b·τ_B (sky through
// other glazing s, window A's part a, B's part b; τ = 1 open, 0.2 closed). With the three traced
// states (open, A closed, B closed) the fold gives every combination's E exactly (to float
// rounding): this is the case of no light path crossing both windows.
TEST(WindowGroupBlinds, FoldIsExactForLightLinearInEachWindow) {
  const std::vector<uint32_t> closure = {0u, 1u, 2u, 3u};  // open, A, B, both
  const float s = 40.0f, a = 700.0f, b = 300.0f;
  auto e = [&](float ta, float tb) { return s + a * ta + b * tb; };
  const std::vector<float> open(4, e(1, 1)), aClosed(4, e(0.2f, 1)), bClosed(4, e(1, 0.2f));
  std::vector<float> combined = open;
  foldClosedGroup(aClosed.data(), open.data(), closure, 0, 1, combined.data());
  foldClosedGroup(bClosed.data(), open.data(), closure, 1, 1, combined.data());
  EXPECT_EQ(combined[0], e(1, 1));
  EXPECT_EQ(combined[1], e(0.2f, 1));  // the traced state itself
  EXPECT_EQ(combined[2], e(1, 0.2f));
  EXPECT_NEAR(combined[3], e(0.2f, 0.2f), 1e-4);
}

}  // namespace
}  // namespace candela
