#include "engine/camera.h"

#include <algorithm>
#include <cmath>

namespace candela {

Camera::Camera(const View& view)
    : type_(view.type),
      position_(view.positionM),
      width_(std::max(1, view.resolution.x)),
      height_(std::max(1, view.resolution.y)) {
  forward_ = glm::normalize(view.direction);
  right_ = glm::normalize(glm::cross(forward_, view.up));
  up_ = glm::cross(right_, forward_);
  halfH_ = 0.5 * degToRad(view.fovDeg.x);
  halfV_ = 0.5 * degToRad(view.fovDeg.y);
  tanHalfH_ = std::tan(halfH_);
  tanHalfV_ = std::tan(halfV_);
}

std::optional<Vec3> Camera::direction(double px, double py) const {
  const double sx = 2.0 * px / width_ - 1.0, sy = 1.0 - 2.0 * py / height_;
  if (type_ == ViewType::kPerspective)
    return glm::normalize(forward_ + sx * tanHalfH_ * right_ + sy * tanHalfV_ * up_);
  if (sx * sx + sy * sy > 1.0) return std::nullopt;
  const double a = sx * halfH_, b = sy * halfV_;
  const double theta = std::sqrt(a * a + b * b);
  if (theta > kPi) return std::nullopt;
  if (theta == 0.0) return forward_;
  const double s = std::sin(theta) / theta;
  return glm::normalize(std::cos(theta) * forward_ + s * (a * right_ + b * up_));
}

std::optional<Vec2> Camera::project(const Vec3& dirIn) const {
  const Vec3 d = glm::normalize(dirIn);
  const double z = glm::dot(d, forward_), x = glm::dot(d, right_), y = glm::dot(d, up_);
  double sx, sy;
  if (type_ == ViewType::kPerspective) {
    if (z <= 0.0) return std::nullopt;
    sx = x / z / tanHalfH_;
    sy = y / z / tanHalfV_;
  } else {
    const double theta = std::atan2(std::sqrt(x * x + y * y), z);
    const double r = std::sqrt(x * x + y * y);
    const double a = r > 0.0 ? theta * x / r : 0.0, b = r > 0.0 ? theta * y / r : 0.0;
    sx = a / halfH_;
    sy = b / halfV_;
    if (sx * sx + sy * sy > 1.0) return std::nullopt;
  }
  return Vec2(0.5 * (sx + 1.0) * width_, 0.5 * (1.0 - sy) * height_);
}

double Camera::solidAngleDensity(double px, double py) const {
  const double sx = 2.0 * px / width_ - 1.0, sy = 1.0 - 2.0 * py / height_;
  if (type_ == ViewType::kPerspective) {
    // Image plane at distance 1: dΩ = dx dy / (1 + x² + y²)^{3/2}.
    const double x = sx * tanHalfH_, y = sy * tanHalfV_;
    const double jac = (2.0 * tanHalfH_ / width_) * (2.0 * tanHalfV_ / height_);
    return jac / std::pow(1.0 + x * x + y * y, 1.5);
  }
  if (sx * sx + sy * sy > 1.0) return 0.0;
  // Equidistant: angular coordinates (a, b) are polar (θ, φ) with area θ dθ dφ, while
  // dΩ = sin θ dθ dφ, so dΩ = (sin θ / θ) da db.
  const double a = sx * halfH_, b = sy * halfV_;
  const double theta = std::sqrt(a * a + b * b);
  if (theta > kPi) return 0.0;
  const double ratio = theta > 1e-12 ? std::sin(theta) / theta : 1.0;
  return ratio * (2.0 * halfH_ / width_) * (2.0 * halfV_ / height_);
}

double Camera::pixelSolidAngleSr(int i, int j) const {
  constexpr int kSub = 4;
  double sum = 0.0;
  for (int a = 0; a < kSub; ++a)
    for (int b = 0; b < kSub; ++b) sum += solidAngleDensity(i + (a + 0.5) / kSub, j + (b + 0.5) / kSub);
  return sum / (kSub * kSub);
}

}  // namespace candela
