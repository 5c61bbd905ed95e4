// --max-memory, shared by run, points and render: the memory a case may need before it is
// refused up front (study/resource_estimate.h; docs/reliability.md, "Resource bounds").
#pragma once

#include "study/resource_estimate.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace candela::cli {

struct ResourceOptions {
  std::string maxMemory;  // empty: the machine's available memory
  // The limit in bytes: --max-memory, else availableMemoryBytes() (0 when that is unknown: no check).
  ResourceLimits limits() const;
};

// Adds --max-memory SIZE.
void addResourceOptions(CLI::App* cmd, ResourceOptions& o);

// "8G", "512M", "1.5GiB", "2048K", "100MB" (binary units: K = 1024 bytes, M = 1024², G = 1024³,
// T = 1024⁴; an optional "B" or "iB" after the letter) or a plain number of GiB ("4" = 4 GiB).
// Throws std::invalid_argument for anything else, zero or a negative size.
uint64_t parseMemorySize(const std::string& text);

// MemAvailable of /proc/meminfo (memory the kernel can give without swapping), else the free
// physical pages (sysconf); 0 when neither is known.
uint64_t availableMemoryBytes();

}  // namespace candela::cli
