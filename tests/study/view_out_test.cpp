#include "study/view_out.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/radiance/reader.h"
#include "engine/tracer.h"

namespace candela {
namespace {

// A wall in the plane y = -d (opaque, 2 km wide and high) with a window of clear glass x in
// [x0, x1], z in [0.5, 2.5]; the eye at (0, 0, 1.2) looks south through it.
std::string wallWithWindow(double d, double x0, double x1) {
  auto poly = [&](const std::string& mod, const std::string& name, double xa, double xb, double za, double zb) {
    const std::string y = std::to_string(-d);
    const std::string a = std::to_string(xa), b = std::to_string(xb), lo = std::to_string(za), hi = std::to_string(zb);
    return mod + " polygon " + name + " 0 0 12 " + a + " " + y + " " + lo + "  " + b + " " + y + " " + lo + "  " + b +
           " " + y + " " + hi + "  " + a + " " + y + " " + hi + "\n";
  };
  return "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
         "void glass clear 0 0 3 0.9 0.9 0.9\n" +
         poly("grey", "left", -1e3, x0, -1e3, 1e3) + poly("grey", "right", x1, 1e3, -1e3, 1e3) +
         poly("grey", "below", x0, x1, -1e3, 0.5) + poly("grey", "above", x0, x1, 2.5, 1e3) +
         poly("clear", "window", x0, x1, 0.5, 2.5);
}

// An opaque wall parallel to the window, D beyond it (y = -d - D), from z = -1e3 up to `top`.
std::string outsideWall(double d, double D, double top) {
  const std::string y = std::to_string(-d - D), t = std::to_string(top);
  return "grey polygon opposite 0 0 12 -1e4 " + y + " -1e3  1e4 " + y + " -1e3  1e4 " + y + " " + t + "  -1e4 " + y +
         " " + t + "\n";
}

// The outside ground: a horizontal plane z = 0 beyond the window wall.
std::string outsideGround(double d) {
  const std::string y = std::to_string(-d);
  return "grey polygon ground 0 0 12 -1e4 " + y + " 0  -1e4 -1e4 0  1e4 -1e4 0  1e4 " + y + " 0\n";
}

ViewOut viewFrom(const std::string& text, const ViewOutOptions& o = {}) {
  Scene sc;
  readRadianceText(text, "view_scene.rad", sc);
  const Tracer tracer(sc);
  const std::vector<ViewOut> v = viewOut(tracer, {Vec3(0.0, 0.0, 1.2)}, o);
  EXPECT_EQ(v.size(), 1u);
  return v[0];
}

double sightAngleDeg(double w, double d) { return radToDeg(2.0 * std::atan(w / (2.0 * d))); }

// The sampled directions' centres in an interval of angle L number L/step ± 1: the measured angle
// lies within one step of the exact one.
TEST(ViewOutTest, SightAngleOfACentredWindowIs2AtanHalfWidthOverDistance) {
  ViewOutOptions o;
  for (const auto& [w, d] : {std::pair{1.2, 2.0}, std::pair{2.4, 4.0}, std::pair{0.6, 5.0}}) {
    const ViewOut v = viewFrom(wallWithWindow(d, -0.5 * w, 0.5 * w), o);
    EXPECT_NEAR(v.sightAngleDeg, sightAngleDeg(w, d), o.horizontalStepDeg + 1e-9) << w << " m at " << d << " m";
    EXPECT_EQ(v.sightAngleDeg, v.totalSightAngleDeg);
    EXPECT_EQ(v.sightLevel, viewSightAngleLevel(v.sightAngleDeg));
  }
}

TEST(ViewOutTest, TwoWindowsAddToTheTotalNotToTheLargest) {
  // The centred window (1.2 m at 2 m) and a second one x 2..3 with a pier between.
  std::string s = "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\nvoid glass clear 0 0 3 0.9 0.9 0.9\n";
  auto rect = [](const std::string& mod, const std::string& name, double xa, double xb, double za, double zb) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s polygon %s 0 0 12 %g -2 %g  %g -2 %g  %g -2 %g  %g -2 %g\n", mod.c_str(),
                  name.c_str(), xa, za, xb, za, xb, zb, xa, zb);
    return std::string(buf);
  };
  s += rect("grey", "left", -1e3, -0.6, -1e3, 1e3) + rect("grey", "pier", 0.6, 2.0, -1e3, 1e3) +
       rect("grey", "right", 3.0, 1e3, -1e3, 1e3);
  for (const auto& [a, b] : {std::pair{-0.6, 0.6}, std::pair{2.0, 3.0}})
    s += rect("grey", "below", a, b, -1e3, 0.5) + rect("grey", "above", a, b, 2.5, 1e3) +
         rect("clear", "window", a, b, 0.5, 2.5);
  ViewOutOptions o;
  const ViewOut v = viewFrom(s, o);
  const double first = sightAngleDeg(1.2, 2.0);
  const double second = radToDeg(std::atan(3.0 / 2.0) - std::atan(2.0 / 2.0));
  EXPECT_NEAR(v.sightAngleDeg, first, o.horizontalStepDeg + 1e-9);
  EXPECT_NEAR(v.totalSightAngleDeg, first + second, 2.0 * o.horizontalStepDeg + 1e-9);
  o.gradeTotalAngle = true;
  const ViewOut graded = viewFrom(s, o);
  EXPECT_EQ(graded.sightLevel, viewSightAngleLevel(graded.totalSightAngleDeg));
}

