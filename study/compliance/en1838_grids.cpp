#include "study/compliance/en1838_grids.h"

#include "engine/polygon_split.h"
#include "metrics/en1838.h"
#include "study/grids/sensor_grid.h"  // insidePolygon

#include <algorithm>
#include <cmath>

namespace candela {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// Points from a to b, both included, at most `spacingM` apart.
void sampleSegment(const Vec2& a, const Vec2& b, double spacingM, bool withEnd, std::vector<Vec2>& out) {
  const int n = std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / spacingM - 1e-9)));
  for (int i = 0; i < n + (withEnd ? 1 : 0); ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / n));
}

}  // namespace

bool isConvexPolygon(const std::vector<Vec2>& ccw) {
  const std::size_t n = ccw.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e0 = ccw[(i + 1) % n] - ccw[i], e1 = ccw[(i + 2) % n] - ccw[(i + 1) % n];
    if (cross(e0, e1) < -1e-12 * glm::length(e0) * glm::length(e1)) return false;
  }
  return true;
}

std::vector<Vec2> insetConvexPolygon(const std::vector<Vec2>& ccw, double distanceM) {
  std::vector<Vec2> poly = ccw;
  const std::size_t n = ccw.size();
  // Sutherland–Hodgman against each edge's half-plane moved inwards (left of the edge).
  for (std::size_t i = 0; i < n && poly.size() >= 3; ++i) {
    const Vec2 a = ccw[i], e = ccw[(i + 1) % n] - a;
    const double len = glm::length(e);
    if (!(len > 0.0)) continue;
    auto side = [&](const Vec2& p) { return cross(e, p - a) / len - distanceM; };  // ≥ 0: kept
    std::vector<Vec2> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec2 p = poly[k], q = poly[(k + 1) % poly.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) out.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    poly = std::move(out);
  }
  // Drop repeated vertices; a sliver of no area is no core.
  std::vector<Vec2> clean;
  for (const Vec2& p : poly)
    if (clean.empty() || glm::length(p - clean.back()) > 1e-9) clean.push_back(p);
  while (clean.size() > 1 && glm::length(clean.front() - clean.back()) <= 1e-9) clean.pop_back();
  double area = 0.0;
  for (std::size_t k = 0; k < clean.size(); ++k) area += cross(clean[k], clean[(k + 1) % clean.size()]);
  if (clean.size() < 3 || !(0.5 * area > 1e-9)) return {};
  return clean;
}

namespace {

// Distance from p to the segment a–b.
double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double l2 = glm::dot(e, e);
  const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, e) / l2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * e));
}

}  // namespace

std::vector<Vec2> insetPolygon(const std::vector<Vec2>& ccw, double distanceM, double arcStepM) {
  if (isConvexPolygon(ccw)) return insetConvexPolygon(ccw, distanceM);
  const std::size_t n = ccw.size();
  auto inward = [&](std::size_t i) {  // unit normal of edge i (ccw[i] to ccw[i + 1]), to the left
    const Vec2 e = glm::normalize(ccw[(i + 1) % n] - ccw[i]);
    return Vec2(-e.y, e.x);
  };
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < n; ++i) {  // the corner at vertex i, between edges i − 1 and i
    const std::size_t prev = (i + n - 1) % n;
    const Vec2 v = ccw[i], e0 = v - ccw[prev], e1 = ccw[(i + 1) % n] - v;
    const Vec2 n0 = inward(prev), n1 = inward(i);
    const double turn = cross(e0, e1);
    if (turn >= 0.0) {  // convex (or straight): the moved edges' lines cross
      const Vec2 a = v + distanceM * n0, b = v + distanceM * n1;
      const double den = cross(e0, e1);
      if (std::abs(den) <= 1e-12 * glm::length(e0) * glm::length(e1)) {
        out.push_back(a);
      } else {
        out.push_back(a + e0 * (cross(b - a, e1) / den));
      }
    } else {  // reflex: an arc about the corner from n0 to n1, turning clockwise
      const double sweep = std::atan2(cross(n0, n1), glm::dot(n0, n1));  // negative
      const double start = std::atan2(n0.y, n0.x);
      const int steps = std::max(1, static_cast<int>(std::ceil(std::max(std::abs(sweep) / (kPi / 18.0),
                                                                          std::abs(sweep) * distanceM / arcStepM))));
      for (int k = 0; k <= steps; ++k) {
        const double a = start + sweep * k / steps;
        out.push_back(v + distanceM * Vec2(std::cos(a), std::sin(a)));
      }
    }
  }
  // One simple polygon, counter-clockwise, every vertex inside and distanceM from the boundary.
  const std::size_t m = out.size();
  double area = 0.0;
  for (std::size_t k = 0; k < m; ++k) area += cross(out[k], out[(k + 1) % m]);
  if (m < 3 || !(area > 1e-9)) return {};
  for (const Vec2& p : out) {
    if (!insidePolygon(ccw, p)) return {};
    for (std::size_t i = 0; i < n; ++i)
      if (segmentDistance(p, ccw[i], ccw[(i + 1) % n]) < distanceM * (1.0 - 1e-9)) return {};
  }
  return outlineSelfCrossing(out) ? std::vector<Vec2>{} : out;
}

