#include "reports/plan_svg.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sample_report.h"

namespace candela {
namespace {

PlanLayout lattice(int nx, int ny, double s, std::vector<double>& values, double (*f)(Vec2)) {
  PlanLayout L;
  L.regular = true;
  L.columns = nx;
  L.rows = ny;
  L.originM = Vec2(-0.5 * nx * s, -0.5 * ny * s);
  L.spacingM = Vec2(s);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      L.cells.emplace_back(i, j);
      values.push_back(f(L.originM + (Vec2(i, j) + 0.5) * s));
    }
  return L;
}

// A linear field f = x: linear interpolation is exact, the 0.3 isoline is the line x = 0.3.
TEST(Isolines, LinearFieldGivesStraightLine) {
  std::vector<double> v;
  const PlanLayout L = lattice(20, 10, 0.1, v, [](Vec2 p) { return p.x; });
  const auto lines = isolines(L, v, 0.3);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FALSE(lines[0].closed);
  EXPECT_EQ(lines[0].points.size(), 10u);  // one crossing per row of nodes
  for (const Vec2& p : lines[0].points) EXPECT_NEAR(p.x, 0.3, 1e-12);
}

// f = x² + y²: the level r² isoline is a closed loop near the circle of radius r. Linear
// interpolation of x² over an edge of length h overestimates by at most h²/4 (f'' = 2, error
// f''h²/8), which moves the crossing inwards by at most (h²/4)/(2r).
TEST(Isolines, RadialFieldGivesClosedCircle) {
  std::vector<double> v;
  const double h = 0.1, r = 1.5;
  const PlanLayout L = lattice(40, 40, h, v, [](Vec2 p) { return glm::dot(p, p); });
  const auto lines = isolines(L, v, r * r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].closed);
  for (const Vec2& p : lines[0].points) EXPECT_NEAR(glm::length(p), r, h * h / (8.0 * r) + 1e-12);
}

// Cells outside a polygon are missing: no isoline crosses the hole.
TEST(Isolines, SkipsMissingCells) {
  std::vector<double> v;
  PlanLayout L = lattice(10, 10, 0.1, v, [](Vec2 p) { return p.x; });
  std::vector<double> kept;
  PlanLayout holed = L;
  holed.cells.clear();
  for (std::size_t k = 0; k < L.cells.size(); ++k)
    if (L.cells[k].y != 5) {
      holed.cells.push_back(L.cells[k]);
      kept.push_back(v[k]);
    }
  const auto lines = isolines(holed, kept, 0.02);
  EXPECT_EQ(lines.size(), 2u);  // the row of missing cells cuts the line in two
}

TEST(PlanSvg, DrawsCellsContoursLegendScaleBarAndNorth) {
  const GridReport g = testing_sample::sampleGrid("Work plane", 0.5, 0.5, 5.5, 3.5, 0.25);
  const ColorScale scale = niceScale(0.0, g.stats.maximumLux);
  PlanOptions opt;
  opt.northDeg = 30.0;
  const std::string svg = planSvg(g, scale, opt);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_EQ(svg.find("xmlns"), std::string::npos);  // inline form
  std::size_t rects = 0;
  for (std::size_t p = svg.find("<rect"); p != std::string::npos; p = svg.find("<rect", p + 1)) ++rects;
  EXPECT_GE(rects, g.values.size());                  // one per cell plus frame, legend, scale bar
  EXPECT_NE(svg.find("<polyline"), std::string::npos);  // isolines
  EXPECT_NE(svg.find("rotate(30)"), std::string::npos);  // north arrow turned to true north
  EXPECT_NE(svg.find(">lx</text>"), std::string::npos);  // legend unit
  EXPECT_NE(svg.find(" m</text>"), std::string::npos);   // scale bar
  EXPECT_NE(svg.find("plan-scale"), std::string::npos);  // gradient id with the prefix
}

TEST(PlanSvg, IrregularGridsAsDots) {
  GridReport g;
  g.name = "desk";
  g.values = {100, 200, 300};
  g.layout.planPositions = {{1, 1}, {1.5, 1}, {2, 1}};
  g.stats = computeGridStats(g.values);
  const std::string svg = planSvg(g, niceScale(0, 300));
  std::size_t dots = 0;
  for (std::size_t p = svg.find("<circle cx"); p != std::string::npos; p = svg.find("<circle cx", p + 1)) ++dots;
  EXPECT_EQ(dots, 3u);
}

TEST(PlanSvg, EscapesText) { EXPECT_EQ(xmlEscape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;"); }

}  // namespace
}  // namespace candela
