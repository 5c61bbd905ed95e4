#include "study/case/case_compliance.h"

#include "base/error.h"

#include <gtest/gtest.h>

#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

const std::string kHead =
    "[sky]\ntype = \"annual\"\nweather = \"../../epw/synthetic_golden_2026.epw\"\n"
    "[[grid]]\nname = \"workplane\"\ncorners = [[0, 0], [2, 2]]\nheight = 0.8\nspacing = 0.5\n";

fs::path casePath() { return fs::path(CANDELA_TEST_DATA) / "cases" / "errors" / "annual.toml"; }

// "LINE: message" of the error a case text raises, or "accepted".
std::string error(const std::string& text) {
  try {
    parseCaseFile(text, casePath());
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

bool says(const std::string& text, int line, const std::string& what) {
  const std::string e = error(text);
  const bool ok = e.rfind(std::to_string(line) + ": ", 0) == 0 && e.find(what) != std::string::npos;
  if (!ok) ADD_FAILURE() << "got: " << e;
  return ok;
}

TEST(CaseCompliance, ReadsEveryKeyOfEachStandard) {
  const CaseFile c = parseCaseFile(kHead +
                                       "[[compliance]]\nstandard = \"en17037\"\nspaces = [\"workplane\"]\n"
                                       "aggregation = \"sensor-first\"\nsunlight_date = \"2026-02-14\"\n"
                                       "sunlight_points = [[1, 0.1, 1.2], [1.5, 0.1, 1.2]]\nsunlight_min_altitude = 12\n"
                                       "view_points = [[1, 1, 1.2]]\n"
                                       "glare_views = [{ position = [1, 1, 1.2], direction = [0, -2, 0], "
                                       "check_hours = [\"2026-01-15T12:00\"] }]\n"
                                       "glare_exceedance = 0.1\n"
                                       "[[compliance]]\nstandard = \"leed-v4.1-option1\"\n"
                                       "[[compliance]]\nstandard = \"leed-v4.1-option2\"\nname = \"leed2\"\n"
                                       "dates = [2026-03-25, \"2026-09-10\"]\nhours = [9, 15.5]\n",
                                   casePath());
  ASSERT_EQ(c.compliance.size(), 3u);
  const ComplianceSpec& en = c.compliance[0];
  EXPECT_EQ(en.name, "en17037");
  EXPECT_EQ(en.spaces, std::vector<std::string>{"workplane"});
  EXPECT_EQ(en.aggregation, ProvisionAggregation::kSensorFirst);
  ASSERT_TRUE(en.sunlightDate);
  EXPECT_EQ(en.sunlightDate->month, 2);
  EXPECT_EQ(en.sunlightDate->day, 14);
  ASSERT_EQ(en.sunlightPoints.size(), 2u);
  EXPECT_DOUBLE_EQ(en.sunlightPoints[1].x, 1.5);
  EXPECT_DOUBLE_EQ(*en.sunlightMinAltitudeDeg, 12.0);
  ASSERT_EQ(en.glareViews.size(), 1u);
  EXPECT_DOUBLE_EQ(en.glareViews[0].direction.y, -1.0);  // made unit
  EXPECT_DOUBLE_EQ(en.glareExceedance, 0.1);
  EXPECT_EQ(en.glareViews[0].checkHours, std::vector<std::string>{"2026-01-15T12:00"});
  EXPECT_EQ(c.compliance[1].name, "leed-v4.1-option1");
  EXPECT_TRUE(c.compliance[1].spaces.empty());  // every grid
  const ComplianceSpec& l2 = c.compliance[2];
  EXPECT_EQ(l2.name, "leed2");
  ASSERT_EQ(l2.leedDates.size(), 2u);
  EXPECT_EQ(l2.leedDates[1].month, 9);
  EXPECT_EQ(l2.leedHours, (std::vector<double>{9.0, 15.5}));
}

TEST(CaseCompliance, DefaultsAreTheStandardsOwn) {
  const CaseFile c = parseCaseFile(kHead + "[[compliance]]\nstandard = \"en17037\"\n", casePath());
  const ComplianceSpec& s = c.compliance.at(0);
  EXPECT_EQ(s.aggregation, ProvisionAggregation::kHourFirst);
  EXPECT_FALSE(s.sunlightDate);
  EXPECT_FALSE(s.sunlightMinAltitudeDeg);
  EXPECT_DOUBLE_EQ(s.glareExceedance, 0.05);
  EXPECT_EQ(s.leedHours, (std::vector<double>{9.0, 15.0}));
}

TEST(CaseCompliance, GlareViewsAsAnArrayOfTables) {
  // The multi-line form, [[compliance.glare_views]], reads as the inline one; its errors name
  // the line of the bad key.
  const std::string entry = kHead + "[[compliance]]\nstandard = \"en17037\"\n[[compliance.glare_views]]\n"
                                    "position = [1, 1, 1.2]\ndirection = [0, 3, 0]\n"
                                    "check_hours = [\"2026-06-01T10:00\"]\n[[compliance.glare_views]]\n"
                                    "position = [1.5, 1, 1.2]\ndirection = [1, 0, 0]\n";
  const CaseFile c = parseCaseFile(entry, casePath());
  const ComplianceSpec& en = c.compliance.at(0);
  ASSERT_EQ(en.glareViews.size(), 2u);
  EXPECT_DOUBLE_EQ(en.glareViews[0].direction.y, 1.0);
  EXPECT_EQ(en.glareViews[0].checkHours, std::vector<std::string>{"2026-06-01T10:00"});
  EXPECT_DOUBLE_EQ(en.glareViews[1].positionM.x, 1.5);
  EXPECT_TRUE(en.glareViews[1].checkHours.empty());
  const int first = 9;  // the line of [[compliance]] after kHead's eight lines
  EXPECT_TRUE(says(kHead + "[[compliance]]\nstandard = \"en17037\"\n[[compliance.glare_views]]\n"
                           "position = [1, 1, 1.2]\ndirection = [0, 1, 0]\ncheck_hours = [\"noon\"]\n",
                   first + 5, "noon"));
}

TEST(CaseCompliance, BadEntriesAreErrorsAtTheirLine) {
  const int first = 9;  // the line of [[compliance]] after kHead
  const std::string c = kHead + "[[compliance]]\n";
  EXPECT_TRUE(says(c + "standard = \"breeam\"\n", first + 1, "unknown standard 'breeam'"));
  EXPECT_TRUE(says(c, first, "needs the key 'standard'"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nspaces = [\"office\"]\n", first + 2, "no grid of the case"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nsunlight_date = \"2026-03-22\"\n", first + 2,
                   "between 1 February and 21 March"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nsunlight_date = \"2026-02-30\"\n", first + 2, "not a date"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\naggregation = \"space-first\"\n", first + 2, "hour-first"));
  EXPECT_TRUE(says(c + "standard = \"leed-v4.1-option1\"\nview_points = [[1, 1, 1.2]]\n", first + 2,
                   "belongs to standard = \"en17037\""));
  EXPECT_TRUE(says(c + "standard = \"leed-v4.1-option2\"\ndates = [\"2026-06-21\"]\n", first + 2,
                   "within 15 days of 21 March or 21 September"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nglare_views = [{ position = [1, 1, 1.2], direction = [0, 1, 0], "
                       "hours = [] }]\n",
                   first + 2, "unknown key 'hours' in a glare view"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nglare_views = [{ position = [1, 1, 1.2] }]\n", first + 2,
                   "needs the key 'direction'"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\nsunlight = 1\n", first + 2, "unknown key 'sunlight'"));
  EXPECT_TRUE(says(c + "standard = \"en17037\"\n[[compliance]]\nstandard = \"en17037\"\n", first + 2,
                   "two [[compliance]] entries are named 'en17037'"));
  // A point-in-time case cannot be checked against these standards.
  const std::string pit = "[[grid]]\nname = \"g\"\ncorners = [[0, 0], [2, 2]]\nheight = 0.8\n"
                          "[[compliance]]\nstandard = \"en17037\"\n";
  EXPECT_TRUE(says(pit, 5, "needs an annual study"));
}

}  // namespace
}  // namespace candela
