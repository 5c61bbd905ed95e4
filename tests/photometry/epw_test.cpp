#include "photometry/epw.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <cmath>
#include <sstream>
#include <vector>

namespace candela {
namespace {

const std::string kDir = std::string(CANDELA_TEST_DATA) + "/epw/";

TEST(Epw, ReadsSyntheticThreeDays) {
  const EpwFile f = readEpw(kDir + "synthetic_3day.epw");
  EXPECT_EQ(f.location.city, "Golden SYNTHETIC");
  EXPECT_DOUBLE_EQ(f.location.latitudeDeg, 39.74);
  EXPECT_DOUBLE_EQ(f.location.longitudeDeg, -105.18);
  EXPECT_DOUBLE_EQ(f.location.timezoneHours, -7.0);
  EXPECT_DOUBLE_EQ(f.location.elevationM, 1829.0);
  ASSERT_EQ(f.records.size(), 72u);
  EXPECT_FALSE(f.isFullYear());
  const EpwRecord& noon = f.records[12];  // 2026-01-01, hour ending 13:00
  EXPECT_EQ(noon.month, 1);
  EXPECT_EQ(noon.day, 1);
  EXPECT_EQ(noon.hour, 13);
  EXPECT_EQ(noon.line, 21);
  EXPECT_GT(noon.directNormalWhm2, 0.0);
  // The synthetic generator writes illuminance = 100 lm/W x direct normal (rounded).
  EXPECT_NEAR(noon.directNormalLux, 100.0 * noon.directNormalWhm2, 100.0);
  EXPECT_EQ(f.records[0].globalHorizontalWhm2, 0.0);  // 00:00-01:00 is night
}

TEST(Epw, ReadsSyntheticFullYear) {
  const EpwFile f = readEpw(kDir + "synthetic_golden_2026.epw");
  EXPECT_EQ(f.records.size(), 8760u);
  EXPECT_TRUE(f.isFullYear());
  EXPECT_EQ(f.records.back().month, 12);
  EXPECT_EQ(f.records.back().day, 31);
  EXPECT_EQ(f.records.back().hour, 24);
  EXPECT_EQ(f.records.back().line, 8768);
}

TEST(Epw, MissingValuesBecomeNaN) {
  std::istringstream in(
      "LOCATION,X,,,,,10,20,1,5\nA\nB\nC\nD\nE\nF\nG\n"
      "2026,1,1,12,60,flags,99.9,5,50,82000,0,0,300,9999,9999,9999,999999,999999,999999,0,"
      "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n");
  const EpwFile f = parseEpw(in, "mem.epw");
  ASSERT_EQ(f.records.size(), 1u);
  EXPECT_TRUE(std::isnan(f.records[0].dryBulbC));
  EXPECT_TRUE(std::isnan(f.records[0].directNormalWhm2));
  EXPECT_TRUE(std::isnan(f.records[0].diffuseHorizontalLux));
}

struct ErrorCase {
  const char* file;
  int line;
  const char* text;
};

class EpwErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(EpwErrors, ReportFileAndLine) {
  const ErrorCase c = GetParam();
  try {
    readEpw(kDir + c.file);
    FAIL() << c.file;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, c.line) << e.what();
    const std::string prefix = std::string(c.file) + ":" + std::to_string(c.line) + ": ";
    EXPECT_NE(std::string(e.what()).find(prefix), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.text), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, EpwErrors,
    ::testing::Values(ErrorCase{"bad_field_count.epw", 11, "has 20 fields, expected 35"},
                      ErrorCase{"bad_number.epw", 10, "bad number 'abc' for direct normal radiation"},
                      ErrorCase{"bad_hour.epw", 12, "hour 25 is outside 1..24"},
                      ErrorCase{"bad_location.epw", 1, "bad number 'north' for latitude"},
                      // 8760 copies of one hour once passed for a year (DA 100 % instead of 92.5 %).
                      ErrorCase{"repeated_hour.epw", 21, "record 01-01 hour 12 follows 01-01 hour 12: the hour is repeated"},
                      ErrorCase{"missing_hour.epw", 21, "record 01-01 hour 14 follows 01-01 hour 12: hours are missing"}));

TEST(Epw, RecordsRunThroughTheYearInOrder) {
  // The full test year parses (day ends, month ends, 28 February to 1 March), and is a year.
  const EpwFile y = readEpw(kDir + "synthetic_golden_2026.epw");
  ASSERT_EQ(y.records.size(), 8760u);
  EXPECT_TRUE(y.isFullYear());
  // Three days from 1 January are hour by hour but not a year.
  EXPECT_FALSE(readEpw(kDir + "synthetic_3day.epw").isFullYear());
}

TEST(Epw, EveryReferenceWeatherFileIsAYearInOrder) {
  // Files nobody here wrote (tests/data/reference/weather, SOURCES.md): several sources and formats
  // (all four are 365-day years; a leap year made from one of them is the next test).
  const std::filesystem::path dir = std::filesystem::path(CANDELA_REFERENCE) / "weather";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".epw") continue;
    ++files;
    const EpwFile f = readEpw(e.path().string());
    EXPECT_TRUE(f.isFullYear()) << e.path() << ": " << f.records.size() << " records";
  }
  EXPECT_GE(files, 4);
}

