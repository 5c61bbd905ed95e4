#include "photometry/luminous_opening.h"

#include <algorithm>
#include <cmath>

namespace candela {

double projectedOpeningAreaM2(const PhotometricInfo& info, const Vec3& dirLocal) {
  const Vec3 d = glm::normalize(dirLocal);
  const double w = info.openingWidthM, l = info.openingLengthM, h = info.openingHeightM;
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  const double horizontal = std::sqrt(d.x * d.x + d.y * d.y);
  switch (info.openingShape) {
    case OpeningShape::kPoint:
      return 0.0;
    case OpeningShape::kRectangular:
    case OpeningShape::kOther:
      return w * l * az;
    case OpeningShape::kRectangularWithSides:
      // The bottom and one face of each pair of sides: the face normal to X is l × h, to Y w × h.
      return w * l * az + l * h * ax + w * h * ay;
    case OpeningShape::kCircular:
      return 0.25 * kPi * w * w * az;
    case OpeningShape::kEllipse:
      return 0.25 * kPi * w * l * az;
    case OpeningShape::kVerticalCylinder:
      return 0.25 * kPi * w * w * az + w * h * horizontal;
    case OpeningShape::kVerticalEllipticalCylinder:
      // Side: the ellipse's width across the horizontal direction (semi-axes w/2 along X, l/2
      // along Y) times the height, times the horizontal part of d: h · 2 √((w/2 dy)² + (l/2 dx)²).
      return 0.25 * kPi * w * l * az + h * std::sqrt(w * w * d.y * d.y + l * l * d.x * d.x);
    case OpeningShape::kSphere:
      return 0.25 * kPi * w * w;
    case OpeningShape::kEllipsoid: {
      const double a = 0.5 * w, b = 0.5 * l, c = 0.5 * h;
      return kPi * std::sqrt(b * c * b * c * d.x * d.x + a * c * a * c * d.y * d.y + a * b * a * b * d.z * d.z);
    }
    case OpeningShape::kHorizontalCylinderAlongWidth:
      // Axis X, length w, diameter l: the side w·l·sin(angle to the axis) plus one end disc.
      return w * l * std::sqrt(std::max(0.0, 1.0 - d.x * d.x)) + 0.25 * kPi * l * l * ax;
    case OpeningShape::kHorizontalCylinderAlongLength:
      return l * w * std::sqrt(std::max(0.0, 1.0 - d.y * d.y)) + 0.25 * kPi * w * w * ay;
    case OpeningShape::kVerticalCircle:
    case OpeningShape::kVerticalEllipse:
      // LM-63-2019: a width (and no length) faces C0 (normal X); a length faces C90 (normal Y).
      return w > 0.0 ? 0.25 * kPi * w * h * ax : 0.25 * kPi * l * h * ay;
  }
  return 0.0;
}

bool hasLuminousArea(const PhotometricInfo& info) {
  return projectedOpeningAreaM2(info, Vec3(1.0, 1.0, -1.0)) > 0.0;
}

}  // namespace candela
