#include "study/run_case.h"

#include "base/error.h"
#include "study/annual_study.h"
#include "study/case_file.h"
#include "study/grid_study.h"
#include "study/run_outputs.h"

namespace candela {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

ReportData reportDataFor(const CaseFile& c, const RunContext& run, uint64_t seed) {
  ReportData data;
  data.run.caseName = c.name;
  data.run.description = c.description;
  data.run.caseFile = c.path.string();
  data.run.version = CANDELA_VERSION;
  data.run.startedAt = run.startedAt;
  data.run.seed = seed;
  data.northDeg = c.site.northDeg;
  return data;
}

RunResult runCase(const std::filesystem::path& caseFile, const RunRequest& request, StudyObserver& observer) {
  RunContext run;
  run.request = request;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = localTimeNow();
  CaseFile c = readCaseFile(caseFile);
  c.settings.scene = sceneReadOptions(&c.settings, request.trace);
  if (c.grids.empty()) throw InputError(FileLoc{c.path.string(), 0, 0}, "the case has no [[grid]] to calculate");
  run.outDir = request.outDir.empty() ? c.output.dir : request.outDir;
  checkResultFolder(run.outDir);
  if (c.sky.type.kind == SkyKind::kAnnual) return runAnnualStudy(c, run, observer);
  return runGridStudy(c, run, observer);
}

}  // namespace candela
