// renderView against closed forms: a Lambertian plane under a distant source has luminance
// ρE/π in every pixel (the engine's direct estimate is exact for a wholly visible source with a
// closed form, so the check is to 1e-9); a light seen directly lands on the pixel the projection
// names; a Lambertian luminaire opening shows I/(A cos γ); the adaptive sampler refines only
// where the luminance changes, and images do not depend on the thread count.
#include "engine/luminaire_source.h"
#include "engine/luminaire_opening.h"
#include "engine/render.h"
#include "metrics/contrast.h"
#include "metrics/glare.h"
#include "photometry/ies_lm63.h"
#include "validation/analytic.h"

#include "tests/engine/lambertian_panel.h"
#include "tests/support/test_views.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela {
namespace {

uint32_t addMaterial(Scene& sc, MaterialType type, double value) {
  Material m;
  m.type = type;
  m.name = type == MaterialType::kLight ? "lamp" : "grey";
  m.color = Rgb(value);
  return sc.addMaterial(m);
}

void addUpRect(Scene& sc, double x0, double y0, double x1, double y1, double z, uint32_t mat) {
  sc.addPolygon({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, mat);
}

constexpr auto view = test_support::makeView;
using test_support::kFloatRel;

// The sun (0.533° disc, radiance L) over a plane of reflectance ρ: E = π L sin²α cos θs
// (W/m², times 179 for lux) and every point of the plane has luminance ρE/π.
struct SunlitPlane {
  static constexpr double kRho = 0.5, kL = 6e6, kFullDeg = 0.533;
  Scene sc;
  Vec3 sunDir = glm::normalize(Vec3(0.3, -0.5, 0.8));
  SunlitPlane() {
    addUpRect(sc, -1e4, -1e4, 1e4, 1e4, 0.0, addMaterial(sc, MaterialType::kPlastic, kRho));
    sc.addDistant(sunDir, kFullDeg, addMaterial(sc, MaterialType::kLight, kL));
  }
  double luminanceCdM2() const {
    const double sinA = std::sin(degToRad(kFullDeg / 2));
    const double eLux = kLumensPerWatt * kPi * kL * sinA * sinA * sunDir.z;
    return kRho * eLux / kPi;
  }
};

TEST(Render, LambertianPlaneHasLuminanceRhoEOverPiInEveryPixel) {
  SunlitPlane p;
  const Tracer tracer(p.sc);
  const double want = p.luminanceCdM2();
  TraceSettings s;
  s.maxBounces = 0;
  // Camera rays sample the sun's disc (path vertices use one plain Monte Carlo sample per light,
  // engine/light_selection.h), so a sample deviates from the exact value by the spread of cos ι
  // over the disc: at most sin(0.2665°) tan θs = 0.34 %. Each pixel is held to 0.5 %, and the
  // mean of the traced pixels (independent samples; interpolated ones are not) to 4 standard
  // errors.
  auto check = [&](const Image& img, auto&& use, const char* what) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0, all = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        if (!use(x, y)) continue;
        const double l = img.luminance[img.index(x, y)];
        EXPECT_NEAR(l, want, 0.005 * want) << what << " " << x << "," << y;
        ++all;
        if (!img.traced[img.index(x, y)]) continue;
        sum += l;
        sum2 += l * l;
        ++n;
      }
    const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    std::printf("[ measured ] sunlit plane, %s: mean %.7g cd/m2 over %d traced pixels, reference %.7g, "
                "standard error %.3g\n",
                what, mean, n, want, se);
    EXPECT_NEAR(mean, want, std::max(4.0 * se, 1e-9 * want)) << what;
    return all;
  };
  // Perspective, looking obliquely down at the plane.
  {
    const View v = view(ViewType::kPerspective, {0, 0, 1.6}, {0, 1, -1}, {0, 0, 1}, {60, 40}, 33, 21);
    const Image img = renderView(tracer, v, s, 2);
    check(img, [](int, int) { return true; }, "perspective");
    // A uniform image: only the coarse lattice is traced (9 × 6 of 33 × 21 with a step of 4).
    EXPECT_EQ(img.tracedPixels, 9u * 6u);
  }
  // With the irradiance estimate at matte surfaces the sun's ratio estimator is exact (wholly
  // visible source with a closed form), so every pixel is ρE/π to rounding.
  {
    const View v = view(ViewType::kPerspective, {0, 0, 1.6}, {0, 1, -1}, {0, 0, 1}, {60, 40}, 33, 21);
    RenderSettings r;
    r.irradianceSamples = 16;
    const Image img = renderView(tracer, v, s, 2, r);
    for (std::size_t i = 0; i < img.luminance.size(); ++i) ASSERT_NEAR(img.luminance[i], want, kFloatRel * want) << i;
  }
  // Fisheye straight down: every pixel whose whole footprint is more than a pixel inside the rim
  // sees the plane (rays at the rim run to the horizon, beyond the 10 km plane).
  {
    const int n = 32;
    const View v = view(ViewType::kFisheye, {0, 0, 1.6}, {0, 0, -1}, {0, 1, 0}, {180, 180}, n, n);
    const Image img = renderView(tracer, v, s, 2);
    const int checked = check(img, [&](int x, int y) {
      return std::hypot(x + 0.5 - n / 2.0, y + 0.5 - n / 2.0) <= n / 2.0 - 1.5; }, "fisheye");
    EXPECT_GT(checked, 600);
  }
}

