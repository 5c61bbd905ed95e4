#include "cli/resource_options.h"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace candela::cli {

uint64_t parseMemorySize(const std::string& text) {
  const std::string bad = "--max-memory wants a size such as 8G, 512M or a number of GiB, got '" + text + "'";
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument(bad);
  }
  if (!std::isdigit(static_cast<unsigned char>(text[0])) && text[0] != '.') throw std::invalid_argument(bad);
  std::string unit = text.substr(used);
  for (char& ch : unit) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  double scale = 0.0;
  const std::string letter = unit.substr(0, 1), rest = unit.empty() ? "" : unit.substr(1);
  if (unit.empty()) scale = 1024.0 * 1024 * 1024;
  else if (rest.empty() || rest == "B" || rest == "IB") {
    if (letter == "K") scale = 1024.0;
    else if (letter == "M") scale = 1024.0 * 1024;
    else if (letter == "G") scale = 1024.0 * 1024 * 1024;
    else if (letter == "T") scale = 1024.0 * 1024 * 1024 * 1024;
    else if (letter == "B" && rest.empty()) scale = 1.0;
  }
  const double bytes = value * scale;
  if (!(scale > 0.0) || !(bytes >= 1.0) || !(bytes < 1.8e19)) throw std::invalid_argument(bad);
  return static_cast<uint64_t>(bytes);
}

uint64_t availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(size) : 0;
}

ResourceLimits ResourceOptions::limits() const {
  ResourceLimits l;
  l.maxMemoryBytes = maxMemory.empty() ? availableMemoryBytes() : parseMemorySize(maxMemory);
  return l;
}

void addResourceOptions(CLI::App* cmd, ResourceOptions& o) {
  cmd->add_option("--max-memory", o.maxMemory,
                  "refuse a case that needs more memory than SIZE: 8G, 512M, 1.5GiB or a number of GiB "
                  "(default: the machine's available memory)")
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            try {
              parseMemorySize(s);
              return {};
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
          },
          "SIZE"));
}

}  // namespace candela::cli
