// The view's estimator (engine/render.h, irradianceSamples > 0) against closed forms where a
// single path per camera ray would be noise: the sky through thin glass is L·T(θ) in every pixel
// (both glass branches followed, not one chosen by roulette), a matte floor under a uniform sky
// seen through a window or in a mirror reads ρL in every pixel; and the standard error it
// reports for the image's mean luminance is the spread of that mean over seeds.
#include "engine/camera.h"
#include "engine/render.h"
#include "tests/support/test_views.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {
namespace {

constexpr double kSkyRadiance = 10.0;  // W/sr/m²: 1790 cd/m²

uint32_t addMaterial(Scene& sc, MaterialType type, double value, const char* name) {
  Material m;
  m.type = type;
  m.name = name;
  m.color = Rgb(value);
  return sc.addMaterial(m);
}

uint32_t addPlastic(Scene& sc, double rho) {
  Material m;
  m.type = MaterialType::kPlastic;
  m.name = "matte";
  m.color = Rgb(rho);
  m.diffuseReflectance = Rgb(rho);
  return sc.addMaterial(m);
}

View perspective(Vec3 pos, Vec3 dir, Vec3 up, Vec2 fov, int w, int h) {
  return test_support::makeView(ViewType::kPerspective, pos, dir, up, fov, w, h);
}
using test_support::kFloatRel;

// Thin glass's transmittance for unpolarised light at incidence cos θ, written out from Radiance's
// glass.c model (Fresnel reflectance r per polarisation at both faces, internal transmittance
// τ^(1/cos θt), incoherent multiple reflections): T = ½ Σ (1 − r)² τθ / (1 − r² τθ²).
double glassTransmittance(double cosI, double transmissivity, double n) {
  const double sinT = std::sqrt(1.0 - cosI * cosI) / n, cosT = std::sqrt(1.0 - sinT * sinT);
  const double rs = std::pow((cosI - n * cosT) / (cosI + n * cosT), 2.0);
  const double rp = std::pow((cosT - n * cosI) / (cosT + n * cosI), 2.0);
  const double tau = std::pow(transmissivity, 1.0 / cosT);
  double t = 0.0;
  for (double r : {rs, rp}) t += 0.5 * (1.0 - r) * (1.0 - r) * tau / (1.0 - r * r * tau * tau);
  return t;
}

RenderSettings viewEstimator() {
  RenderSettings r;
  r.irradianceSamples = 64;
  r.coarseStep = 1;
  return r;
}

// A camera under a horizontal pane of glass looks up at a sky of uniform luminance over the
// upper hemisphere only: the transmitted branch sees L, the reflected one looks down at nothing.
// So every camera ray is L·T(θ), and a pixel lies within the range of L·T over its footprint
// (sampled on a 9 × 9 lattice, 0.1 % for the extremes between lattice points). One branch chosen
// by roulette would give 0 or L·T/P(transmit) instead.
TEST(RenderEstimator, SkyThroughThinGlassIsItsTransmittanceInEveryPixel) {
  constexpr double kTn = 0.9, kN = 1.52;
  Scene sc;
  Material glass;
  glass.type = MaterialType::kGlass;
  glass.name = "pane";
  glass.color = Rgb(kTn);
  glass.refractiveIndex = kN;
  sc.addPolygon({{-100, -100, 1}, {100, -100, 1}, {100, 100, 1}, {-100, 100, 1}}, sc.addMaterial(glass));
  sc.addDistant({0, 0, 1}, 180.0, addMaterial(sc, MaterialType::kGlow, kSkyRadiance, "sky"));
  const Tracer tracer(sc);
  const View v = perspective({0, 0, 0}, {0.3, 0.2, 1.0}, {0, 1, 0}, {70.0, 70.0}, 12, 12);
  TraceSettings s;
  const Image img = renderView(tracer, v, s, 1, viewEstimator());
  const Camera cam(v);
  const double lSky = kLumensPerWatt * kSkyRadiance;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      double lo = 1e300, hi = 0.0;
      for (int j = 0; j <= 8; ++j)
        for (int i = 0; i <= 8; ++i) {
          const auto d = cam.direction(x + i / 8.0, y + j / 8.0);
          ASSERT_TRUE(d);
          const double l = lSky * glassTransmittance(d->z, kTn, kN);
          lo = std::min(lo, l);
          hi = std::max(hi, l);
        }
      const double got = img.luminance[img.index(x, y)];
      EXPECT_GE(got, lo * (1.0 - 1e-3)) << "pixel " << x << "," << y;
      EXPECT_LE(got, hi * (1.0 + 1e-3)) << "pixel " << x << "," << y;
    }
}

