// Outputs are written to a temporary file beside the target and renamed into place, so a failed
// run never leaves half a result. Temporaries are created exclusively under an unpredictable
// name and never through a link, so a link planted in a shared output folder cannot redirect a
// write (docs/reliability.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace candela {

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

// Creates `path` for reading and writing; it must not exist (O_EXCL | O_NOFOLLOW: an existing
// name, a planted link included, is refused). For a file written piece by piece inside a fresh
// temporary folder (createTemporaryFolder) and committed with the folder, where a rename per
// file would buy nothing. Returns the descriptor; throws std::runtime_error.
int createFileExclusive(const std::filesystem::path& path);

// Writes every byte of `content` to `fd` (short writes and EINTR retried). Throws
// std::runtime_error naming `what` on a failure (a full disk, say).
void writeAll(int fd, std::string_view content, const std::string& what);

}  // namespace candela
