#include "study/points_study.h"

#include "engine/rad_reader.h"
#include "study/case_file.h"
#include "study/case_scene.h"

namespace candela {

PointsScene loadPointsScene(const PointsJob& job) {
  PointsScene out;
  DaylightSpec daylight;
  std::optional<CaseFile> c;
  if (!job.caseFile.empty()) {
    c = readCaseFile(job.caseFile);
    // A sky asked for replaces the case's; its site and time still come from the case.
    out.scene = loadCaseScene(*c, !job.sky);
    if (job.sky) daylight = daylightFromCase(*c);
  } else {
    out.scene = std::make_unique<Scene>();
  }
  for (const std::filesystem::path& f : job.scenes) readRadianceFile(f.string(), *out.scene);
  if (job.sky) addDaylight(*out.scene, job.sky(daylight));
  // Points are path traced unless the case or the caller says otherwise.
  out.trace = resolveTrace(c ? &c->settings : nullptr, job.trace, Method::kPath);
  out.limits = job.limits;
  out.pointsName = job.pointsName;
  return out;
}

PointsResult computePoints(const PointsScene& ps, AcceleratorKind accelerator, const std::vector<SensorPoint>& points,
                           StudyObserver& observer) {
  PointsResult r;
  r.trace = ps.trace;
  const FileLoc where{ps.pointsName, 0, 0};
  const ResourceEstimate needs = estimatePoints(points.size(), where, *ps.scene, ps.trace.settings, ps.trace.threads);
  checkResources(needs, ps.limits, where);
  observer.estimated(needs);
  const Tracer tracer(*ps.scene, accelerator);
  const ObservedStep step(observer, "tracing", points.size());
  r.estimates = computeIrradiance(tracer, points, ps.trace.settings, ps.trace.threads,
                                  [&step](std::size_t done) { step(done); });
  return r;
}

}  // namespace candela
