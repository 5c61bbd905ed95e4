#include "engine/daylight_coefficients.h"

#include "engine/daylight.h"
#include "engine/irradiance_estimator.h"
#include "engine/sky_tally.h"
#include "base/parallel.h"
#include "engine/sampling.h"
#include "photometry/site.h"
#include "engine/random_streams.h"

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <cmath>
#include <stdexcept>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The stream of a point's patch-by-patch direct sky samples (skyCoefficients).
constexpr uint64_t kPatchStream = streams::kSkyPatches.first;

// The settings of the coefficient estimates: path traced, and no adaptive supersampling (a
// refined stratum's first sample would change weight in the tallies) nor target error.
TraceSettings coefficientSettings(const TraceSettings& s) {
  TraceSettings t = s;
  t.method = Method::kPath;
  t.adaptiveFraction = 0.0;
  t.targetRelativeError = 0.0;
  return t;
}

}  // namespace

void skyCoefficients(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                     const SkyPatches& patches, double* direct, double* indirect, bool directByPatch) {
  const Scene& scene = tracer.scene();
  if (!scene.sky) throw std::logic_error("skyCoefficients needs a scene with a sky");
  const TraceSettings t = coefficientSettings(s);
  // The sky seen directly, patch by patch: s.lightSamples stratified directions in each (uniform
  // in solid angle; the ground takes 4× as many, being 2π sr), each with its shadow ray through
  // glass and trans as the point estimator's would. Every patch gets its own samples, so a
  // small bright patch (the circumsolar sky) is known as well as a large dim one, which sky
  // samples drawn over the whole hemisphere cannot give a patch seen through a window.
  Rng rng(s.seed, kPatchStream + pointIndex);
  uint64_t rays = 0;
  for (int b = 0; directByPatch && b < patches.count(); ++b) {
    const Strata2D strata(std::max(1, s.lightSamples) * (b == 0 ? 4 : 1));
    double sum = 0.0;
    for (int i = 0; i < strata.size(); ++i) {
      const Vec2 u = strata.sample(i, rng);
      const Vec3 d = trueToModel(patches.sample(b, u.x, u.y), scene.sky->northDeg);
      const double c = glm::dot(n, d);
      if (c <= 0.0) continue;
      sum += c * photopic(tracer.transmittance(p, d, kInf, kNoShape, kNoShape, rays));
    }
    direct[b] += patches.solidAngle(b) * sum / strata.size();
  }
  tracer.addRays(rays);
  SkyTally tally;
  tally.patches = &patches;
  tally.northDeg = scene.sky->northDeg;
  tally.direct = direct;
  tally.indirect = indirect;
  tally.directApart = directByPatch;
  EstimatorInputs in;
  in.tally = &tally;
  estimateIrradiance(tracer, p, n, pointIndex, t, in);
}

void sunCoefficients(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                     const std::vector<Vec3>& sunDirsModel, double* indirect) {
  SkyTally tally;
  tally.suns = &sunDirsModel;
  tally.sunIndirect = indirect;
  EstimatorInputs in;
  in.tally = &tally;
  estimateIrradiance(tracer, p, n, pointIndex, coefficientSettings(s), in);
}

PatchSky::PatchSky(const SkyPatches& patches, std::vector<double> luminanceCdM2)
    : patches_(patches), luminance_(std::move(luminanceCdM2)) {
  if (luminance_.size() != static_cast<size_t>(patches_.count()))
    throw std::invalid_argument("PatchSky: one luminance per patch expected");
  // Relative luminance is the luminance itself: scale 1.
  calibrate(integrateRelative(Vec3(0.0, 0.0, 1.0)));
}

double PatchSky::relativeLuminance(const Vec3& dirTrue) const { return luminance_[patches_.indexOf(dirTrue)]; }

