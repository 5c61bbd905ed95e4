#include "reports/annual_charts.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "reports/html_report.h"
#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// Every pixel of the map area of `m` has colour `c`.
bool mapIsUniform(const TemporalMap& m, Rgb8 c) {
  for (int y = m.mapTop; y < m.mapTop + 24 * m.hourPx; ++y)
    for (int x = m.mapLeft; x < m.mapLeft + m.days * m.dayPx; ++x)
      if (!(m.image.at(x, y) == c)) return false;
  return true;
}

TEST(TemporalMap, ConstantSeriesIsOneColourOverTheWholeYear) {
  const std::vector<HourStamp> hours = testing_sample::sampleYearStamps();
  const TemporalMap m = temporalMap(std::vector<double>(hours.size(), 500.0), hours);
  EXPECT_EQ(m.days, 365);
  EXPECT_EQ(m.dayPx, 2);
  EXPECT_EQ(m.hourPx, 10);
  // The map fits in the picture with room for the labels and the legend.
  EXPECT_GE(m.image.width, m.mapLeft + 365 * 2 + 60);
  EXPECT_GE(m.image.height, m.mapTop + 24 * 10 + 14);
  // 500 lx on the 10–100 000 lx log scale sits at log10(50)/4 of the colour map.
  const ColorScale scale{10.0, 100000.0, true};
  EXPECT_NEAR(scalePosition(500.0, scale), std::log10(50.0) / 4.0, 1e-12);
  EXPECT_TRUE(mapIsUniform(m, viridis(std::log10(50.0) / 4.0)));
  // Clamped ends: 0 lx (night) is the bottom colour, 1e6 lx the top.
  EXPECT_TRUE(mapIsUniform(temporalMap(std::vector<double>(hours.size(), 0.0), hours), viridis(0.0)));
  EXPECT_TRUE(mapIsUniform(temporalMap(std::vector<double>(hours.size(), 1e6), hours), viridis(1.0)));
}

TEST(TemporalMap, PlacesEachHourAtItsDayAndHour) {
  std::vector<HourStamp> hours = testing_sample::sampleYearStamps();
  std::vector<double> lux(hours.size(), 10.0);
  // 21 June is day 171 (0-based) of a non-leap year: 31+28+31+30+31+20; hour ending 13 is row 12.
  std::size_t june21at13 = 0;
  for (std::size_t i = 0; i < hours.size(); ++i)
    if (hours[i] == HourStamp{6, 21, 13}) june21at13 = i;
  lux[june21at13] = 100000.0;
  const TemporalMap m = temporalMap(lux, hours);
  const int x = m.mapLeft + 171 * m.dayPx, y = m.mapTop + 12 * m.hourPx;
  for (int dy = 0; dy < m.hourPx; ++dy)
    for (int dx = 0; dx < m.dayPx; ++dx) EXPECT_EQ(m.image.at(x + dx, y + dy), viridis(1.0));
  EXPECT_EQ(m.image.at(x - 1, y), viridis(0.0));
  EXPECT_EQ(m.image.at(x, y - 1), viridis(0.0));
  EXPECT_EQ(m.image.at(x + m.dayPx, y + m.hourPx), viridis(0.0));
}

TEST(TemporalMap, LeapYearIsWiderAndMissingHoursStayGrey) {
  std::vector<HourStamp> hours;
  for (int h = 1; h <= 24; ++h) hours.push_back({2, 29, static_cast<uint8_t>(h)});
  const TemporalMap m = temporalMap(std::vector<double>(24, 1000.0), hours);
  EXPECT_EQ(m.days, 366);
  const Rgb8 grey{225, 225, 225};
  EXPECT_EQ(m.image.at(m.mapLeft, m.mapTop), grey);  // 1 January: no data
  EXPECT_EQ(m.image.at(m.mapLeft + 59 * m.dayPx, m.mapTop), viridis(0.5));  // 29 Feb = day 59; 1000 lx mid-scale
  EXPECT_THROW(temporalMap({1.0}, {}), std::invalid_argument);
  EXPECT_THROW(temporalMap({1.0}, {HourStamp{2, 30, 1}}), std::invalid_argument);
}

TEST(SdaAsePlan, MarksPassingSensorsAndAseExceedances) {
  const GridReport g = testing_sample::sampleGrid("g", 0.0, 0.0, 2.0, 1.0, 0.5);  // 4 × 2 cells
  const std::vector<bool> pass = {true, true, false, false, true, false, false, false};
  const std::vector<bool> ase = {true, false, false, false, false, false, false, true};
  const std::string svg = sdaAsePlanSvg(g.layout, pass, ase);
  EXPECT_EQ(count(svg, std::string("fill=\"") + kSdaPassColor + "\"/>"), 3u + 1u);  // 3 cells + legend swatch
  EXPECT_EQ(count(svg, std::string("fill=\"") + kSdaFailColor + "\"/>"), 5u + 1u);
  EXPECT_EQ(count(svg, "class=\"ase\""), 2u);
  EXPECT_NE(svg.find("DA300 ≥ 50 %: 3 of 8 sensors"), std::string::npos);
  EXPECT_NE(svg.find("(ASE): 2"), std::string::npos);
}

TEST(SdaAsePlan, VerdictsAreTheSensorsOwn) {
  AnnualGridReport a;
  a.sensors.resize(3);
  a.sensors[0].sdaPass = true;
  a.sensors[1].aseExceeded = true;
  a.sensors[2].sdaPass = true;
  a.sensors[2].aseExceeded = true;
  EXPECT_EQ(sdaPassPerSensor(a), (std::vector<bool>{true, false, true}));
  EXPECT_EQ(aseExceededPerSensor(a), (std::vector<bool>{false, true, true}));
}

