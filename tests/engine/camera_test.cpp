// Camera projections (docs/views.md) against formulas written out independently here, and the
// pixel solid angles against closed-form totals.
#include "engine/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

View makeView(ViewType type, Vec3 dir, Vec3 up, Vec2 fovDeg, int w, int h) {
  View v;
  v.type = type;
  v.positionM = {1.0, 2.0, 1.5};
  v.direction = dir;
  v.up = up;
  v.fovDeg = fovDeg;
  v.resolution = {w, h};
  return v;
}

// A perspective camera looking north (+Y) with +Z up: right is east (+X). Pixel (i, j) centre has
// normalised coordinates sx = (2i + 1)/W − 1, sy = 1 − (2j + 1)/H and looks along
// (sx tan(h/2), 1, sy tan(v/2)).
TEST(Camera, PerspectiveRayPerPixelFollowsThePinholeFormula) {
  const int w = 40, h = 30;
  const Camera cam(makeView(ViewType::kPerspective, {0, 1, 0}, {0, 0, 1}, {60.0, 45.0}, w, h));
  const double th = std::tan(degToRad(30.0)), tv = std::tan(degToRad(22.5));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double sx = (2.0 * i + 1.0) / w - 1.0, sy = 1.0 - (2.0 * j + 1.0) / h;
      const Vec3 want = glm::normalize(Vec3(sx * th, 1.0, sy * tv));
      const auto got = cam.pixelDirection(i, j);
      ASSERT_TRUE(got);
      EXPECT_NEAR(glm::length(*got - want), 0.0, 1e-12) << i << "," << j;
      // And back: the direction lands on the pixel centre.
      const auto p = cam.project(*got);
      ASSERT_TRUE(p);
      EXPECT_NEAR(p->x, i + 0.5, 1e-9);
      EXPECT_NEAR(p->y, j + 0.5, 1e-9);
    }
  // The image's corners are the field of view's corners; behind the camera projects nowhere.
  EXPECT_NEAR(glm::length(*cam.direction(w, 0) - glm::normalize(Vec3(th, 1.0, tv))), 0.0, 1e-12);
  EXPECT_FALSE(cam.project({0, -1, 0}));
}

// Equiangular fisheye looking straight up with north (+Y) at the top of the image: the angle from
// the zenith is 90° × (distance from the centre / radius); seen from below, as any picture of the
// sky, east is on the left (right = direction × up = −X).
TEST(Camera, FisheyeIsEquiangular) {
  const int n = 64;
  const Camera cam(makeView(ViewType::kFisheye, {0, 0, 1}, {0, 1, 0}, {180.0, 180.0}, n, n));
  int inside = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double dx = (i + 0.5) - n / 2.0, dy = n / 2.0 - (j + 0.5);
      const double r = std::hypot(dx, dy) / (n / 2.0);
      const auto d = cam.pixelDirection(i, j);
      if (r > 1.0) {
        EXPECT_FALSE(d) << "outside the circle " << i << "," << j;
        continue;
      }
      ++inside;
      ASSERT_TRUE(d);
      const double zenithDeg = 90.0 * r;
      EXPECT_NEAR(radToDeg(std::acos(std::clamp(d->z, -1.0, 1.0))), zenithDeg, 1e-9);
      if (r > 0.0) {
        // Azimuth on the image mirrors the world's: image right is west (−X), image up north.
        EXPECT_NEAR(std::atan2(d->y, -d->x), std::atan2(dy, dx), 1e-9);
      }
      const auto p = cam.project(*d);
      ASSERT_TRUE(p);
      EXPECT_NEAR(p->x, i + 0.5, 1e-9);
      EXPECT_NEAR(p->y, j + 0.5, 1e-9);
    }
  // π/4 of the square's pixels lie in the circle (3228 of 4096 for 64 × 64, by counting centres).
  EXPECT_NEAR(inside, kPi / 4 * n * n, 0.01 * n * n);
  // The rim is the horizon: the middle of the right edge looks west.
  EXPECT_NEAR(glm::length(*cam.direction(n, n / 2.0) - Vec3(-1, 0, 0)), 0.0, 1e-12);
}

// Σ ω over a 180° fisheye is the hemisphere's 2π and Σ ω cos θ is π (the cosine-weighted
// hemisphere). Pixels cut by the rim carry the error of the 4 × 4 subdivision; 0.3 % at 128 px.
TEST(Camera, FisheyePixelSolidAnglesCoverTheHemisphere) {
  const int n = 128;
  const Camera cam(makeView(ViewType::kFisheye, {0, 0, 1}, {0, 1, 0}, {180.0, 180.0}, n, n));
  double sum = 0.0, sumCos = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double w = cam.pixelSolidAngleSr(i, j);
      sum += w;
      if (const auto d = cam.pixelDirection(i, j)) sumCos += w * d->z;
    }
  EXPECT_NEAR(sum, 2.0 * kPi, 0.003 * 2.0 * kPi);
  EXPECT_NEAR(sumCos, kPi, 0.003 * kPi);
}

// A perspective image subtends the solid angle of a rectangular pyramid,
// 4 asin(sin(h/2) sin(v/2)).
TEST(Camera, PerspectivePixelSolidAnglesSumToThePyramid) {
  const int w = 80, h = 50;
  const Camera cam(makeView(ViewType::kPerspective, {1, 1, 0}, {0, 0, 1}, {90.0, 60.0}, w, h));
  double sum = 0.0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) sum += cam.pixelSolidAngleSr(i, j);
  const double want = 4.0 * std::asin(std::sin(degToRad(45.0)) * std::sin(degToRad(30.0)));
  EXPECT_NEAR(sum, want, 1e-4 * want);
}

// The frame is right-handed with the image's up as close to `up` as the view allows.
TEST(Camera, FrameFollowsDirectionAndUp) {
  const Camera cam(makeView(ViewType::kPerspective, {0, 1, -1}, {0, 0, 1}, {60.0, 45.0}, 4, 4));
  EXPECT_NEAR(glm::length(cam.right() - Vec3(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(cam.up() - glm::normalize(Vec3(0, 1, 1))), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(cam.right(), cam.up()), -cam.forward()), 1.0, 1e-12);
}

}  // namespace
}  // namespace candela