TEST(ViewOutTest, OutsideDistanceToAParallelWall) {
  const double w = 2.4, d = 1.0, D = 15.0;
  const ViewOut v = viewFrom(wallWithWindow(d, -0.5 * w, 0.5 * w) + outsideWall(d, D, 1e3));
  // The ray normal to the window (sampled within half a step, 0.025°: 1e-7 relative) meets the
  // wall D behind the glass; a ray at angle θ from the normal meets it D / cos θ behind, and the
  // view rays' |θ| are spread evenly over [0, θmax], θmax = atan(w / 2d): the median is at θmax/2.
  EXPECT_NEAR(v.outsideDistanceM, D, 1e-6 * D);
  const double thetaMax = std::atan(w / (2.0 * d));
  const double step = degToRad(ViewOutOptions{}.horizontalStepDeg);
  EXPECT_NEAR(v.medianOutsideDistanceM, D / std::cos(0.5 * thetaMax), D * std::tan(thetaMax) * step);
  EXPECT_EQ(v.distanceLevel, En17037Level::kMinimum);  // 6 m ≤ 15 m < 20 m

  const ViewOut open = viewFrom(wallWithWindow(d, -0.5 * w, 0.5 * w));
  EXPECT_TRUE(std::isinf(open.outsideDistanceM));
  EXPECT_EQ(open.distanceLevel, En17037Level::kHigh);
}

TEST(ViewOutTest, LayersOfConstructedViews) {
  const double w = 2.4, d = 1.0;
  const std::string room = wallWithWindow(d, -0.5 * w, 0.5 * w);
  // Nothing outside: the sky above, candela's ground below, the open horizon between.
  const ViewOut open = viewFrom(room);
  EXPECT_EQ(open.layers, kLayerSky | kLayerLandscape | kLayerGround) << viewLayersName(open.layers);
  EXPECT_EQ(open.layersLevel, En17037Level::kHigh);
  // An opaque wall 10 m out, higher than anything the window shows and reaching down below it:
  // landscape only (no sky, no ground).
  const ViewOut walled = viewFrom(room + outsideWall(d, 10.0, 1e3));
  EXPECT_EQ(walled.layers, kLayerLandscape) << viewLayersName(walled.layers);
  EXPECT_EQ(walled.layersLevel, En17037Level::kMinimum);
  // The same wall with the ground in front of it: rays down through the window (elevation
  // −6°…−35°) meet the ground between the facade and the wall.
  const ViewOut grounded = viewFrom(room + outsideWall(d, 10.0, 1e3) + outsideGround(d));
  EXPECT_EQ(grounded.layers, kLayerLandscape | kLayerGround) << viewLayersName(grounded.layers);
  EXPECT_EQ(grounded.layersLevel, En17037Level::kMedium);
  // A wall only 1 m high: the sky above it again.
  const ViewOut low = viewFrom(room + outsideWall(d, 10.0, 1.0) + outsideGround(d));
  EXPECT_EQ(low.layers, kLayerSky | kLayerLandscape | kLayerGround) << viewLayersName(low.layers);
  EXPECT_EQ(low.level, lowerLevel(lowerLevel(low.sightLevel, low.distanceLevel), low.layersLevel));
}

TEST(ViewOutTest, NoWindowNoView) {
  Scene sc;
  readRadianceText("void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                   "grey sphere room 0 0 4 0 0 1.2 5\n",
                   "closed.rad", sc);
  const Tracer tracer(sc);
  const ViewOut v = viewOut(tracer, {Vec3(0.0, 0.0, 1.2)})[0];
  EXPECT_EQ(v.totalSightAngleDeg, 0.0);
  EXPECT_EQ(v.outsideDistanceM, 0.0);
  EXPECT_EQ(v.layers, 0);
  EXPECT_EQ(v.level, En17037Level::kNone);
}

TEST(ViewOutTest, ResultsDoNotDependOnThreads) {
  Scene sc;
  readRadianceText(wallWithWindow(2.0, -1.0, 0.7) + outsideWall(2.0, 7.0, 3.0) + outsideGround(2.0), "v.rad", sc);
  const Tracer tracer(sc);
  const std::vector<Vec3> eyes = {Vec3(0.0, 0.0, 1.2), Vec3(0.3, 1.0, 1.6), Vec3(-0.5, 3.0, 1.2)};
  ViewOutOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = viewOut(tracer, eyes, one), b = viewOut(tracer, eyes, two);
  for (size_t i = 0; i < eyes.size(); ++i) {
    EXPECT_EQ(a[i].sightAngleDeg, b[i].sightAngleDeg);
    EXPECT_EQ(a[i].outsideDistanceM, b[i].outsideDistanceM);
    EXPECT_EQ(a[i].layers, b[i].layers);
  }
}

}  // namespace
}  // namespace candela
