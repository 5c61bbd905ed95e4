#include "study/distributed/shard_distribution.h"

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/input_file.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace candela {
namespace {

namespace fs = std::filesystem;

// Item i's value: what every distribution must deliver whoever computes it.
uint64_t valueOf(size_t i, int fill) { return (i + 1) * 0x9e3779b97f4a7c15ULL ^ static_cast<uint64_t>(fill); }

// The fills a small "study" makes: a shared one whose items a later fill reads, then a result
// fill, as the irradiance cache's records and the points are.
// Item i of a fill of lists: i mod 5 bytes (some empty), as the cache's phase A hits are.
std::vector<std::byte> listOf(size_t i, int fill) {
  std::vector<std::byte> v(i % 5);
  for (size_t k = 0; k < v.size(); ++k) v[k] = static_cast<std::byte>(valueOf(i + k, fill) & 0xff);
  return v;
}

struct Study {
  std::vector<uint64_t> shared, result;
  std::vector<std::vector<std::byte>> sharedLists, resultLists;
  std::atomic<size_t> computed{0};
  void run(const Distribution& d, size_t nShared, size_t nResult) {
    sharedLists.assign(nShared, {});
    d.fillLists(sharedLists, ItemUse::kShared, 2, [&](size_t i, std::vector<std::byte>& b) {
      b = listOf(i, 3);
      ++computed;
    });
    resultLists.assign(nResult, {});
    d.fillLists(resultLists, ItemUse::kResult, 2, [&](size_t i, std::vector<std::byte>& b) {
      b = listOf(i, 4);
      ++computed;
    });
    shared.assign(nShared, 0);
    result.assign(nResult, 0);
    distributedFill(d, shared, ItemUse::kShared, 2, [&](size_t i, uint64_t& v) {
      v = valueOf(i, 1);
      ++computed;
    });
    distributedFill(d, result, ItemUse::kResult, 2, [&](size_t i, uint64_t& v) {
      v = valueOf(i, 2) + shared[i % shared.size()];  // reads the shared items
      ++computed;
    });
  }
};

PartIdentity identity() {
  PartIdentity id;
  id.caseFile = "/cases/office/case.toml";
  id.fingerprint = "0123456789abcdef";
  id.request = "{\"seed\":1}";
  id.version = "test";
  id.shards = 3;
  return id;
}

class Parts : public ::testing::Test {
 protected:
  void SetUp() override { root_ = createTemporaryFolder(fs::temp_directory_path(), "shard_test"); }
  void TearDown() override { fs::remove_all(root_); }
  // Runs the study as shard i of n into part folder i; returns the folders.
  std::vector<fs::path> shardRun(int n, size_t nShared, size_t nResult, PartIdentity id = identity()) {
    std::vector<fs::path> dirs;
    id.shards = n;
    for (int i = 0; i < n; ++i) {
      ShardDistribution d(ShardSpec{i, n});
      EXPECT_TRUE(d.partial());
      EXPECT_FALSE(d.writesOutputs()) << "a shard writes its part, never the result folder";
      Study s;
      s.run(d, nShared, nResult);
      // A shard computes the shared items in full and about 1/n of the others (two fills of each).
      EXPECT_GE(s.computed.load(), 2 * (nShared + nResult / n - shardChunkItems(nResult, n)));
      EXPECT_LE(s.computed.load(), 2 * (nShared + nResult / n + shardChunkItems(nResult, n)));
      const fs::path dir = root_ / ("part_" + std::to_string(i));
      fs::create_directories(dir);
      writePart(dir, id, ShardSpec{i, n}, d.fills());
      dirs.push_back(dir);
    }
    return dirs;
  }
  std::vector<PartHeader> headers(const std::vector<fs::path>& dirs) {
    std::vector<PartHeader> h;
    for (const fs::path& d : dirs) h.push_back(readPartHeader(d));
    return h;
  }
  fs::path root_;
};

TEST(ShardSpec, ParsesIndexOverCount) {
  const ShardSpec s = parseShard("2/5");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 5);
  for (const char* bad : {"", "3", "3/3", "-1/3", "1/0", "a/b", "1/3/4", "1 /3", "9999999/10000000"})
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
}

TEST_F(Parts, MergeGivesTheOneProcessItems) {
  for (const auto& [nShared, nResult] : {std::pair<size_t, size_t>{37, 1000}, {1, 2}, {500, 7}}) {
    Study one;
    one.run(localDistribution(), nShared, nResult);
    std::vector<PartHeader> set = checkPartSet(headers(shardRun(3, nShared, nResult)));
    const MergeDistribution merge(std::move(set));
    Study merged;
    merged.run(merge, nShared, nResult);
    EXPECT_EQ(merged.computed.load(), 0u) << "merge computes nothing again";
    EXPECT_EQ(merged.shared, one.shared);
    EXPECT_EQ(merged.result, one.result);
    EXPECT_EQ(merged.sharedLists, one.sharedLists);
    EXPECT_EQ(merged.resultLists, one.resultLists);
    EXPECT_NO_THROW(merge.finish());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
}

TEST_F(Parts, MergeRefusesFillsThatDoNotMatch) {
  const std::vector<fs::path> dirs = shardRun(3, 10, 100);
  {
    // The study asks for another item count: the parts are of another case.
    const MergeDistribution merge(checkPartSet(headers(dirs)));
    Study s;
    EXPECT_THROW(s.run(merge, 10, 101), InputError);
  }
  {
    // The study asks for fewer fills than the parts hold.
    const MergeDistribution merge(checkPartSet(headers(dirs)));
    std::vector<std::vector<std::byte>> a(10), b(100);
    merge.fillLists(a, ItemUse::kShared, 1, [](size_t, std::vector<std::byte>&) {});
    merge.fillLists(b, ItemUse::kResult, 1, [](size_t, std::vector<std::byte>&) {});
    std::vector<uint64_t> v(10);
    distributedFill(merge, v, ItemUse::kShared, 1, [](size_t, uint64_t&) {});
    EXPECT_THROW(merge.finish(), InputError);
    // ... or a fill of another kind.
    std::vector<uint64_t> x(100);
    EXPECT_THROW(distributedFill(merge, x, ItemUse::kShared, 1, [](size_t, uint64_t&) {}), InputError);
  }
}

TEST_F(Parts, SetMustBeCompleteAndOfOneRun) {
  const std::vector<fs::path> dirs = shardRun(3, 4, 50);
  try {
    checkPartSet(headers({dirs[0], dirs[2]}));
    FAIL() << "an incomplete set was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shard 1/3 missing"), std::string::npos) << e.what();
  }
  try {
    checkPartSet(headers({dirs[0], dirs[1], dirs[1], dirs[2]}));
    FAIL() << "a shard given twice was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shard 1 is given twice"), std::string::npos) << e.what();
  }
  // A part of the same case computed with another seed.
  PartIdentity other = identity();
  other.request = "{\"seed\":2}";
  ShardDistribution d(ShardSpec{1, 3});
  Study s;
  s.run(d, 4, 50);
  const fs::path foreign = root_ / "foreign";
  fs::create_directories(foreign);
  writePart(foreign, other, ShardSpec{1, 3}, d.fills());
  try {
    checkPartSet(headers({dirs[0], foreign, dirs[2]}));
    FAIL() << "a part of another run was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("settings or seed differ"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("foreign"), std::string::npos) << e.what();
  }
}

