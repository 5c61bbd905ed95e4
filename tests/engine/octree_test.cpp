// The octree must be invisible: for every ray it returns what a brute-force loop over all shapes
// with intersectShape returns (nearest shape and t; any-hit for shadow rays), whatever its
// options. Scenes and rays are seeded random, with the awkward cases made common on purpose:
// axis-aligned directions with zero components, rays lying in or crossing the root cube's
// mid-planes, origins outside the cube, shapes lying in the mid-planes.
#include "engine/octree.h"
#include "tests/engine/ray_query_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using test_support::BruteHit;
using test_support::Ray;
using test_support::bruteHits;
using test_support::randomUnit;

// 2000 small shapes of every kind in [0, 10]³. Two tiny triangles pin the scene bounds to
// exactly [0, 10]³, so the root cube's mid-planes are x, y, z = 5; a few shapes lie in them.
Scene randomScene(uint64_t seed, int n) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Scene sc;
  sc.addPolygon({{0, 0, 0}, {0.01, 0, 0}, {0, 0.01, 0}}, 0);
  sc.addPolygon({{10, 10, 10}, {9.99, 10, 10}, {10, 9.99, 10}}, 0);
  // The draws in a sequence of their own: the order in which a constructor's or a function's
  // arguments are evaluated is unspecified (g++ and clang differ), and the scene must not be.
  auto pos = [&](double margin) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = margin + (10 - 2 * margin) * U(g);
    return p;
  };
  for (int k = 0; k < n - 2; ++k) {
    // 1.3 m from the sides: the largest shape (a parallelogram of two 0.6 m edges) stays inside
    // [0, 10]³, so the two triangles alone set the bounds.
    const Vec3 c = pos(1.3);
    const double s = 0.1 + 0.5 * U(g);
    switch (k % 6) {
      case 0: {
        sc.addPolygon({c, c + s * randomUnit(g), c + s * randomUnit(g)}, 0);
        break;
      }
      case 1: {  // planar parallelogram (a 4-vertex Polygon)
        const Vec3 e1 = s * randomUnit(g), e2 = s * randomUnit(g);
        sc.addPolygon({c, c + e1, c + e1 + e2, c + e2}, 0);
        break;
      }
      case 2:
        sc.addSphere(c, 0.3 * s, 0, U(g) < 0.3);
        break;
      case 3: {
        const double r0 = 0.3 * s * U(g);
        sc.addRing(c, randomUnit(g), r0, r0 + 0.05 + 0.3 * s, 0);
        break;
      }
      case 4: {
        const double ra = 0.2 * s * U(g), rb = U(g) < 0.3 ? ra : 0.2 * s * U(g);
        const Vec3 tip = c + s * randomUnit(g);
        const bool inside = U(g) < 0.3;
        sc.addCone(c, tip, ra + 0.01, rb, 0, inside);
        break;
      }
      case 5: {  // shapes in or across the mid-planes
        const int axis = static_cast<int>(3 * U(g)) % 3;
        Vec3 p = c;
        p[axis] = 5.0;
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        Vec3 e1(0.0), e2(0.0);
        e1[a1] = s;
        e2[a2] = s;
        if (U(g) < 0.5) {
          sc.addPolygon({p, p + e1, p + e1 + e2, p + e2}, 0);  // lies in the plane
        } else {
          sc.addSphere(p, 0.2 * s, 0);  // centred on it
        }
        break;
      }
    }
  }
  return sc;
}

