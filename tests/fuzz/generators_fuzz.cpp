// Fuzz target: the generators alone (engine/radiance/generators.h, expandRadCommand): the input's
// inline commands (`!xform`, `!genbox`, `!genprism`, `!gensky`, `!gendaylit`, `!genrev`,
// `!gensurf`, `!genworm` and pipelines of them) expanded with no files to read beyond the working
// directory's and under a memory limit of 256 MiB (about 220 000 primitives), as a small
// machine's run would; primitives are parsed and dropped.
#include "engine/radiance/generators.h"
#include "engine/radiance/parse.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::RadExpandContext ctx;
  ctx.folder = ".";
  ctx.maxMemoryBytes = uint64_t(256) << 20;
  ctx.readFile = [](const std::filesystem::path&, const candela::FileLoc& from) -> std::vector<candela::RadPrimitive> {
    throw candela::InputError(from, "no files in the generators' fuzz target");
  };
  try {
    candela::parseRadiance(
        candela::fuzz::asText(data, size), "fuzz.rad", [](candela::RadPrimitive&&) {},
        [&](candela::RadCommand&& c) { (void)candela::expandRadCommand(c, ctx); });
  } catch (const candela::InputError&) {
  }
  return 0;
}
