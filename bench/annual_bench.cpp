// The hourly product of annual daylight (engine/daylight_coefficients.h): 1000 sensors × a full
// year of sky vectors (Tregenza 146 and Reinhart MF:2 578 patches), sun terms included, on all
// cores. The budget is 5 s for the 8760-hour product (docs/annual.md); docs/performance.md has the times
// of a real case.
#include "engine/daylight_coefficients.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace candela {
namespace {

// A year of synthetic sky vectors: 8760 hours, the sun up half of them, smooth luminances.
AnnualSky syntheticSky(int subdivision) {
  const SkyPatches patches(subdivision);
  AnnualSky sky;
  sky.subdivision = subdivision;
  sky.patchCount = patches.count();
  sky.hours.resize(8760);
  sky.luminance.resize(size_t(8760) * patches.count());
  for (int h = 0; h < 8760; ++h) {
    AnnualHour& a = sky.hours[h];
    a.hour = h % 24 + 1;
    const double alt = 60.0 * std::sin(kPi * ((h % 24) - 6) / 12.0);
    a.sunUp = alt > 0.0;
    if (a.sunUp) {
      const double az = degToRad(90.0 + 15.0 * ((h % 24) - 6));
      a.sunDirTrue = Vec3(std::cos(degToRad(alt)) * std::sin(az), std::cos(degToRad(alt)) * std::cos(az),
                          std::sin(degToRad(alt)));
      a.sunAltitudeDeg = alt;
      a.directNormalLux = 60000.0;
      a.sunPatch = patches.indexOf(a.sunDirTrue);
    }
    for (int p = 0; p < patches.count(); ++p)
      sky.luminance[size_t(h) * patches.count() + p] = a.sunUp ? float(3000.0 + 100.0 * (p % 7)) : 0.0f;
  }
  return sky;
}

void BM_AnnualProduct(benchmark::State& state) {
  const int subdivision = static_cast<int>(state.range(0)), sensors = 1000;
  const AnnualSky sky = syntheticSky(subdivision);
  DaylightCoefficients dc;
  dc.sensors = sensors;
  dc.patches = sky.patchCount;
  dc.total.resize(size_t(sensors) * sky.patchCount);
  for (size_t i = 0; i < dc.total.size(); ++i) dc.total[i] = float(1e-3 * (i % 13));
  const std::vector<int> sun = sunHours(sky);
  const std::vector<float> direct(size_t(sensors) * sun.size(), 0.5f);
  const SunSet set = indirectSunSet(sky);
  const std::vector<float> inter(size_t(sensors) * set.dirsTrue.size(), 0.01f);
  for (auto _ : state) {
    const AnnualIlluminance year = annualIlluminance(dc, direct, inter, set, sky, 0);
    benchmark::DoNotOptimize(year.total.data());
  }
  state.counters["sensor_hours_per_s"] =
      benchmark::Counter(double(sensors) * 8760.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AnnualProduct)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
