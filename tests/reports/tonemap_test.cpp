// Tone mapping and luminance false colour: the operator's fixed points and the chosen ranges.
#include "reports/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace candela {
namespace {

// A uniform grey image maps its luminance to the key: Ls = 0.18 (δ = 10⁻⁴ shifts it by 10⁻⁴
// relative at 1 cd/m²), then Ld = Ls (1 + Ls/Lw²)/(1 + Ls) with Lw = max(Ls, 1) = 1, i.e.
// Ld = Ls: sRGB(0.18) = 118 of 255, whatever the absolute luminance.
TEST(ToneMap, UniformImageMapsToTheKey) {
  for (double l : {1.0, 100.0, 1e5}) {
    const Image8 img = toneMap(3, 2, std::vector<float>(6, static_cast<float>(l)));
    const double v = 0.18;
    const double srgb = 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    EXPECT_EQ(img.at(1, 1).g, static_cast<uint8_t>(std::lround(255 * srgb))) << l;
    EXPECT_EQ(img.at(1, 1).r, img.at(1, 1).b);
  }
}

TEST(ToneMap, BrighterStaysBrighterAndMaskIsBlack) {
  const std::vector<float> lum = {1.0, 10.0, 100.0, 1000.0};
  const Image8 img = toneMap(4, 1, lum, {}, {1, 1, 1, 0});
  EXPECT_LT(img.at(0, 0).g, img.at(1, 0).g);
  EXPECT_LT(img.at(1, 0).g, img.at(2, 0).g);
  EXPECT_EQ(img.at(3, 0), (Rgb8{0, 0, 0}));
  // The brightest pixel maps to white (Ld = 1 at Lw).
  EXPECT_EQ(img.at(2, 0).g, 255);
}

TEST(ToneMap, LuminanceScales) {
  const std::vector<float> lum = {0.0, 3.0, 250.0, 4200.0};
  const ColorScale lin = luminanceScale(lum, false);
  EXPECT_EQ(lin.minValue, 0.0);
  EXPECT_GE(lin.maxValue, 4200.0);
  const ColorScale lg = luminanceScale(lum, true);
  EXPECT_TRUE(lg.logarithmic);
  EXPECT_DOUBLE_EQ(lg.minValue, 1.0);     // decade at or below the smallest positive value, 3
  EXPECT_DOUBLE_EQ(lg.maxValue, 10000.0);
  const ColorScale fixed = luminanceScale(lum, true, 10.0, 1000.0);
  EXPECT_DOUBLE_EQ(fixed.minValue, 10.0);
  EXPECT_DOUBLE_EQ(fixed.maxValue, 1000.0);
  const Image8 fc = luminanceFalseColor(4, 1, lum, lin);
  EXPECT_GT(fc.width, 4);  // the legend is drawn to the right
}

// The three view files land in the folder (created), named after the stem.
TEST(ToneMap, WriteViewImagesWritesThreeFiles) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("candela_view_images_" + std::to_string(::getpid())) / "sub";
  const std::vector<float> lum = {1.0, 10.0, 100.0, 1000.0};
  const ViewImagePaths p = writeViewImages(dir, "v", 2, 2, lum, {}, 1.0, {}, luminanceScale(lum, true), "c");
  EXPECT_EQ(p.exr, dir / "v.exr");
  EXPECT_EQ(p.preview, dir / "v_preview.png");
  for (const fs::path& f : {p.exr, p.falseColor, p.preview}) EXPECT_GT(fs::file_size(f), 0u) << f;
  fs::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace candela
