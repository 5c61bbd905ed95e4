#include "reports/plan_svg.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstdio>
#include <string>

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

// A dense grid (10⁶ points) whose values carry a checkerboard of noise five times the field's
// step from one cell to the next: traced cell by cell it would give thousands of tiny loops; on
// blocks of 4 × 4 cells (1000 / kMaxContourNodes rounded up) the noise cancels and the cone
// f = |p| gives one circle, off by no more than the block mean's and the interpolation's bias,
// a²/(24 r) + a²/(8 r) for blocks of side a (f'' ≤ 1/r).
TEST(Isolines, DenseNoisyGridsAreTracedOnBlocks) {
  std::vector<double> v;
  const int n = 1000;
  const double h = 0.002, r = 0.6;
  PlanLayout L = lattice(n, n, h, v, [](Vec2 p) { return glm::length(p); });
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(j) * n + i] += (i + j) % 2 ? 0.01 : -0.01;
  const int f = (n + kMaxContourNodes - 1) / kMaxContourNodes;
  ASSERT_EQ(f, 4);
  const auto lines = isolines(L, v, r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].closed);
  const double a = f * h;
  for (const Vec2& p : lines[0].points) EXPECT_NEAR(glm::length(p), r, a * a / (6.0 * r) + 1e-12);
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

// Isoline labels never overlap: on a field whose lines run 10 px apart (less than a label's
// 17 px height), every label's box (11 px bold digits 0.556 em wide, as Helvetica's, and the
// 3 px halo) is apart from every other's (separating axes of the rotated boxes), and labels are
// still drawn, spread along the lines.
TEST(PlanSvg, ContourLabelsDoNotOverlap) {
  std::vector<double> values;
  GridReport g;
  g.name = "ramp";
  g.layout = lattice(40, 20, 0.1, values, [](Vec2 p) { return 100.0 * (p.y + 1.0); });  // 4 m × 2 m
  g.values = values;
  g.stats = computeGridStats(g.values);
  PlanOptions o;
  o.cellValues = false;
  for (double v = 5.0; v < 200.0; v += 8.33) o.contourLevels.push_back(v);  // 1/12 m apart: 10 px at 120 px/m
  const std::string svg = planSvg(g, niceScale(0.0, 200.0), o);
  struct Box {
    Vec2 c;
    double angleDeg, w, h;
  };
  std::vector<Box> boxes;
  const std::string mark = "font-size=\"11\" font-weight=\"600\"";
  for (std::size_t at = svg.find(mark); at != std::string::npos; at = svg.find(mark, at + 1)) {
    const std::size_t open = svg.rfind("<text", at), close = svg.find("</text>", at);
    const std::string tag = svg.substr(open, close - open);
    if (tag.find("dominant-baseline=\"central\"") == std::string::npos) continue;  // the legend's unit
    double x = 0, y = 0, a = 0;
    // Along a line: rotated with it; beside a short one: upright (no transform, angle 0).
    ASSERT_GE(std::sscanf(tag.c_str(), "<text x=\"%lf\" y=\"%lf\" transform=\"rotate(%lf", &x, &y, &a), 2) << tag;
    const std::size_t digits = tag.size() - tag.rfind('>') - 1;
    boxes.push_back({Vec2(x, y), a, 0.556 * 11.0 * static_cast<double>(digits) + 6.0, 11.0 + 6.0});
  }
  ASSERT_GE(boxes.size(), 4u);
  auto corners = [](const Box& b) {
    const double r = degToRad(b.angleDeg);
    const Vec2 u(std::cos(r), std::sin(r)), v(-std::sin(r), std::cos(r));
    return std::vector<Vec2>{b.c + 0.5 * b.w * u + 0.5 * b.h * v, b.c - 0.5 * b.w * u + 0.5 * b.h * v,
                             b.c - 0.5 * b.w * u - 0.5 * b.h * v, b.c + 0.5 * b.w * u - 0.5 * b.h * v};
  };
  auto apart = [&](const Box& a, const Box& b) {
    const std::vector<Vec2> ca = corners(a), cb = corners(b);
    for (const std::vector<Vec2>* poly : {&ca, &cb})
      for (std::size_t i = 0; i < 4; ++i) {
        const Vec2 e = (*poly)[(i + 1) % 4] - (*poly)[i], n(-e.y, e.x);
        double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
        for (const Vec2& q : ca) loA = std::min(loA, glm::dot(n, q)), hiA = std::max(hiA, glm::dot(n, q));
        for (const Vec2& q : cb) loB = std::min(loB, glm::dot(n, q)), hiB = std::max(hiB, glm::dot(n, q));
        if (hiA <= loB || hiB <= loA) return true;
      }
    return false;
  };
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_TRUE(apart(boxes[i], boxes[j])) << "labels " << i << " and " << j << " overlap";
}

// Luminaires and observers on the plan: a symbol at each one inside the plan's extent (at the
// plan's own px of its position: 480 px across 4 m, the frame 44 px from the left, 30 px from
// the top), none outside it, and their names while there are few.
// A corridor 12 m × 0.8 m with the light changing along it: its isolines cross its width, too
// short to carry a label on them; each level's line gets its label upright beside it.
TEST(PlanSvg, ShortIsolinesAreLabelledBesideThem) {
  std::vector<double> values;
  GridReport g;
  g.name = "corridor";
  g.layout = lattice(30, 2, 0.4, values, [](Vec2 p) { return 280.0 + 30.0 * p.x; });  // 12 m × 0.8 m, x from −6 m
  g.values = values;
  g.stats = computeGridStats(g.values);
  PlanOptions o;
  o.cellValues = false;
  o.contourLevels = {150.0, 250.0, 350.0};  // x = −4.3, −1, 2.3 m: far apart along the corridor
  const std::string svg = planSvg(g, niceScale(100.0, 460.0), o);
  for (const char* level : {">150</text>", ">250</text>", ">350</text>"}) {
    const std::size_t at = svg.find(level);
    ASSERT_NE(at, std::string::npos) << level;
    const std::string tag = svg.substr(svg.rfind("<text", at), at - svg.rfind("<text", at));
    EXPECT_EQ(tag.find("rotate("), std::string::npos) << tag;  // upright
  }
}

