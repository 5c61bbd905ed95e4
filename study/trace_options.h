// The one settings resolution of every command that traces (points, run, render): what the
// caller asks (command line, script) over the case's [settings] over the quality preset.
#pragma once

#include "engine/trace_settings.h"
#include "study/case/case_file.h"

#include <cstdint>
#include <optional>

namespace candela {

// What the caller asks; unset: the case's, else the preset's.
struct TraceOverrides {
  std::optional<Quality> quality;
  std::optional<int> bounces;     // diffuse interreflections followed
  std::optional<int> samples;     // hemisphere samples per point
  std::optional<uint64_t> seed;
  std::optional<int> threads;     // 0 = all cores
  std::optional<Method> method;
  // Sample each point until its standard error is below this fraction of its value (0: one
  // batch); unset: the case's target_error, else the preset's.
  std::optional<double> targetRelativeError;
  // How the scene files are read ([settings] patterns, nonplanar).
  std::optional<PatternPolicy> patterns;
  std::optional<NonplanarPolicy> nonplanar;
  std::optional<std::filesystem::path> objMapping;  // --obj-map: replaces [settings] obj_map
};

// The scene-reading options of the case's [settings] (or the defaults) with the overrides applied.
SceneReadOptions sceneReadOptions(const Settings* caseSettings, const TraceOverrides& o);

struct ResolvedTrace {
  Quality quality = Quality::kNormal;
  TraceSettings settings;
  int threads = 0;  // 0 = all cores
};

// `caseSettings` may be null (no case). `defaultMethod` applies when neither the caller nor the
// case names one: the irradiance cache for a case's grids (run), the path tracer for points.
ResolvedTrace resolveTrace(const Settings* caseSettings, const TraceOverrides& o, Method defaultMethod);

// The number of threads `threads` stands for (0: the cores this process may use).
unsigned threadsUsed(int threads);

}  // namespace candela
