// Fuzz target: the TOML case file (study/case/case_file.h, parseCaseFile). The case sits in a folder
// that holds no files, so every referenced scene, luminaire or weather file is missing.
#include "study/case/case_file.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::parseCaseFile(candela::fuzz::asText(data, size), "/nonexistent-candela-fuzz/case.toml");
  } catch (const candela::InputError&) {
  }
  return 0;
}
