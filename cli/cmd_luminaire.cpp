// candela luminaire FILE.ies|FILE.ldt [--svg OUT.svg | --no-svg] [--ugr-table [--ugr-csv OUT.csv]
// [--ugr-svg OUT.svg]]: photometric summary on stdout and a polar candela plot of the C0-C180 and
// C90-C270 planes (default <stem>_polar.svg in the current directory, written atomically); with
// --ugr-table the CIE 190 UGR table after the summary, as CSV (<stem>_ugr.csv) and SVG
// (<stem>_ugr.svg).
#include "cli/commands.h"

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "photometry/luminaire_summary.h"
#include "photometry/photometric_web.h"
#include "reports/polar_plot_svg.h"
#include "photometry/photometric_file.h"
#include "reports/ugr_table_report.h"
#include "study/ugr_table_study.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace candela::cli {

namespace {

struct LuminaireOptions {
  std::string file;
  std::string svg;
  bool noSvg = false;
  bool ugrTable = false;
  std::string ugrCsv, ugrSvg;
};

std::filesystem::path besideStem(const std::string& file, const std::string& given, const char* suffix) {
  return given.empty() ? std::filesystem::path(std::filesystem::path(file).stem().string() + suffix)
                       : std::filesystem::path(given);
}

int runLuminaire(const LuminaireOptions& o) {
  const PhotometricWeb web = readPhotometricFile(o.file);
  const std::filesystem::path svgPath = besideStem(o.file, o.svg, "_polar.svg");
  const std::filesystem::path ugrCsvPath = besideStem(o.file, o.ugrCsv, "_ugr.csv");
  const std::filesystem::path ugrSvgPath = besideStem(o.file, o.ugrSvg, "_ugr.svg");
  const bool ugr = o.ugrTable || !o.ugrCsv.empty() || !o.ugrSvg.empty();
  if (!o.noSvg) checkOutputFile(svgPath);
  if (ugr) {
    checkOutputFile(ugrCsvPath);
    checkOutputFile(ugrSvgPath);
  }
  // The table first: a file without a luminous area is refused before anything is written.
  const LuminaireUgrTable ugrTable = ugr ? luminaireUgrTable(web) : LuminaireUgrTable{};
  const LuminaireSummary summary = summarizeLuminaire(web);
  std::string report = formatSummary(summary);
  if (!o.noSvg) {
    const std::filesystem::path& out = svgPath;
    const PlaneCurve c0 = planeCurve(web, 0.0, 1.0), c90 = planeCurve(web, 90.0, 1.0);
    std::string title = std::filesystem::path(o.file).filename().string();
    if (!summary.luminaire.empty()) title = summary.luminaire + " (" + title + ")";
    const std::string svg = polarPlotSvg({PolarCurve{"C0-C180", c0.angleDeg, c0.intensityCd, "#c0392b", false},
                                          PolarCurve{"C90-C270", c90.angleDeg, c90.intensityCd, "#1f5fa8", true}},
                                         PolarPlotOptions{title, 480.0});
    writeFileAtomic(out, svg);
    report += "Polar plot:           " + out.string() + "\n";
  }
  if (ugr) {
    UgrTableLabels labels{summary.luminaire.empty() ? std::filesystem::path(o.file).filename().string()
                                                    : summary.luminaire,
                          kUgrReferenceLampLumens, ugrTable.lampLumens, ugrTable.absolutePhotometry};
    writeFileAtomic(ugrCsvPath, ugrTableCsv(ugrTable.table));
    writeFileAtomic(ugrSvgPath, ugrTableSvg(ugrTable.table, labels));
    report += "\n" + ugrTableText(ugrTable.table, labels);
    report += "UGR table CSV:        " + ugrCsvPath.string() + "\nUGR table SVG:        " + ugrSvgPath.string() + "\n";
  }
  std::cout << report;
  return 0;
}

}  // namespace

void addLuminaireCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<LuminaireOptions>();
  auto* cmd = app.add_subcommand("luminaire", "photometric summary and polar plot of an IES or EULUMDAT file");
  cmd->add_option("file", opts->file, "luminaire file (.ies or .ldt)")->required();
  cmd->add_option("--svg", opts->svg, "polar plot output (default: <stem>_polar.svg in the current directory)");
  cmd->add_flag("--no-svg", opts->noSvg, "do not write the polar plot");
  cmd->add_flag("--ugr-table", opts->ugrTable,
                "print the CIE 190 UGR table (S = 0.25 H, 1000 lm of lamps) and write it as CSV and SVG");
  cmd->add_option("--ugr-csv", opts->ugrCsv, "UGR table CSV (default: <stem>_ugr.csv in the current directory)");
  cmd->add_option("--ugr-svg", opts->ugrSvg, "UGR table SVG (default: <stem>_ugr.svg in the current directory)");
  cmd->callback([opts, &action] { action = [opts] { return runLuminaire(*opts); }; });
}

}  // namespace candela::cli
