// gensurf(1), interpreted: `gensurf mat name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-e expr] [-f file] [-s]`,
// the parametric surface (x, y, z)(s, t), s and t from 0 to 1 in m and n steps, as m·n cells each
// written as a quadrilateral when its two triangles are coplanar and as the triangles otherwise,
// the normal by the right-hand rule on (s, t), the cells alternating their diagonal, a function
// `valid(s, t)` (when defined) leaving out the points where it is not positive. The z argument
// (or all three when they name the same file) may name a data file of m+1 by n+1 values (or m by
// n cell centres; triplets when all three), interpolated bilinearly. Primitives, names
// (name.1, name.2, … in order) and the rules above are those of Radiance's src/gen/gensurf.c
// (facts of its output). With -s each point's normal is the cross product of its neighbours'
// differences along s and t (the rows and columns one step past the ends evaluated for it), and
// each cell whose four points allow it is modified by its own texfunc `Phong` of surf.cal
// (`mat texfunc Phong`, then `Phong polygon ...`): the normals fitted as a u v + b u + c v + d
// over the cell's points, u and v the two coordinates besides the normals' dominant axis
// (docs/engine.md). The code is candela's.
#include "base/input_file.h"
#include "engine/radiance/file_lookup.h"
#include "engine/radiance/gen.h"

#include <cmath>
#include <sstream>

namespace candela {
namespace {

constexpr double kTiny = 1e-6;  // gensurf.c's FTINY
constexpr long kMaxSide = 1000000;
const std::string kPhong = "Phong";  // the name of -s's texture of each cell

struct Point {
  bool valid = false;
  Vec3 p{0.0};
  Vec3 n{0.0};  // -s: the averaged normal (0 where it has none)
};

// -s: the normal at each point of row r1 from its neighbours in rows r0 and r2 and along the row
// (central differences, one-sided at an invalid neighbour; none without a neighbour either way).
// Rows hold n + 3 points, t from -1/n to 1 + 1/n; the normals of points 1..n+1 (t 0..1) are set.
void rowNormals(const std::vector<Point>& r0, std::vector<Point>& r1, const std::vector<Point>& r2) {
  for (size_t j = 1; j + 1 < r1.size(); ++j) {
    Point& c = r1[j];
    c.n = Vec3(0.0);
    if (!c.valid) continue;
    if (!r0[j].valid && !r2[j].valid) continue;
    if (!r1[j - 1].valid && !r1[j + 1].valid) continue;
    const Vec3 ds = !r0[j].valid ? r2[j].p - c.p : !r2[j].valid ? c.p - r0[j].p : r2[j].p - r0[j].p;
    const Vec3 dt = !r1[j - 1].valid ? r1[j + 1].p - c.p : !r1[j + 1].valid ? c.p - r1[j - 1].p
                                                                           : r1[j + 1].p - r1[j - 1].p;
    const Vec3 n = glm::cross(ds, dt);
    const double l = glm::length(n);
    c.n = l > 0.0 ? n / l : Vec3(0.0);
  }
}

// -s: the coefficients (rows: u v, u, v, 1) of the normals over a cell's four points, u and v the
// coordinates after the dominant axis of their sum in cyclic order; the axis, or -1 where the four
// points do not determine them (a pivot below gensurf.c's FTINY in the elimination).
int normalFit(const Point* const pts[4], Vec3 coef[4]) {
  const Vec3 sum = pts[0]->n + pts[1]->n + pts[2]->n + pts[3]->n;
  int ax = std::abs(sum.x) > std::abs(sum.y) ? 0 : 1;
  ax = std::abs(sum[ax]) > std::abs(sum.z) ? ax : 2;
  const int u = (ax + 1) % 3, v = (ax + 2) % 3;
  double a[4][8];  // [E | I], reduced to [I | E^-1]
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = pts[k]->p;
    const double row[4] = {p[u] * p[v], p[u], p[v], 1.0};
    for (int c = 0; c < 4; ++c) a[k][c] = row[c], a[k][4 + c] = c == k ? 1.0 : 0.0;
  }
  for (int i = 0; i < 4; ++i) {
    int pivot = -1;
    double best = kTiny;
    for (int k = i; k < 4; ++k)
      if (std::abs(a[k][i]) > best) best = std::abs(a[k][i]), pivot = k;
    if (pivot < 0) return -1;
    if (pivot != i) std::swap(a[i], a[pivot]);
    const double d = a[i][i];
    for (double& x : a[i]) x /= d;
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      const double f = a[k][i];
      for (int c = 0; c < 8; ++c) a[k][c] -= a[i][c] * f;
    }
  }
  for (int j = 0; j < 4; ++j) {
    coef[j] = Vec3(0.0);
    for (int k = 0; k < 4; ++k) coef[j] += a[j][4 + k] * pts[k]->n;
  }
  return ax;
}

