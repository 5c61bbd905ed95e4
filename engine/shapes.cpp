#include "engine/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela {

namespace {

// Crossing-number point-in-polygon test in the polygon's 2D projection (works for concave
// polygons; Radiance's polygons may be concave).
bool insidePolygon2D(const Vec2* v, uint32_t n, double u, double w) {
  bool inside = false;
  for (uint32_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = v[i];
    const Vec2& b = v[j];
    if ((a.y > w) != (b.y > w)) {
      const double x = a.x + (w - a.y) * (b.x - a.x) / (b.y - a.y);
      if (u < x) inside = !inside;
    }
  }
  return inside;
}

// Roots of a t² + 2 b t + c = 0 in (tMin, tMax), nearest first; numerically stable form.
// 7 parameters: the three coefficients, the interval and the two roots out.
bool nearestQuadraticRoot(double a, double b, double c, double tMin, double tMax, double& t,
                          double* other = nullptr) {
  if (a == 0.0) {
    if (b == 0.0) return false;
    const double r = -c / (2.0 * b);
    if (r > tMin && r < tMax) { t = r; return true; }
    return false;
  }
  const double disc = b * b - a * c;
  if (disc < 0.0) return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  double t0 = q / a;
  double t1 = (q != 0.0) ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > tMin && t0 < tMax) {
    t = t0;
    if (other) *other = t1;
    return true;
  }
  if (t1 > tMin && t1 < tMax) {
    t = t1;
    if (other) *other = t0;
    return true;
  }
  return false;
}

bool intersectCone(const Shape& s, const Vec3& o, const Vec3& dir, double tMin, double tMax, double& t) {
  // Local frame: z along the axis from end a. Lateral surface x² + y² = (r0 + k z)², 0 ≤ z ≤ h.
  const Frame f = Frame::fromNormal(s.n);
  const Vec3 lo = f.toLocal(o - s.a);
  const Vec3 ld = f.toLocal(dir);
  const double k = (s.r1 - s.r0) / s.d;
  const double rAtO = s.r0 + k * lo.z;
  const double qa = ld.x * ld.x + ld.y * ld.y - k * k * ld.z * ld.z;
  const double qb = lo.x * ld.x + lo.y * ld.y - k * rAtO * ld.z;
  const double qc = lo.x * lo.x + lo.y * lo.y - rAtO * rAtO;
  double t0, t1 = 0.0;
  if (!nearestQuadraticRoot(qa, qb, qc, tMin, tMax, t0, &t1)) return false;
  auto valid = [&](double tt) {
    if (!(tt > tMin && tt < tMax)) return false;
    const double z = lo.z + tt * ld.z;
    return z >= 0.0 && z <= s.d && s.r0 + k * z >= 0.0;
  };
  if (valid(t0)) { t = t0; return true; }
  if (t1 > t0 && valid(t1)) { t = t1; return true; }
  return false;
}

// Sutherland–Hodgman clip of a polygon against the half-space  sign·(p[axis] − value) ≥ 0.
// Works for concave input against a convex clip region (the result may contain degenerate edges
// along the boundary, but it is non-empty exactly when the regions overlap).
void clipAxis(std::vector<Vec3>& poly, std::vector<Vec3>& tmp, int axis, double value, double sign) {
  tmp.clear();
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& p = poly[i];
    const Vec3& q = poly[(i + 1) % n];
    const double dp = sign * (p[axis] - value);
    const double dq = sign * (q[axis] - value);
    if (dp >= 0.0) tmp.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) {
      const double s = dp / (dp - dq);
      tmp.push_back(p + s * (q - p));
    }
  }
  poly.swap(tmp);
}

bool polygonOverlapsBox(std::vector<Vec3> poly, const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> tmp;
  tmp.reserve(poly.size() + 8);
  for (int axis = 0; axis < 3 && !poly.empty(); ++axis) {
    clipAxis(poly, tmp, axis, lo[axis], 1.0);
    if (!poly.empty()) clipAxis(poly, tmp, axis, hi[axis], -1.0);
  }
  return !poly.empty();
}

double pointBoxDistance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 q = glm::clamp(p, lo, hi);
  const Vec3 e = p - q;
  return glm::dot(e, e);
}

double pointBoxMaxDistance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 far = glm::max(glm::abs(p - lo), glm::abs(p - hi));
  return glm::dot(far, far);
}

