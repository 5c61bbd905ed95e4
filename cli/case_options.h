// The trace options every case-based command shares (run, render): the case's [settings] first,
// then what the command line says.
#pragma once

#include "study/case_file.h"
#include "engine/tracer.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace candela::cli {

struct CaseTraceOptions {
  std::string quality;  // empty: the case's
  int bounces = -1;     // < 0: the case's, else the quality preset's
  int samples = -1;     // <= 0: the case's, else the preset's
  int64_t seed = -1;    // < 0: the case's
  int threads = -1;     // < 0: the case's
  std::string method;   // empty: the case's, else the command's default
};

// Adds --quality, --bounces, --samples (with `samplesHelp`), --seed, --method and --threads.
void addCaseTraceOptions(CLI::App* cmd, CaseTraceOptions& o, const std::string& samplesHelp);

struct ResolvedTrace {
  Quality quality = Quality::kNormal;
  TraceSettings settings;
  int threads = 0;  // 0 = all cores
};

// `defaultMethod` applies when neither the case nor the command line names one: the irradiance
// cache for grids (`run`), the path tracer for single views (`render`).
ResolvedTrace resolveTrace(const CaseFile& c, const CaseTraceOptions& o, Method defaultMethod);

}  // namespace candela::cli
