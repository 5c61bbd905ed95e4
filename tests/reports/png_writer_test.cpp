#include "reports/png_writer.h"

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>

namespace candela {
namespace {

// Decodes with libpng's simplified API, independently of the writer's code path.
Image8 decode(const std::vector<uint8_t>& bytes) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&img, bytes.data(), bytes.size()));
  img.format = PNG_FORMAT_RGB;
  Image8 out(static_cast<int>(img.width), static_cast<int>(img.height));
  EXPECT_TRUE(png_image_finish_read(&img, nullptr, out.rgb.data(), 0, nullptr));
  return out;
}

TEST(PngWriter, RoundTripsPixels) {
  Image8 im(7, 5, Rgb8{10, 20, 30});
  im.set(0, 0, Rgb8{255, 0, 0});
  im.set(6, 4, Rgb8{0, 0, 255});
  const Image8 back = decode(encodePng(im));
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, im.rgb);
}

TEST(PngWriter, WritesFileAtomically) {
  const std::filesystem::path p = std::filesystem::path(testing::TempDir()) / "candela_png_test.png";
  writePng(p, Image8(3, 2, Rgb8{1, 2, 3}));
  EXPECT_EQ(std::filesystem::file_size(p), encodePng(Image8(3, 2, Rgb8{1, 2, 3})).size());
  std::filesystem::remove(p);
}

TEST(PngWriter, FontDrawsDigits) {
  Image8 im(40, 9);
  drawText(im, 1, 1, "10", Rgb8{0, 0, 0});
  // '1' has its stem in font column 2 on rows 0..6; '0' starts 6 pixels right, its top row is " ### ".
  for (int row = 0; row < 7; ++row) EXPECT_EQ(im.at(1 + 2, 1 + row), (Rgb8{0, 0, 0})) << row;
  EXPECT_EQ(im.at(1 + 6, 1), (Rgb8{255, 255, 255}));      // '0' top-left corner is blank
  EXPECT_EQ(im.at(1 + 6 + 1, 1), (Rgb8{0, 0, 0}));
  EXPECT_EQ(textWidth("10"), 11);
  EXPECT_EQ(textWidth("10", 2), 22);
}

// A left-to-right ramp: the picture keeps the colour map, the legend bar runs from the map's top
// colour (top) to its bottom colour (bottom), and the legend holds text.
TEST(PngWriter, FalseColorImageWithLegend) {
  const int w = 100, h = 240;
  std::vector<float> v(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[y * w + x] = 5.0f * static_cast<float>(x);  // 0..495 lux
  const ColorScale scale{0.0, 500.0, false};
  const Image8 im = falseColorImage(v, w, h, scale, "lx");
  ASSERT_GT(im.width, w);
  EXPECT_EQ(im.height, h);
  EXPECT_EQ(im.at(0, 10), viridis(0.0));
  EXPECT_EQ(im.at(50, 10), falseColor(250.0, scale));
  // Bar geometry of falseColorImage at font scale 1: x from w + 6, top 18, bottom h - 10.
  EXPECT_EQ(im.at(w + 8, 18), viridis(1.0));
  EXPECT_EQ(im.at(w + 8, h - 10), viridis(0.0));
  int dark = 0;
  for (int y = 0; y < h; ++y)
    for (int x = w + 20; x < im.width; ++x) dark += im.at(x, y) == Rgb8{40, 40, 40};
  EXPECT_GT(dark, 50);  // tick labels were drawn
  EXPECT_THROW(falseColorImage({1.0}, 2, 2, scale, "lx"), std::invalid_argument);
}

}  // namespace
}  // namespace candela
