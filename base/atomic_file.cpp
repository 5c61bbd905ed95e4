#include "base/atomic_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace candela {

namespace {

std::string randomHex() {
  uint64_t r = 0;
  if (::getrandom(&r, sizeof r, 0) != static_cast<ssize_t>(sizeof r))
    throw std::runtime_error(std::string("no random bytes for a temporary name: ") + std::strerror(errno));
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(r));
  return buf;
}

std::string errnoText() { return std::strerror(errno); }

}  // namespace

std::filesystem::path uniqueSibling(const std::filesystem::path& dir, const std::string& stem) {
  return dir / ("." + stem + "." + randomHex());
}

std::filesystem::path createTemporaryFolder(const std::filesystem::path& dir, const std::string& stem) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const std::filesystem::path p = uniqueSibling(dir, stem);
    if (::mkdir(p.c_str(), 0700) == 0) return p;
    if (errno != EEXIST) throw std::runtime_error("cannot create a folder in " + dir.string() + ": " + errnoText());
  }
  throw std::runtime_error("cannot create a unique folder in " + dir.string());
}

namespace {

// Unnamed temporaries (O_TMPFILE) need the file system's support and /proc to give them a name.
bool procFdAvailable() {
  static const bool ok = ::access("/proc/self/fd", X_OK) == 0;
  return ok;
}

}  // namespace

AtomicFile::AtomicFile(const std::filesystem::path& path) : path_(path) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (procFdAvailable()) {
    fd_ = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      unnamed_ = true;
      what_ = "a temporary for " + path.string();
      return;
    }
    // Not supported here (EOPNOTSUPP, EISDIR on old kernels): a named temporary instead; any
    // other failure (no such folder, no permission) is the named one's too.
  }
  for (int attempt = 0; attempt < 16 && fd_ < 0; ++attempt) {
    tmp_ = uniqueSibling(dir, path.filename().string() + ".tmp");
    // O_EXCL | O_NOFOLLOW: a name that exists (a planted link included) is never opened.
    fd_ = ::open(tmp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) throw std::runtime_error("cannot write " + tmp_.string() + ": " + errnoText());
  }
  if (fd_ < 0) throw std::runtime_error("cannot create a unique temporary beside " + path.string());
  what_ = tmp_.string();
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::write(std::string_view bytes) { writeAll(fd_, bytes, what_); }

void AtomicFile::commit() { commitAs(path_); }

void AtomicFile::commitAs(const std::filesystem::path& target) {
  if (fd_ < 0) throw std::runtime_error("cannot write " + target.string() + ": the file was committed already");
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  if (unnamed_) {
    // Give the unnamed file a fresh hidden name beside the target (linkat through /proc, which
    // needs no privilege), then rename that into place like a named temporary.
    const std::string self = "/proc/self/fd/" + std::to_string(fd_);
    for (int attempt = 0; attempt < 16 && tmp_.empty(); ++attempt) {
      const std::filesystem::path name = uniqueSibling(dir, target.filename().string() + ".tmp");
      if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) tmp_ = name;
      else if (errno != EEXIST)
        throw std::runtime_error("cannot write " + target.string() + ": " + errnoText());
    }
    if (tmp_.empty()) throw std::runtime_error("cannot create a unique temporary beside " + target.string());
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw std::runtime_error("cannot write " + tmp_.string() + ": " + errnoText());
  // rename() replaces a link at `target` by the file; it never follows it.
  if (::rename(tmp_.c_str(), target.c_str()) != 0)
    throw std::runtime_error("cannot rename into " + target.string() + ": " + errnoText());
  committed_ = true;
}

void writeFileAtomic(const std::filesystem::path& path, std::string_view content) {
  AtomicFile file(path);
  file.write(content);
  file.commit();
}

void writeAll(int fd, std::string_view content, const std::string& what) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write " + what + (n < 0 ? ": " + errnoText() : std::string()));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace candela
