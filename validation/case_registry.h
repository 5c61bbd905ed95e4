// Validation cases: a scene with a closed-form (or independently computed) reference, run at the
// default settings, with errors and wall time side by side (docs/validation.md).
#pragma once

#include "engine/tracer.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace candela::validation {

// Values are in the case's unit: lux for every lighting case (the field names say so), degrees
// for the solar position case.
struct PointResult {
  std::string label;          // e.g. "x=0.25 m"
  double referenceLux = 0.0;
  double resultLux = 0.0;
  double standardErrorLux = 0.0;
  // Relative to the reference; against a reference of 0 (a dark room) any light is an infinite error.
  double relativeError() const {
    if (referenceLux != 0.0) return (resultLux - referenceLux) / referenceLux;
    return resultLux == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
};

struct CaseResult {
  std::string name;
  std::string group;          // "engine", "luminaires", "daylight", ...
  std::string reference;      // the closed form, in words
  double tolerance = 0.01;    // on the relative error of every point
  std::string unit = "lux";   // of the point values
  std::vector<PointResult> points;
  double seconds = 0.0;        // wall time of candela's computation (not of the reference)
  double maxRelativeError() const;
  double rmsRelativeError() const;
  double absoluteToleranceLux = 0.0;  // a point also passes within this many lux of its reference
  bool pointPasses(const PointResult& p) const {
    return std::abs(p.relativeError()) <= tolerance || std::abs(p.resultLux - p.referenceLux) <= absoluteToleranceLux;
  }
  bool pass() const {
    for (const PointResult& p : points)
      if (!pointPasses(p)) return false;
    return true;
  }
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
