// Sample warps against the integrals their densities promise. Every Monte Carlo check uses
// independent uniform (u1, u2) and asserts within 4 standard errors, the standard error being the
// sample standard deviation over √n (a false alarm at 4σ has probability ~6e-5 per check, and
// the seeds are fixed, so a pass is reproducible).
#include "engine/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace candela {
namespace {

struct Mean {
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  void add(double x) {
    sum += x;
    sum2 += x * x;
    ++n;
  }
  double mean() const { return sum / n; }
  double standardError() const {
    const double m = mean();
    return std::sqrt(std::max(0.0, sum2 / n - m * m) / (n - 1));
  }
};

// Asserts that the mean of f over n uniform (u1, u2) pairs is `want` within 4 standard errors
// (and that the error is not zero, which would make the check vacuous unless f is constant).
void expectMean(const std::function<double(double, double)>& f, double want, int n, uint64_t stream,
                const char* what) {
  Rng rng(2024, stream);
  Mean m;
  for (int i = 0; i < n; ++i) {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    m.add(f(u1, u2));
  }
  EXPECT_NEAR(m.mean(), want, 4.0 * m.standardError()) << what << " (n = " << n << ", se = " << m.standardError()
                                                       << ")";
}

constexpr int kN = 200000;

TEST(Sampling, CosineHemisphereIsUnitAndUpward) {
  Rng rng(1, 0);
  for (int i = 0; i < 10000; ++i) {
    const Vec3 d = sampleCosineHemisphere(rng.uniform(), rng.uniform());
    EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
    EXPECT_GE(d.z, 0.0);
  }
  // The corners of the unit square map to the pole and the horizon.
  EXPECT_NEAR(sampleCosineHemisphere(0.0, 0.3).z, 1.0, 1e-15);
  EXPECT_NEAR(sampleCosineHemisphere(1.0, 0.3).z, 0.0, 1e-15);
}

// pdf = cos θ / π. E[cos θ] = ∫ cos² θ / π dω = 2/3.
TEST(Sampling, CosineHemisphereMeanCosineIsTwoThirds) {
  expectMean([](double a, double b) { return sampleCosineHemisphere(a, b).z; }, 2.0 / 3.0, kN, 1, "E[cos θ]");
}

// The pdf integrates to one over the cap θ < 60°: ∫ dω = 2π(1 − cos 60°) = π, estimated as the
// mean of 1{θ < 60°}/pdf = π / cos θ (bounded on the cap, so the variance is finite; 1/pdf over
// the whole hemisphere would have infinite variance).
TEST(Sampling, CosineHemisphereSolidAngleOfCap) {
  expectMean(
      [](double a, double b) {
        const double c = sampleCosineHemisphere(a, b).z;
        return c > 0.5 ? kPi / c : 0.0;
      },
      kPi, kN, 2, "cap solid angle");
  // Fraction in the cap: ∫ cos θ/π dω over θ < θ0 = sin² θ0 = 3/4.
  expectMean([](double a, double b) { return sampleCosineHemisphere(a, b).z > 0.5 ? 1.0 : 0.0; }, 0.75, kN, 3,
             "cap probability");
  // Isotropic in azimuth: E[x] = E[y] = 0, E[x²] = E[y²] = (1 − E[z²]) / 2 = 1/4.
  expectMean([](double a, double b) { return sampleCosineHemisphere(a, b).x; }, 0.0, kN, 4, "E[x]");
  expectMean([](double a, double b) { return std::pow(sampleCosineHemisphere(a, b).y, 2); }, 0.25, kN, 5, "E[y²]");
}

// pdf = 1 / (2π(1 − cosMax)) over the cone. ∫ cos θ dω over the cone = π(1 − cosMax²) is
// estimated as the mean of cos θ / pdf; E[cos θ] = (1 + cosMax)/2 (cos θ uniform on [cosMax, 1]).
TEST(Sampling, UniformConeIntegratesCosine) {
  for (double halfDeg : {0.265, 5.0, 30.0, 90.0, 150.0}) {
    const double cosMax = std::cos(degToRad(halfDeg));
    const double omega = kTwoPi * (1.0 - cosMax);
    Rng rng(3, 0);
    for (int i = 0; i < 2000; ++i) {
      const Vec3 d = sampleUniformCone(rng.uniform(), rng.uniform(), cosMax);
      ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
      ASSERT_GE(d.z, cosMax - 1e-12);
    }
    expectMean([&](double a, double b) { return sampleUniformCone(a, b, cosMax).z * omega; },
               kPi * (1.0 - cosMax * cosMax), kN, 10, "∫ cos dω over the cone");
    expectMean([&](double a, double b) { return sampleUniformCone(a, b, cosMax).z; }, 0.5 * (1.0 + cosMax), kN, 11,
               "E[cos θ] in the cone");
    // Uniform in solid angle: the inner cap of half the solid angle holds half the samples.
    const double cosHalf = 1.0 - 0.5 * (1.0 - cosMax);
    expectMean([&](double a, double b) { return sampleUniformCone(a, b, cosMax).z > cosHalf ? 1.0 : 0.0; }, 0.5, kN,
               12, "half-solid-angle cap");
  }
}

TEST(Sampling, TriangleIsUniform) {
  const Vec3 a(0.2, -1.0, 3.0), b(2.5, 0.5, 3.5), c(-0.5, 1.5, 2.0);
  const Vec3 centroid = (a + b + c) / 3.0;
  const Vec3 n = glm::cross(b - a, c - a);
  Rng rng(4, 0);
  for (int i = 0; i < 10000; ++i) {
    const Vec3 p = sampleTriangle(a, b, c, rng.uniform(), rng.uniform());
    // Barycentric coordinates (signed sub-areas) all in [0, 1].
    const double n2 = glm::dot(n, n);
    const double wa = glm::dot(glm::cross(b - p, c - p), n) / n2;
    const double wb = glm::dot(glm::cross(c - p, a - p), n) / n2;
    ASSERT_GE(wa, -1e-12);
    ASSERT_GE(wb, -1e-12);
    ASSERT_LE(wa + wb, 1.0 + 1e-12);
  }
  for (int k = 0; k < 3; ++k)
    expectMean([&](double u, double v) { return sampleTriangle(a, b, c, u, v)[k]; }, centroid[k], kN, 20 + k,
               "mean position = centroid");
  // The medial triangle (midpoints of the edges) holds a quarter of the area.
  const Vec3 mab = 0.5 * (a + b), mbc = 0.5 * (b + c), mca = 0.5 * (c + a);
  const Vec3 nm = glm::cross(mbc - mab, mca - mab);
  auto inMedial = [&](const Vec3& p) {
    return glm::dot(glm::cross(mbc - mab, p - mab), nm) >= 0 && glm::dot(glm::cross(mca - mbc, p - mbc), nm) >= 0 &&
           glm::dot(glm::cross(mab - mca, p - mca), nm) >= 0;
  };
  expectMean([&](double u, double v) { return inMedial(sampleTriangle(a, b, c, u, v)) ? 1.0 : 0.0; }, 0.25, kN, 24,
             "medial triangle");
}

// Uniform in area on r0 ≤ r ≤ r1: E[r²] = (r0² + r1²)/2; the quadrant φ ∈ [0, π/2) holds 1/4.
TEST(Sampling, AnnulusIsUniform) {
  for (const auto& radii : {std::pair{0.0, 1.0}, std::pair{0.4, 0.5}, std::pair{1.0, 3.0}}) {
    // Plain copies, not a structured binding: clang 14 (the sanitizer build) cannot capture
    // structured bindings in the lambdas below.
    const double r0 = radii.first, r1 = radii.second;
    Rng rng(5, 0);
    for (int i = 0; i < 10000; ++i) {
      const double r = glm::length(sampleAnnulus(r0, r1, rng.uniform(), rng.uniform()));
      ASSERT_GE(r, r0 - 1e-12);
      ASSERT_LE(r, r1 + 1e-12);
    }
    expectMean([&](double u, double v) { return glm::dot(sampleAnnulus(r0, r1, u, v), sampleAnnulus(r0, r1, u, v)); },
               0.5 * (r0 * r0 + r1 * r1), kN, 30, "E[r²]");
    expectMean(
        [&](double u, double v) {
          const Vec2 q = sampleAnnulus(r0, r1, u, v);
          return q.x >= 0.0 && q.y >= 0.0 ? 1.0 : 0.0;
        },
        0.25, kN, 31, "quadrant");
    // Inner half of the area: r² below the mean of r0², r1².
    expectMean(
        [&](double u, double v) {
          const Vec2 q = sampleAnnulus(r0, r1, u, v);
          return glm::dot(q, q) < 0.5 * (r0 * r0 + r1 * r1) ? 1.0 : 0.0;
        },
        0.5, kN, 32, "inner half area");
  }
}

// For n = nx·ny the strata form an nx × ny grid (ny ≈ √(n / aspect)) with exactly one sample
// per cell; every sample is in [0, 1)².
void expectOnePerStratum(int n, double aspect, int nx, int ny) {
  ASSERT_EQ(nx * ny, n);
  const Strata2D strata(n, aspect);
  ASSERT_EQ(strata.size(), n);
  for (uint64_t stream = 0; stream < 20; ++stream) {
    Rng rng(6, stream);
    std::vector<int> count(static_cast<size_t>(n), 0);
    for (int i = 0; i < n; ++i) {
      const Vec2 s = strata.sample(i, rng);
      ASSERT_GE(s.x, 0.0);
      ASSERT_LT(s.x, 1.0);
      ASSERT_GE(s.y, 0.0);
      ASSERT_LT(s.y, 1.0);
      const int cx = static_cast<int>(s.x * nx), cy = static_cast<int>(s.y * ny);
      ++count[static_cast<size_t>(cx * ny + cy)];
    }
    for (int c = 0; c < n; ++c) ASSERT_EQ(count[static_cast<size_t>(c)], 1) << "n " << n << " cell " << c;
  }
}

TEST(Sampling, Strata2DOneSamplePerStratum) {
  expectOnePerStratum(16, 1.0, 4, 4);
  expectOnePerStratum(12, 1.0, 4, 3);
  expectOnePerStratum(1, 1.0, 1, 1);
  expectOnePerStratum(64, 1.0, 8, 8);
  // Hemisphere strata (aspect 1/π): the φ axis gets ≈ π times more strata than the sin²θ axis.
  expectOnePerStratum(30, 1.0 / kPi, 3, 10);
  expectOnePerStratum(1008, 1.0 / kPi, 18, 56);
}

// When n is not a product nx·ny the remainder is drawn unstratified but still inside [0, 1)², and
// the estimate stays unbiased: E[u1] = E[u2] = 1/2 over whole sample sets.
TEST(Sampling, Strata2DRemainderSamplesStayInUnitSquare) {
  const Strata2D strata(2048, 1.0 / kPi);
  ASSERT_EQ(strata.size(), 2048);
  Mean mx, my;
  for (uint64_t stream = 0; stream < 50; ++stream) {
    Rng rng(7, stream);
    for (int i = 0; i < strata.size(); ++i) {
      const Vec2 s = strata.sample(i, rng);
      ASSERT_TRUE(s.x >= 0.0 && s.x < 1.0 && s.y >= 0.0 && s.y < 1.0) << i;
      mx.add(s.x);
      my.add(s.y);
    }
  }
  EXPECT_NEAR(mx.mean(), 0.5, 4.0 * mx.standardError());
  EXPECT_NEAR(my.mean(), 0.5, 4.0 * my.standardError());
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Regression: with n = 1 or 2 and the hemisphere aspect 1/π, √(nπ) rounded to more φ strata than
// samples, so a single continuation ray only ever took azimuths in [0, π) — a bias wherever the
// light is not symmetric about the normal (e.g. a room lit through one window: −9 % to −24 % of
// the interreflected light). For every n and both aspects, each coordinate must have mean 1/2
// and each half of the square in each direction must receive half of the samples.
TEST(Sampling, Strata2DCoversTheWholeSquareForEverySampleCount) {
  for (double aspect : {1.0, 1.0 / kPi}) {
    for (int n = 1; n <= 40; ++n) {
      const Strata2D strata(n, aspect);
      Mean mx, my;
      int upperY = 0, total = 0;
      for (uint64_t stream = 0; stream < 4000 / n + 50; ++stream) {
        Rng rng(11, stream);
        for (int i = 0; i < n; ++i) {
          const Vec2 s = strata.sample(i, rng);
          mx.add(s.x);
          my.add(s.y);
          upperY += s.y >= 0.5;
          ++total;
        }
      }
      EXPECT_NEAR(mx.mean(), 0.5, 4.0 * mx.standardError() + 1e-3) << "n " << n << " aspect " << aspect;
      EXPECT_NEAR(my.mean(), 0.5, 4.0 * my.standardError() + 1e-3) << "n " << n << " aspect " << aspect;
      // Binomial: the share in y >= 1/2 has standard error 0.5/√total at most.
      EXPECT_NEAR(static_cast<double>(upperY) / total, 0.5, 4.0 * 0.5 / std::sqrt(total)) << "n " << n;
    }
  }
}

}  // namespace
}  // namespace candela
