// Outputs are written to a temporary file beside the target and renamed into place, so a failed
// run never leaves half a result.
#pragma once

#include <filesystem>
#include <string_view>

namespace candela {

// Writes `content` to `path` atomically (temporary file + rename). Throws std::runtime_error on
// an I/O failure; the target is then untouched.
void writeFileAtomic(const std::filesystem::path& path, std::string_view content);

}  // namespace candela
