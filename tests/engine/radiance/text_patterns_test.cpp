// brighttext, colortext and mixtext (engine/radiance/text_pattern.h) with Radiance's polygonal
// fonts (engine/radiance/font.h), against layouts and insides worked out by hand from font.c's
// and text.c's rules, and a floor under a uniform sky against its closed form.
//
// The test font: 'A' the whole cell (0 0, 255 0, 255 255, 0 255), 'B' its lower-left half (0 0,
// 255 0, 0 255: inside where x + y < 255 on the glyph grid, y up), ' ' a glyph without outline.
// With a text's origin O, right vector R and down vector D, a point O + u R + v D is in character
// floor(u) of line floor(v) (uniform spacing), at glyph coordinates x = 255 frac(u),
// y = 255 (1 − frac(v)).
#include "engine/irradiance_estimator.h"
#include "engine/daylight.h"
#include "engine/materials/pattern_hook.h"
#include "engine/radiance/font.h"
#include "engine/radiance/reader.h"
#include "engine/radiance/text_pattern.h"
#include "engine/tracer.h"
#include "photometry/sky_type.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFont =
    "# a test font: glyph, vertex count, x y pairs\n"
    "32 0\n"
    "65 4 0 0 255 0 255 255 0 255\n"
    "66 3\n"
    "  0 0   255 0\n"
    "  0 255\n";

Scene readIn(const fs::path& dir, const std::string& text, PatternPolicy patterns = PatternPolicy::kRefuse) {
  std::ofstream(dir / "font.fnt") << kFont;
  std::ofstream(dir / "scene.rad") << text;
  Scene sc;
  SceneReadOptions opt;
  opt.patterns = patterns;
  SceneReader(sc, opt).readFile(dir / "scene.rad");
  return sc;
}