TEST_F(Parts, IncompleteOrMissingPartIsRefused) {
  const std::vector<fs::path> dirs = shardRun(2, 4, 50);
  // Cut the data short, as a copy interrupted half-way would.
  const fs::path data = dirs[1] / kPartData;
  fs::resize_file(data, fs::file_size(data) - 8);
  EXPECT_THROW(readPartHeader(dirs[1]), InputError);
  EXPECT_THROW(readPartHeader(root_ / "no_such_part"), InputError);
  std::ofstream(dirs[0] / kPartManifest) << "{ not json";
  EXPECT_THROW(readPartHeader(dirs[0]), InputError);
}

// fills.bin's fill headers: six uint64 (magic, items, itemBytes, chunk, use, data bytes).
struct RawFill {
  uint64_t offset;  // of the fill's data in fills.bin
  uint64_t h[6];
};
std::vector<RawFill> rawFills(const fs::path& data) {
  std::ifstream in(data, std::ios::binary);
  std::vector<RawFill> fills;
  RawFill f{};
  while (in.read(reinterpret_cast<char*>(f.h), sizeof f.h)) {
    f.offset = static_cast<uint64_t>(in.tellg());
    fills.push_back(f);
    in.seekg(static_cast<std::streamoff>(f.h[5]), std::ios::cur);
  }
  return fills;
}

void overwrite(const fs::path& file, uint64_t offset, const void* bytes, size_t n) {
  std::fstream f(file, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(static_cast<std::streamoff>(offset));
  f.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(n));
}

// part.json with `key` set to `value` (and the rest as written).
void setManifest(const fs::path& dir, const std::string& key, const nlohmann::json& value) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / kPartManifest));
  j[key] = value;
  std::ofstream(dir / kPartManifest, std::ios::trunc) << j.dump();
}

