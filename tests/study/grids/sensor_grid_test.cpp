#include "study/grids/sensor_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace candela {
namespace {

// The EN 12464-1 table of maximum grid sizes (d in m → p in m) for d >= 1 m.
TEST(SensorGrid, AutoSpacingMatchesEn12464Table) {
  EXPECT_DOUBLE_EQ(autoGridSpacingM(5.0), 0.6);   // 0.2·5^log10(5) = 0.6156
  EXPECT_DOUBLE_EQ(autoGridSpacingM(10.0), 1.0);  // 0.2·5 = 1
  EXPECT_DOUBLE_EQ(autoGridSpacingM(1.0), 0.2);
  EXPECT_DOUBLE_EQ(autoGridSpacingM(2.0), 0.3);   // 0.325
  EXPECT_DOUBLE_EQ(autoGridSpacingM(25.0), 2.0);  // 1.90
  EXPECT_DOUBLE_EQ(autoGridSpacingM(50.0), 3.0);  // 3.09
  EXPECT_DOUBLE_EQ(autoGridSpacingM(100.0), 5.0);
  EXPECT_DOUBLE_EQ(autoGridSpacingM(1e6), 10.0);  // capped at 10 m
}

TEST(SensorGrid, GridDimensionUsesShorterSideOfLongAreas) {
  EXPECT_DOUBLE_EQ(gridDimensionM(6.0, 4.0), 6.0);
  EXPECT_DOUBLE_EQ(gridDimensionM(10.0, 5.0), 5.0);  // ratio 2: the shorter side
  EXPECT_DOUBLE_EQ(gridDimensionM(3.0, 20.0), 3.0);
}

PlaneGridSpec rectangle(Vec2 a, Vec2 b, double heightM) {
  PlaneGridSpec s;
  s.outline = {a, b};
  s.origin = Vec3(0.0, 0.0, heightM);
  return s;
}

// A 5 m × 5 m room on auto: p = 0.6 m, ceil(5/0.6) = 9 cells of 5/9 m per side, 81 points at
// the cell centres, the first at 5/18 m from the walls.
TEST(SensorGrid, AutoGridOfFiveMetreRoom) {
  const SensorGrid g = makePlaneGrid(rectangle({0, 0}, {5, 5}, 0.8));
  EXPECT_DOUBLE_EQ(g.nominalSpacingM, 0.6);
  EXPECT_EQ(g.columns, 9);
  EXPECT_EQ(g.rows, 9);
  EXPECT_EQ(g.size(), 81u);
  EXPECT_NEAR(g.spacingM.x, 5.0 / 9.0, 1e-12);
  EXPECT_NEAR(g.points[0].position.x, 5.0 / 18.0, 1e-12);
  EXPECT_NEAR(g.points[0].position.y, 5.0 / 18.0, 1e-12);
  EXPECT_DOUBLE_EQ(g.points[0].position.z, 0.8);
  EXPECT_EQ(g.points[0].normal, Vec3(0, 0, 1));
}

TEST(SensorGrid, AutoGridOfTenMetreRoom) {
  const SensorGrid g = makePlaneGrid(rectangle({0, 0}, {10, 10}, 0.0));
  EXPECT_DOUBLE_EQ(g.nominalSpacingM, 1.0);
  EXPECT_EQ(g.size(), 100u);
  EXPECT_NEAR(g.spacingM.x, 1.0, 1e-12);
  EXPECT_NEAR(g.points.back().position.x, 9.5, 1e-12);
}

// 6 m × 4 m at 0.5 m: 12 × 8 = 96 points; with a 0.5 m border the area is 5 m × 3 m → 10 × 6.
TEST(SensorGrid, FixedSpacingAndBorder) {
  PlaneGridSpec s = rectangle({6, 4}, {0, 0}, 0.75);  // corners in any order
  s.spacingM = 0.5;
  SensorGrid g = makePlaneGrid(s);
  EXPECT_EQ(g.size(), 96u);
  s.borderM = 0.5;
  g = makePlaneGrid(s);
  EXPECT_EQ(g.columns, 10);
  EXPECT_EQ(g.rows, 6);
  EXPECT_EQ(g.size(), 60u);
  for (const SensorPoint& p : g.points) {
    EXPECT_GE(p.position.x, 0.5);
    EXPECT_LE(p.position.x, 5.5);
    EXPECT_GE(p.position.y, 0.5);
    EXPECT_LE(p.position.y, 3.5);
  }
  EXPECT_NEAR(g.points[0].position.x, 0.75, 1e-12);
}

// A spacing that does not divide the side: ceil(6/0.7) = 9 cells of 2/3 m (never coarser).
TEST(SensorGrid, SpacingIsAMaximum) {
  PlaneGridSpec s = rectangle({0, 0}, {6, 6}, 0.0);
  s.spacingM = 0.7;
  const SensorGrid g = makePlaneGrid(s);
  EXPECT_EQ(g.columns, 9);
  EXPECT_NEAR(g.spacingM.x, 2.0 / 3.0, 1e-12);
}

// L-shaped (concave) room: the 4 m × 4 m square minus its upper-right 2 m × 2 m quarter. At
// 1 m spacing the 16 cell centres of the square lose the 4 of the missing quarter: 12 points.
TEST(SensorGrid, ConcavePolygonKeepsInsidePointsOnly) {
  PlaneGridSpec s;
  s.isRectangle = false;
  s.outline = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  s.spacingM = 1.0;
  const SensorGrid g = makePlaneGrid(s);
  EXPECT_EQ(g.size(), 12u);
  for (const SensorPoint& p : g.points) EXPECT_FALSE(p.position.x > 2.0 && p.position.y > 2.0);
  // Same with a 0.6 m border: the lattice covers [0.6, 3.4]² at 1 m → ceil(2.8) = 3 cells of
  // 2.8/3 m per side, centres at 1.067, 2.0 and 2.933 m. Kept (>= 0.6 m from every edge):
  // (1.067, 1.067), (2.0, 1.067), (2.933, 1.067), (1.067, 2.0), (1.067, 2.933) — each 0.933 m or
  // more from the re-entrant edges. Dropped: (2, 2), (2.933, 2) and (2, 2.933) lie on an edge,
  // (2.933, 2.933) is outside. 5 points.
  s.borderM = 0.6;
  const SensorGrid b = makePlaneGrid(s);
  EXPECT_EQ(b.size(), 5u);
  for (const SensorPoint& p : b.points) EXPECT_GE(distanceToOutline(s.outline, Vec2(p.position)), 0.6);
}

TEST(SensorGrid, PolygonHelpers) {
  const std::vector<Vec2> sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(polygonArea(sq), 4.0);
  EXPECT_TRUE(insidePolygon(sq, {1, 1}));
  EXPECT_FALSE(insidePolygon(sq, {3, 1}));
  EXPECT_DOUBLE_EQ(distanceToOutline(sq, {1, 0.5}), 0.5);
}

// A vertical grid on the wall x = 0 facing +X: u along +Y, v up, normal = u × v = +X.
TEST(SensorGrid, VerticalGrid) {
  PlaneGridSpec s;
  s.outline = {{0, 0}, {4, 2}};
  s.origin = Vec3(0.0, 0.0, 0.0);
  s.uAxis = Vec3(0, 1, 0);
  s.vAxis = Vec3(0, 0, 1);
  s.spacingM = 1.0;
  const SensorGrid g = makePlaneGrid(s);
  EXPECT_EQ(g.size(), 8u);
  EXPECT_EQ(g.points[0].normal, Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(g.points[0].position.x, 0.0);
  EXPECT_DOUBLE_EQ(g.points[0].position.y, 0.5);
  EXPECT_DOUBLE_EQ(g.points[0].position.z, 0.5);
}

TEST(SensorGrid, GeometryErrors) {
  EXPECT_THROW(makePlaneGrid(rectangle({0, 0}, {5, 0}, 0.0)), InputError);  // zero area
  PlaneGridSpec s = rectangle({0, 0}, {2, 2}, 0.0);
  s.borderM = 1.0;
  EXPECT_THROW(makePlaneGrid(s), InputError);  // the border eats the area
  s.borderM = 0.0;
  s.spacingM = -1.0;
  try {
    makePlaneGrid(s, FileLoc{"case.toml", 7, 1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 7);
  }
}

TEST(SensorGrid, ReadsPointsWithCommentsAndBlankLines) {
  std::istringstream in("# header\n\n1 2 3 0 0 2\n  4 5 6  0 1 0  # trailing comment\n");
  const std::vector<SensorPoint> pts = readPoints(in, "p.pts");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(pts[0].normal, Vec3(0, 0, 1));  // normalised
  EXPECT_EQ(pts[1].normal, Vec3(0, 1, 0));
}

void expectPointsError(const std::string& text, int line) {
  std::istringstream in(text);
  try {
    readPoints(in, "p.pts");
    FAIL() << "no error for " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_EQ(e.loc().file, "p.pts");
  }
}

TEST(SensorGrid, BadPointLinesNameTheLine) {
  expectPointsError("0 0 0 0 0 1\n1 2 3 0 0\n", 2);          // too few
  expectPointsError("0 0 0 0 0 1\n\n1 2 3 0 0 1 7\n", 3);    // too many
  expectPointsError("# c\n1 2 x 0 0 1\n", 2);                // not a number
  expectPointsError("1 2 3 0 0 0\n", 1);                     // zero direction
  expectPointsError("1 2 3e 0 0 1\n", 1);                    // junk after a number
  // Finite components whose squared length overflows or underflows: glm::normalize gave (0, 0, 0)
  // and Embree aborted the process.
  expectPointsError("0 0 0 0 0 1\n2 1.5 0.8 1e200 0 0\n", 2);
  expectPointsError("2 1.5 0.8 0 -1e300 1\n", 1);
  expectPointsError("2 1.5 0.8 1e-200 0 0\n", 1);
}

TEST(SensorGrid, HugeDirectionsAreRefusedNotNormalisedToZero) {
  const double v[6] = {2, 1.5, 0.8, 1e200, 0, 0};
  try {
    checkedSensorPoint(v, FileLoc{"p.pts", 7, 0});
    FAIL() << "a direction of 1e200 was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "p.pts:7: sensor direction (1e+200 0 0) cannot be normalised: its length overflows or underflows");
  }
  // Large but representable: normalised exactly.
  const double w[6] = {0, 0, 0, 1e150, 0, 0};
  EXPECT_EQ(checkedSensorPoint(w, FileLoc{"p.pts", 1, 0}).normal, Vec3(1, 0, 0));
}

TEST(SensorGrid, ReadsPointsFileFixture) {
  const SensorGrid g = readPointsFile(std::string(CANDELA_TEST_DATA) + "/cases/points/desk.pts");
  EXPECT_EQ(g.size(), 3u);
  EXPECT_FALSE(g.regular);
  EXPECT_THROW(readPointsFile(std::string(CANDELA_TEST_DATA) + "/cases/points/missing.pts"), InputError);
}

// A band around a rectangular task area (EN 12464-1's immediate surrounding, 0.5 m, and the
// background beyond it, within a room): every point lies outside the task at a distance within
// the band, and the points' cells cover the band's exact area (a rectangle's offset: P·w + πw²,
// its perimeter P), up to the cells cut by the band's inner and outer edges: at most their length
// times the spacing.
TEST(SensorGrid, TaskAreaBandsHaveTheirWidthAndArea) {
  const std::vector<Vec2> task = {{1.0, 1.0}, {2.6, 1.0}, {2.6, 1.8}, {1.0, 1.8}};
  const double P = 2.0 * (1.6 + 0.8), A = 1.6 * 0.8, w = 0.5, h = 0.01;
  PlaneGridSpec s;
  s.origin = Vec3(0.0, 0.0, 0.75);
  s.spacingM = h;
  s.outline = {Vec2(1.0 - w, 1.0 - w), Vec2(2.6 + w, 1.8 + w)};
  s.band = {task, 0.0, w};
  const SensorGrid near = makePlaneGrid(s);
  for (const Vec2& uv : near.uv) {
    EXPECT_FALSE(insidePolygon(task, uv));
    EXPECT_LE(distanceToOutline(task, uv), w);
  }
  const double bandArea = P * w + kPi * w * w;
  EXPECT_NEAR(near.size() * h * h, bandArea, (P + (P + 2.0 * kPi * w)) * h);
  // The background in a 4 m × 3 m room: the room less the task and its surrounding (the 3 m band
  // reaches every wall), its cells cut by the surrounding's outer edge and the walls.
  s.outline = {Vec2(0.0, 0.0), Vec2(4.0, 3.0)};
  s.band = {task, w, w + 3.0};
  const SensorGrid far = makePlaneGrid(s);
  for (const Vec2& uv : far.uv) {
    const double d = distanceToOutline(task, uv);
    EXPECT_GT(d, w);
    EXPECT_LE(d, w + 3.0);
  }
  EXPECT_NEAR(far.size() * h * h, 12.0 - A - bandArea, ((P + 2.0 * kPi * w) + 14.0) * h);
  // A task area that fills the room leaves an empty background, not an error.
  s.outline = {Vec2(1.0, 1.0), Vec2(2.6, 1.8)};
  EXPECT_EQ(countPlaneGrid(s), 0u);
}

}  // namespace
TEST(ReadPoints, ByteOrderMarkAndEveryLineEnding) {
  for (const char* f : {"bom_crlf.pts", "cr_only.pts"}) {
    const SensorGrid g = readPointsFile(std::string(CANDELA_TEST_DATA) + "/points/" + f);
    ASSERT_EQ(g.points.size(), 2u) << f;
    EXPECT_EQ(g.points[0].position, Vec3(1, 1, 0.75)) << f;
    EXPECT_EQ(g.points[1].position, Vec3(0.5, 1.5, 0.75)) << f;
  }
  // The same from a stream (stdin): CR and CRLF end lines, the BOM is dropped.
  std::istringstream in("\xEF\xBB\xBF" "1 1 0.75 0 0 1\r0.5 1.5 0.75 0 0 1\r\n2 2 0.75 0 0 1");
  EXPECT_EQ(readPoints(in, "<stdin>").size(), 3u);
}

}  // namespace candela
