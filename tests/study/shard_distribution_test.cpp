#include "study/shard_distribution.h"

#include "base/atomic_file.h"
#include "base/error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
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

}  // namespace
}  // namespace candela