std::string errorOf(const fs::path& dir, const std::string& text) {
  try {
    readIn(dir, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const Material& materialNamed(const Scene& sc, const std::string& name) {
  for (const Material& m : sc.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

// The pattern colour of material `name` at x (the hook's product along its patterns).
Rgb colourAt(const Scene& sc, const std::string& name, const Vec3& x) {
  PatternEvaluator eval(sc);
  PatternPoint p;
  p.x = x;
  p.d = Vec3(0, 0, -1);
  p.ng = Vec3(0, 0, 1);
  return eval.colour(materialNamed(sc, name).pattern, p);
}

double brightnessAt(const Scene& sc, const std::string& name, const Vec3& x) { return colourAt(sc, name, x).x; }

TEST(TextPatterns, FontFilesAreReadAsFontCReadsThem) {
  const RadFont f = parseRadianceFont(std::string(kFont) + "67 3 10 10 50 10 10 60 # a small glyph\n", "t.fnt");
  ASSERT_NE(f.glyph('A'), nullptr);
  ASSERT_NE(f.glyph('C'), nullptr);
  EXPECT_EQ(f.glyph('D'), nullptr);
  EXPECT_EQ(f.glyph(' ')->vertices(), 0u);
  EXPECT_EQ(f.glyph('B')->vertices(), 3u);
  // The box starts at 128 on every side (font.c): C's vertices lie in 10..50 x 10..60, its box
  // reaches 128.
  EXPECT_EQ(f.glyph('C')->left, 10);
  EXPECT_EQ(f.glyph('C')->right, 128);
  EXPECT_EQ(f.glyph('C')->top, 128);
  // Mean width over the glyphs with a box of width and height: (255 + 255 + 118) / 3.
  EXPECT_EQ(f.meanWidth, (255 + 255 + 118) / 3);
}

TEST(TextPatterns, InsideAGlyphByEvenOddCrossings) {
  // A square ring: the outline 0..200 and the hole 50..150 joined by a seam (as helvet.fnt's O).
  const RadFont f = parseRadianceFont("79 10 0 0 200 0 200 200 0 200 0 0 50 50 50 150 150 150 150 50 50 50\n"
                                      "66 3 0 0 255 0 0 255\n",
                                      "t.fnt");
  const RadGlyph* o = f.glyph('O');
  EXPECT_TRUE(insideGlyph(o, 25.3, 100.5));
  EXPECT_TRUE(insideGlyph(o, 175.0, 20.0));
  EXPECT_FALSE(insideGlyph(o, 100.0, 100.0));  // in the hole
  EXPECT_FALSE(insideGlyph(o, 210.0, 100.0));  // beyond the box
  const RadGlyph* b = f.glyph('B');
  EXPECT_TRUE(insideGlyph(b, 10.0, 10.0));
  EXPECT_TRUE(insideGlyph(b, 120.0, 120.0));
  EXPECT_FALSE(insideGlyph(b, 140.0, 140.0));
  EXPECT_FALSE(insideGlyph(b, 250.0, 200.0));
  EXPECT_FALSE(insideGlyph(nullptr, 10.0, 10.0));
}

// Layouts worked out by hand from font.c's rules. Font: A's box 100..200 (x) × 0..200, B's
// vertices 140..160 × 0..100, so its box is 128..160 × 0..128 (the box starts at 128), a space
// without outline; mean width (100 + 32) / 2 = 66.
TEST(TextPatterns, LineLayoutsUniformSqueezedAndProportional) {
  const RadFont f = parseRadianceFont("32 0\n65 4 100 0 200 0 200 200 100 200\n66 3 140 0 160 0 150 100\n", "t.fnt");
  ASSERT_EQ(f.meanWidth, 66);
  const TextLine u = uniformLine("AxB", f);  // 'x' has no glyph: no room
  EXPECT_EQ(u.offsets, (std::vector<int64_t>{0, 255, 0, 255}));
  EXPECT_EQ(u.width, 510);
  // Squeezed, gap 20: A's box starts at 2·10 (origin 20 − 100 = −80), B's 20 after A's right
  // edge (120 + 20 = 140: origin 140 − 128 = 12), the line ends 20 after B's right edge (172 + 20).
  const TextLine s = squeezedLine("AB", f, 20);
  EXPECT_EQ(s.offsets, (std::vector<int64_t>{-80, 92, 180}));
  EXPECT_EQ(s.width, 192);
  // A space is as wide as the mean width: B's box starts 20 + 66 after A's right edge.
  const TextLine sp = squeezedLine("A B", f, 20);
  EXPECT_EQ(sp.offsets, (std::vector<int64_t>{-80, 210, -52, 180}));
  EXPECT_EQ(sp.width, 258);
  // Proportional, gap 20: squeezed, then the run "AB" made 2 × (66 + 20) = 172 long after the
  // first offset: its offsets 92 and 180 (272) lose 100, 50 each.
  const TextLine p = proportionalLine("AB", f, 20);
  EXPECT_EQ(p.offsets, (std::vector<int64_t>{-80, 42, 130}));
  EXPECT_EQ(p.width, 92);
  // A glyph followed by more than three spaces ends a run (an indent): "A    B" is two runs,
  // A with its four spaces (5 characters: 430 units) and B (86 units).
  const TextLine tab = proportionalLine("A    B", f, 20);
  ASSERT_EQ(tab.offsets.size(), 7u);
  EXPECT_EQ(tab.width, -80 + 5 * 86 + 86);
  int64_t sum = 0;
  for (int64_t o : tab.offsets) sum += o;
  EXPECT_EQ(sum, tab.width);
  // The run's adjustment is shared over its offsets, B's own among them: B's cell starts where
  // A's run ends.
  const int64_t bOrigin = tab.offsets[0] + tab.offsets[1] + tab.offsets[2] + tab.offsets[3] + tab.offsets[4] +
                          tab.offsets[5];
  EXPECT_EQ(bOrigin, -80 + 5 * 86);
}

TEST(TextPatterns, TextFileLinesAsGettextReadsThem) {
  EXPECT_EQ(textFileLines("AB\nBA\n"), (std::vector<std::string>{"AB", "BA"}));
  EXPECT_EQ(textFileLines("AB\n\nBA"), (std::vector<std::string>{"AB", "", "BA"}));
  // fgets into 512 bytes: 511 characters a line, the rest a line of its own.
  const std::string l(600, 'A');
  const std::vector<std::string> split = textFileLines(l + "\n");
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0].size(), 511u);
  EXPECT_EQ(split[1].size(), 89u);
  EXPECT_EQ(textFileLines(std::string("A\0B\n", 4)), (std::vector<std::string>{"A"}));
}

// A text file of two lines, "AB" and "BA", at O = 0, R = x, D = −y.
TEST(TextPatterns, BrighttextForegroundInGlyphsOfEachLine) {
  const fs::path dir = test_support::scratchDir("text_patterns", "lines");
  std::ofstream(dir / "two.txt") << "AB\nBA\n";
  const Scene sc = readIn(dir, "void brighttext t 2 font.fnt two.txt 0 11  0 0 0  1 0 0  0 -1 0  .9 .1\n"
                               "t plastic m 0 0 5 1 1 1 0 0\n");
  auto at = [&](double x, double y, double z = 0.0) { return brightnessAt(sc, "m", Vec3(x, y, z)); };
  EXPECT_DOUBLE_EQ(at(0.5, -0.5), 0.9);   // line 0, A
  EXPECT_DOUBLE_EQ(at(1.2, -0.9), 0.9);   // line 0, B: x 51, y 25.5
  EXPECT_DOUBLE_EQ(at(1.8, -0.1), 0.1);   // line 0, B: x 204, y 229.5, outside
  EXPECT_DOUBLE_EQ(at(0.8, -1.1), 0.1);   // line 1, B: x 204, y 229.5
  EXPECT_DOUBLE_EQ(at(0.2, -1.8), 0.9);   // line 1, B: x 51, y 51
  EXPECT_DOUBLE_EQ(at(1.5, -1.5), 0.9);   // line 1, A
  EXPECT_DOUBLE_EQ(at(2.5, -0.5), 0.1);   // past the line's end
  EXPECT_DOUBLE_EQ(at(0.5, -2.5), 0.1);   // below the last line
  EXPECT_DOUBLE_EQ(at(-0.1, -0.5), 0.1);  // before the text
  EXPECT_DOUBLE_EQ(at(0.5, 0.1), 0.1);    // above it
  EXPECT_DOUBLE_EQ(at(0.5, -0.5, 3.0), 0.9);  // off the plane: taken into it along its normal
  // The file is listed once however many patterns read it, with the font.
  ASSERT_EQ(sc.functionFiles.size(), 2u);
  EXPECT_NE(sc.functionFiles[0].find("font.fnt"), std::string::npos);
  EXPECT_NE(sc.functionFiles[1].find("two.txt"), std::string::npos);
}

TEST(TextPatterns, ObliqueAndScaledVectors) {
  const fs::path dir = test_support::scratchDir("text_patterns", "oblique");
  // R two metres a character, D leaning: a point O + u R + v D has coordinates (u, v).
  const Scene sc = readIn(dir, "void brighttext t 3 font.fnt . A 0 11  0 0 0  2 0 0  .5 -1 0  1 0\n"
                               "t plastic m 0 0 5 1 1 1 0 0\n");
  auto at = [&](double u, double v) { return brightnessAt(sc, "m", Vec3(2 * u + 0.5 * v, -v, 0.0)); };
  EXPECT_DOUBLE_EQ(at(0.5, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(at(0.95, 0.05), 1.0);
  EXPECT_DOUBLE_EQ(at(1.05, 0.5), 0.0);
  // (0.2, −0.9) is u = −0.125 on these vectors (before the text); a projection on x alone
  // would have put it inside A.
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(0.2, -0.9, 0.0)), 0.0);
}

TEST(TextPatterns, InlineTextJoinsItsWordsWithSpaces) {
  const fs::path dir = test_support::scratchDir("text_patterns", "inline");
  // "A B": the space has a glyph (no outline), so B is the third character.
  const Scene sc = readIn(dir, "void brighttext t 4 font.fnt . A B 0 11  0 0 0  1 0 0  0 -1 0  1 0\n"
                               "t plastic m 0 0 5 1 1 1 0 0\n");
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(0.5, -0.5, 0)), 1.0);
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(1.2, -0.9, 0)), 0.0);  // the space
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(2.2, -0.9, 0)), 1.0);  // B
  EXPECT_EQ(sc.functionFiles.size(), 1u);  // the font only
  // Reals after the spacing are ignored, as by Radiance.
  const Scene more = readIn(dir, "void brighttext t 4 font.fnt . A B 0 14  0 0 0  1 0 0  0 -1 0  1 0  0 7 8\n"
                                 "t plastic m 0 0 5 1 1 1 0 0\n");
  EXPECT_DOUBLE_EQ(brightnessAt(more, "m", Vec3(0.1, -0.5, 0)), 1.0);
}

