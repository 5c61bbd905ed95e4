// Loading a 10⁶-triangle OBJ file into the compact mesh (Scene::mesh), and building each
// accelerator over it: seconds, and bytes per triangle counted from the structures (the mesh's
// vectors, the accelerator's arrays and Embree's own allocations) and from the growth of the
// resident set. The same triangles as one Shape each (the reader's path before the mesh) for
// comparison. Results in docs/performance.md.
// Run: build/bench/mesh_bench [--benchmark_filter=...]
#include "engine/embree_accelerator.h"
#include "engine/octree.h"
#include "engine/radiance/reader.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr int kGrid = 708;  // 2 · 708² = 1 002 528 triangles over 709² vertices

// Resident set size now (bytes), from /proc/self/statm.
double residentBytes() {
  std::ifstream f("/proc/self/statm");
  long pages = 0, resident = 0;
  f >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// A 20 m × 20 m heightfield of gentle waves as OBJ (written once), and its material.
const fs::path& objFile() {
  static const fs::path path = [] {
    const fs::path dir = fs::temp_directory_path() / "candela_mesh_bench";
    fs::create_directories(dir);
    std::ofstream(dir / "materials.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\n";
    std::ofstream obj(dir / "terrain.obj");
    char buf[128];
    for (int j = 0; j <= kGrid; ++j)
      for (int i = 0; i <= kGrid; ++i) {
        const double x = 20.0 * i / kGrid, y = 20.0 * j / kGrid;
        std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", x, y, 0.3 * std::sin(x) * std::cos(0.7 * y));
        obj << buf;
      }
    obj << "usemtl grey\n";
    auto at = [](int i, int j) { return j * (kGrid + 1) + i + 1; };
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        obj << "f " << at(i, j) << ' ' << at(i + 1, j) << ' ' << at(i + 1, j + 1) << '\n';
        obj << "f " << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i, j + 1) << '\n';
      }
    return dir / "terrain.obj";
  }();
  return path;
}

std::unique_ptr<Scene> load() {
  auto scene = std::make_unique<Scene>();
  readSceneFiles({objFile().parent_path() / "materials.rad", objFile()}, *scene);
  return scene;
}

void BM_LoadObj(benchmark::State& state) {
  objFile();
  double bytes = 0.0, rss = 0.0, tris = 0.0;
  for (auto _ : state) {
    const double before = residentBytes();
    std::unique_ptr<Scene> scene = load();
    rss = residentBytes() - before;
    tris = static_cast<double>(scene->mesh.triangles.size());
    bytes = static_cast<double>(scene->mesh.memoryBytes());
    benchmark::DoNotOptimize(scene.get());
  }
  state.counters["triangles"] = tris;
  state.counters["mesh_B_per_tri"] = bytes / tris;
  state.counters["rss_B_per_tri"] = rss / tris;
}
BENCHMARK(BM_LoadObj)->Unit(benchmark::kMillisecond)->Iterations(3);

template <class Accel>
size_t accelBytes(const Accel& a) {
  return a.stats().memoryBytes;
}

template <class Accel>
void BM_Build(benchmark::State& state) {
  const std::unique_ptr<Scene> scene = load();
  const double tris = static_cast<double>(scene->mesh.triangles.size());
  double bytes = 0.0, rss = 0.0;
  for (auto _ : state) {
    const double before = residentBytes();
    const Accel accel(*scene);
    rss = residentBytes() - before;
    bytes = static_cast<double>(accelBytes(accel));
    benchmark::DoNotOptimize(&accel);
  }
  const double mesh = static_cast<double>(scene->mesh.memoryBytes());
  state.counters["accel_B_per_tri"] = bytes / tris;
  state.counters["total_B_per_tri"] = (bytes + mesh) / tris;  // mesh + accelerator, counted
  state.counters["accel_rss_B_per_tri"] = rss / tris;
}
BENCHMARK_TEMPLATE(BM_Build, EmbreeAccelerator)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_TEMPLATE(BM_Build, Octree)->Unit(benchmark::kMillisecond)->Iterations(2);

// The same triangles as one Shape each, with a name each (how every triangle was stored before
// the mesh), and Embree over them.
void BM_ShapesForComparison(benchmark::State& state) {
  const std::unique_ptr<Scene> mesh = load();
  double bytes = 0.0, tris = 0.0;
  for (auto _ : state) {
    Scene scene;
    scene.materials = mesh->materials;
    for (const auto& t : mesh->mesh.triangles)
      scene.addPolygon({mesh->mesh.vertices[t[0]], mesh->mesh.vertices[t[1]], mesh->mesh.vertices[t[2]]}, 0, "f");
    const EmbreeAccelerator accel(scene);
    tris = static_cast<double>(scene.shapes.size());
    bytes = static_cast<double>(scene.shapes.capacity() * sizeof(Shape) +
                                scene.shapeNames.capacity() * sizeof(std::string) +
                                scene.vertices.points.capacity() * sizeof(Vec3) +
                                scene.vertices.projected.capacity() * sizeof(Vec2) + accel.stats().memoryBytes);
  }
  state.counters["total_B_per_tri"] = bytes / tris;
}
BENCHMARK(BM_ShapesForComparison)->Unit(benchmark::kMillisecond)->Iterations(1);

// Nearest-hit rays per second on the mesh and on the same triangles as Shapes: random rays
// from 2 m above the terrain, downwards within 45° of the vertical.
struct RayFixture {
  std::unique_ptr<Scene> mesh = load(), shapes = std::make_unique<Scene>();
  std::vector<std::pair<Vec3, Vec3>> rays;
  RayFixture() {
    shapes->materials = mesh->materials;
    for (const auto& t : mesh->mesh.triangles)
      shapes->addPolygon({mesh->mesh.vertices[t[0]], mesh->mesh.vertices[t[1]], mesh->mesh.vertices[t[2]]}, 0);
    uint64_t x = 88172645463325252ULL;  // xorshift64: a fixed ray set
    auto uniform = [&x] {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      return static_cast<double>(x >> 11) * 0x1p-53;
    };
    for (int i = 0; i < 1 << 16; ++i) {
      const Vec3 o(20.0 * uniform(), 20.0 * uniform(), 2.0);
      rays.emplace_back(o, glm::normalize(Vec3(2.0 * uniform() - 1.0, 2.0 * uniform() - 1.0, -1.0)));
    }
  }
};

RayFixture& rayFixture() {
  static RayFixture f;
  return f;
}

template <class Accel>
void BM_Rays(benchmark::State& state) {
  RayFixture& f = rayFixture();
  const Scene& scene = state.range(0) ? *f.mesh : *f.shapes;
  static std::unique_ptr<Accel> accel[2];
  if (!accel[state.range(0)]) accel[state.range(0)] = std::make_unique<Accel>(scene);
  size_t i = 0, hits = 0;
  for (auto _ : state) {
    const auto& [o, d] = f.rays[i++ & (f.rays.size() - 1)];
    RayHit h;
    hits += accel[state.range(0)]->intersect(o, d, 0.0, 1e30, h);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel(state.range(0) ? "mesh" : "shapes");
  benchmark::DoNotOptimize(hits);
}
BENCHMARK_TEMPLATE(BM_Rays, EmbreeAccelerator)->Arg(1)->Arg(0);
BENCHMARK_TEMPLATE(BM_Rays, Octree)->Arg(1)->Arg(0);

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
