// Radiance's antimatter (reference manual "Antimatter", src/rt/m_clip.c; engine/antimatter.h):
// an opaque black wall 0.2 m thick (z from 1 to 1.2) between a sensor at the origin (facing up)
// and a light panel above, and antimatter boxes cut through it. The light reaches the sensor only
// through the holes: seen from the sensor a hole of square section is open where both its openings
// are, so in the tangent plane z = 1 it is the intersection R of the bottom opening's projection
// (scaled by 1/1.0) and the top opening's (by 1/1.2), and the illuminance is
//   E = 179 · L · π F(R),
// F(R) the form factor from the sensor to the rectangle R at unit height (Howell's catalogue, B-3:
// a differential area to a parallel rectangle with a corner above it, combined by signs), while
// the panel fills the whole view through the holes. Asserted within 4 standard errors.
#include "engine/integrator_path.h"
#include "engine/irradiance_estimator.h"
#include "engine/antimatter.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "tests/support/direct_only.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace candela {
namespace {

// Form factor from a differential area at the origin (normal +z) to the rectangle [0, x] × [0, y]
// at height 1, odd in x and in y (so that rectangles anywhere combine by signs).
double cornerFormFactor(double x, double y) {
  const double sx = x < 0 ? -1.0 : 1.0, sy = y < 0 ? -1.0 : 1.0;
  x = std::abs(x);
  y = std::abs(y);
  const double a = std::sqrt(1.0 + x * x), b = std::sqrt(1.0 + y * y);
  return sx * sy * (x / a * std::atan(y / a) + y / b * std::atan(x / b)) / (2.0 * kPi);
}

double rectangleFormFactor(double x1, double x2, double y1, double y2) {
  return cornerFormFactor(x2, y2) - cornerFormFactor(x1, y2) - cornerFormFactor(x2, y1) + cornerFormFactor(x1, y1);
}

// The open part, in the plane z = 1, of a square hole [x1, x2] × [y1, y2] through the wall.
double holeFormFactor(double x1, double x2, double y1, double y2) {
  constexpr double kBottom = 1.0, kTop = 1.2;
  auto lo = [&](double v) { return std::max(v / kBottom, v / kTop); };
  auto hi = [&](double v) { return std::min(v / kBottom, v / kTop); };
  return rectangleFormFactor(lo(x1), hi(x2), lo(y1), hi(y2));
}

// The wall (6 m square, z from 1 to 1.2), a light panel 2.4 m square at z = 1.5 facing down
// (radiance 100 W/sr/m²), the antimatter's definition and its boxes (z from 0.9 to 1.3).
std::string wallScene(const std::string& antimatter, const std::string& boxes, const std::string& wall = "black",
                      bool panel = true) {
  return "void plastic black 0 0 5 0 0 0 0 0\n"
         "void glow bright 0 0 4 10 10 10 0\n"
         "void light lamp 0 0 3 100 100 100\n" +
         antimatter + "\n!genbox " + wall + " wall 6 6 0.2 | xform -t -3 -3 1\n" + boxes +
         (panel ? "lamp polygon panel 0 0 12  -1.2 -1.2 1.5  -1.2 1.2 1.5  1.2 1.2 1.5  1.2 -1.2 1.5\n" : "");
}

std::string box(const std::string& cutter, const std::string& name, double x1, double y1, double side) {
  return "!genbox " + cutter + " " + name + " " + std::to_string(side) + " " + std::to_string(side) +
         " 0.4 | xform -t " + std::to_string(x1) + " " + std::to_string(y1) + " 0.9\n";
}

double expectedLux(double formFactor) { return kLumensPerWatt * 100.0 * kPi * formFactor; }

IrradianceEstimate sensorEstimate(const Scene& sc, uint64_t index = 0) {
  const Tracer tracer(sc);
  return estimateIrradiance(tracer, Vec3(0.0), Vec3(0, 0, 1), index, test_support::directOnlySettings(65536));
}

TEST(Antimatter, ReadsItsModifiersAndGivesThemClipBits) {
  Scene sc;
  readRadianceText(wallScene("void antimatter cutter 2 black black 0 0", box("cutter", "hole", -0.2, -0.2, 0.4)),
                   "wall.rad", sc);
  const Material& cutter = sc.materials[3];
  ASSERT_EQ(cutter.type, MaterialType::kAntimatter);
  EXPECT_EQ(cutter.shownMaterial, 0);          // black, the first listed
  EXPECT_EQ(cutter.clipList, std::vector<int>{0});  // listed twice, counted once (m_clip's set)
  EXPECT_EQ(sc.materials[0].clipBit, 0);
  EXPECT_EQ(cutter.clipMask, 1u);
  EXPECT_EQ(sc.materials[1].clipBit, -1);
  EXPECT_TRUE(hasAntimatter(sc.materials));
}

TEST(Antimatter, WallWithoutHoleIsDark) {
  Scene sc;
  readRadianceText(wallScene("void antimatter cutter 1 black 0 0", ""), "wall.rad", sc);
  EXPECT_EQ(sensorEstimate(sc).illuminanceLux(), 0.0);
}

TEST(Antimatter, SquareHoleLetsTheLightOfItsOpenSolidAngleThrough) {
  for (const char* def : {"void antimatter cutter 1 black 0 0", "void antimatter cutter 2 void black 0 0"}) {
    Scene sc;
    readRadianceText(wallScene(def, box("cutter", "hole", -0.2, -0.2, 0.4)), "wall.rad", sc);
    const IrradianceEstimate e = sensorEstimate(sc);
    const double expected = expectedLux(holeFormFactor(-0.2, 0.2, -0.2, 0.2));
    std::cout << def << ": " << e.illuminanceLux() << " ± " << e.standardErrorLux() << " lx, closed form " << expected
              << " lx\n";
    EXPECT_GT(e.illuminanceLux(), 0.0) << def;
    EXPECT_NEAR(e.illuminanceLux(), expected, 4.0 * e.standardErrorLux()) << def;
    // The estimate is worth a test: its error bar well below the effect.
    EXPECT_LT(e.standardErrorLux(), 0.03 * expected) << def;
  }
}

TEST(Antimatter, TwoAntimattersCutTwoHoles) {
  Scene sc;
  readRadianceText(wallScene("void antimatter a 1 black 0 0\nvoid antimatter b 1 black 0 0",
                             box("a", "hole1", -0.2, -0.2, 0.4) + box("b", "hole2", 0.4, -0.2, 0.4)),
                   "wall.rad", sc);
  const IrradianceEstimate e = sensorEstimate(sc, 7);
  const double expected = expectedLux(holeFormFactor(-0.2, 0.2, -0.2, 0.2) + holeFormFactor(0.4, 0.8, -0.2, 0.2));
  std::cout << "two holes: " << e.illuminanceLux() << " ± " << e.standardErrorLux() << " lx, closed form " << expected
            << " lx\n";
  EXPECT_NEAR(e.illuminanceLux(), expected, 4.0 * e.standardErrorLux());
  EXPECT_LT(e.standardErrorLux(), 0.03 * expected);
}

// The hole's sides are seen as the wall's material (a glow here, radiance 10): a ray from the
// sensor to the middle of a side sees it, turned to face the ray; straight up it sees nothing.
TEST(Antimatter, HoleSidesShowTheWallMaterial) {
  Scene sc;
  readRadianceText(
      wallScene("void antimatter cutter 1 bright 0 0", box("cutter", "hole", -0.2, -0.2, 0.4), "bright", false),
      "wall.rad", sc);  // no light panel: nothing above the hole
  const Tracer tracer(sc);
  Rng rng(1, 0);
  const TraceSettings s = test_support::directOnlySettings(1);
  auto seen = [&](const Vec3& target) {
    return rayRadiance(tracer, Vec3(0.0), glm::normalize(target), kNoShape, true, rng, s).x;
  };
  EXPECT_EQ(seen(Vec3(0.2, 0.0, 1.1)), 10.0);   // a side of the hole, inside the wall
  EXPECT_EQ(seen(Vec3(0.0, -0.2, 1.15)), 10.0);
  EXPECT_EQ(seen(Vec3(0.5, 0.0, 1.0)), 10.0);   // the wall's face beside the hole
  EXPECT_EQ(seen(Vec3(0.0, 0.0, 1.0)), 0.0);    // through the hole
  EXPECT_EQ(seen(Vec3(0.05, 0.05, 1.0)), 0.0);
}

// What a ray meets first, from o along d, starting with an empty clip set (Radiance's primary rays).
struct Seen {
  bool hit = false;
  double t = 0.0;
  ClipAction action = ClipAction::kVisible;
};
Seen firstFrom(const Scene& sc, const Tracer& tracer, const Vec3& o, const Vec3& d) {
  ClipState st;
  RayHit h;
  ClipResult r;
  uint64_t rays = 0;
  Seen s;
  s.hit = firstSeen(tracer.accelerator(), sc, o, d, kNoShape, st, h, r, rays);
  s.t = h.t;
  s.action = r.action;
  return s;
}

// A ray starts outside all antimatter, as Radiance's primary rays (an empty clip set): started
// inside the volume it sees the wall until it has left the volume.
TEST(Antimatter, RayStartingInsideTheVolumeSeesTheWall) {
  Scene sc;
  readRadianceText(wallScene("void antimatter cutter 1 black 0 0", box("cutter", "hole", -0.2, -0.2, 0.4)),
                   "wall.rad", sc);
  const Tracer tracer(sc);
  const Seen below = firstFrom(sc, tracer, Vec3(0, 0, 0.95), Vec3(0, 0, 1));  // in the volume, under the wall
  ASSERT_TRUE(below.hit);
  EXPECT_NEAR(below.t, 0.05, 1e-9);
  EXPECT_EQ(below.action, ClipAction::kVisible);
  const Seen inWall = firstFrom(sc, tracer, Vec3(0, 0, 1.1), Vec3(0, 0, 1));  // its top face, from inside
  ASSERT_TRUE(inWall.hit);
  EXPECT_NEAR(inWall.t, 0.1, 1e-9);
  // From outside the same ray passes: the panel above is what it sees.
  const Seen outside = firstFrom(sc, tracer, Vec3(0, 0, 0.5), Vec3(0, 0, 1));
  ASSERT_TRUE(outside.hit);
  EXPECT_NEAR(outside.t, 1.0, 1e-9);
}

// Nested antimatter of the same material: the clip set is a set (m_clip.c), so leaving the inner
// volume un-clips the wall though the ray is still in the outer one. With the wall as the inner
// one's first modifier and the ray inside the wall, the inner volume's top is seen as the wall;
// with void first the ray goes on and meets the wall's top face from inside.
TEST(Antimatter, NestedVolumesOfOneMaterialFollowRadiancesSet) {
  const std::string outer = box("outer", "o", -0.2, -0.2, 0.4);
  const std::string inner = "!genbox inner i 0.2 0.2 0.1 | xform -t -0.1 -0.1 0.95\n";  // z from 0.95 to 1.05
  for (const auto& [first, action, t] : {std::tuple{"black", ClipAction::kShown, 1.05},
                                         std::tuple{"void", ClipAction::kVisible, 1.2}}) {
    Scene sc;
    readRadianceText(wallScene("void antimatter outer 1 black 0 0\nvoid antimatter inner 2 " + std::string(first) +
                                   " black 0 0",
                               outer + inner),
                     "wall.rad", sc);
    const Tracer tracer(sc);
    const Seen s = firstFrom(sc, tracer, Vec3(0.0), Vec3(0, 0, 1));
    ASSERT_TRUE(s.hit) << first;
    EXPECT_EQ(s.action, action) << first;
    EXPECT_NEAR(s.t, t, 1e-9) << first;
  }
}

// The clip state's crossing counts: 4 bits each, signed, saturated at -8 and +7, independent.
TEST(Antimatter, CrossingCountsAreSignedNibbles) {
  ClipState st;
  EXPECT_TRUE(isEmpty(st));
  st.cross(0, 1);
  st.cross(1, -1);
  st.cross(15, -1);
  st.cross(15, -1);
  EXPECT_EQ(st.crossings(0), 1);
  EXPECT_EQ(st.crossings(1), -1);
  EXPECT_EQ(st.crossings(14), 0);
  EXPECT_EQ(st.crossings(15), -2);
  for (int i = 0; i < 20; ++i) st.cross(2, 1), st.cross(3, -1);
  EXPECT_EQ(st.crossings(2), 7);
  EXPECT_EQ(st.crossings(3), -8);
  EXPECT_EQ(st.crossings(1), -1);
  EXPECT_FALSE(isEmpty(st));
  st.cross(0, -1);
  EXPECT_EQ(st.crossings(0), 0);
}

std::string refusal(const std::string& text) {
  Scene sc;
  try {
    readRadianceText(text, "am.rad", sc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Antimatter, RefusalsNameTheirLine) {
  const std::string used = "am polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n";
  // An unknown modifier: refused where a surface uses the antimatter, at the definition's line.
  EXPECT_EQ(refusal("\nvoid antimatter am 1 nosuch 0 0\n" + used),
            "am.rad:2: antimatter 'am': its modifier 'nosuch' is not a material defined before it (used by "
            "polygon 'p' at line 3)");
  EXPECT_EQ(refusal("void antimatter am 1 nosuch 0 0\n"), "no error");  // no surface uses it
  EXPECT_EQ(refusal("void antimatter am 0 0 0\n" + used).rfind("am.rad:1: antimatter 'am' lists no modifier", 0), 0u);
  EXPECT_EQ(refusal("void antimatter am 1 void 0 1 2\n" + used)
                .rfind("am.rad:1: antimatter 'am' needs 0 real arguments, got 1", 0),
            0u);
  EXPECT_EQ(refusal("void antimatter a 1 void 0 0\nvoid antimatter am 1 a 0 0\n" + used),
            "am.rad:2: antimatter 'am': its first modifier 'a' is an antimatter; the first modifier is the material "
            "its surface is seen as (void: none) (used by polygon 'p' at line 3)");
  // More materials than a clip set holds, over all the scene's antimatter.
  std::string many, list;
  for (int i = 0; i <= kMaxClippedMaterials; ++i) {
    many += "void plastic m" + std::to_string(i) + " 0 0 5 .5 .5 .5 0 0\n";
    list += " m" + std::to_string(i);
  }
  const std::string text = many + "void antimatter am " + std::to_string(kMaxClippedMaterials + 1) + list + " 0 0\n";
  EXPECT_EQ(refusal(text), "no error");
  EXPECT_EQ(refusal(text + used),
            "am.rad:18: antimatter 'am' clips 'm16', one more than the 16 materials candela's clip sets hold for "
            "all the antimatter of a scene (used by polygon 'p' at line 19)");
}

}  // namespace
}  // namespace candela
