// Rays per second through the octree (and Embree, engine/embree_accelerator.h) on generated scenes
// of 10³ … 10⁶ small random triangles filling a 10 m cube (results in
// docs/performance.md).
// Run: build/bench/octree_bench [--benchmark_filter=...]
#include "base/rng.h"
#include "engine/embree_accelerator.h"
#include "engine/octree.h"
#include "engine/sampling.h"

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

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
  // Embree over the same scene, per (robust, high quality) option pair, built on first use.
  std::map<std::pair<bool, bool>, std::unique_ptr<EmbreeAccelerator>> embree;
  std::map<std::pair<bool, bool>, double> embreeBuildSeconds;
};

Fixture& fixture(int count, int setSize) {
  static std::map<std::pair<int, int>, std::unique_ptr<Fixture>> cache;
  auto& f = cache[{count, setSize}];
  if (f) return *f;
  f = std::make_unique<Fixture>();
  Rng rng(42, static_cast<uint64_t>(count));
  Material grey;
  grey.type = MaterialType::kPlastic;
  grey.name = "grey";
  grey.color = Rgb(0.5);
  const uint32_t mat = f->scene.addMaterial(grey);
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

// The same scenes and rays through EmbreeAccelerator (Embree's build runs on all cores, TBB).
EmbreeAccelerator& embree(Fixture& f, bool robust, bool highQuality) {
  auto& e = f.embree[{robust, highQuality}];
  if (!e) {
    const auto t0 = std::chrono::steady_clock::now();
    e = std::make_unique<EmbreeAccelerator>(f.scene, EmbreeOptions{robust, highQuality, false});
    f.embreeBuildSeconds[{robust, highQuality}] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return *e;
}

void embreeCounters(benchmark::State& state, Fixture& f, bool robust, bool highQuality, int64_t hits) {
  state.SetItemsProcessed(state.iterations());
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["bytes_per_surface"] =
      static_cast<double>(embree(f, robust, highQuality).stats().memoryBytes) / f.scene.shapes.size();
  state.counters["hit_fraction"] = static_cast<double>(hits) / state.iterations();
  state.counters["build_s"] = f.embreeBuildSeconds[{robust, highQuality}];
}

// Arguments: triangles, robust (0/1), high build quality (0/1).
void BM_NearestHitEmbree(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)), 6);
  const bool robust = state.range(1) != 0, high = state.range(2) != 0;
  const EmbreeAccelerator& acc = embree(f, robust, high);
  size_t i = 0;
  int64_t hits = 0;
  for (auto _ : state) {
    const auto& r = f.rays[i++ & (f.rays.size() - 1)];
    RayHit h;
    hits += acc.intersect(r.first, r.second, 0.0, 1e30, h);
    benchmark::DoNotOptimize(h);
  }
  embreeCounters(state, f, robust, high, hits);
}

void BM_ShadowAnyHitEmbree(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)), 6);
  const bool robust = state.range(1) != 0, high = state.range(2) != 0;
  const EmbreeAccelerator& acc = embree(f, robust, high);
  size_t i = 0;
  int64_t hits = 0;
  for (auto _ : state) {
    const auto& r = f.rays[i++ & (f.rays.size() - 1)];
    const bool occ = acc.occluded(r.first, r.second, 0.0, 2.0);
    hits += occ;
    benchmark::DoNotOptimize(occ);
  }
  embreeCounters(state, f, robust, high, hits);
}

// Embree alone on the same triangles (robust, high quality): float t, no double re-test, no
// mapping back to shapes. The floor under BM_NearestHitEmbree; the difference is mostly the
// cache miss of reading the hit shape for its double t (docs/performance.md).
void BM_NearestHitEmbreeFloatOnly(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)), 6);
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t n = f.scene.shapes.size();
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 3 * n));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, n));
  const Vec3 centre = f.scene.bounds().center();
  for (size_t i = 0; i < n; ++i) {
    const Shape& sh = f.scene.shapes[i];
    const Vec3 p[3] = {sh.a - centre, sh.a + sh.b - centre, sh.a + sh.c - centre};
    for (size_t k = 0; k < 3; ++k) {
      for (int j = 0; j < 3; ++j) v[9 * i + 3 * k + j] = static_cast<float>(p[k][j]);
      idx[3 * i + k] = static_cast<unsigned>(3 * i + k);
    }
  }
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(scene);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  size_t i = 0;
  int64_t hits = 0;
  for (auto _ : state) {
    const auto& r = f.rays[i++ & (f.rays.size() - 1)];
    const Vec3 o = r.first - centre;
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(o.x), rh.ray.org_y = static_cast<float>(o.y);
    rh.ray.org_z = static_cast<float>(o.z);
    rh.ray.dir_x = static_cast<float>(r.second.x), rh.ray.dir_y = static_cast<float>(r.second.y);
    rh.ray.dir_z = static_cast<float>(r.second.z);
    rh.ray.tnear = 0.0f, rh.ray.tfar = 1e30f, rh.ray.time = 0.0f, rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
    rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    benchmark::DoNotOptimize(rh);
  }
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["hit_fraction"] = static_cast<double>(hits) / state.iterations();
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}

BENCHMARK(BM_NearestHit)->ArgsProduct({{1000, 10000, 100000, 1000000}, {6}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShadowAnyHit)->ArgsProduct({{1000, 10000, 100000, 1000000}, {6}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NearestHit)->ArgsProduct({{100000}, {2, 4, 10, 16}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NearestHitEmbree)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1}, {1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ShadowAnyHitEmbree)
    ->ArgsProduct({{1000, 10000, 100000, 1000000}, {1}, {1}})
    ->Unit(benchmark::kMicrosecond);
// The options: robust traversal and build quality (the defaults are chosen from these).
BENCHMARK(BM_NearestHitEmbree)->ArgsProduct({{100000}, {0, 1}, {0, 1}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NearestHitEmbreeFloatOnly)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
