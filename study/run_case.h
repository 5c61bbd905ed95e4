// `candela run` as a library call: a case from its file to its result folder. Reads and checks
// everything before tracing; a case with an annual sky is a climate-based annual study
// (study/annual_study.h), any other a point-in-time study of grids and views
// (study/grid_study.h). Throws InputError for bad input before anything is written.
#pragma once

#include "reports/report_data.h"
#include "study/observer.h"
#include "study/resource_estimate.h"
#include "study/trace_options.h"

#include <chrono>
#include <filesystem>
#include <string>

namespace candela {

struct RunRequest {
  std::filesystem::path outDir;  // empty: the case's [output] dir
  TraceOverrides trace;
  // Every warning becomes an InputError (the first one, before anything is written).
  bool strict = false;
  ResourceLimits limits;  // checked before tracing (study/resource_estimate.h)
};

// What a finished run wrote, for the caller to summarise.
struct RunResult {
  std::filesystem::path outDir;
  ReportData data;               // data.warnings: what the run found suspicious (study/warnings.h)
  bool annual = false;
  int hours = 0;                 // annual: hours of the weather year
  double coefficientsS = 0.0;    // annual: wall time of the coefficients, s
  double productS = 0.0;         // annual: wall time of the hourly products, s
};

// Where a run starts: its request and the clock.
struct RunContext {
  RunRequest request;
  std::filesystem::path outDir;
  std::chrono::steady_clock::time_point start;
  std::string startedAt;  // local time, "YYYY-MM-DD HH:MM"
};

RunResult runCase(const std::filesystem::path& caseFile, const RunRequest& request,
                  StudyObserver& observer = silentObserver());

struct CaseFile;

// The report data every run starts from: the case's name, file and description, the version,
// start time and seed, and the site's north.
ReportData reportDataFor(const CaseFile& c, const RunContext& run, uint64_t seed);

// Seconds since `t`.
double secondsSince(std::chrono::steady_clock::time_point t);

}  // namespace candela
