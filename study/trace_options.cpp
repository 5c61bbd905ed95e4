#include "study/trace_options.h"

#include <tbb/info.h>

#include <algorithm>

namespace candela {

SceneReadOptions sceneReadOptions(const Settings* caseSettings, const TraceOverrides& o) {
  SceneReadOptions r = caseSettings ? caseSettings->scene : SceneReadOptions{};
  if (o.patterns) r.patterns = *o.patterns;
  if (o.nonplanar) r.nonplanar = *o.nonplanar;
  if (o.objMapping) r.objMapping = *o.objMapping;
  return r;
}

ResolvedTrace resolveTrace(const Settings* caseSettings, const TraceOverrides& o, Method defaultMethod) {
  const Settings none;
  const Settings& c = caseSettings ? *caseSettings : none;
  ResolvedTrace r;
  r.quality = o.quality.value_or(c.quality);
  r.settings = settingsForQuality(r.quality);
  if (const std::optional<int> b = o.bounces ? o.bounces : c.bounces) r.settings.maxBounces = *b;
  if (const std::optional<int> n = o.samples ? o.samples : c.samples) r.settings.hemisphereSamples = *n;
  r.settings.seed = o.seed.value_or(c.seed);
  r.settings.method = o.method.value_or(c.method.value_or(defaultMethod));
  if (const std::optional<double> t = o.targetRelativeError ? o.targetRelativeError : c.targetRelativeError) {
    r.settings.targetRelativeError = *t;
    r.settings.gridTargetRelativeError = 0.0;  // the caller's target means per point, grids too
    r.settings.maxBatches = kExplicitTargetMaxBatches;
  }
  r.threads = o.threads.value_or(c.threads);
  return r;
}

unsigned threadsUsed(int threads) {
  // The cores this process may use (its affinity mask, as oneTBB counts them): under mpirun a
  // rank is bound to its own cores, fewer than the machine's.
  return threads > 0 ? static_cast<unsigned>(threads) : static_cast<unsigned>(std::max(1, tbb::info::default_concurrency()));
}

}  // namespace candela