// With a spacing s the layout is proportional and R is (mwidth + 255 s) units. Here mwidth is
// 255 (A and B fill their boxes) and s = 0.2 (gap 51, 25 a side): "A B" squeezed has offsets 50,
// 280, 280, 305 (A's box 25 + 25 in, the space 255 wide); its one run of three characters is
// stretched to 3 × 306 = 918, its offsets (865) gaining 53 in parts 17, 18, 18: 50, 297, 298, 323.
// A starts at 50/306 = 0.163 R, the space at 1.134 R, B at 645/306 = 2.108 R.
TEST(TextPatterns, ProportionalSpacingMovesTheGlyphs) {
  const fs::path dir = test_support::scratchDir("text_patterns", "spacing");
  const Scene sc = readIn(dir, "void brighttext u 4 font.fnt . A B 0 11  0 0 0  1 0 0  0 -1 0  1 0\n"
                               "void brighttext p 4 font.fnt . A B 0 12  0 0 0  1 0 0  0 -1 0  1 0  .2\n"
                               "u plastic mu 0 0 5 1 1 1 0 0\np plastic mp 0 0 5 1 1 1 0 0\n");
  const ScenePattern& pp = sc.patterns[static_cast<size_t>(materialNamed(sc, "mp").pattern)];
  ASSERT_TRUE(pp.text);
  EXPECT_EQ(pp.text->lines()[0].offsets, (std::vector<int64_t>{50, 297, 298, 323}));
  EXPECT_NEAR(pp.text->unitsPerCharacter(), 306.0, 1e-9);
  EXPECT_EQ(sc.functionFiles.size(), 1u);  // one font for both patterns, read and listed once
  auto at = [&](const char* m, double u) { return brightnessAt(sc, m, Vec3(u, -0.5, 0)); };
  EXPECT_DOUBLE_EQ(at("mp", 0.1), 0.0);  // before A's box
  EXPECT_DOUBLE_EQ(at("mp", 0.2), 1.0);  // in A
  EXPECT_DOUBLE_EQ(at("mu", 1.1), 0.0);  // uniform: the space's cell
  EXPECT_DOUBLE_EQ(at("mp", 1.1), 0.0);  // proportional: still the space
  EXPECT_DOUBLE_EQ(at("mp", 2.2), 1.0);  // B from 2.108 R
  EXPECT_DOUBLE_EQ(at("mu", 2.1), 1.0);  // uniform: B from 2 R
  EXPECT_DOUBLE_EQ(at("mp", 2.1), 0.0);  // proportional: B not yet
}