// A data file's values in place of the functions (gensurf.c's loaddata and l_dataval).
struct SurfaceData {
  long m = 0, n = 0;  // the grid's points along s and t
  int size = 1;       // values a point: 1 (z) or 3 (x, y, z)
  bool border = true; // values at the cells' corners (m+1 by n+1), else at their centres
  std::vector<double> values;

  double value(double u, double v, int component) const {
    long i, j;
    if (border) {
      u *= static_cast<double>(m - 1);
      v *= static_cast<double>(n - 1);
    } else {
      u = u * static_cast<double>(m) - 0.5;
      v = v * static_cast<double>(n) - 0.5;
    }
    i = static_cast<long>(u);
    j = static_cast<long>(v);
    i = std::clamp(i, 0L, m - 2);
    j = std::clamp(j, 0L, n - 2);
    auto at = [&](long a, long b) { return values[static_cast<size_t>((b * m + a) * size + component)]; };
    const double d00 = at(i, j), d01 = at(i + 1, j), d10 = at(i, j + 1), d11 = at(i + 1, j + 1);
    return (static_cast<double>(j + 1) - v) * ((static_cast<double>(i + 1) - u) * d00 + (u - static_cast<double>(i)) * d01) +
           (v - static_cast<double>(j)) * ((static_cast<double>(i + 1) - u) * d10 + (u - static_cast<double>(i)) * d11);
  }
};

}  // namespace

