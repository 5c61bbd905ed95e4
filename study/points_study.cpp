#include "study/points_study.h"

#include "engine/rad_reader.h"
#include "study/case_file.h"
#include "study/case_scene.h"
#include "study/finite_results.h"

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
  return out;
}

PointsResult computePoints(const PointsScene& ps, AcceleratorKind accelerator, const std::vector<SensorPoint>& points,
                           StudyObserver& observer) {
  PointsResult r;
  r.trace = ps.trace;
  const Tracer tracer(*ps.scene, accelerator);
  const ObservedStep step(observer, "tracing", points.size());
  r.estimates = computeIrradiance(tracer, points, ps.trace.settings, ps.trace.threads,
                                  [&step](std::size_t done) { step(done); });
  checkFinite(r.estimates, "the points' illuminance");
  return r;
}

}  // namespace candela
