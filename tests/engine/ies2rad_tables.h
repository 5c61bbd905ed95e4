// The candela tables of the ies2rad fixtures (tests/data/rad/ies2rad/*.ies) and the plain linear
// interpolation the tests evaluate them with, independently of engine/radiance/data_file.
#pragma once

#include <vector>

namespace candela::test_support {

// Linear interpolation on a table (x ascending), inside the table only.
inline double lerpTable(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  for (size_t i = 0; i + 1 < xs.size(); ++i)
    if (x <= xs[i + 1] || i + 2 == xs.size()) {
      const double t = (x - xs[i]) / (xs[i + 1] - xs[i]);
      return ys[i] + t * (ys[i + 1] - ys[i]);
    }
  return ys.back();
}

// Bilinear interpolation of rows[h][v] over horizontal angles hs and vertical angles vs.
inline double bilinear(const std::vector<double>& hs, const std::vector<double>& vs,
                       const std::vector<std::vector<double>>& rows, double h, double v) {
  std::vector<double> col;
  for (const auto& r : rows) col.push_back(lerpTable(vs, r, v));
  return hs.size() == 1 ? col[0] : lerpTable(hs, col, h);
}

// The candela tables of the fixtures' IES files (cd).
inline const std::vector<double> kPanelH = {0, 45, 90}, kPanelV = {0, 15, 30, 45, 60, 75, 90};
inline const std::vector<std::vector<double>> kPanelI = {
    {1000, 985, 930, 820, 640, 370, 0}, {1000, 978, 905, 770, 575, 320, 0}, {1000, 970, 880, 720, 510, 270, 0}};
inline const std::vector<double> kGlobeV = {0, 30, 60, 90, 120, 150, 180};
inline const std::vector<double> kGlobeI = {800, 760, 700, 640, 600, 580, 560};
inline const std::vector<double> kBoxH = {0, 90, 180}, kBoxV = {0, 45, 90, 135, 180};
inline const std::vector<std::vector<double>> kBoxI = {
    {1200, 1000, 700, 400, 300}, {1200, 900, 600, 380, 300}, {1200, 950, 650, 390, 300}};
inline const std::vector<double> kCylV = {0, 45, 90, 135, 180};
inline const std::vector<double> kCylI = {300, 420, 500, 420, 300};

}  // namespace candela::test_support
