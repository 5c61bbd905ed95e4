// plasfunc, metfunc, transfunc, plasdata and BRTDfunc's directional functions against closed
// forms. A distant source of radiance L and solid angle Ω at zenith angle θ gives E = L Ω cos θ
// on an infinite plane; a function BRDF f of the source's direction makes the plane's radiance
// (rdiff/π + rspec f) E everywhere (Radiance's dirbrdf, src/rt/m_brdf.c), so a sensor facing
// the plane reads π times it (the plane fills its hemisphere). Nothing else lights the plane, and
// the sun's cone (0.5°) varies cos θ by less than 1e-5 over its samples: the tolerance is 1e-4.
// Under a uniform sky (no sampled source) the same surfaces reflect diffusely with
// colour·(1 − trans') (Radiance's ambient for these types), within 4 standard errors.
#include "engine/render.h"
#include "engine/tracer.h"
#include "tests/support/material_harness.h"
#include "tests/support/temp_files.h"
#include "tests/support/test_views.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace candela {
namespace {

using test_support::distantSun;
using test_support::infinitePlane;
using test_support::sunSolidAngle;
constexpr double kSunL = test_support::kSunRadiance;  // W/sr/m²
constexpr double kSkyLux = test_support::kUniformSkyLux;

const char* kCal =
    "half(lx,ly,lz,om) = .5;\n"
    "steep(lx,ly,lz,om) = if(lz-.8, 1, 0);\n"
    "solid(lx,ly,lz,om) = om*1000;\n"
    "up(lx,ly,lz,om) = lz;\n"
    "same(v,lx,ly,lz,om) = v;\n"
    "blue(lx,ly,lz,om) = .4;\n";

Scene readIn(const std::string& name, const std::string& text, bool sky = false) {
  const std::filesystem::path dir = test_support::scratchDir("brdf_function", name);
  std::ofstream(dir / "f.cal") << kCal;
  // 1-D data over lz from 0 to 1 in 3 points: the value lz itself, by linear interpolation.
  std::ofstream(dir / "lz.dat") << "1\n0 1 3\n0 .5 1\n";
  return test_support::readSceneText(dir, text, sky);
}

IrradianceEstimate measure(const Scene& sc, double z, const Vec3& n) {
  TraceSettings s;
  s.seed = 3;
  s.hemisphereSamples = 4096;
  s.maxBounces = 2;
  return estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, z), Response::planar(n), 0, s);
}

// The illuminance a sensor facing a plane of radiance `radiance` (W/sr/m², RGB) reads: π L, lux.
double luxOf(const Rgb& radiance) { return kLumensPerWatt * kPi * photopic(radiance); }

void expectExact(const Scene& sc, double z, const Vec3& n, const Rgb& radiance, const std::string& what) {
  const double want = luxOf(radiance);
  EXPECT_NEAR(measure(sc, z, n).illuminanceLux(), want, 1e-4 * want + 1e-9) << what;
}

void expectWithin4Se(const Scene& sc, double z, const Vec3& n, double want, const std::string& what) {
  const IrradianceEstimate e = measure(sc, z, n);
  EXPECT_NEAR(e.illuminanceLux(), want, std::max(4.0 * e.standardErrorLux(), 1e-9 * kSkyLux)) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * kSkyLux) << what;
}

const Vec3 kDown(0, 0, -1), kUp(0, 0, 1);

double sunE(double zenithDeg) { return kSunL * sunSolidAngle() * std::cos(degToRad(zenithDeg)); }

