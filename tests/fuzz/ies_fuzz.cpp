// Fuzz target: IES LM-63 text (photometry/ies_lm63.h, parseIes). The folder for TILT=<file> is
// one that holds no files, so a TILT file name is always "cannot open".
#include "photometry/ies_lm63.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::parseIes(candela::fuzz::asText(data, size), "fuzz.ies", "/nonexistent-candela-fuzz");
  } catch (const candela::InputError&) {
  }
  return 0;
}
