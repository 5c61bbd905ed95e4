// The plans' sections (study/grids/plan_section.h): the office demo's four cuts (the workplane at
// 0.8 m, the corridor's floor grid cut at 1.0 m, modelling at 1.2 m, the task area at 0.75 m),
// each with its floor search, as the study computes them; and one cut through a 10⁶-triangle
// heightfield crossing the plane everywhere (the raw cap and the merge at work). Results in
// docs/reports.md ("Plans").
// Run: build/bench/plan_section_bench
#include "engine/radiance/reader.h"
#include "study/grids/plan_section.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace candela {
namespace {

void BM_OfficeSections(benchmark::State& state) {
  Scene scene;
  readRadianceFile(std::filesystem::path(CANDELA_SOURCE_DIR) / "cases/office/office.rad", scene);
  struct Cut {
    double gridZ;
    Vec2 lo, hi;
  };
  const Cut cuts[] = {{0.8, {0.0, 0.0}, {12.0, 6.35}},
                      {0.0, {0.0, 6.8}, {12.0, 8.0}},
                      {1.2, {0.0, 0.0}, {12.0, 6.35}},
                      {0.75, {0.0, 0.0}, {12.0, 6.35}}};
  std::size_t segments = 0;
  for (auto _ : state) {
    segments = 0;
    for (const Cut& c : cuts) {
      const double floorZ = floorLevel(scene, c.gridZ, c.lo - Vec2(1.0), c.hi + Vec2(1.0));
      const PlanSection s = planSection(scene, {planCutHeight(c.gridZ, floorZ), floorZ, c.lo, c.hi});
      segments += s.walls.size() + s.openings.size() + s.openingsAbove.size() + s.furniture.size();
      benchmark::DoNotOptimize(s.walls.data());
    }
  }
  state.counters["surfaces"] = static_cast<double>(scene.surfaceCount());
  state.counters["elements"] = static_cast<double>(segments);
}
BENCHMARK(BM_OfficeSections)->Unit(benchmark::kMicrosecond);

// 2 · 708² triangles of a 20 m × 20 m wavy heightfield (±0.3 m), cut at 0.1 m.
void BM_MeshSection(benchmark::State& state) {
  constexpr int n = 708;
  Scene scene;
  Material m;
  m.type = MaterialType::kPlastic;
  const uint32_t grey = scene.addMaterial(m);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 20.0 * i / n, y = 20.0 * j / n;
      scene.mesh.vertices.emplace_back(x, y, 0.3 * std::sin(x) * std::cos(0.7 * y));
    }
  auto at = [](int i, int j) { return static_cast<uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      scene.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      scene.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  scene.mesh.runs.push_back({0, grey, 0});
  scene.mesh.names.push_back("terrain");
  PlanSection s;
  for (auto _ : state) {
    s = planSection(scene, {0.1, -1.0, Vec2(0.0), Vec2(20.0)});
    benchmark::DoNotOptimize(s.walls.data());
  }
  state.counters["triangles"] = static_cast<double>(scene.mesh.triangles.size());
  state.counters["kept"] = static_cast<double>(s.walls.size());
  state.counters["dropped"] = static_cast<double>(s.droppedSegments);
  state.counters["footprints"] = static_cast<double>(s.furniture.size());
  state.counters["footprints_dropped"] = static_cast<double>(s.droppedFootprints);
}
BENCHMARK(BM_MeshSection)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