std::shared_ptr<const SkyModel> yearSamplingGuide(const AnnualSky& sky) {
  const SkyPatches patches(sky.subdivision);
  std::vector<double> mean(patches.count(), 0.0);
  for (size_t h = 0; h < sky.hours.size(); ++h)
    for (int p = 1; p < patches.count(); ++p) mean[p] += sky.at(static_cast<int>(h), p);
  double all = 0.0;
  for (int p = 1; p < patches.count(); ++p) all += mean[p];
  all /= std::max(1, patches.count() - 1);
  // A year without daylight still needs a sampling density: uniform.
  for (int p = 1; p < patches.count(); ++p) mean[p] += all > 0.0 ? 0.1 * all : 1.0;
  return std::make_shared<PatchSky>(patches, std::move(mean));
}

namespace {

SensorBlock wholeStudy(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals) {
  if (positions.size() != normals.size()) throw std::invalid_argument("positions and normals differ in size");
  return SensorBlock{positions, normals, 0};
}

void checkBlock(const SensorBlock& block) {
  if (block.positions.size() != block.normals.size())
    throw std::invalid_argument("positions and normals differ in size");
}

}  // namespace

DaylightCoefficients computeDaylightCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                                 const std::vector<Vec3>& normals, const SkyPatches& patches,
                                                 const TraceSettings& settings, int threads,
                                                 const std::function<void(size_t)>& progress,
                                                 const Distribution& distribution) {
  return computeDaylightCoefficients(tracer, wholeStudy(positions, normals), patches, settings, threads, progress,
                                     distribution);
}

DaylightCoefficients computeDaylightCoefficients(const Tracer& tracer, const SensorBlock& block,
                                                 const SkyPatches& patches, const TraceSettings& settings,
                                                 int threads, const std::function<void(size_t)>& progress,
                                                 const Distribution& distribution) {
  checkBlock(block);
  const std::span<const Vec3> positions = block.positions, normals = block.normals;
  DaylightCoefficients dc;
  dc.sensors = static_cast<int>(positions.size());
  dc.patches = patches.count();
  const size_t np = static_cast<size_t>(dc.patches);
  dc.total.assign(positions.size() * np, 0.0f);
  std::atomic<size_t> done{0};
  distributedRows(distribution, dc.total, np, ItemUse::kResult, threads, [&](size_t i) {
    std::vector<double> direct(np, 0.0), indirect(np, 0.0);
    skyCoefficients(tracer, positions[i], normals[i], block.firstIndex + i, settings, patches, direct.data(),
                           indirect.data());
    for (size_t p = 0; p < np; ++p) dc.total[i * np + p] = static_cast<float>(direct[p] + indirect[p]);
    const size_t d = ++done;
    if (progress) progress(d);
  });
  return dc;
}

SunSet indirectSunSet(const AnnualSky& sky, int subdivision) {
  const SkyPatches coarse(subdivision);
  std::vector<Vec3> sum(coarse.count(), Vec3(0.0));
  std::vector<int> patchOf(sky.hours.size(), -1);
  for (int h : sunHours(sky)) {
    patchOf[h] = coarse.indexOf(sky.hours[h].sunDirTrue);
    sum[patchOf[h]] += sky.hours[h].sunDirTrue;
  }
  SunSet set;
  for (int p = 0; p < coarse.count(); ++p)
    if (glm::length(sum[p]) > 0.0) set.dirsTrue.push_back(glm::normalize(sum[p]));
  std::array<int, SunSet::kNearest> none;
  none.fill(-1);
  set.nearest.assign(sky.hours.size(), none);
  set.weight.assign(sky.hours.size(), std::array<float, SunSet::kNearest>{});
  for (size_t h = 0; h < sky.hours.size(); ++h) {
    if (patchOf[h] < 0) continue;
    const Vec3& sun = sky.hours[h].sunDirTrue;
    // The kNearest positions by angle (a few hundred: a plain scan).
    std::array<double, SunSet::kNearest> best;
    best.fill(1e300);
    auto& idx = set.nearest[h];
    for (size_t j = 0; j < set.dirsTrue.size(); ++j) {
      const double a = std::acos(std::clamp(glm::dot(sun, set.dirsTrue[j]), -1.0, 1.0));
      for (int k = 0; k < SunSet::kNearest; ++k)
        if (a < best[k]) {
          for (int m = SunSet::kNearest - 1; m > k; --m) best[m] = best[m - 1], idx[m] = idx[m - 1];
          best[k] = a;
          idx[k] = static_cast<int>(j);
          break;
        }
    }
    double sum = 0.0;
    std::array<double, SunSet::kNearest> w{};
    for (int k = 0; k < SunSet::kNearest; ++k)
      if (idx[k] >= 0) sum += w[k] = 1.0 / (best[k] * best[k] + 1e-8);
    for (int k = 0; k < SunSet::kNearest; ++k) set.weight[h][k] = idx[k] >= 0 ? static_cast<float>(w[k] / sum) : 0.0f;
  }
  return set;
}

