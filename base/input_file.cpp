#include "base/input_file.h"

#include "base/error.h"

#include <algorithm>
#include <cerrno>
#include <map>
#include <mutex>
#include <set>
#include <vector>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace candela {

namespace {

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a regular file";
}

// Closes the descriptor when the reading ends, however it ends.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Opens `path` for reading without blocking on a FIFO, and checks that it is a regular file.
Fd openRegular(const std::filesystem::path& path, const std::string& what, struct stat& st) {
  const FileLoc at{path.string(), 0, 0};
  Fd f;
  f.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (f.fd < 0) throw InputError(at, "cannot open " + what + " (" + std::strerror(errno) + ")");
  if (::fstat(f.fd, &st) != 0) throw InputError(at, "cannot read " + what + " (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw InputError(at, "the " + what + " is " + kindOf(st.st_mode) + ", not a regular file");
  return f;
}

}  // namespace

uint64_t fnv1a(const void* bytes, size_t n, uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(bytes);
  for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
  return h;
}

struct InputFileLog::State {
  std::map<std::string, std::set<uint64_t>> reads;  // absolute path -> hashes of what was read
};

namespace {
// The logs alive: a record of reads, never consulted by a reader (it changes no result).
std::mutex logsMutex;
std::vector<InputFileLog::State*>& liveLogs() {
  static std::vector<InputFileLog::State*> logs;
  return logs;
}
}  // namespace

InputFileLog::InputFileLog() : state_(new State) {
  const std::lock_guard<std::mutex> lock(logsMutex);
  liveLogs().push_back(state_);
}

InputFileLog::~InputFileLog() {
  {
    const std::lock_guard<std::mutex> lock(logsMutex);
    auto& logs = liveLogs();
    logs.erase(std::find(logs.begin(), logs.end(), state_));
  }
  delete state_;
}

void InputFileLog::record(const std::filesystem::path& path, const std::string& content) {
  std::error_code ec;
  std::filesystem::path full = std::filesystem::absolute(path, ec);
  if (ec) full = path;
  const std::string name = full.lexically_normal().string();
  const uint64_t h = fnv1a(content.data(), content.size());
  const std::lock_guard<std::mutex> lock(logsMutex);
  for (State* s : liveLogs()) s->reads[name].insert(h);
}

uint64_t InputFileLog::fingerprint() const {
  const std::lock_guard<std::mutex> lock(logsMutex);
  uint64_t h = fnv1a("", 0);
  for (const auto& [name, hashes] : state_->reads) {
    h = fnv1a(name.data(), name.size() + 1, h);
    for (const uint64_t c : hashes) h = fnv1a(&c, sizeof c, h);
  }
  return h;
}

size_t InputFileLog::files() const {
  const std::lock_guard<std::mutex> lock(logsMutex);
  return state_->reads.size();
}

std::string normalizeText(std::string text) {
  std::size_t start = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;
  if (start == 0 && text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size() - start);
  for (std::size_t i = start; i < text.size(); ++i) {
    if (text[i] != '\r') {
      out += text[i];
    } else {
      out += '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;  // CRLF is one line end
    }
  }
  return out;
}

std::string readInputFile(const std::filesystem::path& path, const std::string& what, std::uintmax_t maxBytes) {
  const FileLoc at{path.string(), 0, 0};
  struct stat st {};
  const Fd f = openRegular(path, what, st);
  const std::uintmax_t size = static_cast<std::uintmax_t>(st.st_size);
  if (size > maxBytes)
    throw InputError(at, "the " + what + " has " + std::to_string(size) + " bytes, more than the " +
                             std::to_string(maxBytes) + " candela reads");
  std::string out(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n = ::read(f.fd, out.data() + got, out.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(at, "cannot read " + what + " (" + std::strerror(errno) + ")");
    if (n == 0) break;  // the file shrank while being read: what is there is the content
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);
  std::string text = normalizeText(std::move(out));
  InputFileLog::record(path, text);
  return text;
}

void checkInputFile(const std::filesystem::path& path, const std::string& what) {
  struct stat st {};
  openRegular(path, what, st);
}

void checkOutputFile(const std::filesystem::path& path) {
  const FileLoc at{path.string(), 0, 0};
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) throw InputError(at, "the output is a symbolic link; candela does not write through links");
    if (!S_ISREG(st.st_mode)) throw InputError(at, "the output is " + kindOf(st.st_mode) + "; only a regular file is replaced");
    return;
  }
  if (errno != ENOENT) throw InputError(at, std::string("cannot write the output (") + std::strerror(errno) + ")");
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw InputError(at, "the output's folder " + dir.string() + " does not exist");
}

}  // namespace candela