// ~20000 rays of every awkward kind (see the file comment).
std::vector<Ray> randomRays(uint64_t seed, int n, const Vec3& lo, const Vec3& hi) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Vec3 size = hi - lo, mid = 0.5 * (lo + hi);
  auto inside = [&] {
    Vec3 u;
    for (int a = 0; a < 3; ++a) u[a] = U(g);  // in sequence (see randomScene)
    return lo + u * size;
  };
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    Ray r;
    switch (i % 8) {
      case 0:
      case 1:  // inside, random direction
        r.o = inside();
        r.d = randomUnit(g);
        break;
      case 2: {  // outside the cube, aimed at a point inside (or away from it)
        Vec3 o;
        do o = lo - size + 3.0 * Vec3(U(g), U(g), U(g)) * size;
        while (o.x >= lo.x && o.y >= lo.y && o.z >= lo.z && o.x <= hi.x && o.y <= hi.y && o.z <= hi.z);
        r.o = o;
        r.d = glm::normalize(inside() - o);
        if (U(g) < 0.1) r.d = -r.d;
        break;
      }
      case 3: {  // one or two zero direction components
        r.o = U(g) < 0.8 ? inside() : lo - 0.5 * size + 2.0 * Vec3(U(g), U(g), U(g)) * size;
        Vec3 d(0.0);
        const int a = static_cast<int>(3 * U(g)) % 3;
        d[a] = U(g) < 0.5 ? -1.0 : 1.0;
        if (U(g) < 0.5) d[(a + 1) % 3] = 2.0 * U(g) - 1.0;
        r.d = glm::normalize(d);
        break;
      }
      case 4: {  // lying in a mid-plane: origin on it, zero component across it
        r.o = inside();
        const int a = static_cast<int>(3 * U(g)) % 3;
        r.o[a] = mid[a];
        r.d = randomUnit(g);
        r.d[a] = 0.0;
        if (U(g) < 0.3) r.d[(a + 1) % 3] = 0.0;  // along the intersection of two mid-planes
        r.d = glm::normalize(r.d);
        if (!(glm::length(r.d) > 0.5)) r.d = Vec3(0, 0, 1);
        break;
      }
      case 5:  // from the exact centre of the root cube
        r.o = mid;
        r.d = randomUnit(g);
        break;
      case 6: {  // starting on a mid-plane, crossing it
        r.o = inside();
        const int a = static_cast<int>(3 * U(g)) % 3;
        r.o[a] = mid[a];
        r.d = randomUnit(g);
        break;
      }
      case 7:  // restricted intervals
        r.o = inside();
        r.d = randomUnit(g);
        r.tMin = 2.0 * U(g);
        r.tMax = U(g) < 0.5 ? kInf : r.tMin + 4.0 * U(g);
        break;
    }
    rays.push_back(r);
  }
  return rays;
}

