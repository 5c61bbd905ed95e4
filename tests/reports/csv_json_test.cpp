#include "reports/csv_writer.h"
#include "reports/json_writer.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / ("candela_reports_" + name);
  fs::remove_all(d);
  return d;
}

using test_support::slurp;

// Minimal CSV reader for the tests: RFC 4180 quotes, no embedded line breaks.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted) {
        if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
        else if (c == '"') quoted = false;
        else fields.back() += c;
      } else if (c == '"') quoted = true;
      else if (c == ',') fields.emplace_back();
      else fields.back() += c;
    }
    rows.push_back(fields);
  }
  return rows;
}

TEST(GridCsv, RoundTripsPointsValuesAndExtraColumns) {
  std::vector<ReportPoint> pts;
  const GridReport g = testing_sample::sampleGrid("Work plane", 0.5, 0.5, 5.5, 3.5, 0.5, &pts);
  std::vector<double> df(g.values.size());
  for (std::size_t i = 0; i < df.size(); ++i) df[i] = g.values[i] / 100.0;  // any distinct column
  const fs::path dir = freshDir("grid");
  const fs::path path = writeGridCsv(dir, "Work plane", pts, g.values, {{"daylight_factor_pct", df}});
  EXPECT_EQ(path, dir / "Work_plane.csv");
  const auto rows = parseCsv(slurp(path));
  ASSERT_EQ(rows.size(), pts.size() + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"x", "y", "z", "dx", "dy", "dz", "illuminance_lux",
                                               "daylight_factor_pct"}));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& r = rows[i + 1];
    ASSERT_EQ(r.size(), 8u);
    EXPECT_DOUBLE_EQ(std::stod(r[0]), pts[i].position.x);  // 10 significant digits: exact here
    EXPECT_DOUBLE_EQ(std::stod(r[2]), 0.8);
    EXPECT_DOUBLE_EQ(std::stod(r[5]), 1.0);
    EXPECT_NEAR(std::stod(r[6]), g.values[i], 1e-7 * g.values[i]);  // 8 significant digits
    EXPECT_NEAR(std::stod(r[7]), df[i], 1e-7 * df[i]);
  }
  EXPECT_THROW(gridCsv(pts, {1.0}), std::invalid_argument);
  EXPECT_THROW(gridCsv(pts, g.values, {{"bad", {1.0}}}), std::invalid_argument);
  // No temporary file is left behind by the atomic write.
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename().string()[0] != '.', true);
}

// The file is written in pieces of 4096 rows: 10 001 points (two whole pieces and a part) come
// out row for row, in order, the same bytes as the CSV built as one string.
TEST(GridCsv, LargeGridsAreWrittenInPiecesWithTheSameBytes) {
  std::vector<ReportPoint> pts(10001);
  std::vector<double> lux(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts[i] = {Vec3(0.01 * static_cast<double>(i), 1.0, 0.8), Vec3(0.0, 0.0, 1.0)};
    lux[i] = 100.0 + static_cast<double>(i);
  }
  const fs::path dir = freshDir("grid_pieces");
  const fs::path path = writeGridCsv(dir, "big", pts, lux, {});
  const std::string text = slurp(path);
  EXPECT_EQ(text, gridCsv(pts, lux));
  const auto rows = parseCsv(text);
  ASSERT_EQ(rows.size(), pts.size() + 1);
  for (std::size_t i : {std::size_t{0}, std::size_t{4095}, std::size_t{4096}, std::size_t{8192}, std::size_t{10000}})
    EXPECT_DOUBLE_EQ(std::stod(rows[i + 1][6]), lux[i]) << i;
}

