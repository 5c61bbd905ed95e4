// candela run CASE.toml [--out DIR]: the main job (study/run_case.h computes and writes it); this
// file parses the options, draws progress and prints one line per grid.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/processes.h"
#include "cli/progress.h"
#include "cli/resource_options.h"

#include "reports/report_data.h"
#include "base/error.h"
#include "study/run_case.h"
#include "study/distributed/shard_distribution.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace candela::cli {

namespace {

struct RunOptions {
  std::string caseFile;
  std::string outDir;  // empty: the case's [output] dir
  CaseTraceOptions trace;
  ResourceOptions resources;
  bool quiet = false;
  bool strict = false;
  std::string shard;  // "i/N": this share of the run, a part for `candela merge`
};

std::string gridLine(const GridReport& r) {
  char buf[256];
  if (r.annual) {
    const GridAnnualSummary& m = r.annual->summary;
    std::snprintf(buf, sizeof buf,
                  "%-20s %6d points  DA300 %5.1f %%  cDA300 %5.1f %%  UDI_autonomous %5.1f %%  sDA300_50 %5.1f %%  "
                  "ASE1000_250 %5.1f %%\n",
                  r.name.c_str(), m.sensors, m.DA300, m.cDA300, m.UDI_autonomous, m.sDA300_50, m.ASE1000_250);
  } else if (r.unit == "%") {
    std::snprintf(buf, sizeof buf, "%-20s %6zu points  DFavg %5.2f %%  DFmin %5.2f %%  DFmedian %5.2f %%  %s\n",
                  r.name.c_str(), r.stats.count, r.stats.averageLux, r.stats.minimumLux, r.stats.medianLux,
                  verdictName(r.check.overall));
  } else {
    std::snprintf(buf, sizeof buf, "%-20s %6zu points  Eavg %7.1f lx  Emin %7.1f lx  U0 %.2f  %s\n", r.name.c_str(),
                  r.stats.count, r.stats.averageLux, r.stats.minimumLux, r.stats.u0, verdictName(r.check.overall));
  }
  return buf;
}

// Prints what a finished run wrote, one line per grid and the times.
void printResult(const RunResult& r) {
  std::ostringstream s;
  for (const GridReport& g : r.data.grids) s << gridLine(g);
  if (r.annual)
    s << "coefficients " << formatFixed(r.coefficientsS, 1) << " s, " << r.hours << "-hour product "
      << formatFixed(r.productS, 2) << " s, run time " << formatFixed(r.data.run.runTimeS, 1) << " s; results in "
      << r.outDir.string() << "\n";
  else
    s << "run time " << formatFixed(r.data.run.runTimeS, 1) << " s; results in " << r.outDir.string() << "\n";
  std::cout << s.str() << std::flush;
}

int runCommand(const RunOptions& o) {
  RunRequest request;
  request.outDir = o.outDir;
  request.trace = o.trace.overrides();
  request.strict = o.strict;
  request.limits = o.resources.limits();
  std::unique_ptr<ShardDistribution> shard;
  if (!o.shard.empty()) {
    const FileLoc cli{"command line", 0, 0};
    if (processes().ranks() > 1) throw InputError(cli, "--shard is for runs without MPI: under mpirun the ranks share the work");
    if (o.outDir.empty()) throw InputError(cli, "--shard needs --out (a folder of its own for each part)");
    try {
      shard = std::make_unique<ShardDistribution>(parseShard(o.shard));
    } catch (const std::invalid_argument& e) {
      throw InputError(cli, e.what());
    }
    request.distribution = shard.get();
  } else {
    request.distribution = &processes();
  }
  const bool prints = printsResults(*request.distribution);
  ProgressObserver progress(o.quiet || !prints, request.limits.maxMemoryBytes);
  const RunResult r = runCase(o.caseFile, request, progress);
  if (!prints) return 0;
  printWarnings(r.data.warnings);
  if (o.quiet) return 0;
  if (shard) {
    std::cout << "part " << o.shard << " of the run in " << formatFixed(r.data.run.runTimeS, 1) << " s: "
              << r.outDir.string() << " (candela merge joins the parts)\n"
              << std::flush;
    return 0;
  }
  printResult(r);
  return 0;
}

struct MergeOptions {
  std::vector<std::string> parts;
  std::string outDir;
  int threads = 0;
  bool quiet = false;
};

int mergeCommand(const MergeOptions& o) {
  std::vector<std::filesystem::path> parts(o.parts.begin(), o.parts.end());
  ProgressObserver progress(o.quiet);
  const RunResult r = mergeParts(parts, o.outDir, o.threads, progress);
  printWarnings(r.data.warnings);
  if (!o.quiet) printResult(r);
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "calculate a case: grids, metrics, CSV/JSON summaries and an HTML report");
  cmd->add_option("case", opts->caseFile, "case file (TOML, docs/case-format.md)")->required();
  cmd->add_option("--out", opts->outDir, "results folder (default: the case's [output] dir)");
  addCaseTraceOptions(cmd, opts->trace, "hemisphere samples per point");
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress bar, notes or result lines (errors and warnings only)");
  addStrictOption(cmd, opts->strict);
  addResourceOptions(cmd, opts->resources);
  cmd->add_option("--shard", opts->shard,
                  "i/N: compute share i of N (0 <= i < N) into --out, a part for `candela merge` (docs/distributed.md)");
  cmd->callback([opts, &action] { action = [opts] { return runCommand(*opts); }; });
}

void addMergeCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<MergeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "join the parts of a sharded run (candela run --shard i/N) into the one-process result");
  cmd->add_option("parts", opts->parts, "the part folders, all N of them")->required();
  cmd->add_option("--out", opts->outDir, "results folder (default: the case's [output] dir)");
  cmd->add_option("--threads", opts->threads, "threads for what merge computes again (0 = all cores)")
      ->check(CLI::Range(0, 4096));
  cmd->add_flag("--quiet,-q", opts->quiet, "no progress bar or result lines (errors and warnings only)");
  cmd->callback([opts, &action] { action = [opts] { return mergeCommand(*opts); }; });
}

}  // namespace candela::cli
