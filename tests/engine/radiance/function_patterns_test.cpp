// brightfunc and colorfunc through the function language: the reader (files found as Radiance
// finds them, refusals at their line) and the hook (engine/materials/pattern_hook.h) against
// closed forms. Under a uniform sky of E = 10 000 lux an infinite diffuse floor of reflectance ρ
// has luminance ρ E/π, so a sensor facing it sees ρ E; a pattern multiplying the floor's colour
// by k makes that k ρ E, and stripes that reflect on half the floor ρ E/2.
#include "engine/daylight.h"
#include "engine/fresnel.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "photometry/sky_type.h"
#include "tests/support/temp_files.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFloor = "f polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";

Scene readIn(const fs::path& dir, const std::string& text, PatternPolicy patterns = PatternPolicy::kRefuse) {
  std::ofstream(dir / "scene.rad") << text;
  Scene sc;
  SceneReadOptions opt;
  opt.patterns = patterns;
  SceneReader(sc, opt).readFile(dir / "scene.rad");
  return sc;
}

void addSky(Scene& sc) {
  DaylightSpec d;
  d.skyType = parseSkyType("uniform").value();
  d.diffuseHorizontalLux = 10000.0;
  d.groundReflectance = 0.0;
  addDaylight(sc, d);
}

// The floor's light on a sensor 2 m above it, facing down, within 4 standard errors of `want`.
void expectDownward(const Scene& sc, double want, const char* what, int samples = 1024) {
  const Tracer tracer(sc);
  TraceSettings s;
  s.seed = 1;
  s.hemisphereSamples = samples;
  s.maxBounces = 1;
  const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux()) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * want) << what;  // the test can tell a wrong factor apart
}