// The summary's metrics must equal the statistics recomputed here from the values with plain
// loops (independent of metrics/grid_stats).
TEST(Summary, CsvAndJsonCarryTheMetrics) {
  const ReportData data = testing_sample::sampleReport();
  const fs::path dir = freshDir("summary");
  writeSummary(dir, data);

  const auto rows = parseCsv(slurp(dir / "summary.csv"));
  ASSERT_EQ(rows.size(), data.grids.size() + 1);
  const auto& header = rows[0];
  auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const nlohmann::json j = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(j["case"]["name"], data.run.caseName);
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["settings"]["bounces"], "2");
  EXPECT_DOUBLE_EQ(j["run_time_s"].get<double>(), 3.25);
  ASSERT_EQ(j["grids"].size(), data.grids.size());

  for (std::size_t g = 0; g < data.grids.size(); ++g) {
    const std::vector<double>& v = data.grids[g].values;
    double sum = 0.0, lo = v[0], hi = v[0];
    for (double e : v) {
      sum += e;
      lo = std::min(lo, e);
      hi = std::max(hi, e);
    }
    const double avg = sum / v.size();
    const auto& r = rows[g + 1];
    EXPECT_EQ(r[col("case")], data.run.caseName);
    EXPECT_EQ(r[col("grid")], data.grids[g].name);  // "Desk <A&B>" survives quoting rules
    EXPECT_EQ(std::stoul(r[col("points")]), v.size());
    EXPECT_NEAR(std::stod(r[col("average")]), avg, 1e-7 * avg);  // 8 significant digits
    EXPECT_NEAR(std::stod(r[col("minimum")]), lo, 1e-7 * lo);
    EXPECT_NEAR(std::stod(r[col("maximum")]), hi, 1e-7 * hi);
    EXPECT_NEAR(std::stod(r[col("u0")]), lo / avg, 1e-7);
    EXPECT_NEAR(std::stod(r[col("ud")]), lo / hi, 1e-7);
    EXPECT_EQ(r[col("seed")], "7");
    EXPECT_EQ(r[col("settings")], "quality=normal;method=cache;bounces=2;samples=512;threads=all (8)");

    const nlohmann::json& jg = j["grids"][g];
    EXPECT_EQ(jg["name"], data.grids[g].name);
    EXPECT_EQ(jg["points"], v.size());
    EXPECT_NEAR(jg["average"].get<double>(), avg, 1e-9 * avg);  // JSON keeps full precision
    EXPECT_NEAR(jg["minimum"].get<double>(), lo, 1e-9 * lo);
    EXPECT_NEAR(jg["u0"].get<double>(), lo / avg, 1e-12);
    // Verdicts as a designer would check them by hand.
    const GridTargets& t = data.grids[g].targets;
    const bool avgOk = !t.averageLux || avg >= *t.averageLux;
    const bool u0Ok = !t.uniformity || lo / avg >= *t.uniformity;
    EXPECT_EQ(jg["verdict"], (avgOk && u0Ok) ? "pass" : "fail");
    EXPECT_EQ(r[col("verdict")], (avgOk && u0Ok) ? "pass" : "fail");
    if (!t.uniformity) {
      EXPECT_TRUE(jg["target_uniformity"].is_null());
      EXPECT_EQ(r[col("target_uniformity")], "");
      EXPECT_EQ(jg["verdict_uniformity"], "n/a");
    }
  }
  // The sample is built so that both verdicts occur.
  EXPECT_EQ(j["grids"][0]["verdict"], "pass");
  EXPECT_EQ(j["grids"][1]["verdict"], "fail");
  // The run's verdict, as overallVerdict counts its lines.
  int checked = 0, failed = 0;
  EXPECT_EQ(j["verdict"], verdictName(overallVerdict(testing_sample::sampleReport(), &checked, &failed)));
  EXPECT_EQ(j["verdict"], "fail");
  EXPECT_EQ(j["verdict_lines"]["checked"], checked);
  EXPECT_EQ(j["verdict_lines"]["failed"], failed);
  EXPECT_GE(failed, 1);
}

// Each view's noise under the names docs/reports.md gives; unknown or absent values are null.
TEST(Summary, JsonCarriesEachViewsNoise) {
  ReportData data = testing_sample::sampleReport();
  ViewReport a;
  a.name = "desk";
  a.meanLuminanceCdM2 = 97.5;
  a.meanLuminanceRelativeStandardError = 0.0016;
  a.glareSourceLuminanceCdM2 = 2436.0;
  a.glareSourceLuminanceRelativeStandardError = 0.0025;
  ViewReport b;
  b.name = "overview";
  b.meanLuminanceCdM2 = 50.0;  // one ray per pixel: no error estimate; a perspective: no image glare sources
  data.views = {a, b};
  const nlohmann::json j = nlohmann::json::parse(summaryJson(data));
  ASSERT_EQ(j["views"].size(), 2u);
  const nlohmann::json& ja = j["views"][0];
  EXPECT_EQ(ja["name"], "desk");
  EXPECT_DOUBLE_EQ(ja["mean_luminance_cd_m2"].get<double>(), 97.5);
  EXPECT_DOUBLE_EQ(ja["mean_luminance_relative_standard_error"].get<double>(), 0.0016);
  EXPECT_DOUBLE_EQ(ja["glare_source_luminance_cd_m2"].get<double>(), 2436.0);
  EXPECT_DOUBLE_EQ(ja["glare_source_luminance_relative_standard_error"].get<double>(), 0.0025);
  const nlohmann::json& jb = j["views"][1];
  EXPECT_TRUE(jb["mean_luminance_relative_standard_error"].is_null());
  EXPECT_TRUE(jb["glare_source_luminance_cd_m2"].is_null());
  EXPECT_TRUE(jb["glare_source_luminance_relative_standard_error"].is_null());
  // No views: an empty array, so scripts need no key check.
  data.views.clear();
  EXPECT_TRUE(nlohmann::json::parse(summaryJson(data))["views"].is_array());
}