TEST(TextPatterns, ColortextMultipliesByItsColours) {
  const fs::path dir = test_support::scratchDir("text_patterns", "colour");
  const Scene sc = readIn(dir, "void colortext c 3 font.fnt . A 0 15  0 0 0  1 0 0  0 -1 0  1 .5 .25  .1 .2 .3\n"
                               "void brightfunc half 2 .5 . 0 0\n"
                               "half colortext c2 3 font.fnt . A 0 15  0 0 0  1 0 0  0 -1 0  1 .5 .25  .1 .2 .3\n"
                               "c plastic m 0 0 5 1 1 1 0 0\nc2 plastic m2 0 0 5 1 1 1 0 0\n");
  const Rgb in = colourAt(sc, "m", Vec3(0.5, -0.5, 0)), out = colourAt(sc, "m", Vec3(1.5, -0.5, 0));
  EXPECT_EQ(in, Rgb(1, .5, .25));
  EXPECT_EQ(out, Rgb(.1, .2, .3));
  // Patterns modifying it multiply in turn.
  EXPECT_EQ(colourAt(sc, "m2", Vec3(0.5, -0.5, 0)), Rgb(.5, .25, .125));
}

TEST(TextPatterns, MixtextChoosesTheForegroundInAGlyph) {
  const fs::path dir = test_support::scratchDir("text_patterns", "mix");
  const Scene sc = readIn(dir, "void plastic ink 0 0 5 .1 .1 .1 0 0\nvoid plastic paper 0 0 5 .9 .9 .9 0 0\n"
                               "void mixtext label 5 ink paper font.fnt . B 0 9  0 0 0  1 0 0  0 -1 0\n"
                               "void mixtext stencil 5 ink void font.fnt . B 0 9  0 0 0  1 0 0  0 -1 0\n");
  PatternEvaluator eval(sc);
  Rng rng(1, 0);
  auto chosen = [&](const std::string& mixture, double x, double y) -> std::string {
    PatternPoint p;
    p.x = Vec3(x, y, 0);
    p.d = Vec3(0, 0, -1);
    p.ng = Vec3(0, 0, 1);
    const Material* m = resolved(sc, materialNamed(sc, mixture), p, eval, rng);
    return m ? m->name : "void";
  };
  EXPECT_EQ(chosen("label", 0.1, -0.9), "ink");
  EXPECT_EQ(chosen("label", 0.9, -0.1), "paper");
  EXPECT_EQ(chosen("label", 1.5, -0.5), "paper");
  EXPECT_EQ(chosen("stencil", 0.1, -0.9), "ink");
  EXPECT_EQ(chosen("stencil", 0.9, -0.1), "void");
}

