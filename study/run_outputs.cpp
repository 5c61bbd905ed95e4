#include "study/run_outputs.h"

#include "base/atomic_file.h"
#include "base/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <stdexcept>
#include <system_error>

namespace candela {

namespace fs = std::filesystem;

std::string localTimeNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &tm);
  return buf;
}

namespace {

bool holdsResult(const fs::path& dir) {
  std::error_code ec;
  if (fs::is_empty(dir, ec)) return true;
  // A marker, or the summary every candela result has (folders written before the marker).
  return fs::is_regular_file(fs::symlink_status(dir / kResultMarker, ec)) ||
         fs::is_regular_file(fs::symlink_status(dir / "summary.json", ec));
}

// Puts `fresh` where `target` is, in one rename; returns where the previous target now is (empty
// when there was none).
fs::path swapInto(const fs::path& fresh, const fs::path& target) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(target, ec))) {
    if (::rename(fresh.c_str(), target.c_str()) != 0)
      throw std::runtime_error(std::string("cannot rename the results into place: ") + std::strerror(errno));
    return {};
  }
  if (::renameat2(AT_FDCWD, fresh.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) return fresh;
  if (errno != EINVAL && errno != ENOSYS)
    throw std::runtime_error(std::string("cannot swap the results into place: ") + std::strerror(errno));
  // No atomic exchange on this file system: two renames, the target missing in between.
  const fs::path old = uniqueSibling(target.parent_path().empty() ? fs::path(".") : target.parent_path(),
                                     target.filename().string() + ".old");
  if (::rename(target.c_str(), old.c_str()) != 0 || ::rename(fresh.c_str(), target.c_str()) != 0)
    throw std::runtime_error(std::string("cannot rename the results into place: ") + std::strerror(errno));
  return old;
}

}  // namespace

void checkResultFolder(const fs::path& outDir) {
  const FileLoc at{outDir.string(), 0, 0};
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(outDir, ec);
  if (fs::is_symlink(st)) throw InputError(at, "the output folder is a symbolic link; name the folder itself");
  if (fs::exists(st) && !fs::is_directory(st)) throw InputError(at, "output path exists and is not a folder");
  if (fs::is_directory(st) && !holdsResult(outDir))
    throw InputError(at, "the output folder holds files that are not a candela result; a run replaces its folder "
                         "whole, so name a new or empty folder");
}

namespace {

[[noreturn]] void cannotWrite(const fs::path& outDir, const std::exception& e) {
  throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the results: ") + e.what());
}

}  // namespace

RunOutputFolder::RunOutputFolder(const fs::path& outDir, bool active) : outDir_(outDir), active_(active) {
  if (!active_) return;
  checkResultFolder(outDir);
  guard([&] {
    parent_ = outDir.has_parent_path() ? outDir.parent_path() : fs::path(".");
    fs::create_directories(parent_);
  });
}

RunOutputFolder::~RunOutputFolder() {
  std::error_code ec;
  if (!tmp_.empty()) fs::remove_all(tmp_, ec);
}

void RunOutputFolder::guard(const std::function<void()>& work) const {
  if (!active_) return;
  try {
    work();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    cannotWrite(outDir_, e);
  }
}

const fs::path& RunOutputFolder::folder() {
  if (tmp_.empty()) tmp_ = createTemporaryFolder(parent_, outDir_.filename().string() + ".tmp");
  return tmp_;
}

void RunOutputFolder::write(const std::function<void(const fs::path&)>& write) {
  guard([&] { write(folder()); });
}

void RunOutputFolder::commit() {
  guard([&] {
    const fs::path dir = folder();  // made here should nothing have been written into it
    writeFileAtomic(dir / kResultMarker, "candela " CANDELA_VERSION " result folder\n");
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    const fs::path old = swapInto(dir, outDir_);
    tmp_.clear();
    std::error_code ec;
    if (!old.empty()) fs::remove_all(old, ec);
  });
}

void writeRunOutputs(const fs::path& outDir, const std::function<void(const fs::path&)>& write) {
  RunOutputFolder folder(outDir);
  folder.write(write);
  folder.commit();
}

}  // namespace candela
