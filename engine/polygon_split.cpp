#include "engine/polygon_split.h"

#include <cmath>

namespace candela {

namespace {

// Twice the signed area of the triangle (a, b, c) seen along n.
double signedArea(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  return glm::dot(glm::cross(b - a, c - a), n);
}

// p inside or on the triangle (a, b, c), counter-clockwise about n.
bool inTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  return signedArea(a, b, p, n) >= 0.0 && signedArea(b, c, p, n) >= 0.0 && signedArea(c, a, p, n) >= 0.0;
}

void push(const std::vector<Vec3>& pts, uint32_t a, uint32_t b, uint32_t c, std::vector<std::array<uint32_t, 3>>& out) {
  if (glm::cross(pts[b] - pts[a], pts[c] - pts[a]) == Vec3(0.0)) return;  // zero area
  out.push_back({a, b, c});
}

}  // namespace

bool splitPolygon(const std::vector<Vec3>& pts, const Vec3& normal, std::vector<std::array<uint32_t, 3>>& out,
                  uint64_t maxTests, uint64_t* used) {
  uint64_t tests = 0;
  struct Report {  // the tests made, on every way out
    uint64_t& tests;
    uint64_t* used;
    ~Report() {
      if (used) *used = tests;
    }
  } report{tests, used};
  std::vector<uint32_t> idx(pts.size());
  for (uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
  size_t start = 0;  // where to look for the next ear: just after the last one (fans convex outlines)
  while (idx.size() > 3) {
    bool clipped = false;
    for (size_t step = 0; step < idx.size() && !clipped; ++step) {
      const size_t i = (start + step) % idx.size();
      const uint32_t ip = idx[(i + idx.size() - 1) % idx.size()], ic = idx[i], in = idx[(i + 1) % idx.size()];
      if (!(signedArea(pts[ip], pts[ic], pts[in], normal) > 0.0)) continue;  // reflex or flat corner
      tests += idx.size();
      if (tests > maxTests) return false;
      bool ear = true;
      for (uint32_t k : idx)
        if (k != ip && k != ic && k != in && pts[k] != pts[ip] && pts[k] != pts[ic] && pts[k] != pts[in] &&
            inTriangle(pts[k], pts[ip], pts[ic], pts[in], normal)) {
          ear = false;
          break;
        }
      if (!ear) continue;
      push(pts, ip, ic, in, out);
      idx.erase(idx.begin() + static_cast<long>(i));
      start = i % idx.size();
      clipped = true;
    }
    if (!clipped) break;
  }
  for (size_t i = 1; i + 1 < idx.size(); ++i) push(pts, idx[0], idx[i], idx[i + 1], out);
  return true;
}

double planeDeviation(const std::vector<Vec3>& pts, const Vec3& n, size_t* worst) {
  Vec3 centroid(0.0);
  for (const Vec3& v : pts) centroid += v;
  centroid /= static_cast<double>(pts.size());
  double dev = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const double off = std::abs(glm::dot(n, pts[i] - centroid));
    if (off > dev) {
      dev = off;
      if (worst) *worst = i;
    }
  }
  return dev;
}

std::optional<std::pair<size_t, size_t>> outlineSelfCrossing(const std::vector<glm::dvec2>& q) {
  const size_t m = q.size();
  auto side = [](const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    const double s = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (s > 0.0) - (s < 0.0);
  };
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j == m - 1) continue;  // neighbours through the closing edge
      const glm::dvec2 &a = q[i], &b = q[(i + 1) % m], &c = q[j], &d = q[(j + 1) % m];
      if (side(a, b, c) * side(a, b, d) <= 0 && side(c, d, a) * side(c, d, b) <= 0 &&
          !(side(a, b, c) == 0 && side(a, b, d) == 0))  // collinear overlaps: not a crossing here
        return std::make_pair(i, j);
    }
  return std::nullopt;
}

}  // namespace candela
