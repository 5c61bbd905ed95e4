#include "validation/validation_report.h"

#include "base/atomic_file.h"
#include "base/error.h"
#include "validation/validation_html.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace candela::validation {

int failedCases(const std::vector<CaseResult>& results) {
  int failed = 0;
  for (const CaseResult& r : results) failed += !r.pass();
  return failed;
}

std::string validationTable(const std::vector<CaseResult>& results) {
  std::ostringstream table;
  char line[512];
  std::snprintf(line, sizeof line, "%-28s %-14s %12s %12s %9s %9s %7s %-7s %8s\n", "case", "point", "reference",
                "result", "max_err%", "rms_err%", "tol%", "verdict", "time_s");
  table << line;
  for (const CaseResult& r : results) {
    // The row shows the point with the largest error.
    const PointResult* worst = &r.points.front();
    for (const PointResult& p : r.points)
      if (std::abs(p.relativeError()) > std::abs(worst->relativeError())) worst = &p;
    std::snprintf(line, sizeof line, "%-28s %-14s %12.5g %12.5g %9.3f %9.3f %7.2f %-7s %8.3f\n", r.name.c_str(),
                  worst->label.c_str(), worst->referenceLux, worst->resultLux, 100 * r.maxRelativeError(),
                  100 * r.rmsRelativeError(), 100 * r.tolerance, r.pass() ? "pass" : "FAIL", r.seconds);
    table << line;
  }
  const int failed = failedCases(results);
  std::snprintf(line, sizeof line, "%zu cases: %zu passed, %d failed\n", results.size(), results.size() - failed,
                failed);
  table << line;
  return table.str();
}

std::string validationCsv(const std::vector<CaseResult>& results) {
  std::ostringstream csv;
  csv << "case,group,point,unit,reference,result,standard_error,relative_error,tolerance,verdict,time_s\n";
  char line[512];
  for (const CaseResult& r : results)
    for (const PointResult& p : r.points) {
      std::snprintf(line, sizeof line, "%s,%s,\"%s\",%s,%.9g,%.9g,%.4g,%.6g,%.4g,%s,%.4f\n", r.name.c_str(),
                    r.group.c_str(), p.label.c_str(), r.unit.c_str(), p.referenceLux, p.resultLux, p.standardErrorLux,
                    p.relativeError(), r.tolerance, r.pointPasses(p) ? "pass" : "fail", r.seconds);
      csv << line;
    }
  return csv.str();
}

void prepareOutputFolder(const std::filesystem::path& dir) {
  // An --out that is not a folder (a file, a device) is the user's to fix: exit 2, not 1.
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(FileLoc{dir.string(), 0, 0}, "the output folder cannot be created (" +
                                                      (ec ? ec.message() : std::string("not a folder")) + ")");
}

void writeValidationOutputs(const std::filesystem::path& dir, const std::vector<CaseResult>& results,
                            const std::string& quality, uint64_t seed) {
  prepareOutputFolder(dir);
  writeFileAtomic(dir / "validation.csv", validationCsv(results));
  ValidationPage page;
  page.quality = quality;
  page.seed = seed;
  page.version = CANDELA_VERSION;
  if (std::ifstream svg(dir / "speed_accuracy.svg"); svg) {
    std::ostringstream ss;
    ss << svg.rdbuf();
    page.chartSvg = ss.str();
    if (const size_t at = page.chartSvg.find("<svg"); at != std::string::npos) page.chartSvg.erase(0, at);
  }
  writeFileAtomic(dir / "validation.html", validationHtml(results, page));
}

}  // namespace candela::validation
