#include "engine/irradiance_estimator.h"

#include "engine/integrator_direct.h"
#include "engine/integrator_path.h"
#include "engine/sampling.h"
#include "engine/sky_tally.h"
#include "engine/trace_context.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

double IrradianceEstimate::standardErrorLux() const {
  return kLumensPerWatt * std::sqrt(std::max(0.0, variancePhotopic));
}

namespace {

// Adaptive super-sampling splits a refined stratum into kSub × kSub sub-strata.
constexpr int kSub = 2;

// One sensor point's estimate in progress: its hemisphere strata (the paper's eq. 3,
// E ≈ (π / MN) Σ L(θ_j, φ_k) with θ_j = asin√((j + X)/M) and φ_k = 2π(k + Y)/N, one sample per
// stratum) and what their variance needs.
// A non-planar response (engine/response.h) draws its rays with density w/W instead and weighs
// them by W = ∫ w dω instead of π (docs/quantities.md#the-estimator).
struct SensorEstimate {
  SensorEstimate(TraceContext& c, Rng& j, const Vec3& point, const Response& r, const IrradianceCache* ic)
      : ctx(c), jitter(j), p(point), n(r.n), response(r), cache(ic), frame(Frame::fromNormal(r.n)),
        total(r.integral()) {}
  TraceContext& ctx;
  Rng& jitter;  // the stream of the strata's jitter
  const Vec3 p, n;
  const Response response;
  const IrradianceCache* cache;
  CacheUse use;
  Frame frame;
  const double total;  // W: π for planar illuminance
  int mTheta = 0, nPhi = 0, cells = 0;
  double misRatio = 1.0;
  std::vector<Rgb> value;  // each cell's mean radiance
  std::vector<double> y;   // its photopic value
  std::vector<int> counts;  // samples in each cell
  // Refined cells' own variance estimate of their mean (NaN: not refined), and the records'
  // expected share of each cell's squared second difference (cache method).
  std::vector<double> ownBetween, ownWithin, dRec;
};

// Jittered sample of sub-stratum (su, sv) of `sub`×`sub` inside the cell: its radiance.
Rgb sampleCell(SensorEstimate& e, int cell, double su, double sv, int sub) {
  const int j = cell / e.nPhi, k = cell % e.nPhi;
  const double u1 = (j + (su + e.jitter.uniform()) / sub) / e.mTheta;
  const double u2 = (k + (sv + e.jitter.uniform()) / sub) / e.nPhi;
  const bool planar = e.response.isPlanar();
  const Vec3 dir = planar ? e.frame.toWorld(sampleCosineHemisphere(u1, u2)) : e.response.sample(u1, u2);
  // The ray's share of E (the sky tally runs with adaptiveFraction 0: never refined).
  const TallyFactor tf(e.ctx.tally, e.total / e.cells);
  e.use.tally.setCell(cell);
  PathState st;
  st.misCosPdf = planar ? glm::dot(dir, e.n) * kInvPi : e.response.density(dir);
  st.misRatio = e.misRatio;
  st.litPoint = e.p;  // where estimateIrradiance sampled the sources
  st.lighting = true;
  st.misPortalRatio = e.misRatio * kSensorPortalFactor;
  st.misOrigin = e.p;
  st.misNormal = e.n;
  if (e.cache) return pathRadiance(e.ctx, e.p, dir, st, &e.use);
  st.split = e.ctx.settings.firstBounceSplit;
  return pathRadiance(e.ctx, e.p, dir, st);
}

// Super-samples cell c (after its first sample) and sets its variance estimate
// (derivation: docs/estimator.md#refined-strata, and #refined-strata-under-the-cache).
void refineCell(SensorEstimate& e, int c, const std::vector<double>& yFirst, std::vector<size_t>& marks) {
  Rgb acc = e.value[c];
  double ySub[kSub * kSub], mean = 0.0;
  marks.clear();
  for (int q = 0; q < kSub * kSub; ++q) {
    marks.push_back(e.use.tally.mark());
    const Rgb v = sampleCell(e, c, q / kSub, q % kSub, kSub);
    acc += v;
    ySub[q] = photopic(v);
    mean += ySub[q] / (kSub * kSub);
  }
  const double mm = kSub * kSub, a = (e.y[c] - mean) * (e.y[c] - mean), norm = (1.0 + mm) * (1.0 + mm);
  double sq = 0.0;
  for (int q = 0; q < kSub * kSub; ++q) sq += (ySub[q] - mean) * (ySub[q] - mean);
  e.ownBetween[c] = sq / mm / norm;
  e.ownWithin[c] = mm * (mm * a - sq) / 2.0 * (1.0 + 1.0 / (mm * mm)) / norm;
  if (e.cache) {
    // y0 always finds a record, a sub-sample may not: each part bounded from its own samples,
    // the records' expected shares taken off.
    const int nPhi = e.nPhi, j = c / nPhi, k = c % nPhi;
    const double d = yFirst[j * nPhi + (k + nPhi - 1) % nPhi] - 2.0 * yFirst[c] + yFirst[j * nPhi + (k + 1) % nPhi];
    marks.push_back(e.use.tally.mark());
    const double srec = e.use.tally.spreadVariance(*e.cache, marks);
    e.ownBetween[c] = d * d / 6.0 / norm;
    e.ownWithin[c] = ((sq - srec) * mm / (mm - 1.0) - e.dRec[c] / 6.0) / norm;
  }
  e.value[c] = acc / static_cast<double>(1 + kSub * kSub);
  e.counts[c] = 1 + kSub * kSub;
  e.y[c] = photopic(e.value[c]);
}

// Adaptive super-sampling (after Radiance's ambient super-samples, -as): the `refine` strata
// whose neighbours disagree most (range of the four neighbours' values; φ wraps around) get
// kSub × kSub more samples. The choice for a stratum never looks at its own sample, so every
// sample in it stays an unbiased estimate of its mean (choosing by its own value, as -as does,
// biases the strata left alone towards their neighbours). Under the cache method the choice
// leaves out the radiance the samples took from the records
// (docs/estimator.md#choosing-strata-under-the-cache).
void refineStrata(SensorEstimate& e, int refine) {
  const int cells = e.cells, mTheta = e.mTheta, nPhi = e.nPhi;
  std::vector<double> diff(cells, 0.0);
  std::vector<double> ySel = e.y;
  if (e.cache)
    for (int c = 0; c < cells; ++c) ySel[c] -= e.use.tally.cachedValue(c);
  for (int c = 0; c < cells; ++c) {
    const int j = c / nPhi, k = c % nPhi;
    double lo = std::min(ySel[j * nPhi + (k + 1) % nPhi], ySel[j * nPhi + (k + nPhi - 1) % nPhi]);
    double hi = std::max(ySel[j * nPhi + (k + 1) % nPhi], ySel[j * nPhi + (k + nPhi - 1) % nPhi]);
    if (j > 0) lo = std::min(lo, ySel[c - nPhi]), hi = std::max(hi, ySel[c - nPhi]);
    if (j + 1 < mTheta) lo = std::min(lo, ySel[c + nPhi]), hi = std::max(hi, ySel[c + nPhi]);
    diff[c] = hi - lo;
  }
  std::vector<int> order(cells);
  for (int c = 0; c < cells; ++c) order[c] = c;
  std::partial_sort(order.begin(), order.begin() + refine, order.end(), [&](int a, int b) {
    return diff[a] > diff[b] || (diff[a] == diff[b] && a < b);
  });
  const std::vector<double> yFirst = e.y;
  std::vector<size_t> marks;
  for (int r = 0; r < refine; ++r) {
    const int c = order[r];
    if (diff[c] <= 0.0) break;
    refineCell(e, c, yFirst, marks);
  }
}

}  // namespace

