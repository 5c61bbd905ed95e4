// Outputs are written to a temporary file beside the target and renamed into place, so a failed
// run never leaves half a result. Temporaries are created exclusively under an unpredictable
// name and never through a link, so a link planted in a shared output folder cannot redirect a
// write (docs/reliability.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace candela {

// A file written piece by piece and put in place by commit(): the writes go to a temporary in
// `path`'s folder, an unnamed one (O_TMPFILE) where the file system has them, so that a process
// killed before commit leaves nothing behind, else an exclusive hidden name (never through a
// link). Destroyed before commit, or when commit fails, the temporary is removed and `path` is
// untouched. For outputs too large to assemble in memory, and for files finished before the
// folder they go into exists (commitAs).
class AtomicFile {
 public:
  explicit AtomicFile(const std::filesystem::path& path);  // throws std::runtime_error
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  // Appends at the file offset (writeAll); throws std::runtime_error.
  void write(std::string_view bytes);
  // The temporary's descriptor, open for reading and writing, for writers that seek or read
  // back (until commit).
  int descriptor() const { return fd_; }
  // Closes the temporary and renames it to `path`; throws std::runtime_error.
  void commit();
  // The same, to `target` instead: a path in the same file system as `path`'s folder.
  void commitAs(const std::filesystem::path& target);

 private:
  std::filesystem::path path_, tmp_;
  std::string what_;  // the temporary as write errors name it
  int fd_ = -1;
  bool unnamed_ = false;
  bool committed_ = false;
};

// Writes `content` to `path` atomically (exclusive temporary + rename). Throws
// std::runtime_error on an I/O failure; the target is then untouched. A symbolic link at `path`
// is replaced by the file, never written through.
void writeFileAtomic(const std::filesystem::path& path, std::string_view content);

// A fresh name `<dir>/.<stem>.<random hex>` that did not exist a moment ago (for temporaries
// created exclusively by the caller).
std::filesystem::path uniqueSibling(const std::filesystem::path& dir, const std::string& stem);

// Creates a new folder `<dir>/.<stem>.<random hex>` (mode 0700 until committed, as mkdtemp) and
// returns it. Throws std::runtime_error.
std::filesystem::path createTemporaryFolder(const std::filesystem::path& dir, const std::string& stem);

// Writes every byte of `content` to `fd` (short writes and EINTR retried). Throws
// std::runtime_error naming `what` on a failure (a full disk, say).
void writeAll(int fd, std::string_view content, const std::string& what);

}  // namespace candela
