#include "photometry/sky_patches.h"

#include "base/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace candela {
namespace {

TEST(SkyPatches, Counts) {
  EXPECT_EQ(SkyPatches(1).skyPatchCount(), 145);  // Tregenza
  EXPECT_EQ(SkyPatches(1).count(), 146);          // Radiance's Ntbins/Nrbins with the ground
  EXPECT_EQ(SkyPatches(2).skyPatchCount(), 577);
  EXPECT_EQ(SkyPatches(4).skyPatchCount(), 2305);
  EXPECT_NEAR(SkyPatches(1).rowHeightRad(), degToRad(12.0), 1e-15);
}

TEST(SkyPatches, SolidAnglesSumToTwoPiAndCentresMapBack) {
  for (int n : {1, 2, 3, 6}) {
    const SkyPatches p(n);
    double sum = 0.0;
    for (int i = 1; i < p.count(); ++i) {
      sum += p.solidAngle(i);
      EXPECT_EQ(p.indexOf(p.centre(i)), i) << "n " << n << " patch " << i;
    }
    EXPECT_NEAR(sum, kTwoPi, 1e-12) << n;
    EXPECT_EQ(p.indexOf(p.centre(0)), 0);
    EXPECT_EQ(p.indexOf(Vec3(1, 0, -0.1)), 0);
  }
}

TEST(SkyPatches, LayoutFollowsTregenza) {
  const SkyPatches p(1);
  // Patch 1 is centred on north at 6 degrees altitude; patch 2 is 12 degrees clockwise (east).
  const Vec3 c1 = p.centre(1), c2 = p.centre(2);
  EXPECT_NEAR(c1.x, 0.0, 1e-15);
  EXPECT_NEAR(std::asin(c1.z), degToRad(6.0), 1e-12);
  EXPECT_NEAR(std::atan2(c2.x, c2.y), degToRad(12.0), 1e-12);
  EXPECT_EQ(p.indexOf(Vec3(0, 0, 1)), 145);
  EXPECT_EQ(p.indexOf(Vec3(0.0, 1.0, 0.001)), 1);
  EXPECT_EQ(p.indexOf(Vec3(-1e-3, 1.0, 0.001)), 1);  // just west of north still in patch 1
  // First patch of the second band (30 patches, 12..24 deg) is 31.
  EXPECT_EQ(p.indexOf(Vec3(0.0, std::cos(degToRad(18.0)), std::sin(degToRad(18.0)))), 31);
}

TEST(SkyPatches, PatchAreasByMonteCarlo) {
  // Uniform directions on the upper hemisphere: the fraction in each patch estimates
  // solidAngle / 2 pi. Check every Tregenza patch within 4 binomial standard errors.
  const SkyPatches p(1);
  std::vector<int> hits(p.count(), 0);
  Rng rng(5, 0);
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    const double z = rng.uniform(), az = kTwoPi * rng.uniform(), s = std::sqrt(1 - z * z);
    ++hits[p.indexOf(Vec3(s * std::sin(az), s * std::cos(az), z))];
  }
  for (int i = 1; i < p.count(); ++i) {
    const double q = p.solidAngle(i) / kTwoPi;
    EXPECT_NEAR(double(hits[i]) / n, q, 4.0 * std::sqrt(q * (1 - q) / n)) << i;
  }
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

TEST(SkyPatches, SamplesFallInTheirPatchAndCoverIt) {
  // Every sample lies in its own patch (indexOf), and the mean of z over a patch's samples matches
  // the mean of z over the patch computed from its altitude range (uniform in solid angle).
  for (int n : {1, 2}) {
    const SkyPatches p(n);
    for (int i = 0; i < p.count(); ++i) {
      double sumZ = 0.0;
      const int k = 16;
      for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) {
          const Vec3 d = p.sample(i, (a + 0.5) / k, (b + 0.5) / k);
          ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
          ASSERT_EQ(p.indexOf(d), i) << "patch " << i << " MF " << n;
          sumZ += d.z;
        }
      // For z uniform over [z0, z1] (Archimedes), the mean is the midpoint; the cap and the
      // ground follow from their solid angles: Ω = 2π (z1 − z0) for a full zone.
      const Vec3 lo = p.sample(i, 0.0, 0.5), hi = p.sample(i, 1.0 - 1e-12, 0.5);
      EXPECT_NEAR(sumZ / (k * k), 0.5 * (lo.z + hi.z), 1e-9) << "patch " << i;
    }
  }
}

}  // namespace
}  // namespace candela
