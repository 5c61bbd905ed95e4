// BRTDfunc against closed forms under a uniform sky of E = 10 000 lux (luminance E/π) over a
// black ground. An infinite surface 2 m below a sensor facing it: its diffuse reflectance ρ gives
// ρE, a mirror reflectance r for every direction gives rE, and one for the directions within 60°
// of the normal (RdotP > 0.5) r·E·∫cos dω/π over that cap = r·E·(1 − cos²60°) = 0.75 rE. An
// infinite pane above a sensor facing up passes τE the same way.
#include "engine/tracer.h"
#include "tests/support/material_harness.h"
#include "tests/support/temp_files.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

constexpr double kSkyLux = test_support::kUniformSkyLux;
using test_support::infinitePlane;

Scene readIn(const std::string& name, const std::string& text) {
  return test_support::readSceneText(test_support::scratchDir("brtdfunc", name), text, true);
}

// The light at (0.3, 0.2, z) on a sensor facing n, within 4 standard errors of want (and the
// error small enough to tell a wrong factor apart).
void expectLux(const Scene& sc, double z, const Vec3& n, double want, const std::string& what) {
  TraceSettings s;
  s.seed = 2;
  s.hemisphereSamples = 4096;
  s.maxBounces = 2;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, z), Response::planar(n), 0, s);
  EXPECT_NEAR(e.illuminanceLux(), want, std::max(4.0 * e.standardErrorLux(), 1e-9 * kSkyLux)) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * kSkyLux) << what;
}

const Vec3 kDown(0, 0, -1), kUp(0, 0, 1);

TEST(BrtdFunc, DiffuseReflectanceOfTheSideMetAndThePatternsColour) {
  const std::string mat = "void BRTDfunc b 10 0 0 0 0 0 0 0 0 0 . 0 9 .2 .2 .2 .6 .6 .6 0 0 0\n";
  expectLux(readIn("front", mat + infinitePlane("b", 0.0, true)), 2.0, kDown, 0.2 * kSkyLux, "front");
  expectLux(readIn("back", mat + infinitePlane("b", 0.0, false)), 2.0, kDown, 0.6 * kSkyLux, "back");
  expectLux(readIn("pattern", "void brightfunc half 2 .5 . 0 0\nhalf BRTDfunc b 10 0 0 0 0 0 0 0 0 0 . 0 9 "
                              ".2 .2 .2 .6 .6 .6 0 0 0\n" + infinitePlane("b", 0.0, true)),
            2.0, kDown, 0.1 * kSkyLux, "times the pattern");
}

TEST(BrtdFunc, MirrorReflectanceByItsExpressions) {
  expectLux(readIn("mirror", "void BRTDfunc b 10 .4 .4 .4 0 0 0 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0\n" +
                                 infinitePlane("b", 0.0, true)),
            2.0, kDown, 0.4 * kSkyLux, "constant");
  expectLux(readIn("cap", "void BRTDfunc b 10 if(RdotP-.5,.4,0) if(RdotP-.5,.4,0) if(RdotP-.5,.4,0) 0 0 0 0 0 0 . "
                          "0 9 0 0 0 0 0 0 0 0 0\n" + infinitePlane("b", 0.0, true)),
            2.0, kDown, 0.75 * 0.4 * kSkyLux, "within 60°");
}

// Met from behind (the pane's front faces up, the sensor's rays and the sky's shadow rays come
// from below): RdotP is turned towards the ray, Rdot keeps its sign.
TEST(BrtdFunc, StraightTransmittanceTurnedTowardsTheRay) {
  const std::string cap = "if(RdotP-.5,.6,0)";
  expectLux(readIn("pane", "void BRTDfunc b 10 0 0 0 " + cap + " " + cap + " " + cap + " 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0\n" +
                               infinitePlane("b", 1.0, true)),
            0.0, kUp, 0.75 * 0.6 * kSkyLux, "RdotP");
  expectLux(readIn("sign", "void BRTDfunc b 10 0 0 0 if(Rdot,.6,0) if(Rdot,.6,0) if(Rdot,.6,0) 0 0 0 . 0 9 0 0 0 0 0 0 "
                           "0 0 0\n" + infinitePlane("b", 1.0, true)),
            0.0, kUp, 0.0, "Rdot < 0 from behind");
}

std::string errorOf(const std::string& name, const std::string& text) {
  try {
    readIn(name, text + "b polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BrtdFunc, RefusalsNameTheirLineAndReason) {
  EXPECT_NE(errorOf("directional", "void BRTDfunc b 10 0 0 0 0 0 0 f f f . 0 9 0 0 0 0 0 0 0 0 0\n")
                .find("scene.rad:1: 'f' is not defined in the function files"),
            std::string::npos);
  EXPECT_NE(errorOf("strings", "void BRTDfunc b 9 0 0 0 0 0 0 0 0 0 0 9 0 0 0 0 0 0 0 0 0\n")
                .find("needs 10 or more string arguments"),
            std::string::npos);
  EXPECT_NE(errorOf("reals", "void BRTDfunc b 10 0 0 0 0 0 0 0 0 0 . 0 6 0 0 0 0 0 0\n").find("needs 9 or more real"),
            std::string::npos);
  EXPECT_NE(errorOf("expression", "void BRTDfunc b 10 (1+ 0 0 0 0 0 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0\n")
                .find("its rrefl '(1+' is not an expression"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
