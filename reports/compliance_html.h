// The report's compliance section (docs/compliance.md, docs/reports.md): per [[compliance]]
// entry its verdict and what decided it, then the tables of each part. Part of report.html
// (reports/html_report.h), whose stylesheet styles it.
#pragma once

#include "reports/compliance_report.h"

#include <string>
#include <vector>

namespace candela {

// "" without entries.
std::string complianceHtml(const std::vector<ComplianceReport>& entries);

}  // namespace candela
