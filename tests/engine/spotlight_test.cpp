// Radiance's spotlight: a light whose output is confined to a cone about its aim, the aim's length
// the focal distance behind the source (Radiance reference manual, "Spotlight"; src/rt/source.c
// and srcsupp.c: a direction outside the cone gets nothing, and the source's solid angle seen
// from distance d is scaled by d²/(d + focal)²). A 2 cm disk spotlight of radiance L, 60° cone,
// aim (0, 0, −2), lights a point at distance d, at angle θ off the aim, facing the disk:
//   E = 179 · L · π r² · cos²θ / d² · (d / (d + 2))²   inside the cone, 0 outside,
// within 4 standard errors plus the point-source error (r/d)² of the disk.
#include "engine/radiance/reader.h"
#include "engine/source_distribution.h"
#include "engine/tracer.h"
#include "tests/support/direct_only.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace candela {
namespace {

const char* kSpot =
    "void spotlight spot\n0\n0\n7 1000 1000 1000 60 0 0 -2\n"
    "spot ring disk\n0\n0\n8 0 0 0  0 0 -1  0 .02\n";

TEST(Spotlight, ReadsTheConeAndTheFocalDistance) {
  Scene sc;
  readRadianceText(kSpot, "spot.rad", sc);
  ASSERT_EQ(sc.materials.size(), 1u);
  const Material& m = sc.materials[0];
  EXPECT_EQ(m.type, MaterialType::kLight);
  EXPECT_TRUE(m.spot);
  EXPECT_NEAR(m.spotCosHalf, std::cos(30.0 * kPi / 180.0), 1e-15);
  EXPECT_NEAR(m.spotFocalM, 2.0, 1e-15);
  EXPECT_NEAR(m.spotAim.z, -1.0, 1e-15);
  // Inside the cone a ray meeting the disk sees its radiance, outside black.
  EXPECT_TRUE(m.emitsTowards(glm::normalize(Vec3(0.5, 0, -1))));    // 26.6°
  EXPECT_FALSE(m.emitsTowards(glm::normalize(Vec3(0.7, 0, -1))));   // 35°
  EXPECT_EQ(emittedRadiance(sc, m, glm::normalize(Vec3(-0.7, 0, 1)), 0.8).x, 0.0);
  EXPECT_EQ(emittedRadiance(sc, m, Vec3(0, 0, 1), 1.0).x, 1000.0);
}

TEST(Spotlight, IlluminanceInsideTheConeFollowsTheFocalLawAndIsZeroOutside) {
  Scene sc;
  readRadianceText(kSpot, "spot.rad", sc);
  const Tracer tracer(sc);
  const double r = 0.02, focal = 2.0, radiance = 1000.0;
  uint64_t index = 0;
  for (double d : {1.0, 3.0, 6.0})
    for (double thetaDeg : {0.0, 20.0, 29.0, 31.0, 45.0}) {
      const double t = thetaDeg * kPi / 180.0;
      const Vec3 p(d * std::sin(t), 0.0, -d * std::cos(t));
      const Vec3 n = glm::normalize(-p);  // facing the disk
      const double inside = thetaDeg < 30.0 ? 1.0 : 0.0;
      const double ratio = d / (d + focal);
      const double expected =
          inside * kLumensPerWatt * radiance * kPi * r * r * std::cos(t) / (d * d) * ratio * ratio;
      const IrradianceEstimate e = estimateIrradiance(tracer, p, n, index++, test_support::directOnlySettings(256));
      EXPECT_NEAR(e.illuminanceLux(), expected, 4.0 * e.standardErrorLux() + (r / d) * (r / d) * expected)
          << "d " << d << " θ " << thetaDeg;
    }
}

TEST(Spotlight, BadArgumentsNameTheLine) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"void spotlight s\n0\n0\n7 1 1 1 0 0 0 -1\n", "spot.rad:1: spotlight 's' needs a cone angle in (0, 360]"},
           {"void spotlight s\n0\n0\n7 1 1 1 40 0 0 0\n", "spot.rad:1: spotlight 's' has a zero direction"},
           {"void spotlight s\n0\n0\n3 1 1 1\n", "spot.rad:1: spotlight 's' needs 7 real arguments, got 3"},
           {"void spotlight s\n0\n0\n7 1 1 1 40 0 0 -1\ns source sun\n0\n0\n4 0 0 1 .5\n",
            "spot.rad:5: source 'sun': a spotlight as a distant source is not supported"}}) {
    Scene sc;
    try {
      readRadianceText(text, "spot.rad", sc);
      ADD_FAILURE() << text << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
    }
  }
}

// A spotlight whose cone lies wholly behind its surface's front sends nothing: read, with a
// warning at the surface's line. A cone that reaches past the horizon is not warned of.
TEST(Spotlight, AConeWhollyBehindItsSurfaceIsWarnedOf) {
  auto warnings = [](const std::string& text) {
    Scene sc;
    readRadianceText(text, "spot.rad", sc);
    EXPECT_EQ(sc.shapes.size(), 1u);
    return sc.inputWarnings;
  };
  // Aimed down, 40° cone, on a disk and a polygon facing up.
  const auto ring = warnings("void spotlight s\n0\n0\n7 1 1 1 40 0 0 -1\n\ns ring r\n0\n0\n8 0 0 0 0 0 1 0 .1\n");
  ASSERT_EQ(ring.size(), 1u);
  EXPECT_EQ(ring[0].code, "spotlight_behind_surface");
  EXPECT_EQ(ring[0].loc.line, 6);
  const auto polygon = warnings("void spotlight s\n0\n0\n7 1 1 1 40 0 0 -1\ns polygon q\n0\n0\n9 0 0 0 1 0 0 0 1 0\n");
  ASSERT_EQ(polygon.size(), 1u);
  EXPECT_EQ(polygon[0].loc.line, 5);
  // Aimed 60° below the surface's plane with a 160° cone: 20° of it rises above the plane.
  EXPECT_TRUE(warnings("void spotlight s\n0\n0\n7 1 1 1 160 0.5 0 -0.8660254\ns ring r\n0\n0\n8 0 0 0 0 0 1 0 .1\n")
                  .empty());
  // Aimed along the front: nothing to say.
  EXPECT_TRUE(warnings("void spotlight s\n0\n0\n7 1 1 1 40 0 0 1\ns ring r\n0\n0\n8 0 0 0 0 0 1 0 .1\n").empty());
}

// xform turns the aim with the scene and scales the focal distance (xform.c multiplies the
// direction by the whole transform): -ry 90 takes (0, 0, −2) to (−2, 0, 0), -s 2 to (−4, 0, 0).
TEST(Spotlight, XformTurnsTheAimAndScalesTheFocalDistance) {
  Scene sc;
  SceneReader(sc).readText("!xform -ry 90 -s 2 spot.rad\n", "x.rad", std::filesystem::path(CANDELA_TEST_DATA) / "rad");
  ASSERT_EQ(sc.materials.size(), 1u);
  const Material& m = sc.materials[0];
  EXPECT_NEAR(m.spotAim.x, -1.0, 1e-12);
  EXPECT_NEAR(m.spotAim.z, 0.0, 1e-12);
  EXPECT_NEAR(m.spotFocalM, 4.0, 1e-12);
}

}  // namespace
}  // namespace candela
