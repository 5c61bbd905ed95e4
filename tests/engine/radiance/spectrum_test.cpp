// Spectra reduced to RGB (engine/radiance/spectrum.h): a flat spectrum is its value in every
// channel (the equal-energy white of Radiance's primaries); the photopic value of any spectrum's
// RGB is its luminous factor ∫ s ȳ / ∫ ȳ (Radiance's luminance weights are the Y row of its
// primaries, to their printed 3 decimals); the patterns `spectrum` and `specfile` multiply a
// floor's colour under a uniform sky (ρE on a sensor facing it), and refuse to shape a light.
#include "engine/radiance/spectrum.h"

#include "engine/daylight.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "photometry/sky_type.h"
#include "tests/support/temp_files.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <fstream>

namespace candela {
namespace {

TEST(Spectrum, FlatSpectraAreGreyAndLuminanceIsTheLuminousFactor) {
  const Rgb one = spectrumToRgb([](double) { return 1.0; }, 380, 780);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(one[c], 1.0, 1e-12);
  const Rgb half = spectrumToRgb([](double) { return 0.5; }, 300, 900);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(half[c], 0.5, 1e-12);
  // A band of 500–600 nm: its luminous factor summed from ȳ directly.
  double band = 0.0, all = 0.0;
  for (int nm = 380; nm <= 780; ++nm) {
    all += cieColourMatching(nm).y;
    if (nm >= 500 && nm <= 600) band += cieColourMatching(nm).y;
  }
  const Rgb green = spectrumToRgb([](double) { return 1.0; }, 500, 600);
  EXPECT_NEAR(photopic(green), band / all, 2e-3);
  EXPECT_GT(green.y, green.x);  // a green band is green
  EXPECT_GT(green.y, green.z);
}

Scene floorUnder(const std::string& modifier, const std::string& name) {
  const auto dir = test_support::scratchDir("spectrum", name);
  std::ofstream(dir / "flat.dat") << "1\n380 780 3\n0.8 0.8 0.8\n";
  std::ofstream(dir / "scene.rad") << modifier
                                   << "p plastic f 0 0 5 .5 .5 .5 0 0\n"
                                      "f polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  DaylightSpec d;
  d.skyType = parseSkyType("uniform").value();
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = 0.0;
  addDaylight(sc, d);
  return sc;
}

void expectFloor(const Scene& sc, double want, const char* what) {
  TraceSettings s;
  s.seed = 1;
  s.hemisphereSamples = 1024;
  s.maxBounces = 1;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux()) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * want) << what;
}

TEST(Spectrum, PatternsMultiplyTheMaterialsColour) {
  expectFloor(floorUnder("void spectrum p 0 0 5 400 700 .6 .6 .6\n", "spectrum"), 0.5 * 0.6 * 10000.0 *
                  photopic(spectrumToRgb([](double) { return 1.0; }, 400, 700)), "spectrum 0.6 over 400-700 nm");
  expectFloor(floorUnder("void specfile p 1 flat.dat 0 0\n", "specfile"), 0.5 * 0.8 * 10000.0, "specfile 0.8");
}

TEST(Spectrum, RefusedOnALightAndForBadArguments) {
  auto errorOf = [](const std::string& text, const std::string& name) {
    try {
      floorUnder(text, name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorOf("void spectrum s 0 0 5 400 700 1 1 1\ns light p 0 0 3 1 1 1\n", "light")
                .find("light 'p' is modified by the spectrum 's'"),
            std::string::npos);
  EXPECT_NE(errorOf("void spectrum p 0 0 4 400 700 1 1\n", "few").find("5 or more real arguments"), std::string::npos);
  EXPECT_NE(errorOf("void spectrum p 0 0 5 400 400 1 1 1\n", "same").find("two different positive numbers"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
