// Closed forms of the light sources against independent computations.
#include "engine/lights.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

// Lambert's formula on an N-gon inscribed in the disk converges to the disk as 1/N²; 4096 sides
// leave a relative error ~ (2π/4096)²/6 ≈ 4e-7, far below the 1e-5 asserted.
double diskByPolygon(double R, const Vec3& p, const Vec3& n) {
  std::vector<Vec3> poly;
  const int sides = 4096;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * kPi * k / sides;
    poly.push_back({R * std::cos(a), R * std::sin(a), 0.0});
  }
  return polygonProjectedSolidAngle(poly, p, n);
}

TEST(Lights, DiskVectorIrradianceMatchesLambertOnAFinePolygonOffAxis) {
  const double R = 0.6;
  for (const Vec3 p : {Vec3(0.0, 0.0, -1.0), Vec3(0.4, 0.0, -0.8), Vec3(1.5, -0.7, -0.5), Vec3(0.2, 0.3, -0.1)}) {
    for (const Vec3 n : {Vec3(0, 0, 1), glm::normalize(Vec3(0.3, 0.0, 1.0)), glm::normalize(Vec3(-0.2, 0.5, 1.0))}) {
      // Only configurations with the whole disk above the receiver's horizon.
      if (glm::dot(-p, n) < R * std::sqrt(1.0 - n.z * n.z)) continue;
      Scene sc;
      Material m;
      m.type = MaterialType::kLight;
      m.color = Rgb(1.0);
      sc.addRing({0, 0, 0}, {0, 0, -1}, 0.0, R, sc.addMaterial(m));
      const std::vector<Light> lights = collectLights(sc);
      Rgb e;
      ASSERT_TRUE(unoccludedIrradiance(lights[0], sc, p, n, e));
      const double want = diskByPolygon(R, p, n);
      EXPECT_NEAR(e.x, want, 1e-5 * want) << "p=(" << p.x << "," << p.y << "," << p.z << ")";
    }
  }
}

TEST(Lights, AnnulusIsOuterDiskMinusInnerDisk) {
  Scene sc;
  Material m;
  m.type = MaterialType::kLight;
  m.color = Rgb(2.0);
  sc.addRing({0, 0, 0}, {0, 0, -1}, 0.2, 0.5, sc.addMaterial(m));
  const std::vector<Light> lights = collectLights(sc);
  const Vec3 p(0.3, 0.1, -0.9), n(0, 0, 1);
  Rgb e;
  ASSERT_TRUE(unoccludedIrradiance(lights[0], sc, p, n, e));
  const double want = 2.0 * (diskByPolygon(0.5, p, n) - diskByPolygon(0.2, p, n));
  EXPECT_NEAR(e.x, want, 1e-5 * want);
}

TEST(Lights, NoClosedFormForADiskAcrossTheHorizon) {
  Scene sc;
  Material m;
  m.type = MaterialType::kLight;
  m.color = Rgb(1.0);
  sc.addRing({0, 0, 0}, {0, 0, -1}, 0.0, 0.5, sc.addMaterial(m));
  const std::vector<Light> lights = collectLights(sc);
  Rgb e;
  EXPECT_FALSE(unoccludedIrradiance(lights[0], sc, Vec3(0, 0, -1), Vec3(1, 0, 0), e));
}

}  // namespace
}  // namespace candela
