// Files for tests: a fresh scratch folder under gtest's temporary directory, and a file's text.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace candela::test_support {

// An empty folder <TempDir>/<group>/<name>, created anew.
inline std::filesystem::path scratchDir(const std::string& group, const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(testing::TempDir()) / group / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The whole content of a file ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace candela::test_support
