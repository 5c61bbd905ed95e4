#include "photometry/sky_perez.h"

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

// Upper bounds of the eight sky clearness bins (Perez et al. 1990, Table 1).
constexpr double kClearnessUpper[8] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 1e300};

// Perez, Seals & Michalsky (1993), Table 1: for each bin, x = x1 + x2 Z + Delta (x3 + x4 Z)
// with Z the solar zenith in radians; except in bin 1 where c = exp((Delta (c1 + c2 Z))^c3) - c4
// and d = -exp(Delta (d1 + d2 Z)) + d3 + Delta d4.
struct Coef4 {
  double x1, x2, x3, x4;
};
constexpr Coef4 kA[8] = {{1.3525, -0.2576, -0.2690, -1.4366}, {-1.2219, -0.7730, 1.4148, 1.1016},
                         {-1.1000, -0.2515, 0.8952, 0.0156},  {-0.5484, -0.6654, -0.2672, 0.7117},
                         {-0.6000, -0.3566, -2.5000, 2.3250}, {-1.0156, -0.3670, 1.0078, 1.4051},
                         {-1.0000, 0.0211, 0.5025, -0.5119},  {-1.0500, 0.0289, 0.4260, 0.3590}};
constexpr Coef4 kB[8] = {{-0.7670, 0.0007, 1.2734, -0.1233}, {-0.2054, 0.0367, -3.9128, 0.9156},
                         {0.2782, -0.1812, -4.5000, 1.1766},  {0.7234, -0.6219, -5.6812, 2.6297},
                         {0.2937, 0.0496, -5.6812, 1.8415},   {0.2875, -0.5328, -3.8500, 3.3750},
                         {-0.3000, 0.1922, 0.7023, -1.6317},  {-0.3250, 0.1156, 0.7781, 0.0025}};
constexpr Coef4 kC[8] = {{2.8000, 0.6004, 1.2375, 1.0000},     {6.9750, 0.1774, 6.4477, -0.1239},
                         {24.7219, -13.0812, -37.7000, 34.8438}, {33.3389, -18.3000, -62.2500, 52.0781},
                         {21.0000, -4.7656, -21.5906, 7.2492},   {14.0000, -0.9999, -7.1406, 7.5469},
                         {19.0000, -5.0000, 1.2438, -1.9094},    {31.0625, -14.5000, -46.1148, 55.3750}};
constexpr Coef4 kD[8] = {{1.8734, 0.6297, 0.9738, 0.2809},   {-1.5798, -0.5081, -1.7812, 0.1080},
                         {-5.0000, 1.5218, 3.9229, -2.6204}, {-3.5000, 0.0016, 1.1477, 0.1062},
                         {-3.5000, -0.1554, 1.4062, 0.3988}, {-3.4000, -0.1078, -1.0750, 1.5702},
                         {-4.0000, 0.0250, 0.3844, 0.2656},  {-7.2312, 0.4050, 13.3500, 0.6234}};
constexpr Coef4 kE[8] = {{0.0356, -0.1246, -0.5718, 0.9938}, {0.2624, 0.0672, -0.2190, -0.4285},
                         {-0.0156, 0.1597, 0.4199, -0.5562}, {0.4659, -0.3296, -0.0876, -0.0329},
                         {0.0032, 0.0766, -0.0656, -0.1294}, {-0.0672, 0.4016, 0.3017, -0.4844},
                         {1.0468, -0.3788, -2.4517, 1.4656}, {1.5000, -0.6426, 1.8564, 0.5636}};

