#include "engine/bsdf_tree.h"

#include "engine/radiance/spectrum.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

// Coordinates stay inside [0, 1): the disc's rim maps to the square's edge.
constexpr double kBelowOne = 1.0 - 1e-12;
// Radiance's offset of the 3-D trees' first coordinate below ½ (bsdf_t.c: .5 − FTINY).
constexpr double kTiny = 1e-6;

// Into [0, 1); NaN (a direction that is none) to 0.
double clampUnit(double x) { return x > 0.0 ? std::min(x, kBelowOne) : 0.0; }

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

double smallestLeaf(const TensorTree& t, int node) {
  const TensorTree::Node& n = t.nodes[node];
  if (n.child < 0) return 1.0 / (1 << n.log2Grid);
  double m = 1.0;
  for (int k = 0; k < (1 << t.dims); ++k) m = std::min(m, smallestLeaf(t, n.child + k));
  return 0.5 * m;
}

// Visits the leaf cells of `node` that meet the fixed coordinates pos (local to the node) and
// span the two free ones (freeDim, freeDim + 1), with the cells' corner (x0, y0) and side in the
// free square. f returns false to stop; visit returns false when stopped.
template <class F>
bool visitSlice(const TensorTree& t, int node, const double* pos, int freeDim, double x0, double y0, double size,
                F& f) {
  const TensorTree::Node& n = t.nodes[node];
  if (n.child >= 0) {
    const double half = 0.5 * size;
    for (int c = 0; c < (1 << t.dims); ++c) {
      double sub[4] = {0, 0, 0, 0};
      bool match = true;
      for (int d = 0; d < t.dims && match; ++d) {
        const int bit = (c >> d) & 1;
        if (d == freeDim || d == freeDim + 1) continue;
        const int want = pos[d] >= 0.5 ? 1 : 0;
        if (bit != want) match = false;
        sub[d] = clampUnit(2.0 * pos[d] - bit);
      }
      if (!match) continue;
      if (!visitSlice(t, n.child + c, sub, freeDim, x0 + ((c >> freeDim) & 1) * half,
                      y0 + ((c >> (freeDim + 1)) & 1) * half, half, f))
        return false;
    }
    return true;
  }
  const int g = 1 << n.log2Grid;
  const double cell = size / g;
  int idx[4] = {0, 0, 0, 0};
  for (int d = 0; d < t.dims; ++d)
    if (d != freeDim && d != freeDim + 1) idx[d] = std::min(g - 1, static_cast<int>(g * pos[d]));
  for (int a = 0; a < g; ++a) {
    for (int b = 0; b < g; ++b) {
      idx[freeDim] = a;
      idx[freeDim + 1] = b;
      size_t k = 0;
      for (int d = 0; d < t.dims; ++d) k = (k << n.log2Grid) | static_cast<size_t>(idx[d]);
      if (!f(t.values[n.first + k], x0 + a * cell, y0 + b * cell, cell)) return false;
    }
  }
  return true;
}

}  // namespace

// Shirley & Chiu (1997), the concentric map: the square's four triangles about its centre go to
// the disc's four quarters, radius from the distance to the centre along the axis.
Vec2 squareToDisk(const Vec2& s) {
  const double a = 2.0 * s.x - 1.0, b = 2.0 * s.y - 1.0;
  double r, phi;
  if (a > -b) {
    if (a > b) {
      r = a;
      phi = (kPi / 4.0) * (b / a);
    } else {
      r = b;
      phi = (kPi / 4.0) * (2.0 - a / b);
    }
  } else {
    if (a < b) {
      r = -a;
      phi = (kPi / 4.0) * (4.0 + b / a);
    } else {
      r = -b;
      phi = b != 0.0 ? (kPi / 4.0) * (6.0 - a / b) : 0.0;
    }
  }
  return Vec2(r * std::cos(phi), r * std::sin(phi));
}

