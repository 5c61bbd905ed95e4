// specfunc, specdata and specpict (spectra of the ray, reduced to RGB at each hit) against the
// reduction of the `spectrum` pattern: the same values give the same RGB; specfunc's 5 nm nodes
// against 1 nm steps within the interpolation bound; specdata's and specpict's coordinates; a
// spectrum on a light and bad hyperspectral pictures refused with their reasons.
#include "engine/irradiance_estimator.h"
#include "engine/radiance/spectrum.h"

#include "engine/daylight.h"
#include "engine/materials/pattern_hook.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "photometry/sky_type.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

// A hyperspectral picture `bytes` is written as s.hsr.
Scene readIn(const std::string& name, const std::string& text, const std::string& hsr = "") {
  const fs::path dir = test_support::scratchDir("spectral", name);
  if (!hsr.empty()) std::ofstream(dir / "s.hsr", std::ios::binary) << hsr;
  std::ofstream(dir / "s.cal") << "ramp(nm) = .2 + .6*(nm - 400)/300;\n"
                                  "half(nm) = if(Px, .8, .2);\n";
  // Two rows over a coordinate 0..1, each a spectrum at 400, 500, 600, 700 nm.
  std::ofstream(dir / "d.dat") << "2\n0 1 2\n400 700 4\n.2 .4 .6 .8\n.9 .7 .5 .3\n";
  std::ofstream(dir / "flat.dat") << "1\n380 780 3\n.8 .8 .8\n";
  std::ofstream(dir / "scene.rad") << text;
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  return sc;
}

// The colour of pattern `name` at x.
Rgb colourOf(const Scene& sc, const std::string& name, const Vec3& x = Vec3(0.5, 0.5, 0.0)) {
  for (size_t i = 0; i < sc.patterns.size(); ++i)
    if (sc.patterns[i].name == name) {
      PatternEvaluator eval(sc);
      return eval.colour(static_cast<int>(i), {x, Vec3(0, 0, -1), Vec3(0, 0, 1), 1.0});
    }
  ADD_FAILURE() << "no pattern " << name;
  return Rgb(0.0);
}

const std::string kUse = "void plastic m 0 0 5 .5 .5 .5 0 0\n";

void expectSame(const Rgb& a, const Rgb& b, double tol, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tol) << what << " channel " << c;
}

// A function that is linear between the spectrum's values is that spectrum: both are reduced as
// linear interpolations between nodes, so the RGB agree to rounding.
TEST(SpectralPatterns, SpecfuncOfASpectrumsValuesIsThatSpectrum) {
  const Scene sc = readIn("equal", "void spectrum s 0 0 5 400 700 .2 .5 .8\n"
                                   "void specfunc f 2 ramp s.cal 0 2 400 700\n" + kUse +
                                       "s plastic a 0 0 5 1 1 1 0 0\nf plastic b 0 0 5 1 1 1 0 0\n"
                                       "a polygon p 0 0 9 0 0 0 1 0 0 0 1 0\nb polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n");
  const Rgb want = colourOf(sc, "s");
  expectSame(colourOf(sc, "f"), want, 1e-12, "specfunc ramp");
  EXPECT_GT(want.x, want.z);  // rising towards the red
}

// The ray's variables reach the function: half(nm) is .8 where Px > 0, .2 elsewhere.
TEST(SpectralPatterns, SpecfuncIsAFunctionOfTheRay) {
  const Scene sc = readIn("ray", "void specfunc f 2 half s.cal 0 2 380 780\nf plastic b 0 0 5 1 1 1 0 0\n"
                                 "b polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n");
  expectSame(colourOf(sc, "f", Vec3(0.5, 0, 0)), Rgb(0.8), 1e-12, "Px > 0");
  expectSame(colourOf(sc, "f", Vec3(-0.5, 0, 0)), Rgb(0.2), 1e-12, "Px < 0");
}

