// genbox(1), interpreted: `genbox mat name xsiz ysiz zsiz [-i] [-b bev | -r rad [-n nseg] [-s]]`.
// The faces, their names, vertex order and the rounded and bevelled corners are those Radiance's
// src/gen/genbox.c writes (doc/man/man1/genbox.1); the code is candela's.
#include "base/math.h"
#include "engine/radiance/gen.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace candela {

namespace {

// genbox.c names a face by the codes of its corners, one character each from this table.
constexpr const char* kCornerLetters = "0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
// objutil.c's addFace: a face of area at most FTINY² (FTINY 1e-6, fvect.h) is not written.
constexpr double kDegenerateArea = 1e-12;
constexpr double kTiny = 1e-6;  // fvect.h's FTINY

// A corner code (genbox.c): bit i (i = 0, 1, 2) puts coordinate i on the far side, bit i + 3 moves
// it inwards by the bevel; -i swaps near and far, which turns every face inside out.
struct GenBox {
  std::string mat, name;
  FileLoc loc;
  Vec3 size{0.0};
  double bevel = 0.0;
  bool rev = false;

  Vec3 corner(int v) const {
    Vec3 p(0.0);
    for (int i = 0; i < 3; ++i) {
      const bool far = (((v >> i) & 1) != 0) != rev;
      if ((v >> i) & 010) p[i] = far ? size[i] - bevel : bevel;
      else p[i] = far ? size[i] : 0.0;
    }
    return p;
  }

  RadPrimitive primitive(const char* type, const std::string& suffix, std::vector<double> reals) const {
    return generatedPrimitive(mat, type, name + "." + suffix, loc, {}, std::move(reals));
  }

  static void append(std::vector<double>& r, const Vec3& p) { r.insert(r.end(), {p.x, p.y, p.z}); }

  // A polygon through the corners given (genbox.c's side and corner).
  RadPrimitive face(std::initializer_list<int> corners) const {
    std::string suffix;
    std::vector<double> r;
    for (int c : corners) {
      suffix += kCornerLetters[c];
      append(r, corner(c));
    }
    return primitive("polygon", suffix, std::move(r));
  }

  RadPrimitive edge(int v0, int v1) const {
    std::vector<double> r;
    append(r, corner(v0));
    append(r, corner(v1));
    r.push_back(bevel);
    return primitive("cylinder", std::string{kCornerLetters[v0], kCornerLetters[v1]}, std::move(r));
  }

  RadPrimitive ball(int v) const {
    std::vector<double> r;
    append(r, corner(v));
    r.push_back(bevel);
    return primitive("sphere", std::string(1, kCornerLetters[v]), std::move(r));
  }
};

// The six inset faces of a bevelled or rounded box, then the rest, in genbox.c's order.
constexpr std::array<std::array<int, 4>, 6> kMinorFaces = {{{051, 055, 054, 050}, {064, 066, 062, 060},
                                                            {032, 033, 031, 030}, {053, 052, 056, 057},
                                                            {065, 061, 063, 067}, {036, 034, 035, 037}}};
constexpr std::array<std::array<int, 4>, 12> kBevelFaces = {
    {{031, 051, 050, 030}, {060, 062, 032, 030}, {050, 054, 064, 060}, {034, 036, 066, 064},
     {037, 057, 056, 036}, {052, 062, 066, 056}, {052, 053, 033, 032}, {057, 067, 063, 053},
     {061, 031, 033, 063}, {065, 067, 037, 035}, {055, 051, 061, 065}, {034, 054, 055, 035}}};
constexpr std::array<std::array<int, 3>, 8> kBevelCorners = {{{030, 050, 060}, {051, 031, 061}, {032, 062, 052},
                                                              {064, 054, 034}, {036, 056, 066}, {065, 035, 055},
                                                              {053, 063, 033}, {037, 067, 057}}};
constexpr std::array<std::array<int, 2>, 12> kEdges = {{{070, 071}, {070, 074}, {070, 072}, {073, 071},
                                                        {073, 072}, {073, 077}, {075, 071}, {075, 074},
                                                        {075, 077}, {076, 072}, {076, 074}, {076, 077}}};
constexpr std::array<std::array<int, 4>, 6> kMajorFaces = {
    {{1, 5, 4, 0}, {4, 6, 2, 0}, {2, 3, 1, 0}, {3, 2, 6, 7}, {5, 1, 3, 7}, {6, 4, 5, 7}}};

// Rounded edges and corners as polygons (genbox.c with -i or -n 3 and more: its .OBJ scene,
// written by objutil's toRadiance): faces named name.1, name.2, ... in the reverse of the order
// they were made, degenerate ones left out. With -s the faces keep their vertices' normals (the
// strips' and the corners' directions from the edge or corner, the inset faces' own) and, as
// convertobj.c writes them, each face whose normals do not all agree with it (cosine 0.999995)
// is split into triangles by polyTriangulate's ear order (triangulate.c) and each triangle
// written first, modified by its own texfunc `T-nor` of tmesh.cal: its normals interpolated by
// barycentric coordinates (tmesh.c's comp_baryc and fput_baryc); a face whose normals are all
// reversed turns round and is written flat with the rest.
class FacetedBox {
 public:
  FacetedBox(const GenBox& box, int level, bool smooth) : box_(box), level_(level), smooth_(smooth) {}

