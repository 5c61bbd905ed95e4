// Glare ratings against hand-computed cases. The reference numbers were computed separately (a
// few lines of Python with the published formulas: CIE 117-1995 eq. 1 for UGR, Wienold &
// Christoffersen 2006 eq. 7 for DGP, the Guth position index in the IES Lighting Handbook form
// quoted in the header) and are typed in here as literals, so a slip in the C++ shows.
#include "metrics/glare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace candela {
namespace {

Vec3 aboveLineOfSight(double sigmaDeg) { return {0.0, std::sin(degToRad(sigmaDeg)), std::cos(degToRad(sigmaDeg))}; }

TEST(Glare, GuthPositionIndexHandComputed) {
  EXPECT_DOUBLE_EQ(guthPositionIndex(0.0, 0.0), 1.0);   // on the line of sight
  EXPECT_DOUBLE_EQ(guthPositionIndex(60.0, 0.0), 1.0);
  // ln P = (35.2 − 0.31889 τ − 1.22 e^(−2τ/9))·10⁻³ σ + (21 + 0.26667 τ − 0.002963 τ²)·10⁻⁵ σ²
  EXPECT_NEAR(guthPositionIndex(0.0, 21.80140948635181), 2.3178156222617936, 1e-12);
  EXPECT_NEAR(guthPositionIndex(45.0, 30.0), 2.383327244698465, 1e-12);
  EXPECT_NEAR(guthPositionIndex(90.0, 45.0), 2.049806707923092, 1e-12);
}

TEST(Glare, PositionIndexAboveAndBelowTheLineOfSight) {
  // Straight above the line of sight: τ = 0.
  EXPECT_NEAR(positionIndex(aboveLineOfSight(21.80140948635181)), 2.3178156222617936, 1e-12);
  // To the side at eye level: τ = 90°.
  EXPECT_NEAR(positionIndex({std::sin(degToRad(45.0)), 0.0, std::cos(degToRad(45.0))}), 2.049806707923092, 1e-12);
  // Mirror images left and right have the same index.
  const Vec3 d = glm::normalize(Vec3(0.3, 0.2, 1.0));
  EXPECT_DOUBLE_EQ(positionIndex(d), positionIndex({-d.x, d.y, d.z}));
  // Below: Iwata, P = 1 + 0.8 R/D (R/D < 0.6) or 1 + 1.2 R/D, R/D = tan σ.
  EXPECT_NEAR(positionIndex({0.0, -std::sin(degToRad(20.0)), std::cos(degToRad(20.0))}),
              1.0 + 0.8 * std::tan(degToRad(20.0)), 1e-12);
  EXPECT_NEAR(positionIndex({0.0, -std::sin(degToRad(40.0)), std::cos(degToRad(40.0))}),
              1.0 + 1.2 * std::tan(degToRad(40.0)), 1e-12);
  // Behind the observer: the cap.
  EXPECT_DOUBLE_EQ(positionIndex({0.0, 0.0, -1.0}), 16.0);
}

// A Lambertian 600 × 600 mm panel (I = 1000 cos γ cd, so L = 1000/0.36 cd/m² from every
// direction) 1.6 m above the eye and 4 m ahead along the line of sight; Lb = 40 cd/m².
// σ = atan(1.6/4) = 21.80°, τ = 0: P = 2.31782; ω = 0.36 cos γ / d² = 0.0072037 sr;
// UGR = 8 log10(0.25/40 · L² ω / P²) = 14.4854.
TEST(Glare, UgrOfOnePanelHandComputed) {
  const double d2 = 16.0 + 1.6 * 1.6, cosG = 1.6 / std::sqrt(d2);
  GlareSource s;
  s.luminanceCdM2 = 1000.0 / 0.36;
  s.solidAngleSr = 0.36 * cosG / d2;
  EXPECT_NEAR(s.solidAngleSr, 0.007203698463764941, 1e-15);
  s.positionIndex = positionIndex(glm::normalize(Vec3(0.0, 1.6, 4.0)));
  EXPECT_NEAR(unifiedGlareRating(40.0, {s}), 14.485382159784272, 1e-9);
  // L = 10⁴ cd/m², ω = 0.01 sr on the line of sight, Lb = 40: 8 log10(6250) = 30.3670.
  EXPECT_NEAR(unifiedGlareRating(40.0, {{1e4, 0.01, 1.0}}), 30.367040138752603, 1e-9);
}

TEST(Glare, UgrGrowsByEightLogOfTheNumberOfIdenticalSources) {
  const GlareSource s{3000.0, 0.005, 1.7};
  const double one = unifiedGlareRating(30.0, {s});
  EXPECT_NEAR(unifiedGlareRating(30.0, std::vector<GlareSource>(10, s)), one + 8.0, 1e-9);
  EXPECT_NEAR(unifiedGlareRating(30.0, std::vector<GlareSource>(4, s)), one + 8.0 * std::log10(4.0), 1e-9);
  EXPECT_TRUE(std::isinf(unifiedGlareRating(30.0, {})));
}

// Ev = 2000 lx, one source of 10⁴ cd/m² and 0.01 sr on the line of sight:
// DGP = 5.87e-5·2000 + 9.18e-2 log10(1 + 10⁸·0.01/2000^1.87) + 0.16 = 0.297882 (no low-light
// correction above 1000 lx).
TEST(Glare, DgpHandComputed) {
  EXPECT_NEAR(daylightGlareProbability(2000.0, {{1e4, 0.01, 1.0}}), 0.2978821943925489, 1e-12);
  // Without sources only the saturation term remains.
  EXPECT_NEAR(daylightGlareProbability(3000.0, {}), 5.87e-5 * 3000.0 + 0.16, 1e-12);
  // Capped at 1.
  EXPECT_DOUBLE_EQ(daylightGlareProbability(20000.0, {{1e9, 0.01, 1.0}}), 1.0);
}

// Wienold's low-light correction e^(0.024 Ev − 4)/(1 + e^(0.024 Ev − 4)): 0.960834 at 300 lx,
// 0.975398 at 320 lx, none from 1000 lx (evalglare's limit).
TEST(Glare, LowLightCorrection) {
  EXPECT_NEAR(lowLightCorrection(300.0), 0.9608342772032357, 1e-12);
  EXPECT_NEAR(lowLightCorrection(320.0), 0.9753975715972606, 1e-12);
  EXPECT_DOUBLE_EQ(lowLightCorrection(1000.0), 1.0);
  EXPECT_NEAR(daylightGlareProbability(300.0, {}, true), (5.87e-5 * 300.0 + 0.16) * 0.9608342772032357, 1e-12);
  EXPECT_NEAR(daylightGlareProbability(300.0, {}, false), 5.87e-5 * 300.0 + 0.16, 1e-12);
}

// A 180° equiangular fisheye image written out here (independently of engine/camera): pixel
// (i, j) at angular offsets a = sx·90°, b = sy·90°, θ = √(a² + b²), solid angle
// (sin θ / θ)(Δa Δb).
struct Fisheye {
  int n;
  std::vector<Vec3> dir;
  std::vector<double> omega;
  explicit Fisheye(int size) : n(size), dir(size * size), omega(size * size, 0.0) {
    const double step = kPi / n;  // radians per pixel
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = (i + 0.5 - n / 2.0) * step, b = (n / 2.0 - j - 0.5) * step;
        const double theta = std::hypot(a, b);
        if (theta > kPi / 2) continue;
        const double s = theta > 0 ? std::sin(theta) / theta : 1.0;
        dir[j * n + i] = {s * a, s * b, std::cos(theta)};
        omega[j * n + i] = s * step * step;
      }
  }
  PixelGeometry geometry() const {
    return [this](std::size_t i, Vec3& d, double& o) {
      d = dir[i];
      o = omega[i];
    };
  }
};