// specfunc's nodes every 5 nm against 1 nm steps: the linear interpolation of s between nodes h
// apart is within h² max|s''| / 8 of s, so each of X, Y, Z (normalised colour-matching sums)
// moves by at most that times ∫|c̄| / ∫c̄, and each RGB channel by the row sum of |M| (the
// XYZ → RGB matrix of Radiance's primaries, written out here) times the largest. Gaussians of
// width σ: max|s''| = 1/σ². Measured: at most 1.7e-3 (0.3 % of the largest channel) for σ of
// 10–40 nm, far inside the bounds; it comes from the colour-matching functions' own curvature
// (h²/12 ∫ s c̄''), so it does not fall with σ.
TEST(SpectralPatterns, FiveNanometreNodesWithinTheInterpolationBound) {
  std::vector<double> nodes;
  for (int nm = 380; nm <= 780; nm += 5) nodes.push_back(nm);
  const std::vector<Rgb> w = spectrumNodeWeights(nodes);
  // ∫|c̄| / ∫c̄ of the fit over 380–780 nm (x̄ has a small negative lobe).
  Vec3 absSum(0.0), sum(0.0);
  for (int nm = 380; nm <= 780; ++nm) {
    absSum += glm::abs(cieColourMatching(nm));
    sum += cieColourMatching(nm);
  }
  const double ratio = std::max({absSum.x / sum.x, absSum.y / sum.y, absSum.z / sum.z});
  // Radiance's primaries and equal-energy white: the largest row sum of |XYZ → RGB|.
  auto column = [](double x, double y) { return Vec3(x / y, 1.0, (1.0 - x - y) / y); };
  const glm::dmat3 p(column(0.640, 0.330), column(0.290, 0.600), column(0.150, 0.060));
  const Vec3 scale = glm::inverse(p) * Vec3(1.0);
  const glm::dmat3 m = glm::inverse(glm::dmat3(p[0] * scale.x, p[1] * scale.y, p[2] * scale.z));
  double rowSum = 0.0;
  for (int r = 0; r < 3; ++r) rowSum = std::max(rowSum, std::abs(m[0][r]) + std::abs(m[1][r]) + std::abs(m[2][r]));
  for (double sigma : {10.0, 20.0, 40.0}) {
    for (double mu : {450.0, 552.5, 610.0}) {
      auto s = [&](double nm) { return std::exp(-0.5 * (nm - mu) * (nm - mu) / (sigma * sigma)); };
      Rgb fromNodes(0.0);
      for (size_t k = 0; k < nodes.size(); ++k) fromNodes += s(nodes[k]) * w[k];
      const Rgb exact = spectrumToRgb(s, 380, 780);
      const double bound = 25.0 / 8.0 / (sigma * sigma) * ratio * rowSum;
      for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(fromNodes[c] - exact[c]), bound) << sigma << " " << mu;
      // Measured: within 0.4 % of the largest channel even for σ = 10 nm.
      const double largest = std::max({exact.x, exact.y, exact.z});
      for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(fromNodes[c] - exact[c]), 4e-3 * largest) << sigma << " " << mu;
    }
  }
}

// specdata: the data's row at the coordinate, a spectrum over the last dimension, through its
// function (noop takes the value; the wavelength it is also given is ignored, as calcomp does).
TEST(SpectralPatterns, SpecdataIsTheSpectrumOfItsRowAtTheCoordinates) {
  const Scene sc = readIn("data", "void spectrum r0 0 0 6 400 700 .2 .4 .6 .8\n"
                                  "void spectrum mid 0 0 6 400 700 .55 .55 .55 .55\n"
                                  "void specdata d0 4 noop d.dat . 0 0 0\n"
                                  "void specdata dm 4 noop d.dat . .5 0 0\n"
                                  "void specdata dx 8 noop d.dat . Px -t 0 0 0 0 0\n" + kUse +
                                      "d0 plastic a 0 0 5 1 1 1 0 0\ndm plastic b 0 0 5 1 1 1 0 0\n"
                                      "dx plastic c 0 0 5 1 1 1 0 0\n"
                                      "a polygon p 0 0 9 0 0 0 1 0 0 0 1 0\nb polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n"
                                      "c polygon r 0 0 9 0 0 0 1 0 0 0 1 0\n");
  expectSame(colourOf(sc, "d0"), colourOf(sc, "r0"), 1e-12, "row 0");
  expectSame(colourOf(sc, "dm"), colourOf(sc, "mid"), 1e-12, "between the rows");
  expectSame(colourOf(sc, "dx", Vec3(0.5, 0, 0)), colourOf(sc, "mid"), 1e-12, "at Px = .5");
}