std::vector<float> indirectSunCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                           const std::vector<Vec3>& normals, const std::vector<Vec3>& sunDirsModel,
                                           const TraceSettings& settings, int threads,
                                           const std::function<void(size_t)>& progress,
                                           const Distribution& distribution) {
  return indirectSunCoefficients(tracer, wholeStudy(positions, normals), sunDirsModel, settings, threads, progress,
                                 distribution);
}

std::vector<float> indirectSunCoefficients(const Tracer& tracer, const SensorBlock& block,
                                           const std::vector<Vec3>& sunDirsModel, const TraceSettings& settings,
                                           int threads, const std::function<void(size_t)>& progress,
                                           const Distribution& distribution) {
  checkBlock(block);
  const std::span<const Vec3> positions = block.positions, normals = block.normals;
  const size_t ns = sunDirsModel.size();
  std::vector<float> out(positions.size() * ns, 0.0f);
  std::atomic<size_t> done{0};
  distributedRows(distribution, out, ns, ItemUse::kResult, threads, [&](size_t i) {
    std::vector<double> acc(ns, 0.0);
    sunCoefficients(tracer, positions[i], normals[i], block.firstIndex + i, settings, sunDirsModel, acc.data());
    for (size_t j = 0; j < ns; ++j) out[i * ns + j] = static_cast<float>(acc[j]);
    const size_t d = ++done;
    if (progress) progress(d);
  });
  return out;
}

std::vector<float> directSunCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                         const std::vector<Vec3>& normals, const std::vector<Vec3>& sunDirsModel,
                                         int samples, uint64_t seed, int threads,
                                         const Distribution& distribution) {
  return directSunCoefficients(tracer, wholeStudy(positions, normals), sunDirsModel, samples, seed, threads,
                               distribution);
}