double stratifiedVariance(const std::vector<double>& y, int m, int n, const std::vector<double>* ownBetween,
                          const std::vector<double>* ownWithin, const std::vector<double>* recordShare) {
  const double cells = static_cast<double>(y.size());
  if (y.empty()) return 0.0;
  double sumVar = 0.0, sumWithin = 0.0, sumRec = 0.0;
  auto refined = [&](size_t c) { return ownBetween && !std::isnan((*ownBetween)[c]); };
  if (n >= 3 && static_cast<size_t>(m) * n == y.size()) {
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < n; ++k) {
        const int c = j * n + k;
        if (refined(c)) {
          sumVar += (*ownBetween)[c];
          sumWithin += (*ownWithin)[c];
          continue;
        }
        const double d = y[j * n + (k + n - 1) % n] - 2.0 * y[c] + y[j * n + (k + 1) % n];
        sumVar += d * d / 6.0;
        if (recordShare) sumRec += (*recordShare)[c] / 6.0;
      }
  } else {
    for (size_t c = 0; c + 1 < y.size(); c += 2) sumVar += (y[c] - y[c + 1]) * (y[c] - y[c + 1]);
  }
  return kPi * kPi * std::max(0.0, sumVar + std::max(0.0, sumWithin) - sumRec) / (cells * cells);
}

