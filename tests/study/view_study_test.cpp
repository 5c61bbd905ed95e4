// The report's copy of a view's pictures: the image itself up to 2048 px across, else averaged
// over k × k pixels (the pixels inside only), so that an 8k rendering does not put tens of MB of
// PNG into the HTML page.
#include "study/view_study.h"

#include "reports/png_writer.h"
#include "reports/tonemap.h"
#include "tests/support/test_views.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

ViewResult uniformView(int w, int h, float luminance, bool halfOutside) {
  ViewResult v;
  static_cast<View&>(v.view) = test_support::makeView(ViewType::kPerspective, {0, 0, 1}, {0, 1, 0}, {0, 0, 1},
                                                      {60, 40}, w, h);
  v.view.name = "v";
  Image& img = v.image;
  img.width = w;
  img.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  img.luminance.assign(n, luminance);
  // Grey radiance with that luminance (photopic weights sum to 1).
  img.radiance.assign(n, glm::vec3(luminance / static_cast<float>(kLumensPerWatt)));
  img.standardError.assign(n, 0.0f);
  img.inside.assign(n, 1);
  img.traced.assign(n, 1);
  img.interpolationLevel.assign(n, 0);
  if (halfOutside)
    for (std::size_t i = 0; i < n; i += 2) {  // every other pixel black and outside
      img.inside[i] = 0;
      img.luminance[i] = 0.0f;
      img.radiance[i] = glm::vec3(0.0f);
    }
  v.scale = luminanceScale(img.luminance, true);
  return v;
}

// PNG width and height from the IHDR chunk (bytes 16–23, big-endian).
std::pair<int, int> pngSize(const std::vector<uint8_t>& png) {
  auto be = [&](std::size_t at) { return (png[at] << 24) | (png[at + 1] << 16) | (png[at + 2] << 8) | png[at + 3]; };
  return {be(16), be(20)};
}

TEST(ViewStudy, ReportPicturesAreTheImageUpTo2048Pixels) {
  const ViewResult v = uniformView(300, 7, 120.0f, false);
  const ViewReport r = viewReport(v);
  EXPECT_EQ(r.previewPng, encodePng(toneMap(300, 7, v.image.luminance, v.image.radiance, v.image.inside)));
  EXPECT_EQ(r.falseColorPng, encodePng(luminanceFalseColor(300, 7, v.image.luminance, v.scale)));
}

// 4100 px across: k = 3, a 1367 × 3 copy. Averaging the pixels inside only, an image whose every
// other pixel is outside (black) reads the luminance of the ones inside, not half of it: the
// copy is the uniform picture.
TEST(ViewStudy, ReportPicturesOfLargeImagesAreAveragedOverThePixelsInside) {
  const ViewResult v = uniformView(4100, 9, 120.0f, true);
  const ViewReport r = viewReport(v);
  EXPECT_EQ(pngSize(r.previewPng), std::make_pair(1367, 3));
  const std::vector<float> lum(1367 * 3, 120.0f);
  const std::vector<glm::vec3> rgb(lum.size(), glm::vec3(120.0f / static_cast<float>(kLumensPerWatt)));
  EXPECT_EQ(r.previewPng, encodePng(toneMap(1367, 3, lum, rgb, std::vector<uint8_t>(lum.size(), 1))));
  EXPECT_EQ(r.falseColorPng, encodePng(luminanceFalseColor(1367, 3, lum, v.scale)));
}

}  // namespace
}  // namespace candela
