// `candela run` for a case with [sky] type = "annual" (docs/annual.md): daylight coefficients of
// every grid's sensors, a year of hourly illuminance from the weather file, the annual metrics
// (DA, cDA, UDI, sDA, ASE, hours of sun) and their outputs.
#pragma once

#include "cli/case_options.h"
#include "study/case_file.h"

#include <chrono>
#include <filesystem>
#include <string>

namespace candela::cli {

struct AnnualRunOptions {
  std::filesystem::path outDir;
  CaseTraceOptions trace;
  bool quiet = false;
  std::chrono::steady_clock::time_point start;
  std::string startedAt;
};

// Computes and writes everything; returns the exit code. Throws InputError for bad input before
// anything is written.
int runAnnualCase(const CaseFile& c, const AnnualRunOptions& o);

}  // namespace candela::cli
