// Inputs are read only from regular files, within a size bound, and every failure is an
// InputError naming the file.
#include "base/input_file.h"

#include "base/error.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test_support::scratchDir("candela_input_file", name); }

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(InputFile, ReadsARegularFile) {
  const fs::path f = scratch("regular") / "a.rad";
  std::ofstream(f) << "void plastic m 0 0 5 1 1 1 0 0\n";
  EXPECT_EQ(readInputFile(f, "scene file"), "void plastic m 0 0 5 1 1 1 0 0\n");
}

TEST(InputFile, RefusesFoldersFifosAndDevices) {
  const fs::path d = scratch("kinds");
  const fs::path fifo = d / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A FIFO would block the run forever; the reader must not even wait for a writer.
  EXPECT_NE(errorOf([&] { readInputFile(fifo, "scene file"); }).find("is a FIFO, not a regular file"), std::string::npos);
  EXPECT_NE(errorOf([&] { readInputFile(d, "points file"); }).find("is a folder"), std::string::npos);
  EXPECT_NE(errorOf([&] { readInputFile("/dev/zero", "scene file"); }).find("/dev/zero: the scene file is a device"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { checkInputFile(d / "missing.rad", "scene file"); }).find("cannot open scene file"),
            std::string::npos);
}

TEST(InputFile, RefusesFilesAboveTheBound) {
  const fs::path f = scratch("big") / "big.tlt";
  std::ofstream(f) << std::string(2048, 'x');
  EXPECT_NE(errorOf([&] { readInputFile(f, "TILT file", 1024); }).find("has 2048 bytes, more than the 1024"),
            std::string::npos);
  EXPECT_EQ(readInputFile(f, "TILT file", 2048).size(), 2048u);
}

TEST(OutputFile, OnlyRegularFilesOrNewNames) {
  const fs::path d = scratch("outputs");
  EXPECT_NO_THROW(checkOutputFile(d / "new.svg"));
  std::ofstream(d / "old.svg") << "x";
  EXPECT_NO_THROW(checkOutputFile(d / "old.svg"));
  fs::create_symlink(d / "old.svg", d / "link.svg");
  EXPECT_NE(errorOf([&] { checkOutputFile(d / "link.svg"); }).find("symbolic link"), std::string::npos);
  EXPECT_NE(errorOf([&] { checkOutputFile("/dev/null"); }).find("is a device"), std::string::npos);
  EXPECT_NE(errorOf([&] { checkOutputFile(d); }).find("is a folder"), std::string::npos);
  EXPECT_NE(errorOf([&] { checkOutputFile(d / "no_such_dir" / "x.svg"); }).find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

TEST(InputFile, TextIsNormalised) {
  EXPECT_EQ(normalizeText("\xEF\xBB\xBF" "a\r\nb\rc\n"), "a\nb\nc\n");  // BOM, CRLF and a lone CR
  EXPECT_EQ(normalizeText("plain\nlines\n"), "plain\nlines\n");
  EXPECT_EQ(normalizeText("\r\r\n"), "\n\n");
  EXPECT_EQ(normalizeText("caf\xC3\xA9"), "caf\xC3\xA9");
}

}  // namespace
}  // namespace candela
