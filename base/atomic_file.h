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

}  // namespace candela
