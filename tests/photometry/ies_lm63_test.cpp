#include "photometry/ies_lm63.h"

#include "base/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

const std::string kIes = std::string(CANDELA_TEST_DATA) + "/ies/";

TEST(IesLm63, EditionsAndKeywords) {
  const PhotometricWeb a = readIes(kIes + "lambert_full.ies");
  EXPECT_EQ(a.format(), "IES LM-63-2002");
  EXPECT_EQ(a.keywords().at("MANUFAC"), "candela test fixture");
  EXPECT_DOUBLE_EQ(a.lampLumens(), 4000.0);
  EXPECT_DOUBLE_EQ(a.inputWatts(), 40.0);
  EXPECT_EQ(readIes(kIes + "lambert_rot.ies").format(), "IES LM-63-1995");
  EXPECT_EQ(readIes(kIes + "linear_2019.ies").format(), "IES LM-63-2019");
  EXPECT_EQ(readIes(kIes + "linear_1991.ies").format(), "IES LM-63-1991");
  const PhotometricWeb old = readIes(kIes + "linear_1986.ies");
  EXPECT_EQ(old.format(), "IES LM-63-1986");
  EXPECT_NE(old.keywords().at("TEXT").find("LM-63-1986 layout"), std::string::npos);
}

TEST(IesLm63, CommasAndWrappedLinesReadLikeBlanks) {
  // lambert_full.ies separates numbers with ", " and wraps 7 per line.
  const PhotometricWeb web = readIes(kIes + "lambert_full.ies");
  EXPECT_NEAR(web.intensityCd(30.0, 60.0), 500.0, 1e-9);
  EXPECT_NEAR(web.intensityCd(300.0, 85.0), 87.155743, 1e-9);
}

TEST(IesLm63, MultipliersAndGenerationType) {
  // 2019: the third number of line "ballast factor ..." is the file generation type 1.10001,
  // not a multiplier; absolute photometry (lumens -1).
  const PhotometricWeb y2019 = readIes(kIes + "linear_2019.ies");
  EXPECT_DOUBLE_EQ(y2019.intensityCd(0.0, 0.0), 1000.0);
  EXPECT_DOUBLE_EQ(y2019.info().fileGenerationType, 1.10001);
  EXPECT_TRUE(y2019.isAbsolute());
  EXPECT_LE(y2019.lampLumens(), 0.0);
  EXPECT_TRUE(std::isnan(y2019.lightOutputRatio()));
  // 1991: values 500 x candela multiplier 2 x ballast 0.95 x ballast-lamp factor 0.9.
  const PhotometricWeb y1991 = readIes(kIes + "linear_1991.ies");
  EXPECT_NEAR(y1991.intensityCd(0.0, 0.0), 500.0 * 2.0 * 0.95 * 0.9, 1e-9);
  EXPECT_DOUBLE_EQ(y1991.lampLumens(), 5000.0);
}

TEST(IesLm63, TiltAppliedAtInstalledAngle) {
  // Table 0/30/60/90 deg -> 0.8/0.85/0.9/1.0; the test orientation (0 deg) gives 0.8.
  const PhotometricWeb inc = readIes(kIes + "tilt_include.ies");
  EXPECT_NEAR(inc.intensityCd(0.0, 0.0), 800.0, 1e-9);
  EXPECT_EQ(inc.info().tilt.source, "INCLUDE");
  EXPECT_EQ(inc.info().tilt.lampGeometry, 1);
  const PhotometricWeb at45 = readIes(kIes + "tilt_include.ies", IesOptions{45.0});
  EXPECT_NEAR(at45.intensityCd(0.0, 0.0), 875.0, 1e-9);  // halfway between 0.85 and 0.9
  const PhotometricWeb file = readIes(kIes + "tilt_file.ies");
  EXPECT_NEAR(file.intensityCd(0.0, 0.0), 800.0, 1e-9);
  EXPECT_EQ(file.info().tilt.source, "tilt_table.tlt");
}

