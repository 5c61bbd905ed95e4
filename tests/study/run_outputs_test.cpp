// A result folder holds the complete previous result or the complete new one, never a mix.
#include "study/run_outputs.h"

#include "base/atomic_file.h"
#include "base/error.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test_support::scratchDir("candela_run_outputs", name); }

using test_support::slurp;

// Everything in `parent` but `keep`: temporaries left behind would show here.
std::vector<std::string> strays(const fs::path& parent, const std::string& keep) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(parent))
    if (e.path().filename() != keep) out.push_back(e.path().filename().string());
  return out;
}

TEST(RunOutputs, NewResultIsMarkedAndComplete) {
  const fs::path out = scratch("new") / "out";
  writeRunOutputs(out, [](const fs::path& dir) {
    writeFileAtomic(dir / "summary.json", "{\"seed\": 1}\n");
    writeFileAtomic(dir / "a.csv", "x\n");
  });
  EXPECT_EQ(slurp(out / "summary.json"), "{\"seed\": 1}\n");
  EXPECT_TRUE(fs::exists(out / kResultMarker));
  EXPECT_TRUE(strays(out.parent_path(), "out").empty());
}

TEST(RunOutputs, ANewResultReplacesTheOldOneWhole) {
  const fs::path out = scratch("replace") / "out";
  writeRunOutputs(out, [](const fs::path& dir) {
    writeFileAtomic(dir / "summary.json", "seed 1");
    writeFileAtomic(dir / "old_grid.csv", "seed 1");
  });
  writeRunOutputs(out, [](const fs::path& dir) { writeFileAtomic(dir / "summary.json", "seed 2"); });
  EXPECT_EQ(slurp(out / "summary.json"), "seed 2");
  EXPECT_FALSE(fs::exists(out / "old_grid.csv"));  // no seed-1 file beside the seed-2 summary
  EXPECT_TRUE(strays(out.parent_path(), "out").empty());
}

TEST(RunOutputs, AFailedWriteLeavesThePreviousResult) {
  const fs::path out = scratch("fail") / "out";
  writeRunOutputs(out, [](const fs::path& dir) {
    writeFileAtomic(dir / "summary.json", "seed 1");
    writeFileAtomic(dir / "report.html", "seed 1");
  });
  // The second run writes its summary, then its report fails (a folder in the way).
  EXPECT_THROW(writeRunOutputs(out,
                               [](const fs::path& dir) {
                                 writeFileAtomic(dir / "summary.json", "seed 2");
                                 fs::create_directories(dir / "report.html");
                                 writeFileAtomic(dir / "report.html", "seed 2");
                               }),
               InputError);
  EXPECT_EQ(slurp(out / "summary.json"), "seed 1");
  EXPECT_EQ(slurp(out / "report.html"), "seed 1");
  EXPECT_TRUE(strays(out.parent_path(), "out").empty());
}

TEST(RunOutputs, AFolderOfOtherFilesIsRefused) {
  const fs::path out = scratch("foreign") / "documents";
  fs::create_directories(out);
  std::ofstream(out / "thesis.tex") << "years of work";
  EXPECT_THROW(checkResultFolder(out), InputError);
  EXPECT_THROW(writeRunOutputs(out, [](const fs::path&) {}), InputError);
  EXPECT_EQ(slurp(out / "thesis.tex"), "years of work");
  fs::create_symlink(out, out.parent_path() / "link");
  EXPECT_THROW(checkResultFolder(out.parent_path() / "link"), InputError);
  EXPECT_NO_THROW(checkResultFolder(out.parent_path() / "fresh"));
}

// A study that streams (the annual one): its files are unnamed temporaries beside the result
// until the end, and the result folder itself appears only when written into, so a run that
// stops midway leaves nothing; once committed, the streamed file is in the result.
TEST(RunOutputs, AStreamingRunLeavesNothingUntilItIsCommitted) {
  const fs::path parent = scratch("streaming");
  const fs::path out = parent / "out";
  {
    RunOutputFolder folder(out);
    EXPECT_EQ(folder.beside(), parent);
    AtomicFile streamed(folder.beside() / "hourly.f32");
    streamed.write("rows");
    EXPECT_FALSE(fs::exists(parent / "hourly.f32"));  // unnamed, or else a hidden exclusive name
    EXPECT_FALSE(fs::exists(out));                      // no folder before the first write
  }  // a failed run: nothing made
  EXPECT_TRUE(fs::is_empty(parent));
  {
    RunOutputFolder folder(out);
    auto streamed = std::make_unique<AtomicFile>(folder.beside() / "hourly.f32");
    streamed->write("rows");
    folder.write([&](const fs::path& dir) {
      streamed->commitAs(dir / "hourly.f32");
      writeFileAtomic(dir / "summary.json", "{}\n");
    });
    EXPECT_FALSE(fs::exists(out));  // not before commit
    folder.commit();
  }
  EXPECT_EQ(slurp(out / "hourly.f32"), "rows");
  EXPECT_TRUE(fs::exists(out / kResultMarker));
  EXPECT_TRUE(strays(parent, "out").empty());
}

}  // namespace
}  // namespace candela
