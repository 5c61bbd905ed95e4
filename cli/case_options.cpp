#include "cli/case_options.h"

namespace candela::cli {

void addCaseTraceOptions(CLI::App* cmd, CaseTraceOptions& o, const std::string& samplesHelp) {
  cmd->add_option("--quality", o.quality, "draft | normal | high (default: the case's, else normal)")
      ->check(CLI::IsMember({"draft", "normal", "high"}));
  cmd->add_option("--bounces", o.bounces, "diffuse interreflections followed (default: case, else quality)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--samples", o.samples, samplesHelp + " (default: case, else quality)")->check(CLI::PositiveNumber);
  cmd->add_option("--seed", o.seed, "random seed (default: the case's, else 1)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--method", o.method, "path | cache (default: the case's, else cache for grids, path for views)")
      ->check(CLI::IsMember({"path", "cache"}));
  cmd->add_option("--threads", o.threads, "threads, 0 = all cores (default: the case's)")->check(CLI::NonNegativeNumber);
}

ResolvedTrace resolveTrace(const CaseFile& c, const CaseTraceOptions& o, Method defaultMethod) {
  ResolvedTrace r;
  r.quality = o.quality.empty() ? c.settings.quality : parseQuality(o.quality);
  r.settings = settingsForQuality(r.quality);
  if (c.settings.bounces) r.settings.maxBounces = *c.settings.bounces;
  if (c.settings.samples) r.settings.hemisphereSamples = *c.settings.samples;
  if (o.bounces >= 0) r.settings.maxBounces = o.bounces;
  if (o.samples > 0) r.settings.hemisphereSamples = o.samples;
  r.settings.seed = o.seed >= 0 ? static_cast<uint64_t>(o.seed) : c.settings.seed;
  r.settings.method = c.settings.method.value_or(defaultMethod);
  if (!o.method.empty()) r.settings.method = parseMethod(o.method);
  r.threads = o.threads >= 0 ? o.threads : c.settings.threads;
  return r;
}

}  // namespace candela::cli
