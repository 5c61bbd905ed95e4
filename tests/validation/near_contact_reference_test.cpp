// The near-contact points of the sphere-on-plane sun + sky case (validation/speed_accuracy.cpp):
// the case's converged reference and the irradiance cache against an independent path-traced
// estimate (docs/accuracy.md#near-contact-cache-bias-cause-and-fix).
#include "engine/sensors.h"
#include "validation/speed_accuracy.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {
namespace {

// The scene with only its two shadow points 0.3 m either side of the contact, on the sun's
// azimuth line: (−0.3, 0) and (0.3, 0), 1 cm above the plane.
validation::IndirectScene nearContact() {
  validation::IndirectScene sc;
  for (const auto& s : validation::indirectScenes())
    if (s.name == "sphere-on-plane-sun-sky") sc = s;
  sc.points = {{Vec3(-0.3, 0, 0.01), Vec3(0, 0, 1)}, {Vec3(0.3, 0, 0.01), Vec3(0, 0, 1)}};
  return sc;
}

// Mean and standard error of the mean of each point over `runs` independent runs (seeds
// first..first + runs − 1), from the runs' spread (no trust in the estimator's own error bars).
struct Spread {
  std::vector<double> mean, se;
};
Spread overSeeds(const validation::IndirectScene& sc, TraceSettings s, uint64_t first, int runs) {
  const size_t n = sc.points.size();
  std::vector<double> sum(n, 0.0), sum2(n, 0.0);
  for (int r = 0; r < runs; ++r) {
    s.seed = first + r;
    const auto est = validation::runIndirectScene(sc, s, 0, nullptr);
    for (size_t i = 0; i < n; ++i) {
      sum[i] += est[i].illuminanceLux();
      sum2[i] += est[i].illuminanceLux() * est[i].illuminanceLux();
    }
  }
  Spread out;
  for (size_t i = 0; i < n; ++i) {
    const double m = sum[i] / runs;
    out.mean.push_back(m);
    out.se.push_back(std::sqrt(std::max(0.0, (sum2[i] - runs * m * m) / (runs - 1)) / runs));
  }
  return out;
}

// The case's reference (3 % tolerance), computed once for both tests.
const std::vector<IrradianceEstimate>& caseReference() {
  static const std::vector<IrradianceEstimate> ref = validation::referenceEstimates(nearContact(), 0.03, 0);
  return ref;
}

TEST(NearContact, ReferenceIsConvergedToATenthOfTheTolerance) {
  // The case's tolerance is 3 %: its reference must carry a standard error of at most 0.3 %
  // (8192 samples alone gave 1.1 % at (−0.3, 0) and read +1.4 %), and agree with the mean of 8
  // independent runs of the same settings (other seeds) within 4 combined standard errors.
  const validation::IndirectScene sc = nearContact();
  const auto& ref = caseReference();
  const Spread indep = overSeeds(sc, validation::referenceSettings(), 101, 8);
  for (size_t i = 0; i < sc.points.size(); ++i) {
    const double v = ref[i].illuminanceLux(), se = ref[i].standardErrorLux();
    std::printf("[ measured ] reference at x=%+.1f: %.2f ± %.2f lux (%.2f %%); 8 other seeds %.2f ± %.2f lux\n",
                sc.points[i].position.x, v, se, 100 * se / v, indep.mean[i], indep.se[i]);
    EXPECT_LE(se, 0.003 * v * 1.0001);
    EXPECT_NEAR(v, indep.mean[i], 4.0 * std::hypot(se, indep.se[i]));
  }
}

TEST(NearContact, CacheIsUnbiasedAgainstTheConvergedReference) {
  // The irradiance cache at the default quality over 10 seeds: its mean lies within 4 standard
  // errors (the seeds' spread, and the reference's own) of the converged path tracer. Measured
  // before the reference fix: +0.02 ± 0.35 % at (−0.3, 0) and −0.6 ± 0.2 % at (0.3, 0) over 30
  // seeds, so the −3.1 % filed in issue 16 was the reference's +1.4 % and the cache's noise.
  const validation::IndirectScene sc = nearContact();
  const auto& ref = caseReference();
  TraceSettings s = settingsForQuality(Quality::kNormal);
  s.method = Method::kCache;
  const Spread cache = overSeeds(sc, s, 1, 10);
  for (size_t i = 0; i < sc.points.size(); ++i) {
    const double v = ref[i].illuminanceLux();
    const double tol = 4.0 * std::hypot(cache.se[i], ref[i].standardErrorLux());
    std::printf("[ measured ] cache at x=%+.1f: mean of 10 seeds %.2f ± %.2f lux, reference %.2f (%+.2f %%)\n",
                sc.points[i].position.x, cache.mean[i], cache.se[i], v, 100 * (cache.mean[i] / v - 1));
    EXPECT_NEAR(cache.mean[i], v, tol);
  }
}

}  // namespace
}  // namespace candela
