// A task area's verdict from its three grids' and its observers' (study/task_area_report.h).
#include "study/task_area_report.h"

#include "reports/html_report.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

// A case of one 500 lx task area (two corners at (1, 1) and (2, 2)) and two observers, one in
// its background and one 5 m away, and the grid and observer reports a run would make.
struct Fixture {
  CaseFile c;
  ReportData data;
  Fixture() {
    c = parseCaseFile("[[task_area]]\nname = \"desk\"\ncorners = [[1, 1], [2, 2]]\nheight = 0.8\n"
                      "maintained_illuminance = 500\nugr_limit = 19\n"
                      "[[observer]]\nname = \"near\"\nposition = [4.0, 1.5]\ndirection = [-1, 0]\n"
                      "[[observer]]\nname = \"far\"\nposition = [7.6, 1.5]\ndirection = [-1, 0]\n",
                      "case.toml");
    for (const GridSpec& g : c.grids) {
      GridReport r;
      r.name = g.name;
      r.check.overall = Verdict::kPass;
      data.grids.push_back(r);
    }
    for (const ObserverSpec& o : c.observers) {
      ObserverReport r;
      r.name = o.name;
      r.ugr = 25.0;  // only an observer in the areas counts
      data.observers.push_back(r);
    }
    data.observers[0].ugr = 17.5;
  }
};

TEST(TaskAreaReport, GridsObserversAndVerdicts) {
  Fixture f;
  addTaskAreaReports(f.c, f.data);
  ASSERT_EQ(f.data.taskAreas.size(), 1u);
  const TaskAreaReport& a = f.data.taskAreas[0];
  EXPECT_EQ(a.task, 0);
  EXPECT_EQ(a.surrounding, 1);
  EXPECT_EQ(a.background, 2);
  EXPECT_EQ(f.data.grids[1].area, "immediate surrounding");
  EXPECT_EQ(f.data.grids[2].taskArea, "desk");
  // "near" stands 2 m from the desk (within 0.5 + 3 m), "far" 5.6 m away.
  ASSERT_EQ(a.observers, std::vector<std::string>{"near"});
  EXPECT_EQ(a.ugr.value(), 17.5);
  EXPECT_EQ(a.ugrVerdict, Verdict::kPass);
  EXPECT_EQ(a.verdict, Verdict::kPass);
}

// The fourth grid (Ē_z, modelling) joins the task area's lines and verdict, and its table.
TEST(TaskAreaReport, CylindricalGridAndModellingCount) {
  Fixture f;
  f.c = parseCaseFile("[[task_area]]\nname = \"desk\"\ncorners = [[1, 1], [2, 2]]\nheight = 0.8\n"
                      "maintained_illuminance = 500\ncylindrical_illuminance = 150\nmodelling = true\n",
                      "case.toml");
  f.data.grids.clear();
  f.data.observers.clear();
  for (const GridSpec& g : f.c.grids) {
    GridReport r;
    r.name = g.name;
    r.check.overall = Verdict::kPass;
    f.data.grids.push_back(r);
  }
  f.data.grids[3].modelling.emplace();
  f.data.grids[3].modelling->ratio = 0.7;
  f.data.grids[3].modelling->verdict = Verdict::kFail;  // above 0.60: flat
  f.data.grids[3].targets.averageLux = 150.0;
  addTaskAreaReports(f.c, f.data);
  const TaskAreaReport& a = f.data.taskAreas[0];
  EXPECT_EQ(a.cylindrical, 3);
  EXPECT_EQ(f.data.grids[3].area, "cylindrical");
  EXPECT_EQ(a.verdict, Verdict::kFail);
  const std::string html = htmlReport(f.data);
  EXPECT_NE(html.find(">Cylindrical Ē<sub>z</sub></a>"), std::string::npos);
  EXPECT_NE(html.find("Ē<sub>h</sub> = 0.70 (required 0.30–0.60)"), std::string::npos);
}

