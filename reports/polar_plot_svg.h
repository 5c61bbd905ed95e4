// Polar candela plot (SVG) of vertical planes through a luminaire, e.g. C0-C180 and C90-C270.
// Takes plain angle/intensity vectors so that reports stays independent of photometry.
#pragma once

#include <string>
#include <vector>

namespace candela {

struct PolarCurve {
  std::string label;               // legend text, e.g. "C0-C180"
  std::vector<double> angleDeg;    // from nadir, -180..180; positive to the right of the plot
  std::vector<double> intensityCd; // same length as angleDeg, in cd
  std::string colour;              // CSS colour; empty: a default per curve
  bool dashed = false;
};

struct PolarPlotOptions {
  std::string title;      // drawn above the plot when not empty, in as many lines as it needs
  double sizePx = 480.0;  // width of the drawing; the title and the legend add height
  bool legend = true;     // each curve's style and label below the plot
};

// Ring spacing in cd for a plot whose largest intensity is maxCd: a 1, 2, 2.5 or 5 x 10^k step
// giving at most 5 rings.
double polarRingStepCd(double maxCd);

// The SVG document (UTF-8 text). Nadir points down, zenith up; rings every polarRingStepCd,
// labelled in cd inside each ring; radial lines every 30 deg, labelled outside; a legend below
// with each curve's style. A title wider than the drawing is broken into lines (at spaces,
// else inside a word), never clipped.
std::string polarPlotSvg(const std::vector<PolarCurve>& curves, const PolarPlotOptions& options = {});

}  // namespace candela