std::string annualReportHtml() {
  const char* target = std::getenv("CANDELA_SAMPLE_ANNUAL_REPORT");
  const fs::path path =
      target ? fs::path(target) : fs::path(testing::TempDir()) / "candela_annual_report" / "report.html";
  writeHtmlReport(path, testing_sample::sampleAnnualReport());
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HtmlReport, AnnualSectionHasTheMetricsPlansAndTemporalMap) {
  const ReportData data = testing_sample::sampleAnnualReport();
  const std::size_t i = data.grids.size() - 1;
  const GridAnnualSummary& s = data.grids[i].annual->summary;
  const std::string html = annualReportHtml();
  const std::string id = "id=\"annual-" + std::to_string(i + 1) + "\"";
  const std::size_t at = html.find(id);
  ASSERT_NE(at, std::string::npos);
  const std::string section = html.substr(at, html.find("</section>", at) - at);
  EXPECT_NE(section.find("Annual daylight: Daylit office"), std::string::npos);
  // Every metric under its human name (never the summary.json key).
  for (const auto& [name, v] : std::vector<std::pair<std::string, double>>{
           {"Daylight autonomy DA<sub>300</sub>", s.DA300},
           {"Continuous daylight autonomy cDA<sub>300</sub>", s.cDA300},
           {"Useful daylight illuminance, fell short (UDI-f)", s.UDI_fell_short},
           {"UDI supplementary (UDI-s)", s.UDI_supplementary},
           {"UDI autonomous (UDI-a)", s.UDI_autonomous},
           {"UDI exceeded (UDI-e)", s.UDI_exceeded},
           {"Spatial daylight autonomy sDA<sub>300/50%</sub>", s.sDA300_50},
           {"Annual sunlight exposure ASE<sub>1000,250</sub>", s.ASE1000_250}})
    EXPECT_NE(section.find("<td>" + name + "</td><td class=\"num\">" + formatFixed(v, 1) + " %</td>"),
              std::string::npos)
        << name << " " << v;
  for (const char* key : {"UDI_fell_short", "UDI_supplementary", "UDI_autonomous", "UDI_exceeded", "sDA300_50",
                          "ASE1000_250", "coefficients_time_s"}) {
    EXPECT_EQ(section.find(std::string("<td>") + key), std::string::npos) << key;
    EXPECT_EQ(section.find(std::string("<figcaption>") + key), std::string::npos) << key;  // plans' captions
  }
  EXPECT_NE(section.find("<figcaption>UDI-a, autonomous (300–3000 lx)"), std::string::npos);
  // LEED v4.1 option 1's points for the sDA (1 from 40 %, 2 from 55 %, 3 from 75 %) and the
  // ASE's 10 %.
  const int points = s.sDA300_50 >= 75.0 ? 3 : s.sDA300_50 >= 55.0 ? 2 : s.sDA300_50 >= 40.0 ? 1 : 0;
  EXPECT_NE(section.find("LEED v4.1 option 1: " + std::to_string(points) + " point"), std::string::npos);
  EXPECT_NE(section.find(s.ASE1000_250 > 10.0 ? "above LEED v4.1's 10 %" : "within LEED v4.1's 10 %"),
            std::string::npos);
  EXPECT_NE(section.find("<td>Occupied hours</td><td class=\"num\">3650</td>"), std::string::npos);
  EXPECT_NE(section.find("<td>Daylight-coefficient time</td><td class=\"num\">12.50 s</td>"), std::string::npos);
  EXPECT_NE(section.find("<td>Hourly product time</td><td class=\"num\">0.75 s</td>"), std::string::npos);
  // DA plan + four UDI small multiples + the sDA/ASE plan.
  EXPECT_EQ(count(section, "<svg "), 6u);
  EXPECT_EQ(count(section, "class=\"plan sda-ase\""), 1u);
  // The sample's window-side sensors get sun, so some are crossed; the data has both verdicts.
  EXPECT_GT(s.ASE1000_250, 0.0);
  EXPECT_GT(s.sDA300_50, 0.0);
  EXPECT_LT(s.sDA300_50, 100.0);
  EXPECT_GT(count(section, "class=\"ase\""), 0u);
  // The temporal map is an embedded PNG of the documented size.
  const TemporalMap m = temporalMap(data.grids[i].annual->chosenSensorLux, data.grids[i].annual->hours);
  EXPECT_NE(section.find("alt=\"temporal map of sensor " + std::to_string(data.grids[i].annual->chosenSensor) +
                         "\" width=\"" + std::to_string(m.image.width) + "\" height=\"" +
                         std::to_string(m.image.height) + "\" src=\"data:image/png;base64,"),
            std::string::npos);
  // Plan element ids stay unique on the page.
  const std::regex ids(R"re( id="([^"]+)")re");
  std::vector<std::string> seen;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ids); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(std::find(seen.begin(), seen.end(), (*it)[1].str()), seen.end()) << (*it)[1].str();
    seen.push_back((*it)[1].str());
  }
  // Still self-contained: no external references.
  EXPECT_EQ(html.find("http"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(src="(?!data:image/png;base64,))")));
  // The plain grids keep no annual section.
  EXPECT_EQ(count(html, "class=\"grid annual\""), 1u);
}

}  // namespace
}  // namespace candela
