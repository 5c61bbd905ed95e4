// The trace options every command shares (points, run, render), parsed into the study layer's
// TraceOverrides (study/trace_options.h resolves them over the case and the preset).
#pragma once

#include "base/warning.h"
#include "study/trace_options.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela::cli {

struct CaseTraceOptions {
  std::string quality;  // empty: the case's
  int bounces = -1;     // < 0: the case's, else the quality preset's
  int samples = -1;     // <= 0: the case's, else the preset's
  int64_t seed = -1;    // < 0: the case's
  int threads = -1;     // < 0: the case's
  double targetErrorPct = -1.0;  // < 0: the case's, else the preset's
  std::string method;   // empty: the case's, else the command's default
  std::string patterns;   // empty: the case's ([settings] patterns), else refuse
  std::string nonplanar;  // empty: the case's ([settings] nonplanar), else refuse
  std::string objMap;     // empty: the case's ([settings] obj_map), else none
  TraceOverrides overrides() const;
};

// Checks an option's text with the engine's own parser of those names (parseQuality,
// parseMethod, parseAccelerator), so the names live in one place.
template <class Parse>
CLI::Validator parsedBy(Parse parse, const std::string& description) {
  return CLI::Validator(
      [parse](std::string& s) -> std::string {
        try {
          parse(s);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      description);
}

// Adds --quality, --bounces, --samples (with `samplesHelp`), --seed, --method and --threads;
// `defaults` ends the help text of --quality and --method ("the case's, else ...").
void addCaseTraceOptions(CLI::App* cmd, CaseTraceOptions& o, const std::string& samplesHelp,
                         const std::string& methodDefault = "cache");

// Adds --strict (every warning an error, exit 2) to a command.
void addStrictOption(CLI::App* cmd, bool& strict);

// Prints each warning as one line on stderr ("warning: file:line: message [code]"); --quiet
// does not silence them.
void printWarnings(const std::vector<Warning>& warnings);

}  // namespace candela::cli
