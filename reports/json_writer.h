// summary.json: the content of summary.csv as structured data (nlohmann-json), for scripts.
#pragma once

#include <filesystem>
#include <string>

#include "reports/report_data.h"

namespace candela {

// {
//   "case": {"name", "description", "file"}, "version", "started_at", "seed", "run_time_s",
//   "settings": {key: value, ...},
//   "grids": [{"name", "description", "quantity", "unit", "points", "average", "minimum",
//              "maximum", "u0", "ud", "target_average", "target_uniformity" (null if unset),
//              "verdict_average", "verdict_uniformity", "verdict"}]
// }
// Values are in each grid's unit (lux, or % for daylight-factor grids); verdicts "pass",
// "fail" or "n/a".
std::string summaryJson(const SummaryData& data);

// Writes <dir>/summary.json and returns its path.
std::filesystem::path writeSummaryJson(const std::filesystem::path& dir, const SummaryData& data);

// summary.csv and summary.json together.
void writeSummary(const std::filesystem::path& dir, const SummaryData& data);

}  // namespace candela