std::vector<RadPrimitive> expandGensurf(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::vector<std::string>& w = cmd.words;
  auto fail = [&](const std::string& msg) -> void { throw InputError(cmd.loc, "gensurf: " + msg); };
  if (w.size() < 8) fail("usage: gensurf material name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-e expr] [-f file] [-s]");
  const std::string& mat = w[1];
  const std::string& name = w[2];
  auto count = [&](const std::string& word, const char* what) {
    char* end = nullptr;
    const long v = std::strtol(word.c_str(), &end, 10);
    if (end == word.c_str() || *end != '\0' || v < 1 || v > kMaxSide)
      fail(std::string(what) + " must be a whole number from 1 to " + std::to_string(kMaxSide) + ", got '" + word + "'");
    return v;
  };
  const long m = count(w[6], "m"), n = count(w[7], "n");
  FunctionFiles files;
  cal::Program& program = *files.program();
  bool smooth = false;
  readFunctionOptions(cmd, ctx, 8, files, &smooth);
  const double weight = smooth ? kSmoothedPolygonWeight : 1.0;
  if (2.0 * static_cast<double>(m) * static_cast<double>(n) * weight > generatedPrimitivesAllowed(ctx))
    fail("m × n = " + std::to_string(m) + " × " + std::to_string(n) + " cells would make up to " +
         std::to_string(2 * m * n) + " polygons" + (smooth ? " (smoothed: each counts as " + std::to_string(static_cast<int>(kSmoothedPolygonWeight)) + ")" : "") + ", more than " +
         generatedLimitText(ctx));
  // Data: z names a file (all three the same file: triplets).
  std::optional<SurfaceData> data;
  std::filesystem::path dataPath;
  try {
    dataPath = findSceneFile(w[5], ctx.folder, cmd.loc, "gensurf", "data file", ctx.root);
  } catch (const InputError&) {
    dataPath.clear();  // an expression
  }
  if (!dataPath.empty()) {
    SurfaceData d;
    d.size = w[3] == w[5] && w[4] == w[5] ? 3 : 1;
    std::istringstream in(readInputFile(dataPath, "gensurf data file"));
    std::string word;
    while (in >> word) {
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(v))
        fail("data file '" + w[5] + "': '" + word.substr(0, 40) + "' is not a number");
      if (d.values.size() > static_cast<size_t>((m + 1) * (n + 1) * d.size)) break;
      d.values.push_back(v);
    }
    const size_t corners = static_cast<size_t>((m + 1) * (n + 1) * d.size), centres = static_cast<size_t>(m * n * d.size);
    d.border = d.values.size() == corners;
    d.m = d.border ? m + 1 : m;
    d.n = d.border ? n + 1 : n;
    if ((d.values.size() != corners && d.values.size() != centres) || d.m < 2 || d.n < 2)
      fail("data file '" + w[5] + "' holds " + std::to_string(d.values.size()) + " values; " + std::to_string(m) +
           " × " + std::to_string(n) + " cells need " + std::to_string(corners) + " (corners) or " +
           std::to_string(centres) + " (centres)");
    data = std::move(d);
  }
  static const char* const kName[] = {"`gensurf.x", "`gensurf.y", "`gensurf.z"};
  static const char* const kWhat[] = {"x(s,t)", "y(s,t)", "z(s,t)"};
  const int functions = !data ? 3 : data->size == 3 ? 0 : 2;
  cal::Symbol f[3] = {-1, -1, -1};
  for (int k = 0; k < functions; ++k)
    f[k] = defineGeneratorFunction(program, cmd, kName[k], "s, t", 2, w[3 + static_cast<size_t>(k)], kWhat[k]);
  // valid(s, t), when the options define it as a function of two arguments.
  bool checkValid = false;
  if (program.find("valid") >= 0) {
    try {
      program.check("valid", 2, cmd.loc);
      checkValid = true;
    } catch (const InputError&) {
      checkValid = false;
    }
  }
  cal::Evaluator eval(program);
  const cal::Symbol validF = checkValid ? program.find("valid") : -1;
  // Row i (s = i/m) at t = j/n, j from 0 to n; with -s from -1 to n + 1 (at index j + 1).
  const long first = smooth ? -1 : 0, last = smooth ? n + 1 : n;
  auto row = [&](long i, std::vector<Point>& out) {
    out.assign(static_cast<size_t>(last - first + 1), Point{});
    for (long j = first; j <= last; ++j) {
      const double st[] = {static_cast<double>(i) / static_cast<double>(m), static_cast<double>(j) / static_cast<double>(n)};
      eval.begin({});
      if (checkValid && !(eval.call(validF, st) > 0.0)) continue;
      Point& pt = out[static_cast<size_t>(j - first)];
      // -s's points one step past the ends only shape the normals: one that is not finite there
      // leaves the point out (its neighbours' differences turn one-sided) instead of failing.
      const bool beyond = i < 0 || i > m || j < 0 || j > n;
      bool finite = true;
      for (int k = 0; k < 3 && finite; ++k) {
        double v;
        if (k < functions) {
          eval.begin({});
          v = eval.call(f[k], st);
        } else {
          v = data->value(st[0], st[1], data->size == 3 ? k : 0);
        }
        finite = std::isfinite(v);
        if (!finite && !beyond)
          fail(std::string(kWhat[k]) + " is not a finite number at s = " + std::to_string(st[0]) + ", t = " +
               std::to_string(st[1]));
        pt.p[k] = v;
      }
      pt.valid = finite;
      if (!finite) pt.p = Vec3(0.0);
    }
  };
  std::vector<RadPrimitive> out;
  long serial = 0;
  // A polygon of the material, or of the texture just written (smoothed).
  auto polygon = [&](bool smoothed, std::initializer_list<Vec3> vs) {
    std::vector<double> reals;
    for (const Vec3& v : vs) reals.insert(reals.end(), {v.x, v.y, v.z});
    out.push_back(generatedPrimitive(smoothed ? kPhong : mat, "polygon", name + "." + std::to_string(++serial), cmd.loc, {}, std::move(reals)));
  };
  // -s: the texture of the polygon that follows, its perturbation the fitted normal less the
  // polygon's own (face).
  auto phong = [&](int axis, const Vec3 coef[4], const Vec3& face) {
    std::vector<double> reals{static_cast<double>(axis)};
    for (const Vec3& c : {coef[0], coef[1], coef[2], coef[3] - face}) reals.insert(reals.end(), {c.x, c.y, c.z});
    out.push_back(generatedPrimitive(mat, "texfunc", kPhong, cmd.loc, {"surf_dx", "surf_dy", "surf_dz", "surf.cal"},
                                     std::move(reals)));
  };
  // One cell: the triangles (p0, p1, p2) and (p2, p1, p3), or the quadrilateral p0 p1 p3 p2 when
  // their normals agree.
  auto cell = [&](const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
    Vec3 n1(0.0), n2(0.0);
    bool ok1 = p0.valid && p1.valid && p2.valid, ok2 = p1.valid && p2.valid && p3.valid;
    if (ok1) {
      n1 = glm::cross(p1.p - p0.p, p2.p - p0.p);
      const double l = glm::length(n1);
      ok1 = l > 0.0;
      if (ok1) n1 /= l;
    }
    if (ok2) {
      n2 = glm::cross(p2.p - p3.p, p1.p - p3.p);
      const double l = glm::length(n2);
      ok2 = l > 0.0;
      if (ok2) n2 /= l;
    }
    if (!(ok1 || ok2)) return;
    Vec3 coef[4];
    const Point* const pts[4] = {&p0, &p1, &p2, &p3};
    const int axis = smooth ? normalFit(pts, coef) : -1;
    if (ok1 && ok2 && glm::dot(n1, n2) >= 1.0 - kTiny * kTiny) {
      if (axis >= 0) phong(axis, coef, 0.5 * (n1 + n2));
      return polygon(axis >= 0, {p0.p, p1.p, p3.p, p2.p});
    }
    if (ok1) {
      if (axis >= 0) phong(axis, coef, n1);
      polygon(axis >= 0, {p0.p, p1.p, p2.p});
    }
    if (ok2) {
      if (axis >= 0) phong(axis, coef, n2);
      polygon(axis >= 0, {p2.p, p1.p, p3.p});
    }
  };
  // Rows i and i + 1 (row0, row1), and i + 2 (next) for the normals with -s.
  std::vector<Point> row0, row1, next;
  if (smooth) row(-1, row0);
  row(0, row1);
  if (smooth) {
    row(1, next);
    rowNormals(row0, row1, next);
  }
  const size_t off = static_cast<size_t>(-first);
  for (long i = 0; i < m; ++i) {
    if (smooth) {
      row0.swap(row1);  // row i
      row1.swap(next);  // row i + 1
      row(i + 2, next);
      rowNormals(row0, row1, next);
    } else {
      row0.swap(row1);
      row(i + 1, row1);
    }
    for (long j = 0; j < n; ++j) {
      const size_t a = static_cast<size_t>(j) + off, b = a + 1;
      bool orient = (j & 1) != 0;
      if (!(row0[a].valid && row1[b].valid)) orient = true;
      else if (!(row1[a].valid && row0[b].valid)) orient = false;
      if (orient) cell(row0[a], row1[a], row0[b], row1[b]);
      else cell(row1[a], row1[b], row0[a], row0[b]);
    }
  }
  return out;
}

}  // namespace candela