// A matte floor (ρ 0.5) under a uniform sky, with a tall vertical pane standing on it: clear glass
// without absorption (transmissivity 1, so T + R = 1 at every angle) or a perfect mirror. A
// vertical pane keeps a ray's upward component, so every floor point still sees sky in every
// upward direction, directly or through or off the pane: E = πL, and the floor's luminance is
// ρL = 895 cd/m² from everywhere. Seen through the pane, in it, or directly, every pixel reads
// that (T ρL + R ρL for the glass), to 1e-9: no sample of the estimate varies.
TEST(RenderEstimator, MatteFloorSeenThroughGlassOrInAMirrorReadsRhoLInEveryPixel) {
  constexpr double kRho = 0.5;
  const double want = kRho * kLumensPerWatt * kSkyRadiance;
  for (const MaterialType type : {MaterialType::kGlass, MaterialType::kMirror}) {
    Scene sc;
    sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, addPlastic(sc, kRho));
    Material pane;
    pane.type = type;
    pane.name = "pane";
    pane.color = Rgb(1.0);
    sc.addPolygon({{1, -20, 0}, {1, 20, 0}, {1, 20, 30}, {1, -20, 30}}, sc.addMaterial(pane));
    sc.addDistant({0, 0, 1}, 180.0, addMaterial(sc, MaterialType::kGlow, kSkyRadiance, "sky"));
    const Tracer tracer(sc);
    // Looking down at 45° ± 20° towards the pane from 1 m before it: floor before it, through it
    // (or, for the mirror, in it).
    const View v = perspective({0, 0, 1.5}, {1, 0, -1}, {0, 0, 1}, {40.0, 40.0}, 16, 16);
    TraceSettings s;
    const Image img = renderView(tracer, v, s, 1, viewEstimator());
    for (std::size_t i = 0; i < img.luminance.size(); ++i)
      EXPECT_NEAR(img.luminance[i], want, kFloatRel * want) << (type == MaterialType::kGlass ? "glass" : "mirror")
                                                       << ", pixel " << i;
  }
}

// A glossy floor (Ward lobe of roughness 0.05, ρs = 0.1, diffuse ρd = 0.4) under the upper-
// hemisphere sky, seen from above within 30° of the normal: its diffuse part is ρd L (E = πL, the
// floor sees only sky), and every sample of its lobe leaves upwards (a sample would have to tilt
// the half vector by 30°: probability e^(−tan²30°/α²) = e^(−133)) and sees L, carrying ρs. So
// every pixel reads (ρd + ρs) L to rounding: the lobe counted once, with the diffuse part.
TEST(RenderEstimator, GlossyFloorReadsDiffusePlusSpecularReflectanceTimesTheSky) {
  constexpr double kRhoD = 0.4, kRhoS = 0.1;
  Scene sc;
  Material m;
  m.type = MaterialType::kPlastic;
  m.name = "glossy";
  m.color = Rgb(kRhoD / (1.0 - kRhoS));  // Radiance's plastic: diffuse colour·(1 − spec), specular spec
  m.specularity = kRhoS;
  m.roughness = 0.05;
  sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, sc.addMaterial(m));
  sc.addDistant({0, 0, 1}, 180.0, addMaterial(sc, MaterialType::kGlow, kSkyRadiance, "sky"));
  const Tracer tracer(sc);
  const View v = perspective({0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {60.0, 60.0}, 12, 12);
  TraceSettings s;
  const Image img = renderView(tracer, v, s, 1, viewEstimator());
  const double want = (kRhoD + kRhoS) * kLumensPerWatt * kSkyRadiance;
  for (std::size_t i = 0; i < img.luminance.size(); ++i) EXPECT_NEAR(img.luminance[i], want, kFloatRel * want) << i;
}