// A small light sphere seen directly (camera rays count sources) appears at the pixel where
// Camera::project puts its centre, for both projections.
TEST(Render, LightSeenDirectlyLandsWhereTheProjectionSays) {
  for (ViewType type : {ViewType::kPerspective, ViewType::kFisheye}) {
    Scene sc;
    const Vec3 eye(0.0, 0.0, 1.0);
    const Vec3 centre = eye + 5.0 * glm::normalize(Vec3(0.9, 1.0, 0.45));  // off-axis, up and right
    sc.addSphere(centre, 0.3, addMaterial(sc, MaterialType::kLight, 100.0));  // 6.9° across
    const Tracer tracer(sc);
    const View v = type == ViewType::kPerspective
                           ? view(type, eye, {0, 1, 0}, {0, 0, 1}, {120, 90}, 60, 45)
                           : view(type, eye, {0, 1, 0}, {0, 0, 1}, {180, 180}, 61, 61);
    RenderSettings r;
    r.coarseStep = 1;
    r.samplesPerPixel = 16;
    const Image img = renderView(tracer, v, TraceSettings{}, 1, r);
    // The luminance-weighted centroid of the sphere's image (a disc a few pixels wide).
    double sum = 0.0, sx = 0.0, sy = 0.0, peak = 0.0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const double l = img.luminance[img.index(x, y)];
        sum += l;
        sx += l * (x + 0.5);
        sy += l * (y + 0.5);
        peak = std::max(peak, l);
      }
    const auto p = Camera(v).project(centre - eye);
    ASSERT_TRUE(p);
    ASSERT_GT(sum, 0.0);
    EXPECT_NEAR(sx / sum, p->x, 0.5) << (type == ViewType::kFisheye);
    EXPECT_NEAR(sy / sum, p->y, 0.5) << (type == ViewType::kFisheye);
    // Pixels wholly on the sphere see exactly its luminance, 179 × 100 cd/m².
    EXPECT_NEAR(peak, kLumensPerWatt * 100.0, kFloatRel * kLumensPerWatt * 100.0);
  }
}

