#include "reports/polar_plot_svg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

namespace candela {
namespace {

TEST(PolarPlotSvg, RingStepIsNiceAndCoversTheMaximum) {
  EXPECT_DOUBLE_EQ(polarRingStepCd(1234.0), 250.0);
  EXPECT_DOUBLE_EQ(polarRingStepCd(1000.0), 200.0);
  EXPECT_DOUBLE_EQ(polarRingStepCd(90.0), 20.0);
  EXPECT_DOUBLE_EQ(polarRingStepCd(12.0), 2.5);
  EXPECT_DOUBLE_EQ(polarRingStepCd(0.0), 1.0);
}

TEST(PolarPlotSvg, ConstantCurveLiesOnTheOuterRing) {
  // I = 1000 cd in every direction: step 200 cd, 5 rings, so the curve is the outer circle.
  PolarCurve c{"C0-C180", {}, {}, "", false};
  for (int a = -180; a <= 180; a += 10) {
    c.angleDeg.push_back(a);
    c.intensityCd.push_back(1000.0);
  }
  PolarCurve d = c;
  d.label = "C90-C270 & more";
  d.dashed = true;
  const std::string svg = polarPlotSvg({c, d}, PolarPlotOptions{"Test <plot>", 480.0});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("Test &lt;plot&gt;"), std::string::npos);
  EXPECT_NE(svg.find("C90-C270 &amp; more"), std::string::npos);
  EXPECT_NE(svg.find("1000 cd"), std::string::npos);
  EXPECT_NE(svg.find("200 cd"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find(">90&#176;<"), std::string::npos);

  double outer = 0.0;
  const std::regex ring("<circle class=\"ring\" r=\"([0-9.]+)\"");
  int nRings = 0;
  for (std::sregex_iterator it(svg.begin(), svg.end(), ring), end; it != end; ++it, ++nRings)
    outer = std::max(outer, std::stod((*it)[1]));
  EXPECT_EQ(nRings, 5);
  EXPECT_NEAR(outer, 480.0 / 2.0 - 36.0, 0.01);
  // Every vertex of the curves at the outer radius (coordinates printed to 0.01 px).
  const std::regex path("<path class=\"curve\" d=\"([^\"]+)\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, path));
  const std::string pts = m[1];
  const std::regex pt("[ML](-?[0-9.]+) (-?[0-9.]+)");
  int n = 0;
  for (std::sregex_iterator it(pts.begin(), pts.end(), pt), end; it != end; ++it, ++n)
    EXPECT_NEAR(std::hypot(std::stod((*it)[1]), std::stod((*it)[2])), outer, 0.02);
  EXPECT_EQ(n, 37);
}

TEST(PolarPlotSvg, NadirPointsDown) {
  // A single lobe at nadir: its vertex is straight below the centre (positive SVG y).
  PolarCurve c{"down", {-10.0, 0.0, 10.0}, {0.0, 100.0, 0.0}, "", false};
  const std::string svg = polarPlotSvg({c});
  EXPECT_NE(svg.find("L0.00 " ), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("L0.00 ([0-9.]+) L")));
  EXPECT_GT(std::stod(m[1]), 0.0);
}

// The title is never wider than the drawing: a long one (a luminaire's name with its file) is
// broken at spaces into lines of at most (width − 12 px) / (0.64 · 13 px) characters, each
// centred, the plot moved down by 16 px a line; a word longer than a line is cut.
TEST(PolarPlotSvg, LongTitlesWrapInsteadOfClipping) {
  PolarCurve c{"C0-C180", {-90.0, 0.0, 90.0}, {0.0, 100.0, 0.0}, "", false};
  const std::string title = "LED panel 600 x 600 mm, opal diffuser, recessed (led_panel_600.ies)";
  for (const double size : {200.0, 480.0}) {
    const std::string svg = polarPlotSvg({c}, PolarPlotOptions{title, size});
    const std::size_t maxChars = static_cast<std::size_t>((size - 12.0) / (0.64 * 13.0));
    const std::regex line("<text x=\"([0-9.]+)\" y=\"([0-9.]+)\" text-anchor=\"middle\" font-size=\"13\" "
                          "font-weight=\"bold\">([^<]*)</text>");
    std::string joined;
    std::vector<std::string> texts;
    for (std::sregex_iterator it(svg.begin(), svg.end(), line), end; it != end; ++it) {
      const std::string text = (*it)[3];
      EXPECT_LE(text.size(), maxChars) << text;
      EXPECT_DOUBLE_EQ(std::stod((*it)[1]), size / 2.0);
      EXPECT_DOUBLE_EQ(std::stod((*it)[2]), 20.0 + 16.0 * static_cast<double>(texts.size()));
      joined += (joined.empty() ? "" : " ") + text;
      texts.push_back(text);
    }
    EXPECT_EQ(joined, title);  // every word, in order
    EXPECT_EQ(texts.size(), size < 300.0 ? 4u : 2u);
    // No more lines than needed: the next line's first word would not have fitted.
    for (std::size_t k = 0; k + 1 < texts.size(); ++k)
      EXPECT_GT(texts[k].size() + 1 + std::min(texts[k + 1].find(' '), texts[k + 1].size()), maxChars) << texts[k];
    const int lines = static_cast<int>(texts.size());
    // The drawing is as much taller as the lines need (legend: one curve, 36 px).
    std::smatch h;
    ASSERT_TRUE(std::regex_search(svg, h, std::regex("height=\"([0-9.]+)\"")));
    EXPECT_DOUBLE_EQ(std::stod(h[1]), size + 28.0 + 16.0 * (lines - 1) + 36.0);
  }
  // A word wider than the plot is cut where it must be; a short title stays one line at y = 20.
  const std::string word(60, 'x');
  const std::string cut = polarPlotSvg({c}, PolarPlotOptions{word, 200.0});
  EXPECT_NE(cut.find(">" + std::string(22, 'x') + "<"), std::string::npos);
  EXPECT_NE(polarPlotSvg({c}, PolarPlotOptions{"P", 200.0}).find("y=\"20\" text-anchor"), std::string::npos);
}

// Each ring's label lies just inside its ring, so the outer ring's never meets the angle labels
// outside the circle; without a legend the drawing ends below the 0° label.
TEST(PolarPlotSvg, RingLabelsInsideAndOptionalLegend) {
  PolarCurve c{"C0-C180", {-90.0, 0.0, 90.0}, {0.0, 1000.0, 0.0}, "", false};
  const std::string svg = polarPlotSvg({c}, PolarPlotOptions{"", 200.0, false});
  EXPECT_EQ(svg.find("C0-C180"), std::string::npos);  // no legend
  EXPECT_NE(svg.find("height=\"200.00\""), std::string::npos);
  const double outer = 200.0 / 2.0 - 36.0;  // 5 rings of 200 cd: the last at the radius
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("<text x=\"4\" y=\"(-?[0-9.]+)\">1000 cd</text>")));
  const double y = std::stod(m[1]);
  EXPECT_GT(y, -outer + 10.0);  // the label's 10 px cap height below the ring line
  EXPECT_LT(y, -outer + 12.0);
}

}  // namespace
}  // namespace candela
