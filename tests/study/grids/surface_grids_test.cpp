// [[surface_grid]] (study/grids/surface_grids.cpp): identifiers matched by glob, one grid per plane,
// sensors facing the room whichever way the surface is wound, covered parts left out, the room
// type's targets; and a black room's walls against the direct light's closed form I·cos θ / d².
#include "study/grids/surface_grids.h"

#include "engine/radiance/reader.h"
#include "study/case/case_scene.h"
#include "study/grids/prepared_grid.h"
#include "study/run_case.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(CANDELA_TEST_DATA) / "study";

TEST(GlobMatch, StarsQuestionMarksAndLiterals) {
  EXPECT_TRUE(globMatch("wall_*", "wall_north"));
  EXPECT_TRUE(globMatch("wall_*", "wall_"));
  EXPECT_FALSE(globMatch("wall_*", "wallnorth"));
  EXPECT_FALSE(globMatch("wall_*", "my_wall_north"));
  EXPECT_TRUE(globMatch("*", ""));
  EXPECT_TRUE(globMatch("w?ll", "wall"));
  EXPECT_FALSE(globMatch("w?ll", "wll"));
  EXPECT_TRUE(globMatch("*ab", "aab"));  // the star has to give back what it took
  EXPECT_TRUE(globMatch("a*b*c", "aXbYbc"));
  EXPECT_FALSE(globMatch("a*b*c", "abcb"));
  EXPECT_FALSE(globMatch("Wall", "wall"));  // Radiance identifiers are case-sensitive
  EXPECT_TRUE(globMatch("ceiling", "ceiling"));
}

TEST(SideFacing, TowardsTheInsideOrNone) {
  const Vec3 n(1, 0, 0);
  EXPECT_EQ(*sideFacing(n, Vec3(0, 5, 5), Vec3(2, 0, 0)), n);
  EXPECT_EQ(*sideFacing(n, Vec3(0, 5, 5), Vec3(-2, 0, 0)), -n);
  EXPECT_FALSE(sideFacing(n, Vec3(0, 5, 5), Vec3(0.005, 1, 1)).has_value());
}

std::unique_ptr<Scene> room() {
  auto scene = std::make_unique<Scene>();
  readRadianceFile(kData / "surface_room.rad", *scene);
  return scene;
}

SurfaceGridSpec spec(std::vector<std::string> patterns) {
  SurfaceGridSpec s;
  s.name = "walls";
  s.patterns = std::move(patterns);
  s.spacingM = 0.5;
  s.loc = FileLoc{"case.toml", 7, 1};
  s.patternsLoc = FileLoc{"case.toml", 9, 12};
  return s;
}

const GridSpec& named(const std::vector<GridSpec>& grids, const std::string& name) {
  for (const GridSpec& g : grids)
    if (g.name == name) return g;
  ADD_FAILURE() << "no grid " << name;
  return grids.front();
}

TEST(SurfaceGrids, OneGridPerWallPlaneFacingTheRoom) {
  const std::unique_ptr<Scene> scene = room();
  SurfaceGridSpec s = spec({"wall_*"});
  s.roomType = RoomType::kOffice;
  const std::vector<GridSpec> grids = surfaceGridSpecs(s, *scene);
  // North, west, east and the south wall's four pieces as one plane, in scene order.
  ASSERT_EQ(grids.size(), 4u);
  EXPECT_EQ(grids[0].name, "walls: wall_north");
  EXPECT_EQ(grids[1].name, "walls: wall_west");
  EXPECT_EQ(grids[2].name, "walls: wall_east");
  EXPECT_EQ(grids[3].name, "walls: wall_south");
  EXPECT_EQ(grids[3].onSurfaces.size(), 4u);
  const std::map<std::string, Vec3> inward = {{"walls: wall_north", {0, -1, 0}},
                                              {"walls: wall_west", {1, 0, 0}},
                                              {"walls: wall_east", {-1, 0, 0}},
                                              {"walls: wall_south", {0, 1, 0}}};
  for (const GridSpec& g : grids) {
    EXPECT_EQ(g.roomSurface, RoomSurface::kWall) << g.name;
    EXPECT_EQ(g.surfaceGrid, "walls");
    EXPECT_NEAR(glm::length(*g.plane.normal - inward.at(g.name)), 0.0, 1e-12) << g.name;
    // EN 12464-1:2021 for offices: walls Ē_m ≥ 75 lx, U0 ≥ 0.10.
    EXPECT_EQ(g.targetAverageLux, 75.0);
    EXPECT_EQ(g.targetUniformity, 0.10);
    // Every sensor 1 mm off its wall, into the room.
    for (const SensorPoint& p : makePlaneGrid(g.plane).points) {
      EXPECT_GT(p.position.x, 0.0);
      EXPECT_LT(p.position.x, 4.0);
      EXPECT_GT(p.position.y, 0.0);
      EXPECT_LT(p.position.y, 3.0);
      EXPECT_EQ(p.normal, *g.plane.normal);
    }
  }
}

