// Fuzz target: Radiance scene text (engine/radiance/reader.h, SceneReader::readText), its inline
// commands expanded by the generators under a memory limit of 256 MiB (what --max-memory gives
// the reader: about 220 000 generated primitives), so that an input asking for 10^7 is refused
// as a user's would be on a small machine, not a finding of the fuzzer's 1 GB limit.
#include "engine/radiance/reader.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    candela::Scene scene;
    candela::SceneReadOptions options;
    options.maxMemoryBytes = uint64_t(256) << 20;
    candela::SceneReader(scene, options).readText(candela::fuzz::asText(data, size), "fuzz.rad");
  } catch (const candela::InputError&) {
  }
  return 0;
}