Vec2 diskToSquare(const Vec2& d) {
  const double r = std::sqrt(d.x * d.x + d.y * d.y);
  double phi = std::atan2(d.y, d.x);
  if (phi < -kPi / 4.0) phi += kTwoPi;
  double a, b;
  if (phi < kPi / 4.0) {
    a = r;
    b = phi * a / (kPi / 4.0);
  } else if (phi < 3.0 * kPi / 4.0) {
    b = r;
    a = -(phi - kPi / 2.0) * b / (kPi / 4.0);
  } else if (phi < 5.0 * kPi / 4.0) {
    a = -r;
    b = (phi - kPi) * a / (kPi / 4.0);
  } else {
    b = -r;
    a = -(phi - 3.0 * kPi / 2.0) * b / (kPi / 4.0);
  }
  return Vec2(clampUnit(0.5 * a + 0.5), clampUnit(0.5 * b + 0.5));
}

size_t TensorTree::locate(const double* posIn, double* cellSide) const {
  double pos[4];
  for (int d = 0; d < dims; ++d) pos[d] = clampUnit(posIn[d]);
  double side = 1.0;
  int node = 0;
  while (nodes[node].child >= 0) {
    int c = 0;
    for (int d = 0; d < dims; ++d) {
      const double sp = 2.0 * pos[d];
      const int t = sp >= 1.0 ? 1 : 0;
      c |= t << d;
      pos[d] = clampUnit(sp - t);
    }
    side *= 0.5;
    node = nodes[node].child + c;
  }
  const Node& n = nodes[node];
  const int g = 1 << n.log2Grid;
  size_t k = 0;
  for (int d = 0; d < dims; ++d)
    k = (k << n.log2Grid) | static_cast<size_t>(std::min(g - 1, static_cast<int>(g * pos[d])));
  if (cellSide) *cellSide = side / g;
  return n.first + k;
}

TreeBsdf::TreeBsdf(Trees parts, Trees uPrime, Trees vPrime, std::string kind) : kind_(std::move(kind)) {
  for (int pi = 0; pi < kBsdfParts; ++pi) {
    if (!parts[pi]) continue;
    Part p;
    p.which = static_cast<BsdfPart>(pi);
    if (uPrime[pi] && vPrime[pi]) {
      p.u = std::move(uPrime[pi]);
      p.v = std::move(vPrime[pi]);
    }
    p.tree = std::move(*parts[pi]);
    const double leaf = smallestLeaf(p.tree, 0);
    p.minProjSA = kPi * leaf * leaf;  // Radiance's minProjSA (bsdf_t.c, get_extrema)
    p.minY = *std::min_element(p.tree.values.begin(), p.tree.values.end());
    parts_[pi] = std::move(p);
  }
}

Rgb TreeBsdf::partValue(int part, const Vec3& in, const Vec3& out) const {
  const Part& p = *parts_[part];
  if (in.z * bsdfInSide(p.which) <= 0.0 || out.z * bsdfOutSide(p.which) <= 0.0) return Rgb(0.0);
  double pos[4];
  if (p.tree.dims == 4) {
    const Vec2 a = diskToSquare(Vec2(-in.x, -in.y)), b = diskToSquare(Vec2(out.x, out.y));
    pos[0] = a.x, pos[1] = a.y, pos[2] = b.x, pos[3] = b.y;
  } else {
    const Slice s = slice(p, true, in);
    const Vec2 b = freeSquare(s, out);
    pos[0] = s.pos[0], pos[1] = b.x, pos[2] = b.y;
  }
  return colourAt(p, pos, p.tree.lookup(pos));
}