TEST(BrdfFunction, PlasfuncReflectsASourceByItsFunctionOfTheSourcesDirection) {
  // rdiff = colour (1 − spec), the function uncoloured, times spec.
  const std::string mat = "void plasfunc pf 2 half f.cal 0 4 .5 .4 .3 .2\n";
  for (double zen : {0.0, 40.0}) {
    const Rgb c(.5, .4, .3);
    expectExact(readIn("plasfunc", distantSun(zen) + mat + infinitePlane("pf", 0.0, true)), 2.0, kDown,
                (c * (0.8 * kInvPi) + Rgb(0.2 * 0.5)) * sunE(zen), "zenith " + std::to_string(zen));
  }
  // A function of the direction: 1 within 36.9° of the zenith (lz > .8), else 0.
  const std::string steep = "void plasfunc pf 2 steep f.cal 0 4 .5 .5 .5 .2\n";
  expectExact(readIn("steep30", distantSun(30.0) + steep + infinitePlane("pf", 0.0, true)), 2.0, kDown,
              Rgb(0.5 * 0.8 * kInvPi + 0.2) * sunE(30.0), "lz .87");
  expectExact(readIn("steep45", distantSun(45.0) + steep + infinitePlane("pf", 0.0, true)), 2.0, kDown,
              Rgb(0.5 * 0.8 * kInvPi) * sunE(45.0), "lz .71");
  // omega is the source's solid angle.
  expectExact(readIn("omega", distantSun(0.0) + "void plasfunc pf 2 solid f.cal 0 4 .5 .5 .5 .2\n" + infinitePlane("pf", 0.0, true)),
              2.0, kDown, Rgb(0.4 * kInvPi + 0.2 * sunSolidAngle() * 1000.0) * sunE(0.0), "omega");
  // The function's transform turns the light's direction: rotated 90° about x, the zenith sun's
  // direction (0 0 1) reads as (0 ±1 0) in the function's coordinates (lz 0: steep is 0).
  expectExact(readIn("rotated", distantSun(0.0) + "void plasfunc pf 4 steep f.cal -rx 90 0 4 .5 .5 .5 .2\n" +
                                    infinitePlane("pf", 0.0, true)),
              2.0, kDown, Rgb(0.4 * kInvPi) * sunE(0.0), "rotated");
}

TEST(BrdfFunction, MetfuncColoursItsDirectionalPart) {
  const Rgb c(.6, .3, .1);
  expectExact(readIn("metfunc", distantSun(20.0) + "void metfunc mf 2 half f.cal 0 4 .6 .3 .1 .5\n" + infinitePlane("mf", 0.0, true)),
              2.0, kDown, (c * (0.5 * kInvPi) + c * (0.5 * 0.5)) * sunE(20.0), "metfunc");
}

TEST(BrdfFunction, TransfuncTransmitsASourceByItsFunction) {
  // trans' = .5 (1 − .2) = .4, tspec' = .4 · .4 = .16: the underside of a pane lit from above
  // shows colour (trans' − tspec')/π + colour tspec' f (transfunc colours its transmission); the
  // pane stops shadow rays (Radiance's m_brdf2), so the sensor below gets only that.
  const Rgb c(.9, .8, .7);
  const std::string mat = "void transfunc tf 2 half f.cal 0 6 .9 .8 .7 .2 .5 .4\n";
  expectExact(readIn("transfunc", distantSun(10.0) + mat + infinitePlane("tf", 1.0, true)), 0.0, kUp,
              (c * (0.24 * kInvPi) + c * (0.16 * 0.5)) * sunE(10.0), "through");
  // Its top: colour (1 − trans' − rspec)/π + rspec f (uncoloured).
  expectExact(readIn("transtop", distantSun(10.0) + mat + infinitePlane("tf", 0.0, true)), 2.0, kDown,
              (c * (0.4 * kInvPi) + Rgb(0.2 * 0.5)) * sunE(10.0), "reflected");
}

TEST(BrdfFunction, PlasdataLooksItsDataUpAtTheSourcesDirection) {
  // lz.dat holds lz over [0, 1]: the function `same` passes the value looked up at lz on.
  for (double zen : {0.0, 50.0}) {
    const double lz = std::cos(degToRad(zen));
    expectExact(readIn("plasdata", distantSun(zen) + "void plasdata pd 4 same lz.dat f.cal up 0 4 .5 .5 .5 .25\n" +
                                       infinitePlane("pd", 0.0, true)),
                2.0, kDown, Rgb(0.5 * 0.75 * kInvPi + 0.25 * lz) * sunE(zen), "zenith " + std::to_string(zen));
  }
}

TEST(BrdfFunction, BrtdfuncDirectionalFunctionsOnBothSides) {
  // Front: rdf/π + the three functions; through from the other side: rdt/π + the functions.
  const std::string mat = "void BRTDfunc b 10 0 0 0 0 0 0 half half blue f.cal 0 9 .2 .2 .2 .6 .6 .6 .1 .1 .1\n";
  expectExact(readIn("brtd_front", distantSun(0.0) + mat + infinitePlane("b", 0.0, true)), 2.0, kDown,
              (Rgb(0.2 * kInvPi) + Rgb(.5, .5, .4)) * sunE(0.0), "front");
  expectExact(readIn("brtd_through", distantSun(0.0) + mat + infinitePlane("b", 1.0, true)), 0.0, kUp,
              (Rgb(0.1 * kInvPi) + Rgb(.5, .5, .4)) * sunE(0.0), "through");
}