TEST(IesLm63, OpeningUnitsAndShapes) {
  const PhotometricWeb ft = readIes(kIes + "feet_rect.ies");  // 2 ft x 4 ft
  EXPECT_NEAR(ft.openingWidthM(), 2.0 * 0.3048, 1e-12);
  EXPECT_NEAR(ft.openingLengthM(), 4.0 * 0.3048, 1e-12);
  EXPECT_DOUBLE_EQ(ft.openingHeightM(), 0.0);
  EXPECT_EQ(ft.openingShape(), OpeningShape::kRectangular);
  const PhotometricWeb circ = readIes(kIes + "metres_circle.ies");  // -0.2 -0.2 0
  EXPECT_EQ(circ.openingShape(), OpeningShape::kCircular);
  EXPECT_NEAR(circ.openingWidthM(), 0.2, 1e-12);
  EXPECT_EQ(readIes(kIes + "lambert_rot.ies").openingShape(), OpeningShape::kPoint);
  // LM-63-2019 table 1 sign conventions.
  EXPECT_EQ(iesOpeningShape(-1, -1, -1), OpeningShape::kSphere);
  EXPECT_EQ(iesOpeningShape(-1, -1, 2), OpeningShape::kVerticalCylinder);
  EXPECT_EQ(iesOpeningShape(-1, 3, -1), OpeningShape::kHorizontalCylinderAlongLength);
  EXPECT_EQ(iesOpeningShape(3, -1, -1), OpeningShape::kHorizontalCylinderAlongWidth);
  EXPECT_EQ(iesOpeningShape(-1, -2, 0), OpeningShape::kEllipse);
  EXPECT_EQ(iesOpeningShape(1, 2, 0.5), OpeningShape::kRectangularWithSides);
  EXPECT_EQ(iesOpeningShape(-1, 0, -1), OpeningShape::kVerticalCircle);
  EXPECT_EQ(iesOpeningShape(-0.3, 0, 0), OpeningShape::kCircular);  // pre-2019 round
}

struct BadFile {
  const char* name;
  int line;
  const char* text;  // part of the message
};

class IesErrors : public testing::TestWithParam<BadFile> {};

TEST_P(IesErrors, NamesFileAndLine) {
  const BadFile& b = GetParam();
  try {
    readIes(kIes + b.name);
    FAIL() << b.name << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, b.line) << e.what();
    const std::string what = e.what();
    EXPECT_NE(what.find(std::string(b.name) + ":" + std::to_string(b.line) + ": "), std::string::npos) << what;
    EXPECT_NE(what.find(b.text), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, IesErrors,
    testing::Values(BadFile{"bad_truncated.ies", 11, "truncated"},
                    BadFile{"bad_huge_counts.ies", 8, "46341 vertical x 46341 horizontal angles need"},
                    BadFile{"bad_count.ies", 13, "after the candela table"},
                    BadFile{"bad_angles.ies", 8, "vertical angles must increase"},
                    BadFile{"bad_negative.ies", 11, "negative candela"},
                    BadFile{"bad_type.ies", 6, "unknown photometric type 4"},
                    BadFile{"bad_type_a.ies", 6, "type A"},
                    BadFile{"bad_number.ies", 7, "bad number '4O'"},
                    BadFile{"bad_units.ies", 6, "units type"},
                    BadFile{"bad_no_tilt.ies", 12, "no TILT= line"},
                    BadFile{"bad_tilt_file.ies", 5, "cannot open TILT file"},
                    BadFile{"bad_tilt_multiplier.ies", 9, "TILT multiplier"},
                    BadFile{"bad_lumens.ies", 6, "lumens per lamp"},
                    BadFile{"bad_horizontal.ies", 10, "not a known symmetry"},
                    // TILT files stay in the IES file's folder, are regular files, and are never quoted.
                    BadFile{"tilt_absolute.ies", 5, "TILT file '/etc/shadow' must lie in the IES file's folder"},
                    BadFile{"tilt_dotdot.ies", 5, "must lie in the IES file's folder"},
                    BadFile{"tilt_folder.ies", 5, "is a folder, not a regular file"},
                    BadFile{"tilt_content.ies", 5, "TILT file 'secret_content.tlt' is not a valid TILT block (its line 1)"}),
    [](const testing::TestParamInfo<BadFile>& info) {
      std::string n = info.param.name;
      return n.substr(0, n.find('.'));
    });

TEST(IesLm63, TiltFileContentIsNeverEchoed) {
  try {
    readIes(kIes + "tilt_content.ies");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("SECRET"), std::string::npos) << e.what();
  }
}

TEST(IesLm63, CrOnlyLineEndingsReadAsLines) {
  // Classic Mac line endings once made a whole file one 1 295-character line.
  const PhotometricWeb a = readIes(kIes + "cr_only.ies"), b = readIes(kIes + "lambert_full.ies");
  EXPECT_EQ(a.totalLumens(), b.totalLumens());
  EXPECT_EQ(a.maxIntensityCd(), b.maxIntensityCd());
}

TEST(IesLm63, TrailingEndLineAndBlankLines) {
  const PhotometricWeb a = readIes(kIes + "trailing_end.ies"), b = readIes(kIes + "lambert_full.ies");
  EXPECT_EQ(a.totalLumens(), b.totalLumens());
}

TEST(IesLm63, MissingFile) {
  EXPECT_THROW(readIes(kIes + "no_such_file.ies"), InputError);
}

}  // namespace
}  // namespace candela
