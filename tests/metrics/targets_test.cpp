#include "metrics/targets.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

// EN 12464-1 office writing task: Em = 500 lx, U0 >= 0.6.
TEST(Targets, PassAndFailAsEn12464) {
  GridStats s = computeGridStats({450.0, 550.0, 600.0, 400.0});  // Eavg 500, U0 0.8
  GridTargets t{500.0, 0.6};
  TargetCheck c = checkTargets(s, t);
  EXPECT_EQ(c.average, Verdict::kPass);  // equal to the target passes ("not below")
  EXPECT_EQ(c.uniformity, Verdict::kPass);
  EXPECT_EQ(c.overall, Verdict::kPass);
  EXPECT_DOUBLE_EQ(c.averageRatio, 1.0);
  EXPECT_DOUBLE_EQ(c.uniformityRatio, 0.8 / 0.6);

  s = computeGridStats({200.0, 600.0, 700.0, 500.0});  // Eavg 500, U0 0.4
  c = checkTargets(s, t);
  EXPECT_EQ(c.average, Verdict::kPass);
  EXPECT_EQ(c.uniformity, Verdict::kFail);
  EXPECT_EQ(c.overall, Verdict::kFail);

  s = computeGridStats({499.0});
  c = checkTargets(s, GridTargets{500.0, std::nullopt});
  EXPECT_EQ(c.average, Verdict::kFail);
  EXPECT_EQ(c.uniformity, Verdict::kNotChecked);
  EXPECT_EQ(c.overall, Verdict::kFail);
  // A 1 % tolerance accepts 499 lx against 500 lx.
  EXPECT_EQ(checkTargets(s, GridTargets{500.0, std::nullopt}, 0.01).average, Verdict::kPass);
}

TEST(Targets, NothingToCheck) {
  const TargetCheck c = checkTargets(computeGridStats({1.0}), GridTargets{});
  EXPECT_EQ(c.overall, Verdict::kNotChecked);
  EXPECT_STREQ(verdictName(c.overall), "n/a");
  EXPECT_STREQ(verdictName(Verdict::kPass), "pass");
  EXPECT_STREQ(verdictName(Verdict::kFail), "fail");
}

// The EN 12464-1:2021 relation of the immediate surrounding's Ē_m to the task area's, row by row,
// and between rows (the row at or below); the background takes a third.
TEST(Targets, ImmediateSurroundingAndBackgroundFromTheTaskArea) {
  const double rows[][2] = {{1000.0, 500.0}, {750.0, 500.0}, {500.0, 300.0}, {400.0, 200.0}, {300.0, 200.0},
                            {200.0, 150.0},  {150.0, 150.0}, {100.0, 100.0}, {50.0, 50.0}};
  for (const auto& r : rows) EXPECT_EQ(immediateSurroundingLux(r[0]), r[1]) << r[0];
  EXPECT_DOUBLE_EQ(backgroundLux(500.0), 100.0);
  EXPECT_DOUBLE_EQ(backgroundLux(150.0), 50.0);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// EN 12464-1:2021 walls and ceilings: 50 / 30 lx in any work place, 75 / 50 lx in offices,
// education and health care, U0 ≥ 0.10; nothing for floors or surfaces between.
TEST(Targets, RoomSurfacesOfEachRoomType) {
  EXPECT_EQ(roomSurfaceTargets(RoomType::kGeneral, RoomSurface::kWall).averageLux, 50.0);
  EXPECT_EQ(roomSurfaceTargets(RoomType::kGeneral, RoomSurface::kCeiling).averageLux, 30.0);
  for (RoomType t : {RoomType::kOffice, RoomType::kEducation, RoomType::kHealthcare}) {
    EXPECT_EQ(roomSurfaceTargets(t, RoomSurface::kWall).averageLux, 75.0);
    EXPECT_EQ(roomSurfaceTargets(t, RoomSurface::kCeiling).averageLux, 50.0);
    EXPECT_EQ(roomSurfaceTargets(t, RoomSurface::kWall).uniformity, 0.10);
    EXPECT_FALSE(roomSurfaceTargets(t, RoomSurface::kFloor).averageLux.has_value());
    EXPECT_FALSE(roomSurfaceTargets(t, RoomSurface::kNone).uniformity.has_value());
    EXPECT_EQ(parseRoomType(roomTypeKey(t)), t);
  }
  EXPECT_EQ(parseRoomType("school"), RoomType::kEducation);
  EXPECT_FALSE(parseRoomType("Office").has_value());
}

}  // namespace
}  // namespace candela
