// `candela merge` in-process: shards of a small case whose scene includes a file (`!xform`), and
// what a merge must refuse (docs/distributed.md#faults): a file the scene reads that changed
// between the shards or since, a part damaged in place, a NaN in a part.
#include "study/run_case.h"
#include "study/distributed/shard_distribution.h"

#include "base/error.h"
#include "base/input_file.h"
#include "study/finite_results.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCase = R"(
[[scene]]
file = "main.rad"

[[grid]]
name = "floor"
corners = [[-1.0, -1.0], [1.0, 1.0]]
height = 0.5
spacing = 0.5

[settings]
quality = "draft"
)";

// A glow sky over a floor the main file includes: E = pi L at every sensor whatever the floor.
constexpr const char* kMain = R"(
void glow skyglow
0
0
4 10 10 10 0

skyglow source sky
0
0
4 0 0 1 180

!xform floor.rad
)";

std::string floorRad(double rho) {
  return "void plastic floor_mat\n0\n0\n5 " + std::to_string(rho) + " " + std::to_string(rho) + " " +
         std::to_string(rho) + " 0 0\n\nfloor_mat polygon floor\n0\n0\n12\n-10 -10 0\n10 -10 0\n10 10 0\n-10 10 0\n";
}

class MergeParts : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder per test: CTest runs the suite's tests as parallel processes, and one test's
    // SetUp must not remove another's case while it runs.
    root_ = fs::path(testing::TempDir()) / "merge_parts_test" /
            testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "case");
    write("case/case.toml", kCase);
    write("case/main.rad", kMain);
    write("case/floor.rad", floorRad(0.5));
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& name, const std::string& text) { std::ofstream(root_ / name) << text; }
  fs::path shard(int i, int n) {
    const ShardDistribution d(ShardSpec{i, n});
    RunRequest r;
    r.outDir = root_ / ("part_" + std::to_string(i));
    r.distribution = &d;
    r.trace.method = Method::kPath;
    runCase(root_ / "case/case.toml", r);
    return r.outDir;
  }
  std::string mergeError(const std::vector<fs::path>& parts) {
    try {
      mergeParts(parts, root_ / "out", 1);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path root_;
};

TEST_F(MergeParts, AnIncludedFileThatChangedIsRefused) {
  const fs::path a = shard(0, 2), b = shard(1, 2);
  // The parts record every file read, the included one too.
  EXPECT_EQ(mergeError({a, b}), "");
  EXPECT_TRUE(fs::exists(root_ / "out/floor.csv"));
  // The include changes after the shards ran: the merge refuses before writing.
  write("case/floor.rad", floorRad(0.2));
  const std::string m = mergeError({a, b});
  EXPECT_NE(m.find("or a file it reads"), std::string::npos) << m;
  EXPECT_NE(m.find("changed since the shards ran"), std::string::npos) << m;
  // ... and between the shards: shard 1 was traced against another floor than shard 0.
  fs::remove_all(root_ / "out");
  fs::remove_all(b);
  shard(1, 2);
  const std::string between = mergeError({a, b});
  EXPECT_NE(between.find("belongs to another run"), std::string::npos) << between;
  EXPECT_FALSE(fs::exists(root_ / "out"));
}

TEST_F(MergeParts, ANaNInAPartIsBadInputNotAnInternalError) {
  const fs::path a = shard(0, 2), b = shard(1, 2);
  // The first item of the grid's fill (IrradianceEstimate: irradiance first) set to NaN, and
  // part.json's checksum made to match, as a deliberate edit would.
  const fs::path data = b / kPartData;
  std::string bytes;
  {
    std::ifstream in(data, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  size_t at = 0;
  bool done = false;
  while (at + 48 <= bytes.size()) {
    uint64_t h[6];
    std::memcpy(h, bytes.data() + at, sizeof h);
    at += sizeof h;
    if (h[4] == 0 && h[2] == sizeof(IrradianceEstimate) && h[5] >= sizeof(double)) {
      const double nan = std::nan("");
      std::memcpy(bytes.data() + at, &nan, sizeof nan);
      done = true;
      break;
    }
    at += h[5];
  }
  ASSERT_TRUE(done) << "no grid fill in the part";
  std::ofstream(data, std::ios::binary | std::ios::trunc) << bytes;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(b / kPartManifest));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(bytes.data(), bytes.size())));
  j["data_checksum"] = hex;
  std::ofstream(b / kPartManifest, std::ios::trunc) << j.dump();
  std::string m;
  EXPECT_NO_THROW(m = mergeError({a, b})) << "not an internal error";
  EXPECT_NE(m.find("the parts hold a value that is not a number"), std::string::npos) << m;
  EXPECT_FALSE(fs::exists(root_ / "out"));
}

}  // namespace
}  // namespace candela