bool ringOverlapsBox(const Shape& s, const Vec3& lo, const Vec3& hi) {
  // The plane ∩ box is a convex polygon; the annulus overlaps it exactly when the polygon's
  // nearest point to the centre is within r1 and its farthest vertex is beyond r0.
  const Frame f = Frame::fromNormal(s.n);
  const Vec3 boxC = 0.5 * (lo + hi);
  const double reach = glm::length(hi - lo) + glm::length(boxC - s.a) + s.r1;
  std::vector<Vec3> poly = {s.a + reach * (-f.t - f.b), s.a + reach * (f.t - f.b), s.a + reach * (f.t + f.b),
                            s.a + reach * (-f.t + f.b)};
  std::vector<Vec3> tmp;
  for (int axis = 0; axis < 3 && !poly.empty(); ++axis) {
    clipAxis(poly, tmp, axis, lo[axis], 1.0);
    if (!poly.empty()) clipAxis(poly, tmp, axis, hi[axis], -1.0);
  }
  if (poly.size() < 1) return false;
  double maxD2 = 0.0;
  for (const Vec3& p : poly) maxD2 = std::max(maxD2, glm::dot(p - s.a, p - s.a));
  if (maxD2 < s.r0 * s.r0) return false;
  // Nearest distance from the centre to the convex polygon (in its plane).
  std::vector<Vec2> q;
  for (const Vec3& p : poly) q.emplace_back(glm::dot(p - s.a, f.t), glm::dot(p - s.a, f.b));
  if (q.size() >= 3 && insidePolygon2D(q.data(), static_cast<uint32_t>(q.size()), 0.0, 0.0)) return true;
  double minD2 = 1e300;
  for (size_t i = 0; i < q.size(); ++i) {
    const Vec2 a = q[i], b = q[(i + 1) % q.size()];
    const Vec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double tt = len2 > 0 ? std::clamp(-glm::dot(a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 p = a + tt * ab;
    minD2 = std::min(minD2, glm::dot(p, p));
  }
  return minD2 <= s.r1 * s.r1;
}

bool coneOverlapsBox(const Shape& s, const Vec3& lo, const Vec3& hi) {
  // Conservative: the cube's bounding sphere must reach the lateral surface's radial band, and
  // the cube must not lie wholly inside the (convex) solid frustum.
  const Vec3 c = 0.5 * (lo + hi);
  const double rad = 0.5 * glm::length(hi - lo);
  const Vec3 rel = c - s.a;
  const double z = std::clamp(glm::dot(rel, s.n), 0.0, s.d);
  const double dAxis = glm::length(rel - z * s.n);
  const double zc = glm::dot(rel, s.n);
  if (zc < -rad || zc > s.d + rad) return false;
  if (dAxis > std::max(s.r0, s.r1) + rad) return false;
  const double k = (s.r1 - s.r0) / s.d;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const Vec3 pr = p - s.a;
    const double pz = glm::dot(pr, s.n);
    if (pz <= 0.0 || pz >= s.d) return true;
    if (glm::length(pr - pz * s.n) >= s.r0 + k * pz) return true;
  }
  return false;  // every corner strictly inside the solid: the box misses the lateral surface
}

}  // namespace

bool intersectShape(const Shape& s, const VertexStore& vs, const Vec3& o, const Vec3& dir, double tMin,
                    double tMax, double& t) {
  switch (s.type) {
    case ShapeType::kTriangle:
      return intersectTriangle(s.a, s.b, s.c, o, dir, tMin, tMax, t);
    case ShapeType::kPolygon: {
      const double denom = glm::dot(s.n, dir);
      if (denom == 0.0) return false;
      const double tt = (s.d - glm::dot(s.n, o)) / denom;
      if (tt <= tMin || tt >= tMax) return false;
      const Vec3 p = o + tt * dir;
      if (!insidePolygon2D(&vs.projected[s.firstVertex], s.vertexCount, p[s.axisU], p[s.axisV])) return false;
      t = tt;
      return true;
    }
    case ShapeType::kSphere: {
      const Vec3 oc = o - s.a;
      return nearestQuadraticRoot(glm::dot(dir, dir), glm::dot(oc, dir), glm::dot(oc, oc) - s.r0 * s.r0, tMin,
                                  tMax, t);
    }
    case ShapeType::kRing: {
      const double denom = glm::dot(s.n, dir);
      if (denom == 0.0) return false;
      const double tt = glm::dot(s.n, s.a - o) / denom;
      if (tt <= tMin || tt >= tMax) return false;
      const Vec3 e = o + tt * dir - s.a;
      const double r2 = glm::dot(e, e);
      if (r2 > s.r1 * s.r1 || r2 < s.r0 * s.r0) return false;
      t = tt;
      return true;
    }
    case ShapeType::kCone:
      return intersectCone(s, o, dir, tMin, tMax, t);
  }
  return false;
}