  std::vector<RadPrimitive> make() {
    for (const auto& f : kMinorFaces) {
      std::vector<Vec3> p{box_.corner(f[0]), box_.corner(f[1]), box_.corner(f[2]), box_.corner(f[3])};
      const Vec3 n = glm::normalize(glm::cross(p[2] - p[1], p[3] - p[2]));  // genbox.c's onormal
      add(std::move(p), {n, n, n, n});
    }
    for (const auto& e : kEdges) edge(e[0], e[1]);
    for (int v = 070; v <= 077; ++v) ball(v);
    std::vector<RadPrimitive> out;
    int n = 0;
    std::vector<bool> smoothed(faces_.size(), false);
    if (smooth_) {
      std::vector<Face> triangles;  // the smoothed faces' triangles, newest first (objtriangulate.c)
      std::vector<const Face*> kept;  // the smoothed triangles made as such, in the order made
      for (size_t i = 0; i < faces_.size(); ++i) {
        if (area(faces_[i].p) <= kDegenerateArea || !smoothable(faces_[i])) continue;
        smoothed[i] = true;
        if (faces_[i].p.size() == 3) kept.push_back(&faces_[i]);
        else triangulate(faces_[i], triangles);
      }
      for (auto it = triangles.rbegin(); it != triangles.rend(); ++it) smoothTriangle(*it, n, out);
      for (const Face* f : kept) smoothTriangle(*f, n, out);
    }
    for (size_t i = faces_.size(); i-- > 0;) {
      if (smoothed[i] || area(faces_[i].p) <= kDegenerateArea) continue;
      std::vector<double> r;
      for (const Vec3& p : faces_[i].p) GenBox::append(r, p);
      out.push_back(box_.primitive("polygon", std::to_string(++n), std::move(r)));
    }
    return out;
  }

 private:
  struct Face {
    std::vector<Vec3> p, n;  // vertices and their unit normals
  };

  void add(std::vector<Vec3> p, std::vector<Vec3> n) { faces_.push_back(Face{std::move(p), std::move(n)}); }

  static Vec3 newell(const std::vector<Vec3>& f) {
    Vec3 n(0.0);
    for (size_t i = 2; i < f.size(); ++i) n += glm::cross(f[i - 1] - f[0], f[i] - f[0]);
    return n;
  }
  static double area(const std::vector<Vec3>& f) { return 0.5 * glm::length(newell(f)); }
  // The axis of n's largest component, a tie to the earlier axis (objtriangulate.c's and tmesh.c's test).
  static int dominantAxis(const Vec3& n) {
    const int ax = n.y * n.y > n.x * n.x ? 1 : 0;
    return n.z * n.z > n[ax] * n[ax] ? 2 : ax;
  }

