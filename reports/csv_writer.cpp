#include "reports/csv_writer.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "base/atomic_file.h"

namespace candela {

namespace fs = std::filesystem;

std::string csvField(const std::string& text) {
  // A text that a spreadsheet would take for a formula (=, +, -, @, or a leading tab or CR: a
  // grid named "=cmd|' /C calc'!A0") gets a leading apostrophe, so it is shown as text (OWASP,
  // "CSV Injection").
  const bool formula = !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos;
  if (!formula && text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string q = formula ? "\"'" : "\"";
  for (char c : text) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

// Rows are handed to the sink in pieces of at most kRowsPerPiece rows (the header first), so that
// a file of 10⁶ rows is never one string in memory.
constexpr std::size_t kRowsPerPiece = 4096;

PointsCsvWriter::PointsCsvWriter(std::function<void(std::string_view)> sink, const std::vector<std::string>& columns)
    : sink_(std::move(sink)), columns_(columns.size()) {
  // Every column name once: a cylindrical modelling grid once named cylindrical_illuminance_lux
  // twice, and a reader by name took the first of two different values.
  std::vector<std::string> names = {"x", "y", "z", "dx", "dy", "dz"};
  for (const std::string& c : columns) {
    if (std::find(names.begin(), names.end(), c) != names.end())
      throw std::logic_error("CSV column '" + c + "' is named twice");
    names.push_back(c);
  }
  pending_ = "x,y,z,dx,dy,dz";
  for (const std::string& c : columns) pending_ += "," + csvField(c);
  pending_ += "\n";
}

void PointsCsvWriter::row(const Vec3& position, const Vec3& normal, const double* values) {
  std::string row;
  for (double v : {position.x, position.y, position.z, normal.x, normal.y, normal.z})
    row += (row.empty() ? "" : ",") + formatNumber(v, 10);
  for (std::size_t c = 0; c < columns_; ++c) row += "," + formatNumber(values[c], 8);
  pending_ += row + "\n";
  if (++rows_ % kRowsPerPiece == 0) {
    sink_(pending_);
    pending_.clear();
  }
}

void PointsCsvWriter::finish() {
  sink_(pending_);
  pending_.clear();
}

namespace {

void emitPointsCsv(const std::vector<ReportPoint>& points, const std::vector<ExtraColumn>& columns,
                   const std::function<void(std::string_view)>& sink) {
  std::vector<std::string> names;
  for (const ExtraColumn& c : columns) {
    if (c.values.size() != points.size())
      throw std::invalid_argument("CSV column '" + c.name + "' has " + std::to_string(c.values.size()) +
                                  " values for " + std::to_string(points.size()) + " points");
    names.push_back(c.name);
  }
  PointsCsvWriter writer(sink, names);
  std::vector<double> row(columns.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t c = 0; c < columns.size(); ++c) row[c] = columns[c].values[i];
    writer.row(points[i].position, points[i].normal, row.data());
  }
  writer.finish();
}

fs::path writePointsCsv(const fs::path& path, const std::vector<ReportPoint>& points,
                        const std::vector<ExtraColumn>& columns) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  AtomicFile file(path);
  emitPointsCsv(points, columns, [&file](std::string_view piece) { file.write(piece); });
  file.commit();
  return path;
}

std::vector<ExtraColumn> gridColumns(const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                                     const std::vector<ExtraColumn>& extraColumns) {
  if (lux.size() != points.size())
    throw std::invalid_argument("gridCsv: " + std::to_string(points.size()) + " points but " +
                                std::to_string(lux.size()) + " illuminances");
  std::vector<ExtraColumn> columns = {{"illuminance_lux", lux}};
  columns.insert(columns.end(), extraColumns.begin(), extraColumns.end());
  return columns;
}

std::vector<ExtraColumn> annualColumns(const AnnualGridReport& a) {
  using M = SensorAnnualMetrics;
  return {{"DA300", annualColumn(a, &M::da)},
          {"cDA300", annualColumn(a, &M::cda)},
          {"UDI_fell_short", annualColumn(a, &M::udiFellShort)},
          {"UDI_supplementary", annualColumn(a, &M::udiSupplementary)},
          {"UDI_autonomous", annualColumn(a, &M::udiAutonomous)},
          {"UDI_exceeded", annualColumn(a, &M::udiExceeded)},
          {"ASE_hours", annualColumn(a, &M::aseHours)},
          {"sun_hours", annualColumn(a, &M::sunHours)}};
}

}  // namespace

std::string pointsCsv(const std::vector<ReportPoint>& points, const std::vector<ExtraColumn>& columns) {
  std::string out;
  emitPointsCsv(points, columns, [&out](std::string_view piece) { out += piece; });
  return out;
}

std::string gridCsv(const std::vector<ReportPoint>& points, const std::vector<double>& lux,
                    const std::vector<ExtraColumn>& extraColumns) {
  return pointsCsv(points, gridColumns(points, lux, extraColumns));
}

std::string annualGridCsv(const std::vector<ReportPoint>& points, const AnnualGridReport& a) {
  return pointsCsv(points, annualColumns(a));
}

fs::path writeAnnualGridCsv(const fs::path& dir, const std::string& gridName, const std::vector<ReportPoint>& points,
                            const AnnualGridReport& annual) {
  return writePointsCsv(dir / (safeFileName(gridName) + "_annual.csv"), points, annualColumns(annual));
}

fs::path writeGridCsv(const fs::path& dir, const std::string& gridName, const std::vector<ReportPoint>& points,
                      const std::vector<double>& lux, const std::vector<ExtraColumn>& extraColumns) {
  return writePointsCsv(dir / (safeFileName(gridName) + ".csv"), points, gridColumns(points, lux, extraColumns));
}

std::string summaryCsv(const ReportData& data) {
  std::string settings;
  for (const auto& [k, v] : data.run.settings) settings += (settings.empty() ? "" : ";") + k + "=" + v;
  std::string out =
      "case,grid,unit,points,average,minimum,maximum,median,u0,ud,target_average,target_uniformity,"
      "verdict_average,verdict_uniformity,verdict,seed,version,run_time_s,settings";
  bool anyAnnual = false;
  for (const GridReport& g : data.grids) anyAnnual = anyAnnual || g.annual.has_value();
  if (anyAnnual)
    out += ",DA300,cDA300,UDI_fell_short,UDI_supplementary,UDI_autonomous,UDI_exceeded,sDA300_50,ASE1000_250,"
           "occupied_hours,coefficients_time_s,product_time_s";
  // The quantity and modelling columns only when some grid gives them (a case without keeps its bytes).
  bool anyQuantity = false;
  for (const GridReport& g : data.grids) anyQuantity = anyQuantity || !g.quantityKey.empty() || g.modelling;
  if (anyQuantity)
    out += ",quantity,cylindrical_average_lux,horizontal_average_lux,modelling_ratio,verdict_modelling";
  out += "\n";
  auto optionalTime = [](const std::optional<double>& t) { return t ? formatNumber(*t, 6) : std::string(); };
  for (const GridReport& g : data.grids) {
    const GridStats& s = g.stats;
    std::vector<std::string> f = {csvField(data.run.caseName),
                                  csvField(g.name),
                                  csvField(g.unit),
                                  std::to_string(s.count),
                                  formatNumber(s.averageLux),
                                  formatNumber(s.minimumLux),
                                  formatNumber(s.maximumLux),
                                  formatNumber(s.medianLux),
                                  formatNumber(s.u0),
                                  formatNumber(s.ud),
                                  g.targets.averageLux ? formatNumber(*g.targets.averageLux) : "",
                                  g.targets.uniformity ? formatNumber(*g.targets.uniformity) : "",
                                  verdictName(g.check.average),
                                  verdictName(g.check.uniformity),
                                  verdictName(g.check.overall),
                                  std::to_string(data.run.seed),
                                  csvField(data.run.version),
                                  formatNumber(data.run.runTimeS, 6),
                                  csvField(settings)};
    if (anyAnnual && g.annual) {
      const GridAnnualSummary& a = g.annual->summary;
      for (double v : {a.DA300, a.cDA300, a.UDI_fell_short, a.UDI_supplementary, a.UDI_autonomous, a.UDI_exceeded,
                       a.sDA300_50, a.ASE1000_250})
        f.push_back(formatNumber(v));
      f.push_back(std::to_string(a.occupiedHours));
      f.push_back(optionalTime(data.run.coefficientsTimeS));
      f.push_back(optionalTime(data.run.productTimeS));
    } else if (anyAnnual) {
      f.insert(f.end(), 11, "");
    }
    if (anyQuantity) {
      f.push_back(csvField(g.quantity));
      if (g.modelling) {
        const ModellingResult& m = *g.modelling;
        for (double v : {m.cylindricalAverageLux, m.horizontalAverageLux, m.ratio}) f.push_back(formatNumber(v));
        f.push_back(verdictName(m.verdict));
      } else {
        f.insert(f.end(), 4, "");
      }
    }
    for (std::size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    out += "\n";
  }
  return out;
}

std::string observersCsv(const ReportData& data) {
  std::string out =
      "observer,x_m,y_m,eye_height_m,direction_x,direction_y,ugr,ugr_limit,verdict,luminaires_in_view,"
      "vertical_illuminance_lux,background_luminance_cd_m2\n";
  for (const ObserverReport& o : data.observers) {
    const std::optional<bool> pass = o.pass();
    const std::vector<std::string> f = {csvField(o.name),
                                        formatNumber(o.eyeM.x),
                                        formatNumber(o.eyeM.y),
                                        formatNumber(o.eyeM.z),
                                        formatNumber(o.direction.x),
                                        formatNumber(o.direction.y),
                                        o.ugr ? formatNumber(*o.ugr) : "",
                                        o.ugrLimit ? formatNumber(*o.ugrLimit) : "",
                                        pass ? (*pass ? "pass" : "fail") : "",
                                        std::to_string(o.luminairesInView),
                                        formatNumber(o.verticalLux),
                                        formatNumber(o.backgroundCdM2)};
    for (std::size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
    out += "\n";
  }
  return out;
}

fs::path writeSummaryCsv(const fs::path& dir, const ReportData& data) {
  fs::create_directories(dir);
  const fs::path path = dir / "summary.csv";
  writeFileAtomic(path, summaryCsv(data));
  if (!data.observers.empty()) writeFileAtomic(dir / "observers.csv", observersCsv(data));
  return path;
}

}  // namespace candela
