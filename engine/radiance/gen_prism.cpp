// genprism(1), interpreted: `genprism mat name { N x1 y1 .. xN yN | vfile } [-l lx ly lz]
// [-r radius] [-c] [-e]`. A polygon in the z = 0 plane extruded along the length vector; the
// faces, names and vertex order, and the rounded version's spheres and cylinders, are those of
// Radiance's src/gen/genprism.c (doc/man/man1/genprism.1); the code is candela's.
#include "base/input_file.h"
#include "base/math.h"
#include "engine/radiance/file_lookup.h"
#include "engine/radiance/gen.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace candela {

namespace {

namespace fs = std::filesystem;


constexpr size_t kMaxVertices = 1024;  // genprism.c's MAXVERT
constexpr double kTiny = 1e-6;         // genprism.c's FTINY

[[noreturn]] void fail(const RadCommand& cmd, const std::string& msg) {
  throw InputError(cmd.loc, "genprism: " + msg);
}

bool parseNumber(const std::string& w, double& v) {
  const char* b = w.data() + (!w.empty() && w[0] == '+');
  const auto r = std::from_chars(b, w.data() + w.size(), v);
  return r.ec == std::errc() && r.ptr == w.data() + w.size() && std::isfinite(v);
}

double number(const RadCommand& cmd, size_t i, const std::string& what) {
  if (i >= cmd.words.size()) fail(cmd, what + " needs a number");
  double v = 0.0;
  if (!parseNumber(cmd.words[i], v)) fail(cmd, what + " needs a number, not '" + cmd.words[i] + "'");
  return v;
}

using Vec2 = glm::dvec2;

// x y pairs, blank-separated, from a vertex file (genprism.c's readverts).
std::vector<Vec2> readVertexFile(const RadCommand& cmd, const RadExpandContext& ctx, const std::string& name) {
  const fs::path path = findSceneFile(name, ctx.folder, cmd.loc, "genprism", "vertex file", ctx.root);
  std::istringstream in(readInputFile(path, "genprism vertex file"));
  std::vector<double> xy;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      double v = 0.0;
      if (!parseNumber(w, v))
        fail(cmd, "vertex file '" + name + "' line " + std::to_string(lineNo) + ": '" + w + "' is not a number");
      xy.push_back(v);
      if (xy.size() > 2 * kMaxVertices) fail(cmd, "vertex file '" + name + "' has more than 1024 vertices");
    }
  }
  if (xy.size() % 2) fail(cmd, "vertex file '" + name + "' has an odd count of numbers (vertices are x y pairs)");
  std::vector<Vec2> v;
  for (size_t i = 0; i < xy.size(); i += 2) v.emplace_back(xy[i], xy[i + 1]);
  return v;
}

struct Prism {
  std::string mat, name;
  FileLoc loc;
  std::vector<Vec2> v;
  Vec3 l{0.0, 0.0, 1.0};  // length (extrusion) vector
  double lvdir = 1.0;     // sign of l.z
  double crad = 0.0;      // corner radius times lvdir (genprism.c)
  std::vector<Vec2> u;    // u[i]: unit vector from vertex i to vertex i − 1
  std::vector<double> a;  // corner trims, signed by the turn

  RadPrimitive primitive(const char* type, const std::string& suffix, std::vector<double> reals) const {
    return generatedPrimitive(mat, type, name + "." + suffix, loc, {}, std::move(reals));
  }

  // Where the rounded outline passes near vertex i: inside the corner by the radius.
  Vec2 inset(size_t i) const { return v[i] + crad * Vec2(a[i] * u[i].x - u[i].y, a[i] * u[i].y + u[i].x); }

