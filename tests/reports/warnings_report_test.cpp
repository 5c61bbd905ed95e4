// Warnings in the reports (docs/warnings.md): summary.json always has a top-level "warnings"
// array of {code, message, file, line}; report.html shows them in a box above the summary, with
// everything escaped; summary.csv does not change.
#include "reports/csv_writer.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

using test_support::slurp;

ReportData withWarnings() {
  ReportData d = testing_sample::sampleReport();
  d.warnings.push_back({"sensor_near_surface", "grid '<b>desk</b>': a sensor & its \"wall\"\x1b[31m",
                        FileLoc{"rooms/a<b>.pts", 4, 0}});
  d.warnings.push_back({"no_light_source", "the scene has no light source", FileLoc{"case.toml", 0, 0}});
  return d;
}

TEST(WarningsReport, SummaryJsonCarriesTheFourFields) {
  const nlohmann::json j = nlohmann::json::parse(summaryJson(withWarnings()));
  ASSERT_TRUE(j.contains("warnings"));
  ASSERT_EQ(j["warnings"].size(), 2u);
  const nlohmann::json& w = j["warnings"][0];
  EXPECT_EQ(w.size(), 4u);
  EXPECT_EQ(w["code"], "sensor_near_surface");
  EXPECT_EQ(w["message"], "grid '<b>desk</b>': a sensor & its \"wall\"\x1b[31m");  // JSON escapes it
  EXPECT_EQ(w["file"], "rooms/a<b>.pts");
  EXPECT_EQ(w["line"], 4);
  EXPECT_TRUE(j["warnings"][1]["line"].is_null());  // only the file is known
  // Without warnings the key is there, empty.
  const nlohmann::json none = nlohmann::json::parse(summaryJson(testing_sample::sampleReport()));
  ASSERT_TRUE(none.contains("warnings"));
  EXPECT_TRUE(none["warnings"].is_array());
  EXPECT_TRUE(none["warnings"].empty());
}

TEST(WarningsReport, HtmlShowsThemEscapedAboveTheSummary) {
  const std::string html = htmlReport(withWarnings());
  const std::size_t box = html.find("<section class=\"warnings\">");
  ASSERT_NE(box, std::string::npos);
  EXPECT_LT(box, html.find("<section class=\"summary\">"));
  EXPECT_NE(html.find("Warnings (2)"), std::string::npos);
  EXPECT_NE(html.find("rooms/a&lt;b&gt;.pts:4"), std::string::npos);
  EXPECT_NE(html.find("grid &#39;&lt;b&gt;desk&lt;/b&gt;&#39;: a sensor &amp; its &quot;wall&quot;\\x1b[31m"),
            std::string::npos);
  EXPECT_EQ(html.find("<b>desk"), std::string::npos);
  EXPECT_EQ(html.find('\x1b'), std::string::npos);
  EXPECT_NE(html.find("[sensor_near_surface]"), std::string::npos);
  // No warnings, no box.
  EXPECT_EQ(htmlReport(testing_sample::sampleReport()).find("class=\"warnings\""), std::string::npos);
}

TEST(WarningsReport, SummaryCsvIsUnchanged) {
  const fs::path a = fs::path(testing::TempDir()) / "candela_warn_csv_a";
  const fs::path b = fs::path(testing::TempDir()) / "candela_warn_csv_b";
  fs::remove_all(a);
  fs::remove_all(b);
  writeSummaryCsv(a, testing_sample::sampleReport());
  writeSummaryCsv(b, withWarnings());
  EXPECT_EQ(slurp(a / "summary.csv"), slurp(b / "summary.csv"));
}

}  // namespace
}  // namespace candela
