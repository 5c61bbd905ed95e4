// Radiance data files (engine/radiance/data_file.h): the ies2rad panel's .dat against its IES table,
// data.c's interpolation and extrapolation rule, irregular and descending axes, and one error per
// check with its line.
#include "engine/radiance/data_file.h"
#include "tests/engine/ies2rad_tables.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;
using namespace test_support;

fs::path fixtures() { return fs::path(CANDELA_TEST_DATA) / "rad" / "ies2rad"; }

TEST(RadDataFile, ReadsTheIes2radPanelData) {
  const RadDataArray a = readRadDataFile(fixtures() / "panel.dat", FileLoc{"test", 1, 0});
  ASSERT_EQ(a.dimensions(), 2);
  EXPECT_EQ(a.axes[0].count, 3);
  EXPECT_EQ(a.axes[1].count, 7);
  EXPECT_DOUBLE_EQ(a.axes[0].end, 90.0);
  ASSERT_EQ(a.values.size(), 21u);
  // At the grid points the values are the IES candela / 179 (6 digits, as ies2rad prints them).
  for (size_t h = 0; h < kPanelH.size(); ++h)
    for (size_t v = 0; v < kPanelV.size(); ++v) {
      const double pt[2] = {kPanelH[h], kPanelV[v]};
      EXPECT_NEAR(a.value(pt), kPanelI[h][v] / 179.0, 5e-6 * kPanelI[h][v] / 179.0 + 1e-12);
    }
  // Between them, bilinear.
  for (double h : {10.0, 33.0, 80.0})
    for (double v : {7.0, 40.0, 88.0}) {
      const double pt[2] = {h, v};
      EXPECT_NEAR(a.value(pt), bilinear(kPanelH, kPanelV, kPanelI, h, v) / 179.0, 1e-5);
    }
}

// data.c: "extrapolate as far as one division, then taper off harmonically to zero". With the
// fractional index x and the last cell i (points i, i+1): beyond x = i + 2 the weights are
// c0 = 1/(i − 1 − x), c1 = −2 c0; below x = i − 1 (i = 0), c1 = 1/x, c0 = −2 c1.
TEST(RadDataFile, ExtrapolatesOneDivisionThenTapers) {
  const RadDataArray a = parseRadData("1\n0 2 3\n1 2 4\n", "t.dat");
  auto at = [&](double x) { return a.value(&x); };
  EXPECT_DOUBLE_EQ(at(0.5), 1.5);
  EXPECT_DOUBLE_EQ(at(2.5), 5.0);    // linear: 4 + 0.5 · 2
  EXPECT_DOUBLE_EQ(at(3.0), 6.0);    // one division beyond
  EXPECT_DOUBLE_EQ(at(4.0), -0.25 * 2 + 0.5 * 4);  // x = 4, i = 1: c0 = −1/4, c1 = 1/2
  EXPECT_DOUBLE_EQ(at(-0.5), 0.5);   // linear below: 1 − 0.5 · 1
  EXPECT_DOUBLE_EQ(at(-2.0), 1.0 * 1 + -0.5 * 2);  // x = −2: c1 = −1/2, c0 = 1
}

TEST(RadDataFile, IrregularAndDescendingAxes) {
  // 0 0 n: the points are listed; comments anywhere.
  const RadDataArray a = parseRadData("# irregular\n1\n0 0 4 0 10 30 60 # points\n0 1 3 6\n", "t.dat");
  double x = 20.0;
  EXPECT_DOUBLE_EQ(a.value(&x), 2.0);
  x = 45.0;
  EXPECT_DOUBLE_EQ(a.value(&x), 4.5);
  const RadDataArray d = parseRadData("1\n0 0 3 30 20 0\n5 7 9\n", "t.dat");
  x = 25.0;
  EXPECT_DOUBLE_EQ(d.value(&x), 6.0);
  x = 10.0;
  EXPECT_DOUBLE_EQ(d.value(&x), 8.0);
  // Evenly spaced, descending.
  const RadDataArray e = parseRadData("1\n90 0 3\n0 1 2\n", "t.dat");
  x = 22.5;
  EXPECT_DOUBLE_EQ(e.value(&x), 1.5);
  // Three dimensions: a trilinear function is reproduced exactly.
  std::string text = "3\n0 1 2\n0 2 3\n-1 1 2\n";
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k) {
        const int z = 2 * k - 1;  // the third axis runs from −1 to 1
        text += std::to_string(1 + 2 * i + 3 * j - 5 * z + i * j * z) + " ";
      }
  const RadDataArray t = parseRadData(text, "t.dat");
  const double p[3] = {0.3, 1.7, 0.2};
  EXPECT_NEAR(t.value(p), 1 + 2 * 0.3 + 3 * 1.7 - 5 * 0.2 + 0.3 * 1.7 * 0.2, 1e-12);
}

void expectDataError(const std::string& text, int line, const std::string& part) {
  try {
    parseRadData(text, "t.dat");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().file, "t.dat");
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(e.message().find(part), std::string::npos) << e.what();
  }
}

TEST(RadDataFile, ErrorsNameTheLine) {
  expectDataError("0\n", 1, "number of dimensions must be 1 to 6");
  expectDataError("7\n", 1, "number of dimensions must be 1 to 6");
  expectDataError("1\n0 1 1\n5\n", 2, "at least 2 points");
  expectDataError("1\n0 0 3\n0 2 1\n1 2 3\n", 3, "strictly increasing or strictly decreasing");
  expectDataError("1\n0 1 2\n1\nx\n", 4, "'x' is not a number");
  expectDataError("1\n0 1 2\n1 2\n3\n", 4, "after the 2 values");
  expectDataError("1\n0 1 3\n1 2\n", 3, "unexpected end of file");
  // 10^15 values asked for: refused at the dimension that passes 2^24, before anything is allocated.
  expectDataError("3\n0 1 100000\n0 1 100000\n0 1 100000\n", 3, "more than 16777216 values");
  // The fixtures: a bad word on line 6, a file cut short after line 8.
  try {
    readRadDataFile(fixtures() / "bad_value.dat", FileLoc{"x.rad", 3, 0});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(fs::path(e.loc().file).filename(), "bad_value.dat");
    EXPECT_EQ(e.loc().line, 6) << e.what();
  }
  try {
    readRadDataFile(fixtures() / "short.dat", FileLoc{"x.rad", 3, 0});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 8) << e.what();
  }
}

}  // namespace
}  // namespace candela
