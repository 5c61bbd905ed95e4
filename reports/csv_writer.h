// CSV outputs: one file per grid (the `candela points` columns plus extras) and summary.csv with
// one row per grid. Written atomically (base/atomic_file.h).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "reports/report_data.h"

namespace candela {

// Header "x,y,z,dx,dy,dz,illuminance_lux[,extra...]" and one row per point (m, unit normal, lux).
// Throws std::invalid_argument when a column's length differs from the number of points.
std::string gridCsv(const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                    const std::vector<ExtraColumn>& extraColumns = {});

// Header "x,y,z,dx,dy,dz[,column...]" and one row per point: the first six columns of every grid
// CSV, then `columns` (8 significant digits). gridCsv is this with illuminance_lux first.
// Throws std::invalid_argument when a column's length differs from the number of points.
std::string pointsCsv(const std::vector<ReportPoint>& points, const std::vector<ExtraColumn>& columns);

// A points CSV made a row at a time, for results that come in blocks (the grid study streams its
// estimates): the header "x,y,z,dx,dy,dz[,column...]" and rows as pointsCsv writes them, the
// same bytes, handed to `sink` a few thousand rows at a time. finish() hands over the rest.
// Throws std::logic_error when a column name repeats another (every header's names are unique).
class PointsCsvWriter {
 public:
  PointsCsvWriter(std::function<void(std::string_view)> sink, const std::vector<std::string>& columns);
  // One row: the point (m), its unit normal, and one value per column.
  void row(const Vec3& position, const Vec3& normal, const double* values);
  void finish();

 private:
  std::function<void(std::string_view)> sink_;
  std::size_t columns_ = 0, rows_ = 0;
  std::string pending_;
};

// Writes <dir>/<safeFileName(gridName)>.csv and returns its path; creates `dir` if needed.
std::filesystem::path writeGridCsv(const std::filesystem::path& dir, const std::string& gridName,
                                   const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                                   const std::vector<ExtraColumn>& extraColumns = {});

// Per-sensor annual metrics of a grid: x,y,z,dx,dy,dz,DA300,cDA300,UDI_fell_short,
// UDI_supplementary,UDI_autonomous,UDI_exceeded,ASE_hours,sun_hours (m, unit normal, % of
// occupied hours, hours). Throws std::invalid_argument when a metric has the wrong length.
std::string annualGridCsv(const std::vector<ReportPoint>& points, const AnnualGridReport& annual);

// Writes <dir>/<safeFileName(gridName)>_annual.csv and returns its path; creates `dir` if needed.
std::filesystem::path writeAnnualGridCsv(const std::filesystem::path& dir, const std::string& gridName,
                                         const std::vector<ReportPoint>& points, const AnnualGridReport& annual);

// summary.csv columns, in order (empty field = not applicable):
//   case,grid,unit,points,average,minimum,maximum,median,u0,ud,target_average,target_uniformity,
//   verdict_average,verdict_uniformity,verdict,seed,version,run_time_s,settings
// and, only when some grid has annual results (empty on the other rows):
//   DA300,cDA300,UDI_fell_short,UDI_supplementary,UDI_autonomous,UDI_exceeded (grid means, % of
//   occupied hours),sDA300_50,ASE1000_250 (% of sensors),occupied_hours,coefficients_time_s,
//   product_time_s (s)
// and, only when some grid has a `quantity` or `modelling` (docs/quantities.md):
//   quantity (the grid's quantity as the report names it),cylindrical_average_lux,
//   horizontal_average_lux,modelling_ratio,verdict_modelling (empty without modelling)
// `settings` is "key=value;key=value". Fields are quoted as RFC 4180 when needed.
std::string summaryCsv(const ReportData& data);

// Writes <dir>/summary.csv and returns its path.
std::filesystem::path writeSummaryCsv(const std::filesystem::path& dir, const ReportData& data);

// observers.csv: a row per [[observer]] (name, eye position, line of sight, UGR, limit, verdict,
// luminaires in view, vertical illuminance and background luminance at the eye); written by
// writeSummaryCsv beside summary.csv when the case has observers.
std::string observersCsv(const ReportData& data);

// One CSV field, quoted when it holds a comma, quote or line break (RFC 4180).
std::string csvField(const std::string& text);

}  // namespace candela
