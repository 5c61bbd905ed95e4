#include "cli/case_options.h"

#include <iostream>

namespace candela::cli {

void addCaseTraceOptions(CLI::App* cmd, CaseTraceOptions& o, const std::string& samplesHelp,
                         const std::string& methodDefault) {
  cmd->add_option("--quality", o.quality, "draft | normal | high (default: the case's, else normal: accurate)")
      ->check(parsedBy(parseQuality, "QUALITY"));
  // The same bounds as the case file's [settings] (docs/case-format.md).
  cmd->add_option("--bounces", o.bounces, "diffuse interreflections followed (default: case, else quality)")
      ->check(CLI::Range(0, 100));
  cmd->add_option("--samples", o.samples, samplesHelp + " (default: case, else quality)")
      ->check(CLI::Range(1, 1'000'000));
  cmd->add_option("--seed", o.seed, "random seed (same seed, same numbers; default: the case's, else 1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--method", o.method,
                  "path (unbiased path tracer) | cache (Ward's irradiance cache) (default: the case's, else " +
                      methodDefault + ")")
      ->check(parsedBy(parseMethod, "METHOD"));
  cmd->add_option("--target-error", o.targetErrorPct,
                  "sample each point until its standard error is below PCT percent of its value, 0 = one "
                  "batch (default: the case's, else quality: normal and high 0.25 a point, and for run's grids 0.5 of the "
                  "larger of the point's value and its grid's mean; draft none)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--threads", o.threads, "threads, 0 = all cores (default: the case's, else all)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--patterns", o.patterns,
                  "refuse | base: patterns, textures and mixtures candela does not implement are refused, or "
                  "replaced by the material they modify, with a warning each (default: the case's, else refuse)")
      ->check(parsedBy(parsePatternPolicy, "POLICY"));
  cmd->add_option("--nonplanar", o.nonplanar,
                  "refuse | triangulate: a polygon beyond the planarity tolerance is refused, or split into "
                  "triangles with a warning (default: the case's, else refuse)")
      ->check(parsedBy(parseNonplanarPolicy, "POLICY"));
  cmd->add_option("--obj-map", o.objMap,
                  "obj2rad mapping file (obj2rad -m rules) naming the modifiers of the OBJ scene files' faces "
                  "(default: the case's, else usemtl, group, white)")
      ->check(CLI::ExistingFile);
}

TraceOverrides CaseTraceOptions::overrides() const {
  TraceOverrides t;
  if (!quality.empty()) t.quality = parseQuality(quality);
  if (bounces >= 0) t.bounces = bounces;
  if (samples > 0) t.samples = samples;
  if (seed >= 0) t.seed = static_cast<uint64_t>(seed);
  if (threads >= 0) t.threads = threads;
  if (targetErrorPct >= 0.0) t.targetRelativeError = targetErrorPct / 100.0;
  if (!method.empty()) t.method = parseMethod(method);
  if (!patterns.empty()) t.patterns = parsePatternPolicy(patterns);
  if (!nonplanar.empty()) t.nonplanar = parseNonplanarPolicy(nonplanar);
  if (!objMap.empty()) t.objMapping = std::filesystem::path(objMap);
  return t;
}

void addStrictOption(CLI::App* cmd, bool& strict) {
  cmd->add_flag("--strict", strict,
                "treat every warning as an error: exit 2 with the first one, before any output is written");
}

void printWarnings(const std::vector<Warning>& warnings) {
  for (const Warning& w : warnings) std::cerr << warningLine(w) << "\n";
  std::cerr << std::flush;
}

}  // namespace candela::cli