// part.json's checksum made to match fills.bin again, as a deliberate edit would.
void resealPart(const fs::path& dir) {
  const std::string data = [&] {
    std::ifstream in(dir / kPartData, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(data.data(), data.size())));
  setManifest(dir, "data_checksum", hex);
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(Parts, SameSizeDamageIsRefusedByTheChecksum) {
  const std::vector<fs::path> dirs = shardRun(2, 4, 50);
  EXPECT_NO_THROW(readPartHeader(dirs[1]));
  // One double of the data set to -1000: the size is unchanged (once merged into -179 000 lx).
  const std::vector<RawFill> fills = rawFills(dirs[1] / kPartData);
  ASSERT_FALSE(fills.empty());
  const RawFill& last = fills.back();
  ASSERT_GE(last.h[5], 8u);
  const double bad = -1000.0;
  overwrite(dirs[1] / kPartData, last.offset, &bad, sizeof bad);
  const std::string m = messageOf([&] { readPartHeader(dirs[1]); });
  EXPECT_NE(m.find("fills.bin: the part is damaged: fills.bin's checksum differs"), std::string::npos) << m;
  // A part without a checksum (an older format) is refused too.
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dirs[0] / kPartManifest));
  j.erase("data_checksum");
  std::ofstream(dirs[0] / kPartManifest, std::ios::trunc) << j.dump();
  EXPECT_THROW(readPartHeader(dirs[0]), InputError);
}

TEST_F(Parts, CountsInPartJsonAreBoundedBeforeUse) {
  const std::vector<fs::path> dirs = shardRun(2, 4, 50);
  // "shards": 20000000 once printed a 369 MB line naming every missing shard.
  setManifest(dirs[0], "shards", 20000000);
  std::string m = messageOf([&] { readPartHeader(dirs[0]); });
  EXPECT_NE(m.find("part.json: \"shards\" must be an integer from 1 to 999999"), std::string::npos) << m;
  EXPECT_LT(m.size(), 300u);
  for (const nlohmann::json& bad : {nlohmann::json(-1), nlohmann::json(2.5), nlohmann::json("2"),
                                    nlohmann::json(18446744073709551615ULL)}) {
    setManifest(dirs[0], "shards", bad);
    EXPECT_THROW(readPartHeader(dirs[0]), InputError) << bad;
  }
  setManifest(dirs[0], "shards", 2);
  setManifest(dirs[0], "fills", 1000000000);  // more fills than the data could hold
  EXPECT_THROW(readPartHeader(dirs[0]), InputError);
  // The most shards a part may name, one given: the message names 8 and counts the rest.
  setManifest(dirs[1], "shards", 999999);
  setManifest(dirs[1], "shard", 5);
  m = messageOf([&] { checkPartSet(headers({dirs[1]})); });
  EXPECT_NE(m.find("shard 0/999999, 1/999999, 2/999999, 3/999999, 4/999999, 6/999999, 7/999999, 8/999999 and "
                   "999990 more missing"),
            std::string::npos)
      << m;
  EXPECT_LT(m.size(), 400u);
}

TEST_F(Parts, ListSizesThatWrapAreRefusedBeforeAllocating) {
  const std::vector<fs::path> dirs = shardRun(1, 4, 50);
  // The first fill is the shared lists (4 sizes, then the bytes): make the first size huge and
  // the second wrap the sum back to the fill's size, then reseal the part.
  const std::vector<RawFill> fills = rawFills(dirs[0] / kPartData);
  ASSERT_EQ(fills[0].h[2], 0u) << "a fill of lists";
  uint64_t sizes[4];
  {
    std::ifstream in(dirs[0] / kPartData, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(fills[0].offset));
    in.read(reinterpret_cast<char*>(sizes), sizeof sizes);
  }
  sizes[0] += uint64_t(3) << 30;           // 3 GiB more ...
  sizes[1] -= uint64_t(3) << 30;           // ... and the sum wraps back
  overwrite(dirs[0] / kPartData, fills[0].offset, sizes, sizeof sizes);
  resealPart(dirs[0]);
  const MergeDistribution merge(checkPartSet(headers(dirs)));
  std::vector<std::vector<std::byte>> lists(4);
  const std::string m = messageOf(
      [&] { merge.fillLists(lists, ItemUse::kShared, 1, [](size_t, std::vector<std::byte>&) {}); });
  EXPECT_NE(m.find("is damaged or was computed from another case"), std::string::npos) << m;
  for (const auto& l : lists) EXPECT_LT(l.size(), 1000u);
}

}  // namespace
}  // namespace candela
