#include "reports/ugr_table_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace candela {
namespace {

// A table of the standard rooms and reflectances with made-up values: 10 + room + reflectance / 10.
UgrTable sampleTable() {
  UgrTable t;
  for (size_t i = 0; i < t.settings.rooms.size(); ++i) {
    std::vector<double> row;
    for (size_t j = 0; j < t.settings.reflectances.size(); ++j) row.push_back(10.0 + double(i) + 0.1 * double(j));
    t.crosswise.push_back(row);
    for (double& v : row) v += 0.5;
    t.endwise.push_back(row);
    t.luminaires.push_back(16 * int(t.settings.rooms[i].xH * t.settings.rooms[i].yH));
  }
  t.crosswise[0][0] = -std::numeric_limits<double>::infinity();  // no luminaire counted
  return t;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(UgrTableReport, CellsHaveOneDecimal) {
  EXPECT_EQ(ugrCell(18.25), "18.2");  // printf rounding of the binary value 18.25 → even
  EXPECT_EQ(ugrCell(19.06), "19.1");
  EXPECT_EQ(ugrCell(std::nan("")), "-");
  EXPECT_EQ(ugrCell(-std::numeric_limits<double>::infinity()), "-");
}

TEST(UgrTableReport, CsvHasOneRowPerRoomAndAColumnPerCell) {
  const std::vector<std::string> rows = lines(ugrTableCsv(sampleTable()));
  ASSERT_EQ(rows.size(), 20u);
  EXPECT_EQ(rows[0],
            "room_x_H,room_y_H,luminaires,crosswise_70_50_20,crosswise_70_30_20,crosswise_50_50_20,"
            "crosswise_50_30_20,crosswise_30_30_20,endwise_70_50_20,endwise_70_30_20,endwise_50_50_20,"
            "endwise_50_30_20,endwise_30_30_20");
  EXPECT_EQ(rows[1], "2,2,64,,10.10,10.20,10.30,10.40,10.50,10.60,10.70,10.80,10.90");
  EXPECT_EQ(rows[19], "12,8,1536,28.00,28.10,28.20,28.30,28.40,28.50,28.60,28.70,28.80,28.90");
}

TEST(UgrTableReport, TextShowsBothBlocksAndTheCorrection) {
  UgrTableLabels labels{"Panel", 1000.0, 4000.0, false};
  const std::string text = ugrTableText(sampleTable(), labels);
  EXPECT_NE(text.find("Viewed crosswise"), std::string::npos);
  EXPECT_NE(text.find("Viewed endwise"), std::string::npos);
  EXPECT_NE(text.find("  2H   2H      -  10.1  10.2  10.3  10.4    10.5  10.6  10.7  10.8  10.9"), std::string::npos)
      << text;
  EXPECT_NE(text.find(" 12H   8H   28.0  28.1  28.2  28.3  28.4    28.5  28.6  28.7  28.8  28.9"), std::string::npos);
  EXPECT_NE(text.find("this file's 4000 lm add +4.8"), std::string::npos);  // 8 log10 4 = 4.82
}

TEST(UgrTableReport, SvgHoldsEveryCellAndIsWideEnoughForItsText) {
  UgrTableLabels labels{std::string(150, 'W'), 1000.0, 4000.0, false};
  const std::string svg = ugrTableSvg(sampleTable(), labels);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find(">28.9</text>"), std::string::npos);
  EXPECT_NE(svg.find(">10.1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">-</text>"), std::string::npos);
  // The title at 15 px, "UGR table — " and 150 W: at least 0.6 em a character fits.
  const size_t at = svg.find("width=\"") + 7;
  const double width = std::stod(svg.substr(at));
  EXPECT_GE(width, (12 + 150) * 15.0 * 0.6);
}

}  // namespace
}  // namespace candela