// Uniform luminance Lb everywhere: Ev = π Lb and no glare source (nothing exceeds 5 × the mean).
// With a bright disc of angular radius 10° on the line of sight: Ev = π Lb + (Ls − Lb) π sin²10°,
// one source of ω = 2π(1 − cos 10°) with P ≈ 1. Pixelisation (256 px across 180°) limits the
// agreement to about 1 % of ω; the DGP then agrees to 0.002.
TEST(Glare, DgpFromAFisheyeImage) {
  const Fisheye f(256);
  const double lb = 100.0, ls = 50000.0, r = degToRad(10.0);
  std::vector<float> lum(f.dir.size(), static_cast<float>(lb));
  ImageGlare g = evaluateImageGlare(lum, f.geometry(), f.n, f.n);
  EXPECT_NEAR(g.verticalIlluminanceLux, kPi * lb, 0.003 * kPi * lb);
  EXPECT_TRUE(g.sources.empty());
  EXPECT_NEAR(g.dgpUncorrected, 5.87e-5 * g.verticalIlluminanceLux + 0.16, 1e-12);
  EXPECT_NEAR(g.dgp, g.dgpUncorrected * lowLightCorrection(g.verticalIlluminanceLux), 1e-12);

  for (std::size_t i = 0; i < lum.size(); ++i)
    if (f.omega[i] > 0.0 && f.dir[i].z > std::cos(r)) lum[i] = static_cast<float>(ls);
  g = evaluateImageGlare(lum, f.geometry(), f.n, f.n);
  const double ev = kPi * lb + (ls - lb) * kPi * std::sin(r) * std::sin(r);
  const double omega = kTwoPi * (1.0 - std::cos(r));
  std::printf("[ measured ] fisheye disc: Ev %.2f lx (closed form %.2f), source %.5f sr (closed form %.5f)\n",
              g.verticalIlluminanceLux, ev, g.sources.empty() ? 0.0 : g.sources[0].solidAngleSr, omega);
  EXPECT_NEAR(g.verticalIlluminanceLux, ev, 0.01 * ev);
  ASSERT_EQ(g.sources.size(), 1u);
  EXPECT_NEAR(g.sources[0].solidAngleSr, omega, 0.01 * omega);
  EXPECT_NEAR(g.sources[0].luminanceCdM2, ls, 1e-9 * ls);
  EXPECT_NEAR(g.sources[0].positionIndex, 1.0, 1e-6);
  const double want = daylightGlareProbability(ev, {{ls, omega, 1.0}});
  EXPECT_NEAR(g.dgp, want, 0.002);
  // A fixed threshold above the disc finds nothing.
  GlareDetection fixed;
  fixed.thresholdCdM2 = 60000.0;
  EXPECT_TRUE(evaluateImageGlare(lum, f.geometry(), f.n, f.n, fixed).sources.empty());
}

// Two separate bright patches are two sources, each with its own position index.
TEST(Glare, SeparatePatchesAreSeparateSources) {
  const Fisheye f(64);
  std::vector<float> lum(f.dir.size(), 50.0f);
  lum[20 * 64 + 20] = lum[20 * 64 + 21] = 1e5;
  lum[40 * 64 + 45] = 1e5;
  const ImageGlare g = evaluateImageGlare(lum, f.geometry(), f.n, f.n);
  ASSERT_EQ(g.sources.size(), 2u);
  EXPECT_NEAR(g.sources[0].solidAngleSr, f.omega[20 * 64 + 20] + f.omega[20 * 64 + 21], 1e-15);
  EXPECT_NEAR(g.sources[1].positionIndex, positionIndex(f.dir[40 * 64 + 45]), 1e-12);
}

}  // namespace
}  // namespace candela
