#include "engine/radiance/data_file.h"

#include "base/input_file.h"
#include "engine/radiance/words.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

RadDataArray::Axis readAxis(RadWords& w, int d, size_t valuesSoFar) {
  const std::string dim = "dimension " + std::to_string(d + 1);
  RadDataArray::Axis a;
  a.begin = w.number("the first point of " + dim);
  a.end = w.number("the last point of " + dim);
  const long n = w.integer("the number of points of " + dim);
  if (n < 2) w.fail(dim + " needs at least 2 points, got " + std::to_string(n));
  if (static_cast<size_t>(n) > kMaxDataValues / std::max<size_t>(1, valuesSoFar))
    w.fail("the data array has more than " + std::to_string(kMaxDataValues) + " values");
  a.count = static_cast<int>(n);
  if (a.begin != a.end) return a;
  // begin = end: the points are listed (data.c); they must be monotonic to be a grid.
  a.points.reserve(a.count);
  for (int j = 0; j < a.count; ++j) {
    a.points.push_back(w.number("point " + std::to_string(j + 1) + " of " + dim));
    if (j >= 1 && (a.points[j] == a.points[j - 1] ||
                   (j >= 2 && (a.points[j] > a.points[j - 1]) != (a.points[j - 1] > a.points[j - 2]))))
      w.fail("the points of " + dim + " must be strictly increasing or strictly decreasing");
  }
  a.begin = a.points.front();
  a.end = a.points.back();
  return a;
}

// Position of x on axis a as a fractional index, and the cell i (0 ≤ i ≤ count − 2) it falls in
// or is nearest to (data.c).
double fractionalIndex(const RadDataArray::Axis& a, double x, int& i) {
  const int last = a.count - 2;
  if (a.points.empty()) {
    const double f = (x - a.begin) / (a.end - a.begin) * (a.count - 1);
    i = std::clamp(static_cast<int>(std::max(-1.0, std::min(f, static_cast<double>(a.count)))), 0, last);
    return f;
  }
  // The last point not beyond x in the axis' direction.
  const bool up = a.points.back() > a.points.front();
  int lo = 0, hi = a.count;  // points[lo] not beyond x (or lo = 0), points[hi] beyond (or hi = count)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (up ? x >= a.points[mid] : x <= a.points[mid]) lo = mid; else hi = mid;
  }
  i = std::min(lo, last);
  return i + (x - a.points[i]) / (a.points[i + 1] - a.points[i]);
}

}  // namespace

double RadDataArray::value(const double* pt) const {
  const int nd = dimensions();
  int cell[kMaxDataDimensions];
  double c0[kMaxDataDimensions], c1[kMaxDataDimensions];
  for (int d = 0; d < nd; ++d) {
    int i = 0;
    const double x = fractionalIndex(axes[d], pt[d], i);
    // data.c: linear within the grid and one division beyond it, then 1/distance to zero.
    if (x > i + 2) {
      c0[d] = 1.0 / (i - 1 - x);
      c1[d] = -2.0 * c0[d];
    } else if (x < i - 1) {
      c1[d] = 1.0 / (x - i);
      c0[d] = -2.0 * c1[d];
    } else {
      c0[d] = i + 1 - x;
      c1[d] = x - i;
    }
    cell[d] = i;
  }
  // Sum over the 2^nd corners of the cell.
  double sum = 0.0;
  for (int corner = 0; corner < (1 << nd); ++corner) {
    size_t index = 0;
    double weight = 1.0;
    for (int d = 0; d < nd; ++d) {
      const int up = (corner >> (nd - 1 - d)) & 1;
      index = index * static_cast<size_t>(axes[d].count) + static_cast<size_t>(cell[d] + up);
      weight *= up ? c1[d] : c0[d];
    }
    if (weight != 0.0) sum += weight * values[index];
  }
  return sum;
}

double RadDataArray::maxAbsValue() const {
  double m = 0.0;
  for (const double v : values) m = std::max(m, std::abs(v));
  return m;
}

RadDataArray parseRadData(std::string_view text, const std::string& fileName) {
  RadWords w(text, fileName);
  RadDataArray out;
  out.file = fileName;
  const long nd = w.integer("the number of dimensions");
  if (nd < 1 || nd > kMaxDataDimensions)
    w.fail("the number of dimensions must be 1 to " + std::to_string(kMaxDataDimensions) + ", got " +
           std::to_string(nd));
  size_t total = 1;
  for (int d = 0; d < nd; ++d) {
    out.axes.push_back(readAxis(w, d, total));
    total *= static_cast<size_t>(out.axes.back().count);
  }
  // Values are read as they come: a file that claims more than it holds fails at its end
  // without the claimed size being allocated.
  for (size_t i = 0; i < total; ++i)
    out.values.push_back(w.number("value " + std::to_string(i + 1) + " of " + std::to_string(total)));
  std::string_view extra;
  if (w.next(extra))
    w.fail("'" + RadWords::quoted(extra) + "' after the " + std::to_string(total) +
           " values the dimensions ask for: the dimensions or the values are wrong");
  return out;
}

RadDataArray readRadDataFile(const std::filesystem::path& path, const FileLoc& from) {
  std::string text;
  try {
    text = readInputFile(path, "data file");
  } catch (const InputError& e) {
    throw InputError(from, "data file '" + path.string() + "': " + e.message());
  }
  return parseRadData(text, path.string());
}

}  // namespace candela
