#include "study/points_study.h"
#include "study/case/portal_file.h"

#include "engine/radiance/reader.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/finite_results.h"
#include "study/warnings.h"
#include "engine/irradiance_estimator.h"

namespace candela {

PointsScene loadPointsScene(const PointsJob& job) {
  PointsScene out;
  DaylightSpec daylight;
  std::optional<CaseFile> c;
  if (!job.caseFile.empty()) {
    c = readCaseFile(job.caseFile);
    c->settings.scene = sceneReadOptions(&c->settings, job.trace);
    c->settings.scene.maxMemoryBytes = job.limits.maxMemoryBytes;
    // A sky asked for replaces the case's; its site and time still come from the case.
    out.scene = loadCaseScene(*c, !job.sky);
    if (job.sky) daylight = daylightFromCase(*c);
  } else {
    out.scene = std::make_unique<Scene>();
  }
  SceneReadOptions reading = sceneReadOptions(c ? &c->settings : nullptr, job.trace);
  reading.maxMemoryBytes = job.limits.maxMemoryBytes;
  readSceneFiles(job.scenes, *out.scene, reading);
  for (const auto& f : job.portalFiles)
    for (Portal& p : readPortalFile(f)) out.scene->portals.push_back(std::move(p));
  placeLuminaires(*out.scene, job.luminaires);
  if (job.sky) addDaylight(*out.scene, job.sky(daylight));
  // Points are path traced unless the case or the caller says otherwise.
  out.trace = resolveTrace(c ? &c->settings : nullptr, job.trace, Method::kPath);
  out.strict = job.strict;
  const FileLoc where{c ? c->path.string() : !job.scenes.empty() ? job.scenes.front().string() : "command line", 0, 0};
  checkSceneInput(*out.scene, out.warnings);
  checkLightSources(*out.scene, where, out.warnings);
  if (c) out.luminaires = c->luminaires;
  out.luminaires.insert(out.luminaires.end(), job.luminaires.begin(), job.luminaires.end());
  if (!out.luminaires.empty()) checkPhotometry(*out.scene, out.luminaires, out.warnings);
  if (c) checkCaseSite(*c, out.warnings);  // the case's site and weather hour apply under --sky too
  out.limits = job.limits;
  out.pointsName = job.pointsName;
  out.distribution = job.distribution;
  return out;
}

PointsResult computePoints(const PointsScene& ps, AcceleratorKind accelerator, const std::vector<SensorPoint>& points,
                           StudyObserver& observer, const std::vector<FileLoc>& pointLocs) {
  PointsResult r;
  r.trace = ps.trace;
  r.warnings = ps.warnings;
  const FileLoc where{ps.pointsName, 0, 0};
  checkResources(estimatePoints(points.size(), where, *ps.scene, ps.trace.settings, ps.trace.threads), ps.limits,
                 where);
  const Tracer tracer(*ps.scene, accelerator);
  // The time estimate with the share of hemisphere rays that meet the scene (an open site's leave).
  observer.estimated(estimatePoints(points.size(), where, *ps.scene, ps.trace.settings, ps.trace.threads,
                                    hemispherePilot(tracer, points, &ps.trace.settings, ps.trace.threads)));
  SensorSet set;
  set.name = "points";
  set.points = &points;
  set.loc = pointLocs.empty() ? FileLoc{"points", 0, 0} : FileLoc{pointLocs.front().file, 0, 0};
  set.pointLocs = pointLocs;
  checkLuminaires(tracer, ps.luminaires, {set}, r.warnings);
  checkSensors(tracer, set, r.warnings);
  throwIfStrict(r.warnings, ps.strict);
  {
    const ObservedStep step(observer, "tracing", points.size());
    r.estimates = computeIrradiance(tracer, points, ps.trace.settings, ps.trace.threads,
                                    [&step](std::size_t done) { step(done); },
                                    ps.distribution ? *ps.distribution : localDistribution());
  }
  checkFinite(r.estimates, "the points' illuminance");
  if (!points.empty()) {
    std::vector<double> lux, errorLux;
    for (const IrradianceEstimate& e : r.estimates) {
      lux.push_back(e.illuminanceLux());
      errorLux.push_back(e.standardErrorLux());
    }
    checkErrorBars(tracer, set, lux.data(), errorLux.data(), r.warnings);
    checkDarkSensors(set, lux.data(), errorLux.data(), r.warnings);
  }
  throwIfStrict(r.warnings, ps.strict);
  return r;
}

}  // namespace candela