IrradianceEstimate estimateIrradiance(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex,
                                      const TraceSettings& s, const EstimatorInputs& in) {
  return estimateIrradiance(tracer, p, Response::planar(n), pointIndex, s, in);
}

IrradianceEstimate estimateIrradiance(const Tracer& tracer, const Vec3& p, const Response& response,
                                      uint64_t pointIndex, const TraceSettings& s, const EstimatorInputs& in) {
  Rng rng(s.seed, pointIndex);
  // Path method: directions from the point's one stream; cache method: from a stream of their
  // own (see cacheQueries).
  Rng dirRng(s.seed, kDirectionStream + pointIndex);
  TraceContext ctx(tracer, s, rng, in.tally);
  SensorEstimate e(ctx, in.cache ? dirRng : rng, p, response, in.cache);
  const Vec3& n = response.n;
  e.use.cache = in.cache;
  e.use.depth = 0;
  IrradianceEstimate est;
  double var = 0.0;
  const int cellsN = hemisphereThetaStrata(s, response) * hemispherePhiStrata(s, response);
  e.misRatio = static_cast<double>(std::max(1, s.lightSamples)) / cellsN;
  const Receiver at{p, n, kNoShape, response.isPlanar() ? nullptr : &response};
  est.irradiance = directIrradiance(ctx, at, std::max(1, s.lightSamples), &var, e.misRatio);

  e.mTheta = hemisphereThetaStrata(s, response);
  e.nPhi = hemispherePhiStrata(s, response);
  const int cells = e.cells = e.mTheta * e.nPhi;
  e.value.assign(cells, Rgb(0.0));
  e.y.assign(cells, 0.0);
  e.counts.assign(cells, 1);
  e.ownBetween.assign(cells, std::numeric_limits<double>::quiet_NaN());
  e.ownWithin.assign(cells, 0.0);
  for (int c = 0; c < cells; ++c) {
    e.value[c] = sampleCell(e, c, 0, 0, 1);
    e.y[c] = photopic(e.value[c]);
  }
  // The records' expected share of each first sample's second difference
  // (docs/estimator.md#records-in-the-second-differences).
  e.dRec.assign(cells, 0.0);
  if (in.cache) e.use.tally.secondDifferenceVariance(*in.cache, e.use.tally.mark(), e.mTheta, e.nPhi, e.dRec);
  const int refine = std::min(cells, static_cast<int>(s.adaptiveFraction * cells) / (kSub * kSub));
  if (refine > 0) refineStrata(e, refine);
  Rgb sum(0.0);
  for (int c = 0; c < cells; ++c) sum += e.value[c];
  est.irradiance += e.total * sum / static_cast<double>(cells);
  // stratifiedVariance is that of π/(MN) Σ y: (W/π)² times it for W/(MN) Σ y (1 when planar).
  const double scale = (e.total / kPi) * (e.total / kPi);
  var += scale * stratifiedVariance(e.y, e.mTheta, e.nPhi, &e.ownBetween, &e.ownWithin, in.cache ? &e.dRec : nullptr);
  // The cached share, by the law of total variance (docs/estimator.md#the-records-share).
  if (in.cache && !e.use.tally.empty()) {
    est.varianceRecordsPhotopic = e.use.tally.recordVariance(*in.cache, e.total / static_cast<double>(cells), &e.counts);
    var += est.varianceRecordsPhotopic;
  }
  est.variancePhotopic = var;
  return est;
}

}  // namespace candela
