// The validation page: one self-contained HTML file with every case's verdict, errors and time,
// its points, and the speed–accuracy chart when one was made (docs/validation.md).
#pragma once

#include "validation/case_registry.h"

#include <string>
#include <vector>

namespace candela::validation {

struct ValidationPage {
  std::string quality;        // "normal", ...
  uint64_t seed = 1;
  std::string version;        // candela version
  std::string chartSvg;       // inline SVG of the speed–accuracy chart, or empty
};

std::string validationHtml(const std::vector<CaseResult>& results, const ValidationPage& page);

}  // namespace candela::validation