// On a floor under a uniform sky a specfunc multiplies the colour as the spectrum does.
TEST(SpectralPatterns, SpecfuncOnAFloorUnderTheSky) {
  Scene sc = readIn("floor", "void specfunc f 2 ramp s.cal 0 2 400 700\n"
                             "f plastic p 0 0 5 .5 .5 .5 0 0\n"
                             "p polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n");
  const double want = 0.5 * 10000.0 * photopic(spectrumToRgb([](double nm) { return .2 + .6 * (nm - 400) / 300; },
                                                              400, 700));
  DaylightSpec d;
  d.skyType = parseSkyType("uniform").value();
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = 0.0;
  addDaylight(sc, d);
  TraceSettings s;
  s.seed = 1;
  s.hemisphereSamples = 1024;
  s.maxBounces = 1;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
  EXPECT_LT(e.standardErrorLux(), 0.02 * want);
}

// A Radiance 6 hyperspectral picture (color.h, color.c: NCOMP mantissas and one exponent a
// pixel, flat) of 8 bands from 780 to 380 nm, 50 nm each (centres 755 … 405 nm), two rows of two
// pixels, the top row first ("-Y 2 +X 2"); pixel values are (m + 0.5)/256 (exponent 128).
const std::string kHsrHeader = "#?RADIANCE\nNCOMP=8\nWAVELENGTH_SPLITS= 780 588 480 380\nFORMAT=Radiance_spectra\n\n";
std::string hsrPixel(const std::array<int, 8>& m) {
  std::string p;
  for (int v : m) p += static_cast<char>(v);
  return p + static_cast<char>(128);
}
const std::array<int, 8> kA{200, 180, 160, 140, 120, 100, 80, 60}, kB{20, 40, 60, 80, 100, 120, 140, 160},
    kC{90, 90, 90, 90, 90, 90, 90, 90};
const std::string kHsr = kHsrHeader + "-Y 2 +X 2\n" + hsrPixel(kA) + hsrPixel(kB) + hsrPixel(kC) + hsrPixel(kC);

// The `spectrum` line of a pixel's values: from the shortest band's centre (405 nm) to the
// longest's (755), the file's order reversed.
std::string spectrumOf(const std::string& name, const std::array<int, 8>& m) {
  std::string line = "void spectrum " + name + " 0 0 10 405 755";
  for (int k = 7; k >= 0; --k) {
    char v[32];
    std::snprintf(v, sizeof v, " %.17g", (m[static_cast<size_t>(k)] + 0.5) / 256.0);  // exact: 9 digits at most
    line += v;
  }
  return line + "\n";
}

// specpict: the picture's spectrum at (u, v) = (Px, Py), through noop: at a pixel's centre that
// pixel's spectrum (as the `spectrum` of its values), between them the bilinear mix (the
// reduction to RGB is linear in the values). The picture is 1 × 1 (square): pixel centres at 0
// and 1 along each axis, as Radiance's getspec places them.
TEST(SpectralPatterns, SpecpictIsThePicturesSpectrumAtItsCoordinates) {
  const Scene sc = readIn("pict", spectrumOf("a", kA) + spectrumOf("b", kB) + spectrumOf("c", kC) +
                                      "void specpict p 5 noop s.hsr . Px Py 0 0\n" + kUse +
                                      "p plastic x 0 0 5 1 1 1 0 0\nx polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n",
                          kHsr);
  const Rgb a = colourOf(sc, "a"), b = colourOf(sc, "b"), c = colourOf(sc, "c");
  EXPECT_GT(a.x, a.z);  // A falls towards the blue, B rises
  EXPECT_LT(b.x, b.z);
  expectSame(colourOf(sc, "p", Vec3(0, 1, 0)), a, 1e-9, "top left");
  expectSame(colourOf(sc, "p", Vec3(1, 1, 0)), b, 1e-9, "top right");
  expectSame(colourOf(sc, "p", Vec3(0, 0, 0)), c, 1e-9, "bottom left");
  expectSame(colourOf(sc, "p", Vec3(0.25, 1, 0)), 0.75 * a + 0.25 * b, 1e-9, "along the top row");
  expectSame(colourOf(sc, "p", Vec3(0.25, 0.5, 0)), 0.5 * (0.75 * a + 0.25 * b) + 0.5 * c, 1e-9, "inside");
}

