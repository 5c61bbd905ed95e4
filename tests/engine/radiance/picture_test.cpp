// Radiance pictures read as getpict (src/rt/data.c) reads them: RGBE decoded as (m + 0.5)·2^(e−136)
// (color.c), rows from the bottom, the shorter side from 0 to 1; flat, old and new run-length
// scanlines; damaged files refused at their place.
#include "engine/radiance/picture.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace candela {
namespace {

std::string pixel(uint8_t r, uint8_t g, uint8_t b, uint8_t e) { return std::string{char(r), char(g), char(b), char(e)}; }

const std::string kHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=2\n\n";

TEST(RadiancePicture, FlatPixelsRowsFromTheBottomAndTheShorterSideToOne) {
  // Three wide, two high: the file's first scanline is the top row.
  std::string bytes = kHeader + "-Y 2 +X 3\n";
  for (int k = 0; k < 6; ++k) bytes += pixel(static_cast<uint8_t>(10 * (k + 1)), 0, 0, 136);
  const auto rgb = parseRadiancePicture(bytes, "p.hdr");
  const RadDataArray& r = rgb[0];
  ASSERT_EQ(r.dimensions(), 2);
  EXPECT_EQ(r.axes[0].count, 2);  // y
  EXPECT_EQ(r.axes[1].count, 3);  // x
  EXPECT_DOUBLE_EQ(r.axes[0].end, 1.0);  // the shorter side
  EXPECT_DOUBLE_EQ(r.axes[1].end, 1.5);
  // Row 0 (bottom) holds the file's second scanline; values (m + 0.5)·2^0, EXPOSURE not undone.
  EXPECT_DOUBLE_EQ(r.values[0], 40.5);
  EXPECT_DOUBLE_EQ(r.values[3], 10.5);
  const double bottomLeft[] = {0.0, 0.0}, topRight[] = {1.0, 1.5};
  EXPECT_DOUBLE_EQ(r.value(bottomLeft), 40.5);
  EXPECT_DOUBLE_EQ(r.value(topRight), 30.5);
  EXPECT_DOUBLE_EQ(rgb[1].values[0], 0.5);  // m = 0 with e ≠ 0 decodes to half a step, as in Radiance
}

TEST(RadiancePicture, RunLengthScanlinesNewAndOld) {
  // New RLE: width 8, each component a run of 8 (code 128 + 8).
  std::string bytes = kHeader + "-Y 1 +X 8\n" + std::string{2, 2, 0, 8};
  for (uint8_t v : {uint8_t(64), uint8_t(32), uint8_t(16), uint8_t(137)}) bytes += std::string{char(128 + 8), char(v)};
  const auto a = parseRadiancePicture(bytes, "new.hdr");
  for (double v : a[0].values) EXPECT_DOUBLE_EQ(v, 64.5 * 2.0);
  for (double v : a[2].values) EXPECT_DOUBLE_EQ(v, 16.5 * 2.0);
  // Old RLE: a pixel, then (1, 1, 1, 3) repeating it three times.
  const std::string old = kHeader + "-Y 1 +X 4\n" + pixel(100, 50, 25, 136) + pixel(1, 1, 1, 3);
  const auto b = parseRadiancePicture(old, "old.hdr");
  for (double v : b[1].values) EXPECT_DOUBLE_EQ(v, 50.5);
}

TEST(RadiancePicture, OrientationsPlaceThePixels) {
  // +X 2 +Y 2: scanlines are columns from the left, each from the bottom up.
  std::string bytes = kHeader + "+X 2 +Y 2\n";
  for (int k = 0; k < 4; ++k) bytes += pixel(static_cast<uint8_t>(k + 1), 0, 0, 136);
  const auto rgb = parseRadiancePicture(bytes, "t.hdr");
  // values[y * 2 + x]: column 0 holds 1 (bottom) and 2 (top); column 1 holds 3 and 4.
  const std::vector<double> want = {1.5, 3.5, 2.5, 4.5};
  EXPECT_EQ(rgb[0].values, want);
}

TEST(RadiancePicture, DamagedFilesAreRefusedAtTheirPlace) {
  auto errorOf = [](const std::string& bytes) {
    try {
      parseRadiancePicture(bytes, "bad.hdr");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorOf(kHeader + "-Y 2 +X 2\n" + pixel(1, 1, 1, 130)).find("bad.hdr:5: picture: scanline 1 of 2"),
            std::string::npos);
  EXPECT_NE(errorOf("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n").find("bad.hdr:2: picture: format"),
            std::string::npos);
  EXPECT_NE(errorOf(kHeader + "-Y 2 -Y 2\n").find("resolution line"), std::string::npos);
  EXPECT_NE(errorOf(kHeader + "-Y 100000 +X 100000\n").find("beyond what candela reads"), std::string::npos);
  EXPECT_NE(errorOf("P6\n2 2\n255\n").find("not a Radiance picture"), std::string::npos);
}

}  // namespace
}  // namespace candela
