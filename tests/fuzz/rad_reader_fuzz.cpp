// Fuzz target: Radiance scene text (engine/radiance/reader.h, readRadianceText).
#include "engine/radiance/reader.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::Scene scene;
    candela::readRadianceText(candela::fuzz::asText(data, size), "fuzz.rad", scene);
  } catch (const candela::InputError&) {
  }
  return 0;
}
