#include "reports/plan_section_svg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "reports/html_report.h"
#include "reports/plan_svg.h"
#include "sample_report.h"

namespace candela {
namespace {

// The `d` attribute of the first <path class="cls">, or "" without one.
std::string pathData(const std::string& svg, const std::string& cls) {
  const std::size_t at = svg.find("<path class=\"" + cls + "\" d=\"");
  if (at == std::string::npos) return "";
  const std::size_t from = at + cls.size() + 18, to = svg.find('"', from);
  return svg.substr(from, to - from);
}

std::size_t count(const std::string& text, char c) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), c)); }

// A 4 m × 2 m grid (x −2…2, y −1…1; 480 px across: 120 px a metre, the frame 44 px from the
// left and 30 px from the top) in a room of four walls along its edges with a window in the south
// wall, another above the cut in the north wall, and two desks.
struct Fixture {
  GridReport grid;
  PlanSection section;
  Fixture() {
    grid = testing_sample::sampleGrid("room", -2.0, -1.0, 2.0, 1.0, 0.25);
    section.cutHeightM = 0.8;
    section.walls = {{{-2, -1}, {-0.5, -1}}, {{0.5, -1}, {2, -1}}, {{2, -1}, {2, 1}}, {{2, 1}, {-2, 1}}, {{-2, 1}, {-2, -1}}};
    section.openings = {{{-0.5, -1}, {0.5, -1}}};
    section.openingsAbove = {{{-1, 1}, {1, 1}}};
    section.furniture = {{{{-1.5, 0}, {-0.7, 0}, {-0.7, 0.4}, {-1.5, 0.4}}, true},
                         {{{0.7, 0}, {1.5, 0}, {1.5, 0.4}, {0.7, 0.4}}, true}};
  }
};

// Each wall is one subpath of the walls' path, from its first point (the south wall's west piece
// starts at the frame's bottom-left corner, 44 + 0, 30 + 240 px); each window cut gives two lines
// (its faces) over a band, each window above the cut two dashed ones; each desk one closed
// outline; the key names them.
TEST(PlanSectionSvg, DrawsWallsOpeningsAndFurniture) {
  const Fixture f;
  PlanOptions o;
  o.section = &f.section;
  o.cellValues = false;
  const std::string svg = planSvg(f.grid, niceScale(0.0, 600.0), o);
  const std::string walls = pathData(svg, "walls");
  EXPECT_EQ(count(walls, 'M'), f.section.walls.size());
  EXPECT_EQ(walls.rfind("M44 270L224 270", 0), 0u) << walls;
  EXPECT_EQ(count(pathData(svg, "openings"), 'M'), 2u);
  EXPECT_EQ(count(pathData(svg, "opening-band"), 'M'), 1u);
  EXPECT_EQ(count(pathData(svg, "openings-above"), 'M'), 2u);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  const std::size_t furniture = svg.find("<g class=\"furniture\"");
  ASSERT_NE(furniture, std::string::npos);
  const std::size_t outlinePath = svg.find("<path d=\"", furniture);
  const std::string outlines = svg.substr(outlinePath, svg.find("\"/>", outlinePath) - outlinePath);
  EXPECT_EQ(count(outlines, 'Z'), 2u);
  for (const char* label : {">wall, partition (cut)<", ">window<", ">window above the cut<", ">furniture<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_NE(svg.find("<clipPath id=\"plan-geo\">"), std::string::npos);
}

// Furniture over the cells and under the area's outline; walls over the outline, under the
// isolines and the markers; the legend and the scale bar stay.
TEST(PlanSectionSvg, LayersInOrder) {
  const Fixture f;
  PlanOptions o;
  o.section = &f.section;
  o.markers = {{PlanMarker::Kind::kLuminaire, Vec2(0.0), Vec2(0.0), "L1"}};
  const std::string svg = planSvg(f.grid, niceScale(0.0, 600.0), o);
  const std::size_t cells = svg.find("<g shape-rendering=\"crispEdges\">"), furniture = svg.find("class=\"furniture\""),
                    outline = svg.find("<polygon points="), walls = svg.find("class=\"walls\""),
                    contours = svg.find("<polyline"), markers = svg.find("class=\"markers\"");
  for (std::size_t at : {cells, furniture, outline, walls, contours, markers}) ASSERT_NE(at, std::string::npos);
  EXPECT_LT(cells, furniture);
  EXPECT_LT(furniture, outline);
  EXPECT_LT(outline, walls);
  EXPECT_LT(walls, contours);
  EXPECT_LT(contours, markers);
  EXPECT_NE(svg.find(">luminaire<"), std::string::npos);  // in the key with the section's items
  EXPECT_NE(svg.find("-scale)\""), std::string::npos);    // legend
  EXPECT_NE(svg.find(" m</text>"), std::string::npos);    // scale bar
}

