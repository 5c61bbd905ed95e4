// Evaluations per second of the function language (engine/radiance/cal/cal.h) on expressions of
// the kinds real patterns use: a wood-grain style function of the hit point, the library's
// noise with turbulence (recursion), and the sky brightness of a CIE overcast sky.
#include "engine/radiance/cal/cal.h"

#include <benchmark/benchmark.h>

namespace {

using namespace candela::cal;

void run(benchmark::State& state, const char* text, const char* name) {
  Program p;
  p.addText(text, "bench.cal");
  const Symbol s = p.find(name);
  Evaluator e(p);
  Environment env;
  double x = 0.0, sum = 0.0;
  for (auto _ : state) {
    env.ray[kPx] = x;
    env.ray[kPy] = 0.5 * x;
    env.ray[kPz] = 1.0;
    env.ray[kDz] = 0.7;
    e.begin(env);
    sum += e.value(s);
    x += 0.001;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}

void BM_CalArithmetic(benchmark::State& state) {
  run(state, "r = sqrt(Px*Px + Py*Py); grain = .5 + .5*sin(40*r + 3*Pz); v = if(grain - .8, .6, .9*grain);", "v");
}
void BM_CalTurbulence(benchmark::State& state) {
  run(state, "v = .5 + .2*turbulence(Px, Py, Pz, .0625);", "v");  // 5 octaves
}
void BM_CalOvercastSky(benchmark::State& state) {
  // CIE overcast: L(θ) ∝ (1 + 2 cos θ)/3, Dz the cosine of the zenith angle.
  run(state, "v = if(Dz, (1 + 2*Dz)/3, 0);", "v");
}

BENCHMARK(BM_CalArithmetic);
BENCHMARK(BM_CalTurbulence);
BENCHMARK(BM_CalOvercastSky);

}  // namespace

BENCHMARK_MAIN();
