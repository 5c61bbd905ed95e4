// The sensor responses of engine/response.h against their definitions: each is the mean of
// planar responses over its family of normals (cylindrical: every horizontal normal;
// semi-cylindrical: those within ±90° of the facing; hemispherical: the upper hemisphere, for
// light from above), integrates to W, and its warp draws directions with density w/W (the
// warp's Jacobian, by finite differences, against the density).
#include "engine/response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace candela {
namespace {

Vec3 fromAngles(double thetaDeg, double phiDeg) {
  const double t = degToRad(thetaDeg), p = degToRad(phiDeg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

const Vec3 kUp(0.0, 0.0, 1.0);
const Vec3 kFacing = glm::normalize(Vec3(1.0, 2.0, 0.0));

std::vector<Response> allResponses() {
  return {Response::planar(glm::normalize(Vec3(0.3, -0.2, 0.9))),
          {Quantity::kCylindrical, kUp, Vec3(1, 0, 0)},
          {Quantity::kSemiCylindrical, kUp, kFacing},
          {Quantity::kHemispherical, kUp, Vec3(1, 0, 0)}};
}

TEST(SolveXMinusSin, InvertsOverTheWholeRange) {
  for (int i = 0; i <= 2000; ++i) {
    const double m = kTwoPi * i / 2000.0;
    const double x = solveXMinusSin(m);
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, kTwoPi);
    EXPECT_NEAR(x - std::sin(x), m, 1e-13) << "m " << m;
  }
  // Near 0 relative accuracy matters: x³/6 (1 − x²/20 + x⁴/840) = m, the series of x − sin x.
  for (double m : {1e-15, 1e-12, 1e-9, 1e-6, 1e-4}) {
    const double x = solveXMinusSin(m), x2 = x * x;
    EXPECT_NEAR(x * x2 / 6.0 * (1.0 - x2 / 20.0 + x2 * x2 / 840.0), m, 1e-10 * m) << m;
  }
}

// The mean over `count` normals n(k) of max(0, n·d), by the midpoint rule.
template <class Normal>
double meanPlanar(const Vec3& d, int count, const Normal& normal) {
  double s = 0.0;
  for (int k = 0; k < count; ++k) s += std::max(0.0, glm::dot(normal((k + 0.5) / count), d));
  return s / count;
}

TEST(Response, CylindricalIsTheMeanOfVerticalPlanes) {
  const Response r{Quantity::kCylindrical, kUp, Vec3(1, 0, 0)};
  for (double theta : {0.0, 10.0, 45.0, 90.0, 130.0, 180.0})
    for (double phi : {0.0, 77.0, 200.0}) {
      const Vec3 d = fromAngles(theta, phi);
      const double mean = meanPlanar(d, 20000, [](double u) { return Vec3(std::cos(kTwoPi * u), std::sin(kTwoPi * u), 0.0); });
      EXPECT_NEAR(r.weight(d), mean, 1e-7) << theta << " " << phi;
      EXPECT_NEAR(r.weight(d), std::sin(degToRad(theta)) / kPi, 1e-15);
    }
}

TEST(Response, SemiCylindricalIsTheMeanOfPlanesFacingWithin90Degrees) {
  const Response r{Quantity::kSemiCylindrical, kUp, kFacing};
  const double f = std::atan2(kFacing.y, kFacing.x);
  for (double theta : {5.0, 60.0, 90.0, 150.0})
    for (double alphaDeg : {0.0, 45.0, 120.0, 180.0, -90.0}) {
      const Vec3 d = fromAngles(theta, radToDeg(f) + alphaDeg);
      const double mean = meanPlanar(d, 20000, [f](double u) {
        const double a = f + kPi * (u - 0.5);
        return Vec3(std::cos(a), std::sin(a), 0.0);
      });
      EXPECT_NEAR(r.weight(d), mean, 1e-7) << theta << " " << alphaDeg;
      EXPECT_NEAR(r.weight(d), std::sin(degToRad(theta)) * (1.0 + std::cos(degToRad(alphaDeg))) / kPi, 1e-15);
    }
}

TEST(Response, HemisphericalIsTheMeanOverUpperNormalsForLightFromAbove) {
  const Response r{Quantity::kHemispherical, kUp, Vec3(1, 0, 0)};
  // Normals uniform in solid angle over the upper hemisphere: n_z uniform in [0, 1], midpoints
  // of a 400 × 400 lattice in (n_z, φ).
  auto mean = [](const Vec3& d) {
    const int m = 400;
    double s = 0.0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const double z = (i + 0.5) / m, sz = std::sqrt(1.0 - z * z), p = kTwoPi * (j + 0.5) / m;
        s += std::max(0.0, glm::dot(Vec3(sz * std::cos(p), sz * std::sin(p), z), d));
      }
    return s / (m * m);
  };
  for (double theta : {0.0, 30.0, 60.0, 89.0}) {
    const Vec3 d = fromAngles(theta, 33.0);
    EXPECT_NEAR(r.weight(d), mean(d), 2e-5) << theta;
    EXPECT_NEAR(r.weight(d), 0.25 * (1.0 + std::cos(degToRad(theta))), 1e-15);
  }
  // Below the horizon the contract counts nothing (docs/quantities.md#definitions-as-responses).
  EXPECT_EQ(r.weight(fromAngles(91.0, 0.0)), 0.0);
  EXPECT_EQ(r.weight(fromAngles(180.0, 0.0)), 0.0);
}

TEST(Response, IntegratesToItsTotal) {
  // Midpoint rule over the sphere in (cos θ, φ): dω = d(cos θ) dφ.
  for (const Response& r : allResponses()) {
    const int m = 1000, n = 1000;
    double s = 0.0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) {
        const double z = -1.0 + 2.0 * (i + 0.5) / m, sz = std::sqrt(1.0 - z * z), p = kTwoPi * (j + 0.5) / n;
        s += r.weight(Vec3(sz * std::cos(p), sz * std::sin(p), z));
      }
    EXPECT_NEAR(s * 2.0 * kTwoPi / (m * n), r.integral(), 2e-5 * r.integral()) << static_cast<int>(r.kind);
  }
}

