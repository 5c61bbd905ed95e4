// Fuzz target: EULUMDAT text (photometry/eulumdat.h, parseEulumdat).
#include "photometry/eulumdat.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::parseEulumdat(candela::fuzz::asText(data, size), "fuzz.ldt");
  } catch (const candela::InputError&) {
  }
  return 0;
}