  // convertobj.c's checksmooth: whether face f is smoothed; a face whose normals are all reversed
  // is turned round (its vertices in reverse order) and written flat.
  static bool smoothable(Face& f) {
    constexpr double kCosTol = 0.999995;  // tmesh.h's COSTOL
    const Vec3 fn = glm::normalize(newell(f.p));
    size_t reversed = 0;
    for (const Vec3& vn : f.n) {
      const double d = glm::dot(vn, fn);
      if (d >= kCosTol) continue;
      if (d > -kCosTol) return true;
      ++reversed;
    }
    if (reversed == f.p.size()) {
      std::reverse(f.p.begin(), f.p.end());
      std::reverse(f.n.begin(), f.n.end());
    }
    return false;
  }

  // objtriangulate.c's mktriangles for a convex face: the vertices projected past the normal's
  // dominant axis, taken counter-clockwise, ears cut from the last vertex on, each triangle kept
  // in the face's own orientation; appended in the order made.
  static void triangulate(const Face& f, std::vector<Face>& out) {
    const int ax = dominantAxis(newell(f.p));
    const int x = (ax + 1) % 3, y = (ax + 2) % 3;
    const int count = static_cast<int>(f.p.size());
    double a2 = 0.0;
    for (int p = count - 1, q = 0; q < count; p = q++) a2 += f.p[p][x] * f.p[q][y] - f.p[q][x] * f.p[p][y];
    const bool rev = a2 < 0.0;
    std::vector<int> v(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) v[static_cast<size_t>(i)] = rev ? count - 1 - i : i;
    int left = count, at = count - 1;
    while (left > 2) {
      const int u = at >= left ? 0 : at;
      at = u + 1 >= left ? 0 : u + 1;
      const int w = at + 1 >= left ? 0 : at + 1;
      int a = v[static_cast<size_t>(u)], b = v[static_cast<size_t>(at)], c = v[static_cast<size_t>(w)];
      if (rev) std::swap(a, c);
      out.push_back(Face{{f.p[static_cast<size_t>(a)], f.p[static_cast<size_t>(b)], f.p[static_cast<size_t>(c)]},
                         {f.n[static_cast<size_t>(a)], f.n[static_cast<size_t>(b)], f.n[static_cast<size_t>(c)]}});
      v.erase(v.begin() + at);
      --left;
    }
  }

  // convertobj.c's trismooth: the texture T-nor of tmesh.cal (the normals as functions of the
  // point's coordinates past the dominant axis, through the barycentric coordinates) and the
  // triangle of it, numbered ++k; a triangle without barycentric coordinates is left out.
  void smoothTriangle(const Face& t, int& k, std::vector<RadPrimitive>& out) const {
    const int ax = dominantAxis(glm::cross(t.p[0] - t.p[1], t.p[2] - t.p[1]));
    const int x = (ax + 1) % 3, y = (ax + 2) % 3;
    double tm[2][3];
    for (int i = 0; i < 2; ++i) {  // the weight of vertex i as a x + b y + c (tmesh.c's comp_baryc)
      const Vec3& v1 = t.p[static_cast<size_t>(i)];
      const Vec3& v2 = t.p[static_cast<size_t>((i + 1) % 3)];
      const Vec3& v3 = t.p[static_cast<size_t>((i + 2) % 3)];
      const double ab0 = v1[x] - v2[x], cb0 = v3[x] - v2[x], ab1 = v1[y] - v2[y], cb1 = v3[y] - v2[y];
      double d = cb0 * cb0 + cb1 * cb1;
      if (d <= kTiny * kTiny) return;
      d = (cb0 * ab0 + cb1 * ab1) / d;
      double a0 = ab0 - cb0 * d, a1 = ab1 - cb1 * d;
      d = a0 * a0 + a1 * a1;
      if (d <= kTiny * kTiny) return;
      a0 /= d, a1 /= d;
      tm[i][0] = a0, tm[i][1] = a1, tm[i][2] = -(v2[x] * a0 + v2[y] * a1);
    }
    std::vector<double> r{static_cast<double>(ax)};
    for (int c = 0; c < 3; ++c) {  // normal component c = n0 w0 + n1 w1 + n2 (1 - w0 - w1)
      const double a = t.n[0][c] - t.n[2][c], b = t.n[1][c] - t.n[2][c];
      r.insert(r.end(), {tm[0][0] * a + tm[1][0] * b, tm[0][1] * a + tm[1][1] * b, tm[0][2] * a + tm[1][2] * b + t.n[2][c]});
    }
    out.push_back(generatedPrimitive(box_.mat, "texfunc", "T-nor", box_.loc, {"dx", "dy", "dz", "tmesh.cal"}, std::move(r)));
    std::vector<double> v;
    for (const Vec3& p : t.p) GenBox::append(v, p);
    out.push_back(generatedPrimitive("T-nor", "polygon", box_.name + "." + std::to_string(++k), box_.loc, {}, std::move(v)));
  }