std::vector<Vec2> polygonPoints(const std::vector<Vec2>& ccw, double spacingM) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < ccw.size(); ++i) sampleSegment(ccw[i], ccw[(i + 1) % ccw.size()], spacingM, false, out);
  Vec2 lo = ccw.front(), hi = ccw.front();
  for (const Vec2& p : ccw) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const int nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / spacingM)));
  const int ny = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / spacingM)));
  // The lattice centred in the box, so that its margins to the boundary are even.
  const Vec2 start = 0.5 * (lo + hi) - 0.5 * spacingM * Vec2(nx - 1, ny - 1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p = start + spacingM * Vec2(i, j);
      if (insidePolygon(ccw, p)) out.push_back(p);
    }
  return out;
}

namespace {

// A route's strips (4.2.1: at most 2 m wide each) and the intervals across a strip's central band
// (half its width) at most `spacingM` apart, at least 2; in double, so that a bound of absurd
// sizes counts without overflowing.
double stripCount(double widthM) { return std::max(1.0, std::ceil(widthM / kEn1838MaxStripWidthM - 1e-9)); }
double bandIntervals(double stripWidthM, double spacingM) {
  return std::max(2.0, std::ceil(0.5 * stripWidthM / spacingM - 1e-9));
}

// polygonPoints' count at most: its edges' points and the lattice over its box.
double polygonPointBound(const std::vector<Vec2>& poly, double spacingM) {
  double edges = 0.0;
  Vec2 lo = poly.front(), hi = poly.front();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    edges += glm::length(poly[(i + 1) % poly.size()] - poly[i]) / spacingM + 1.0;
    lo = glm::min(lo, poly[i]), hi = glm::max(hi, poly[i]);
  }
  return edges + ((hi.x - lo.x) / spacingM + 1.0) * ((hi.y - lo.y) / spacingM + 1.0);
}

}  // namespace

double en1838PointBound(const CaseFile& c) {
  double n = static_cast<double>(c.emergency.safetyPoints.size());
  for (const EscapeRouteSpec& r : c.emergency.routes) {
    double stations = 0.0;
    for (std::size_t i = 0; i + 1 < r.path.size(); ++i) stations += glm::length(r.path[i + 1] - r.path[i]) / r.spacingM + 2.0;
    const double strips = stripCount(r.widthM), across = bandIntervals(r.widthM / strips, r.spacingM);
    n += strips * stations * (across + 2.0);  // each strip's centre line and its band
  }
  for (const OpenAreaSpec& a : c.emergency.openAreas)
    n += polygonPointBound(a.outline, a.spacingM) + kPi * a.outline.size() * kEn1838BorderM / a.spacingM;
  for (const TaskAreaSpec& a : c.taskAreas)
    if (a.emergencyHighRisk) n += polygonPointBound(a.outline, a.spacingM.value_or(kHighRiskSpacingM));
  return n;
}

std::vector<RouteStripPoints> routeStrips(const EscapeRouteSpec& route) {
  const int strips = static_cast<int>(stripCount(route.widthM));
  const double w = route.widthM / strips;
  std::vector<RouteStripPoints> out;
  for (int k = 0; k < strips; ++k) {
    RouteStripPoints s;
    s.widthM = w;
    s.offsetM = -0.5 * route.widthM + w * (k + 0.5);
    // Across the central band (half the strip's width): its two edges and points between.
    const double half = 0.25 * w;
    const int across = static_cast<int>(bandIntervals(w, route.spacingM));
    for (std::size_t i = 0; i + 1 < route.path.size(); ++i) {
      const Vec2 a = route.path[i], b = route.path[i + 1];
      const Vec2 d = glm::normalize(b - a), left(-d.y, d.x);
      sampleSegment(a + s.offsetM * left, b + s.offsetM * left, route.spacingM, true, s.centreLine);
      std::vector<Vec2> stations;
      sampleSegment(a, b, route.spacingM, true, stations);
      for (const Vec2& st : stations)
        for (int j = 0; j <= across; ++j)
          s.band.push_back(st + (s.offsetM - half + 2.0 * half * j / across) * left);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace candela
