#include "study/grids/sensor_grid.h"
#include "base/input_file.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace candela {

namespace {

// A grid beyond this many cells is a unit mistake (spacing in mm), not a study.
constexpr long long kMaxCells = 10'000'000;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

double autoGridSpacingM(double dM) {
  if (!(dM > 0.0)) return 0.0;
  const double p = std::min(10.0, 0.2 * std::pow(5.0, std::log10(dM)));
  // One significant figure; the 1e-9 guards values such as 0.2·5^1 = 1.0000000000000002.
  const double decade = std::pow(10.0, std::floor(std::log10(p) + 1e-9));
  return std::round(p / decade) * decade;
}

double gridDimensionM(double sideAM, double sideBM) {
  const double longer = std::max(sideAM, sideBM), shorter = std::min(sideAM, sideBM);
  return (shorter > 0.0 && longer >= 2.0 * shorter) ? shorter : longer;
}

int cellsAlong(double lengthM, double maxSpacingM) {
  if (!(lengthM > 0.0) || !(maxSpacingM > 0.0)) return 1;
  // The relative 1e-9 keeps 6 m at 0.5 m spacing at 12 cells despite rounding.
  const double n = std::ceil(lengthM / maxSpacingM * (1.0 - 1e-9));
  return static_cast<int>(std::max(1.0, std::min(n, 1e9)));
}

bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

double distanceToOutline(const std::vector<Vec2>& polygon, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = polygon[j], ab = polygon[i] - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(p - (a + t * ab)));
  }
  return best;
}

double polygonArea(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    twice += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  return 0.5 * twice;
}

namespace {

// makePlaneGrid and countPlaneGrid: the same checks and lattice; the points stored only when
// `store` (a count alone needs no memory per point).
SensorGrid planeGrid(const PlaneGridSpec& spec, const FileLoc& loc, bool store, std::size_t& count) {
  const double axisTol = 1e-6;
  if (std::abs(glm::length(spec.uAxis) - 1.0) > axisTol || std::abs(glm::length(spec.vAxis) - 1.0) > axisTol ||
      std::abs(glm::dot(spec.uAxis, spec.vAxis)) > axisTol)
    throw InputError(loc, "grid axes must be orthogonal unit vectors");
  if (spec.spacingM && !(*spec.spacingM > 0.0))
    throw InputError(loc, "grid spacing must be positive, got " + num(*spec.spacingM) + " m");
  if (spec.borderM < 0.0) throw InputError(loc, "grid border must not be negative");

  // Outline as a polygon, whatever form it was given in.
  std::vector<Vec2> polygon;
  if (spec.isRectangle) {
    if (spec.outline.size() != 2) throw InputError(loc, "a rectangular grid needs two corners");
    const Vec2 lo = glm::min(spec.outline[0], spec.outline[1]);
    const Vec2 hi = glm::max(spec.outline[0], spec.outline[1]);
    polygon = {lo, Vec2(hi.x, lo.y), hi, Vec2(lo.x, hi.y)};
  } else {
    if (spec.outline.size() < 3)
      throw InputError(loc, "a grid outline needs at least 3 points, got " + std::to_string(spec.outline.size()));
    polygon = spec.outline;
  }
  if (!(std::abs(polygonArea(polygon)) > 0.0)) throw InputError(loc, "grid area is zero");

  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Vec2& p : polygon) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // A point inside the polygon and within `border` of its bounding box is also within `border`
  // of an edge, so the lattice can cover the shrunk box.
  lo += Vec2(spec.borderM);
  hi -= Vec2(spec.borderM);
  const Vec2 size = hi - lo;
  if (!(size.x > 0.0) || !(size.y > 0.0))
    throw InputError(loc, "the border of " + num(spec.borderM) + " m leaves no area for the grid");

  SensorGrid g;
  g.regular = true;
  g.nominalSpacingM = spec.spacingM ? *spec.spacingM : autoGridSpacingM(gridDimensionM(size.x, size.y));
  g.columns = cellsAlong(size.x, g.nominalSpacingM);
  g.rows = cellsAlong(size.y, g.nominalSpacingM);
  if (static_cast<long long>(g.columns) * g.rows > kMaxCells)
    throw InputError(loc, "grid of " + std::to_string(g.columns) + " x " + std::to_string(g.rows) +
                              " points is too large; check the spacing (m)");
  g.spacingM = Vec2(size.x / g.columns, size.y / g.rows);
  g.latticeOriginUv = lo;

