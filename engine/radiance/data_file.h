// Radiance data files (the .dat files of brightdata, colordata and ies2rad luminaires): an
// array of values over a regular or irregular grid of up to six dimensions, and its lookup by
// multilinear interpolation as Radiance does it (src/common/data.c, getdata and data_interp).
//
// Format (words separated by white space, `#` to the end of the line a comment):
//   N                      number of dimensions, 1 to 6
//   begin end n            per dimension: n ≥ 2 points evenly spaced from begin to end, or
//   0 0 n p1 .. pn         n explicit points, strictly increasing or strictly decreasing
//   v ...                  n1·n2·…·nN values, the last dimension varying fastest
#pragma once

#include "base/error.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

inline constexpr int kMaxDataDimensions = 6;  // Radiance's MAXDDIM (src/common/data.h)
// No data file candela reads holds more values (memory stays bounded by what a file can mean).
inline constexpr size_t kMaxDataValues = size_t(1) << 24;

struct RadDataArray {
  struct Axis {
    double begin = 0.0, end = 0.0;  // first and last point
    int count = 0;                  // number of points (≥ 2)
    std::vector<double> points;     // explicit points (empty: evenly spaced)
  };
  std::string file;
  std::vector<Axis> axes;
  std::vector<double> values;  // row-major, the last axis fastest

  int dimensions() const { return static_cast<int>(axes.size()); }
  // The value at pt[0..dimensions()-1]: multilinear interpolation between the grid points;
  // outside the grid, extrapolated linearly as far as one division and then tapered
  // harmonically to zero (data.c's data_interp). No allocation.
  double value(const double* pt) const;
  // The largest |value| in the array.
  double maxAbsValue() const;
};

// Parses a data file's text; errors are InputError at `fileName`:line.
RadDataArray parseRadData(std::string_view text, const std::string& fileName);

// Reads a data file (UTF-8 BOM and CRLF tolerated). A file that cannot be read is an InputError
// at `from` (the primitive that names it).
RadDataArray readRadDataFile(const std::filesystem::path& path, const FileLoc& from);

}  // namespace candela
