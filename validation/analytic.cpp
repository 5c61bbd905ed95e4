#include "validation/analytic.h"

#include <cmath>

namespace candela::analytic {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double sphereSource(double radiance, double radiusM, double distanceM, double cosTheta) {
  return kPi * radiance * radiusM * radiusM * cosTheta / (distanceM * distanceM);
}

double rectangleCorner(double radiance, double aM, double bM, double hM) {
  const double A = aM / hM, B = bM / hM;
  const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
  const double f = (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * kPi);
  return kPi * radiance * f;
}

double rectangleAbove(double radiance, const RectXY& r, double hM, double x, double y) {
  // Signed corner rectangles from the receiver's foot point to each corner.
  auto corner = [&](double cx, double cy) {
    const double a = cx - x, b = cy - y;
    const double s = (a < 0 ? -1.0 : 1.0) * (b < 0 ? -1.0 : 1.0);
    return s * rectangleCorner(radiance, std::abs(a), std::abs(b), hM);
  };
  return corner(r.x1, r.y1) - corner(r.x0, r.y1) - corner(r.x1, r.y0) + corner(r.x0, r.y0);
}

double coaxialDisk(double radiance, double radiusM, double hM) {
  return kPi * radiance * radiusM * radiusM / (radiusM * radiusM + hM * hM);
}

double uniformSky(double radiance) { return kPi * radiance; }

double sphereOnPlane(double rho, double skyRadiance, double radiusM, double xM, double hM, int n) {
  const double ox = xM, oz = hM - radiusM;  // receiver relative to the sphere's centre (0, 0, R)
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;  // sin²θ
    const double s = std::sqrt(u), c = std::sqrt(1.0 - u);
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / (2 * n);
      const double dx = s * std::cos(phi), dz = c;  // y does not enter: the receiver is at y = 0
      // Ray–sphere: |o + t d|² = R² with o = (ox, 0, oz).
      const double b = ox * dx + oz * dz;
      const double cc = ox * ox + oz * oz - radiusM * radiusM;
      const double disc = b * b - cc;
      double l = skyRadiance;
      if (disc > 0.0) {
        const double t = -b - std::sqrt(disc);
        if (t > 0.0) {
          const double nz = (oz + t * dz) / radiusM;
          l = rho * skyRadiance * 0.5 * (1.0 + nz);
        }
      }
      sum += l;
    }
  }
  return kPi * sum / (2.0 * n * n);
}

double overcastAperture(const double p[3], const double normal[3], const double c[3], const double u[3],
                        const double v[3], double eh, int n) {
  const double lz = 9.0 * eh / (7.0 * kPi);
  // Aperture normal and area from the edges.
  const double an[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double area = std::sqrt(an[0] * an[0] + an[1] * an[1] + an[2] * an[2]);
  const double cell = area / (static_cast<double>(n) * n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double a = (i + 0.5) / n, b = (j + 0.5) / n;
      double e[3];
      for (int k = 0; k < 3; ++k) e[k] = c[k] + a * u[k] + b * v[k] - p[k];
      const double r2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2], r = std::sqrt(r2);
      const double w[3] = {e[0] / r, e[1] / r, e[2] / r};
      const double cosI = normal[0] * w[0] + normal[1] * w[1] + normal[2] * w[2];
      if (w[2] <= 0.0 || cosI <= 0.0) continue;
      const double cosA = std::abs(an[0] * w[0] + an[1] * w[1] + an[2] * w[2]) / area;
      sum += lz * (1.0 + 2.0 * w[2]) / 3.0 * cosI * cosA / r2 * cell;
    }
  }
  return sum;
}

double integratingSphere(double directIrradiance, double rho) { return directIrradiance / (1.0 - rho); }

}  // namespace candela::analytic