Rgb TreeBsdf::colourAt(const Part& p, const double* pos, double y) {
  if (!p.u || !(y > 0.0)) return Rgb(y);
  // CIE 1976 u′v′ to xy (x = 9u′/(6u′ − 16v′ + 12), y = 4v′/(…)), then XYZ of luminance Y, then
  // Radiance's RGB (engine/radiance/spectrum.h); a chromaticity outside the diagram is grey.
  const double up = p.u->lookup(pos), vp = p.v->lookup(pos);
  const double den = 6.0 * up - 16.0 * vp + 12.0;
  if (!(den > 0.0) || !(vp > 0.0)) return Rgb(y);
  const double cx = 9.0 * up / den, cy = 4.0 * vp / den;
  if (!(cy > 0.0) || cx < 0.0 || cx + cy > 1.0) return Rgb(y);
  return glm::max(xyzToRadianceRgb(Vec3(cx / cy * y, y, (1.0 - cx - cy) / cy * y)), Rgb(0.0));
}

double TreeBsdf::pairProjSA(int part, const Vec3& in, const Vec3& out) const {
  const Part& p = *parts_[part];
  const Slice s = slice(p, true, in);
  const Vec2 b = freeSquare(s, out);
  double pos[4] = {s.pos[0], s.pos[1], s.pos[2], s.pos[3]};
  pos[s.freeDim] = b.x;
  pos[s.freeDim + 1] = b.y;
  double side = 0.0;
  p.tree.lookup(pos, &side);
  return kPi * side * side;
}

// The free coordinates: for a 4-D tree the other direction's square; for a 3-D one the fixed
// direction gives the first coordinate and the rotation. With the outgoing direction fixed, a
// 3-D tree is read with the two directions' roles swapped (reciprocity, f(in, out) =
// f(out, in)): its incident coordinate is not separable from the rotation, and Radiance does
// the same (doc/notes/BSDFdirections.txt: isotropic data are sampled from the incident side).
TreeBsdf::Slice TreeBsdf::slice(const Part& p, bool fixedIsIn, const Vec3& fixed) const {
  Slice s;
  if (p.tree.dims == 4) {
    if (fixedIsIn) {
      const Vec2 a = diskToSquare(Vec2(-fixed.x, -fixed.y));
      s.pos[0] = a.x, s.pos[1] = a.y;
      s.freeDim = 2;
      s.freeIsIncident = false;
      s.freeSide = bsdfOutSide(p.which);
    } else {
      const Vec2 b = diskToSquare(Vec2(fixed.x, fixed.y));
      s.pos[2] = b.x, s.pos[3] = b.y;
      s.freeDim = 0;
      s.freeIsIncident = true;
      s.freeSide = bsdfInSide(p.which);
    }
    return s;
  }
  s.pos[0] = clampUnit((0.5 - kTiny) - 0.5 * std::sqrt(fixed.x * fixed.x + fixed.y * fixed.y));
  s.spin = std::atan2(-fixed.y, -fixed.x);
  s.freeDim = 1;
  s.freeIsIncident = false;
  s.freeSide = fixedIsIn ? bsdfOutSide(p.which) : bsdfInSide(p.which);
  return s;
}

Vec3 TreeBsdf::freeDirection(const Slice& s, const Vec2& square) const {
  Vec2 d = squareToDisk(square);
  if (s.freeIsIncident) d = -d;
  d = rotate(d, s.spin);
  const double z = std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y));
  return Vec3(d.x, d.y, s.freeSide * std::max(z, 1e-12));
}

Vec2 TreeBsdf::freeSquare(const Slice& s, const Vec3& free) const {
  Vec2 d = rotate(Vec2(free.x, free.y), -s.spin);
  if (s.freeIsIncident) d = -d;
  return diskToSquare(d);
}

double TreeBsdf::samplingTotal(int part, bool fixedIsIn, const Vec3& fixed) const {
  const Part& p = *parts_[part];
  const int side = fixedIsIn ? bsdfInSide(p.which) : bsdfOutSide(p.which);
  if (fixed.z * side <= 0.0) return 0.0;
  const Slice s = slice(p, fixedIsIn, fixed);
  double total = 0.0;
  auto add = [&](double v, double, double, double size) {
    total += v * size * size;
    return true;
  };
  visitSlice(p.tree, 0, s.pos, s.freeDim, 0.0, 0.0, 1.0, add);
  return kPi * total;
}

