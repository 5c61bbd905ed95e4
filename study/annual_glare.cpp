#include "study/annual_glare.h"

#include "base/parallel.h"
#include "base/units.h"
#include "engine/daylight.h"
#include "engine/sampling.h"
#include "photometry/site.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {

namespace {

double secondsFrom(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Photopic transmittance from the eye to infinity along `dir` (0 behind anything opaque).
double seenTransmittance(const Tracer& tracer, const Vec3& eye, const Vec3& dir) {
  return photopic(tracer.transmittance(eye, dir, std::numeric_limits<double>::infinity(), kNoShape, kNoShape));
}

}  // namespace

ViewFrame viewFrame(const Vec3& direction) {
  ViewFrame f;
  f.forward = glm::normalize(direction);
  const Vec3 up = std::abs(f.forward.z) > std::cos(degToRad(0.1)) ? Vec3(0.0, 1.0, 0.0) : Vec3(0.0, 0.0, 1.0);
  f.right = glm::normalize(glm::cross(f.forward, up));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

double GlareSourceThreshold::imagelessCdM2(double evLux) const {
  return fixedCdM2 > 0.0 ? fixedCdM2 : factorOfMean * evLux / kPi;
}

double sunSolidAngleSr() { return kTwoPi * (1.0 - std::cos(degToRad(0.5 * kSunDiameterDeg))); }

GlareSource SkyViewTally::source(int p, double luminanceCdM2) const {
  GlareSource s;
  const double omega = solidAngleSr[p], w = glareWeightSr[p];
  if (!(omega > 0.0) || !(w > 0.0)) return s;
  const double tau = transmittedSr[p] / omega;
  s.luminanceCdM2 = tau * luminanceCdM2;
  s.solidAngleSr = omega;
  s.positionIndex = std::sqrt(tau * tau * omega / w);  // (τL)² ω / P² = L² Σ τ²ω/P²
  return s;
}

SkyViewTally skyViewTally(const Tracer& tracer, const GlareView& view, const SkyPatches& patches, double northDeg,
                          int rowsPer90Deg, int threads) {
  if (rowsPer90Deg < 1) throw std::invalid_argument("skyViewTally: rowsPer90Deg must be >= 1");
  const ViewFrame frame = viewFrame(view.direction);
  const int rows = rowsPer90Deg, cols = 4 * rowsPer90Deg, np = patches.count();
  const double dTheta = 0.5 * kPi / rows, dPhi = kTwoPi / cols;
  // Row-wise partial sums, added in row order afterwards (no dependence on the thread count).
  std::vector<double> part(static_cast<size_t>(rows) * np * 3, 0.0);
  parallelFor(static_cast<size_t>(rows), threads, [&](size_t i) {
    double* omegaRow = part.data() + i * np * 3;
    double* tauRow = omegaRow + np;
    double* weightRow = tauRow + np;
    const double t0 = i * dTheta, t1 = (i + 1) * dTheta, tm = (i + 0.5) * dTheta;
    const double omega = (std::cos(t0) - std::cos(t1)) * dPhi;  // exact solid angle of the cell
    for (int j = 0; j < cols; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const Vec3 dv(std::sin(tm) * std::cos(phi), std::sin(tm) * std::sin(phi), std::cos(tm));
      const Vec3 d = frame.toModel(dv);
      const double tau = seenTransmittance(tracer, view.eyeM, d);
      if (!(tau > 0.0)) continue;
      const int p = patches.indexOf(modelToTrue(d, northDeg));
      const double pi = positionIndex(dv);
      omegaRow[p] += omega;
      tauRow[p] += tau * omega;
      weightRow[p] += tau * tau * omega / (pi * pi);
    }
  });
  SkyViewTally t;
  t.rowsPer90Deg = rows;
  t.solidAngleSr.assign(np, 0.0);
  t.transmittedSr.assign(np, 0.0);
  t.glareWeightSr.assign(np, 0.0);
  for (int i = 0; i < rows; ++i)
    for (int p = 0; p < np; ++p) {
      const double* row = part.data() + static_cast<size_t>(i) * np * 3;
      t.solidAngleSr[p] += row[p];
      t.transmittedSr[p] += row[np + p];
      t.glareWeightSr[p] += row[2 * np + p];
    }
  return t;
}

GlareSource SunViewTally::source(std::size_t j, double directNormalLux) const {
  GlareSource s;
  if (!(visibleFraction[j] > 0.0f)) return s;
  const double omega = sunSolidAngleSr();
  s.luminanceCdM2 = rmsTransmittance[j] * directNormalLux / omega;
  s.solidAngleSr = visibleFraction[j] * omega;
  s.positionIndex = positionIndex[j];
  return s;
}

SunViewTally sunViewTally(const Tracer& tracer, const GlareView& view, const std::vector<Vec3>& sunDirsModel,
                          int samples, int threads) {
  const ViewFrame frame = viewFrame(view.direction);
  const int n = std::max(1, samples);
  const double cosMax = std::cos(degToRad(0.5 * kSunDiameterDeg));
  SunViewTally t;
  t.visibleFraction.assign(sunDirsModel.size(), 0.0f);
  t.rmsTransmittance.assign(sunDirsModel.size(), 0.0f);
  t.positionIndex.assign(sunDirsModel.size(), 16.0f);
  parallelFor(sunDirsModel.size(), threads, [&](size_t j) {
    const Vec3& sun = sunDirsModel[j];
    const Vec3 sv = frame.toView(sun);
    if (!(sv.z > 0.0)) return;  // outside the forward hemisphere: not in the field of view
    const Frame disc = Frame::fromNormal(sun);
    int visible = 0;
    double sum2 = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        // Cell centres of an n × n grid in the cone's equal-area parameters.
        const Vec3 d = disc.toWorld(sampleUniformCone((a + 0.5) / n, (b + 0.5) / n, cosMax));
        if (!(glm::dot(d, frame.forward) > 0.0)) continue;
        const double tau = seenTransmittance(tracer, view.eyeM, d);
        if (!(tau > 0.0)) continue;
        ++visible;
        sum2 += tau * tau;
      }
    if (visible == 0) return;
    t.visibleFraction[j] = static_cast<float>(static_cast<double>(visible) / (n * n));
    t.rmsTransmittance[j] = static_cast<float>(std::sqrt(sum2 / visible));
    t.positionIndex[j] = static_cast<float>(positionIndex(sv));
  });
  return t;
}

TraceSettings interreflectedSunSettings(const TraceSettings& settings) {
  TraceSettings s = settings;
  s.hemisphereSamples = std::max(64, settings.hemisphereSamples / 8);
  s.firstBounceSplit = std::max(1, settings.firstBounceSplit / 4);
  return s;
}

std::vector<float> imagelessHourlyDgp(std::span<const float> verticalLux, const AnnualSky& sky,
                                      const SkyViewTally& skyTally, const SunViewTally& sun,
                                      const ImagelessGlareOptions& options) {
  const size_t nh = sky.hours.size();
  const int np = sky.patchCount;
  if (verticalLux.size() != nh) throw std::invalid_argument("imagelessHourlyDgp: one Ev per hour expected");
  if (skyTally.solidAngleSr.size() != static_cast<size_t>(np))
    throw std::invalid_argument("imagelessHourlyDgp: the sky tally has another patch count than the sky");
  const std::vector<int> sunHour = sunHours(sky);
  if (sun.visibleFraction.size() != sunHour.size())
    throw std::invalid_argument("imagelessHourlyDgp: one sun tally entry per sun hour expected");
  std::vector<int> sunIndex(nh, -1);
  for (size_t j = 0; j < sunHour.size(); ++j) sunIndex[sunHour[j]] = static_cast<int>(j);
  // Patches seen at all: the only ones that can be sources.
  std::vector<int> seen;
  for (int p = 0; p < np; ++p)
    if (skyTally.glareWeightSr[p] > 0.0) seen.push_back(p);

  std::vector<float> dgp(nh, 0.0f);
  std::vector<GlareSource> sources;
  sources.reserve(seen.size() + 1);
  for (size_t h = 0; h < nh; ++h) {
    const double ev = verticalLux[h];
    if (!(ev > 0.0)) continue;  // no daylight: DGP 0, as metrics' formula and dcglare give
    const double threshold = options.threshold.imagelessCdM2(ev);
    sources.clear();
    for (int p : seen) {
      const GlareSource s = skyTally.source(p, sky.at(static_cast<int>(h), p));
      if (s.luminanceCdM2 > threshold) sources.push_back(s);
    }
    if (sunIndex[h] >= 0) {
      const GlareSource s = sun.source(static_cast<size_t>(sunIndex[h]), sky.hours[h].directNormalLux);
      if (s.luminanceCdM2 > threshold) sources.push_back(s);
    }
    dgp[h] = static_cast<float>(daylightGlareProbability(ev, sources, options.lowLightCorrection));
  }
  return dgp;
}

ViewAnnualGlare imagelessAnnualGlare(const Tracer& tracer, const GlareView& view, uint64_t stream,
                                     const AnnualGlareJob& job, const ImagelessGlareOptions& options) {
  if (!job.sky || !job.sunSet) throw std::invalid_argument("imagelessAnnualGlare: the job needs its sky and sun set");
  const AnnualSky& sky = *job.sky;
  ViewAnnualGlare out;
  const auto t0 = std::chrono::steady_clock::now();
  // Ev: one sensor at the eye facing the line of sight, through the annual machinery.
  TraceSettings settings = job.settings;
  settings.method = Method::kPath;  // coefficients are path traced (skyCoefficients)
  const int factor = std::max(1, options.evSampleFactor);
  settings.hemisphereSamples *= factor;
  settings.lightSamples *= factor;
  const Vec3 eye = view.eyeM, normal = glm::normalize(view.direction);
  const SensorBlock block{std::span<const Vec3>(&eye, 1), std::span<const Vec3>(&normal, 1), stream};
  const SkyPatches patches(sky.subdivision);
  const std::vector<Vec3> suns = sunDirectionsModel(sky, job.northDeg);
  std::vector<Vec3> setModel;
  for (const Vec3& d : job.sunSet->dirsTrue) setModel.push_back(trueToModel(d, job.northDeg));
  const DaylightCoefficients dc = computeDaylightCoefficients(tracer, block, patches, settings, job.threads);
  const std::vector<float> direct =
      directSunCoefficients(tracer, block, suns, job.sunSamples, settings.seed, job.threads);
  const std::vector<float> inter =
      indirectSunCoefficients(tracer, block, setModel, interreflectedSunSettings(settings), job.threads);
  const AnnualIlluminance year = annualIlluminance(dc, direct, inter, *job.sunSet, sky, job.threads);
  out.verticalLux = year.total;
  out.coefficientsS = secondsFrom(t0);
  // The sources' tallies, then the hours.
  const auto t1 = std::chrono::steady_clock::now();
  out.sky = skyViewTally(tracer, view, patches, job.northDeg, options.rowsPer90Deg, job.threads);
  out.sun = sunViewTally(tracer, view, suns, options.sunDiscSamples, job.threads);
  out.tallyS = secondsFrom(t1);
  const auto t2 = std::chrono::steady_clock::now();
  out.dgp = imagelessHourlyDgp(out.verticalLux, sky, out.sky, out.sun, options);
  out.hoursS = secondsFrom(t2);
  return out;
}

}  // namespace candela
