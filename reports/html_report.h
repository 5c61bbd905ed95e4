// One self-contained HTML report (inline CSS and SVG, no external resources; opens offline and
// prints): case, summary of verdicts, a plan and metrics table per grid, settings and timing.
#pragma once

#include <filesystem>
#include <string>

#include "reports/report_data.h"

namespace candela {

std::string htmlReport(const ReportData& data);

// Writes the report atomically; creates the parent folder if needed.
void writeHtmlReport(const std::filesystem::path& path, const ReportData& data);

}  // namespace candela
