// The luminaire schedule, energy and surfaces as summary.json and report.html write them, from
// report data made here (the study's side is tests/study/luminaire_schedule_test.cpp).
#include "reports/installation_html.h"
#include "reports/html_report.h"
#include "reports/json_writer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <string>

#include "sample_report.h"

namespace candela {
namespace {

using nlohmann::json;

LuminaireTypeReport absoluteType() {
  LuminaireTypeReport t;
  t.file = "luminaires/<panel>.ies";
  t.entries = {"P"};
  t.luminaire = "Panel <A&B>";
  t.count = 12;
  t.fluxLm = 3600.0;
  t.maintenanceFactor = 0.8;
  t.polar = {PolarCurve{"C0-C180", {-90.0, 0.0, 90.0}, {0.0, 1000.0, 0.0}, "", false}};
  return t;
}

InstallationReport sampleInstallation() {
  InstallationReport in;
  in.luminaires = {absoluteType()};
  SurfaceMaterialReport wall{"wall_paint", "plastic", 0.62, 0.0, std::nullopt, 9};
  SurfaceMaterialReport glass{"clear_glass", "glass", 0.08, 0.08, 0.88, 3};
  in.surfaces = {wall, glass};
  in.energy.luminairesWithoutPower = {"P"};
  return in;
}

// Runs that do not set the installation (annual runs) write summary.json as before.
TEST(InstallationReport, AbsentWhenTheStudyGivesNone) {
  const json j = json::parse(summaryJson(testing_sample::sampleReport()));
  for (const char* key : {"luminaires", "surfaces", "energy"}) EXPECT_FALSE(j.contains(key)) << key;
  const std::string html = htmlReport(testing_sample::sampleReport());
  for (const char* s : {"Luminaire schedule", "<h2>Energy</h2>", "<h2>Surfaces</h2>"})
    EXPECT_EQ(html.find(s), std::string::npos) << s;
}

// What is unknown is null, never 0: absolute photometry has no lamp flux or LOR, an unknown power
// no efficacy, a scene without geometry no floor area and so no power density.
TEST(InstallationReport, JsonWritesUnknownsAsNull) {
  ReportData d = testing_sample::sampleReport();
  d.installation = sampleInstallation();
  const json j = json::parse(summaryJson(d));
  const json& t = j["luminaires"][0];
  EXPECT_EQ(t["file"], "luminaires/<panel>.ies");
  EXPECT_EQ(t["count"], 12);
  EXPECT_EQ(t["flux_lm"], 3600.0);
  for (const char* key : {"lamp_flux_lm", "power_w", "power_source", "light_output_ratio", "efficacy_lm_per_w"})
    EXPECT_TRUE(t[key].is_null()) << key;
  EXPECT_EQ(t["maintenance_factor"], 0.8);
  EXPECT_EQ(j["surfaces"][0]["material"], "wall_paint");
  EXPECT_TRUE(j["surfaces"][0]["transmittance"].is_null());
  EXPECT_EQ(j["surfaces"][1]["transmittance"], 0.88);
  const json& e = j["energy"];
  EXPECT_EQ(e["installed_power_w"], 0.0);
  EXPECT_EQ(e["installed_power_is_lower_bound"], true);
  EXPECT_EQ(e["luminaires_without_power"], json({"P"}));
  for (const char* key : {"floor_area_m2", "floor_area_source", "power_density_w_m2", "power_density_w_m2_per_100lx",
                          "reference_grid", "reference_grid_average_lux"})
    EXPECT_TRUE(e[key].is_null()) << key;
}

// The report names things as a reader does: materials without underscores (the scene's name in
// the tooltip), types in words, texts escaped; an unknown power and a missing reference grid are
// said, not shown as 0.
TEST(InstallationReport, HtmlUsesHumanNamesAndSaysWhatIsUnknown) {
  ReportData d = testing_sample::sampleReport();
  d.installation = sampleInstallation();
  const std::string html = htmlReport(d);
  for (const char* s : {"<td title=\"wall_paint\">wall paint</td>", "Plastic (diffuse, uncoloured highlight)",
                        "<td title=\"clear_glass\">clear glass</td>", "Glass (thin pane)", "Panel &lt;A&amp;B&gt;",
                        "Photometric file: luminaires/&lt;panel&gt;.ies", ">unknown<", "at least 0.0 W",
                        "no grid of horizontal illuminance to take Ē on",
                        "unknown: the scene has no geometry and the case gives no floor area"})
    EXPECT_NE(html.find(s), std::string::npos) << s;
  // The scene's identifiers appear only inside the title attributes, never as text.
  EXPECT_EQ(std::regex_search(html, std::regex(">[^<]*wall_paint")), false);
  // Sections in the order a reader scans them: schedule, energy, surfaces, then the grids.
  const std::size_t schedule = html.find("id=\"luminaires\""), energy = html.find("id=\"energy\""),
                    surfaces = html.find("id=\"surfaces\""), grid = html.find("id=\"grid-1\"");
  EXPECT_LT(schedule, energy);
  EXPECT_LT(energy, surfaces);
  EXPECT_LT(surfaces, grid);
}

TEST(InstallationReport, ReadableNamesAndMaterialTypes) {
  EXPECT_EQ(readableName("wall_paint_2"), "wall paint 2");
  EXPECT_EQ(readableName("Ceiling tile"), "Ceiling tile");
  EXPECT_EQ(materialTypeText("trans"), "Translucent");
  EXPECT_EQ(materialTypeText("metal"), "Metal (diffuse, coloured highlight)");
  EXPECT_EQ(materialTypeText("antimatter"), "antimatter");
}

}  // namespace
}  // namespace candela
