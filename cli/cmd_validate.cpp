// candela validate [--quick] [--out DIR]: runs the validation cases at the default (or given)
// quality and prints case, reference, result, errors, tolerance, verdict and wall time; writes
// validation.csv and validation.html. Exit code 1 when any case fails.
#include "cli/commands.h"

#include "base/atomic_file.h"
#include "validation/case_registry.h"
#include "validation/validation_html.h"
#include "validation/speed_accuracy.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace candela::cli {

namespace {

struct ValidateOptions {
  bool quick = false;
  std::string out = ".";
  std::string quality = "normal";
  int threads = 0;
  uint64_t seed = 1;
  bool chart = false;
};

int runValidate(const ValidateOptions& o) {
  if (o.chart) {
    // The speed–accuracy study (docs/accuracy.md): CSV and SVG chart in --out.
    const auto rows = validation::runSpeedAccuracy(o.threads, o.quick);
    std::filesystem::create_directories(o.out);
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

  std::ostringstream table, csv;
  char line[512];
  std::snprintf(line, sizeof line, "%-28s %-14s %12s %12s %9s %9s %7s %-7s %8s\n", "case", "point", "reference",
                "result", "max_err%", "rms_err%", "tol%", "verdict", "time_s");
  table << line;
  csv << "case,group,point,unit,reference,result,standard_error,relative_error,tolerance,verdict,time_s\n";
  int failed = 0;
  for (const auto& r : results) {
    // The row shows the point with the largest error.
    const validation::PointResult* worst = &r.points.front();
    for (const auto& p : r.points)
      if (std::abs(p.relativeError()) > std::abs(worst->relativeError())) worst = &p;
    failed += !r.pass();
    std::snprintf(line, sizeof line, "%-28s %-14s %12.5g %12.5g %9.3f %9.3f %7.2f %-7s %8.3f\n", r.name.c_str(),
                  worst->label.c_str(), worst->referenceLux, worst->resultLux, 100 * r.maxRelativeError(),
                  100 * r.rmsRelativeError(), 100 * r.tolerance, r.pass() ? "pass" : "FAIL", r.seconds);
    table << line;
    for (const auto& p : r.points) {
      std::snprintf(line, sizeof line, "%s,%s,\"%s\",%s,%.9g,%.9g,%.4g,%.6g,%.4g,%s,%.4f\n", r.name.c_str(),
                    r.group.c_str(), p.label.c_str(), r.unit.c_str(), p.referenceLux, p.resultLux, p.standardErrorLux,
                    p.relativeError(), r.tolerance, r.pointPasses(p) ? "pass" : "fail",
                    r.seconds);
      csv << line;
    }
  }
  std::snprintf(line, sizeof line, "%zu cases: %zu passed, %d failed\n", results.size(), results.size() - failed,
                failed);
  table << line;
  std::filesystem::create_directories(o.out);
  writeFileAtomic(std::filesystem::path(o.out) / "validation.csv", csv.str());
  // The page embeds the speed–accuracy chart when `--chart` has left one in the same folder.
  validation::ValidationPage page;
  page.quality = o.quality;
  page.seed = o.seed;
  page.version = CANDELA_VERSION;
  if (std::ifstream svg(std::filesystem::path(o.out) / "speed_accuracy.svg"); svg) {
    std::ostringstream ss;
    ss << svg.rdbuf();
    page.chartSvg = ss.str();
    if (const size_t at = page.chartSvg.find("<svg"); at != std::string::npos) page.chartSvg.erase(0, at);
  }
  writeFileAtomic(std::filesystem::path(o.out) / "validation.html", validation::validationHtml(results, page));
  std::cout << table.str() << std::flush;
  return failed ? 1 : 0;
}

}  // namespace

void addValidateCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "validation cases against closed forms, with errors and times");
  cmd->add_flag("--quick", opts->quick, "only the quick subset (run by CI)");
  cmd->add_option("--out", opts->out, "directory for validation.csv (default: current directory)");
  cmd->add_option("--quality", opts->quality, "draft | normal | high (default normal)")
      ->check(CLI::IsMember({"draft", "normal", "high"}));
  cmd->add_option("--threads", opts->threads, "threads, 0 = all cores")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", opts->seed, "random seed");
  cmd->add_flag("--chart", opts->chart, "speed-accuracy study instead: speed_accuracy.csv and .svg in --out");
  cmd->callback([opts, &action] { action = [opts] { return runValidate(*opts); }; });
}

}  // namespace candela::cli