  void ends(std::vector<RadPrimitive>& out, bool round) const {
    std::vector<double> b, t;
    for (size_t i = 0; i < v.size(); ++i) {
      const Vec2 p = round ? inset(i) : v[i];
      b.insert(b.end(), {p.x, p.y, 0.0});
    }
    for (size_t i = v.size(); i--;) {
      const Vec2 p = (round ? inset(i) : v[i]) + Vec2(l);
      t.insert(t.end(), {p.x, p.y, l.z});
    }
    out.push_back(primitive("polygon", "b", std::move(b)));
    out.push_back(primitive("polygon", "t", std::move(t)));
  }

  // genprism.c's printrends after the end faces: spheres at the convex corners and cylinders
  // along the edges, at the bottom ("bc", "be") and the top ("tc", "te").
  void roundedRims(std::vector<RadPrimitive>& out) const {
    for (int top = 0; top < 2; ++top) {
      const Vec2 shift = top ? Vec2(l) : Vec2(0.0);
      const double z = top ? l.z - crad : crad;
      const std::string tag = top ? "t" : "b";
      Vec2 c0 = inset(v.size() - 1) + shift;
      for (size_t i = 0; i < v.size(); ++i) {
        const Vec2 c1 = inset(i) + shift;
        if (lvdir * a[i] > 0.0)
          out.push_back(primitive("sphere", tag + "c" + std::to_string(i + 1), {c1.x, c1.y, z, lvdir * crad}));
        out.push_back(primitive("cylinder", tag + "e" + std::to_string(i + 1),
                                {c0.x, c0.y, z, c1.x, c1.y, z, lvdir * crad}));
        c0 = c1;
      }
    }
  }

  void side(std::vector<RadPrimitive>& out, size_t n0, size_t n1) const {
    const Vec2 p0 = v[n0], p1 = v[n1], L(l);
    out.push_back(primitive("polygon", std::to_string(n0 + 1),
                            {p0.x, p0.y, 0.0, p0.x + L.x, p0.y + L.y, l.z, p1.x + L.x, p1.y + L.y, l.z, p1.x, p1.y, 0.0}));
  }

  // genprism.c's rside: the side moved in by the radius, tilted with a slanted length vector,
  // and the cylinder along its end edge when the corner there is convex.
  void roundedSide(std::vector<RadPrimitive>& out, size_t n0, size_t n1) const {
    const Vec2 un = u[n1], L(l);
    const double s = lvdir * (l.y * un.x - l.x * un.y) / glm::length(l);
    Vec3 t(0.0);
    if (s < -kTiny || s > kTiny) {
      const double c = std::sqrt(1.0 - s * s);
      t = Vec3((c - 1.0) * un.y, (1.0 - c) * un.x, s);
    }
    const Vec2 t2(t);
    const Vec2 q0 = v[n0] + crad * (t2 - a[n0] * un), q1 = v[n1] + crad * (t2 + a[n1] * un);
    out.push_back(primitive("polygon", std::to_string(n0 + 1),
                            {q0.x, q0.y, crad * (t.z + 1.0), q0.x + L.x, q0.y + L.y, l.z + crad * (t.z - 1.0),
                             q1.x + L.x, q1.y + L.y, l.z + crad * (t.z - 1.0), q1.x, q1.y, crad * (t.z + 1.0)}));
    if (lvdir * a[n1] < 0.0) return;
    const Vec2 e = v[n1] + crad * Vec2(a[n1] * un.x - un.y, a[n1] * un.y + un.x);
    out.push_back(primitive("cylinder", std::string("e").append(std::to_string(n0 + 1)),
                            {e.x, e.y, crad, e.x + L.x, e.y + L.y, l.z - crad, lvdir * crad}));
  }
};

