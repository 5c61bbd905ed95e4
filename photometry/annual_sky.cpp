#include "photometry/annual_sky.h"

#include "base/parallel.h"

#include "photometry/sky_patches.h"
#include "photometry/sky_perez.h"
#include "photometry/sun_spa.h"


#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace candela {

namespace {

// The sun's disc as in engine/daylight.cpp (kSunDiameterDeg there): 0.533 deg across.
constexpr double kSunDiameterDeg = 0.533;

// n-point Gauss-Legendre nodes and weights on [-1, 1] by Newton's iteration on P_n from the
// Chebyshev-like initial guess cos(pi (i + 3/4) / (n + 1/2)) (Abramowitz & Stegun 25.4.29 and
// Press et al., Numerical Recipes, sec. 4.6); converges to machine precision in a few steps.
struct GaussRule {
  std::vector<double> x, w;
};

GaussRule gaussLegendre(int n) {
  GaussRule g;
  g.x.resize(n);
  g.w.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = z;  // P_0, P_1; recurrence (k+1) P_{k+1} = (2k+1) z P_k - k P_{k-1}
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * z * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);  // P_n'(z)
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-15) break;
    }
    g.x[i] = -z;
    g.x[n - 1 - i] = z;
    g.w[i] = g.w[n - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
  return g;
}

// Quadrature points of every sky patch: directions and weights normalised to sum to 1 per patch,
// so that the weighted sum of luminances is the patch mean. Points are a product Gauss-Legendre
// rule in (azimuth, sin altitude); d(omega) = d(sin h) d(az), so the weights need no Jacobian.
// The layout repeats sky_patches.h's (rows of height alpha from the horizon, patches centred on
// multiples of their width from north, zenith cap) and is checked against SkyPatches::indexOf in
// the tests.
struct PatchRule {
  std::vector<Vec3> dir;
  std::vector<double> weight;
  std::vector<int> start;  // points of patch p (p >= 1) are [start[p], start[p + 1])
};

PatchRule makePatchRule(const SkyPatches& patches, int m) {
  static const int kTregenza[7] = {30, 30, 24, 24, 18, 12, 6};
  const int n = patches.multiplier();
  const double alpha = patches.rowHeightRad();
  const GaussRule g = gaussLegendre(m);
  const int mCap = 4 * m;  // the cap spans the full circle of azimuth
  const GaussRule gCap = gaussLegendre(mCap);
  PatchRule rule;
  rule.start.assign(size_t(patches.count()) + 1, 0);
  const auto addCell = [&](double mu0, double mu1, double az0, double az1, const GaussRule& ga) {
    double sum = 0.0;
    const size_t first = rule.dir.size();
    for (int i = 0; i < m; ++i) {
      const double mu = 0.5 * (mu0 + mu1) + 0.5 * (mu1 - mu0) * g.x[i];
      const double c = std::sqrt(std::max(0.0, 1.0 - mu * mu));
      for (size_t j = 0; j < ga.x.size(); ++j) {
        const double az = 0.5 * (az0 + az1) + 0.5 * (az1 - az0) * ga.x[j];
        rule.dir.emplace_back(c * std::sin(az), c * std::cos(az), mu);
        rule.weight.push_back(g.w[i] * ga.w[j]);
        sum += g.w[i] * ga.w[j];
      }
    }
    for (size_t k = first; k < rule.weight.size(); ++k) rule.weight[k] /= sum;
  };
  int p = 1;
  for (int r = 0; r < 7 * n; ++r) {
    const int count = n * kTregenza[r / n];
    const double width = kTwoPi / count;
    const double mu0 = std::sin(r * alpha), mu1 = std::sin((r + 1) * alpha);
    for (int k = 0; k < count; ++k, ++p) {
      rule.start[p] = int(rule.dir.size());
      addCell(mu0, mu1, (k - 0.5) * width, (k + 0.5) * width, g);
    }
  }
  rule.start[p] = int(rule.dir.size());  // the zenith cap
  addCell(std::sin(7 * n * alpha), 1.0, 0.0, kTwoPi, gCap);
  rule.start[p + 1] = int(rule.dir.size());
  if (p + 1 != patches.count()) throw std::logic_error("annual sky: patch layout differs from SkyPatches");
  return rule;
}

// A value from the weather file, or 0 (counted) when missing or negative.
double usable(double v, int* missing) {
  if (std::isfinite(v) && v >= 0.0) return v;
  ++*missing;
  return 0.0;
}

}  // namespace

