// Fuzz target: a shard's part as `candela merge` reads it (study/distributed/shard_distribution.h): part.json
// (readPartHeader, checkPartSet) and fills.bin (MergeDistribution's fills of a small study).
//
// Input: one flag byte, a little-endian uint16 L, L bytes of part.json, then fills.bin. When the
// flag is odd and part.json parses, its "data_checksum" is set to fills.bin's (as a deliberate
// edit would), so that the fuzzer reaches the fills behind the checksum. tests/fuzz/part/ holds
// seeds made from a real part of this study.
#include "study/distributed/shard_distribution.h"
#include "base/error.h"
#include "base/input_file.h"
#include "tests/fuzz/fuzz_target.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The fills the seeds' study makes (tests/study/distributed/shard_distribution_test.cpp's Study): shared
// lists, result lists, shared items, result items.
void runStudy(const candela::Distribution& d) {
  std::vector<std::vector<std::byte>> a(4), b(50);
  d.fillLists(a, candela::ItemUse::kShared, 1, [](size_t, std::vector<std::byte>&) {});
  d.fillLists(b, candela::ItemUse::kResult, 1, [](size_t, std::vector<std::byte>&) {});
  std::vector<uint64_t> x(4), y(50);
  candela::distributedFill(d, x, candela::ItemUse::kShared, 1, [](size_t, uint64_t&) {});
  candela::distributedFill(d, y, candela::ItemUse::kResult, 1, [](size_t, uint64_t&) {});
  d.finish();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const bool seal = data[0] & 1;
  const size_t manifestBytes = std::min<size_t>(size - 3, data[1] | (size_t(data[2]) << 8));
  std::string manifest(reinterpret_cast<const char*>(data) + 3, manifestBytes);
  const std::string fills(reinterpret_cast<const char*>(data) + 3 + manifestBytes, size - 3 - manifestBytes);
  if (seal) {
    try {
      nlohmann::json j = nlohmann::json::parse(manifest);
      char hex[17];
      std::snprintf(hex, sizeof hex, "%016llx",
                    static_cast<unsigned long long>(candela::fnv1a(fills.data(), fills.size())));
      if (j.is_object()) j["data_checksum"] = hex;
      manifest = j.dump();
    } catch (const nlohmann::json::exception&) {
    }
  }
  static const fs::path dir = fs::temp_directory_path() / ("candela_fuzz_part_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / candela::kPartManifest, std::ios::trunc | std::ios::binary) << manifest;
  std::ofstream(dir / candela::kPartData, std::ios::trunc | std::ios::binary) << fills;
  try {
    std::vector<candela::PartHeader> parts{candela::readPartHeader(dir)};
    parts = candela::checkPartSet(std::move(parts));
    const candela::MergeDistribution merge(std::move(parts));
    runStudy(merge);
  } catch (const candela::InputError&) {
  }
  return 0;
}