// Perez et al. (1990), Table 4: luminous efficacy, lm/W, per clearness bin:
// diffuse  = a + b W + c cos Z + d ln(Delta),
// direct   = max(0, a + b W + c exp(5.73 Z - 5) + d Delta), Z in radians, W in cm.
constexpr Coef4 kDiffuseEff[8] = {{97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},
                                  {104.97, 2.96, -5.53, -8.77},   {102.39, 5.59, -13.95, -13.90},
                                  {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
                                  {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98}};
constexpr Coef4 kDirectEff[8] = {{57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},
                                 {109.83, -4.90, -1.71, -8.81}, {110.34, -5.84, -1.99, -4.56},
                                 {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
                                 {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29}};

double linear(const Coef4& k, double z, double delta) { return k.x1 + k.x2 * z + delta * (k.x3 + k.x4 * z); }

}  // namespace

int perezClearnessBin(double epsilon) {
  int bin = 1;
  while (bin < 8 && epsilon >= kClearnessUpper[bin - 1]) ++bin;
  return bin;
}

PerezCoefficients perezCoefficients(int bin, double zenith, double dl) {
  const int i = std::clamp(bin, 1, 8) - 1;
  PerezCoefficients k;
  k.a = linear(kA[i], zenith, dl);
  k.b = linear(kB[i], zenith, dl);
  k.e = linear(kE[i], zenith, dl);
  if (i == 0) {
    k.c = std::exp(std::pow(dl * (kC[0].x1 + kC[0].x2 * zenith), kC[0].x3)) - kC[0].x4;
    k.d = -std::exp(dl * (kD[0].x1 + kD[0].x2 * zenith)) + kD[0].x3 + dl * kD[0].x4;
  } else {
    k.c = linear(kC[i], zenith, dl);
    k.d = linear(kD[i], zenith, dl);
  }
  return k;
}

double perezDiffuseEfficacy(int bin, double w, double zenith, double delta) {
  const Coef4& k = kDiffuseEff[std::clamp(bin, 1, 8) - 1];
  return k.x1 + k.x2 * w + k.x3 * std::cos(zenith) + k.x4 * std::log(delta);
}

double perezDirectEfficacy(int bin, double w, double zenith, double delta) {
  const Coef4& k = kDirectEff[std::clamp(bin, 1, 8) - 1];
  return k.x1 + k.x2 * w + k.x3 * std::exp(5.73 * zenith - 5.0) + k.x4 * delta;
}

double extraterrestrialNormalWm2(int dayOfYear) {
  const double g = kTwoPi * (dayOfYear - 1) / 365.0;  // Spencer's day angle
  return 1367.0 * (1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
                   0.000077 * std::sin(2 * g));
}

double relativeAirMass(double zenithDeg) {
  const double z = std::min(zenithDeg, 90.0);
  return 1.0 / (std::cos(degToRad(z)) + 0.50572 * std::pow(96.07995 - z, -1.6364));
}

PerezSky::PerezSky(const PerezInput& in, const FileLoc& loc) : sun_(glm::normalize(in.sunDirTrue)) {
  if (!(in.directNormalWm2 >= 0.0 && std::isfinite(in.directNormalWm2)))
    throw InputError(loc, "perez sky: direct normal irradiance must be >= 0 W/m2");
  if (!(in.diffuseHorizontalWm2 >= 0.0 && std::isfinite(in.diffuseHorizontalWm2)))
    throw InputError(loc, "perez sky: diffuse horizontal irradiance must be >= 0 W/m2");
  if (in.dayOfYear < 1 || in.dayOfYear > 366) throw InputError(loc, "perez sky: day of year must be 1..366");

  // The model is defined for the sun above the horizon; twilight hours with diffuse light are
  // evaluated with the sun on the horizon and no direct component.
  const double sunAlt = std::asin(std::clamp(sun_.z, -1.0, 1.0));
  const double zenith = 0.5 * kPi - std::max(0.0, sunAlt);  // radians
  const double dni = sunAlt > 0.0 ? in.directNormalWm2 : 0.0;
  const double dhi = in.diffuseHorizontalWm2;

  // Perez et al. (1990) eq. 1 (kappa = 1.041 for Z in radians) and eq. 2.
  const double z3 = 1.041 * zenith * zenith * zenith;
  epsilon_ = dhi > 0.0 ? ((dhi + dni) / dhi + z3) / (1.0 + z3) : 1.0;
  delta_ = dhi * relativeAirMass(radToDeg(zenith)) / extraterrestrialNormalWm2(in.dayOfYear);
  bin_ = perezClearnessBin(epsilon_);
  // Precipitable water from the dew point (Perez 1990, after Wright, Perez & Michalsky 1989).
  w_ = in.dewPointC ? std::exp(0.07 * *in.dewPointC - 0.075) : 2.0;

  // The distribution was fitted for Delta within ~[0.01, 0.6]; outside, the gradation term can
  // turn positive and grow without bound towards the horizon, so Delta is clamped for it.
  const double dl = std::clamp(delta_, 0.01, 0.6);
  const int i = bin_ - 1;
  const PerezCoefficients k = perezCoefficients(bin_, zenith, dl);
  a_ = k.a;
  b_ = k.b;
  c_ = k.c;
  d_ = k.d;
  e_ = k.e;
  // A positive b (possible at the extremes of the fitted range) makes exp(b / cos Z) diverge at
  // the horizon; no sky does that, so the gradation is capped at its horizon value for b = 0.
  b_ = std::min(b_, 0.0);

  const double dEff = std::max(delta_, 0.001);  // ln(Delta) needs Delta > 0
  diffuseEfficacy_ = dhi > 0.0 ? std::max(0.0, kDiffuseEff[i].x1 + kDiffuseEff[i].x2 * w_ +
                                                   kDiffuseEff[i].x3 * std::cos(zenith) + kDiffuseEff[i].x4 * std::log(dEff))
                               : 0.0;
  directEfficacy_ = std::max(0.0, kDirectEff[i].x1 + kDirectEff[i].x2 * w_ +
                                      kDirectEff[i].x3 * std::exp(5.73 * zenith - 5.0) + kDirectEff[i].x4 * delta_);
  diffuseLux_ = dhi * diffuseEfficacy_;
  directLux_ = dni * directEfficacy_;
  if (in.calibrate) calibrate(diffuseLux_);
}

double PerezSky::coefficient(char which) const {
  switch (which) {
    case 'a': return a_;
    case 'b': return b_;
    case 'c': return c_;
    case 'd': return d_;
    case 'e': return e_;
    default: return 0.0;
  }
}

double PerezSky::relativeLuminance(const Vec3& d) const {
  const double cosGamma = std::clamp(glm::dot(d, sun_), -1.0, 1.0);
  const double gamma = std::acos(cosGamma);
  const double grad = d.z > 0.0 ? 1.0 + a_ * std::exp(b_ / d.z) : 1.0 + (b_ < 0.0 ? 0.0 : a_);
  const double ind = 1.0 + c_ * std::exp(d_ * gamma) + e_ * cosGamma * cosGamma;
  // Some coefficient combinations give small negative values near the anti-solar point;
  // luminance cannot be negative.
  return std::max(0.0, grad * ind);
}

}  // namespace candela