// A Lambertian 600 mm panel (I = 1000 cos γ cd) seen from below: its opening has luminance
// I/(A cos γ) = 1000/0.36 cd/m² from every direction, in the image and for glare ratings.
// With the opening as a surface (opening_reflectance; lit by nothing here, so it reflects 0) the
// same: the ray meets the surface in the opening's plane and still sees the luminance, and the
// glare source's shadow rays pass its own surface.
TEST(Render, LuminaireOpeningShowsIntensityOverProjectedArea) {
  for (const bool surface : {false, true}) {
    SCOPED_TRACE(surface ? "opening surface of reflectance 0.5" : "no opening surface");
    Scene sc;
    LuminaireMounting lp;
    lp.name = "panel";
    lp.positionM = {0, 2, 2.8};
    sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(), lp));
    if (surface) {
      ASSERT_EQ(addOpeningSurface(sc, 0, 0.5), 0u);
    }
    const Tracer tracer(sc);
    const Vec3 eye(0, 0, 1.2);
    const Vec3 d = lp.positionM - eye;
    const double dist = glm::length(d), cosG = d.z / dist;
    // I/(A cos γ) with I from the placed web itself (its 5° linear interpolation of the cosine
    // puts it 0.07 % below 1000/0.36 here; the formula, not the web, is under test).
    const double want = sc.luminaires[0].intensityCd(-d / dist) / (0.36 * cosG);
    EXPECT_NEAR(want, 1000.0 / 0.36, 1e-3 * want);
    const View v = view(ViewType::kPerspective, eye, {0, 1, 0.8}, {0, 0, 1}, {60, 60}, 41, 41);
    RenderSettings r;
    r.coarseStep = 1;
    const Image img = renderView(tracer, v, TraceSettings{}, 2, r);
    const auto p = Camera(v).project(lp.positionM - eye);
    ASSERT_TRUE(p);
    // The sample rays of the pixel at the panel's centre all hit the opening (it spans several pixels).
    // Its sample rays meet the opening at directions up to a pixel apart, where the web's
    // interpolation error (at most h²/8 = 0.095 % of the cosine for 5° steps) differs: 0.2 %.
    EXPECT_NEAR(img.luminance[img.index(static_cast<int>(p->x), static_cast<int>(p->y))], want, 2e-3 * want);
    const std::vector<SeenLuminaire> seen = seenLuminaires(tracer, eye, v.direction);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_NEAR(seen[0].luminanceCdM2, want, 1e-9 * want);
    EXPECT_NEAR(seen[0].solidAngleSr, 0.36 * cosG / (dist * dist), 1e-12);
    EXPECT_NEAR(seen[0].transmittance, 1.0, 1e-12);
  }
}

// Half the plane dark, half lit (a black strip): refinement traces along the edge and leaves the
// uniform parts interpolated; the edge pixels are exact, not smeared.
TEST(Render, AdaptiveSamplingRefinesOnlyWhereLuminanceChanges) {
  SunlitPlane p;
  addUpRect(p.sc, 0.0, -1e4, 1e4, 1e4, 1e-3, addMaterial(p.sc, MaterialType::kPlastic, 0.0));
  const Tracer tracer(p.sc);
  const View v = view(ViewType::kPerspective, {0.013, 0, 3}, {0, 0, -1}, {0, 1, 0}, {60, 60}, 65, 65);
  TraceSettings s;
  s.maxBounces = 0;
  RenderSettings r;
  r.coarseStep = 8;
  r.noiseAllowance = 0.0;  // a pixel cut by the edge has sample variance that is not noise
  const Image img = renderView(tracer, v, s, 2, r);
  std::printf("[ measured ] edge image: %zu of %zu pixels traced, %zu camera rays\n", img.tracedPixels,
              img.luminance.size(), img.cameraRays);
  EXPECT_LT(img.tracedPixels, img.luminance.size() / 3);
  // Columns well away from the edge (x = 0 is near the image's middle column): lit to 0.5 % (the
  // sun disc's cosine spread, see above) and black exactly.
  const double want = p.luminanceCdM2();
  for (int y = 0; y < img.height; ++y) {
    EXPECT_NEAR(img.luminance[img.index(5, y)], want, 5e-3 * want);
    EXPECT_NEAR(img.luminance[img.index(60, y)], 0.0, 1e-9 * want);
  }
  // Interpolated pixels are within the refinement threshold of lit or dark: a pixel half on the
  // edge is never smeared from its block's corners.
  for (std::size_t i = 0; i < img.luminance.size(); ++i) {
    const double l = img.luminance[i];
    if (!img.traced[i]) {
      EXPECT_TRUE(l < r.refineThreshold * want || l > (1 - r.refineThreshold) * want) << i;
    }
  }
}

// A grey floor and wall lit by a small spherical lamp: noisy indirect light and sharp shadows, for
// the images that must not depend on how they were computed.
Scene floorWallAndLamp() {
  Scene sc;
  const uint32_t grey = addMaterial(sc, MaterialType::kPlastic, 0.6);
  addUpRect(sc, -2, -2, 2, 2, 0.0, grey);
  sc.addPolygon({{-2, -2, 0}, {-2, -2, 2}, {2, -2, 2}, {2, -2, 0}}, grey);  // a wall at y = -2
  sc.addSphere({0, 0, 2.5}, 0.2, addMaterial(sc, MaterialType::kLight, 50.0));
  return sc;
}