// Compares the octree with brute force on every ray, for intersect, occluded and the skip
// arguments. Ties (two shapes at the same t) may resolve either way; t must agree.
void compareWithBruteForce(const Scene& sc, const Octree& oct, const std::vector<Ray>& rays,
                           const std::vector<std::vector<BruteHit>>& brute, const char* label) {
  int hits = 0, mismatches = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    const auto& bh = brute[i];
    Octree::Hit h;
    const bool got = oct.intersect(r.o, r.d, r.tMin, r.tMax, h);
    if (got != !bh.empty() && ++mismatches <= 10)
      ADD_FAILURE() << label << " ray " << i << ": octree " << (got ? "hit" : "miss") << ", brute force "
                    << (bh.empty() ? "miss" : "hit") << " o=(" << r.o.x << "," << r.o.y << "," << r.o.z << ") d=("
                    << r.d.x << "," << r.d.y << "," << r.d.z << ")";
    if (got && !bh.empty()) {
      ++hits;
      // Same intersection routine on the same inputs: t agrees to far better than 1e-9 relative.
      EXPECT_NEAR(h.t, bh[0].t, 1e-9 * std::max(1.0, bh[0].t)) << label << " ray " << i;
      if (h.shape != bh[0].shape) {
        const bool tie = std::any_of(bh.begin(), bh.end(), [&](const BruteHit& b) {
          return b.shape == h.shape && std::abs(b.t - bh[0].t) <= 1e-9 * std::max(1.0, b.t);
        });
        EXPECT_TRUE(tie) << label << " ray " << i << ": shape " << h.shape << " instead of " << bh[0].shape;
      }
    }
    EXPECT_EQ(oct.occluded(r.o, r.d, r.tMin, r.tMax), !bh.empty()) << label << " ray " << i;
    // Skip the nearest one or two shapes: the next nearest remains.
    if (!bh.empty() && i % 3 == 0) {
      const uint32_t a = bh[0].shape;
      const uint32_t b = bh.size() > 1 ? bh[1].shape : kNoShape;
      for (int variant = 0; variant < 3; ++variant) {
        const uint32_t sa = variant == 1 ? kNoShape : a;
        const uint32_t sb = variant == 0 ? kNoShape : (variant == 1 ? a : b);
        const BruteHit* want = nullptr;
        for (const BruteHit& x : bh)
          if (x.shape != sa && x.shape != sb) { want = &x; break; }
        Octree::Hit hs;
        const bool gs = oct.intersect(r.o, r.d, r.tMin, r.tMax, hs, sa, sb);
        ASSERT_EQ(gs, want != nullptr) << label << " ray " << i << " skip variant " << variant;
        if (want) {
          EXPECT_NEAR(hs.t, want->t, 1e-9 * std::max(1.0, want->t)) << label << " ray " << i;
        }
        EXPECT_EQ(oct.occluded(r.o, r.d, r.tMin, r.tMax, sa, sb), want != nullptr) << label << " ray " << i;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << label;
  EXPECT_GT(hits, static_cast<int>(rays.size() / 5)) << label << ": too few hits to mean anything";
}

void expectConsistentStats(const Octree& oct, size_t shapes, const char* label) {
  const OctreeStats st = oct.stats();
  // A full octree: every internal node has 8 children.
  EXPECT_EQ(st.nodes, 1 + 8 * (st.nodes - st.leaves)) << label;
  EXPECT_GE(st.items, shapes) << label;  // every shape lies in at least one leaf
  EXPECT_GE(st.memoryBytes, st.items * sizeof(uint32_t)) << label;
  std::printf("[ stats    ] %-28s nodes %zu leaves %zu items %zu (%.2f per surface) depth %d, %.1f bytes per surface\n",
              label, st.nodes, st.leaves, st.items, static_cast<double>(st.items) / shapes, st.depth,
              static_cast<double>(st.memoryBytes) / shapes);
}

TEST(Octree, MatchesBruteForceOnRandomMixedScene) {
  const Scene sc = randomScene(42, 2000);
  ASSERT_EQ(sc.shapes.size(), 2000u);
  const Octree ref(sc);
  EXPECT_EQ(ref.cube().center(), Vec3(5.0));  // the rays' mid-plane cases rely on this
  const std::vector<Ray> rays = randomRays(43, 20000, ref.cube().lo, ref.cube().hi);
  std::vector<std::vector<BruteHit>> brute;
  brute.reserve(rays.size());
  for (const Ray& r : rays) brute.push_back(bruteHits(sc, r));

  struct Variant {
    OctreeOptions opt;
    const char* label;
  };
  const Variant variants[] = {
      {{6, 0.0}, "maxSetSize 6 (default)"},
      {{1, 0.0}, "maxSetSize 1"},
      {{20, 0.0}, "maxSetSize 20"},
      {{6, 1e-4}, "maxSetSize 6, min cube 0.1 mm"},
      {{2, 0.5}, "maxSetSize 2, min cube 0.5 m"},
  };
  for (const Variant& v : variants) {
    const Octree oct(sc, v.opt);
    expectConsistentStats(oct, sc.shapes.size(), v.label);
    compareWithBruteForce(sc, oct, rays, brute, v.label);
  }
  // Smaller leaves make a deeper tree.
  EXPECT_GT(Octree(sc, {1, 0.0}).stats().depth, Octree(sc, {20, 0.0}).stats().depth);
}

// A tessellated floor: 10⁴ tiny coplanar triangles sharing edges and vertices (rays through
// shared vertices and edges, grazing rays in the floor's plane).
TEST(Octree, MatchesBruteForceOnTessellatedFloor) {
  Scene sc;
  const int nx = 50, ny = 100;
  const double cell = 0.1;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const Vec3 p(i * cell, j * cell, 0.0);
      const Vec3 ex(cell, 0, 0), ey(0, cell, 0);
      sc.addPolygon({p, p + ex, p + ex + ey}, 0);
      sc.addPolygon({p, p + ex + ey, p + ey}, 0);
    }
  ASSERT_EQ(sc.shapes.size(), 10000u);
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Ray> rays;
  for (int k = 0; k < 20000; ++k) {
    Ray r;
    switch (k % 4) {
      case 0:  // from above, random downward direction
        r.o = Vec3(-1 + 7 * U(g), -1 + 12 * U(g), 0.01 + 3 * U(g));
        r.d = randomUnit(g);
        r.d.z = -std::abs(r.d.z);
        break;
      case 1:  // straight down through vertices and edges of the grid
        r.o = Vec3(cell * static_cast<int>(nx * U(g)), cell * static_cast<int>(ny * U(g)) + (k % 8 == 1 ? 0.05 : 0.0),
                   1.0);
        r.d = Vec3(0, 0, -1);
        break;
      case 2:  // from below, upward
        r.o = Vec3(5 * U(g), 10 * U(g), -2 * U(g) - 0.01);
        r.d = randomUnit(g);
        r.d.z = std::abs(r.d.z);
        break;
      case 3:  // grazing: in the plane of the floor (no hits) or just above it
        r.o = Vec3(5 * U(g), 10 * U(g), k % 8 == 3 ? 0.0 : 1e-3);
        r.d = glm::normalize(Vec3(2 * U(g) - 1, 2 * U(g) - 1, k % 8 == 3 ? 0.0 : -1e-3));
        break;
    }
    rays.push_back(r);
  }
  std::vector<std::vector<BruteHit>> brute;
  for (const Ray& r : rays) brute.push_back(bruteHits(sc, r));
  for (const OctreeOptions& opt : {OctreeOptions{6, 0.0}, OctreeOptions{20, 0.0}}) {
    const Octree oct(sc, opt);
    const std::string label = "floor, maxSetSize " + std::to_string(opt.maxSetSize);
    expectConsistentStats(oct, sc.shapes.size(), label.c_str());
    compareWithBruteForce(sc, oct, rays, brute, label.c_str());
  }
}

TEST(Octree, EmptySceneAndSingleShape) {
  const Scene empty;
  const Octree oe(empty);
  Octree::Hit h;
  EXPECT_FALSE(oe.intersect({0, 0, 0}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_FALSE(oe.occluded({0, 0, 0}, {0, 0, 1}, 0.0, kInf));

  Scene one;
  one.addSphere({1, 2, 3}, 0.5, 0);
  const Octree o1(one);
  ASSERT_TRUE(o1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_DOUBLE_EQ(h.t, 2.5);
  EXPECT_EQ(h.shape, 0u);
  EXPECT_FALSE(o1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, 2.4, h));
  EXPECT_FALSE(o1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, kInf, h, 0));
  EXPECT_TRUE(o1.occluded({1, 2, 0}, {0, 0, 1}, 0.0, kInf));
  EXPECT_FALSE(o1.occluded({1, 2, 0}, {0, 0, 1}, 0.0, kInf, kNoShape, 0));
  // Far outside the cube, pointing at it, and pointing away.
  EXPECT_TRUE(o1.intersect({1, 2, -100}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_DOUBLE_EQ(h.t, 102.5);
  EXPECT_FALSE(o1.occluded({1, 2, -100}, {0, 0, -1}, 0.0, kInf));
}

}  // namespace
}  // namespace candela