// Without a section: no section, no key, as before. A section lying outside the plan draws
// nothing the key would name.
TEST(PlanSectionSvg, KeyListsOnlyWhatThePlanShows) {
  Fixture f;
  PlanOptions o;
  const std::string none = planSvg(f.grid, niceScale(0.0, 600.0), o);
  EXPECT_EQ(none.find("class=\"walls\""), std::string::npos);
  EXPECT_EQ(none.find("class=\"key\""), std::string::npos);
  PlanSection far;
  far.walls = {{{10, 10}, {12, 10}}};
  far.furniture = {{{{10, 10}, {11, 10}, {11, 11}}, true}};
  o.section = &far;
  const std::string svg = planSvg(f.grid, niceScale(0.0, 600.0), o);
  EXPECT_EQ(svg.find(">wall, partition (cut)<"), std::string::npos);
  EXPECT_EQ(svg.find(">furniture<"), std::string::npos);
  const PlanKeyItems shown = sectionItemsIn(f.section, Vec2(-2, -1), Vec2(2, 1));
  EXPECT_TRUE(shown.walls && shown.openings && shown.openingsAbove && shown.furniture);
  EXPECT_FALSE(sectionItemsIn(f.section, Vec2(5), Vec2(6)).any());
}

// The key wraps onto a second row when its items do not fit the width, and the plan grows by it.
TEST(PlanSectionSvg, KeyWraps) {
  PlanKeyItems all;
  all.walls = all.openings = all.openingsAbove = all.furniture = all.luminaires = all.observers = true;
  EXPECT_DOUBLE_EQ(planKeyHeight(all, 2000.0), 16.0);
  EXPECT_GT(planKeyHeight(all, 200.0), 16.0);
  EXPECT_DOUBLE_EQ(planKeyHeight(PlanKeyItems{}, 200.0), 0.0);
}

// The caption: the cut height and, for a floor-level grid, why it is 1 m above the floor; what
// was left out.
TEST(PlanSectionSvg, Caption) {
  PlanSection s;
  s.cutHeightM = 0.8;
  PlanKeyItems shown;
  EXPECT_EQ(planSectionCaption(s, shown), "Walls, windows and furniture cut at 0.80 m (the grid's height).");
  s.cutHeightM = 1.0;
  s.raisedAboveFloor = true;
  s.droppedSegments = 12;
  s.skippedCurved = 2;
  shown.openingsAbove = true;
  const std::string c = planSectionCaption(s, shown);
  EXPECT_NE(c.find("1.00 m above the floor at 0.00 m (the grid lies at floor level"), std::string::npos) << c;
  EXPECT_NE(c.find("Dashed: windows above the cut."), std::string::npos) << c;
  EXPECT_NE(c.find("12 cut lines"), std::string::npos) << c;
  EXPECT_NE(c.find("2 spheres, cones or rings"), std::string::npos) << c;
}

// The HTML report draws a grid's section on its plan and says where it is cut in the caption;
// a grid without a section index gets neither.
TEST(PlanSectionSvg, HtmlReportDrawsTheGridsSection) {
  ReportData data = testing_sample::sampleReport();
  ASSERT_GE(data.grids.size(), 2u);
  Fixture f;
  data.planSections = {f.section};
  data.grids[0].planIsXY = true;
  data.grids[0].planSection = 0;
  data.grids[1].planSection = -1;
  const std::string html = htmlReport(data);
  std::size_t walls = 0;
  for (std::size_t at = html.find("class=\"walls\""); at != std::string::npos; at = html.find("class=\"walls\"", at + 1))
    ++walls;
  EXPECT_EQ(walls, 1u);
  EXPECT_NE(html.find("Walls, windows and furniture cut at 0.80 m (the grid&#39;s height)."), std::string::npos);
}

}  // namespace
}  // namespace candela
