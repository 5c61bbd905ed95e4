// candela validate [--quick] [--out DIR]: runs the validation cases at the default (or given)
// quality and prints case, reference, result, errors, tolerance, verdict and wall time; writes
// validation.csv and validation.html into DIR (default validation-results/, never the current
// folder itself). Exit code 1 when any case fails; 2 when DIR cannot be a folder, found before
// any case runs.
#include "cli/case_options.h"
#include "cli/commands.h"

#include "base/atomic_file.h"
#include "validation/case_registry.h"
#include "validation/validation_report.h"
#include "validation/speed_accuracy.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace candela::cli {

namespace {

struct ValidateOptions {
  bool quick = false;
  std::string out = "validation-results";
  std::string quality = "normal";
  int threads = 0;
  uint64_t seed = 1;
  bool chart = false;
};

int runValidate(const ValidateOptions& o) {
  // A folder that cannot be made is reported before minutes of tracing, not after.
  validation::prepareOutputFolder(o.out);
  if (o.chart) {
    // The speed–accuracy study (docs/accuracy.md): CSV and SVG chart in --out.
    const auto rows = validation::runSpeedAccuracy(o.threads, o.quick);
    writeFileAtomic(std::filesystem::path(o.out) / "speed_accuracy.csv", validation::speedAccuracyCsv(rows));
    writeFileAtomic(std::filesystem::path(o.out) / "speed_accuracy.svg", validation::speedAccuracySvg(rows));
    std::cout << validation::speedAccuracyCsv(rows) << std::flush;
    return 0;
  }
  validation::RunConfig cfg;
  cfg.settings = settingsForQuality(parseQuality(o.quality));
  cfg.settings.seed = o.seed;
  cfg.threads = o.threads;
  const std::vector<validation::CaseResult> results = validation::runCases(o.quick, cfg);
  validation::writeValidationOutputs(o.out, results, o.quality, o.seed);
  std::cout << validation::validationTable(results) << std::flush;
  return validation::failedCases(results) ? 1 : 0;
}

}  // namespace

void addValidateCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "validation cases against closed forms, with errors and times");
  cmd->add_flag("--quick", opts->quick, "only the quick subset (run by CI)");
  cmd->add_option("--out", opts->out, "folder for validation.csv and validation.html (default validation-results)");
  cmd->add_option("--quality", opts->quality, "draft | normal | high (default normal)")
      ->check(parsedBy(parseQuality, "QUALITY"));
  cmd->add_option("--threads", opts->threads, "threads, 0 = all cores")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", opts->seed, "random seed");
  cmd->add_flag("--chart", opts->chart, "speed-accuracy study instead: speed_accuracy.csv and .svg in --out");
  cmd->callback([opts, &action] { action = [opts] { return runValidate(*opts); }; });
}

}  // namespace candela::cli