// A grid's plan section in summary.json: its cut and counts; none for a grid without one.
TEST(Summary, PlanSectionCounts) {
  ReportData data = testing_sample::sampleReport();
  PlanSection p;
  p.cutHeightM = 1.0;
  p.floorLevelM = 0.0;
  p.raisedAboveFloor = true;
  p.walls = {{Vec2(0.0), Vec2(1.0)}, {Vec2(1.0), Vec2(2.0, 1.0)}};
  p.openingsAbove = {{Vec2(0.0), Vec2(0.0, 1.0)}};
  p.droppedSegments = 3;
  data.planSections = {p};
  data.grids[0].planSection = 0;
  const nlohmann::json j = nlohmann::json::parse(summaryJson(data));
  const nlohmann::json& s = j["grids"][0]["plan_section"];
  EXPECT_DOUBLE_EQ(s["cut_height_m"].get<double>(), 1.0);
  EXPECT_TRUE(s["raised_above_floor"].get<bool>());
  EXPECT_EQ(s["walls"], 2);
  EXPECT_EQ(s["openings"], 0);
  EXPECT_EQ(s["openings_above"], 1);
  EXPECT_EQ(s["dropped_segments"], 3);
  EXPECT_FALSE(j["grids"][1].contains("plan_section"));
}

// Observers: UGR, limit and verdict in summary.json and observers.csv; no luminaire in view reads
// as no UGR and passes its limit; without a limit there is no verdict.
TEST(Summary, ObserversInJsonAndCsv) {
  ReportData data = testing_sample::sampleReport();
  EXPECT_TRUE(nlohmann::json::parse(summaryJson(data))["observers"].empty());
  ObserverReport a;
  a.name = "desk, north";
  a.eyeM = {1.0, 2.0, 1.2};
  a.direction = {0.0, 1.0};
  a.ugr = 19.4;
  a.ugrLimit = 19.0;
  a.luminairesInView = 6;
  a.verticalLux = 310.0;
  a.backgroundCdM2 = 40.0;
  ObserverReport b;
  b.name = "corner";
  b.ugrLimit = 22.0;  // nothing in view: passes
  ObserverReport c;
  c.name = "free";
  c.ugr = 15.0;  // no limit: no verdict
  data.observers = {a, b, c};
  const nlohmann::json j = nlohmann::json::parse(summaryJson(data))["observers"];
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[0]["name"], "desk, north");
  EXPECT_EQ(j[0]["ugr"], 19.4);
  EXPECT_EQ(j[0]["verdict"], "fail");
  EXPECT_EQ(j[0]["position_m"], nlohmann::json::array({1.0, 2.0}));
  EXPECT_EQ(j[0]["eye_height_m"], 1.2);
  EXPECT_EQ(j[0]["luminaires_in_view"], 6);
  EXPECT_TRUE(j[1]["ugr"].is_null());
  EXPECT_EQ(j[1]["verdict"], "pass");
  EXPECT_TRUE(j[2]["verdict"].is_null());
  std::istringstream csv(observersCsv(data));
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "observer,x_m,y_m,eye_height_m,direction_x,direction_y,ugr,ugr_limit,verdict,luminaires_in_view,"
            "vertical_illuminance_lux,background_luminance_cd_m2");
  std::getline(csv, row);
  EXPECT_EQ(row, "\"desk, north\",1,2,1.2,0,1,19.4,19,fail,6,310,40");
  std::getline(csv, row);
  EXPECT_EQ(row.substr(0, 7), "corner,");
  EXPECT_NE(row.find(",,22,pass,0,"), std::string::npos) << row;
}

