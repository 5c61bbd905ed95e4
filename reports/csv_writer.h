// CSV outputs: one file per grid (the `candela points` columns plus extras) and summary.csv with
// one row per grid. Written atomically (engine/base/atomic_file.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "reports/report_data.h"

namespace candela {

// Header "x,y,z,dx,dy,dz,illuminance_lux[,extra...]" and one row per point (m, unit normal, lux).
// Throws std::invalid_argument when a column's length differs from the number of points.
std::string gridCsv(const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                    const std::vector<ExtraColumn>& extraColumns = {});

// Writes <dir>/<safeFileName(gridName)>.csv and returns its path; creates `dir` if needed.
std::filesystem::path writeGridCsv(const std::filesystem::path& dir, const std::string& gridName,
                                   const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                                   const std::vector<ExtraColumn>& extraColumns = {});

// summary.csv columns, in order (empty field = not applicable):
//   case,grid,unit,points,average,minimum,maximum,u0,ud,target_average,target_uniformity,
//   verdict_average,verdict_uniformity,verdict,seed,version,run_time_s,settings
// `settings` is "key=value;key=value". Fields are quoted as RFC 4180 when needed.
std::string summaryCsv(const SummaryData& data);

// Writes <dir>/summary.csv and returns its path.
std::filesystem::path writeSummaryCsv(const std::filesystem::path& dir, const SummaryData& data);

// One CSV field, quoted when it holds a comma, quote or line break (RFC 4180).
std::string csvField(const std::string& text);

}  // namespace candela
