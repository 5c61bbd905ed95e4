// Rays per second through the octree on generated scenes of 10³ … 10⁶ small random triangles
// filling a 10 m cube (issue "Engine core"; results in docs/performance.md).
// Run: build/bench/octree_bench [--benchmark_filter=...]
#include "engine/base/rng.h"
#include "engine/octree.h"
#include "engine/sampling.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>

namespace candela {
namespace {

constexpr double kCubeM = 10.0;
constexpr double kTriangleM = 0.2;  // vertices within a 0.2 m box around a random centre

struct Fixture {
  Scene scene;
  std::unique_ptr<Octree> octree;
  std::vector<std::pair<Vec3, Vec3>> rays;
  double buildSeconds = 0.0;
};

Fixture& fixture(int count, int setSize) {
  static std::map<std::pair<int, int>, std::unique_ptr<Fixture>> cache;
  auto& f = cache[{count, setSize}];
  if (f) return *f;
  f = std::make_unique<Fixture>();
  Rng rng(42, static_cast<uint64_t>(count));
  const uint32_t mat = f->scene.addMaterial(Material{MaterialType::Plastic, "grey", {}, Rgb(0.5)});
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * kCubeM, rng.uniform() * kCubeM, rng.uniform() * kCubeM);
    std::vector<Vec3> v;
    for (int k = 0; k < 3; ++k)
      v.push_back(c + kTriangleM * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
    if (glm::length(glm::cross(v[1] - v[0], v[2] - v[0])) < 1e-6) continue;
    f->scene.addPolygon(v, mat);
  }
  const auto t0 = std::chrono::steady_clock::now();
  OctreeOptions opt;
  opt.maxSetSize = setSize;
  f->octree = std::make_unique<Octree>(f->scene, opt);
  f->buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (int i = 0; i < 1 << 16; ++i) {
    const Vec3 o(rng.uniform() * kCubeM, rng.uniform() * kCubeM, rng.uniform() * kCubeM);
    const Vec3 d = glm::normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
    f->rays.emplace_back(o, d);
  }
  return *f;
}

void counters(benchmark::State& state, const Fixture& f, int64_t hits) {
  const OctreeStats s = f.octree->stats();
  state.SetItemsProcessed(state.iterations());
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["bytes_per_surface"] = static_cast<double>(s.memoryBytes) / f.scene.shapes.size();
  state.counters["depth"] = s.depth;
  state.counters["hit_fraction"] = static_cast<double>(hits) / state.iterations();
  state.counters["build_s"] = f.buildSeconds;
}

void BM_NearestHit(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  size_t i = 0;
  int64_t hits = 0;
  for (auto _ : state) {
    const auto& r = f.rays[i++ & (f.rays.size() - 1)];
    Octree::Hit h;
    hits += f.octree->intersect(r.first, r.second, 0.0, 1e30, h);
    benchmark::DoNotOptimize(h);
  }
  counters(state, f, hits);
}

void BM_ShadowAnyHit(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  size_t i = 0;
  int64_t hits = 0;
  for (auto _ : state) {
    const auto& r = f.rays[i++ & (f.rays.size() - 1)];
    // Shadow rays of 2 m, a typical source distance in a room.
    const bool occ = f.octree->occluded(r.first, r.second, 0.0, 2.0);
    hits += occ;
    benchmark::DoNotOptimize(occ);
  }
  counters(state, f, hits);
}

BENCHMARK(BM_NearestHit)->ArgsProduct({{1000, 10000, 100000, 1000000}, {6}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShadowAnyHit)->ArgsProduct({{1000, 10000, 100000, 1000000}, {6}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NearestHit)->ArgsProduct({{100000}, {2, 4, 10, 16}})->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
