// candela run CASE.toml [--out DIR]: the main job (study/run_case.h computes and writes it); this
// file parses the options, draws progress and prints one line per grid.
#include "cli/case_options.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/resource_options.h"

#include "reports/report_data.h"
#include "study/run_case.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace candela::cli {

namespace {

struct RunOptions {
  std::string caseFile;
  std::string outDir;  // empty: the case's [output] dir
  CaseTraceOptions trace;
  ResourceOptions resources;
  bool quiet = false;
  bool strict = false;
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

int runCommand(const RunOptions& o) {
  RunRequest request;
  request.outDir = o.outDir;
  request.trace = o.trace.overrides();
  request.strict = o.strict;
  request.limits = o.resources.limits();
  ProgressObserver progress(o.quiet, request.limits.maxMemoryBytes);
  const RunResult r = runCase(o.caseFile, request, progress);
  printWarnings(r.data.warnings);
  if (o.quiet) return 0;
  std::ostringstream s;
  for (const GridReport& g : r.data.grids) s << gridLine(g);
  if (r.annual)
    s << "coefficients " << formatFixed(r.coefficientsS, 1) << " s, " << r.hours << "-hour product "
      << formatFixed(r.productS, 2) << " s, run time " << formatFixed(r.data.run.runTimeS, 1) << " s; results in "
      << r.outDir.string() << "\n";
  else
    s << "run time " << formatFixed(r.data.run.runTimeS, 1) << " s; results in " << r.outDir.string() << "\n";
  std::cout << s.str() << std::flush;
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
  cmd->callback([opts, &action] { action = [opts] { return runCommand(*opts); }; });
}

}  // namespace candela::cli
