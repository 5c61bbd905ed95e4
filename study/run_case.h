// `candela run` as a library call: a case from its file to its result folder. Reads and checks
// everything before tracing; a case with an annual sky is a climate-based annual study
// (study/annual_study.h), any other a point-in-time study of grids and views
// (study/grid_study.h). Throws InputError for bad input before anything is written.
#pragma once

#include "base/distribution.h"
#include "base/input_file.h"
#include "reports/report_data.h"
#include "study/observer.h"
#include "study/resource_estimate.h"
#include "study/trace_options.h"

#include <chrono>
#include <filesystem>
#include <functional>
#include <vector>
#include <string>

namespace candela {

struct RunRequest {
  std::filesystem::path outDir;  // empty: the case's [output] dir
  TraceOverrides trace;
  // Every warning becomes an InputError (the first one, before anything is written).
  bool strict = false;
  ResourceLimits limits;  // checked before tracing (study/resource_estimate.h)
  // The processes the run is shared between (an MPI job, a shard, a merge); null: this one.
  // Not owned.
  const Distribution* distribution = nullptr;
  // How the outputs name the case file; empty: as it was read (a merge reads it by its absolute
  // path and names it as the shards were given it).
  std::string caseFileShown;
  const Distribution& processes() const { return distribution ? *distribution : localDistribution(); }
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
  // The files read since the run started (base/input_file.h); a shard's part carries their
  // fingerprint and a merge compares it. Not owned.
  const InputFileLog* inputs = nullptr;
};

RunResult runCase(const std::filesystem::path& caseFile, const RunRequest& request,
                  StudyObserver& observer = silentObserver());

struct CaseFile;

// `candela merge`: the parts of one sharded run (folders written by `candela run --shard i/N`),
// checked to be one complete set of the case as it is now, into the result folder `outDir`
// (empty: the case's) that the one-process run writes. Throws InputError naming the part that
// is missing, incomplete or from another case, settings or seed.
RunResult mergeParts(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& outDir,
                     int threads, StudyObserver& observer = silentObserver());

// The report data every run starts from: the case's name, file and description, the version,
// start time and seed, and the site's north.
ReportData reportDataFor(const CaseFile& c, const RunContext& run, uint64_t seed);

// Commits the run's result as its processes ask (docs/distributed.md): rank 0 of a job (or the
// one process) writes the result folder by calling write(dir) inside writeRunOutputs; the other
// ranks write nothing; a shard writes its part (study/distributed/shard_distribution.h) instead. A merge's
// distribution first checks that the parts held nothing the run did not use.
void commitRun(const CaseFile& c, const RunContext& run, const std::function<void(const std::filesystem::path&)>& write);

// Rank 0 decides: calls check() there and, when it throws InputError, throws the same on every
// rank (a folder that only rank 0 sees, say), so that no rank waits for another forever.
void checkOnRankZero(const Distribution& d, const std::function<void()>& check);

// The run's options that change its results (everything but threads and resource limits), as
// JSON text: what a shard's part records and merge runs again.
std::string requestJson(const RunRequest& request);
RunRequest requestFromJson(const std::string& text);

// Seconds since `t`.
double secondsSince(std::chrono::steady_clock::time_point t);

}  // namespace candela