Rgb TreeBsdf::integrateFree(int part, bool fixedIsIn, const Vec3& fixed) const {
  const Part& p = *parts_[part];
  if (!p.u) return Rgb(samplingTotal(part, fixedIsIn, fixed));
  const int side = fixedIsIn ? bsdfInSide(p.which) : bsdfOutSide(p.which);
  if (fixed.z * side <= 0.0) return Rgb(0.0);
  const Slice s = slice(p, fixedIsIn, fixed);
  // Each cell's colour at its centre (the chromaticity trees' cell there).
  Rgb total(0.0);
  auto add = [&](double v, double x0, double y0, double size) {
    double pos[4] = {s.pos[0], s.pos[1], s.pos[2], s.pos[3]};
    pos[s.freeDim] = x0 + 0.5 * size;
    pos[s.freeDim + 1] = y0 + 0.5 * size;
    total += colourAt(p, pos, v) * (size * size);
    return true;
  };
  visitSlice(p.tree, 0, s.pos, s.freeDim, 0.0, 0.0, 1.0, add);
  return kPi * total;
}

bool TreeBsdf::sampleFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec2& u, double pick, Vec3& free,
                          double& pdf) const {
  const Part& p = *parts_[part];
  const double total = samplingTotal(part, fixedIsIn, fixed);
  if (!(total > 0.0)) return false;
  const Slice s = slice(p, fixedIsIn, fixed);
  const double target = std::clamp(pick, 0.0, 1.0) * total / kPi;
  double acc = 0.0, value = 0.0, cx = 0.0, cy = 0.0, side = 0.0;
  auto find = [&](double v, double x0, double y0, double size) {
    if (v <= 0.0) return true;
    value = v, cx = x0, cy = y0, side = size;  // the last non-empty cell, should rounding run out
    acc += v * size * size;
    return acc <= target;
  };
  visitSlice(p.tree, 0, s.pos, s.freeDim, 0.0, 0.0, 1.0, find);
  if (!(value > 0.0)) return false;
  free = freeDirection(s, Vec2(cx + u.x * side, cy + u.y * side));
  // Uniform over the cell in the square, so in projected solid angle: |cos|/(π s²) per sr,
  // times the cell's chance v·π s²/total.
  pdf = value * std::abs(free.z) / total;
  return pdf > 0.0;
}

double TreeBsdf::pdfFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free) const {
  const Part& p = *parts_[part];
  const Slice s = slice(p, fixedIsIn, fixed);
  if (free.z * s.freeSide <= 0.0) return 0.0;
  const double total = samplingTotal(part, fixedIsIn, fixed);
  if (!(total > 0.0)) return 0.0;
  const Vec2 q = freeSquare(s, free);
  double pos[4] = {s.pos[0], s.pos[1], s.pos[2], s.pos[3]};
  pos[s.freeDim] = q.x;
  pos[s.freeDim + 1] = q.y;
  return p.tree.lookup(pos) * std::abs(free.z) / total;
}

long TreeBsdf::freeCell(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free, double& projSA) const {
  const Part& p = *parts_[part];
  const Slice s = slice(p, fixedIsIn, fixed);
  projSA = 0.0;
  if (free.z * s.freeSide <= 0.0) return -1;
  const Vec2 q = freeSquare(s, free);
  double pos[4] = {s.pos[0], s.pos[1], s.pos[2], s.pos[3]};
  pos[s.freeDim] = q.x;
  pos[s.freeDim + 1] = q.y;
  double side = 0.0;
  const size_t k = p.tree.locate(pos, &side);
  projSA = kPi * side * side;
  return static_cast<long>(k);
}

}  // namespace candela