std::string errorOf(const std::string& name, const std::string& text, const std::string& hsr = "") {
  try {
    readIn(name, text, hsr);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpectralPatterns, RefusalsNameTheirLineAndReason) {
  const std::string pict = "void specpict p 5 noop s.hsr . Px Py 0 0\np plastic m 0 0 5 1 1 1 0 0\n"
                           "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n";
  EXPECT_NE(errorOf("pict_args", "void specpict p 4 noop s.hsr . Px 0 0\np plastic m 0 0 5 1 1 1 0 0\n"
                                 "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n", kHsr)
                .find("scene.rad:1: specpict 'p' needs 5 or more string arguments (sfunc picture funcfile u v"),
            std::string::npos);
  EXPECT_NE(errorOf("pict_absent", pict).find("scene.rad:1: specpict 'p'"), std::string::npos);
  std::string threeBands = kHsr;
  threeBands.replace(threeBands.find("NCOMP=8"), 7, "NCOMP=3");
  EXPECT_NE(errorOf("pict_ncomp", pict, threeBands).find("s.hsr:5: picture: a hyperspectral picture needs NCOMP="),
            std::string::npos);
  EXPECT_NE(errorOf("pict_short", pict, kHsr.substr(0, kHsr.size() - 9))
                .find("s.hsr:6: picture: scanline 2 of 2 is missing"),
            std::string::npos);
  std::string rgbe = kHsr;
  rgbe.replace(rgbe.find("Radiance_spectra"), 16, "32-bit_rle_rgbe");
  EXPECT_NE(errorOf("pict_format", pict, rgbe).find("s.hsr:4: picture: format '32-bit_rle_rgbe' is not a Radiance "
                                                    "hyperspectral picture"),
            std::string::npos);
  EXPECT_NE(errorOf("light", "void specfunc f 2 ramp s.cal 0 2 400 700\nf light l 0 0 3 1 1 1\n")
                .find("scene.rad:2: light 'l' is modified by the spectrum 'f'"),
            std::string::npos);
  EXPECT_NE(errorOf("reals", "void specfunc f 2 ramp s.cal 0 1 400\nf plastic m 0 0 5 1 1 1 0 0\n"
                             "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n")
                .find("scene.rad:1: specfunc 'f' needs 2 or more real arguments"),
            std::string::npos);
  EXPECT_NE(errorOf("range", "void specfunc f 2 ramp s.cal 0 2 800 900\nf plastic m 0 0 5 1 1 1 0 0\n"
                             "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n")
                .find("leave nothing of 380-780 nm"),
            std::string::npos);
  EXPECT_NE(errorOf("dims", "void specdata f 3 noop flat.dat . 0 0\nf plastic m 0 0 5 1 1 1 0 0\n"
                            "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n")
                .find("scene.rad:1: specdata 'f': its data file 'flat.dat' needs 2 or more dimensions"),
            std::string::npos);
  EXPECT_NE(errorOf("name", "void specfunc f 2 'ramp(nm)' s.cal 0 2 400 700\nf plastic m 0 0 5 1 1 1 0 0\n"
                            "m polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n")
                .find("must name a function of the wavelength"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
