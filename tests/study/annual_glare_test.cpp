// Imageless annual glare (study/annual_glare.h) and its rendered check (study/annual_glare_check.h)
// against closed forms. A black room (no interreflection) with a 2 m × 1.2 m hole in its south
// wall; the eye 3 m behind the hole's centre looks straight at it. Sky and ground are uniform of
// luminance L in each hour, so the field of view is L inside the hole and 0 elsewhere, and
//   Ev = L · (projected solid angle of the rectangle)        (view factor of a rectangle)
//   Σ Ls² ωs / Ps² = L² ∫_hole dω / P²                        (a fine quadrature over the hole)
// plus, in one hour, the sun through the hole 6° above the line of sight with E_n known:
// Ev += E_n cos 6°, and the source term E_n² / (ω_sun P²) with P = Guth's index at τ = 0.
// Tolerances: 4 standard errors of the coefficients' Ev (their spread over independent streams),
// the tally's edge cells (a bound: 2 × the hole's angular perimeter × the cell size, in sr) and,
// for the image, its edge pixels likewise.
#include "study/annual_glare.h"
#include "study/annual_glare_check.h"

#include "engine/daylight.h"
#include "engine/radiance/reader.h"
#include "photometry/epw.h"
#include "photometry/make_sky.h"
#include "photometry/site.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace candela {
namespace {

const char* kBlackRoom = R"(
void plastic black 0 0 5 0 0 0 0 0
black polygon floor 0 0 12  0 0 0  0 4 0  4 4 0  4 0 0
black polygon ceiling 0 0 12  0 0 3  4 0 3  4 4 3  0 4 3
black polygon north 0 0 12  0 4 0  0 4 3  4 4 3  4 4 0
black polygon west 0 0 12  0 0 0  0 0 3  0 4 3  0 4 0
black polygon east 0 0 12  4 0 0  4 4 0  4 4 3  4 0 3
black polygon south_low 0 0 12  0 0 0  4 0 0  4 0 0.9  0 0 0.9
black polygon south_high 0 0 12  0 0 2.1  4 0 2.1  4 0 3  0 0 3
black polygon south_left 0 0 12  0 0 0.9  1 0 0.9  1 0 2.1  0 0 2.1
black polygon south_right 0 0 12  3 0 0.9  4 0 0.9  4 0 2.1  3 0 2.1
)";
// The hole: half-widths a (x) and b (z) at distance d from the eye.
constexpr double kA = 1.0, kB = 0.6, kD = 3.0;
const GlareView kView{"south", Vec3(2.0, 3.0, 1.5), Vec3(0.0, -1.0, 0.0)};
constexpr double kSunAltitudeDeg = 6.0, kSunNormalLux = 5000.0;

SkyDome uniformDome(double luminanceCdM2) {
  SkyConditions c;
  c.diffuseHorizontalLux = kPi * luminanceCdM2;
  SkyDome d;
  d.model = makeSky({SkyKind::kUniform}, c);
  d.groundLuminanceCdM2 = luminanceCdM2;
  d.horizontalSkyLux = c.diffuseHorizontalLux;
  return d;
}

Scene blackRoom(double skyCdM2) {
  Scene s;
  readRadianceText(kBlackRoom, "room.rad", s);
  s.sky = uniformDome(skyCdM2);
  return s;
}

// Four hours: uniform 5000 cd/m²; 3000 cd/m² with the sun in the hole; 1500 cd/m² (below the
// 2000 cd/m² source threshold); night.
const double kHourLuminance[4] = {5000.0, 3000.0, 1500.0, 0.0};

AnnualSky handSky() {
  AnnualSky sky;
  const SkyPatches patches(1);
  sky.subdivision = 1;
  sky.patchCount = patches.count();
  for (int i = 0; i < 4; ++i) {
    AnnualHour h;
    h.month = 6;
    h.day = 21;
    h.hour = 11 + i;
    h.dayOfYear = 172;
    if (i == 1) {
      h.sunUp = true;
      h.sunAltitudeDeg = kSunAltitudeDeg;
      h.sunAzimuthDeg = 180.0;
      h.sunDirTrue = directionFromAzAlt(180.0, kSunAltitudeDeg, 0.0);
      h.directNormalLux = kSunNormalLux;
      h.sunPatch = patches.indexOf(h.sunDirTrue);
    }
    sky.hours.push_back(h);
    for (int p = 0; p < sky.patchCount; ++p) sky.luminance.push_back(static_cast<float>(kHourLuminance[i]));
  }
  return sky;
}