TEST(TextPatterns, XformMovesTheTextAnchorAndVectors) {
  const fs::path dir = test_support::scratchDir("text_patterns", "xform");
  std::ofstream(dir / "label.rad") << "void brighttext t 3 font.fnt . A 0 11  0 0 0  1 0 0  0 -1 0  1 0\n"
                                      "t plastic m 0 0 5 1 1 1 0 0\n";
  // Turned 90° about z, then 5 m along x: R is +y, D is +x, O is (5, 0, 0).
  const Scene sc = readIn(dir, "!xform -rz 90 -t 5 0 0 label.rad\n");
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(5.5, 0.5, 0)), 1.0);
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(0.5, -0.5, 0)), 0.0);
  EXPECT_DOUBLE_EQ(brightnessAt(sc, "m", Vec3(5.5, 1.5, 0)), 0.0);
}

// Under a uniform sky of E = 10 000 lux an infinite floor of reflectance ρ has luminance ρ E/π; a
// sensor 2 m above it, facing down, sees ρ E. One character A, 10 km a side, covers the floor at
// x > x0 (from 5 km north to 5 km south): a part of the sensor's view whose weight is the view
// factor of a half-plane a = x0 − x beside the point below the sensor, F = (1 − a/√(a² + h²))/2
// (∫ h² dA / (π r⁴) over the half-plane). brighttext 1 in the glyph and 0.2 outside gives
// ρ E (F + 0.2 (1 − F)); mixtext of plastics 0.5 and 0.1 gives E (0.5 F + 0.1 (1 − F)).
TEST(TextPatterns, FloorUnderAUniformSkyAgainstTheHalfPlaneViewFactor) {
  const double e = 10000.0, h = 2.0, a = 1.0, x = 0.3;
  const double f = 0.5 * (1.0 - a / std::sqrt(a * a + h * h));
  const std::string anchor = std::to_string(x + a) + " 5000 0  1e4 0 0  0 -1e4 0";
  const std::string floor = " polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";
  auto measure = [&](const std::string& name, const std::string& text, double want) {
    const fs::path dir = test_support::scratchDir("text_patterns", name);
    Scene sc = readIn(dir, text);
    DaylightSpec d;
    d.skyType = parseSkyType("uniform").value();
    d.diffuseHorizontalLux = e;
    d.groundReflectance = 0.0;
    addDaylight(sc, d);
    TraceSettings s;
    s.seed = 1;
    s.hemisphereSamples = 16384;
    s.maxBounces = 1;
    const IrradianceEstimate est =
        estimateIrradiance(Tracer(sc), Vec3(x, 0.2, h), Response::planar(Vec3(0, 0, -1)), 0, s);
    std::cout << name << ": " << est.illuminanceLux() << " ± " << est.standardErrorLux() << " lx, closed form "
              << want << "\n";
    EXPECT_NEAR(est.illuminanceLux(), want, 4.0 * est.standardErrorLux()) << name;
    EXPECT_LT(est.standardErrorLux(), 0.01 * want) << name;  // fine enough to tell F from 1 − F
  };
  measure("bright", "void brighttext t 3 font.fnt . A 0 11 " + anchor + " 1 .2\nt plastic m 0 0 5 .5 .5 .5 0 0\nm" + floor,
          0.5 * e * (f + 0.2 * (1.0 - f)));
  measure("mix", "void plastic hi 0 0 5 .5 .5 .5 0 0\nvoid plastic lo 0 0 5 .1 .1 .1 0 0\n"
                 "void mixtext m 5 hi lo font.fnt . A 0 9 " + anchor + "\nm" + floor,
          e * (0.5 * f + 0.1 * (1.0 - f)));
}