namespace {

// Rows of (1 + labels) × suns floats per sensor of the block: the total S(s, j), then its part
// through each label (labels null: the total alone). One code path for both, so the total is the
// same float with or without labels.
// 8 parameters: directSunCoefficientsByLabel's.
std::vector<float> directSunRows(const Tracer& tracer, const SensorBlock& block, const std::vector<Vec3>& sunDirsModel,
                                 int samples, uint64_t seed, int threads, const SurfaceLabels* labels,
                                 const Distribution& distribution) {
  checkBlock(block);
  const std::span<const Vec3> positions = block.positions, normals = block.normals;
  const size_t ns = sunDirsModel.size();
  const size_t nl = labels ? static_cast<size_t>(labels->count) : 0, row = (1 + nl) * ns;
  if (labels && labels->ofSurface.size() != tracer.scene().surfaceCount())
    throw std::invalid_argument("surface labels: one per surface of the scene expected");
  std::vector<float> out(positions.size() * row, 0.0f);
  const double cosMax = std::cos(0.5 * degToRad(kSunDiameterDeg));
  const Strata2D strata(std::max(1, samples));
  // Its own streams, apart from the points' (which the sky coefficients use).
  constexpr uint64_t kSunStream = streams::kSuns.first;
  distributedRows(distribution, out, row, ItemUse::kResult, threads, [&](size_t i) {
    Rng rng(seed, kSunStream + block.firstIndex + i);
    const Vec3& p = positions[i];
    const Vec3& n = normals[i];
    float* r = out.data() + i * row;
    uint64_t rays = 0;
    for (size_t j = 0; j < ns; ++j) {
      const Vec3& sun = sunDirsModel[j];
      // Wholly behind the receiver (the disc's half-angle is 0.27°): nothing to trace.
      if (glm::dot(n, sun) < -0.005) continue;
      const Frame frame = Frame::fromNormal(sun);
      double sum = 0.0;
      for (int k = 0; k < strata.size(); ++k) {
        const Vec2 u = strata.sample(k, rng);
        const Vec3 d = frame.toWorld(sampleUniformCone(u.x, u.y, cosMax));
        const double c = glm::dot(n, d);
        if (c <= 0.0) continue;
        uint32_t glass = kNoShape;
        const double v =
            c * photopic(tracer.transmittance(p, d, std::numeric_limits<double>::infinity(), kNoShape, kNoShape, rays, glass));
        sum += v;
        if (labels && glass != kNoShape && v > 0.0) {
          const int g = labels->ofSurface[glass];
          if (g >= 0) r[(1 + static_cast<size_t>(g)) * ns + j] += static_cast<float>(v / strata.size());
        }
      }
      r[j] = static_cast<float>(sum / strata.size());
    }
    tracer.addRays(rays);
  });
  return out;
}

}  // namespace

std::vector<float> directSunCoefficients(const Tracer& tracer, const SensorBlock& block,
                                         const std::vector<Vec3>& sunDirsModel, int samples, uint64_t seed,
                                         int threads, const Distribution& distribution) {
  return directSunRows(tracer, block, sunDirsModel, samples, seed, threads, nullptr, distribution);
}

std::vector<std::vector<float>> directSunCoefficientsByLabel(const Tracer& tracer, const SensorBlock& block,
                                                             const std::vector<Vec3>& sunDirsModel, int samples,
                                                             uint64_t seed, int threads, const SurfaceLabels& labels,
                                                             const Distribution& distribution) {
  const std::vector<float> rows = directSunRows(tracer, block, sunDirsModel, samples, seed, threads, &labels, distribution);
  const size_t ns = sunDirsModel.size(), parts = 1 + static_cast<size_t>(labels.count), row = parts * ns;
  std::vector<std::vector<float>> out(parts, std::vector<float>(block.positions.size() * ns));
  for (size_t i = 0; i < block.positions.size(); ++i)
    for (size_t q = 0; q < parts; ++q)
      std::copy_n(rows.data() + i * row + q * ns, ns, out[q].data() + i * ns);
  return out;
}

std::vector<int> sunHours(const AnnualSky& sky) {
  std::vector<int> hours;
  for (size_t h = 0; h < sky.hours.size(); ++h)
    if (sky.hours[h].sunUp && sky.hours[h].directNormalLux > 0.0 && sky.hours[h].sunPatch > 0)
      hours.push_back(static_cast<int>(h));
  return hours;
}

std::vector<float> hourlyDirectSun(const std::vector<float>& sunCoefficients, int sensors, const AnnualSky& sky) {
  const std::vector<int> sun = sunHours(sky);
  const size_t nsun = sun.size(), nh = sky.hours.size();
  if (sensors < 0 || sunCoefficients.size() != static_cast<size_t>(sensors) * nsun)
    throw std::invalid_argument("direct sun coefficients: wrong size");
  std::vector<float> out(static_cast<size_t>(sensors) * nh, 0.0f);
  for (size_t s = 0; s < static_cast<size_t>(sensors); ++s)
    for (size_t j = 0; j < nsun; ++j) {
      const int h = sun[j];
      const double direct = sunCoefficients[s * nsun + j] * sky.hours[h].directNormalLux;
      out[s * nh + h] = static_cast<float>(direct);
    }
  return out;
}