// A grid's quantity and modelling (docs/quantities.md): summary.json's quantity_key and
// modelling block, summary.csv's extra columns only when some grid has them.
TEST(Summary, QuantityAndModellingInJsonAndCsv) {
  ReportData d = testing_sample::sampleReport();
  const std::string plainCsv = summaryCsv(d);
  EXPECT_EQ(plainCsv.find("modelling_ratio"), std::string::npos);
  EXPECT_EQ(summaryJson(d).find("modelling"), std::string::npos);
  d.grids[0].quantity = "Cylindrical illuminance Ē_z";
  d.grids[0].quantityKey = "cylindrical";
  d.grids[0].modelling = modellingRatio({100.0, 200.0}, {300.0, 500.0});
  const nlohmann::json j = nlohmann::json::parse(summaryJson(d));
  EXPECT_EQ(j["grids"][0]["quantity"], "Cylindrical illuminance Ē_z");
  EXPECT_EQ(j["grids"][0]["quantity_key"], "cylindrical");
  const nlohmann::json& m = j["grids"][0]["modelling"];
  EXPECT_DOUBLE_EQ(m["cylindrical_average_lux"].get<double>(), 150.0);
  EXPECT_DOUBLE_EQ(m["horizontal_average_lux"].get<double>(), 400.0);
  EXPECT_DOUBLE_EQ(m["ratio"].get<double>(), 0.375);
  EXPECT_EQ(m["range"], nlohmann::json({0.3, 0.6}));
  EXPECT_EQ(m["verdict"], "pass");
  EXPECT_FALSE(j["grids"][1].contains("modelling"));
  EXPECT_FALSE(j["grids"][1].contains("quantity_key"));
  const auto rows = parseCsv(summaryCsv(d));
  const std::vector<std::string>& head = rows[0];
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  ASSERT_LT(col("verdict_modelling"), head.size());
  EXPECT_EQ(head.back(), "verdict_modelling");
  EXPECT_EQ(rows[1][col("quantity")], "Cylindrical illuminance Ē_z");
  EXPECT_EQ(rows[1][col("modelling_ratio")], "0.375");
  EXPECT_EQ(rows[1][col("verdict_modelling")], "pass");
  EXPECT_EQ(rows[2][col("quantity")], "Illuminance");
  EXPECT_EQ(rows[2][col("modelling_ratio")], "");
  EXPECT_EQ(rows[2].size(), head.size());
}

TEST(Summary, CsvFieldQuoting) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
}

TEST(Summary, CsvFieldsThatLookLikeFormulasStayText) {
  // A grid named like a spreadsheet formula must not run as one when summary.csv is opened.
  EXPECT_EQ(csvField("=cmd|' /C calc'!A0"), "\"'=cmd|' /C calc'!A0\"");
  for (const char* f : {"+1", "-2", "@SUM(A1)", "\tx", "\rx"}) EXPECT_EQ(csvField(f).substr(0, 2), "\"'") << f;
  EXPECT_EQ(csvField("desk-1"), "desk-1");  // only a leading sign counts
  EXPECT_EQ(csvField(""), "");
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Every CSV header names each column once: the cylindrical modelling grid named
// cylindrical_illuminance_lux twice (tests/study/quantities_study_test.cpp checks that grid's
// header); here every writer of reports/csv_writer.h with every optional block switched on.
void expectUniqueHeader(const std::string& csv, const std::string& what) {
  const std::vector<std::string> head = parseCsv(csv).at(0);
  std::vector<std::string> sorted = head;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  EXPECT_EQ(twice, sorted.end()) << what << " names '" << (twice == sorted.end() ? "" : *twice) << "' twice";
  EXPECT_GT(head.size(), 1u) << what;
}

TEST(CsvHeaders, EveryWriterNamesEachColumnOnce) {
  ReportData d = testing_sample::sampleAnnualReport();
  d.grids[0].quantity = "Cylindrical illuminance Ē_z";
  d.grids[0].quantityKey = "cylindrical";
  d.grids[0].modelling = modellingRatio({100.0, 200.0}, {300.0, 500.0});
  ObserverReport o;
  o.name = "desk";
  d.observers = {o};
  expectUniqueHeader(summaryCsv(d), "summary.csv");
  expectUniqueHeader(observersCsv(d), "observers.csv");
  std::vector<ReportPoint> pts;
  const GridReport g = testing_sample::sampleGrid("Daylit office", 0.0, 0.0, 6.0, 4.0, 0.25, &pts);
  const AnnualGridReport annual = testing_sample::sampleAnnual(g);
  expectUniqueHeader(annualGridCsv(pts, annual), "the annual grid CSV");
  const std::vector<double> ones(pts.size(), 1.0);
  expectUniqueHeader(gridCsv(pts, g.values, {{"error_lux", ones}, {"daylight_factor_pct", ones}}), "a grid CSV");
  // The streaming writer refuses a repeated name outright (an internal error, never a file).
  EXPECT_THROW(PointsCsvWriter([](std::string_view) {}, {"cylindrical_illuminance_lux", "error_lux",
                                                          "cylindrical_illuminance_lux"}),
               std::logic_error);
  EXPECT_THROW(PointsCsvWriter([](std::string_view) {}, {"x"}), std::logic_error);
  EXPECT_THROW(gridCsv(pts, g.values, {{"illuminance_lux", ones}}), std::logic_error);
}

}  // namespace
}  // namespace candela
