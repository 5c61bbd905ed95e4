// candela luminaire FILE.ies|FILE.ldt [--svg OUT.svg | --no-svg]: photometric summary on stdout
// and a polar candela plot of the C0-C180 and C90-C270 planes (default <stem>_polar.svg in the
// current directory, written atomically).
#include "cli/commands.h"

#include "base/atomic_file.h"
#include "base/input_file.h"
#include "photometry/luminaire_summary.h"
#include "photometry/photometric_web.h"
#include "reports/polar_plot_svg.h"
#include "photometry/photometric_file.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace candela::cli {

namespace {

struct LuminaireOptions {
  std::string file;
  std::string svg;
  bool noSvg = false;
};

int runLuminaire(const LuminaireOptions& o) {
  const PhotometricWeb web = readPhotometricFile(o.file);
  const std::filesystem::path svgPath =
      o.svg.empty() ? std::filesystem::path(std::filesystem::path(o.file).stem().string() + "_polar.svg")
                    : std::filesystem::path(o.svg);
  if (!o.noSvg) checkOutputFile(svgPath);
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
  cmd->callback([opts, &action] { action = [opts] { return runLuminaire(*opts); }; });
}

}  // namespace candela::cli
