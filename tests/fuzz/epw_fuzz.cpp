// Fuzz target: EnergyPlus weather (photometry/epw.h, parseEpw).
#include "photometry/epw.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::istringstream in{std::string(candela::fuzz::asText(data, size))};
    candela::parseEpw(in, "fuzz.epw");
  } catch (const candela::InputError&) {
  }
  return 0;
}
