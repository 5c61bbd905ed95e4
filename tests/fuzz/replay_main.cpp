// Replays kept fuzz inputs through a fuzz target without libFuzzer (any compiler):
//   fuzz_replay_<reader> FILE_OR_FOLDER...
// Each input runs once; the target must return (accepted or InputError). An uncaught exception,
// a crash or a sanitizer report ends the process with a failure, naming the input first.
#include "tests/fuzz/fuzz_target.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CANDELA_REPLAY_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CANDELA_REPLAY_ASAN 1
#endif
#ifndef CANDELA_REPLAY_ASAN
#include <sys/resource.h>
#endif

namespace fs = std::filesystem;

int main(int argc, char** argv) {
#ifndef CANDELA_REPLAY_ASAN
  // The fuzz pass refuses allocations over 1 GB (scripts/fuzz.sh); here an address-space limit
  // of 2 GB turns such an input into std::bad_alloc (a failure) instead of swapping the machine.
  // Not under ASan, whose shadow memory needs terabytes of address space.
  const rlim_t limit = rlim_t(2) << 30;
  rlimit rl{limit, limit};
  setrlimit(RLIMIT_AS, &rl);
#endif
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const fs::path p = argv[i];
    if (fs::is_directory(p)) {
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file()) inputs.push_back(e.path());
    } else {
      inputs.push_back(p);
    }
  }
  std::sort(inputs.begin(), inputs.end());
  for (const fs::path& p : inputs) {
    std::ifstream in(p, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "cannot read %s\n", p.c_str());
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay %s (%zu bytes)\n", p.c_str(), bytes.size());
    std::fflush(stderr);
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::fprintf(stderr, "replayed %zu inputs\n", inputs.size());
  return 0;
}
