// Atomic writes: exclusive temporaries with unpredictable names, never through a link.
#include "base/atomic_file.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test_support::scratchDir("candela_atomic_file", name); }

using test_support::slurp;

TEST(AtomicFile, WritesTheContentAndLeavesNoTemporary) {
  const fs::path d = scratch("plain");
  writeFileAtomic(d / "summary.csv", "a,b\n1,2\n");
  EXPECT_EQ(slurp(d / "summary.csv"), "a,b\n1,2\n");
  int files = 0;
  for (const auto& e : fs::directory_iterator(d)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, APlantedLinkIsReplacedNotFollowed) {
  const fs::path d = scratch("link");
  const fs::path victim = d / "victim.txt";
  std::ofstream(victim) << "precious";
  // The old scheme's predictable temporary name, and the target itself, as links to the victim.
  fs::create_symlink(victim, d / (".summary.csv.tmp" + std::to_string(::getpid())));
  fs::create_symlink(victim, d / "summary.csv");
  writeFileAtomic(d / "summary.csv", "new");
  EXPECT_EQ(slurp(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(d / "summary.csv"));
  EXPECT_EQ(slurp(d / "summary.csv"), "new");
}

TEST(AtomicFile, TemporaryNamesAreUnpredictable) {
  const fs::path d = scratch("names");
  EXPECT_NE(uniqueSibling(d, "x"), uniqueSibling(d, "x"));
  const fs::path a = createTemporaryFolder(d, "out.tmp"), b = createTemporaryFolder(d, "out.tmp");
  EXPECT_NE(a, b);
  EXPECT_TRUE(fs::is_directory(a));
  EXPECT_EQ(a.parent_path(), d);
}

TEST(AtomicFile, FailureLeavesTheTargetUntouched) {
  const fs::path d = scratch("fail");
  std::ofstream(d / "report.html") << "old";
  // A folder where the file should go: the rename fails (even as root), the folder and the
  // neighbouring file stay as they were, and no temporary is left behind.
  fs::create_directories(d / "report_dir.html");
  EXPECT_THROW(writeFileAtomic(d / "report_dir.html", "new"), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(d / "report_dir.html"));
  EXPECT_EQ(slurp(d / "report.html"), "old");
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "temporary left: " << e.path();
}

}  // namespace
}  // namespace candela
