// The OpenEXR writer, checked by reading the files back with OpenEXR itself: FLOAT channels with
// the written values (also above half's 65504 limit), the unit attribute, nothing left behind.
#include "reports/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>
#include <vector>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
  const fs::path d = fs::temp_directory_path() / ("candela_exr_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<float> readChannel(Imf::InputFile& file, const char* name) {
  const Imath::Box2i dw = file.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  Imf::FrameBuffer fb;
  fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data() - dw.min.x - dw.min.y * w), sizeof(float),
                             sizeof(float) * w));
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return v;
}

TEST(ExrWriter, ReadBackGivesTheWrittenFloatsAndTheUnit) {
  const fs::path dir = tempDir();
  const fs::path path = dir / "view.exr";
  const int w = 7, h = 5;
  std::vector<float> lum(w * h);
  std::vector<glm::vec3> rgb(w * h);
  const double scale = 179.0;  // RGB as radiance, written in cd/m²
  for (int i = 0; i < w * h; ++i) {
    // Values spanning dark corners to the sun's disc (1.6e9 cd/m²), far beyond half's 65504.
    lum[i] = static_cast<float>(0.001 * std::pow(10.0, i * 12.0 / (w * h)));
    rgb[i] = glm::vec3(lum[i] * 1.1f, lum[i], lum[i] * 0.7f) / 179.0f;
  }
  writeLuminanceExr(path, w, h, lum, rgb, scale, "test image");
  ASSERT_TRUE(fs::exists(path));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename(), "view.exr") << "temporary left";

  Imf::InputFile file(path.string().c_str());
  const Imf::Header& hd = file.header();
  const Imath::Box2i dw = hd.dataWindow();
  EXPECT_EQ(dw.max.x - dw.min.x + 1, w);
  EXPECT_EQ(dw.max.y - dw.min.y + 1, h);
  for (const char* c : {"Y", "R", "G", "B"}) {
    const Imf::Channel* ch = hd.channels().findChannel(c);
    ASSERT_NE(ch, nullptr) << c;
    EXPECT_EQ(ch->type, Imf::FLOAT) << c;
  }
  const auto* unit = hd.findTypedAttribute<Imf::StringAttribute>(kExrUnitAttribute);
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->value(), "cd/m2");
  ASSERT_TRUE(Imf::hasWhiteLuminance(hd));
  EXPECT_EQ(Imf::whiteLuminance(hd), 1.0f);
  EXPECT_EQ(Imf::comments(hd), "test image");

  const std::vector<float> y = readChannel(file, "Y"), r = readChannel(file, "R"), b = readChannel(file, "B");
  for (int i = 0; i < w * h; ++i) {
    EXPECT_EQ(y[i], lum[i]) << i;  // bit-exact float round trip
    EXPECT_EQ(r[i], static_cast<float>(scale * rgb[i].x)) << i;
    EXPECT_EQ(b[i], static_cast<float>(scale * rgb[i].z)) << i;
  }
  EXPECT_GT(y.back(), 65504.0f);
  fs::remove_all(dir);
}

TEST(ExrWriter, LuminanceOnlyHasJustY) {
  const fs::path dir = tempDir();
  const fs::path path = dir / "y.exr";
  writeLuminanceExr(path, 2, 2, {1.0, 2.0, 3.0, 4.0});
  Imf::InputFile file(path.string().c_str());
  EXPECT_NE(file.header().channels().findChannel("Y"), nullptr);
  EXPECT_EQ(file.header().channels().findChannel("R"), nullptr);
  const std::vector<float> y = readChannel(file, "Y");
  EXPECT_EQ(y, (std::vector<float>{1.0f, 2.0f, 3.0f, 4.0f}));  // rows top to bottom
  fs::remove_all(dir);
}

// The file is written a block of 64 rows at a time: an image of several blocks and a partial
// one comes back row for row, each pixel its own value.
TEST(ExrWriter, RowsOfSeveralBlocksComeBackInOrder) {
  const fs::path dir = tempDir();
  const fs::path path = dir / "tall.exr";
  const int w = 3, h = 150;
  std::vector<float> lum(w * h);
  std::vector<glm::vec3> rgb(w * h);
  for (int i = 0; i < w * h; ++i) {
    lum[i] = static_cast<float>(i);
    rgb[i] = glm::vec3(static_cast<float>(i), static_cast<float>(2 * i), static_cast<float>(3 * i));
  }
  writeLuminanceExr(path, w, h, lum, rgb);
  Imf::InputFile file(path.string().c_str());
  const std::vector<float> y = readChannel(file, "Y"), g = readChannel(file, "G"), b = readChannel(file, "B");
  EXPECT_EQ(y, lum);
  for (int i = 0; i < w * h; ++i) {
    EXPECT_EQ(g[i], static_cast<float>(2 * i)) << i;
    EXPECT_EQ(b[i], static_cast<float>(3 * i)) << i;
  }
  fs::remove_all(dir);
}

// A failed write (missing folder) throws and leaves nothing, not even the temporary.
TEST(ExrWriter, FailureLeavesNoFile) {
  const fs::path dir = tempDir();
  const fs::path path = dir / "missing" / "view.exr";
  EXPECT_THROW(writeLuminanceExr(path, 1, 1, {1.0}), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_THROW(writeLuminanceExr(dir / "bad.exr", 2, 2, {1.0}), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace candela
