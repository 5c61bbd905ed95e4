#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "reports/csv_writer.h"
#include "reports/json_writer.h"
#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

using test_support::slurp;

// Split on commas; the fields tested here hold no quotes (names are checked in csv_json_test).
std::vector<std::vector<std::string>> rowsOf(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f(1);
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) f.emplace_back();
      else f.back() += c;
    }
    rows.push_back(f);
  }
  return rows;
}

TEST(AnnualGridCsv, HasTheMetricColumnsPerSensor) {
  std::vector<ReportPoint> pts;
  const GridReport g = testing_sample::sampleGrid("Daylit office", 0.0, 0.0, 6.0, 4.0, 0.5, &pts);
  const AnnualGridReport a = testing_sample::sampleAnnual(g);
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_csv";
  fs::remove_all(dir);
  const fs::path path = writeAnnualGridCsv(dir, "Daylit office", pts, a);
  EXPECT_EQ(path.filename().string(), "Daylit_office_annual.csv");
  const auto rows = rowsOf(slurp(path));
  ASSERT_EQ(rows.size(), pts.size() + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"x", "y", "z", "dx", "dy", "dz", "DA300", "cDA300", "UDI_fell_short",
                                               "UDI_supplementary", "UDI_autonomous", "UDI_exceeded", "ASE_hours",
                                               "sun_hours"}));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& r = rows[i + 1];
    ASSERT_EQ(r.size(), 14u);
    EXPECT_DOUBLE_EQ(std::stod(r[1]), pts[i].position.y);
    const SensorAnnualMetrics& m = a.sensors[i];
    EXPECT_NEAR(std::stod(r[6]), m.da, 1e-7 * m.da);  // 8 significant digits
    EXPECT_NEAR(std::stod(r[10]), m.udiAutonomous, 1e-7 * m.udiAutonomous);
    EXPECT_EQ(std::stod(r[12]), m.aseHours);  // whole hours print exactly
    // The four UDI bins partition the occupied hours.
    EXPECT_NEAR(std::stod(r[8]) + std::stod(r[9]) + std::stod(r[10]) + std::stod(r[11]), 100.0, 4e-6);
  }
  AnnualGridReport bad = a;
  bad.sensors.pop_back();
  EXPECT_THROW(annualGridCsv(pts, bad), std::invalid_argument);
}

TEST(AnnualSummary, CsvAndJsonCarryTheExactNames) {
  const ReportData data = testing_sample::sampleAnnualReport();
  const std::size_t annualIndex = data.grids.size() - 1;
  const GridAnnualSummary& s = data.grids[annualIndex].annual->summary;
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_summary";
  fs::remove_all(dir);
  writeSummary(dir, data);

  const auto rows = rowsOf(slurp(dir / "summary.csv"));
  ASSERT_EQ(rows.size(), data.grids.size() + 1);
  const auto& header = rows[0];
  auto col = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::vector<std::pair<std::string, double>> expected = {
      {"DA300", s.DA300},           {"cDA300", s.cDA300},
      {"UDI_fell_short", s.UDI_fell_short}, {"UDI_supplementary", s.UDI_supplementary},
      {"UDI_autonomous", s.UDI_autonomous}, {"UDI_exceeded", s.UDI_exceeded},
      {"sDA300_50", s.sDA300_50},   {"ASE1000_250", s.ASE1000_250}};
  const auto& r = rows[annualIndex + 1];
  ASSERT_EQ(r.size(), header.size());
  for (const auto& [name, v] : expected) EXPECT_NEAR(std::stod(r[col(name)]), v, 1e-7 * std::abs(v) + 1e-12) << name;
  EXPECT_EQ(std::stoi(r[col("occupied_hours")]), 3650);  // 10 h × 365 days
  EXPECT_DOUBLE_EQ(std::stod(r[col("coefficients_time_s")]), 12.5);
  EXPECT_DOUBLE_EQ(std::stod(r[col("product_time_s")]), 0.75);
  // A non-annual grid leaves the annual fields empty (same number of fields).
  ASSERT_EQ(rows[1].size(), header.size());
  EXPECT_EQ(rows[1][col("DA300")], "");

  const nlohmann::json j = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_DOUBLE_EQ(j["coefficients_time_s"].get<double>(), 12.5);
  EXPECT_DOUBLE_EQ(j["product_time_s"].get<double>(), 0.75);
  const nlohmann::json& ga = j["grids"][annualIndex];
  for (const auto& [name, v] : expected) EXPECT_DOUBLE_EQ(ga[name].get<double>(), v) << name;
  EXPECT_EQ(ga["occupied_hours"], 3650);
  EXPECT_EQ(ga["sensors"], data.grids[annualIndex].values.size());
  EXPECT_DOUBLE_EQ(ga["product_time_s"].get<double>(), 0.75);
  EXPECT_FALSE(j["grids"][0].contains("DA300"));
}

// Without annual grids the summary is exactly what it was: no annual columns or keys.
TEST(AnnualSummary, NoAnnualColumnsForOtherRuns) {
  const ReportData data = testing_sample::sampleReport();
  const std::string csv = summaryCsv(data);
  EXPECT_EQ(csv.substr(0, csv.find('\n')).substr(csv.find("run_time_s")), "run_time_s,settings");
  const nlohmann::json j = nlohmann::json::parse(summaryJson(data));
  EXPECT_FALSE(j.contains("coefficients_time_s"));
  EXPECT_FALSE(j["grids"][0].contains("DA300"));
}

}  // namespace
}  // namespace candela