TraceSettings testSettings() {
  TraceSettings s;
  s.hemisphereSamples = 1024;
  s.lightSamples = 1024;
  s.maxBounces = 2;
  s.method = Method::kPath;
  s.adaptiveFraction = 0.0;
  s.seed = 7;
  return s;
}

// Hand-computed geometry of the hole seen from the eye.
struct Hole {
  double projectedSolidAngle, solidAngle, inversePSquared, perimeterRad;
};

Hole handHole() {
  Hole h;
  const double A = kA / kD, B = kB / kD;
  // View factor of a rectangle with a corner on the normal (Howell's catalogue, C-11), × 4 × π.
  h.projectedSolidAngle = 2.0 * (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                                 B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B)));
  h.solidAngle = 4.0 * std::asin(std::sin(std::atan(A)) * std::sin(std::atan(B)));
  h.perimeterRad = 2.0 * (2.0 * std::atan(kA / std::hypot(kD, kB)) + 2.0 * std::atan(kB / std::hypot(kD, kA)));
  // ∫ dω / P² over the hole plane y = 0: dω = d dA / r³; view frame x = −X, y = +Z, z = −Y.
  const int nx = 800, nz = 480;
  double sum = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) {
      const double x = -kA + (i + 0.5) * 2 * kA / nx, z = -kB + (k + 0.5) * 2 * kB / nz;
      const double r = std::sqrt(x * x + z * z + kD * kD);
      const double p = positionIndex(Vec3(-x, z, kD));
      sum += kD / (r * r * r) * (2 * kA / nx) * (2 * kB / nz) / (p * p);
    }
  h.inversePSquared = sum;
  return h;
}

double handDgp(double ev, double sourceSum) {
  if (!(ev > 0.0)) return 0.0;
  double dgp = 5.87e-5 * ev + 9.18e-2 * std::log10(1.0 + sourceSum / std::pow(ev, 1.87)) + 0.16;
  if (ev < 1000.0) dgp *= std::exp(0.024 * ev - 4.0) / (1.0 + std::exp(0.024 * ev - 4.0));
  return std::min(dgp, 1.0);
}

// The largest change of handDgp over Ev ± dEv and the source term ± dS.
double dgpTolerance(double ev, double s, double dEv, double dS) {
  double worst = 0.0;
  for (double se : {-1.0, 1.0})
    for (double ss : {-1.0, 1.0})
      worst = std::max(worst, std::abs(handDgp(ev + se * dEv, std::max(0.0, s + ss * dS)) - handDgp(ev, s)));
  return worst + 1e-6;  // float storage
}

// The sensor's Ev per cd/m² of uniform sky and ground, from `streams` independent coefficient
// runs: mean and standard deviation of one run.
std::pair<double, double> evPerLuminanceSpread(const Tracer& tracer, int streams) {
  const SkyPatches patches(1);
  std::vector<double> v;
  for (int k = 0; k < streams; ++k) {
    const Vec3 n = glm::normalize(kView.direction);
    const SensorBlock b{std::span<const Vec3>(&kView.eyeM, 1), std::span<const Vec3>(&n, 1),
                        static_cast<uint64_t>(1000 + k)};
    const DaylightCoefficients dc = computeDaylightCoefficients(tracer, b, patches, testSettings(), 1);
    v.push_back(std::accumulate(dc.total.begin(), dc.total.end(), 0.0));
  }
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  double var = 0.0;
  for (double x : v) var += (x - mean) * (x - mean);
  return {mean, std::sqrt(var / (v.size() - 1))};
}

// The coefficients at the test's own settings (evPerLuminanceSpread's), not multiplied.
ImagelessGlareOptions plainOptions() {
  ImagelessGlareOptions o;
  o.evSampleFactor = 1;
  return o;
}

struct Year {
  AnnualSky sky = handSky();
  SunSet sunSet = indirectSunSet(sky);
  AnnualGlareJob job(int threads) const {
    AnnualGlareJob j;
    j.sky = &sky;
    j.sunSet = &sunSet;
    j.settings = testSettings();
    j.sunSamples = 16;
    j.threads = threads;
    return j;
  }
};

