#include "engine/sensors.h"

#include "engine/parallel.h"

namespace candela {

std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads) {
  std::vector<IrradianceEstimate> out(points.size());
  parallelFor(points.size(), threads, [&](size_t i) {
    out[i] = tracer.irradiance(points[i].position, points[i].normal, i, settings);
  });
  return out;
}

}  // namespace candela