TEST(SurfaceGrids, PointsCountTheWallsAreaLessWindowAndCabinet) {
  const std::unique_ptr<Scene> scene = room();
  const std::vector<GridSpec> grids = surfaceGridSpecs(spec({"wall_*"}), *scene);
  // 0.5 m spacing: the north wall 4 m × 2.8 m is ceil(4/0.5) × ceil(2.8/0.5) = 8 × 6 cells.
  EXPECT_EQ(makePlaneGrid(named(grids, "walls: wall_north").plane).size(), 48u);
  // The south wall's cells are 0.5 × 0.4667 m: centres at u = 0.25 + 0.5 i, v = 0.2333 + 0.4667 j.
  // The window (x 1..2, z 1..2) holds those with u in 2..3 from the wall's left end (x = 4 − u)
  // and v in 1..2: u = 2.25, 2.75; v = 1.1667, 1.6333: 4 cells.
  EXPECT_EQ(makePlaneGrid(named(grids, "walls: wall_south").plane).size(), 48u - 4u);
  // The west wall 3 m × 2.8 m: 6 × 6 cells, none covered.
  EXPECT_EQ(makePlaneGrid(named(grids, "walls: wall_west").plane).size(), 36u);
  // The east wall: the cabinet's back (y 2..2.5, z 0..0.5) covers the cell of centre
  // (y 2.25, z 0.2333): one left out.
  const GridSpec& east = named(grids, "walls: wall_east");
  EXPECT_EQ(east.plane.holes.size(), 1u);
  const SensorGrid g = makePlaneGrid(east.plane);
  EXPECT_EQ(g.size(), 35u);
  for (const SensorPoint& p : g.points)
    EXPECT_FALSE(p.position.y > 2.0 && p.position.y < 2.5 && p.position.z < 0.5) << p.position.y;
}

TEST(SurfaceGrids, CeilingFacesDownInPlanCoordinatesWithItsTargets) {
  const std::unique_ptr<Scene> scene = room();
  SurfaceGridSpec s = spec({"ceiling"});
  s.name = "ceiling";
  s.roomType = RoomType::kGeneral;
  const std::vector<GridSpec> grids = surfaceGridSpecs(s, *scene);
  ASSERT_EQ(grids.size(), 1u);
  const GridSpec& c = grids[0];
  EXPECT_EQ(c.name, "ceiling: ceiling");
  EXPECT_EQ(c.roomSurface, RoomSurface::kCeiling);
  EXPECT_TRUE(inPlanCoordinates(c.plane));  // drawn as a plan, luminaires marked on it
  EXPECT_EQ(*c.plane.normal, Vec3(0, 0, -1));
  EXPECT_NEAR(c.plane.origin.z, 2.8 - 0.001, 1e-12);
  EXPECT_EQ(c.targetAverageLux, 30.0);  // any work place: ceiling Ē_m ≥ 30 lx
  EXPECT_EQ(c.targetUniformity, 0.10);
  EXPECT_EQ(makePlaneGrid(c.plane).size(), 8u * 6u);
  // The case's own targets win over the room type's.
  s.targetAverageLux = 120.0;
  EXPECT_EQ(surfaceGridSpecs(s, *scene)[0].targetAverageLux, 120.0);
  EXPECT_EQ(surfaceGridSpecs(s, *scene)[0].targetUniformity, 0.10);
  // The floor: no requirement.
  s = spec({"floor"});
  s.roomType = RoomType::kOffice;
  const GridSpec f = surfaceGridSpecs(s, *scene)[0];
  EXPECT_EQ(f.roomSurface, RoomSurface::kFloor);
  EXPECT_FALSE(f.targetAverageLux.has_value());
}

TEST(SurfaceGrids, ExplicitSidesOverrideTheRoom) {
  const std::unique_ptr<Scene> scene = room();
  SurfaceGridSpec s = spec({"wall_west"});
  // wall_west is wound with its front normal to −x, out of the room.
  s.side = SurfaceGridSpec::Side::kFront;
  EXPECT_EQ(*surfaceGridSpecs(s, *scene)[0].plane.normal, Vec3(-1, 0, 0));
  s.side = SurfaceGridSpec::Side::kBack;
  EXPECT_EQ(*surfaceGridSpecs(s, *scene)[0].plane.normal, Vec3(1, 0, 0));
  // Auto with one wall alone: its box lies in its plane, the scene's centre decides.
  s.side = SurfaceGridSpec::Side::kAuto;
  EXPECT_EQ(*surfaceGridSpecs(s, *scene)[0].plane.normal, Vec3(1, 0, 0));
}