// A leap year from a real file: chicago.epw (8760 records) with 29 February inserted, its 24
// records those of 28 February with the day changed, is 8784 records in order and a full year.
TEST(Epw, LeapYearOfARealFileIsAYearInOrder) {
  std::ifstream in(std::filesystem::path(CANDELA_REFERENCE) / "weather" / "chicago.epw");
  std::ostringstream leap;
  std::vector<std::string> february28;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string year, month, day;
    std::getline(fields, year, ',');
    std::getline(fields, month, ',');
    std::getline(fields, day, ',');
    const bool feb28 = month == "2" && day == "28";
    if (!feb28 && !february28.empty()) {  // the first record after 28 February
      for (const std::string& r : february28) leap << year << ",2,29," << r << "\n";
      february28.clear();
    }
    if (feb28) february28.push_back(line.substr(year.size() + month.size() + day.size() + 3));
    leap << line << "\n";
  }
  std::istringstream text(leap.str());
  const EpwFile f = parseEpw(text, "chicago_leap.epw");
  EXPECT_EQ(f.records.size(), 8784u);
  EXPECT_TRUE(f.isFullYear());
}

TEST(Epw, ByteOrderMarkBeforeLocation) {
  const EpwFile a = readEpw(kDir + "bom.epw"), b = readEpw(kDir + "synthetic_3day.epw");
  EXPECT_EQ(a.location.city, b.location.city);
  EXPECT_EQ(a.records.size(), b.records.size());
}

TEST(Epw, MissingMarksAreCountedNotRefused) {
  // -999 (Meteonorm), an empty field and 9999 (the data dictionary's mark) are missing values;
  // a Meteonorm file with -999 was once refused as "negative irradiation".
  const EpwFile f = readEpw(kDir + "missing_marks.epw");
  EXPECT_EQ(f.missingIrradianceHours, 3);
  EXPECT_TRUE(std::isnan(f.records[12].directNormalWhm2));   // -999
  EXPECT_TRUE(std::isnan(f.records[13].diffuseHorizontalWhm2));  // empty
  EXPECT_TRUE(std::isnan(f.records[14].directNormalWhm2));   // 9999
  EXPECT_FALSE(std::isnan(f.records[15].directNormalWhm2));
  EXPECT_EQ(readEpw(kDir + "synthetic_3day.epw").missingIrradianceHours, 0);
}

TEST(Epw, MissingFile) {
  EXPECT_THROW(readEpw(kDir + "no_such.epw"), InputError);
}

}  // namespace
}  // namespace candela