// Indirect light makes pixels noisy; the image is nevertheless the same for 1 and 2 threads.
TEST(Render, SameImageForAnyThreadCount) {
  const Scene sc = floorWallAndLamp();
  const Tracer tracer(sc);
  const View v = view(ViewType::kPerspective, {0, 1.8, 1.2}, {0, -1, -0.3}, {0, 0, 1}, {70, 50}, 24, 16);
  TraceSettings s;
  s.maxBounces = 2;
  const Image a = renderView(tracer, v, s, 1), b = renderView(tracer, v, s, 2);
  ASSERT_EQ(a.luminance.size(), b.luminance.size());
  for (std::size_t i = 0; i < a.luminance.size(); ++i) ASSERT_EQ(a.luminance[i], b.luminance[i]) << i;
  EXPECT_EQ(a.tracedPixels, b.tracedPixels);
}

// A pass goes out in bands of about pixelsPerFill pixels (bounded memory for large images): the
// image, its interpolation record and its mean's standard error do not depend on the band size,
// down to bands of a single lattice row.
TEST(Render, SameImageForAnyBandSize) {
  const Scene sc = floorWallAndLamp();
  const Tracer tracer(sc);
  const View v = view(ViewType::kPerspective, {0, 1.8, 1.2}, {0, -1, -0.3}, {0, 0, 1}, {70, 50}, 37, 23);
  TraceSettings s;
  s.maxBounces = 1;
  RenderSettings whole;
  whole.coarseStep = 8;
  const Image a = renderView(tracer, v, s, 2, whole);
  std::size_t interpolated = 0;
  for (uint8_t l : a.interpolationLevel) interpolated += l > 0;
  ASSERT_GT(interpolated, 0u);  // the case this test is about
  ASSERT_GT(a.tracedPixels, 0u);
  auto unit = [](std::size_t) { return 1.0; };
  for (std::size_t band : {1, 40, 300}) {
    RenderSettings r = whole;
    r.pixelsPerFill = band;
    const Image b = renderView(tracer, v, s, 2, r);
    ASSERT_EQ(a.luminance.size(), b.luminance.size());
    for (std::size_t i = 0; i < a.luminance.size(); ++i) {
      ASSERT_EQ(a.luminance[i], b.luminance[i]) << band << " " << i;
      ASSERT_EQ(a.radiance[i], b.radiance[i]) << band << " " << i;
      ASSERT_EQ(a.interpolationLevel[i], b.interpolationLevel[i]) << band << " " << i;
    }
    EXPECT_EQ(a.tracedPixels, b.tracedPixels);
    EXPECT_EQ(a.cameraRays, b.cameraRays);
    EXPECT_EQ(meanStandardError(a, unit), meanStandardError(b, unit));
  }
}

// The mean's standard error is computed in bands of rows (bounded memory): against the whole
// image at once, written out here in double (every interpolated pixel's weight carried to its
// corners, finest level first, last pixel first), on an image of three bands and a part.
TEST(Render, MeanStandardErrorInBandsIsTheWholeImages) {
  Scene sc;
  const uint32_t grey = addMaterial(sc, MaterialType::kPlastic, 0.6);
  addUpRect(sc, -20, -20, 20, 20, 0.0, grey);
  sc.addSphere({0, 0, 2.5}, 0.2, addMaterial(sc, MaterialType::kLight, 50.0));
  const Tracer tracer(sc);
  const View v = view(ViewType::kPerspective, {0, 1.8, 1.2}, {0, -1, -0.6}, {0, 0, 1}, {20, 100}, 24, 800);
  RenderSettings r;
  r.coarseStep = 8;
  TraceSettings s;
  s.maxBounces = 1;
  s.hemisphereSamples = 4;
  const Image img = renderView(tracer, v, s, 2, r);
  std::size_t interpolated = 0;
  for (uint8_t l : img.interpolationLevel) interpolated += l > 0;
  ASSERT_GT(interpolated, 0u);
  auto weight = [&](std::size_t i) { return 1.0 + static_cast<double>(i % 7); };
  const std::size_t n = img.luminance.size();
  std::vector<double> c(n);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) total += c[i] = weight(i);
  for (int level = 1; level <= 3; ++level)
    for (std::size_t i = n; i-- > 0;) {
      if (img.interpolationLevel[i] != level) continue;
      const int x = static_cast<int>(i % img.width), y = static_cast<int>(i / img.width);
      const LatticeInterval ix = interpolationInterval(img.width, 1 << level, x);
      const LatticeInterval iy = interpolationInterval(img.height, 1 << level, y);
      const double ci = c[i];
      c[i] = 0.0;
      c[img.index(ix.c0, iy.c0)] += (1 - ix.f) * (1 - iy.f) * ci;
      c[img.index(ix.c1, iy.c0)] += ix.f * (1 - iy.f) * ci;
      c[img.index(ix.c0, iy.c1)] += (1 - ix.f) * iy.f * ci;
      c[img.index(ix.c1, iy.c1)] += ix.f * iy.f * ci;
    }
  double variance = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (img.traced[i]) variance += c[i] * c[i] * img.standardError[i] * img.standardError[i];
  const double want = std::sqrt(variance) / total;
  ASSERT_GT(want, 0.0);
  // The engine's coefficients are float (4 B a pixel): each sum of up to 17 × 17 terms rounded
  // once a term, 2^-24 relative each, so a few 10^-6 at most.
  EXPECT_NEAR(meanStandardError(img, weight), want, 1e-5 * want);
}

