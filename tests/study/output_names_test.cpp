// Every output name of a case is checked before tracing: two entries that would write the same
// file are an input error naming both, at the later entry's line.
#include "study/output_names.h"

#include "base/error.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

std::string collision(const std::string& toml) {
  const CaseFile c = parseCaseFile(toml, std::filesystem::path(CANDELA_TEST_DATA) / "study" / "names.toml");
  try {
    checkOutputNames(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kGrid = R"(
[[grid]]
name = "%s"
corners = [[0.0, 0.0], [1.0, 1.0]]
height = 0.8
spacing = 0.5
)";

const char* kView = R"(
[[view]]
name = "%s"
position = [0.5, 0.5, 1.2]
direction = [0.0, 1.0, 0.0]
)";

std::string entry(const char* pattern, const std::string& name) {
  char buf[512];
  std::snprintf(buf, sizeof buf, pattern, name.c_str());
  return buf;
}

const std::string kAnnualSky = R"(
[sky]
type = "annual"
weather = "../epw/synthetic_golden_2026.epw"
)";

TEST(OutputNames, AnnualGridDirectSunFileIsClaimedOnce) {
  const std::string e = collision(kAnnualSky + entry(kGrid, "desk") + entry(kGrid, "desk_direct_sun"));
  EXPECT_NE(e.find("grids 'desk' and 'desk_direct_sun' would both write desk_direct_sun_hourly.f32"), std::string::npos)
      << e;
  EXPECT_NE(e.find("names.toml:"), std::string::npos) << e;
}

TEST(OutputNames, ViewsWithTheSameFiles) {
  EXPECT_NE(collision(entry(kGrid, "g") + entry(kView, "v") + entry(kView, "v")).find("views 'v' and 'v' would both write v.exr"),
            std::string::npos);
  EXPECT_NE(collision(entry(kGrid, "g") + entry(kView, "a/b") + entry(kView, "a_b")).find("views 'a/b' and 'a_b'"),
            std::string::npos);
  EXPECT_NE(collision(entry(kGrid, "g") + entry(kView, "x") + entry(kView, "x_preview"))
                .find("views 'x' and 'x_preview' would both write x_preview.png"),
            std::string::npos);
}

TEST(OutputNames, GridAgainstViewAndReservedNames) {
  EXPECT_NE(collision(entry(kGrid, "summary")).find("grid name 'summary' would overwrite summary.csv"), std::string::npos);
  EXPECT_EQ(collision(entry(kGrid, "desk") + entry(kGrid, "desk_direct_sun") + entry(kView, "desk")), "no error");
}

TEST(OutputNames, LineOfTheLaterEntry) {
  try {
    checkOutputNames(parseCaseFile(entry(kGrid, "a b") + entry(kGrid, "a_b"), "c.toml"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 8);
  }
}

}  // namespace
}  // namespace candela
