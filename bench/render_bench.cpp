// renderView speed: camera paths per second in a closed grey room lit by a small light sphere
// (interreflections, 2 bounces), one thread, with every pixel traced and with the adaptive
// lattice; and the adaptive sampler on a smooth image (a sunlit plane), where it interpolates.
#include "engine/render.h"

#include <benchmark/benchmark.h>

namespace candela {
namespace {

uint32_t material(Scene& sc, MaterialType type, double value) {
  Material m;
  m.type = type;
  m.name = "m";
  m.color = Rgb(value);
  return sc.addMaterial(m);
}

// A 4 × 3 × 2.8 m room seen from inside (all faces face inward).
Scene room() {
  Scene sc;
  const uint32_t grey = material(sc, MaterialType::kPlastic, 0.5);
  const double x = 4, y = 3, z = 2.8;
  sc.addPolygon({{0, 0, 0}, {x, 0, 0}, {x, y, 0}, {0, y, 0}}, grey);  // floor, up
  sc.addPolygon({{0, 0, z}, {0, y, z}, {x, y, z}, {x, 0, z}}, grey);  // ceiling, down
  sc.addPolygon({{0, 0, 0}, {0, 0, z}, {x, 0, z}, {x, 0, 0}}, grey);  // y = 0, +y
  sc.addPolygon({{0, y, 0}, {x, y, 0}, {x, y, z}, {0, y, z}}, grey);  // y = 3, −y
  sc.addPolygon({{0, 0, 0}, {0, y, 0}, {0, y, z}, {0, 0, z}}, grey);  // x = 0, +x
  sc.addPolygon({{x, 0, 0}, {x, 0, z}, {x, y, z}, {x, y, 0}}, grey);  // x = 4, −x
  sc.addSphere({2.0, 1.5, 2.4}, 0.1, material(sc, MaterialType::kLight, 200.0));
  return sc;
}

View roomView() {
  View v;
  v.positionM = {0.3, 0.3, 1.5};
  v.direction = {1.0, 0.8, -0.2};
  v.fovDeg = {80.0, 60.0};
  v.resolution = {64, 48};
  return v;
}

void BM_RenderRoom(benchmark::State& state) {
  const Scene sc = room();
  const Tracer tracer(sc);
  TraceSettings s;
  s.maxBounces = 2;
  RenderSettings r;
  r.samplesPerPixel = 4;
  r.coarseStep = static_cast<int>(state.range(0));
  std::size_t rays = 0;
  for (auto _ : state) {
    const Image img = renderView(tracer, roomView(), s, 1, r);
    rays += img.cameraRays;
    benchmark::DoNotOptimize(img.luminance.data());
  }
  state.counters["camera_paths_per_s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderRoom)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

void BM_RenderSmoothPlane(benchmark::State& state) {
  Scene sc;
  sc.addPolygon({{-1e3, -1e3, 0}, {1e3, -1e3, 0}, {1e3, 1e3, 0}, {-1e3, 1e3, 0}}, material(sc, MaterialType::kPlastic, 0.5));
  sc.addDistant({0.3, -0.5, 0.8}, 0.533, material(sc, MaterialType::kLight, 6e6));
  const Tracer tracer(sc);
  View v = roomView();
  v.resolution = {128, 96};
  TraceSettings s;
  s.maxBounces = 0;
  RenderSettings r;
  r.coarseStep = static_cast<int>(state.range(0));
  std::size_t traced = 0;
  for (auto _ : state) {
    const Image img = renderView(tracer, v, s, 1, r);
    traced = img.tracedPixels;
    benchmark::DoNotOptimize(img.luminance.data());
  }
  state.counters["traced_pixels"] = static_cast<double>(traced);
}
BENCHMARK(BM_RenderSmoothPlane)->Arg(1)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace candela
BENCHMARK_MAIN();