// Each interpolated pixel's record names its block's corners: its value is their bilinear blend
// (computed in double from the float corners, then rounded to float).
TEST(Render, InterpolatedPixelsAreTheirCornersBlend) {
  const Scene sc = floorWallAndLamp();
  const Tracer tracer(sc);
  const View v = view(ViewType::kPerspective, {0, 1.8, 1.2}, {0, -1, -0.3}, {0, 0, 1}, {70, 50}, 37, 23);
  RenderSettings r;
  r.coarseStep = 8;
  const Image img = renderView(tracer, v, TraceSettings{}, 2, r);
  std::size_t checked = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int level = img.interpolationLevel[img.index(x, y)];
      if (level == 0) continue;
      const LatticeInterval ix = interpolationInterval(img.width, 1 << level, x);
      const LatticeInterval iy = interpolationInterval(img.height, 1 << level, y);
      ASSERT_LE(ix.c0, x);
      ASSERT_GE(ix.c1, x);
      const double l = (1 - ix.f) * (1 - iy.f) * img.luminance[img.index(ix.c0, iy.c0)] +
                       ix.f * (1 - iy.f) * img.luminance[img.index(ix.c1, iy.c0)] +
                       (1 - ix.f) * iy.f * img.luminance[img.index(ix.c0, iy.c1)] +
                       ix.f * iy.f * img.luminance[img.index(ix.c1, iy.c1)];
      // Luminance is linear in the radiance blended: equal to the blend of the corners' (each
      // rounded to float) to a few float roundings.
      EXPECT_NEAR(img.luminance[img.index(x, y)], l, 4 * kFloatRel * std::max(l, 1e-30)) << x << " " << y;
      ++checked;
    }
  EXPECT_GT(checked, 0u);
  // The closed form of the lattice's intervals: lines at multiples of the spacing and at the
  // last pixel.
  EXPECT_EQ(interpolationInterval(37, 8, 36).c0, 32);
  EXPECT_EQ(interpolationInterval(37, 8, 36).c1, 36);
  EXPECT_EQ(interpolationInterval(37, 8, 33).c1, 36);
  EXPECT_DOUBLE_EQ(interpolationInterval(37, 8, 34).f, 0.5);
  EXPECT_EQ(interpolationInterval(33, 8, 32).c0, 24);  // the last pixel on a line: the last interval
  EXPECT_DOUBLE_EQ(interpolationInterval(33, 8, 32).f, 1.0);
  EXPECT_EQ(interpolationInterval(1, 8, 0).c1, 0);
}