double perezRelativeHorizontal(const SkyModel& sky, const Vec3& sunDirTrue) {
  // Sun-centred polar coordinates: d = cos(g) s + sin(g) (cos(psi) u + sin(psi) v), d(omega) =
  // sin(g) dg dpsi, with u the unit vector perpendicular to s in the vertical plane through s
  // (upwards). The Perez shape depends on g and the height z = cos(g) s.z + sin(g) cos(psi) u.z
  // only, so the psi range is symmetric: z > 0 for cos(psi) > -cos(g) s.z / (sin(g) u.z), and
  // the whole ring is above the horizon for g < sun altitude, none of it for g > pi - altitude.
  // Both are panel boundaries, so the only non-smooth points of the integrand lie on them.
  static const GaussRule kRingRule = gaussLegendre(24);  // psi, on [0, psi_max]
  static const GaussRule kGammaRule = gaussLegendre(8);   // gamma, per panel
  constexpr double kPanelRad = 15.0 * kPi / 180.0;

  const Vec3 s = glm::normalize(sunDirTrue);
  const double sz = std::clamp(s.z, 0.0, 1.0);
  const double altS = std::asin(sz);
  Vec3 u(0.0, 0.0, 1.0);
  u -= sz * s;
  if (glm::length(u) < 1e-9) u = Vec3(1.0, 0.0, 0.0);  // sun at the zenith: any horizontal u
  u = glm::normalize(u);
  const Vec3 v = glm::cross(s, u);

  const auto ring = [&](double gamma) {
    const double cg = std::cos(gamma), sg = std::sin(gamma);
    const double a = cg * sz, b = sg * u.z;  // z = a + b cos(psi)
    double psiMax = kPi;
    if (b <= 1e-14) {
      if (a <= 0.0) return 0.0;
    } else {
      const double k = -a / b;
      if (k >= 1.0) return 0.0;
      if (k > -1.0) psiMax = std::acos(k);
    }
    double sum = 0.0;
    for (size_t i = 0; i < kRingRule.x.size(); ++i) {
      const double psi = 0.5 * psiMax * (1.0 + kRingRule.x[i]);
      const Vec3 d = cg * s + sg * (std::cos(psi) * u + std::sin(psi) * v);
      const double z = a + b * std::cos(psi);
      if (z > 0.0) sum += kRingRule.w[i] * sky.relativeLuminance(d) * z;
    }
    return 2.0 * 0.5 * psiMax * sum * sg;  // both halves of the ring; Jacobian sin(g)
  };
  const auto interval = [&](double g0, double g1) {
    if (g1 <= g0) return 0.0;
    const int panels = std::max(1, int(std::ceil((g1 - g0) / kPanelRad - 1e-9)));
    const double h = (g1 - g0) / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p)
      for (size_t i = 0; i < kGammaRule.x.size(); ++i)
        sum += kGammaRule.w[i] * ring(g0 + (p + 0.5) * h + 0.5 * h * kGammaRule.x[i]);
    return 0.5 * h * sum;
  };
  return interval(0.0, altS) + interval(altS, kPi - altS);
}