// genprism.c's compute_rounding: the edge directions and the trim at each corner,
// sqrt((1 − cos θ)/(1 + cos θ)) = tan(θ/2) for the angle θ between neighbouring edges.
void computeRounding(const RadCommand& cmd, Prism& p) {
  const size_t n = p.v.size();
  p.u.resize(n);
  p.a.assign(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 d = p.v[(i + n - 1) % n] - p.v[i];
    const double len = glm::length(d);
    if (len <= kTiny) fail(cmd, "side " + std::to_string(i + 1) + " of the prism has no length");
    p.u[i] = d / len;
  }
  for (size_t i = n; i--;) {
    const Vec2 v0 = p.u[i], v1 = p.u[(i + 1) % n];
    const double c = glm::dot(v0, v1);
    if (1.0 + c <= kTiny) fail(cmd, "sides " + std::to_string(i + 1) + " and " + std::to_string(i + 2) + " overlap");
    if (1.0 - c > 0.0) {
      p.a[i] = std::sqrt((1.0 - c) / (1.0 + c));
      if (v1.x * v0.y - v1.y * v0.x < 0.0) p.a[i] = -p.a[i];
    }
  }
}

constexpr const char* kUsage = " (genprism mat name { N x1 y1 .. xN yN | vfile } [-l lx ly lz] [-r radius] [-c] [-e])";

}  // namespace

std::vector<RadPrimitive> expandGenprism(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::vector<std::string>& w = cmd.words;
  if (w.size() < 4) fail(cmd, std::string("needs a material, a name and the vertices") + kUsage);
  Prism p;
  p.mat = w[1];
  p.name = w[2];
  p.loc = cmd.loc;
  size_t an = 4;
  if (w[3] == "-") fail(cmd, "'-' reads the vertices from the standard input, which a scene file cannot give");
  if (std::isdigit(static_cast<unsigned char>(w[3][0]))) {
    const double n = number(cmd, 3, "the vertex count");
    if (n != std::floor(n) || n > kMaxVertices) fail(cmd, "the vertex count must be a whole number up to 1024, not '" + w[3] + "'");
    if (w.size() < 4 + 2 * size_t(n)) fail(cmd, w[3] + " vertices need " + std::to_string(2 * size_t(n)) + " numbers" + kUsage);
    for (size_t i = 0; i < size_t(n); ++i)
      p.v.emplace_back(number(cmd, 4 + 2 * i, "vertex " + std::to_string(i + 1)),
                       number(cmd, 5 + 2 * i, "vertex " + std::to_string(i + 1)));
    an = 4 + 2 * size_t(n);
  } else {
    p.v = readVertexFile(cmd, ctx, w[3]);
  }
  if (p.v.size() < 3) fail(cmd, "a prism needs at least 3 vertices, got " + std::to_string(p.v.size()));
  bool ends = true, complete = false;
  double radius = 0.0;
  for (; an < w.size(); ++an) {
    const std::string& o = w[an];
    if (o == "-l") {
      p.l = Vec3(number(cmd, an + 1, "-l"), number(cmd, an + 2, "-l"), number(cmd, an + 3, "-l"));
      an += 3;
      if (std::abs(p.l.z) <= kTiny) fail(cmd, "-l needs a length vector with a z component (it extrudes from z = 0)");
      p.lvdir = p.l.z < 0.0 ? -1.0 : 1.0;
    } else if (o == "-r") {
      radius = number(cmd, ++an, "-r");
    } else if (o == "-e") {
      ends = !ends;
    } else if (o == "-c") {
      complete = !complete;
    } else {
      fail(cmd, "unknown option '" + o + "'" + kUsage);
    }
  }
  std::vector<RadPrimitive> out;
  const bool round = radius > kTiny;  // genprism.c ignores a radius not above FTINY
  if (round) {
    if (radius > p.lvdir * p.l.z) fail(cmd, "a corner radius of " + std::to_string(radius) + " is more than the height");
    p.crad = radius * p.lvdir;
    computeRounding(cmd, p);
  }
  if (ends) {
    p.ends(out, round);
    if (round) p.roundedRims(out);
  }
  const size_t n = p.v.size();
  for (size_t i = 0; i + 1 < n; ++i) round ? p.roundedSide(out, i, i + 1) : p.side(out, i, i + 1);
  if (!complete) round ? p.roundedSide(out, n - 1, 0) : p.side(out, n - 1, 0);
  return out;
}

}  // namespace candela