// The contrast rendition factor of a matte task is 1: a dark matte card (ρ = 0.1) on a matte
// desk (ρ = 0.5) in sunlight has the contrast (ρt − ρb)/ρb that the reference uniform sphere
// gives. Luminances are means over 5 × 5 pixels well inside each area (each pixel to 0.34 %, the
// sun disc's cosine spread, so C to 0.7 % of ρt/ρb = 0.2: 0.002 of CRF).
TEST(Render, MatteTaskHasContrastRenditionFactorOne) {
  SunlitPlane p;
  const double rt = 0.1;
  addUpRect(p.sc, -0.5, 1.0, 0.5, 2.0, 1e-3, addMaterial(p.sc, MaterialType::kPlastic, rt));  // 1 m card
  const Tracer tracer(p.sc);
  const Vec3 eye(0.0, 0.0, 1.2);
  const View v = view(ViewType::kPerspective, eye, {0, 1.5, -1.2}, {0, 0, 1}, {60, 60}, 41, 41);
  TraceSettings s;
  s.maxBounces = 0;
  const Image img = renderView(tracer, v, s, 2);
  const Camera cam(v);
  auto meanAround = [&](const Vec3& target) {
    const auto c = cam.project(target - eye);
    double sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) sum += img.luminance[img.index(int(c->x) + dx, int(c->y) + dy)];
    return sum / 9.0;
  };
  const double lt = meanAround({0.0, 1.5, 0.0}), lb = meanAround({0.0, 3.0, 0.0});
  const double crf = contrastRenditionFactor(luminanceContrast(lt, lb), matteReferenceContrast(rt, SunlitPlane::kRho));
  std::printf("[ measured ] matte task: Lt %.6g, Lb %.6g cd/m2, CRF %.5f\n", lt, lb, crf);
  EXPECT_NEAR(crf, 1.0, 0.002);
}

// With nothing in the scene but a Lambertian panel (L = I0/A from every direction) 1.6 m above
// an eye looking straight up: the luminaire's direct share is the uniform rectangle's closed form
// E = π L F (validation/analytic), to the web's 5° interpolation of the cosine (≤ 0.1 %) and the
// 8 × 8 midpoint rule; the tracer's vertical illuminance at the eye is the same light (near field:
// sampled over the opening), so UGR's background, the rest over π, is 0 to its Monte Carlo error.
TEST(Render, EyeLightSeparatesDirectFromIndirect) {
  Scene sc;
  LuminaireMounting lp;
  lp.positionM = {0.3, 0.5, 2.8};
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(), lp));
  const Tracer tracer(sc);
  const View v = view(ViewType::kPerspective, {0, 0, 1.2}, {0, 0, 1}, {0, 1, 0}, {60, 45}, 8, 6);
  TraceSettings s;
  s.lightSamples = 1024;
  const EyeLight e = eyeLight(tracer, v, s);
  ASSERT_EQ(e.luminaires.size(), 1u);
  const double want = kLumensPerWatt * analytic::rectangleAbove(1000.0 / 0.36 / kLumensPerWatt, {0.0, 0.2, 0.6, 0.8}, 1.6, 0.0, 0.0);
  std::printf("[ measured ] panel at the eye: direct %.5g lx (closed form %.5g), tracer %.5g lx\n", e.directLuminaireLux,
              want, e.verticalLux);
  EXPECT_NEAR(e.directLuminaireLux, want, 2e-3 * want);
  EXPECT_NEAR(e.luminaires[0].transmittance, 1.0, 1e-12);
  const IrradianceEstimate est = estimateIrradiance(tracer, v.positionM, v.direction, 0, s);
  EXPECT_NEAR(e.verticalLux, e.directLuminaireLux, 4.0 * est.standardErrorLux() + 2e-3 * want);
  EXPECT_NEAR(e.backgroundLuminanceCdM2(), 0.0, (4.0 * est.standardErrorLux() + 2e-3 * want) / kPi);
  // The view-frame direction of the photometric centre.
  const Vec3 d = glm::normalize(lp.positionM - v.positionM);
  const Camera cam(v);
  EXPECT_NEAR(glm::length(e.luminaires[0].directionView -
                          Vec3(glm::dot(d, cam.right()), glm::dot(d, cam.up()), glm::dot(d, cam.forward()))),
              0.0, 1e-12);
}

// End to end, camera + renderer + image glare: a fisheye under a uniform sky of luminance L (a
// 360° glow) sees L in every pixel, and the image's vertical illuminance Σ L cos θ ω is π L to the
// rim pixels' share (pixels whose centre lies outside the circle are left out: −0.3 % at 96 px).
TEST(Render, FisheyeUnderUniformSkyGivesPiLAtTheEye) {
  Scene sc;
  const double radiance = 2.0;
  sc.addDistant({0, 0, 1}, 360.0, addMaterial(sc, MaterialType::kGlow, radiance));
  const Tracer tracer(sc);
  const View v = view(ViewType::kFisheye, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {180, 180}, 96, 96);
  const Image img = renderView(tracer, v, TraceSettings{}, 2);
  const double l = kLumensPerWatt * radiance;
  for (std::size_t i = 0; i < img.luminance.size(); ++i)
    ASSERT_NEAR(img.luminance[i], img.inside[i] ? l : 0.0, kFloatRel * l) << i;
  const ImageGlare glare = evaluateImageGlare(img.luminance, ViewGeometry(v), img.width, img.height);
  std::printf("[ measured ] uniform sky: Ev from the image %.6g lx, pi L = %.6g lx\n", glare.verticalIlluminanceLux,
              kPi * l);
  EXPECT_NEAR(glare.verticalIlluminanceLux, kPi * l, 0.005 * kPi * l);
  EXPECT_TRUE(glare.sources.empty());
}