// The weighted mean's standard error: three pixels in a row, the middle one interpolated half
// and half from the outer two. Mean = (L0 + (L0 + L2)/2 + L2)/3 = (L0 + L2)/2, so its standard
// error is √(s0² + s2²)/2, not the √(s0² + ((s0 + s2)/2)² + s2²)/3 of independent pixels.
TEST(RenderEstimator, MeanStandardErrorCarriesInterpolatedPixelsToTheirCorners) {
  Image img;
  img.width = 3;
  img.height = 1;
  img.luminance = {100.0f, 110.0f, 120.0f};
  img.standardError = {3.0f, 2.0f, 4.0f};  // the middle one's, interpolated, is not used
  img.traced = {1, 0, 1};
  img.inside = {1, 1, 1};
  // The middle pixel interpolated on the lattice of spacing 2 (level 1): corners 0 and 2.
  img.interpolationLevel = {0, 1, 0};
  img.samplesPerPixel = 4;
  auto weights = [](std::vector<double> w) { return [w](std::size_t i) { return w[i]; }; };
  EXPECT_NEAR(meanStandardError(img, weights({1.0, 1.0, 1.0})), std::sqrt(9.0 + 16.0) / 2.0, 1e-6);
  // Weights leave pixels out: the last pixel alone.
  EXPECT_NEAR(meanStandardError(img, weights({0.0, 0.0, 2.0})), 4.0, 1e-6);
  // One ray per pixel has no spread to estimate from.
  img.samplesPerPixel = 1;
  EXPECT_TRUE(std::isnan(meanStandardError(img, weights({1.0, 1.0, 1.0}))));
}

// Mean luminance over the image (solid-angle weights) and its reported standard error.
struct MeanAndError {
  double mean = 0.0, standardError = 0.0;
};
MeanAndError meanOf(const Image& img, const View& v) {
  const Camera cam(v);
  std::vector<double> w(img.luminance.size());
  double sum = 0.0, omega = 0.0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      w[img.index(x, y)] = cam.pixelSolidAngleSr(x, y);
      sum += w[img.index(x, y)] * img.luminance[img.index(x, y)];
      omega += w[img.index(x, y)];
    }
  return {sum / omega, meanStandardError(img, [&w](std::size_t i) { return w[i]; })};
}

// Over 16 seeds, the sample standard deviation s of the image means against the reported standard
// error σ (root mean square over the seeds): (16 − 1) s²/σ² is χ² with 15 degrees of freedom, so
// s/σ lies in [√(3.483/15), √(37.70/15)] = [0.482, 1.585] with probability 0.998 (the 0.001 and
// 0.999 quantiles). Reported errors that missed the interpolated pixels' correlation, or counted
// the pixels' stratified samples wrong, would fall outside.
constexpr int kSeeds = 16;
constexpr double kSpreadLow = 0.482, kSpreadHigh = 1.585;

void expectSpreadMatchesReportedError(const std::vector<MeanAndError>& runs, const char* what) {
  double m = 0.0, var = 0.0, se2 = 0.0;
  for (const MeanAndError& r : runs) m += r.mean / runs.size();
  for (const MeanAndError& r : runs) {
    var += (r.mean - m) * (r.mean - m) / (runs.size() - 1);
    se2 += r.standardError * r.standardError / runs.size();
  }
  const double ratio = std::sqrt(var / se2);
  std::printf("[ measured ] %s: mean %.3f cd/m2, spread over %zu seeds %.4f, reported standard error %.4f (ratio %.3f)\n",
              what, m, runs.size(), std::sqrt(var), std::sqrt(se2), ratio);
  EXPECT_GT(ratio, kSpreadLow) << what << ": spread " << std::sqrt(var) << ", reported " << std::sqrt(se2);
  EXPECT_LT(ratio, kSpreadHigh) << what << ": spread " << std::sqrt(var) << ", reported " << std::sqrt(se2);
}

