// `candela points` as a library call: illuminance at sensor points in a scene made of a case
// (its scene files, luminaires and daylight), further Radiance files and a sky, with the one
// settings resolution of every command (study/trace_options.h).
#pragma once

#include "engine/daylight.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "base/warning.h"
#include "study/case/case_file.h"
#include "study/observer.h"
#include "study/resource_estimate.h"
#include "study/trace_options.h"
#include "engine/irradiance_estimator.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

namespace candela {

struct PointsJob {
  std::filesystem::path caseFile;             // empty: no case
  std::vector<std::filesystem::path> scenes;  // Radiance files read after the case's, in order
  std::vector<std::filesystem::path> portalFiles;  // openings added to the case's (study/case/portal_file.h)
  // Luminaires placed after the case's and the scene files (the Python module's `luminaires`).
  std::vector<LuminairePlacement> luminaires;
  // A sky asked for by the caller: called with the case's daylight (or the default without a
  // case) and returns the daylight to use instead of it. Unset: the case's daylight.
  std::function<DaylightSpec(DaylightSpec)> sky;
  TraceOverrides trace;
  AcceleratorKind accelerator = AcceleratorKind::kEmbree;
  bool strict = false;  // every warning an InputError (the first one, before any output)
  ResourceLimits limits;            // checked before tracing (study/resource_estimate.h)
  std::string pointsName = "<stdin>";  // where the points come from, for the estimate's messages
  // The processes the points are shared between (base/distribution.h); null: this one.
  const Distribution* distribution = nullptr;
};

struct PointsResult {
  ResolvedTrace trace;
  std::vector<IrradianceEstimate> estimates;  // one per point, in input order
  std::vector<Warning> warnings;              // study/warnings.h
};

// The scene and settings a job describes (throws InputError naming the bad file and line).
struct PointsScene {
  std::unique_ptr<Scene> scene;
  ResolvedTrace trace;
  std::vector<LuminairePlacement> luminaires;  // the case's, for the warnings
  std::vector<Warning> warnings;               // on the scene and the case, found on loading
  bool strict = false;                         // the job's
  ResourceLimits limits;
  std::string pointsName;
  const Distribution* distribution = nullptr;  // the job's
};
PointsScene loadPointsScene(const PointsJob& job);

// Traces `points` in a loaded scene. `pointLocs` (one per point, or empty) names where each
// point was read, for the warnings. Throws InputError for the first warning when strict.
PointsResult computePoints(const PointsScene& scene, AcceleratorKind accelerator,
                           const std::vector<SensorPoint>& points, StudyObserver& observer = silentObserver(),
                           const std::vector<FileLoc>& pointLocs = {});

}  // namespace candela
