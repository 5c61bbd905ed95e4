#include "reports/falsecolor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

double relativeLuminance(Rgb8 c) {
  auto lin = [](uint8_t v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
}

TEST(FalseColor, ViridisEndsAndMiddle) {
  EXPECT_EQ(viridis(0.0), (Rgb8{0x44, 0x01, 0x54}));
  EXPECT_EQ(viridis(0.5), (Rgb8{0x21, 0x90, 0x8C}));
  EXPECT_EQ(viridis(1.0), (Rgb8{0xFD, 0xE7, 0x25}));
  EXPECT_EQ(viridis(-3.0), viridis(0.0));  // clamped
  EXPECT_EQ(viridis(7.0), viridis(1.0));
  EXPECT_EQ(viridis(std::nan("")), viridis(0.0));
}

// Viridis is designed with monotonically increasing lightness: a brighter value never looks darker.
TEST(FalseColor, ViridisLightnessIncreases) {
  double previous = -1.0;
  for (int i = 0; i <= 200; ++i) {
    const double y = relativeLuminance(viridis(i / 200.0));
    EXPECT_GE(y, previous - 1e-3) << i;  // 1e-3: 8-bit rounding of neighbouring samples
    previous = y;
  }
}

TEST(FalseColor, ScalePositionLinearAndLog) {
  const ColorScale lin{0.0, 500.0, false};
  EXPECT_DOUBLE_EQ(scalePosition(125.0, lin), 0.25);
  EXPECT_DOUBLE_EQ(scalePosition(-5.0, lin), 0.0);
  EXPECT_DOUBLE_EQ(scalePosition(900.0, lin), 1.0);
  const ColorScale log{10.0, 10000.0, true};  // three decades
  EXPECT_NEAR(scalePosition(100.0, log), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(scalePosition(1000.0, log), 2.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(scalePosition(0.0, log), 0.0);
  EXPECT_EQ(falseColor(500.0, lin), viridis(1.0));
}

TEST(FalseColor, NiceScalesAndTicks) {
  EXPECT_DOUBLE_EQ(niceScale(0.0, 523.0).maxValue, 600.0);
  EXPECT_DOUBLE_EQ(niceScale(0.0, 100.0).maxValue, 100.0);
  EXPECT_DOUBLE_EQ(niceScale(0.0, 1234.0).maxValue, 1500.0);
  const ColorScale log = niceScale(3.0, 4200.0, true);
  EXPECT_DOUBLE_EQ(log.minValue, 1.0);
  EXPECT_DOUBLE_EQ(log.maxValue, 10000.0);

  const std::vector<double> t = scaleTicks(ColorScale{0.0, 600.0, false}, 6);
  ASSERT_EQ(t.size(), 7u);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], 100.0 * i, 1e-9);
  const std::vector<double> lt = scaleTicks(ColorScale{1.0, 100.0, true});
  const std::vector<double> expected = {1, 2, 5, 10, 20, 50, 100};
  ASSERT_EQ(lt.size(), expected.size());
  for (std::size_t i = 0; i < lt.size(); ++i) EXPECT_NEAR(lt[i], expected[i], 1e-9);
}

// 421..653 lx: step 50 (span 232 / 5 parts → 50), so 400..700.
TEST(FalseColor, NiceRangeAroundTheValues) {
  const ColorScale s = niceRange(420.77, 652.98);
  EXPECT_DOUBLE_EQ(s.minValue, 400.0);
  EXPECT_DOUBLE_EQ(s.maxValue, 700.0);
  EXPECT_FALSE(s.logarithmic);
  const ColorScale flat = niceRange(500.0, 500.0);  // a uniform grid still gets a scale
  EXPECT_DOUBLE_EQ(flat.minValue, 0.0);
  EXPECT_DOUBLE_EQ(flat.maxValue, 500.0);
}

TEST(FalseColor, HexAndContrast) {
  EXPECT_EQ(hexColor(Rgb8{255, 16, 0}), "#ff1000");
  EXPECT_EQ(contrastingText(viridis(0.0)), (Rgb8{255, 255, 255}));  // white on dark violet
  EXPECT_EQ(contrastingText(viridis(1.0)), (Rgb8{0, 0, 0}));        // black on yellow
}

}  // namespace
}  // namespace candela
