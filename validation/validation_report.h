// The outputs of a validation run: the table printed on stdout (the worst point of each case),
// validation.csv (every point) and validation.html.
#pragma once

#include "validation/case_registry.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::validation {

// The table, one row per case and a closing "N cases: P passed, F failed" line.
std::string validationTable(const std::vector<CaseResult>& results);

// validation.csv: one row per point.
std::string validationCsv(const std::vector<CaseResult>& results);

// Creates `dir` (and its parents) if needed; InputError (exit 2) when it cannot be a folder.
void prepareOutputFolder(const std::filesystem::path& dir);

// Writes validation.csv and validation.html into `dir` (created if needed), each atomically. The
// page embeds the speed–accuracy chart when `candela validate --chart` has left one in `dir`.
void writeValidationOutputs(const std::filesystem::path& dir, const std::vector<CaseResult>& results,
                            const std::string& quality, uint64_t seed);

// Cases that failed.
int failedCases(const std::vector<CaseResult>& results);

}  // namespace candela::validation