namespace {

void checkOptions(const AnnualSkyOptions& options) {
  if (options.subdivision < 1 || options.subdivision > 64)
    throw InputError({}, "annual sky: the sky subdivision (Reinhart MF) must be 1..64");
  if (options.subSamples < 1 || options.subSamples > 64)
    throw InputError({}, "annual sky: patch sub-samples must be 1..64");
  if (!(options.groundReflectance >= 0.0 && options.groundReflectance <= 1.0))
    throw InputError({}, "annual sky: the ground reflectance must be in [0, 1]");
}

// What every hour shares (patch layout and quadrature, site, options), and the counts of the
// hours' problems: atomic, as the hours run in parallel.
struct AnnualSkyJob {
  const SkyPatches& patches;
  const PatchRule& rule;
  const Site& site;
  const AnnualSkyOptions& options;
  int patchCount;
  // The disc's horizontal illuminance per unit direct normal illuminance and sin(altitude).
  double discFactor;
  std::atomic<int> missingValues{0}, missingHours{0}, degenerateHours{0};
};

// The hour's calendar fields and the sun's position at the middle of the hour-ending record.
SpaResult hourAndSun(const AnnualSkyJob& job, const EpwRecord& rec, AnnualHour& hour) {
  const Site& site = job.site;
  hour.month = rec.month;
  hour.day = rec.day;
  hour.hour = rec.hour;
  LocalTime t;
  t.year = rec.year;
  t.month = rec.month;
  t.day = rec.day;
  hour.dayOfYear = std::clamp(t.dayOfYear(), 1, 366);

  SpaInput in;
  in.year = rec.year;
  in.month = rec.month;
  in.day = rec.day;
  in.hourOfDay = rec.hour - 0.5;  // the middle of the hour-ending record
  in.timezoneHours = site.timezoneHours;
  in.latitudeDeg = site.latitudeDeg;
  in.longitudeDeg = site.longitudeDeg;
  in.elevationM = site.elevationM;
  in.deltaTSec = estimateDeltaTSec(rec.year + (hour.dayOfYear - 0.5) / 365.25);
  const SpaResult sun = computeSunPositionOnly(in);
  hour.sunAltitudeDeg = sun.altitudeDeg;
  hour.sunAzimuthDeg = sun.azimuthDeg;
  hour.sunUp = sun.altitudeDeg > 0.0;
  hour.sunDirTrue = directionFromAzAlt(sun.azimuthDeg, sun.altitudeDeg, 0.0);
  hour.sunPatch = hour.sunUp ? job.patches.indexOf(hour.sunDirTrue) : -1;
  return sun;
}

// The hour's Perez sky: its illuminances in `hour` and the patch luminances in lum[0..patchCount)
// (lum[0] the ground), left at 0 at night or when the record holds no light.
void skyHour(AnnualSkyJob& job, const EpwRecord& rec, const SpaResult& sun, AnnualHour& hour, float* lum) {
  const PatchRule& rule = job.rule;
  int missing = 0;
  const double dni = usable(rec.directNormalWhm2, &missing);
  const double dhi = usable(rec.diffuseHorizontalWhm2, &missing);
  job.missingValues += missing;
  job.missingHours += missing > 0;
  if (dhi <= 0.0 && (dni <= 0.0 || !hour.sunUp)) return;  // night, or no light recorded

  PerezInput pin;
  pin.directNormalWm2 = dni;
  pin.diffuseHorizontalWm2 = dhi;
  // As engine/daylight.cpp: the sky's sun is clamped to the horizon.
  pin.sunDirTrue = directionFromAzAlt(sun.azimuthDeg, std::max(sun.altitudeDeg, 0.0), 0.0);
  pin.dayOfYear = hour.dayOfYear;
  pin.calibrate = false;
  const PerezSky sky(pin, FileLoc{"", rec.line, 0});

  hour.diffuseHorizontalLux = sky.diffuseHorizontalIlluminanceLux();
  hour.directNormalLux = hour.sunUp ? sky.directNormalIlluminanceLux() : 0.0;
  double skyLux = 0.0;
  if (hour.diffuseHorizontalLux > 0.0) {
    const double relH = perezRelativeHorizontal(sky, pin.sunDirTrue);
    // A Perez shape that is <= 0 everywhere (possible at the edges of the fitted ranges, see
    // AnnualSky::degenerateHours) gives a black sky, as PerezSky's calibrate does.
    const double scale = relH > 0.0 ? hour.diffuseHorizontalLux / relH : 0.0;
    job.degenerateHours += relH <= 0.0;
    skyLux = scale * relH;
    for (int p = 1; p < job.patchCount; ++p) {
      double mean = 0.0;
      for (int k = rule.start[p]; k < rule.start[p + 1]; ++k) mean += rule.weight[k] * sky.relativeLuminance(rule.dir[k]);
      lum[p] = float(scale * mean);
    }
  }
  const double sunLux = hour.directNormalLux > 0.0
                            ? hour.directNormalLux * std::sin(degToRad(hour.sunAltitudeDeg)) * job.discFactor
                            : 0.0;
  hour.globalHorizontalLux = skyLux + sunLux;
  lum[0] = float(job.options.groundReflectance * hour.globalHorizontalLux / kPi);
}

}  // namespace

AnnualSky makeAnnualSky(const EpwFile& epw, const Site& site, const AnnualSkyOptions& options) {
  checkOptions(options);
  const SkyPatches patches(options.subdivision);
  const PatchRule rule = makePatchRule(patches, options.subSamples);
  AnnualSky out;
  out.subdivision = options.subdivision;
  out.patchCount = patches.count();
  const size_t nHours = epw.records.size();
  out.hours.resize(nHours);
  out.luminance.assign(nHours * size_t(out.patchCount), 0.0f);
  const double halfSun = degToRad(0.5 * kSunDiameterDeg);
  // The disc's horizontal illuminance per unit direct normal illuminance and sin(altitude):
  // pi sin^2(a) / (2 pi (1 - cos a)) = (1 + cos a) / 2, as engine/daylight.cpp's cap formula.
  const double discFactor = 0.5 * (1.0 + std::cos(halfSun));
  AnnualSkyJob job{patches, rule, site, options, out.patchCount, discFactor};

  // Each hour writes only its own slots, so the result does not depend on the thread count.
  parallelFor(nHours, options.threads, [&](size_t h) {
    const EpwRecord& rec = epw.records[h];
    AnnualHour& hour = out.hours[h];
    const SpaResult sun = hourAndSun(job, rec, hour);
    skyHour(job, rec, sun, hour, &out.luminance[h * size_t(out.patchCount)]);
  });
  out.missingValues = job.missingValues;
  out.missingHours = job.missingHours;
  out.degenerateHours = job.degenerateHours;
  return out;
}

std::vector<float> patchMeanLuminance(const SkyModel& sky, int subdivision, double groundReflectance, int subSamples) {
  const SkyPatches patches(subdivision);
  const PatchRule rule = makePatchRule(patches, subSamples);
  std::vector<float> lum(size_t(patches.count()), 0.0f);
  for (int p = 1; p < patches.count(); ++p) {
    double mean = 0.0;
    for (int k = rule.start[p]; k < rule.start[p + 1]; ++k) mean += rule.weight[k] * sky.luminance(rule.dir[k]);
    lum[p] = float(mean);
  }
  lum[0] = float(groundReflectance * sky.horizontalIlluminanceLux() / kPi);
  return lum;
}

}  // namespace candela