Vec3 shapeNormal(const Shape& s, const Vec3& p) {
  Vec3 n;
  switch (s.type) {
    case ShapeType::kTriangle:
    case ShapeType::kPolygon:
    case ShapeType::kRing:
      n = s.n;
      break;
    case ShapeType::kSphere:
      n = glm::normalize(p - s.a);
      break;
    case ShapeType::kCone: {
      const Vec3 rel = p - s.a;
      const double z = glm::dot(rel, s.n);
      const Vec3 radial = rel - z * s.n;
      const double rl = glm::length(radial);
      const Vec3 u = rl > 0.0 ? radial / rl : Frame::fromNormal(s.n).t;
      const double k = (s.r1 - s.r0) / s.d;
      n = glm::normalize(u - k * s.n);
      break;
    }
  }
  return s.inward ? -n : n;
}

Box shapeBounds(const Shape& s, const VertexStore& vs) {
  Box b;
  switch (s.type) {
    case ShapeType::kTriangle:
      b.extend(s.a);
      b.extend(s.a + s.b);
      b.extend(s.a + s.c);
      break;
    case ShapeType::kPolygon:
      for (uint32_t i = 0; i < s.vertexCount; ++i) b.extend(vs.points[s.firstVertex + i]);
      break;
    case ShapeType::kSphere:
      b.extend(s.a - Vec3(s.r0));
      b.extend(s.a + Vec3(s.r0));
      break;
    case ShapeType::kRing: {
      // Extent of a disk of radius r with normal n along axis i is r·sqrt(1 − n_i²).
      const Vec3 e = s.r1 * glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - s.n * s.n));
      b.extend(s.a - e);
      b.extend(s.a + e);
      break;
    }
    case ShapeType::kCone: {
      const Vec3 e = glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - s.n * s.n));
      b.extend(s.a - s.r0 * e);
      b.extend(s.a + s.r0 * e);
      b.extend(s.b - s.r1 * e);
      b.extend(s.b + s.r1 * e);
      break;
    }
  }
  return b;
}

std::vector<Vec3> polygonOutline(const Shape& s, const VertexStore& vs) {
  if (s.type == ShapeType::kTriangle) return {s.a, s.a + s.b, s.a + s.c};
  if (s.type == ShapeType::kPolygon)
    return std::vector<Vec3>(vs.points.begin() + s.firstVertex, vs.points.begin() + s.firstVertex + s.vertexCount);
  return {};
}

bool shapeOverlapsBox(const Shape& s, const VertexStore& vs, const Vec3& lo, double size) {
  // A hair of slack so that surfaces lying exactly on a cube face belong to both cubes.
  const double eps = 1e-9 * size;
  const Vec3 l = lo - Vec3(eps), h = lo + Vec3(size + eps);
  const Box bb = shapeBounds(s, vs);
  if (bb.lo.x > h.x || bb.lo.y > h.y || bb.lo.z > h.z || bb.hi.x < l.x || bb.hi.y < l.y || bb.hi.z < l.z)
    return false;
  switch (s.type) {
    case ShapeType::kTriangle:
    case ShapeType::kPolygon:
      return polygonOverlapsBox(polygonOutline(s, vs), l, h);
    case ShapeType::kSphere: {
      const double r2 = s.r0 * s.r0;
      return pointBoxDistance2(s.a, l, h) <= r2 && pointBoxMaxDistance2(s.a, l, h) >= r2;
    }
    case ShapeType::kRing:
      return ringOverlapsBox(s, l, h);
    case ShapeType::kCone:
      return coneOverlapsBox(s, l, h);
  }
  return true;
}

double shapeArea(const Shape& s, const VertexStore& vs) {
  switch (s.type) {
    case ShapeType::kTriangle:
      return 0.5 * glm::length(glm::cross(s.b, s.c));
    case ShapeType::kPolygon: {
      Vec3 sum(0.0);
      for (uint32_t i = 0; i < s.vertexCount; ++i) {
        const Vec3& p = vs.points[s.firstVertex + i];
        const Vec3& q = vs.points[s.firstVertex + (i + 1) % s.vertexCount];
        sum += glm::cross(p, q);
      }
      return 0.5 * std::abs(glm::dot(sum, s.n));
    }
    case ShapeType::kSphere:
      return 4.0 * kPi * s.r0 * s.r0;
    case ShapeType::kRing:
      return kPi * (s.r1 * s.r1 - s.r0 * s.r0);
    case ShapeType::kCone: {
      const double slant = std::sqrt(s.d * s.d + (s.r1 - s.r0) * (s.r1 - s.r0));
      return kPi * (s.r0 + s.r1) * slant;
    }
  }
  return 0.0;
}

}  // namespace candela