TEST(Response, WarpDrawsWithDensityWeightOverTotal) {
  // |∂d/∂u1 × ∂d/∂u2| is the solid angle per unit area of the square: 1/pdf.
  const double h = 1e-6;
  for (const Response& r : allResponses())
    for (int i = 1; i < 20; ++i)
      for (int j = 0; j < 20; ++j) {
        const double u1 = i / 20.0, u2 = (j + 0.37) / 20.0;
        const Vec3 d = r.sample(u1, u2);
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
        const Vec3 a = (r.sample(u1 + h, u2) - r.sample(u1 - h, u2)) / (2 * h);
        const Vec3 b = (r.sample(u1, u2 + h) - r.sample(u1, u2 - h)) / (2 * h);
        const double jacobian = glm::length(glm::cross(a, b));
        EXPECT_NEAR(jacobian * r.density(d), 1.0, 1e-5) << static_cast<int>(r.kind) << " u " << u1 << " " << u2;
      }
}

TEST(Response, WarpRunsFromTheAxisAndWrapsAround) {
  // u1 = 0 is the axis, φ wraps: u2 = 0 and 1 give the same direction (the strata's second
  // differences along φ wrap around); semi-cylindrical faces its facing at u2 = ½.
  for (const Response& r : allResponses()) {
    EXPECT_NEAR(glm::dot(r.sample(1e-9, 0.3), r.n), 1.0, 1e-4);
    const Vec3 a = r.sample(0.6, 0.0), b = r.sample(0.6, 1.0);
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-9);
  }
  const Response semi{Quantity::kSemiCylindrical, kUp, kFacing};
  const Vec3 d = semi.sample(0.5, 0.5);
  EXPECT_NEAR(glm::dot(d, kFacing), 1.0, 1e-9);
}

TEST(Response, MirroredWeighsTheReflectedDirection) {
  const Vec3 m = glm::normalize(Vec3(0.2, 1.0, 0.1));
  for (const Response& r : allResponses()) {
    const Response img = r.mirrored(m);
    for (double theta : {20.0, 80.0, 120.0}) {
      const Vec3 d = fromAngles(theta, 40.0), reflected = d - 2.0 * glm::dot(d, m) * m;
      EXPECT_NEAR(img.weight(d), r.weight(reflected), 1e-14);
    }
  }
}

}  // namespace
}  // namespace candela