  // A quarter cylinder of 2^level strips about the edge from v0 to v1, bending from the face
  // along axis a0 to the face along a1 (genbox.c's cylinder, .OBJ branch).
  void edge(int v0, int v1) {
    const Vec3 p0 = box_.corner(v0), p1 = box_.corner(v1);
    const double b = box_.bevel;
    auto side = [&](int c) { return b * (p1[c] < 0.5 * box_.size[c] ? -1.0 : 1.0); };
    Vec3 a0(0.0), a1(0.0);
    switch ((v0 ^ v1) & 07) {
      case 01: a1.y = side(1), a0.z = side(2); break;
      case 02: a0.x = side(0), a1.z = side(2); break;
      default: a0.y = side(1), a1.x = side(0); break;
    }
    const int n = 1 << level_;
    const double step = 0.5 * kPi / n;
    const double sign = box_.rev ? -1.0 : 1.0;  // genbox.c's nsgn: -i turns the normals in
    Vec3 prev0 = p0 + a0, prev1 = p1 + a0, prevN = glm::normalize(a0) * sign;
    for (int i = 1; i <= n; ++i) {
      const Vec3 off = std::cos(step * i) * a0 + std::sin(step * i) * a1;
      const Vec3 offN = glm::normalize(off) * sign;
      add({prev0, prev1, p1 + off, p0 + off}, {prevN, prevN, offN, offN});
      prev0 = p0 + off;
      prev1 = p1 + off;
      prevN = offN;
    }
  }

  // An eighth of a sphere, its triangle split in four `level` times with the new corners pushed
  // onto the sphere (genbox.c's sphere and osubcorner).
  void ball(int v) {
    std::array<Vec3, 3> c{Vec3(0.0), Vec3(0.0), Vec3(0.0)};
    for (int i = 0; i < 3; ++i) c[i][i] = (((v >> i) & 1) != 0) != box_.rev ? 1.0 : -1.0;
    const int low = v & 07;
    if (low == 0 || low == 3 || low == 5 || low == 6) std::swap(c[0], c[1]);  // keeps the outside out
    subdivide(box_.corner(v), c[0], c[1], c[2], level_);
  }

  void subdivide(const Vec3& o, const Vec3& c0, const Vec3& c1, const Vec3& c2, int level) {
    if (level <= 0) {
      const double b = box_.bevel, sign = box_.rev ? -1.0 : 1.0;
      add({o + c0 * b, o + c1 * b, o + c2 * b}, {c0 * sign, c1 * sign, c2 * sign});
      return;
    }
    const Vec3 m01 = glm::normalize(c0 + c1), m12 = glm::normalize(c1 + c2), m20 = glm::normalize(c2 + c0);
    subdivide(o, c0, m01, m20, level - 1);
    subdivide(o, c1, m12, m01, level - 1);
    subdivide(o, c2, m20, m12, level - 1);
    subdivide(o, m01, m12, m20, level - 1);
  }

  const GenBox& box_;
  int level_;
  bool smooth_;
  std::vector<Face> faces_;
};

double number(const RadCommand& cmd, size_t i, const std::string& what) {
  if (i >= cmd.words.size()) throw InputError(cmd.loc, "genbox: " + what + " needs a number after it");
  const std::string& w = cmd.words[i];
  double v = 0.0;
  const char* b = w.data() + (!w.empty() && w[0] == '+');
  const auto r = std::from_chars(b, w.data() + w.size(), v);
  if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(v))
    throw InputError(cmd.loc, "genbox: " + what + " needs a number, not '" + w + "'");
  return v;
}

