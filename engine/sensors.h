// Illuminance at many sensor points, in parallel, reproducibly.
#pragma once

#include "engine/sensor_grid.h"
#include "engine/tracer.h"

#include <vector>

namespace candela {

// Estimates irradiance at every sensor (point i uses random stream i), on `threads` threads
// (0 = all cores).
std::vector<IrradianceEstimate> computeIrradiance(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                                  const TraceSettings& settings, int threads);

}  // namespace candela
