// Whole cases run in-process through the study layer, against closed forms: the glow-sky floor
// (tests/data/study/glow_floor.rad) has E = π L at every sensor and ρ E / π in every pixel, so
// `run` and `render` must both give exactly 895 cd/m² in every pixel of the same view (the issue's
// contract is ±1 %; the estimate is exact, so the check is to rounding).
#include "study/run_case.h"
#include "study/view_study.h"

#include "base/units.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kCase = fs::path(CANDELA_TEST_DATA) / "study" / "glow_floor.toml";
constexpr double kGlowRadiance = 10.0;  // W/sr/m², glow_floor.rad
constexpr double kFloorRho = 0.5;

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

std::vector<float> exrLuminance(const fs::path& path, int& width, int& height) {
  Imf::InputFile file(path.string().c_str());
  const Imath::Box2i dw = file.header().dataWindow();
  width = dw.max.x - dw.min.x + 1;
  height = dw.max.y - dw.min.y + 1;
  std::vector<float> v(static_cast<std::size_t>(width) * height);
  Imf::FrameBuffer fb;
  fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data() - dw.min.x - dw.min.y * width),
                            sizeof(float), sizeof(float) * width));
  file.setFrameBuffer(fb);
  file.readPixels(dw.min.y, dw.max.y);
  return v;
}

TEST(RunCase, GlowFloorGridReadsPiLAtEverySensor) {
  RunRequest request;
  request.outDir = freshDir("study_glow_run");
  const RunResult r = runCase(kCase, request);
  ASSERT_EQ(r.data.grids.size(), 1u);
  const GridReport& g = r.data.grids[0];
  ASSERT_EQ(g.values.size(), 16u);  // 2 m × 2 m at 0.5 m
  // Every hemisphere ray meets the glow: the estimate is exact up to rounding.
  const double expected = kPi * kGlowRadiance * kLumensPerWatt;
  for (double e : g.values) EXPECT_NEAR(e, expected, 1e-12 * expected);
  for (const char* f : {"floor.csv", "down.exr", "down.png", "down_preview.png", "summary.csv", "summary.json",
                        "report.html"})
    EXPECT_TRUE(fs::exists(r.outDir / f)) << f;
}

TEST(RunCase, RunAndRenderGiveTheSameImageOfAView) {
  RunRequest run;
  run.outDir = freshDir("study_glow_run_view");
  runCase(kCase, run);
  RenderRequest render;
  render.view = "down";
  render.outDir = freshDir("study_glow_render_view");
  const RenderResult rr = renderCaseView(kCase, render);

  int w1 = 0, h1 = 0, w2 = 0, h2 = 0;
  const std::vector<float> fromRun = exrLuminance(run.outDir / "down.exr", w1, h1);
  const std::vector<float> fromRender = exrLuminance(rr.paths.exr, w2, h2);
  ASSERT_EQ(w1, 16);
  ASSERT_EQ(h1, 16);
  ASSERT_EQ(w2, w1);
  ASSERT_EQ(h2, h1);
  const double expected = kFloorRho * kGlowRadiance * kLumensPerWatt;  // ρ E / π with E = π L: 895 cd/m²
  for (std::size_t i = 0; i < fromRun.size(); ++i) {
    EXPECT_NEAR(fromRun[i], expected, 1e-6 * expected) << "run, pixel " << i;  // float32 in the file
    EXPECT_EQ(fromRender[i], fromRun[i]) << "pixel " << i;
  }
  for (double l : rr.view.image.luminance) EXPECT_NEAR(l, expected, 0x1p-23 * expected);  // float32 pixels
}

// The view's noise as the report and summary.json give it: every camera ray of the glow floor
// reads ρL exactly (each irradiance estimate is exact: every hemisphere ray meets the sky), so the
// mean is ρL and its reported relative standard error 0; a perspective view has no image glare
// sources. With plain paths (--irradiance-samples 0: each ray 0 or 2ρL) the error is reported and
// the mean lies within 4 of it of ρL.
TEST(RunCase, ViewsReportTheirNoise) {
  RunRequest run;
  run.outDir = freshDir("study_glow_run_noise");
  const RunResult r = runCase(kCase, run);
  ASSERT_EQ(r.data.views.size(), 1u);
  const ViewReport& v = r.data.views[0];
  const double expected = kFloorRho * kGlowRadiance * kLumensPerWatt;
  EXPECT_NEAR(v.meanLuminanceCdM2, expected, 0x1p-23 * expected);  // a mean of float32 pixels
  EXPECT_NEAR(v.meanLuminanceRelativeStandardError, 0.0, 1e-9);
  EXPECT_FALSE(v.glareSourceLuminanceCdM2);
  EXPECT_FALSE(v.glareSourceLuminanceRelativeStandardError);

  RenderRequest render;
  render.view = "down";
  render.outDir = freshDir("study_glow_render_plain");
  render.options.irradianceSamples = 0;
  render.options.coarseStep = 1;
  const RenderResult rr = renderCaseView(kCase, render);
  const ViewLuminance lum = viewLuminance(rr.view);
  ASSERT_GT(lum.meanRelativeStandardError, 0.0);
  EXPECT_NEAR(lum.meanCdM2, expected, 4.0 * lum.meanRelativeStandardError * lum.meanCdM2);
}

TEST(RunCase, UnknownViewNamesTheViews) {
  RenderRequest render;
  render.view = "up";
  try {
    renderCaseView(kCase, render);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no [[view]] named 'up' (views: down)"), std::string::npos) << e.what();
  }
}

// The run's settings name the sun's position only where the sky depends on it: not under the CIE
// overcast sky (its luminance does not depend on the sun), but under a clear one.
TEST(RunCase, SunPositionOnlyWhereTheSkyDependsOnIt) {
  auto settingNames = [](const std::string& file) {
    RunRequest run;
    run.outDir = freshDir("study_sun_position_" + file);
    std::vector<std::string> names;
    for (const auto& [k, v] : runCase(fs::path(CANDELA_TEST_DATA) / "study" / (file + ".toml"), run).data.run.settings)
      names.push_back(k);
    return names;
  };
  const std::vector<std::string> overcast = settingNames("sky_overcast"), clear = settingNames("sky_clear");
  EXPECT_NE(std::find(overcast.begin(), overcast.end(), "sky"), overcast.end());
  EXPECT_EQ(std::find(overcast.begin(), overcast.end(), "sun position"), overcast.end());
  EXPECT_NE(std::find(clear.begin(), clear.end(), "sun position"), clear.end());
}

}  // namespace
}  // namespace candela
