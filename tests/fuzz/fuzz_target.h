// The one entry point every reader's fuzz target defines (libFuzzer's signature). Built two ways
// (tests/fuzz/CMakeLists.txt): with clang and -fsanitize=fuzzer as a fuzzer (scripts/fuzz.sh),
// and with any compiler against replay_main.cpp, which runs the kept inputs as a CTest.
//
// A target returns normally for accepted input and for an InputError (the reader's way of saying
// "bad file, here is the line"); anything else -- another exception, a sanitizer report, a
// crash, a hang, a huge allocation -- is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace candela::fuzz {

inline std::string_view asText(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace candela::fuzz