TEST(PlanSvg, MarksLuminairesAndObserversInsideThePlan) {
  std::vector<double> values;
  GridReport g;
  g.layout = lattice(8, 4, 0.5, values, [](Vec2 p) { return 100.0 + p.x; });  // x −2…2, y −1…1
  g.values = values;
  g.stats = computeGridStats(values);
  PlanOptions o;
  o.cellValues = false;
  o.markers = {{PlanMarker::Kind::kLuminaire, Vec2(1.0, 0.5), Vec2(0.0), "L1"},
               {PlanMarker::Kind::kLuminaire, Vec2(9.0, 0.5), Vec2(0.0), "far"},
               {PlanMarker::Kind::kObserver, Vec2(-1.0, -0.5), Vec2(0.0, 1.0), "seat"}};
  const std::string svg = planSvg(g, niceScale(0.0, 200.0), o);
  const double k = 480.0 / 4.0;
  auto X = [&](double x) { return svgNumber(44.0 + (x + 2.0) * k); };
  auto Y = [&](double y) { return svgNumber(30.0 + (1.0 - y) * k); };
  EXPECT_NE(svg.find("<rect x=\"" + svgNumber(44.0 + 3.0 * k - 4) + "\" y=\"" + svgNumber(30.0 + 0.5 * k - 4) + "\""),
            std::string::npos);
  EXPECT_NE(svg.find("<circle cx=\"" + X(-1.0) + "\" cy=\"" + Y(-0.5) + "\""), std::string::npos);
  EXPECT_NE(svg.find(">L1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">seat</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">far</text>"), std::string::npos);  // outside the plan
  // Past kMaxNamedMarkers the symbols stay, the names go.
  o.markers.assign(kMaxNamedMarkers + 1, {PlanMarker::Kind::kLuminaire, Vec2(0.0), Vec2(0.0), "many"});
  const std::string crowded = planSvg(g, niceScale(0.0, 200.0), o);
  EXPECT_EQ(crowded.find(">many</text>"), std::string::npos);
  EXPECT_NE(crowded.find("<g class=\"markers\""), std::string::npos);
}

// RFC 4648 base64 decoding (the test's own), of the plan picture's data URI.
std::vector<uint8_t> unbase64(const std::string& text) {
  const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<uint8_t> out;
  uint32_t bits = 0;
  int have = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<uint32_t>(table.find(c));
    have += 6;
    if (have >= 8) {
      have -= 8;
      out.push_back(static_cast<uint8_t>((bits >> have) & 0xff));
    }
  }
  return out;
}

// A grid of more than kMaxSvgCells cells is one picture at twice the plan's px: no element a
// cell, and each pixel the false colour of the cell under its centre (cells 3.2 px wide here,
// larger than a pixel), found from the plan's own scale (480 px across its 6 m).
TEST(PlanSvg, LargeGridsAsOnePicture) {
  std::vector<double> values;
  GridReport g;
  g.name = "hall";
  g.layout = lattice(300, 100, 0.02, values, [](Vec2 p) { return 100.0 * (p.x + 3.0) + 10.0 * p.y; });
  ASSERT_GT(g.layout.cells.size(), kMaxSvgCells);
  g.values = values;
  g.stats = computeGridStats(g.values);
  const ColorScale scale = niceScale(0.0, g.stats.maximumLux);
  const std::string svg = planSvg(g, scale);
  std::size_t rects = 0;
  for (std::size_t p = svg.find("<rect"); p != std::string::npos; p = svg.find("<rect", p + 1)) ++rects;
  EXPECT_LT(rects, 20u);  // frame, background, legend, scale bar: no cells
  const std::string key = "href=\"data:image/png;base64,";
  const std::size_t at = svg.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::size_t from = at + key.size();
  const std::vector<uint8_t> png = unbase64(svg.substr(from, svg.find('"', from) - from));
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&img, png.data(), png.size()));
  img.format = PNG_FORMAT_RGB;
  std::vector<uint8_t> rgb(PNG_IMAGE_SIZE(img));
  ASSERT_TRUE(png_image_finish_read(&img, nullptr, rgb.data(), 0, nullptr));
  const double k = 2.0 * std::min(480.0 / 6.0, 380.0 / 2.0);  // picture px per m
  EXPECT_EQ(img.width, static_cast<png_uint_32>(std::ceil(6.0 * k)));
  EXPECT_EQ(img.height, static_cast<png_uint_32>(std::ceil(2.0 * k)));
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {5, 300}, {480, 160}, {957, 3}, {700, 319}}) {
    const Vec2 q(-3.0 + (x + 0.5) / k, 1.0 - (y + 0.5) / k);
    const int i = static_cast<int>(std::floor((q.x + 3.0) / 0.02)), j = static_cast<int>(std::floor((q.y + 1.0) / 0.02));
    const Rgb8 want = falseColor(values[static_cast<std::size_t>(j) * 300 + i], scale);
    const uint8_t* got = &rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
    EXPECT_EQ((Rgb8{got[0], got[1], got[2]}), want) << x << "," << y;
  }
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
