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

void writeFileAtomic(const std::filesystem::path& path, std::string_view content) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::filesystem::path tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
    tmp = uniqueSibling(dir, path.filename().string() + ".tmp");
    // O_EXCL | O_NOFOLLOW: a name that exists (a planted link included) is never opened.
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) throw std::runtime_error("cannot write " + tmp.string() + ": " + errnoText());
  }
  if (fd < 0) throw std::runtime_error("cannot create a unique temporary beside " + path.string());
  try {
    writeAll(fd, content, tmp.string());
  } catch (const std::runtime_error&) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const std::string why = errnoText();
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + tmp.string() + ": " + why);
  }
  // rename() replaces a link at `path` by the file; it never follows it.
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = errnoText();
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot rename into " + path.string() + ": " + reason);
  }
}

int createFileExclusive(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error("cannot create " + path.string() + ": " + errnoText());
  return fd;
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
