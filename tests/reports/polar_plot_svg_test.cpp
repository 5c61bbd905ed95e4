#include "reports/polar_plot_svg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

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

}  // namespace
}  // namespace candela
