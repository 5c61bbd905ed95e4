// Fuzz target: Radiance-style sensor points (study/grids/sensor_grid.h, readPoints).
#include "study/grids/sensor_grid.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::istringstream in{std::string(candela::fuzz::asText(data, size))};
    candela::readPoints(in, "fuzz.pts");
  } catch (const candela::InputError&) {
  }
  return 0;
}