TEST(ImagelessAnnualGlare, HourlyDgpMatchesAHandCalculation) {
  const Scene scene = blackRoom(1.0);
  const Tracer tracer(scene);
  const Year y;
  const ViewAnnualGlare g = imagelessAnnualGlare(tracer, kView, kAnnualGlareStreamBase, y.job(0), plainOptions());
  const Hole hole = handHole();
  const auto [evPerL, sdPerL] = evPerLuminanceSpread(tracer, 8);
  const double cellRad = degToRad(90.0 / g.sky.rowsPer90Deg);
  const double tallyBoundSr = 2.0 * hole.perimeterRad * cellRad;
  // The sun: L = E_n / ω_sun over ω_sun, P at σ = 6°, τ = 0 (Guth, IES Lighting Handbook form).
  const double sigma = kSunAltitudeDeg;
  const double pSun = std::exp((35.2 - 1.22) * 1e-3 * sigma + 21e-5 * sigma * sigma);
  const double omegaSun = kTwoPi * (1.0 - std::cos(degToRad(0.2665)));
  const double sunTerm = kSunNormalLux * kSunNormalLux / omegaSun / (pSun * pSun);
  std::printf("[ measured ] Ev per cd/m2: closed form %.5f, coefficients %.5f (sd %.5f); hole: Ω %.4f sr, "
              "∫dω/P² %.4f sr, tally %.4f sr\n",
              hole.projectedSolidAngle, evPerL, sdPerL, hole.solidAngle, hole.inversePSquared,
              std::accumulate(g.sky.glareWeightSr.begin(), g.sky.glareWeightSr.end(), 0.0));
  EXPECT_NEAR(evPerL, hole.projectedSolidAngle, 4.0 * sdPerL / std::sqrt(8.0) + 1e-9);
  for (int h = 0; h < 4; ++h) {
    const double L = kHourLuminance[h];
    const bool sun = h == 1;
    double ev = L * hole.projectedSolidAngle + (sun ? kSunNormalLux * std::cos(degToRad(sigma)) : 0.0);
    const double s = (L > 2000.0 ? L * L * hole.inversePSquared : 0.0) + (sun ? sunTerm : 0.0);
    const double dEv = 4.0 * sdPerL * L + (sun ? 1e-4 * kSunNormalLux : 0.0);
    const double dS = L > 2000.0 ? L * L * tallyBoundSr : 0.0;
    const double want = handDgp(ev, s);
    std::printf("[ measured ] hour %d: Ev %.1f lx (hand %.1f), DGP %.4f (hand %.4f ± %.4f)\n", h, g.verticalLux[h], ev,
                g.dgp[h], want, dgpTolerance(ev, s, dEv, dS));
    EXPECT_NEAR(g.verticalLux[h], ev, dEv + 1e-3) << "hour " << h;
    EXPECT_NEAR(g.dgp[h], want, dgpTolerance(ev, s, dEv, dS)) << "hour " << h;
  }
  EXPECT_EQ(g.dgp[3], 0.0f);  // night: no daylight
  // The tally alone, against the quadrature, within its edge-cell bound.
  const double tally = std::accumulate(g.sky.glareWeightSr.begin(), g.sky.glareWeightSr.end(), 0.0);
  EXPECT_NEAR(tally, hole.inversePSquared, tallyBoundSr);
  const double seen = std::accumulate(g.sky.solidAngleSr.begin(), g.sky.solidAngleSr.end(), 0.0);
  EXPECT_NEAR(seen, hole.solidAngle, tallyBoundSr);
}

TEST(ImagelessAnnualGlare, ResultsDoNotDependOnTheThreadCount) {
  const Scene scene = blackRoom(1.0);
  const Tracer tracer(scene);
  const Year y;
  const ViewAnnualGlare one = imagelessAnnualGlare(tracer, kView, 5, y.job(1));
  const ViewAnnualGlare two = imagelessAnnualGlare(tracer, kView, 5, y.job(2));
  EXPECT_EQ(one.dgp, two.dgp);
  EXPECT_EQ(one.verticalLux, two.verticalLux);
  EXPECT_EQ(one.sky.glareWeightSr, two.sky.glareWeightSr);
}