  const Vec3 normal =
      glm::normalize(spec.normal ? *spec.normal : glm::cross(spec.uAxis, spec.vAxis));
  for (int j = 0; j < g.rows; ++j) {
    for (int i = 0; i < g.columns; ++i) {
      const Vec2 uv = lo + Vec2((i + 0.5) * g.spacingM.x, (j + 0.5) * g.spacingM.y);
      if (!spec.isRectangle) {
        if (!insidePolygon(polygon, uv)) continue;
        if (spec.borderM > 0.0 && distanceToOutline(polygon, uv) < spec.borderM) continue;
      }
      if (!spec.pieces.empty() &&
          std::none_of(spec.pieces.begin(), spec.pieces.end(),
                       [&](const std::vector<Vec2>& piece) { return insidePolygon(piece, uv); }))
        continue;
      if (std::any_of(spec.holes.begin(), spec.holes.end(),
                      [&](const std::vector<Vec2>& hole) { return insidePolygon(hole, uv); }))
        continue;
      if (!spec.band.inner.empty()) {
        if (insidePolygon(spec.band.inner, uv)) continue;
        const double d = distanceToOutline(spec.band.inner, uv);
        if (!(d > spec.band.fromM && d <= spec.band.toM)) continue;
      }
      ++count;
      if (!store) continue;
      g.points.push_back({spec.origin + uv.x * spec.uAxis + uv.y * spec.vAxis, normal});
      g.uv.push_back(uv);
      g.cell.emplace_back(i, j);
    }
  }
  // A band may be empty (a task area that fills its room has no background), and so may a
  // surface's pieces (slivers narrower than the spacing): their callers decide.
  if (count == 0 && spec.band.inner.empty() && spec.pieces.empty() && spec.holes.empty())
    throw InputError(loc, "no grid point falls inside the outline; reduce the spacing or border");
  return g;
}

}  // namespace

SensorGrid makePlaneGrid(const PlaneGridSpec& spec, const FileLoc& loc) {
  std::size_t count = 0;
  return planeGrid(spec, loc, true, count);
}

std::size_t countPlaneGrid(const PlaneGridSpec& spec, const FileLoc& loc) {
  std::size_t count = 0;
  planeGrid(spec, loc, false, count);
  return count;
}

namespace {

// A sensor line is a few dozen characters; a "line" without end (stdin from /dev/zero) must not
// grow without bound.
constexpr std::size_t kMaxPointsLineChars = 1 << 16;

// std::getline with a bound: false at the end of the input; throws InputError at the line when
// it is longer than kMaxPointsLineChars.
bool readBoundedLine(std::istream& in, std::string& line, const std::string& sourceName, int lineNo) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n') return true;
    if (c == '\r') {  // CRLF or a lone CR ends the line
      if (buf->sgetc() == '\n') buf->sbumpc();
      return true;
    }
    if (line.size() == kMaxPointsLineChars)
      throw InputError(FileLoc{sourceName, lineNo, 0},
                       "a sensor point line is longer than " + std::to_string(kMaxPointsLineChars) + " characters");
    line.push_back(static_cast<char>(c));
  }
}

}  // namespace

SensorPoint checkedSensorPoint(const double v[6], const FileLoc& loc) {
  for (int k = 0; k < 6; ++k)
    if (!std::isfinite(v[k])) throw InputError(loc, "a sensor point's numbers must be finite");
  // Within 10 000 km of the origin (engine/radiance/reader.cpp says why): a point at 1e30 m once
  // aborted the process inside Embree.
  for (int k = 0; k < 3; ++k)
    if (std::abs(v[k]) > kMaxCoordinateM) throw InputError(loc, "a sensor point lies beyond 1e7 m from the origin");
  const Vec3 dir(v[3], v[4], v[5]);
  if (dir == Vec3(0.0)) throw InputError(loc, "sensor direction is zero");
  // A component of 1e200 once reached Embree as a zero direction and aborted the process.
  const std::optional<Vec3> unit = unitDirection(dir);
  if (!unit)
    throw InputError(loc, "sensor direction (" + compactNumber(v[3]) + " " + compactNumber(v[4]) + " " +
                              compactNumber(v[5]) + ") cannot be normalised: its length overflows or underflows");
  return {Vec3(v[0], v[1], v[2]), *unit};
}

std::vector<SensorPoint> readPoints(std::istream& in, const std::string& sourceName, std::vector<int>* lines) {
  std::vector<SensorPoint> points;
  std::string line;
  int lineNo = 0;
  while (readBoundedLine(in, line, sourceName, lineNo + 1)) {
    ++lineNo;
    if (lineNo == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // UTF-8 BOM
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    double v[6];
    int n = 0;
    std::string word;
    bool bad = false;
    while (fields >> word) {
      if (n == 6) { bad = true; ++n; break; }
      try {
        std::size_t used = 0;
        v[n] = std::stod(word, &used);
        if (used != word.size() || !std::isfinite(v[n])) bad = true;
      } catch (const std::exception&) {
        bad = true;
      }
      if (bad) break;
      ++n;
    }
    const FileLoc loc{sourceName, lineNo, 0};
    if (bad || n != 6)
      throw InputError(loc, "a sensor point needs 6 numbers 'x y z dx dy dz', got '" + line + "'");
    points.push_back(checkedSensorPoint(v, loc));
    if (lines) lines->push_back(lineNo);
  }
  return points;
}

SensorGrid readPointsFile(const std::filesystem::path& path) {
  std::istringstream in(readInputFile(path, "sensor points file"));
  SensorGrid g;
  g.points = readPoints(in, path.string(), &g.lines);
  if (g.points.empty()) throw InputError(FileLoc{path.string(), 0, 0}, "sensor points file holds no points");
  return g;
}

}  // namespace candela