TEST(TaskAreaReport, AnyFailingLineFailsTheTaskArea) {
  Fixture f;
  f.data.grids[2].check.overall = Verdict::kFail;  // the background too dark
  addTaskAreaReports(f.c, f.data);
  EXPECT_EQ(f.data.taskAreas[0].verdict, Verdict::kFail);
  Fixture g;
  g.data.observers[0].ugr = 21.0;  // above UGR_L 19
  addTaskAreaReports(g.c, g.data);
  EXPECT_EQ(g.data.taskAreas[0].ugrVerdict, Verdict::kFail);
  EXPECT_EQ(g.data.taskAreas[0].verdict, Verdict::kFail);
  // Without an observer in its areas the UGR line is not checked, and the grids decide.
  Fixture h;
  h.c.observers.resize(0);
  h.data.observers.clear();
  addTaskAreaReports(h.c, h.data);
  EXPECT_EQ(h.data.taskAreas[0].ugrVerdict, Verdict::kNotChecked);
  EXPECT_EQ(h.data.taskAreas[0].verdict, Verdict::kPass);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// The required Ra against the least Ra of the luminaires over the task area (else the case's):
// checked when every one's file states it.
TEST(TaskAreaReport, ColourRenderingFromTheLuminaireFiles) {
  auto run = [](std::vector<std::optional<double>> leastRa) {
    Fixture f;
    f.c.taskAreas[0].ra = 80.0;
    InstallationReport& in = f.data.installation.emplace();
    int k = 0;
    for (const std::optional<double>& ra : leastRa) {
      LuminaireTypeReport t;
      t.file = "lum" + std::to_string(k++) + (ra ? ".ldt" : ".ies");
      t.leastRa = ra;
      in.luminaires.push_back(t);
    }
    addTaskAreaReports(f.c, f.data);
    return f.data.taskAreas[0];
  };
  TaskAreaReport a = run({80.0, 90.0});
  EXPECT_EQ(a.leastRa, 80.0);
  EXPECT_EQ(a.raVerdict, Verdict::kPass);
  EXPECT_EQ(a.verdict, Verdict::kPass);
  a = run({90.0, 70.0});
  EXPECT_EQ(a.leastRa, 70.0);
  EXPECT_EQ(a.raVerdict, Verdict::kFail);
  EXPECT_EQ(a.verdict, Verdict::kFail);
  a = run({90.0, std::nullopt});
  EXPECT_FALSE(a.leastRa.has_value());
  EXPECT_EQ(a.raUnknown, std::vector<std::string>{"lum1.ies"});
  EXPECT_EQ(a.raVerdict, Verdict::kNotChecked);
  EXPECT_EQ(a.verdict, Verdict::kPass);  // the grids and UGR pass; Ra is left to the reader

  // Only the luminaires over the task area and its bands count: an IES downlight 6 m away does not.
  Fixture f;
  f.c.taskAreas[0].ra = 80.0;
  InstallationReport& in = f.data.installation.emplace();
  for (const char* name : {"panel", "downlight"}) {
    LuminaireTypeReport t;
    t.file = std::string(name) + (name[0] == 'p' ? ".ldt" : ".ies");
    t.entries = {name};
    if (name[0] == 'p') t.leastRa = 80.0;
    in.luminaires.push_back(t);
    f.c.luminaireEntries.push_back({name, t.file, {}});
    LuminairePlacement p;
    p.entry = static_cast<int>(f.c.luminaireEntries.size()) - 1;
    p.positionM = name[0] == 'p' ? Vec3(1.5, 1.5, 2.8) : Vec3(1.5, 9.0, 2.8);  // the desk spans y 1..2
    f.c.luminaires.push_back(p);
  }
  addTaskAreaReports(f.c, f.data);
  EXPECT_EQ(f.data.taskAreas[0].leastRa, 80.0);
  EXPECT_TRUE(f.data.taskAreas[0].raUnknown.empty());
  EXPECT_EQ(f.data.taskAreas[0].raVerdict, Verdict::kPass);
}

// A [[surface_grid]]'s grids (as withSurfaceGrids makes them) labelled in the report, its verdict
// failing with any wall, and the report's table of them.
TEST(SurfaceGridReport, GridsLabelledAndVerdict) {
  CaseFile c;
  SurfaceGridSpec s;
  s.name = "walls";
  s.roomType = RoomType::kOffice;
  c.surfaceGrids.push_back(s);
  ReportData data;
  for (const char* name : {"workplane", "walls: wall_north", "walls: wall_east"}) {
    GridSpec g;
    g.name = name;
    if (g.name != "workplane") {
      g.surfaceGrid = "walls";
      g.roomSurface = RoomSurface::kWall;
    }
    c.grids.push_back(g);
    GridReport r;
    r.name = name;
    r.values = {80.0, 120.0};
    r.stats = computeGridStats(r.values);
    r.targets = {75.0, 0.10};
    r.check = checkTargets(r.stats, r.targets);
    data.grids.push_back(r);
  }
  addSurfaceGridReports(c, data);
  ASSERT_EQ(data.surfaceGrids.size(), 1u);
  const SurfaceGridReport& r = data.surfaceGrids[0];
  EXPECT_EQ(r.grids, (std::vector<int>{1, 2}));
  EXPECT_EQ(r.roomType, "office");
  EXPECT_EQ(r.verdict, Verdict::kPass);
  EXPECT_EQ(data.grids[2].roomSurface, "wall");
  EXPECT_TRUE(data.grids[0].surfaceGrid.empty());
  const std::string html = htmlReport(data);
  EXPECT_NE(html.find("Walls and ceiling (EN 12464-1:2021)"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#grid-3\">wall_east (wall)</a>"), std::string::npos);
  EXPECT_NE(html.find("False-colour elevation, seen from the room, of walls: wall_east"), std::string::npos);
  EXPECT_NE(html.find("False-colour view of workplane"), std::string::npos);  // planIsXY unset here

  // A wall below 75 lx fails the entry.
  data.surfaceGrids.clear();
  data.grids[1].values = {40.0, 60.0};
  data.grids[1].stats = computeGridStats(data.grids[1].values);
  data.grids[1].check = checkTargets(data.grids[1].stats, data.grids[1].targets);
  addSurfaceGridReports(c, data);
  EXPECT_EQ(data.surfaceGrids[0].verdict, Verdict::kFail);
}

}  // namespace
}  // namespace candela
