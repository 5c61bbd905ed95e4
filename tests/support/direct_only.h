// Trace settings for tests of direct light only: `lightSamples` light samples a point, no
// interreflection, no adaptive sampling (so the estimate is the plain mean of the light samples).
#pragma once

#include "engine/trace_settings.h"

namespace candela::test_support {

inline TraceSettings directOnlySettings(int lightSamples) {
  TraceSettings s;
  s.lightSamples = lightSamples;
  s.hemisphereSamples = 16;
  s.maxBounces = 0;
  s.adaptiveFraction = 0.0;
  return s;
}

}  // namespace candela::test_support
