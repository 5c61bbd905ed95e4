#include "study/compliance/en1838_grids.h"

#include "metrics/en1838.h"

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

// Even-odd rule (any simple polygon).
bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
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

std::vector<RouteStripPoints> routeStrips(const EscapeRouteSpec& route) {
  const int strips = std::max(1, static_cast<int>(std::ceil(route.widthM / kEn1838MaxStripWidthM - 1e-9)));
  const double w = route.widthM / strips;
  std::vector<RouteStripPoints> out;
  for (int k = 0; k < strips; ++k) {
    RouteStripPoints s;
    s.widthM = w;
    s.offsetM = -0.5 * route.widthM + w * (k + 0.5);
    // Across the central band (half the strip's width): its two edges and points between.
    const double half = 0.25 * w;
    const int across = std::max(2, static_cast<int>(std::ceil(2.0 * half / route.spacingM - 1e-9)));
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