TEST(FunctionPatterns, ConstantBrightnessScalesTheFloor) {
  const fs::path dir = test_support::scratchDir("function_patterns", "constant");
  std::ofstream(dir / "k.cal") << "{ a constant factor from the primitive's argument } k = A1;\n";
  Scene sc = readIn(dir, std::string("void brightfunc dim 2 k k.cal 0 1 0.4\n"
                                     "dim plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 0.4 * 0.5 * 10000.0, "brightfunc 0.4 on a 0.5 floor");
}

TEST(FunctionPatterns, StripesThroughATransformReflectOnHalfTheFloor) {
  // Stripes 1 unit wide in the function's coordinates, scaled to 5 cm: far finer than the 2 m
  // height, so the floor reads as half as bright.
  const fs::path dir = test_support::scratchDir("function_patterns", "stripes");
  std::ofstream(dir / "stripes.cal") << "on = if(sin(PI * Px), 1, 0);\n";
  Scene sc = readIn(dir, std::string("void brightfunc stripes 4 on stripes.cal -s .05 0 0\n"
                                     "stripes plastic f 0 0 5 .6 .6 .6 0 0\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 0.5 * 0.6 * 10000.0, "stripes", 16384);  // a two-valued floor: more samples
}

TEST(FunctionPatterns, ColourFunctionsByChannelWithInlineExpressions) {
  const fs::path dir = test_support::scratchDir("function_patterns", "colour");
  Scene sc = readIn(dir, std::string("void colorfunc tint 4 1 A1 0*Px . 0 1 .5\n"
                                     "tint plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(sc);
  // Red 1, green 0.5, blue 0: the photopic factor 0.265 + 0.670 · 0.5.
  expectDownward(sc, (kWeightR * 1.0 + kWeightG * 0.5) * 0.5 * 10000.0, "colorfunc");
}

TEST(FunctionPatterns, ChainedPatternsMultiply) {
  const fs::path dir = test_support::scratchDir("function_patterns", "chain");
  Scene sc = readIn(dir, std::string("void brightfunc a 2 .5 . 0 0\n"
                                     "a brightfunc b 2 .8 . 0 0\n"
                                     "b plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 0.4 * 0.5 * 10000.0, "two patterns");
}

TEST(FunctionPatterns, PatternedGlassTransmitsShadowRaysByItsPattern) {
  const fs::path dir = test_support::scratchDir("function_patterns", "glass");
  const Scene plain = readIn(dir, "void glass g 0 0 3 .9 .9 .9\ng polygon pane 0 0 12 -1 -1 1 1 -1 1 1 1 1 -1 1 1\n");
  const Scene half = readIn(dir, "void brightfunc half 2 .5 . 0 0\nhalf glass g 0 0 3 .9 .9 .9\n"
                                 "g polygon pane 0 0 12 -1 -1 1 1 -1 1 1 1 1 -1 1 1\n");
  const Tracer a(plain), b(half);
  const Rgb ta = a.transmittance(Vec3(0.1, 0.2, 0.0), Vec3(0, 0, 1), 10.0, kNoShape, kNoShape);
  const Rgb tb = b.transmittance(Vec3(0.1, 0.2, 0.0), Vec3(0, 0, 1), 10.0, kNoShape, kNoShape);
  ASSERT_GT(photopic(ta), 0.5);
  Rgb tr, rf;
  thinGlass(Rgb(0.45), 1.52, -1.0, tr, rf);  // the glass's transmissivity halved
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(tb[c], tr[c], 1e-12);
}

// mixfunc: the foreground where the coefficient is 1, the background where 0. A floor that is a
// quarter white plastic, three quarters void (holes onto the black ground) reflects a quarter.
TEST(FunctionPatterns, MixtureOfAMaterialAndVoid) {
  const fs::path dir = test_support::scratchDir("function_patterns", "mixture");
  Scene sc = readIn(dir, std::string("void plastic white 0 0 5 .8 .8 .8 0 0\n"
                                     "void mixfunc f 4 white void .25 . 0 0\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 0.25 * 0.8 * 10000.0, "mixfunc 0.25 of white and void", 16384);
}

TEST(FunctionPatterns, MixtureByPositionOfTwoMaterials) {
  // Stripes (coefficient 1 on half the floor, 0 on the other) of plastics 0.8 and 0.2: 0.5 on average.
  const fs::path dir = test_support::scratchDir("function_patterns", "mixture_stripes");
  std::ofstream(dir / "mix.cal") << "side = if(sin(PI * Px / A1), 1, 0);\n";
  Scene sc = readIn(dir, std::string("void plastic light 0 0 5 .8 .8 .8 0 0\n"
                                     "void plastic dark 0 0 5 .2 .2 .2 0 0\n"
                                     "void mixfunc f 4 light dark side mix.cal 0 1 .05\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 0.5 * 10000.0, "striped mixture", 16384);
}

// Data patterns (Radiance's p_data.c, mx_data.c): the data at the point the coordinates give,
// passed to the named functions. A 1-D array rising linearly from 0.2 to 0.6 over frac(Px), a
// stripe width of 5 cm, averages 0.4 on the floor; colordata gives each channel its own file; a
// mixdata coefficient of 0.25 mixes a quarter of white plastic with void.
TEST(FunctionPatterns, DataPatternsLookUpTheirFilesAtTheCoordinates) {
  const fs::path dir = test_support::scratchDir("function_patterns", "data");
  std::ofstream(dir / "ramp.dat") << "1\n0 1 2\n0.2 0.6\n";
  std::ofstream(dir / "one.dat") << "1\n0 1 2\n1 1\n";
  std::ofstream(dir / "half.dat") << "1\n0 1 2\n.5 .5\n";
  std::ofstream(dir / "quarter.dat") << "1\n0 1 2\n.25 .25\n";
  Scene ramp = readIn(dir, std::string("void brightdata p 4 noop ramp.dat . frac(Px/.05) 0 0\n"
                                       "p plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(ramp);
  expectDownward(ramp, 0.4 * 0.5 * 10000.0, "brightdata ramp", 16384);
  Scene colour = readIn(dir, std::string("void colordata p 8 red green blue one.dat half.dat ramp.dat . frac(Px)\n0 0\n"
                                         "p plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(colour);
  // Red 1, green 0.5, blue 0.4 on average (red(r, g, b) = r, ...).
  expectDownward(colour, (kWeightR + 0.5 * kWeightG + 0.4 * kWeightB) * 0.5 * 10000.0, "colordata", 16384);
  Scene mix = readIn(dir, std::string("void plastic white 0 0 5 .8 .8 .8 0 0\n"
                                      "void mixdata f 6 white void noop quarter.dat . frac(Py)\n0 0\n") + kFloor);
  addSky(mix);
  expectDownward(mix, 0.25 * 0.8 * 10000.0, "mixdata 0.25", 16384);
}

// colorpict of a uniform picture (every pixel m = 128, e = 128: (128.5)·2^-8) on the floor,
// looked up at (frac(Px), frac(Py)) inside the picture.
TEST(FunctionPatterns, PicturePatternLooksUpTheImage) {
  const fs::path dir = test_support::scratchDir("function_patterns", "picture");
  {
    std::ofstream out(dir / "grey.hdr", std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n";
    for (int k = 0; k < 16; ++k) out << char(128) << char(128) << char(128) << char(128);
  }
  Scene sc = readIn(dir, std::string("void colorpict p 7 red green blue grey.hdr . frac(Px) frac(Py)\n0 0\n"
                                     "p plastic f 0 0 5 .5 .5 .5 0 0\n") + kFloor);
  addSky(sc);
  expectDownward(sc, 128.5 / 256.0 * 0.5 * 10000.0, "colorpict", 4096);
  // The picture and data files are listed with the function files (summary.json).
  ASSERT_EQ(sc.functionFiles.size(), 1u);
  EXPECT_NE(sc.functionFiles[0].find("grey.hdr"), std::string::npos);
}

// texfunc and texdata turn the shading normal (Radiance's raynormal: the normal plus the
// perturbation, normalised). A floor of reflectance 0.5 under a sun 40° from the zenith (in the
// x–z plane) and nothing else, seen by a sensor facing down 2 m above it (first bounce only),
// reads 0.5 E_n cos γ, E_n = L π sin²α the sun's normal irradiance and γ the angle between the
// sun and the shading normal: cos 40° unperturbed; the perturbation (1, 0, 0) turns the normal
// 45° towards +x, cos 5°; turned by the texture's -rz 90 it is (0, 1, 0), cos 40°/√2.
TEST(FunctionPatterns, TexturesTurnTheShadingNormal) {
  const fs::path dir = test_support::scratchDir("function_patterns", "texture");
  std::ofstream(dir / "one.dat") << "1\n0 1 2\n1 1\n";
  std::ofstream(dir / "zero.dat") << "1\n0 1 2\n0 0\n";
  const double a = 40.0 * kPi / 180.0;
  const std::string sun = "void light s 0 0 3 1e4 1e4 1e4\ns source sun 0 0 4 " + std::to_string(std::sin(a)) +
                          " 0 " + std::to_string(std::cos(a)) + " 0.5\n";
  const double sinA = std::sin(0.25 * kPi / 180.0);
  const double en = 1e4 * kLumensPerWatt * kPi * sinA * sinA;
  auto reflected = [&](const std::string& modifier) {
    const Scene sc = readIn(dir, sun + modifier + "p plastic f 0 0 5 .5 .5 .5 0 0\n" + kFloor);
    TraceSettings s;
    s.seed = 4;
    s.hemisphereSamples = 1024;
    s.maxBounces = 1;
    return estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  };
  auto expectNear = [&](const IrradianceEstimate& e, double cosG, const char* what) {
    const double want = 0.5 * en * cosG;
    EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux()) << what;
    EXPECT_LT(e.standardErrorLux(), 0.01 * want) << what;
  };
  expectNear(reflected("void brightfunc p 2 1 . 0 0\n"), std::cos(a), "unperturbed");
  expectNear(reflected("void texfunc p 4 1 0 0 . 0 0\n"), std::cos(a - kPi / 4.0), "texfunc (1, 0, 0)");
  expectNear(reflected("void texfunc p 6 1 0 0 . -rz 90 0 0\n"), std::cos(a) / std::sqrt(2.0), "texfunc turned");
  expectNear(reflected("void texdata p 8 red green blue one.dat zero.dat zero.dat . frac(Px) 0 0\n"),
             std::cos(a - kPi / 4.0), "texdata (1, 0, 0)");
}

// Radiance's other order, a pattern modified by the material (`m texfunc t`, then surfaces of t:
// what gensurf -s and obj2rad write): the surface has the material with the pattern, as in the
// usual order. The floor of the test above, its normal turned by (1, 0, 0): cos 5°.
TEST(FunctionPatterns, APatternOfAMaterialStandsForThePatternedMaterial) {
  const fs::path dir = test_support::scratchDir("function_patterns", "pattern_of_material");
  const double a = 40.0 * kPi / 180.0;
  const std::string sun = "void light s 0 0 3 1e4 1e4 1e4\ns source sun 0 0 4 " + std::to_string(std::sin(a)) +
                          " 0 " + std::to_string(std::cos(a)) + " 0.5\n";
  const double sinA = std::sin(0.25 * kPi / 180.0);
  const double en = 1e4 * kLumensPerWatt * kPi * sinA * sinA;
  // The brightness 0.5 after the texture, both over the plastic: 0.5 · 0.5 E_n cos 5°.
  const Scene sc = readIn(dir, sun + "void plastic p 0 0 5 .5 .5 .5 0 0\np brightfunc half 2 .5 . 0 0\n"
                                     "half texfunc f 4 1 0 0 . 0 0\n" + kFloor);
  TraceSettings s;
  s.seed = 4;
  s.hemisphereSamples = 1024;
  s.maxBounces = 1;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  const double want = 0.25 * en * std::cos(a - kPi / 4.0);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
  EXPECT_LT(e.standardErrorLux(), 0.01 * want);
  // Over a mixture (Radiance's torus.rad: genrev -s over a mixfunc) the texture turns the normal
  // of both materials: 0.3 of reflectance 0.4 and 0.7 of 0.6, (0.12 + 0.42) E_n cos 5°.
  const Scene mixed = readIn(dir, sun + "void plastic a 0 0 5 .4 .4 .4 0 0\nvoid plastic b 0 0 5 .6 .6 .6 0 0\n"
                                        "void mixfunc mx 4 a b .3 . 0 0\nmx texfunc f 4 1 0 0 . 0 0\n" + kFloor);
  const IrradianceEstimate m = estimateIrradiance(Tracer(mixed), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, s);
  const double wantMixed = 0.54 * en * std::cos(a - kPi / 4.0);
  EXPECT_NEAR(m.illuminanceLux(), wantMixed, 4.0 * m.standardErrorLux());
  EXPECT_LT(m.standardErrorLux(), 0.01 * wantMixed);
}

// The function files Radiance's generators name (surf.cal, rev.cal, tmesh.cal) are built in,
// used where no copy is found where files are looked up; a copy found there is read instead.
TEST(FunctionPatterns, GeneratorsLibraryFilesAreBuiltInUnlessFound) {
  const fs::path dir = test_support::scratchDir("function_patterns", "library_files");
  const std::string text = "void plastic p 0 0 5 .5 .5 .5 0 0\np texfunc t 4 rev_dx rev_dy rev_dz rev.cal 0 4 0 0 0 1\n"
                           "t polygon x 0 0 9 0 0 0 1 0 0 0 1 0\n";
  EXPECT_EQ(readIn(dir, text).functionFiles, (std::vector<std::string>{"rev.cal (built in)"}));
  std::ofstream(dir / "rev.cal") << "rev_dx = 0; rev_dy = 0; rev_dz = 0;\n";
  const std::vector<std::string> files = readIn(dir, text).functionFiles;
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(fs::path(files[0]).filename(), "rev.cal");
  EXPECT_EQ(fs::path(files[0]).parent_path(), dir);
}

// Shadow rays through a mixture of glass and void blend what each lets through.
TEST(FunctionPatterns, ShadowRaysThroughAMixtureBlendItsMaterials) {
  const fs::path dir = test_support::scratchDir("function_patterns", "mixture_glass");
  const Scene sc = readIn(dir, "void glass g 0 0 3 .9 .9 .9\nvoid mixfunc m 4 g void .3 . 0 0\n"
                               "m polygon pane 0 0 12 -1 -1 1 1 -1 1 1 1 1 -1 1 1\n");
  const Tracer tracer(sc);
  const Rgb t = tracer.transmittance(Vec3(0.1, 0.2, 0.0), Vec3(0, 0, 1), 10.0, kNoShape, kNoShape);
  Rgb tr, rf;
  thinGlass(Rgb(0.9), 1.52, -1.0, tr, rf);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], 0.3 * tr[c] + 0.7, 1e-12);
}

// A pattern is refused only when a surface uses it: each text ends with a material the pattern
// `p` modifies and a surface of it (a mixture `m`: a surface of it).
std::string errorOf(const fs::path& dir, const std::string& text, PatternPolicy patterns = PatternPolicy::kRefuse,
                    const std::string& user = "p plastic used 0 0 5 .5 .5 .5 0 0\nused") {
  try {
    readIn(dir, text + user + " polygon x 0 0 9 0 0 0 1 0 0 0 1 0\n", patterns);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FunctionPatterns, FilesAreFoundAsRadianceFindsThemAndNowhereElse) {
  const fs::path dir = test_support::scratchDir("function_patterns", "files");
  const fs::path lib = test_support::scratchDir("function_patterns", "raypath");
  std::ofstream(lib / "libpat.cal") << "v = .5;\n";
  const std::string uses = "void brightfunc p 2 v libpat.cal 0 0\np plastic f 0 0 5 .5 .5 .5 0 0\n";
  EXPECT_NE(errorOf(dir, uses).find("scene.rad:1: brightfunc 'p': function file 'libpat.cal' is not in the working "
                                    "directory, in RAYPATH or in"),
            std::string::npos);
  ::setenv("RAYPATH", ("/nonexistent:" + lib.string()).c_str(), 1);
  EXPECT_EQ(errorOf(dir, uses), "no error");
  ::unsetenv("RAYPATH");
  EXPECT_NE(errorOf(dir, "void brightfunc p 2 v /etc/passwd 0 0\n").find("must be a name relative to"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightfunc p 2 v ../x.cal 0 0\n").find("no absolute path, no '..'"), std::string::npos);
}

// A pattern no surface uses is never refused: a library may define what a scene does not use.
TEST(FunctionPatterns, UnusedPatternsAreNotRefused) {
  const fs::path dir = test_support::scratchDir("function_patterns", "unused");
  const Scene sc = readIn(dir, "void brightfunc p 2 v nofile.cal 0 0\nvoid colorpict pic 7 r g b x.hdr p.cal u v 0 0\n"
                               "void BSDF am 1 void 0 0\n");
  EXPECT_TRUE(sc.inputWarnings.empty());
  // Used by a material a surface uses, it is refused at its own line, saying what used it.
  const std::string used = errorOf(dir, "void colorpict pic 7 r g b x.hdr p.cal u v 0 0\n", PatternPolicy::kRefuse,
                                   "pic plastic used 0 0 5 .5 .5 .5 0 0\nused");
  EXPECT_NE(used.find("scene.rad:1: colorpict 'pic': function file 'p.cal' is not in the working directory"),
            std::string::npos)
      << used;
  EXPECT_NE(used.find("(used by plastic 'used' at line 2)"), std::string::npos) << used;
  EXPECT_NE(errorOf(dir, "void BSDF am 1 void 0 0\nvoid alias p am\n")
                .find("(used by alias 'p' at line 2)"),
            std::string::npos);
}

TEST(FunctionPatterns, RefusalsNameTheirLine) {
  const fs::path dir = test_support::scratchDir("function_patterns", "refusals");
  std::ofstream(dir / "bad.cal") << "ok = 1;\n\nbroken = (2 + ;\n";
  EXPECT_NE(errorOf(dir, "void brightfunc p 2 ok bad.cal 0 0\n").find("bad.cal:3: unexpected ';'"), std::string::npos);
  std::ofstream(dir / "good.cal") << "uses = 1 + nowhere;\n";
  EXPECT_NE(errorOf(dir, "\nvoid brightfunc p 2 uses good.cal 0 0\n").find("good.cal:1: 'uses' uses 'nowhere', which is not defined"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightfunc p 2 missing good.cal 0 0\n").find("scene.rad:1: 'missing' is not defined"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightfunc p 2 (1+ . 0 0\n").find("its function '(1+' is not an expression"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightfunc p 3 1 . -q 0 0\n").find("'-q' is not a transform option"), std::string::npos);
  EXPECT_NE(errorOf(dir, "void mixfunc m 4 nothere void .5 . 0 0\n", PatternPolicy::kRefuse, "m")
                .find("its foreground 'nothere' is not a material"),
            std::string::npos);
  // A missing file under --patterns base: the material unmodified, with the reason.
  const Scene base = readIn(dir, "void brightfunc p 2 v nofile.cal 0 0\np plastic f 0 0 5 .5 .5 .5 0 0\n",
                            PatternPolicy::kBase);
  ASSERT_EQ(base.inputWarnings.size(), 1u);
  EXPECT_NE(base.inputWarnings[0].message.find("cannot be read (brightfunc 'p': function file 'nofile.cal'"),
            std::string::npos);
}

// Function patterns on light sources (Radiance's srcvalue: the pattern is evaluated where the
// shadow ray or the ray meets the source). A 4 m square light of radiance L 1 m above a sensor
// facing it, under a pattern P: E = L ∫ P cos θ cos θ' / d² dA = L ∫ P / d⁴ dA (the sensor
// below the plane's point (x, y)), computed here by the midpoint rule on 800 × 800 cells
// (relative error below 1e-5). A constant pattern k gives k times the unpatterned light; a
// pattern lighting the x > 0 half, half of it for a sensor at x = 0; the pattern Dz (the shadow
// ray's direction: P = 1/d) the integral of 1/d⁵.
constexpr const char* kCeiling = "lamp polygon ceiling 0 0 12 -2 -2 1  -2 2 1  2 2 1  2 -2 1\n";
constexpr const char* kBlackFloor =
    "void plastic black 0 0 5 0 0 0 0 0\nblack polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";

// ∫ over the ceiling of d^-power, d the distance from (0, y0, 0).
double ceilingIntegral(double y0, int power) {
  const int n = 800;
  const double h = 4.0 / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -2.0 + (i + 0.5) * h, y = -2.0 + (j + 0.5) * h - y0;
      sum += std::pow(x * x + y * y + 1.0, -0.5 * power);
    }
  return sum * h * h;
}

void expectLux(const Scene& sc, const Vec3& at, const Vec3& n, double want, const char* what, int maxBounces = 0) {
  const Tracer tracer(sc);
  TraceSettings s;
  s.seed = 3;
  s.hemisphereSamples = 1024;
  s.lightSamples = 1024;
  s.maxBounces = maxBounces;
  const IrradianceEstimate e = estimateIrradiance(tracer, at, Response::planar(n), 0, s);
  // A constant pattern is exact (the ratio estimator): then the quadrature's error, 1e-5.
  EXPECT_NEAR(e.illuminanceLux(), want, std::max(4.0 * e.standardErrorLux(), 1e-5 * want)) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * want) << what;  // the test tells a wrong factor apart
}

TEST(FunctionPatterns, PatternsOnAreaLightsWeighTheirSamples) {
  const fs::path dir = test_support::scratchDir("function_patterns", "lamp");
  const double l = 10.0 * kLumensPerWatt;  // the light's luminance (cd/m²)
  const Vec3 at(0.0, -0.2, 0.0), up(0, 0, 1);
  const double plain = l * ceilingIntegral(-0.2, 4);
  const std::string lamp = "p light lamp 0 0 3 10 10 10\n";
  expectLux(readIn(dir, "void brightfunc p 2 .4 . 0 0\n" + lamp + kCeiling), at, up, 0.4 * plain, "constant 0.4");
  expectLux(readIn(dir, "void brightfunc p 2 if(Px,1,0) . 0 0\n" + lamp + kCeiling), at, up, 0.5 * plain,
            "the x > 0 half");
  expectLux(readIn(dir, "void brightfunc p 2 Dz . 0 0\n" + lamp + kCeiling), at, up, l * ceilingIntegral(-0.2, 5),
            "L cos θ");
  // At a path vertex (one light chosen per sample): light reflected by a floor under the square
  // is 0.4 times the unpatterned light's, sample for sample (the same stream: the pattern
  // changes no choice).
  const std::string floor = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                            "grey polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";
  auto reflected = [&](const std::string& text) {
    const Scene sc = readIn(dir, text);
    TraceSettings s;
    s.seed = 5;
    s.hemisphereSamples = 256;
    s.maxBounces = 1;
    return estimateIrradiance(Tracer(sc), Vec3(0.3, -0.2, 0.5), Response::planar(-up), 0, s).illuminanceLux();
  };
  const double patterned = reflected("void brightfunc p 2 .4 . 0 0\n" + lamp + kCeiling + floor);
  const double unpatterned = reflected("void light lamp 0 0 3 10 10 10\n" + std::string(kCeiling) + floor);
  ASSERT_GT(unpatterned, 0.01 * plain);
  EXPECT_NEAR(patterned, 0.4 * unpatterned, 1e-9 * unpatterned);
}

TEST(FunctionPatterns, PatternsOnDistantSources) {
  const fs::path dir = test_support::scratchDir("function_patterns", "distant");
  const Vec3 at(0.0, 0.0, 1.0), up(0, 0, 1);
  // A glow dome of luminance L Dz (found by hemisphere rays): 2π L / 3 on a horizontal sensor
  // above a black floor.
  const Scene dome =
      readIn(dir, std::string("void brightfunc p 2 Dz . 0 0\np glow g 0 0 4 10 10 10 0\ng source dome 0 0 4 0 0 1 180\n") +
                      kBlackFloor);
  expectLux(dome, at, up, 2.0 * kPi / 3.0 * 10.0 * kLumensPerWatt, "glow dome L Dz");
  // A sun (a light source, sampled) under a pattern 0.25: a quarter of L π sin²α.
  const Scene sun =
      readIn(dir, std::string("void brightfunc p 2 .25 . 0 0\np light s 0 0 3 1e4 1e4 1e4\ns source sun 0 0 4 0 0 1 0.5\n") +
                      kBlackFloor);
  const double sinA = std::sin(0.25 * kPi / 180.0);  // exact (the cap formula)
  expectLux(sun, at, up, 0.25 * 1e4 * kLumensPerWatt * kPi * sinA * sinA, "sun 0.25");
}

TEST(FunctionPatterns, DataPatternRefusals) {
  const fs::path dir = test_support::scratchDir("function_patterns", "data_refusals");
  std::ofstream(dir / "two.dat") << "2\n0 1 2\n0 1 2\n1 1 1 1\n";
  EXPECT_NE(errorOf(dir, "void brightdata p 4 noop two.dat . Px 0 0\n").find("needs 5 or more string arguments"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightdata p 5 Px+1 two.dat . Px Py 0 0\n").find("'Px+1' must name a function of 1 argument"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void colorpict p 7 red green blue none.hdr . Px Py 0 0\n")
                .find("picture 'none.hdr' is not in the working directory"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, "void brightdata p 5 noop /etc/passwd . Px Py 0 0\n").find("must be a name relative"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