TEST(SurfaceGrids, BadPatternsAndSurfacesAreErrorsAtTheEntry) {
  const std::unique_ptr<Scene> scene = room();
  try {
    surfaceGridSpecs(spec({"wall_*", "walls_typo*"}), *scene);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "case.toml:9: no surface of the scene is named 'walls_typo*'");
  }
  Scene round;
  readRadianceText("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere wall_lamp 0 0 4 1 1 1 0.2\n", "lamp.rad", round);
  try {
    surfaceGridSpecs(spec({"wall_*"}), round);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("surface 'wall_lamp' is a sphere"), std::string::npos) << e.what();
  }
  // An L of 0.1 m wide arms at 2 m spacing: the one cell's centre (0.5, 0.5) lies outside it.
  Scene thin;
  readRadianceText("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon wall_l 0 0 18 0 0 0 1 0 0 1 0.1 0 "
                   "0.1 0.1 0 0.1 1 0 0 1 0\n",
                   "thin.rad", thin);
  SurfaceGridSpec wide = spec({"wall_l"});
  wide.spacingM = 2.0;
  EXPECT_THROW(surfaceGridSpecs(wide, thin), InputError);
  wide.spacingM = 0.05;
  EXPECT_EQ(makePlaneGrid(surfaceGridSpecs(wide, thin)[0].plane).size(), 2u * 20u * 2u - 4u);
}

TEST(SurfaceGrids, CaseGridsAreAppendedWithUniqueNames) {
  const fs::path casePath = kData / "surface_grids.toml";
  const CaseFile c = readCaseFile(casePath);
  ASSERT_EQ(c.surfaceGrids.size(), 1u);
  EXPECT_TRUE(c.grids.empty());
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  const CaseFile with = withSurfaceGrids(c, *scene);
  ASSERT_EQ(with.grids.size(), 4u);
  CaseFile clash = c;
  clash.grids.push_back(with.grids[1]);
  EXPECT_THROW(withSurfaceGrids(clash, *scene), InputError);
}

// The segment p → q meets the axis-aligned box [lo, hi] (slab test), for the cabinet's shadow.
bool segmentHitsBox(const Vec3& p, const Vec3& q, const Vec3& lo, const Vec3& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double d = q[a] - p[a];
    if (std::abs(d) < 1e-15) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - p[a]) / d, tb = (hi[a] - p[a]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(SurfaceGridsStudy, BlackRoomWallsReadTheDirectClosedForm) {
  const fs::path casePath = kData / "surface_grids.toml";
  const CaseFile asRead = readCaseFile(casePath);
  const std::unique_ptr<Scene> scene = loadCaseScene(asRead);
  const CaseFile c = withSurfaceGrids(asRead, *scene);
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  ASSERT_EQ(scene->luminaires.size(), 1u);
  const LuminaireSource& lum = scene->luminaires[0];
  RunRequest request;
  request.outDir = fs::path(testing::TempDir()) / "study_surface_grids";
  fs::remove_all(request.outDir);
  const RunResult r = runCase(casePath, request);
  ASSERT_EQ(r.data.grids.size(), 4u);
  int lit = 0;
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const GridReport& g = r.data.grids[gi];
    ASSERT_EQ(g.values.size(), grids[gi].grid.size()) << g.name;
    EXPECT_EQ(g.roomSurface, "wall");
    EXPECT_EQ(g.surfaceGrid, "walls");
    for (std::size_t k = 0; k < g.values.size(); ++k) {
      const SensorPoint& s = grids[gi].grid.points[k];
      const Vec3 e = lum.position - s.position;
      const double d = glm::length(e);
      double want = lum.intensityCd(-e / d) * std::max(0.0, glm::dot(s.normal, e / d)) / (d * d);
      if (segmentHitsBox(s.position, lum.position, Vec3(3.9, 2.0, 0.0), Vec3(4.0, 2.5, 0.5))) want = 0.0;
      lit += want > 0.0;
      // Nothing reflects and the source is a point: one shadow ray, no noise.
      EXPECT_NEAR(g.values[k], want, 1e-9 * want + 1e-9) << g.name << " point " << k;
    }
  }
  EXPECT_GT(lit, 100);  // the luminaire at 2.5 m lights every wall below it
  // The summary: each wall's grid with its surface, and the entry's verdict (Ē ≥ 75 lx, U0 ≥ 0.10
  // over each wall, the walls above the luminaire dark: U0 = 0, so it fails).
  std::ifstream in(request.outDir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["surface_grids"].size(), 1u);
  EXPECT_EQ(j["surface_grids"][0]["name"], "walls");
  EXPECT_EQ(j["surface_grids"][0]["room_type"], "office");
  EXPECT_EQ(j["surface_grids"][0]["grids"].size(), 4u);
  bool anyFail = false;
  for (const GridReport& g : r.data.grids) anyFail |= g.check.overall == Verdict::kFail;
  EXPECT_EQ(j["surface_grids"][0]["verdict"], anyFail ? "fail" : "pass");
  for (const auto& g : j["grids"]) {
    EXPECT_EQ(g["surface_grid"], "walls");
    EXPECT_EQ(g["room_surface"], "wall");
  }
}

}  // namespace
}  // namespace candela
