// `candela run` with daylight: a daylight-factor grid on an open ground under the CIE overcast
// sky. A horizontal sensor there sees the whole sky and no ground, so E = E_h,outside and
// DF = 100 % at every point. The tolerance, 1 %, is the validation suite's; the estimate's own
// standard error here is ~0.02 % (sky sampling of a smooth sky).
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#ifndef CANDELA_EXE
#error "CANDELA_EXE must be defined by tests/CMakeLists.txt"
#endif

namespace {

namespace fs = std::filesystem;

TEST(RunDaylight, OpenGroundHasDaylightFactor100EverywhereInCsvAndSummary) {
  const fs::path caseFile = fs::path(CANDELA_TEST_DATA).parent_path() / "cli/run/daylight_factor/case.toml";
  const fs::path out = fs::temp_directory_path() / ("candela_df_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const std::string cmd = std::string("\"") + CANDELA_EXE + "\" run \"" + caseFile.string() + "\" --out \"" +
                          out.string() + "\" --quiet --quality draft > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);

  std::ifstream js(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(js);
  const auto& g = j["grids"][0];
  EXPECT_EQ(g["unit"], "%");
  EXPECT_EQ(g["quantity"], "Daylight factor");
  EXPECT_NEAR(g["average"].get<double>(), 100.0, 1.0);
  EXPECT_NEAR(g["minimum"].get<double>(), 100.0, 1.0);
  EXPECT_NEAR(g["median"].get<double>(), 100.0, 1.0);

  // The grid CSV keeps lux and adds the daylight factor per point.
  std::ifstream csv(out / "df.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "x,y,z,dx,dy,dz,illuminance_lux,error_lux,daylight_factor_pct");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) {
    std::stringstream ss(line);
    std::string field;
    std::vector<double> v;
    while (std::getline(ss, field, ',')) v.push_back(std::stod(field));
    ASSERT_EQ(v.size(), 9u);
    EXPECT_NEAR(v[6], 10000.0, 100.0);
    EXPECT_NEAR(v[8], v[6] / 100.0, 1e-3 * v[8]);  // DF = 100 E / 10000 lux, to the printed digits
    ++rows;
  }
  EXPECT_EQ(rows, 16);
  fs::remove_all(out);
}

}  // namespace