TEST(BrdfFunction, SkyLightIsReflectedDiffuselyAsRadiancesAmbient) {
  // No sampled source: plasfunc reflects colour (all of it, the specular share included),
  // transfunc colour (1 − trans') above and colour trans' below.
  expectWithin4Se(readIn("sky_plasfunc", "void plasfunc pf 2 half f.cal 0 4 .5 .5 .5 .2\n" + infinitePlane("pf", 0.0, true), true),
                  2.0, kDown, 0.5 * kSkyLux, "plasfunc");
  const std::string tf = "void transfunc tf 2 half f.cal 0 6 .5 .5 .5 .2 .5 .4\n";
  expectWithin4Se(readIn("sky_transfunc_top", tf + infinitePlane("tf", 0.0, true), true), 2.0, kDown, 0.5 * 0.6 * kSkyLux,
                  "transfunc reflected");
  expectWithin4Se(readIn("sky_transfunc_under", tf + infinitePlane("tf", 1.0, true), true), 0.0, kUp, 0.5 * 0.4 * kSkyLux,
                  "transfunc transmitted");
}

TEST(BrdfFunction, TheCameraSeesTheDirectionalPart) {
  // A view straight down on the sunlit plasfunc plane: every traced pixel's luminance is the
  // plane's radiance × 179 (paths: the sun's cone varies it by < 1e-5).
  const Scene sc = readIn("camera", distantSun(0.0) + "void plasfunc pf 2 half f.cal 0 4 .5 .5 .5 .2\n" +
                                        infinitePlane("pf", 0.0, true));
  const Tracer tracer(sc);
  TraceSettings s;
  s.maxBounces = 0;
  const View v = test_support::makeView(ViewType::kPerspective, {0, 0, 1.6}, {0, 0, -1}, {0, 1, 0}, {40, 40}, 9, 9);
  const Image img = renderView(tracer, v, s, 2);
  const double want = kLumensPerWatt * (0.4 * kInvPi + 0.1) * sunE(0.0);
  for (std::size_t i = 0; i < img.luminance.size(); ++i) EXPECT_NEAR(img.luminance[i], want, 1e-4 * want) << i;
  EXPECT_NEAR(luminanceToward(tracer, {0, 0, 1.6}, {0.2, 0.1, 0}, s, 0, 4), want, 1e-4 * want);
}

std::string errorOf(const std::string& name, const std::string& text) {
  try {
    readIn(name, text + "m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A material no surface uses is never refused (a shared library's plasfunc whose function file
// is not on this machine's RAYPATH); used, it is refused saying what used it.
TEST(BrdfFunction, AnUnusedMaterialIsNotRefused) {
  EXPECT_NO_THROW(readIn("unused", "void plasfunc lib 2 absdf aniso.cal 0 4 .5 .5 .5 .1\n"));
  const std::string used = errorOf("used", "void plasfunc m 2 absdf aniso.cal 0 4 .5 .5 .5 .1\n");
  EXPECT_NE(used.find("scene.rad:1: plasfunc 'm': function file 'aniso.cal' is not in the working directory"),
            std::string::npos)
      << used;
  EXPECT_NE(used.find("(used by polygon 'p' at line 2)"), std::string::npos) << used;
}

TEST(BrdfFunction, RefusalsNameTheirLineAndReason) {
  EXPECT_NE(errorOf("reals", "void plasfunc m 2 half f.cal 0 3 .5 .5 .5\n")
                .find("scene.rad:1: plasfunc 'm' needs 4 or more real arguments (red green blue spec), got 3"),
            std::string::npos);
  EXPECT_NE(errorOf("treals", "void transfunc m 2 half f.cal 0 4 .5 .5 .5 .1\n").find("needs 6 or more real"),
            std::string::npos);
  EXPECT_NE(errorOf("notname", "void plasfunc m 2 .5*lz f.cal 0 4 .5 .5 .5 .1\n")
                .find("its function '.5*lz' must name a function of the light's direction"),
            std::string::npos);
  EXPECT_NE(errorOf("undefined", "void metfunc m 2 nothing f.cal 0 4 .5 .5 .5 .1\n").find("'nothing' is not defined"),
            std::string::npos);
  EXPECT_NE(errorOf("spec", "void plasfunc m 2 half f.cal 0 4 .5 .5 .5 1.5\n").find("needs a specularity in [0, 1]"),
            std::string::npos);
  EXPECT_NE(errorOf("dims", "void plasdata m 3 same lz.dat f.cal 0 4 .5 .5 .5 .1\n")
                .find("has 1 dimensions: give as many coordinate functions"),
            std::string::npos);
  EXPECT_NE(errorOf("brtd", "void BRTDfunc m 10 0 0 0 0 0 0 half lz*2 0 f.cal 0 9 0 0 0 0 0 0 0 0 0\n")
                .find("its directional function 'lz*2' must name a function"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