constexpr const char* kUsage = " (genbox mat name xsiz ysiz zsiz [-i] [-b bevel | -r radius [-n nseg] [-s]])";

}  // namespace

std::vector<RadPrimitive> expandGenbox(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::vector<std::string>& w = cmd.words;
  if (w.size() < 6) throw InputError(cmd.loc, std::string("genbox needs a material, a name and three sizes") + kUsage);
  GenBox box;
  box.mat = w[1];
  box.name = w[2];
  box.loc = cmd.loc;
  for (int i = 0; i < 3; ++i) {
    box.size[i] = number(cmd, 3 + i, "the size");
    if (box.size[i] <= 0.0) throw InputError(cmd.loc, "genbox: the sizes must be positive, not '" + w[3 + i] + "'");
  }
  int rounde = 0;   // genbox.c's rounde: 1 for -r, then the log2 of the segments per quarter
  long nsegs = 1;
  bool smooth = false;
  std::string bevelWord;
  for (size_t i = 6; i < w.size(); ++i) {
    const std::string& o = w[i];
    if (o == "-i") {
      box.rev = true;
    } else if (o == "-r" || o == "-b") {
      if (o == "-r") rounde = 1;  // -r then -b keeps the rounding, as genbox.c does
      box.bevel = number(cmd, ++i, o);
      bevelWord = w[i];
      if (box.bevel <= 0.0) throw InputError(cmd.loc, "genbox: " + o + " needs a positive size, not '" + w[i] + "'");
    } else if (o == "-n") {
      const double n = number(cmd, ++i, o);
      if (n < 1.0 || n != std::floor(n) || n > 1e6)
        throw InputError(cmd.loc, "genbox: -n needs a whole number of segments from 1 to 1000000, not '" + w[i] + "'");
      nsegs = static_cast<long>(n);
    } else if (o == "-s") {
      smooth = true;
    } else if (o == "-o") {
      throw InputError(cmd.loc, "genbox: -o writes a Wavefront .OBJ file, not a scene; drop it");
    } else {
      throw InputError(cmd.loc, "genbox: unknown option '" + o + "'" + kUsage);
    }
  }
  const double minSize = std::min({box.size.x, box.size.y, box.size.z});
  if (2.0 * box.bevel > minSize)
    throw InputError(cmd.loc, "genbox: a bevel or radius of " + bevelWord + " is more than half the smallest size");
  if (box.rev && nsegs == 1) nsegs = 32;  // genbox.c: an inverted rounded box defaults to 32 segments
  if (rounde)
    for (long n = nsegs - 1; n >>= 1;) ++rounde;
  std::vector<RadPrimitive> out;
  if (rounde > 1) {
    const double faces = 6.0 + 12.0 * std::ldexp(1.0, rounde) + 8.0 * std::ldexp(1.0, 2 * rounde);
    if (faces * (smooth ? kSmoothedPolygonWeight : 1.0) > generatedPrimitivesAllowed(ctx))
      throw InputError(cmd.loc, "genbox: -n " + std::to_string(nsegs) + " makes " + std::to_string(long(faces)) +
                                    " polygons" + (smooth ? " (smoothed: each counts as " + std::to_string(static_cast<int>(kSmoothedPolygonWeight)) + ")" : "") + ", more than " +
                                    generatedLimitText(ctx));
    return FacetedBox(box, rounde, smooth).make();
  }
  if (box.bevel > 0.0)
    for (const auto& f : kMinorFaces) out.push_back(box.face({f[0], f[1], f[2], f[3]}));
  if (box.bevel > 0.0 && !rounde) {
    for (const auto& f : kBevelFaces) out.push_back(box.face({f[0], f[1], f[2], f[3]}));
    for (const auto& c : kBevelCorners) out.push_back(box.face({c[0], c[1], c[2]}));
  }
  if (box.bevel > 0.0 && rounde) {
    for (const auto& e : kEdges) out.push_back(box.edge(e[0], e[1]));
    for (int v = 070; v <= 077; ++v) out.push_back(box.ball(v));
  }
  if (box.bevel == 0.0)
    for (const auto& f : kMajorFaces) out.push_back(box.face({f[0], f[1], f[2], f[3]}));
  return out;
}

}  // namespace candela
