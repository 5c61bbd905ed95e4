#include "study/grids/plan_section.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reports/plan_svg.h"

namespace candela {
namespace {

// A box room 4 m (x) × 3 m (y) × 2.8 m; its south wall (y = 0) one polygon with a window hole
// 1.5 m wide (x 1–2.5, sill 0.6 m, head 2.1 m) joined to its outline by a seam, as Radiance
// models a wall with an opening; the window's glass in the hole; a desk top 1.6 m × 0.8 m at
// 0.72 m on two end panels (0–0.69 m), and the floor and ceiling.
struct BoxRoom {
  Scene scene;
  uint32_t paint = 0, glass = 0;
  static constexpr double kWindowWidth = 1.5;
  static constexpr double kDeskArea = 1.6 * 0.8;
  static constexpr double kPerimeter = 2 * (4.0 + 3.0);

  BoxRoom() {
    Material p;
    p.type = MaterialType::kPlastic;
    p.name = "paint";
    paint = scene.addMaterial(p);
    Material g;
    g.type = MaterialType::kGlass;
    g.name = "glass";
    glass = scene.addMaterial(g);
    const double h = 2.8;
    scene.addPolygon({{0, 0, 0}, {0, 3, 0}, {4, 3, 0}, {4, 0, 0}}, paint, "floor");  // faces down, as office.rad's
    scene.addPolygon({{0, 0, h}, {4, 0, h}, {4, 3, h}, {0, 3, h}}, paint, "ceiling");
    scene.addPolygon({{0, 0, 0}, {4, 0, 0}, {4, 0, h}, {0, 0, h}, {0, 0, 0}, {1, 0, 0.6}, {1, 0, 2.1}, {2.5, 0, 2.1},
                      {2.5, 0, 0.6}, {1, 0, 0.6}},
                     paint, "wall_south");
    scene.addPolygon({{1, 0, 0.6}, {2.5, 0, 0.6}, {2.5, 0, 2.1}, {1, 0, 2.1}}, glass, "window");
    scene.addPolygon({{0, 3, 0}, {0, 3, h}, {4, 3, h}, {4, 3, 0}}, paint, "wall_north");
    scene.addPolygon({{0, 0, 0}, {0, 0, h}, {0, 3, h}, {0, 3, 0}}, paint, "wall_west");
    scene.addPolygon({{4, 0, 0}, {4, 3, 0}, {4, 3, h}, {4, 0, h}}, paint, "wall_east");
    scene.addPolygon({{1.5, 1.0, 0.72}, {3.1, 1.0, 0.72}, {3.1, 1.8, 0.72}, {1.5, 1.8, 0.72}}, paint, "desk_top");
    scene.addPolygon({{1.55, 1.05, 0}, {1.55, 1.75, 0}, {1.55, 1.75, 0.69}, {1.55, 1.05, 0.69}}, paint, "desk_end1");
    scene.addPolygon({{3.05, 1.05, 0}, {3.05, 1.75, 0}, {3.05, 1.75, 0.69}, {3.05, 1.05, 0.69}}, paint, "desk_end2");
  }
};

double totalLength(const std::vector<PlanSegment>& segments) {
  double sum = 0.0;
  for (const PlanSegment& s : segments) sum += glm::length(s.b - s.a);
  return sum;
}

double area(const std::vector<Vec2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
  return 0.5 * std::abs(a);
}

// The cut at 0.8 m: the four walls' segments sum to the perimeter less the window's width (the
// south wall's seam polygon gives its two piers either side of the hole), the window gives one
// segment of its width on the line y = 0 between x = 1 and 2.5, and the desk top its footprint.
// The desk's end panels stop at 0.69 m, below the cut: nothing of them.
TEST(PlanSection, BoxRoomCutAtWorkPlane) {
  const BoxRoom room;
  SectionRequest r;
  r.cutHeightM = 0.8;
  const PlanSection s = planSection(room.scene, r);
  EXPECT_NEAR(totalLength(s.walls), BoxRoom::kPerimeter - BoxRoom::kWindowWidth, 1e-9);
  EXPECT_EQ(s.walls.size(), 5u);  // two south piers, north, west, east
  ASSERT_EQ(s.openings.size(), 1u);
  EXPECT_NEAR(glm::length(s.openings[0].b - s.openings[0].a), BoxRoom::kWindowWidth, 1e-9);
  EXPECT_NEAR(std::min(s.openings[0].a.x, s.openings[0].b.x), 1.0, 1e-9);
  EXPECT_NEAR(s.openings[0].a.y, 0.0, 1e-12);
  EXPECT_TRUE(s.openingsAbove.empty());
  ASSERT_EQ(s.furniture.size(), 1u);
  EXPECT_NEAR(area(s.furniture[0].outline), BoxRoom::kDeskArea, 1e-9);
  EXPECT_TRUE(s.furniture[0].outlined);
  EXPECT_EQ(s.droppedSegments + s.droppedFootprints + s.skippedCurved, 0u);
}

// The floor is found whichever way it faces (the box room's faces down), and a grid on it, or
// less than 0.3 m above it, is cut 1 m above the floor: there the window (0.6–2.1 m) is cut,
// and the desk (0.72 m) lies below the cut.
TEST(PlanSection, FloorLevelGridIsCutOneMetreAboveTheFloor) {
  const BoxRoom room;
  const Vec2 lo(0.0), hi(4.0, 3.0);
  EXPECT_NEAR(floorLevel(room.scene, 0.0, lo, hi), 0.0, 1e-12);
  EXPECT_NEAR(floorLevel(room.scene, 0.8, lo, hi), 0.0, 1e-12);  // the desk covers a tenth of the room
  EXPECT_DOUBLE_EQ(planCutHeight(0.0, 0.0), kFloorPlanCutM);
  EXPECT_DOUBLE_EQ(planCutHeight(0.29, 0.0), kFloorPlanCutM);
  EXPECT_DOUBLE_EQ(planCutHeight(0.8, 0.0), 0.8);
  EXPECT_DOUBLE_EQ(planCutHeight(3.1, 3.0), 4.0);  // an upper storey's floor grid
  SectionRequest r;
  r.cutHeightM = planCutHeight(0.0, floorLevel(room.scene, 0.0, lo, hi));
  const PlanSection s = planSection(room.scene, r);
  EXPECT_NEAR(totalLength(s.walls), BoxRoom::kPerimeter - BoxRoom::kWindowWidth, 1e-9);
  EXPECT_NEAR(totalLength(s.openings), BoxRoom::kWindowWidth, 1e-9);
  ASSERT_EQ(s.furniture.size(), 1u);
}

// A grid over the desk alone sees the floor around it once its region is grown by 1 m (as
// addPlanSections does); over the desk's own outline the desk is as large as the floor there,
// and the higher of the two would be taken.
TEST(PlanSection, FloorUnderAGridOnADesk) {
  const BoxRoom room;
  const Vec2 lo(1.5, 1.0), hi(3.1, 1.8);
  EXPECT_NEAR(floorLevel(room.scene, 0.75, lo - Vec2(1.0), hi + Vec2(1.0)), 0.0, 1e-12);
  EXPECT_NEAR(floorLevel(room.scene, 0.75, lo, hi), 0.72, 1e-12);
}

// Of two storeys' slabs (each spanning the room), the upper one is an upper grid's floor; a
// scene without horizontal surfaces falls back to its lowest z.
TEST(PlanSection, UpperStoreyFloorAndFallback) {
  BoxRoom room;
  room.scene.addPolygon({{0, 0, 3.0}, {4, 0, 3.0}, {4, 3, 3.0}, {0, 3, 3.0}}, room.paint, "slab");
  EXPECT_NEAR(floorLevel(room.scene, 3.8, Vec2(-1.0), Vec2(5.0, 4.0)), 3.0, 1e-12);
  Scene walls;
  Material p;
  p.type = MaterialType::kPlastic;
  const uint32_t m = walls.addMaterial(p);
  walls.addPolygon({{0, 0, -0.5}, {4, 0, -0.5}, {4, 0, 2}, {0, 0, 2}}, m);
  EXPECT_NEAR(floorLevel(walls, 0.8, Vec2(0.0), Vec2(4.0, 3.0)), -0.5, 1e-12);
}

// A work plane below the window's sill: the window is drawn as a window above the cut (its plan
// projection, its width), not cut; a clerestory 2 m or more above the cut is another storey's.
TEST(PlanSection, WindowsAboveTheCut) {
  BoxRoom room;
  room.scene.addPolygon({{0, 3, 2.6}, {0, 3, 2.75}, {2, 3, 2.75}, {2, 3, 2.6}}, room.glass, "clerestory");
  SectionRequest r;
  r.cutHeightM = 0.5;
  const PlanSection s = planSection(room.scene, r);
  EXPECT_TRUE(s.openings.empty());
  ASSERT_EQ(s.openingsAbove.size(), 1u);
  EXPECT_NEAR(glm::length(s.openingsAbove[0].b - s.openingsAbove[0].a), BoxRoom::kWindowWidth, 1e-9);
  // Below the hole the south wall is whole (its seam's two crossings meet); the desk's end panels
  // (0.7 m each, up to 0.69 m) are cut too, and its top is above the cut.
  EXPECT_NEAR(totalLength(s.walls), BoxRoom::kPerimeter + 2 * 0.7, 1e-9);
  EXPECT_EQ(s.walls.size(), 6u);
  EXPECT_TRUE(s.furniture.empty());
}

// A surface whose top edge lies in the cut plane (a 1.2 m screen cut at 1.2 m) gives that edge;
// a horizontal surface in the plane is furniture, not cut; one whose bottom edge lies in it
// gives nothing.
TEST(PlanSection, EdgesInTheCutPlane) {
  BoxRoom room;
  room.scene.addPolygon({{1, 2, 0}, {3, 2, 0}, {3, 2, 1.2}, {1, 2, 1.2}}, room.paint, "screen");
  room.scene.addPolygon({{3, 2.5, 1.2}, {3.5, 2.5, 1.2}, {3.5, 2.9, 1.2}, {3, 2.9, 1.2}}, room.paint, "shelf");
  room.scene.addPolygon({{0.5, 2.5, 1.2}, {0.5, 2.5, 2.0}, {0.5, 2.9, 2.0}, {0.5, 2.9, 1.2}}, room.paint, "above");
  SectionRequest r;
  r.cutHeightM = 1.2;
  const PlanSection s = planSection(room.scene, r);
  EXPECT_NEAR(totalLength(s.walls), BoxRoom::kPerimeter - BoxRoom::kWindowWidth + 2.0, 1e-9);
  ASSERT_EQ(s.furniture.size(), 2u);  // desk and shelf
  EXPECT_NEAR(area(s.furniture[0].outline) + area(s.furniture[1].outline), BoxRoom::kDeskArea + 0.5 * 0.4, 1e-9);
}

// A wall as a mesh of 6 × 4 quads (48 triangles) on x = 4: each triangle it cuts gives a piece,
// merged into one segment the wall's length; a box-shaped desk top (top and bottom faces as
// mesh triangles) gives its triangles' footprints once, without outline.
TEST(PlanSection, MeshWallMergesIntoOneSegment) {
  Scene scene;
  Material p;
  p.type = MaterialType::kPlastic;
  const uint32_t m = scene.addMaterial(p);
  TriangleMesh& mesh = scene.mesh;
  const int nu = 6, nv = 4;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) mesh.vertices.emplace_back(4.0, 3.0 * i / nu, 2.8 * j / nv);
  auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const auto base = static_cast<uint32_t>(mesh.vertices.size());
  for (double z : {0.69, 0.72})
    for (Vec2 q : {Vec2(1, 1), Vec2(2, 1), Vec2(2, 2), Vec2(1, 2)}) mesh.vertices.emplace_back(q.x, q.y, z);
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
  mesh.triangles.push_back({base + 4, base + 6, base + 5});
  mesh.triangles.push_back({base + 4, base + 7, base + 6});
  mesh.runs.push_back({0, m, 0});
  mesh.names.push_back("wall");
  SectionRequest r;
  r.cutHeightM = 0.8;
  const PlanSection s = planSection(scene, r);
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_NEAR(totalLength(s.walls), 3.0, 1e-9);
  ASSERT_EQ(s.furniture.size(), 2u);  // the top's two triangles; the bottom's are the same
  EXPECT_FALSE(s.furniture[0].outlined);
  EXPECT_NEAR(area(s.furniture[0].outline) + area(s.furniture[1].outline), 1.0, 1e-9);
}

// The caps: of 300 short walls at different angles (none merge) and one window, with room for
// 100 segments, the window is kept and 99 walls, 201 counted as dropped; of three desks (4
// vertices each) with room for 8 vertices, two.
TEST(PlanSection, CapsSegmentsAndFootprints) {
  BoxRoom room;
  Scene& scene = room.scene;
  scene.shapes.clear();
  scene.vertices = {};
  scene.addPolygon({{1, 0, 0.6}, {2.5, 0, 0.6}, {2.5, 0, 2.1}, {1, 0, 2.1}}, room.glass, "window");
  for (int i = 0; i < 300; ++i) {
    const double a = 0.01 * i, x = 0.01 * i;
    const Vec3 p(x, 1.0, 0.0), q = p + 0.1 * Vec3(std::cos(a), std::sin(a), 0.0);
    scene.addPolygon({p, q, q + Vec3(0, 0, 2), p + Vec3(0, 0, 2)}, room.paint);
  }
  for (int i = 0; i < 3; ++i)
    scene.addPolygon({{i, 2, 0.7}, {i + 0.5, 2, 0.7}, {i + 0.5, 2.5, 0.7}, {i, 2.5, 0.7}}, room.paint);
  SectionRequest r;
  r.cutHeightM = 0.8;
  r.floorLevelM = 0.0;
  const PlanSection s = planSection(scene, r, SectionLimits{100, 8});
  EXPECT_EQ(s.openings.size(), 1u);
  EXPECT_EQ(s.walls.size(), 99u);
  EXPECT_EQ(s.droppedSegments, 201u);
  EXPECT_EQ(s.furniture.size(), 2u);
  EXPECT_EQ(s.droppedFootprints, 1u);
}

// Light, glow and void surfaces are a luminaire's or invisible; a sphere crossing the cut is
// counted, not drawn; surfaces outside the request's region are left out.
TEST(PlanSection, SkipsSourcesCurvedShapesAndSurfacesOutsideTheRegion) {
  BoxRoom room;
  Material light;
  light.type = MaterialType::kLight;
  const uint32_t l = room.scene.addMaterial(light);
  room.scene.addPolygon({{1, 1, 0}, {2, 1, 0}, {2, 1, 2}, {1, 1, 2}}, l, "light panel");
  room.scene.addSphere(Vec3(3, 2, 0.8), 0.2, room.paint, false, "ball");
  SectionRequest r;
  r.cutHeightM = 0.8;
  PlanSection s = planSection(room.scene, r);
  EXPECT_NEAR(totalLength(s.walls), BoxRoom::kPerimeter - BoxRoom::kWindowWidth, 1e-9);
  EXPECT_EQ(s.skippedCurved, 1u);
  r.lo = Vec2(3.5, 0.5);
  r.hi = Vec2(4.5, 2.5);  // the east wall only
  s = planSection(room.scene, r);
  EXPECT_NEAR(totalLength(s.walls), 3.0, 1e-9);
  EXPECT_TRUE(s.openings.empty());
  EXPECT_TRUE(s.furniture.empty());
  EXPECT_EQ(s.skippedCurved, 0u);
}

// The study's step: grids at 0.8 m and 0.0 m get two sections (the second cut 1 m above the
// floor), a second 0.8 m grid shares the first's, a vertical grid gets none.
TEST(PlanSection, AddPlanSectionsOnePerCut) {
  const BoxRoom room;
  std::vector<GridSpec> specs(4);
  specs[0].plane.origin.z = 0.8;
  specs[1].plane.origin.z = 0.0;
  specs[2].plane.origin.z = 0.8;
  specs[3].plane.origin = Vec3(0, 1, 0);
  specs[3].plane.vAxis = Vec3(0, 0, 1);
  std::vector<PreparedGrid> grids(specs.size());
  ReportData data;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    grids[i].spec = &specs[i];
    GridReport g;
    g.planIsXY = i != 3;
    g.values = {1.0};
    g.layout.planPositions = {Vec2(0.0), Vec2(4.0, 3.0)};  // up to the walls, as office's workplane
    data.grids.push_back(g);
  }
  addPlanSections(data, room.scene, grids);
  ASSERT_EQ(data.planSections.size(), 2u);
  ASSERT_GE(data.grids[0].planSection, 0);
  ASSERT_GE(data.grids[1].planSection, 0);
  EXPECT_EQ(data.grids[2].planSection, data.grids[0].planSection);
  EXPECT_EQ(data.grids[3].planSection, -1);
  const PlanSection& work = data.planSections[static_cast<std::size_t>(data.grids[0].planSection)];
  const PlanSection& floor = data.planSections[static_cast<std::size_t>(data.grids[1].planSection)];
  EXPECT_DOUBLE_EQ(work.cutHeightM, 0.8);
  EXPECT_FALSE(work.raisedAboveFloor);
  EXPECT_DOUBLE_EQ(floor.cutHeightM, kFloorPlanCutM);
  EXPECT_TRUE(floor.raisedAboveFloor);
  // The walls lie on the plan region's edges (the grids' extent): all four are kept.
  EXPECT_NEAR(totalLength(work.walls), BoxRoom::kPerimeter - BoxRoom::kWindowWidth, 1e-9);
}

// A ceiling's grid ([[surface_grid]]) is a reflected ceiling plan: no section (its own surface
// would be taken for the floor and the plan cut a metre above the roof).
TEST(PlanSection, CeilingGridsGetNone) {
  const BoxRoom room;
  GridSpec ceiling;
  ceiling.plane.origin.z = 2.799;
  ceiling.plane.normal = Vec3(0, 0, -1);
  ceiling.surfaceGrid = "ceiling";
  ceiling.roomSurface = RoomSurface::kCeiling;
  PreparedGrid g;
  g.spec = &ceiling;
  EXPECT_FALSE(gridPlanHeight(g).has_value());
  ceiling.roomSurface = RoomSurface::kFloor;  // a floor's grid is a plan at floor level as any
  EXPECT_DOUBLE_EQ(gridPlanHeight(g).value(), 2.799);
}

}  // namespace
}  // namespace candela