TEST(TextPatterns, RefusalsNameTheirLine) {
  const fs::path dir = test_support::scratchDir("text_patterns", "refusals");
  const std::string uses = "t plastic m 0 0 5 1 1 1 0 0\nm polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n";
  const std::string missing = errorOf(dir, "void brighttext t 2 nofont.fnt x.txt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses);
  EXPECT_NE(missing.find("scene.rad:1: brighttext 't': font file 'nofont.fnt' is not in the working directory"),
            std::string::npos)
      << missing;
  EXPECT_NE(missing.find("(used by plastic 'm' at line 2)"), std::string::npos) << missing;
  EXPECT_NE(errorOf(dir, "void brighttext t 2 font.fnt none.txt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("scene.rad:1: brighttext 't': text file 'none.txt' is not in"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "\nvoid brighttext t 3 font.fnt . A 0 10 0 0 0 1 0 0 0 -1 0 1\n" + uses)
                .find("scene.rad:2: brighttext 't' needs 11 or more real arguments"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void colortext t 3 font.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("colortext 't' needs 15 or more real arguments"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void mixtext t 3 a b font.fnt 0 9 0 0 0 1 0 0 0 -1 0\nt polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n")
                .find("mixtext 't' needs 4 or more string arguments"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 1 font.fnt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("needs 2 or more string arguments"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 3 font.fnt . A 0 11 0 0 0 1 0 0 2 0 0 1 0\n" + uses)
                .find("must be neither zero nor parallel"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 3 font.fnt . A 0 12 0 0 0 1 0 0 0 -1 0 1 0 1e5\n" + uses)
                .find("its spacing 100000 is beyond"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 3 /etc/font.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("no absolute path, no '..'"),
            std::string::npos);
  // Bad font content: at the font file's line.
  std::ofstream(dir / "bad.fnt") << "65 4 0 0 255 0\n  255 255\n  0 300\n";
  const std::string bad = errorOf(dir, "void brighttext t 3 bad.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses);
  EXPECT_NE(bad.find("bad.fnt:3: a vertex of character 65 is 300, outside 0-255"), std::string::npos) << bad;
  // Unused, nothing is refused; under --patterns base, the material unmodified with a warning.
  EXPECT_EQ(errorOf(dir, "void brighttext t 3 bad.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n"), "no error");
  const Scene base = readIn(dir, "void brighttext t 3 bad.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses,
                            PatternPolicy::kBase);
  ASSERT_EQ(base.inputWarnings.size(), 1u);
  EXPECT_NE(base.inputWarnings[0].message.find("cannot be read"), std::string::npos);
  // A font file beyond 4 MiB is refused at the pattern's line, before it is read.
  {
    std::ofstream big(dir / "big.fnt");
    const std::string line(1023, ' ');
    for (int k = 0; k < 4 * 1024 + 1; ++k) big << line << "\n";
  }
  EXPECT_NE(errorOf(dir, "void brighttext t 3 big.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("scene.rad:1: brighttext 't': font file '"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 3 big.fnt . A 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("more than the 4194304 candela reads"),
            std::string::npos);
  // A text file beyond 1 MiB likewise.
  std::ofstream(dir / "long.txt") << std::string((1 << 20) + 1, 'A');
  EXPECT_NE(errorOf(dir, "void brighttext t 2 font.fnt long.txt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("scene.rad:1: brighttext 't': text file '"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brighttext t 2 font.fnt long.txt 0 11 0 0 0 1 0 0 0 -1 0 1 0\n" + uses)
                .find("more than the 1048576 candela reads"),
            std::string::npos);
}

TEST(TextPatterns, BadFontContentAtItsLine) {
  auto error = [](const std::string& text) {
    try {
      parseRadianceFont(text, "f.fnt");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("65 1 0 0\n"), "no error");
  EXPECT_NE(error("\n65 x\n").find("f.fnt:2: 'x' is not an integer (the number of vertices of character 65)"),
            std::string::npos);
  EXPECT_NE(error("0 0\n").find("f.fnt:1: character code 0 is outside 1-255"), std::string::npos);
  EXPECT_NE(error("256 0\n").find("character code 256 is outside 1-255"), std::string::npos);
  EXPECT_NE(error("65 0\n\n65 0\n").find("f.fnt:3: character 65 is given twice"), std::string::npos);
  EXPECT_NE(error("65 32001\n").find("is 32001, outside 0-32000"), std::string::npos);
  EXPECT_NE(error("65 -1\n").find("is -1, outside 0-32000"), std::string::npos);
  EXPECT_NE(error("65 2 0 0\n1").find("f.fnt:2: unexpected end of the font file: expected a y coordinate of character 65"),
            std::string::npos);
  EXPECT_NE(error("65 99999999999999999999\n").find("out of range"), std::string::npos);
}

// Hostile counts: the counts a font states allocate nothing until words back them. 255 glyphs
// each claiming the most vertices, with none given, are refused at the first; a file of
// 32000-vertex glyphs costs the words it holds, never 255 × 32000 vertices in advance.
TEST(TextPatterns, HostileCountsAllocateOnlyWhatTheFileHolds) {
  std::string hostile;
  for (int c = 1; c < 256; ++c) hostile += std::to_string(c) + " 32000\n";
  EXPECT_THROW(parseRadianceFont(hostile, "h.fnt"), InputError);
  // The most a font can hold: 255 glyphs of 32000 vertices (16 million coordinates, 32 MB as
  // int16), read only when the file spells them out (at least 2 bytes a coordinate: 32 MB of
  // text, refused by the 4 MiB limit before parsing). A glyph at the limit is accepted.
  std::string full = "65 32000";
  for (int k = 0; k < 32000; ++k) full += " 1 2";
  const RadFont f = parseRadianceFont(full, "full.fnt");
  EXPECT_EQ(f.glyph('A')->vertices(), 32000u);
}

}  // namespace
}  // namespace candela
