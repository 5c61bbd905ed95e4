// Cameras for [[view]]s: the projection from image positions to ray directions and back, and the
// solid angle of each pixel (docs/views.md documents both projections).
#pragma once

#include "base/math.h"

#include <optional>

namespace candela {

enum class ViewType { kPerspective, kFisheye };

// Where a camera stands and what it sees.
struct View {
  ViewType type = ViewType::kPerspective;
  Vec3 positionM{0.0};
  Vec3 direction{0.0, 1.0, 0.0};        // unit
  Vec3 up{0.0, 0.0, 1.0};               // unit
  Vec2 fovDeg{60.0, 45.0};              // horizontal, vertical full angles
  glm::ivec2 resolution{800, 600};      // pixels, width × height
};

// A pinhole camera at `position` looking along `forward`, with image x to `right` and image y
// (rows, top to bottom) against `up`.
//
// Image coordinates (px, py) are in pixels from the top-left corner of the image; pixel (i, j)
// covers [i, i+1) × [j, j+1) and its centre is (i + ½, j + ½). Normalised device coordinates are
// sx = 2 px / W − 1 (−1 left, +1 right) and sy = 1 − 2 py / H (−1 bottom, +1 top).
//
// - perspective: dir ∝ forward + sx tan(h/2) right + sy tan(v/2) up, h × v the full fields of
//   view (Radiance's -vtv);
// - fisheye, equiangular (equidistant, Radiance's -vta): the angle from the axis grows linearly
//   with the distance from the image centre, θ = √((sx h/2)² + (sy v/2)²), in the direction
//   atan2(sy v/2, sx h/2) on the image; a 180° × 180° square image holds the forward hemisphere
//   in its inscribed circle. Positions outside the ellipse sx² + sy² ≤ 1 have no ray.
class Camera {
 public:
  explicit Camera(const View& view);

  // Unit ray direction through image position (px, py) in pixels; nothing outside a fisheye's
  // circle.
  std::optional<Vec3> direction(double px, double py) const;
  // Unit direction through the centre of pixel (i, j).
  std::optional<Vec3> pixelDirection(int i, int j) const { return direction(i + 0.5, j + 0.5); }
  // Image position (pixels) where the world direction `dir` lands; nothing when it is behind a
  // perspective camera or outside the fisheye's field.
  std::optional<Vec2> project(const Vec3& dir) const;
  // Solid angle in sr seen by pixel (i, j): the exact integral of the projection's Jacobian over
  // the pixel, by 4 × 4 midpoint subdivision (exact to ~10⁻⁴ for 1° pixels); 0 outside the field.
  double pixelSolidAngleSr(int i, int j) const;

  const Vec3& position() const { return position_; }
  const Vec3& forward() const { return forward_; }
  const Vec3& right() const { return right_; }
  const Vec3& up() const { return up_; }
  int width() const { return width_; }
  int height() const { return height_; }
  ViewType type() const { return type_; }

 private:
  // Solid angle per unit image area (sr per pixel²) at image position (px, py); 0 outside.
  double solidAngleDensity(double px, double py) const;

  ViewType type_;
  Vec3 position_, forward_, right_, up_;
  int width_, height_;
  double halfH_, halfV_;        // half fields of view, radians
  double tanHalfH_, tanHalfV_;  // perspective
};

}  // namespace candela
