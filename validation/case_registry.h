// Validation cases: a scene with a closed-form (or independently computed) reference, run at the
// default settings, with errors and wall time side by side (docs/validation.md).
#pragma once

#include "engine/tracer.h"

#include <functional>
#include <string>
#include <vector>

namespace candela::validation {

struct PointResult {
  std::string label;          // e.g. "x=0.25 m"
  double referenceLux = 0.0;
  double resultLux = 0.0;
  double standardErrorLux = 0.0;
  double relativeError() const { return referenceLux != 0.0 ? (resultLux - referenceLux) / referenceLux : 0.0; }
};

struct CaseResult {
  std::string name;
  std::string group;          // "engine", "luminaires", "daylight", ...
  std::string reference;      // the closed form, in words
  double tolerance = 0.01;    // on the relative error of every point
  std::vector<PointResult> points;
  double seconds = 0.0;        // wall time of candela's computation (not of the reference)
  double maxRelativeError() const;
  double rmsRelativeError() const;
  bool pass() const { return maxRelativeError() <= tolerance; }
};

struct RunConfig {
  TraceSettings settings;     // default: settingsForQuality(kNormal)
  int threads = 0;
};

struct Case {
  std::string name;
  std::string group;
  bool quick = true;          // part of `candela validate --quick` (CI)
  std::function<CaseResult(const RunConfig&)> run;
};

// Every case, in report order.
std::vector<Case> allCases();

// Runs the cases (all, or the quick subset).
std::vector<CaseResult> runCases(bool quickOnly, const RunConfig& config);

}  // namespace candela::validation