TEST(ImagelessAnnualGlare, AgreesWithTheRenderedMethodUnderASkyWithoutSun) {
  // Hour 0 (uniform 5000 cd/m², no sun) both ways. The rendered Ev and the per-pixel source term
  // err at most by the hole's edge pixels (bound: perimeter × pixel size × L, in lux); evalglare's
  // grouping makes the hole one source of mean luminance L over Ω at the index of its mean
  // direction, the line of sight (P = 1).
  const Year y;
  const Scene dcScene = blackRoom(1.0);
  const Tracer dcTracer(dcScene);
  const ViewAnnualGlare g = imagelessAnnualGlare(dcTracer, kView, kAnnualGlareStreamBase, y.job(0), plainOptions());
  const Scene skyScene = blackRoom(kHourLuminance[0]);
  const Tracer tracer(skyScene);
  RenderedGlareOptions o;
  o.render.irradianceSamples = 0;  // black surfaces: nothing to estimate
  const RenderedGlare r = renderedGlare(tracer, kView, testSettings(), 0, GlareSourceThreshold{}, o);
  const Hole hole = handHole();
  const double L = kHourLuminance[0];
  const double pixelRad = kPi / o.resolutionPx;
  const double evBound = L * hole.perimeterRad * pixelRad;
  const double sBound = L * L * hole.perimeterRad * pixelRad;
  const double ev = L * hole.projectedSolidAngle;
  const auto [evPerL, sdPerL] = evPerLuminanceSpread(dcTracer, 8);
  const double dEvImageless = 4.0 * sdPerL * L;
  const double tallyBound = L * L * 2.0 * hole.perimeterRad * degToRad(90.0 / g.sky.rowsPer90Deg);
  std::printf("[ measured ] Ev: imageless %.1f, rendered %.1f, closed form %.1f lx; DGP: imageless %.4f, rendered "
              "per pixel %.4f, rendered grouped %.4f (%zu sources); render %.1f s\n",
              g.verticalLux[0], r.image.verticalIlluminanceLux, ev, g.dgp[0], r.dgpPerPixel, r.image.dgp,
              r.image.sources.size(), r.seconds);
  EXPECT_NEAR(r.image.verticalIlluminanceLux, ev, evBound);
  EXPECT_NEAR(r.sensorEvLux, ev, 4.0 * r.sensorEvStandardErrorLux + 1e-6 * ev);
  EXPECT_NEAR(r.image.verticalIlluminanceLux, g.verticalLux[0], evBound + dEvImageless);
  const double s = L * L * hole.inversePSquared;
  EXPECT_NEAR(r.dgpPerPixel, g.dgp[0],
              dgpTolerance(ev, s, evBound + dEvImageless, sBound + tallyBound));
  ASSERT_EQ(r.image.sources.size(), 1u);
  // The group's mean direction is the line of sight to within the pixels' asymmetry (< 0.25°).
  const double pMean = guthPositionIndex(0.0, 0.25);
  const double grouped = L * L * hole.solidAngle;
  EXPECT_NEAR(r.image.dgp, handDgp(ev, grouped),
              dgpTolerance(ev, grouped, evBound, sBound + grouped * (1.0 - 1.0 / (pMean * pMean))));
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

TEST(AnnualGlareCheck, HourSceneIsThePointInTimeSkyOfTheSkyVectorsHour) {
  // The rendered check's sky must be the hour the imageless method used: the same sun position,
  // the same Perez diffuse illuminance and the ground of ρ_g E_gh / π (annual_sky.h's definitions).
  const EpwFile epw = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  const Site site = makeSite(epw.location.latitudeDeg, epw.location.longitudeDeg, epw.location.elevationM,
                             epw.location.timezoneHours, 0.0);
  const AnnualSky sky = makeAnnualSky(epw, site, AnnualSkyOptions{});
  const Scene geometry = blackRoom(1.0);
  const HourSceneInput in{&geometry, &epw, &sky, 20.0, 0.2};
  int checked = 0;
  for (int h : {sunHours(sky)[100], sunHours(sky)[2000], sunHours(sky)[3500]}) {
    const AnnualHour& a = sky.hours[h];
    const Scene s = hourScene(in, h);
    ASSERT_TRUE(s.sky.has_value());
    EXPECT_NEAR(glm::length(s.sky->sunDirModel - trueToModel(a.sunDirTrue, 20.0)), 0.0, 1e-9);
    EXPECT_NEAR(s.sky->horizontalSkyLux, a.diffuseHorizontalLux, 1e-3 * a.diffuseHorizontalLux);
    EXPECT_NEAR(s.sky->groundLuminanceCdM2, sky.at(h, 0), 1e-3 * sky.at(h, 0));
    EXPECT_EQ(s.distant.size(), geometry.distant.size() + 1);  // the sun
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  const int night = 0;  // 1 January, 01:00
  EXPECT_THROW(hourScene(in, night), InputError);
}

}  // namespace
}  // namespace candela