// CRF end to end: a matte card on a matte desk lit by a point luminaire of Lambertian intensity
// (the engine's point law I cos ι / d² is exact for it), reference the uniform sphere of referenceSphereScene.
// Matte surfaces have L = ρE/π, so C = (ρt E_t − ρb E_b)/(ρb E_b), with E_t/E_b from the web's
// intensities; under the sphere (task and desk alone, the wall added afterwards left out) both
// points see the whole sky over a 40 m floor, E = π L exactly, so C_ref = (ρt − ρb)/ρb and CRF = 1 to the small illuminance difference between the two points.
TEST(Render, ReferenceSphereGivesTheMatteReferenceContrast) {
  Scene sc;
  const double rb = 0.5, rt = 0.1;
  addUpRect(sc, -20, -20, 20, 20, 0.0, addMaterial(sc, MaterialType::kPlastic, rb));
  addUpRect(sc, -0.1, 0.9, 0.1, 1.1, 1e-3, addMaterial(sc, MaterialType::kPlastic, rt));
  LuminaireMounting lp;
  lp.positionM = {0.0, 1.0, 3.5};
  // A point luminaire (no opening): the point law below is exact, not an opening's sampled average.
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(1000.0, 0.0, 0.0), lp));
  // A wall behind (no light reflected with 0 bounces, no shadow cast); walls around would shut the
  // sphere out, so the reference keeps only the two surfaces seen.
  sc.addPolygon({{-3, 3, 0}, {3, 3, 0}, {3, 3, 3}, {-3, 3, 3}}, addMaterial(sc, MaterialType::kPlastic, 0.7));
  const Tracer tracer(sc);
  TraceSettings s;
  s.maxBounces = 0;
  const Vec3 eye(0.0, 0.0, 0.6), task(0.0, 1.0, 1e-3), background(0.0, 1.15, 0.0);
  const std::vector<uint32_t> keep = {shapeToward(tracer, eye, task), shapeToward(tracer, eye, background), 1u};
  EXPECT_EQ(keep[0], 1u);
  EXPECT_EQ(keep[1], 0u);
  const Scene refScene = referenceSphereScene(sc, keep, 100.0);
  EXPECT_EQ(refScene.shapes.size(), 2u);
  const Tracer ref(refScene);
  const double ct = luminanceContrast(luminanceToward(tracer, eye, task, s, 1), luminanceToward(tracer, eye, background, s, 2));
  const double lt = luminanceToward(ref, eye, task, s, 3), lb = luminanceToward(ref, eye, background, s, 4);
  EXPECT_NEAR(lt, rt * 100.0, 1e-9 * 100.0);
  EXPECT_NEAR(lb, rb * 100.0, 1e-9 * 100.0);
  const double cref = luminanceContrast(lt, lb);
  EXPECT_NEAR(cref, matteReferenceContrast(rt, rb), 1e-9);
  const auto e = [&](const Vec3& p) {
    const Vec3 d = lp.positionM - p;
    const double dist = glm::length(d);
    return sc.luminaires[0].intensityCd(-d / dist) * (d.z / dist) / (dist * dist);
  };
  const double ratio = e(task) / e(background);
  const double crf = contrastRenditionFactor(ct, cref);
  std::printf("[ measured ] reference sphere: C %.6f, C_ref %.6f, CRF %.6f (E_t/E_b %.6f)\n", ct, cref, crf, ratio);
  // (The estimate is taken 10⁻⁷ m off the surface, where the ray met it: 10⁻⁷ relative.)
  EXPECT_NEAR(ct, (rt * ratio - rb) / rb, 1e-7);
  EXPECT_NEAR(crf, (rt * ratio - rb) / (rt - rb), 1e-7);
  EXPECT_NEAR(crf, 1.0, 0.01);
}

}  // namespace
}  // namespace candela
