// How a study's results reach the disk, and when they were made.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace candela {

// The local time now, "YYYY-MM-DD HH:MM".
std::string localTimeNow();

// Creates `outDir` and calls write(); a file-system or write failure becomes InputError at
// outDir, "cannot write the results: ...". Each writer writes atomically, so a failure leaves no
// half file.
void writeRunOutputs(const std::filesystem::path& outDir, const std::function<void()>& write);

}  // namespace candela
