// Radiance's own test scenes (its test/renders folder, "the peer suite") are not copied into this
// repository: the tests that read them find the folder through the environment variable
// CANDELA_PEER_SUITE. Their test suites' names end in "PeerSuite", which is how CMake gives them the
// CTest label needs-peer-suite (tests/CMakeLists.txt). Without the setting such a test reports one
// line, "peer suite not run: set CANDELA_PEER_SUITE", and is skipped (it passes); with CI=true it
// fails instead, and a setting that names no folder fails everywhere.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace candela::test_support {

inline constexpr const char* kPeerSuiteNotRun = "peer suite not run: set CANDELA_PEER_SUITE";

// The folder CANDELA_PEER_SUITE names; empty when it is not set.
inline std::filesystem::path peerSuiteSetting() {
  const char* dir = std::getenv("CANDELA_PEER_SUITE");
  return dir ? std::filesystem::path(dir) : std::filesystem::path();
}

// CI=true: every test must run, the peer suite's too.
inline bool peerSuiteRequired() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace candela::test_support

// In a test body: declares `dir`, the peer suite's folder, or ends the test (skipped with one line
// when the setting is absent outside CI; failed on CI or when the setting names no folder).
#define CANDELA_PEER_SUITE_DIR(dir)                                                                    \
  const std::filesystem::path dir = ::candela::test_support::peerSuiteSetting();                       \
  if (dir.empty() && ::candela::test_support::peerSuiteRequired())                                     \
    FAIL() << "CI=true, so the peer suite must run: set CANDELA_PEER_SUITE to Radiance's test/renders"; \
  if (dir.empty()) GTEST_SKIP() << ::candela::test_support::kPeerSuiteNotRun;                          \
  if (!std::filesystem::is_directory(dir)) FAIL() << "CANDELA_PEER_SUITE=" << dir.string() << " is not a folder"