std::vector<Vec3> sunDirectionsModel(const AnnualSky& sky, double northDeg) {
  std::vector<Vec3> dirs;
  for (int h : sunHours(sky)) dirs.push_back(trueToModel(sky.hours[h].sunDirTrue, northDeg));
  return dirs;
}

AnnualIlluminance annualIlluminance(const DaylightCoefficients& dc, const std::vector<float>& sunCoefficients,
                                    const std::vector<float>& sunIndirect, const SunSet& sunSet,
                                    const AnnualSky& sky, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const int nh = static_cast<int>(sky.hours.size());
  const int np = dc.patches;
  if (sky.patchCount != np) throw std::invalid_argument("daylight coefficients and sky vectors have different patch counts");
  if (sky.luminance.size() != static_cast<size_t>(nh) * np) throw std::invalid_argument("sky vectors: wrong size");
  const std::vector<int> sun = sunHours(sky);
  const size_t nsun = sun.size(), nset = sunSet.dirsTrue.size();
  if (sunCoefficients.size() != static_cast<size_t>(dc.sensors) * nsun)
    throw std::invalid_argument("direct sun coefficients: wrong size");
  if (sunIndirect.size() != static_cast<size_t>(dc.sensors) * nset || sunSet.nearest.size() != sky.hours.size())
    throw std::invalid_argument("interreflected sun coefficients: wrong size");

  AnnualIlluminance out;
  out.sensors = dc.sensors;
  out.hours = nh;
  out.total.assign(static_cast<size_t>(dc.sensors) * nh, 0.0f);
  out.directSun.assign(static_cast<size_t>(dc.sensors) * nh, 0.0f);

  // Column-major views: L is patches × hours, DC is patches × sensors, E is hours × sensors, so
  // E = Lᵀ DC is sensor-major in memory. Sensors go in blocks of a fixed size, so every value
  // is summed in the same order whatever the number of threads.
  using ConstMap = Eigen::Map<const Eigen::MatrixXf>;
  const ConstMap lum(sky.luminance.data(), np, nh);
  constexpr int kBlock = kAnnualProductBlock;
  const int blocks = (dc.sensors + kBlock - 1) / kBlock;
  parallelFor(static_cast<size_t>(blocks), threads, [&](size_t b) {
    const int s0 = static_cast<int>(b) * kBlock, count = std::min(kBlock, dc.sensors - s0);
    const ConstMap coef(dc.total.data() + static_cast<size_t>(s0) * np, np, count);
    Eigen::Map<Eigen::MatrixXf> e(out.total.data() + static_cast<size_t>(s0) * nh, nh, count);
    e.noalias() = lum.transpose() * coef;
    // The sun: direct at its position, interreflected from its stand-in of the set.
    for (int s = s0; s < s0 + count; ++s) {
      float* es = out.total.data() + static_cast<size_t>(s) * nh;
      float* ds = out.directSun.data() + static_cast<size_t>(s) * nh;
      const float* sc = sunCoefficients.data() + static_cast<size_t>(s) * nsun;
      const float* si = sunIndirect.data() + static_cast<size_t>(s) * nset;
      for (size_t j = 0; j < nsun; ++j) {
        const int h = sun[j];
        const double edn = sky.hours[h].directNormalLux;
        const double direct = sc[j] * edn;
        double inter = 0.0;
        for (int k = 0; k < SunSet::kNearest; ++k)
          if (sunSet.nearest[h][k] >= 0) inter += sunSet.weight[h][k] * si[sunSet.nearest[h][k]];
        inter *= edn;
        ds[h] = static_cast<float>(direct);
        es[h] += static_cast<float>(direct + inter);
      }
    }
  });
  out.productTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace candela
