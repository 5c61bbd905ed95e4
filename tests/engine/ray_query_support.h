// Shared by the accelerator tests (octree, Embree): a ray, and every hit of it found by brute
// force over all shapes with intersectShape, nearest first.
#pragma once

#include "engine/scene.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace candela::test_support {

struct Ray {
  Vec3 o, d;
  double tMin = 0.0, tMax = std::numeric_limits<double>::infinity();
};

struct BruteHit {
  double t;
  uint32_t shape;
};

inline std::vector<BruteHit> bruteHits(const Scene& sc, const Ray& r) {
  std::vector<BruteHit> hits;
  for (uint32_t i = 0; i < sc.shapes.size(); ++i) {
    double t;
    if (intersectShape(sc.shapes[i], sc.vertices, r.o, r.d, r.tMin, r.tMax, t)) hits.push_back({t, i});
  }
  std::sort(hits.begin(), hits.end(), [](const BruteHit& a, const BruteHit& b) { return a.t < b.t; });
  return hits;
}

// A uniformly distributed unit vector (normalised Gaussian triple).
inline Vec3 randomUnit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  for (;;) {
    const Vec3 v(n(g), n(g), n(g));
    const double l = glm::length(v);
    if (l > 1e-6) return v / l;
  }
}

}  // namespace candela::test_support