// Plain paths (irradianceSamples 0, every pixel traced) on the glow floor: each camera ray's
// value is 0 or 2ρL (Russian roulette by ρ = 0.5), the truth ρL = 895 cd/m². Each seed's mean is
// within 4 of its reported standard errors of the truth, the mean over seeds within 4 of theirs
// combined, and the spread over seeds matches the reported error.
TEST(RenderEstimator, ReportedErrorOfPlainPathsMatchesTheTruthAndTheSpreadOverSeeds) {
  constexpr double kRho = 0.5;
  Scene sc;
  sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, addPlastic(sc, kRho));
  sc.addDistant({0, 0, 1}, 180.0, addMaterial(sc, MaterialType::kGlow, kSkyRadiance, "sky"));
  const Tracer tracer(sc);
  const View v = perspective({0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {60.0, 60.0}, 16, 16);
  const double truth = kRho * kLumensPerWatt * kSkyRadiance;
  RenderSettings r;
  r.irradianceSamples = 0;
  r.coarseStep = 1;
  std::vector<MeanAndError> runs;
  double se2 = 0.0, mean = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    TraceSettings s;
    s.seed = seed;
    const MeanAndError m = meanOf(renderView(tracer, v, s, 2, r), v);
    ASSERT_GT(m.standardError, 0.0);
    EXPECT_NEAR(m.mean, truth, 4.0 * m.standardError) << "seed " << seed;
    runs.push_back(m);
    mean += m.mean / kSeeds;
    se2 += m.standardError * m.standardError / (kSeeds * kSeeds);
  }
  EXPECT_NEAR(mean, truth, 4.0 * std::sqrt(se2));
  expectSpreadMatchesReportedError(runs, "plain paths");
}

// The default estimator with adaptive sampling (coarse step 4: interpolated pixels) on a floor
// beside a wall under a uniform sky: irradiance estimates that vary with the wall's shadow, a few
// per cent noise, so that some blocks are interpolated and some refined. No closed form needed:
// the spread of the mean over seeds matches the reported error.
TEST(RenderEstimator, ReportedErrorOfTheViewEstimatorMatchesTheSpreadOverSeeds) {
  Scene sc;
  sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, addPlastic(sc, 0.5));
  sc.addPolygon({{0, -20, 0}, {0, 20, 0}, {0, 20, 2}, {0, -20, 2}}, addPlastic(sc, 0.5));
  sc.addDistant({0, 0, 1}, 180.0, addMaterial(sc, MaterialType::kGlow, kSkyRadiance, "sky"));
  const Tracer tracer(sc);
  const View v = perspective({1.5, 0, 3}, {0, 0, -1}, {0, 1, 0}, {60.0, 60.0}, 32, 32);
  RenderSettings r;
  r.irradianceSamples = 16;
  std::vector<MeanAndError> runs;
  std::size_t interpolated = 0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    TraceSettings s;
    s.seed = seed;
    s.maxBounces = 1;
    const Image img = renderView(tracer, v, s, 2, r);
    for (std::size_t i = 0; i < img.interpolationLevel.size(); ++i) interpolated += img.interpolationLevel[i] > 0;
    runs.push_back(meanOf(img, v));
  }
  EXPECT_GT(interpolated, 0u);  // the case this test is about
  std::printf("[ measured ] view estimator: %zu of %d pixels interpolated over the seeds\n", interpolated,
              kSeeds * 32 * 32);
  expectSpreadMatchesReportedError(runs, "view estimator");
}

}  // namespace
}  // namespace candela
