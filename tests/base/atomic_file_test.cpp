// Atomic writes: exclusive temporaries with unpredictable names, never through a link.
#include "base/atomic_file.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
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

std::size_t entries(const fs::path& d) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++n;
  return n;
}

// Whether `d`'s file system has unnamed temporaries (O_TMPFILE): AtomicFile uses them where it
// can, else a hidden exclusive name.
bool unnamedTemporaries(const fs::path& d) {
  const int fd = ::open(d.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  ::close(fd);
  return ::access("/proc/self/fd", X_OK) == 0;
}

// A file written piece by piece shows nothing in its folder until committed where the file
// system has unnamed temporaries (else one hidden temporary), and can be committed into a folder
// made after it was written.
TEST(AtomicFile, PiecesThenCommitIntoAFolderMadeLater) {
  const fs::path d = scratch("pieces");
  AtomicFile f(d / "view.exr");
  f.write("abc");
  f.write("def");
  EXPECT_EQ(entries(d), unnamedTemporaries(d) ? 0u : 1u);
  fs::create_directories(d / "later");
  f.commitAs(d / "later" / "view.exr");
  EXPECT_EQ(slurp(d / "later" / "view.exr"), "abcdef");
  EXPECT_EQ(entries(d), 1u);  // the folder only
  EXPECT_THROW(f.commit(), std::runtime_error);  // once only
}

// Destroyed before commit, or its process killed: nothing is left.
TEST(AtomicFile, UncommittedLeavesNothingEvenWhenKilled) {
  const fs::path d = scratch("killed");
  { AtomicFile f(d / "a.png"); f.write("x"); }
  EXPECT_EQ(entries(d), 0u);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    AtomicFile f(d / "b.png");
    f.write(std::string(1 << 20, 'x'));
    ::kill(::getpid(), SIGKILL);  // no destructor runs
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  // Without unnamed temporaries a kill leaves the hidden one (docs/reliability.md).
  EXPECT_EQ(entries(d), unnamedTemporaries(d) ? 0u : 1u);
}

}  // namespace
}  // namespace candela
